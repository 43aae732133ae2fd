// SyntheticAorticPhantom: writes a CT-like aorto-iliac phantom with its analytic ground truth.
#include <cstdlib>
#include <iostream>

#include <itkObject.h>

#include "CLPSupport.h"
#include "IO/OutputTransaction.h"
#include "IO/WriteImage.h"
#include "IO/WritePhantomTruth.h"
#include "IO/WriteReturnParameters.h"
#include "SlicerProgress.h"
#include "SyntheticAorticPhantomCLP.h"
#include "SyntheticAorticPhantomParameters.h"

int main(int argc, char* argv[])
{
  PARSE_ARGS;
  itk::Object::GlobalWarningDisplayOff();
  try
  {
    using namespace sgp;
    PhantomParams p = MakePhantomParams(spacingMm, directionLps, sizeVoxels);
    p.neckDiameterMm = neckDiameterMm;
    p.neckLengthMm = neckLengthMm;
    p.maxAneurysmDiameterMm = maxAneurysmDiameterMm;
    p.aneurysmLengthMm = aneurysmLengthMm;
    p.distalNeckDiameterMm = distalNeckDiameterMm;
    p.neckAngleDeg = neckAngleDeg;
    p.rightIliacDiameterMm = rightIliacDiameterMm;
    p.leftIliacDiameterMm = leftIliacDiameterMm;
    p.rightCommonIliacLengthMm = rightCommonIliacLengthMm;
    p.leftCommonIliacLengthMm = leftCommonIliacLengthMm;
    p.lumenHu = lumenHu;
    p.tissueHu = tissueHu;
    p.blurSigmaMm = blurSigmaMm;
    p.noiseSigmaHu = noiseSigmaHu;
    p.noiseSeed = noiseSeed;
    p.includeBone = includeBone;
    p.boneGapMm = boneGapMm;
    p.includeKidneys = includeKidneys;
    p.kidneyHu = kidneyHu;
    p.wallThicknessMm = wallThicknessMm;
    p.wallHu = wallHu;
    p.thrombusMaxThicknessMm = thrombusMaxThicknessMm;
    p.thrombusConcentric = thrombusShape == "concentric";
    p.thrombusSide = ParsePhantomSide(thrombusSide, "thrombusSide");
    p.thrombusHu = thrombusHu;
    p.neckThrombusThicknessMm = neckThrombusThicknessMm;
    p.neckThrombusLengthMm = neckThrombusLengthMm;
    p.neckThrombusSide = ParsePhantomSide(neckThrombusSide, "neckThrombusSide");
    p.neckLumenPerLevel = neckLumenPerLevel;
    p.calcificationHu = calcificationHu;
    p.sacCalcificationArcDeg = sacCalcificationArcDeg;
    p.sacCalcificationSide = ParsePhantomSide(sacCalcificationSide, "sacCalcificationSide");
    p.neckCalcificationArcDeg = neckCalcificationArcDeg;
    p.neckCalcificationSide = ParsePhantomSide(neckCalcificationSide, "neckCalcificationSide");
    p.includePsoas = includePsoas;
    p.psoasHu = psoasHu;
    p.includeIvc = includeIvc;
    p.ivcHu = ivcHu;
    p.includeDuodenum = includeDuodenum;
    p.duodenumHu = duodenumHu;
    p.includeLeftRenalVein = includeLeftRenalVein;
    p.leftRenalVeinHu = leftRenalVeinHu;
    p.bolusGradientHuPerCm = bolusGradientHuPerCm;
    p.renalRadiusMm = 0.5 * renalDiameterMm;
    p.ivcArcDeg = ivcArcDeg;
    p.sacAxisRatio = sacAxisRatio;
    p.sacMajorAxis = ParsePhantomSide(sacMajorAxis, "sacMajorAxis");
    p.rightCommonIliacAngleDeg = rightCommonIliacAngleDeg;
    p.leftCommonIliacAngleDeg = leftCommonIliacAngleDeg;
    p.distalNeckLengthMm = distalNeckLengthMm;
    p.rightInternalIliac = !omitRightInternalIliac;
    p.leftInternalIliac = !omitLeftInternalIliac;
    ValidatePhantomParams(p);

    SlicerProgress progress(std::cout, { { "GeneratePhantom", 8.0 }, { "WriteOutputs", 2.0 } });
    progress.Begin("GeneratePhantom", "Generating the aorto-iliac phantom");
    const AorticPhantom phantom = GenerateAorticPhantom(p, progress.Callback());
    const Point3 seedLps = phantom.truth.seedLps;
    seedRas = { -seedLps.x(), -seedLps.y(), seedLps.z() };
    truthLumenVolumeMl = phantom.truth.lumenVolumeMl;

    progress.Begin("WriteOutputs", "Writing the phantom and its truth");
    OutputTransaction outputs;
    WriteCtImage(*phantom.ct, outputs.Stage(outputVolume));
    if (!outputTruthLabelMap.empty())
    {
      WriteLabelMap(*phantom.labels, outputs.Stage(outputTruthLabelMap));
    }
    if (!outputTruth.empty())
    {
      WritePhantomTruth(phantom, outputs.Stage(outputTruth));
    }
    if (!returnParameterFile.empty())
    {
      WriteReturnParameters({ { "seedRas", FormatReturnValue(seedRas[0]) + "," + FormatReturnValue(seedRas[1]) + "," +
                                             FormatReturnValue(seedRas[2]) },
                              { "truthLumenVolumeMl", FormatReturnValue(truthLumenVolumeMl) } },
                            outputs.Stage(returnParameterFile));
    }
    outputs.Commit();
    progress.End();
    const auto size = phantom.ct->GetLargestPossibleRegion().GetSize();
    std::cout << "Phantom: " << size[0] << " x " << size[1] << " x " << size[2] << " voxels written to " << outputVolume
              << "; seed (RAS) " << FormatReturnValue(seedRas[0]) << "," << FormatReturnValue(seedRas[1]) << ","
              << FormatReturnValue(seedRas[2]) << std::endl;
    return EXIT_SUCCESS;
  }
  catch (const std::exception& e)
  {
    std::cerr << "ERROR: " << sgp::clp::OneLine(e.what()) << std::endl;
    return EXIT_FAILURE;
  }
}
