// StentGraftSimulation: the SEM command-line module of StentGraftPlanner.
// Sequence (STYLE.md B7): PARSE_ARGS, ValidateParameters, read, convert the seed once, run the
// stages in DESIGN.md's order with progress, write every output at once, return.
#include <cstdlib>
#include <iostream>

#include <itkObject.h>
#include <vtkObject.h>

#include "GrowLumenRegion.h"
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
    ValidateParameters(inputVolume, seed, growParams);
    SlicerProgress progress(std::cout, { { "ReadVolume", 2.0 }, { "SegmentLumen", 6.0 }, { "WriteOutputs", 2.0 } });

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

    progress.Begin("WriteOutputs", "Writing the outputs");
    OutputTransaction outputs;
    if (!outputLabelMap.empty())
    {
      WriteLabelMap(*lumen.mask, outputs.Stage(outputLabelMap));
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
    if (!outputLabelMap.empty())
    {
      std::cout << "Lumen label map: " << outputLabelMap << std::endl;
    }
    return EXIT_SUCCESS;
  }
  catch (const std::exception& e)
  {
    std::cerr << "ERROR: " << sgp::clp::OneLine(e.what()) << std::endl;
    return EXIT_FAILURE;
  }
}
