// StentGraftSimulation: the SEM command-line module of StentGraftPlanner.
// Sequence (STYLE.md B7): PARSE_ARGS, ValidateParameters, read, convert the seed once, run the
// stages in DESIGN.md's order with progress, write every output at once, return.
#include <cstdlib>
#include <iostream>

#include <itkObject.h>
#include <vtkObject.h>

#include "AssignInscribedRadii.h"
#include "GrowLumenRegion.h"
#include "IO/WriteCenterlines.h"
#include "CLPSupport.h"
#include "IO/OutputTransaction.h"
#include "IO/ReadCtImage.h"
#include "IO/WriteImage.h"
#include "IO/WriteReturnParameters.h"
#include "SlicerProgress.h"
#include "StentGraftSimulationCLP.h"
#include "StentGraftSimulationParameters.h"

namespace
{

void PrintWarnings(const std::vector<std::string>& warnings)
{
  for (const std::string& warning : warnings)
  {
    std::cerr << "WARNING: " << warning << std::endl;
  }
}

} // namespace

int main(int argc, char* argv[])
{
  PARSE_ARGS;
  // ITK and VTK would print multi-line diagnostics to stderr; every failure reaches the user
  // instead as the one ERROR line below.
  itk::Object::GlobalWarningDisplayOff();
  vtkObject::GlobalWarningDisplayOff();
  try
  {
    using namespace sgp;
    const RegionGrowingParams growParams = MakeRegionGrowingParams(
      thresholdMode, lowerHu, upperHu, windowSigmas, seedMinimumHu, leakOpeningRadiusMm, maximumLumenVolumeMl);
    const SkeletonGraphParams graphParams = MakeSkeletonGraphParams(spurLengthRatio);
    const CenterlineParams centerlineParams = MakeCenterlineParams(centerlineStepMm, centerlineSmoothingMm);
    ValidateParameters(inputVolume, seed, growParams, graphParams, centerlineParams);
    const bool wantCenterlines = !outputCenterlines.empty() || !outputLandmarks.empty();
    SlicerProgress progress(std::cout, { { "ReadVolume", 2.0 },
                                         { "SegmentLumen", 4.0 },
                                         { "ThinLumen", 2.0 },
                                         { "ExtractCenterlines", 1.0 },
                                         { "WriteOutputs", 1.0 } });

    progress.Begin("ReadVolume", "Reading the CT volume");
    const CtVolume volume = ReadCtImage(inputVolume);
    PrintWarnings(volume.warnings);
    const Point3 seedLps = RasToLps(seed);

    progress.Begin("SegmentLumen", "Segmenting the aortic lumen by region growing");
    const LumenSegmentation lumen = GrowLumenRegion(*volume.image, seedLps, growParams, progress.Callback());
    PrintWarnings(lumen.warnings);
    lumenVolumeMl = lumen.volumeMl;
    lowerHuUsed = lumen.lowerHu;
    upperHuUsed = lumen.upperHu;
    edgeHuUsed = lumen.edgeHu;

    CenterlineTree centerlines;
    if (wantCenterlines)
    {
      progress.Begin("ThinLumen", "Thinning the lumen into its skeleton");
      const Skeleton skeleton = ThinLabelMap(*lumen.mask, progress.Callback());
      progress.Begin("ExtractCenterlines", "Labelling the aorta, the iliac arteries and their branches");
      const SkeletonGraph graph = BuildSkeletonGraph(skeleton, *lumen.mask, graphParams);
      progress.Report(0.3);
      centerlines = LabelAortoIliacTree(graph, centerlineParams);
      AssignInscribedRadii(centerlines, skeleton);
    }

    progress.Begin("WriteOutputs", "Writing the outputs");
    OutputTransaction outputs;
    if (!outputLabelMap.empty())
    {
      WriteLabelMap(*lumen.mask, outputs.Stage(outputLabelMap));
    }
    if (!outputCenterlines.empty())
    {
      WriteCenterlines(centerlines, outputs.Stage(outputCenterlines));
    }
    if (!outputLandmarks.empty())
    {
      WriteLandmarks(centerlines, outputs.Stage(outputLandmarks));
    }
    if (!returnParameterFile.empty())
    {
      WriteReturnParameters({ { "lumenVolumeMl", FormatReturnValue(lumenVolumeMl) },
                              { "lowerHuUsed", FormatReturnValue(lowerHuUsed) },
                              { "upperHuUsed", FormatReturnValue(upperHuUsed) },
                              { "edgeHuUsed", FormatReturnValue(edgeHuUsed) } },
                            outputs.Stage(returnParameterFile));
    }
    outputs.Commit();
    progress.End();

    std::cout << "Lumen: " << FormatReturnValue(lumenVolumeMl) << " mL; window " << FormatReturnValue(lowerHuUsed)
              << " to " << FormatReturnValue(upperHuUsed) << " HU (seed median " << lumen.seedMedianHu << " HU, sigma "
              << lumen.seedSigmaHu << " HU); boundary at " << FormatReturnValue(edgeHuUsed) << " HU" << std::endl;
    if (wantCenterlines)
    {
      std::cout << "Centerlines: aorta " << FormatReturnValue(centerlines.aorta.LengthMm()) << " mm, right iliac "
                << FormatReturnValue(centerlines.rightIliac.LengthMm()) << " mm, left iliac "
                << FormatReturnValue(centerlines.leftIliac.LengthMm()) << " mm; side branches:";
      for (const Centerline& c : centerlines.sideBranches)
        std::cout << " " << c.name;
      std::cout << std::endl;
    }
    return EXIT_SUCCESS;
  }
  catch (const std::exception& e)
  {
    std::cerr << "ERROR: " << sgp::clp::OneLine(e.what()) << std::endl;
    return EXIT_FAILURE;
  }
}
