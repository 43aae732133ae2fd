// StentGraftSimulation: the SEM command-line module of StentGraftPlanner.
// Sequence (STYLE.md B7): PARSE_ARGS, the parameters and ValidateParameters, the catalogue, read,
// convert the seed once, PlanRepair (Logic/Pipeline) with Slicer progress, write every output at
// once, print the summary. No stage logic lives here.
#include <cstdlib>
#include <future>
#include <optional>
#include <iostream>

#include <itkObject.h>
#include <vtkObject.h>

#include "CLPSupport.h"
#include "IO/ReadCtImage.h"
#include "IO/ReadDeviceCatalog.h"
#include "IO/ReadLumenSegmentation.h"
#include "IO/ReadNeckRules.h"
#include "IO/ResourcePath.h"
#include "IO/WriteImage.h"
#include "IO/WritePlanOutputs.h"
#include "Pipeline/PlanRepair.h"
#include "Pipeline/PlanValues.h"
#include "PrintPlanSummary.h"
#include "QuietStderr.h"
#include "SlicerProgress.h"
#include "StentGraftSimulationCLP.h"
#include "StentGraftSimulationParameters.h"

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
    // Inside Slicer, PARSE_ARGS (SEM's GenerateCLP) reads a point's components with atof.
    ValidatePointArguments(
      argc, argv,
      { "seed", "lowestRenalOstium", "aorticBifurcation", "rightInternalIliacOrigin", "leftInternalIliacOrigin" });
    PlanOutputPaths paths;
    paths.labelMap = outputLabelMap;
    paths.wallLabelMap = outputWallLabelMap;
    paths.outerWallModel = outputOuterWallModel;
    paths.centerlines = outputCenterlines;
    paths.landmarks = outputLandmarks;
    paths.stentModel = outputStentModel;
    paths.initialStentModel = outputInitialStentModel;
    paths.simulatedStentModel = outputSimulatedStentModel;
    paths.measurements = outputMeasurements;
    paths.diameterProfile = outputDiameterProfile;
    paths.report = outputReport;
    paths.reportHtml = outputReportHtml;
    paths.configuration = outputConfiguration;
    paths.straightenedVolume = outputStraightenedVolume;
    paths.straightenedLeftVolume = outputStraightenedLeftVolume;
    paths.returnParameterFile = returnParameterFile;
    const auto contour = [&](const std::string& mode, const std::vector<double>& diametersMm)
    {
      return MakeActiveContourParams(mode, measureStiffnessWeights, measureBalloonRadiusMm, measureBalloonPressure,
                                     diametersMm, stentStiffnessWeights, stentBalloonPressure, acmTau, wallWeight,
                                     wallSofteningMm, acmMaxIterations, acmToleranceMm);
    };
    PlanParams params;
    params.growing = MakeRegionGrowingParams(thresholdMode, lowerHu, upperHu, windowSigmas, seedMinimumHu,
                                             leakOpeningRadiusMm, maximumLumenVolumeMl);
    params.graph = MakeSkeletonGraphParams(spurLengthRatio);
    params.centerlines = MakeCenterlineParams(centerlineStepMm, centerlineSmoothingMm);
    params.mesh = MakeStentMeshParams(verticesPerRing, ringSpacingMm, startRadiusMm, proximalStartMm);
    params.measure = contour("measure", stentDiametersMm);
    if (acmMode != "measure")
      params.simulate = contour(acmMode, stentDiametersMm);
    params.graft = contour("simulate", { 24.0, 14.0, 14.0 }); // the graft's radii are the chosen device's
    params.selection = MakeDeviceSelectionParams(device, proximalOversizingRange, limbOversizingRange, ipsilateralSide);
    params.deploymentOffsetMm = CheckDeploymentOffset(deploymentOffsetMm);
    params.selection.deploymentToleranceMm = CheckDeploymentTolerance(deploymentToleranceMm);
    ValidateParameters(inputVolume, seed, params.growing, params.graph, params.centerlines, params.mesh,
                       params.simulate ? *params.simulate : params.measure);
    PlanRequest request = PlanRequestFor(paths);
    if (!lowestRenalOstium.empty())
      request.lowestRenalOstiumLps = RasToLps(lowestRenalOstium);
    if (!aorticBifurcation.empty())
      request.landmarks.aorticBifurcationLps = RasToLps(aorticBifurcation);
    if (!rightInternalIliacOrigin.empty())
      request.landmarks.internalIliacOriginLps[0] = RasToLps(rightInternalIliacOrigin);
    if (!leftInternalIliacOrigin.empty())
      request.landmarks.internalIliacOriginLps[1] = RasToLps(leftInternalIliacOrigin);
    // The input volume named as the lumen segmentation too: the plan runs on the segmentation alone.
    const bool ctGiven = inputLumenSegmentation.empty() || inputLumenSegmentation != inputVolume;
    if (!ctGiven)
      RequireNoCtOutputs(paths);
    if (inputLumenSegmentation.empty() && !lumenLabels.empty())
      PrintWarnings({ "lumenLabels (" + lumenLabels +
                      ") is used only with inputLumenSegmentation, which was not given; the lumen is grown from the "
                      "CT." },
                    std::cerr);
    if (!configuration.empty() && request.through != PlanStage::Device)
      PrintWarnings({ "configuration (" + configuration +
                      ") is used only when the plan reaches the device (a report, the measurements, the simulated "
                      "graft, the configuration or the return parameters); none was asked for, so it is not read." },
                    std::cerr);
    // The catalogue is read before any heavy work: a broken catalogue or unknown --device fails at once.
    const PlanRunInfo run{ inputVolume,
                           deviceCatalog.empty() ? BesideExecutable(argv[0], "devices.json") : deviceCatalog,
                           neckRules.empty() ? DefaultNeckRulesPath(argv[0]) : neckRules };
    if (request.through >= PlanStage::Measurements)
      params.neckRules = ReadNeckRules(run.neckRules);
    if (request.through == PlanStage::Device)
    {
      params.catalog = ReadDeviceCatalog(run.deviceCatalog);
      if (!params.selection.forcedDevice.empty())
        ParseForcedDevice(params.selection.forcedDevice, params.catalog);
      if (!configuration.empty())
        params.selection.configuration = ReadGivenConfiguration(configuration, params.selection, params.catalog);
    }

    SlicerProgress progress(std::cout, { { "ReadVolume", 2.0 },
                                         { "FindSeed", 0.5 },
                                         { "SegmentLumen", 4.0 },
                                         { "ThinLumen", 2.0 },
                                         { "ExtractCenterlines", 1.0 },
                                         { "FitStent", 2.0 },
                                         { "SegmentOuterWall", 0.5 },
                                         { "MeasureAnatomy", 0.2 },
                                         { "SelectDevice", 0.1 },
                                         { "SimulateGraft", 1.0 },
                                         { "WriteOutputs", 1.0 } });
    progress.Begin("ReadVolume", ctGiven ? "Reading the CT volume" : "Reading the lumen segmentation");
    // ITK's readers' own prints are dropped: a failure is our one ERROR: line (QuietStderr.h). The
    // segmentation first: its mask is small beside the CT, and a bad one fails before the CT is read.
    if (!inputLumenSegmentation.empty())
    {
      GivenLumenFile given =
        clp::WithStderrDropped([&] { return ReadLumenSegmentation(inputLumenSegmentation, lumenLabels); });
      request.givenLumen = given.mask;
      request.givenLumenDescription = given.description;
    }
    CtVolume volume;
    if (ctGiven)
      volume = clp::WithStderrDropped([&] { return ReadCtImage(inputVolume); });
    PrintWarnings(volume.warnings, std::cerr);

    // `labelMapWritten` and `wallLabelMapWritten` are declared after `outputs`, so on an exception
    // they are waited for before the transaction removes the staged files.
    OutputTransaction outputs;
    std::future<void> labelMapWritten, wallLabelMapWritten;
    PlanObserver observer;
    observer.begin = [&](std::string_view name, std::string_view text)
    { progress.Begin(std::string(name), std::string(text)); };
    observer.progress = progress.Callback();
    observer.ownTime = [&](double seconds) { progress.SetOwnTime(seconds); };
    observer.warn = [](const std::string& warning) { PrintWarnings({ warning }, std::cerr); };
    observer.lumenReady = [&](const LumenSegmentation& lumen)
    {
      // The label map is final: compress and write it on the second core while the rest runs.
      if (!paths.labelMap.empty())
        labelMapWritten = std::async(std::launch::async, [mask = lumen.mask, staged = outputs.Stage(paths.labelMap)]
                                     { WriteLabelMap(*mask, staged); });
    };
    observer.wallLabelsReady = [&](const LabelImage::Pointer& labels)
    {
      // Likewise the wall label map, while the plan measures, chooses and deploys the graft.
      if (!paths.wallLabelMap.empty())
        wallLabelMapWritten = std::async(std::launch::async, [labels, staged = outputs.Stage(paths.wallLabelMap)]
                                         { WriteLabelMap(*labels, staged); });
    };
    // The plan takes the only reference to the CT, so the input is freed once the lumen is segmented.
    const std::optional<Point3> seedLps = seed.empty() ? std::nullopt : std::optional<Point3>(RasToLps(seed));
    const RepairPlan plan = PlanRepair(std::move(volume.image), seedLps, request, params, observer);

    progress.Begin("WriteOutputs", "Writing the outputs");
    PlanOutputPaths rest = paths;
    if (wallLabelMapWritten.valid())
      rest.wallLabelMap.clear(); // being written on the second core
    if (!rest.configuration.empty() && !ConfigurationNotWritten(plan).empty())
    {
      PrintWarnings({ ConfigurationNotWritten(plan) }, std::cerr);
      rest.configuration.clear();
    }
    WritePlanOutputs(plan, rest, run, outputs);
    for (std::future<void>* written : { &labelMapWritten, &wallLabelMapWritten })
      if (written->valid())
        written->get(); // rethrows a write error
    if (!paths.returnParameterFile.empty())
      PrintUnmeasuredValues(PlanReturnValues(plan), std::cerr);
    outputs.Commit();
    progress.End();
    PrintPlanSummary(plan, acmMode, std::cout);
    return EXIT_SUCCESS;
  }
  catch (const std::exception& e)
  {
    std::cerr << "ERROR: " << sgp::clp::OneLine(e.what()) << std::endl;
    return EXIT_FAILURE;
  }
}
