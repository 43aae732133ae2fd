// StentGraftSimulation: the SEM command-line module of StentGraftPlanner.
// Sequence (STYLE.md B7): PARSE_ARGS, ValidateParameters, read, convert the seed once, run the
// stages in DESIGN.md's order with progress, write every output at once, return.
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <filesystem>
#include <future>
#include <optional>

#include <nlohmann/json.hpp>

#include <itkObject.h>
#include <vtkObject.h>

#include "AssignInscribedRadii.h"
#include "GrowLumenRegion.h"
#include "IO/WriteCenterlines.h"
#include "CLPSupport.h"
#include "IO/OutputTransaction.h"
#include "IO/ReadCtImage.h"
#include "IO/DeviceSelectionToJson.h"
#include "IO/ReadDeviceCatalog.h"
#include "IO/WriteImage.h"
#include "IO/WriteMeasurements.h"
#include "IO/WriteReturnParameters.h"
#include "IO/WriteStentModel.h"
#include "IO/WriteTextFile.h"
#include "Errors.h"
#include "FitCheck.h"
#include "Format.h"
#include "MeasureAnatomy.h"
#include "SelectDevice.h"
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

/// The device catalogue installed beside the executable (CMake copies Resources/devices.json
/// there, in the build tree and on install).
std::string DefaultDeviceCatalog(const char* argv0)
{
  std::error_code error;
  std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error)
    exe = std::filesystem::absolute(argv0, error);
  return (exe.parent_path() / "devices.json").string();
}

/// The family to simulate: the recommended one, else the one with all three sizes chosen and the
/// fewest failing checks (so that a plan outside every IFU still shows how the nearest graft
/// sits); −1 when no family has all three sizes.
int FamilyToSimulate(const sgp::DeviceSelection& selection)
{
  const auto complete = [](const sgp::FamilyEvaluation& f)
  { return f.mainBody.Chosen() && f.rightLimb.Chosen() && f.leftLimb.Chosen(); };
  if (selection.recommended >= 0 && complete(selection.families[selection.recommended]))
    return selection.recommended;
  int best = -1;
  for (int i = 0; i < static_cast<int>(selection.families.size()); ++i)
    if (complete(selection.families[i]) && (best < 0 || selection.families[i].Count(sgp::CheckStatus::Fail) <
                                                          selection.families[best].Count(sgp::CheckStatus::Fail)))
      best = i;
  return best;
}

/// A measurement, size or length as a return value: −1 when there is none (every such value is
/// positive when measured; the XML says so).
std::string OrMinusOne(double value)
{
  return sgp::FormatReturnValue(std::isfinite(value) ? value : -1.0);
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
    StentMeshParams meshParams = MakeStentMeshParams(verticesPerRing, ringSpacingMm, startRadiusMm, proximalStartMm);
    const ActiveContourParams acmParams =
      MakeActiveContourParams(acmMode, measureStiffnessWeights, measureBalloonRadiusMm, measureBalloonPressure,
                              stentDiametersMm, stentStiffnessWeights, stentBalloonPressure, acmTau, wallWeight,
                              wallSofteningMm, acmMaxIterations, acmToleranceMm);
    // Measurements are always read off a measure-mode fit (paper, section 2.2).
    const ActiveContourParams measureParams =
      MakeActiveContourParams("measure", measureStiffnessWeights, measureBalloonRadiusMm, measureBalloonPressure,
                              stentDiametersMm, stentStiffnessWeights, stentBalloonPressure, acmTau, wallWeight,
                              wallSofteningMm, acmMaxIterations, acmToleranceMm);
    ValidateParameters(inputVolume, seed, growParams, graphParams, centerlineParams, meshParams, acmParams);
    std::optional<Point3> lowestRenalOstiumLps;
    if (!lowestRenalOstium.empty())
      lowestRenalOstiumLps = RasToLps(lowestRenalOstium);
    const bool wantDevice = !outputSimulatedStentModel.empty() || !outputReport.empty() || !outputMeasurements.empty();
    const bool wantMeasurements = wantDevice || !outputDiameterProfile.empty();
    const bool wantStent = wantMeasurements || !outputStentModel.empty() || !outputInitialStentModel.empty();
    const DeviceSelectionParams selectionParams =
      MakeDeviceSelectionParams(device, proximalOversizingRange, limbOversizingRange);
    // The catalogue is read before any heavy work: a broken catalogue fails at once.
    const std::string catalogPath = deviceCatalog.empty() ? DefaultDeviceCatalog(argv[0]) : deviceCatalog;
    DeviceCatalog catalog;
    if (wantDevice)
    {
      catalog = ReadDeviceCatalog(catalogPath);
      if (!selectionParams.forcedDevice.empty())
        ParseForcedDevice(selectionParams.forcedDevice, catalog); // an unknown device fails here, not after the fit
    }
    const bool wantCenterlines = wantStent || !outputCenterlines.empty() || !outputLandmarks.empty();
    SlicerProgress progress(std::cout, { { "ReadVolume", 2.0 },
                                         { "SegmentLumen", 4.0 },
                                         { "ThinLumen", 2.0 },
                                         { "ExtractCenterlines", 1.0 },
                                         { "FitStent", 2.0 },
                                         { "MeasureAnatomy", 0.2 },
                                         { "SelectDevice", 0.1 },
                                         { "SimulateGraft", 1.0 },
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
    // The label map is final now: compress and write it on the second core while the rest runs.
    // (`labelMapWritten` is declared after `outputs`, so on an exception it is waited for before
    // the transaction removes the staged file.)
    OutputTransaction outputs;
    std::future<void> labelMapWritten;
    if (!outputLabelMap.empty())
    {
      labelMapWritten = std::async(std::launch::async, [&lumen, staged = outputs.Stage(outputLabelMap)]
                                   { WriteLabelMap(*lumen.mask, staged); });
    }

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
    StentMesh mesh;
    ActiveContourResult fit;
    Measurements measurements;
    DeviceSelection selection;
    int simulatedFamily = -1;
    std::array<double, 3> graftDiameters{ 0.0, 0.0, 0.0 };
    ActiveContourResult simulated;
    FitCheck fitCheck;
    Eigen::VectorXd initialRadius, initialWallDistance;
    if (wantStent)
    {
      progress.Begin("FitStent", "Fitting the bifurcated stent surface (active contour)");
      const ProximalSite site = FindProximalSite(centerlines, lowestRenalOstiumLps);
      if (!wantMeasurements && !site.warning.empty()) // otherwise among the measurements' warnings
        std::cerr << "WARNING: " << site.warning << std::endl;
      if (meshParams.proximalAbscissaMm < 0.0)
        meshParams.proximalAbscissaMm = site.abscissaMm;
      mesh = BuildStentMesh(centerlines, meshParams);
      const WallDistanceField wall = WallDistanceField::FromLumen(*lumen.mask, 5.0, StentReach(mesh, centerlines));
      if (!outputInitialStentModel.empty()) // only that output needs the initial surface's values
      {
        initialRadius = Eigen::VectorXd::Constant(mesh.V.rows(), meshParams.startRadiusMm);
        initialWallDistance.resize(mesh.V.rows());
        for (Eigen::Index i = 0; i < mesh.V.rows(); ++i)
          initialWallDistance[i] = wall.Sample(mesh.V.row(i).transpose());
      }
      fit = FitActiveContour(mesh, wall, acmParams, progress.Callback());
      acmIterations = fit.iterations;
      acmConverged = fit.converged;
      if (!fit.converged)
        std::cerr << "WARNING: The active contour did not converge within " << fit.iterations
                  << " iterations (acmMaxIterations); the surface written is the last one." << std::endl;
      if (wantMeasurements)
      {
        progress.Begin("MeasureAnatomy", "Measuring diameters, lengths and angles");
        ActiveContourResult measureFit;
        if (acmMode != "measure")
          measureFit = FitActiveContour(mesh, wall, measureParams);
        measurements = MeasureAnatomy(centerlines, mesh, acmMode == "measure" ? fit.V : measureFit.V, site);
        PrintWarnings(measurements.warnings); // the site's first, if any
      }
      if (wantDevice)
      {
        progress.Begin("SelectDevice", "Choosing the stent graft from the device catalogue");
        selection = SelectDevice(SizingFromMeasurements(measurements), catalog, selectionParams);
        simulatedFamily = FamilyToSimulate(selection);
        if (simulatedFamily >= 0)
        {
          progress.Begin("SimulateGraft", "Simulating the chosen stent graft in the vessel");
          const FamilyEvaluation& family = selection.families[simulatedFamily];
          graftDiameters = { family.mainBody.diameterMm, family.rightLimb.diameterMm, family.leftLimb.diameterMm };
          const ActiveContourParams graftParams = MakeActiveContourParams(
            "simulate", measureStiffnessWeights, measureBalloonRadiusMm, measureBalloonPressure,
            { graftDiameters[0], graftDiameters[1], graftDiameters[2] }, stentStiffnessWeights, stentBalloonPressure,
            acmTau, wallWeight, wallSofteningMm, acmMaxIterations, acmToleranceMm);
          simulated = FitActiveContour(mesh, wall, graftParams, progress.Callback());
          fitCheck =
            CheckGraftFit(mesh, simulated.V, simulated.wallDistanceMm, measurements, centerlines, graftDiameters);
          if (selection.recommended < 0)
            std::cerr << "WARNING: No device is within its instructions for use; the graft simulated is the nearest, "
                      << family.family << " (outside its IFU)." << std::endl;
        }
        else if (!outputSimulatedStentModel.empty())
        {
          throw AlgorithmError("No catalogue device has a main body and both limbs within the oversizing ranges (" +
                               selection.summary +
                               "), so there is no graft to simulate for outputSimulatedStentModel; "
                               "widen proximalOversizingRange or limbOversizingRange, or force one with --device.");
        }
      }
    }

    progress.Begin("WriteOutputs", "Writing the outputs");
    if (labelMapWritten.valid())
    {
      labelMapWritten.get(); // rethrows a write error
    }
    if (!outputCenterlines.empty())
    {
      WriteCenterlines(centerlines, outputs.Stage(outputCenterlines));
    }
    if (!outputLandmarks.empty())
    {
      WriteLandmarks(centerlines, outputs.Stage(outputLandmarks));
    }
    if (!outputInitialStentModel.empty())
    {
      WriteStentModel(mesh, mesh.V, initialRadius, initialWallDistance, outputs.Stage(outputInitialStentModel));
    }
    if (!outputStentModel.empty())
    {
      WriteStentModel(mesh, fit.V, fit.radiusMm, fit.wallDistanceMm, outputs.Stage(outputStentModel));
    }
    // The table and the return values: the measurements, then the device's sizes and the fit check.
    std::vector<Measurement> rows = measurements.values;
    if (simulatedFamily >= 0)
    {
      const FamilyEvaluation& family = selection.families[simulatedFamily];
      const std::string name = family.family + (selection.recommended == simulatedFamily ? "" : " (outside IFU)");
      rows.push_back({ "mainBodyDiameter", family.mainBody.diameterMm, "mm",
                       name + " main body, " + FormatNumber(family.mainBody.oversizingPercent) + " % over (a)", "aorta",
                       measurements.site.abscissaMm });
      rows.push_back({ "rightLimbDiameter", family.rightLimb.diameterMm, "mm",
                       name + " right limb, " + FormatNumber(family.rightLimb.oversizingPercent) + " % over (e)",
                       "rightIliac", mesh.ringAbscissaMm[RightLegSegment].back() });
      rows.push_back({ "leftLimbDiameter", family.leftLimb.diameterMm, "mm",
                       name + " left limb, " + FormatNumber(family.leftLimb.oversizingPercent) + " % over (f)",
                       "leftIliac", mesh.ringAbscissaMm[LeftLegSegment].back() });
      for (const Measurement& m : FitCheckRows(fitCheck, mesh))
        rows.push_back(m);
    }
    if (!outputMeasurements.empty())
    {
      WriteMeasurementsTable(rows, outputs.Stage(outputMeasurements));
    }
    if (!outputSimulatedStentModel.empty())
    {
      WriteStentModel(mesh, simulated.V, simulated.radiusMm, simulated.wallDistanceMm,
                      { { "Oversizing", fitCheck.oversizingPercent },
                        { "Apposition", fitCheck.appositionMm },
                        { "Sealing", fitCheck.sealing.cast<double>() } },
                      outputs.Stage(outputSimulatedStentModel));
    }
    if (!outputDiameterProfile.empty())
    {
      WriteDiameterProfiles(measurements, outputs.Stage(outputDiameterProfile));
    }
    if (!outputReport.empty())
    {
      nlohmann::json report = MeasurementsToJson(measurements);
      report["format"] = "StentGraftPlanner.report/1";
      report["notes"] = { "Diameters are lumen diameters (wall to wall of the contrast-filled lumen); instructions for "
                          "use give outer-wall diameters, so sizes are under-called where there is thrombus or a thick "
                          "wall.",
                          "Device figures come from the catalogue " + catalogPath +
                            ": public defaults, verify them against the current instructions for use." };
      report["device"] = DeviceSelectionToJson(selection);
      report["device"]["simulated"] =
        simulatedFamily >= 0 ? nlohmann::json(selection.families[simulatedFamily].family) : nlohmann::json(nullptr);
      report["fitCheck"] = simulatedFamily >= 0 ? FitCheckToJson(fitCheck) : nlohmann::json(nullptr);
      report["run"] = { { "inputVolume", inputVolume },
                        { "lumenVolumeMl", lumenVolumeMl },
                        { "acmIterations", acmIterations },
                        { "acmConverged", static_cast<bool>(acmConverged) } };
      WriteTextFile(report.dump(2) + "\n", outputs.Stage(outputReport), "planning report");
    }
    if (!returnParameterFile.empty())
    {
      ReturnValues values = {
        { "lumenVolumeMl", FormatReturnValue(lumenVolumeMl) }, { "lowerHuUsed", FormatReturnValue(lowerHuUsed) },
        { "upperHuUsed", FormatReturnValue(upperHuUsed) },     { "edgeHuUsed", FormatReturnValue(edgeHuUsed) },
        { "acmIterations", std::to_string(acmIterations) },    { "acmConverged", acmConverged ? "true" : "false" }
      };
      if (wantMeasurements)
      {
        for (const Measurement& m : rows) // the measurements, then the device's rows
          values.emplace_back(m.name, OrMinusOne(m.value));
        values.emplace_back("proximalSiteSource", ToString(measurements.site.source));
      }
      if (wantDevice)
      {
        const bool simulatedAny = simulatedFamily >= 0;
        values.emplace_back("recommendedDevice",
                            selection.recommended >= 0 ? selection.families[selection.recommended].family : "none");
        values.emplace_back("withinIfu",
                            selection.recommended >= 0 && selection.recommendedWithinIfu ? "true" : "false");
        values.emplace_back("coveredOstia", simulatedAny ? fitCheck.CoveredOstia() : "none");
        values.emplace_back("migrationRisk", simulatedAny && fitCheck.migrationRisk ? "true" : "false");
        values.emplace_back("fitCheckPassed", simulatedAny && fitCheck.Passed() ? "true" : "false");
      }
      WriteReturnParameters(values, outputs.Stage(returnParameterFile));
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
    if (wantStent)
    {
      std::cout << "Stent surface: " << mesh.V.rows() << " vertices, " << acmMode << " mode, "
                << (fit.converged ? "converged" : "not converged") << " after " << fit.iterations << " iterations"
                << std::endl;
    }
    if (wantDevice)
    {
      std::cout << "Device: " << selection.summary << std::endl;
      for (const std::string& reason : selection.reasons)
        std::cout << "  " << reason << std::endl;
      if (simulatedFamily >= 0)
      {
        std::cout << "Simulated graft (" << selection.families[simulatedFamily].family << "): proximal seal "
                  << FormatNumber(fitCheck.proximalSealLengthMm) << " mm, iliac seal right "
                  << FormatNumber(fitCheck.rightIliacSealLengthMm) << " mm / left "
                  << FormatNumber(fitCheck.leftIliacSealLengthMm) << " mm, covered ostia: " << fitCheck.CoveredOstia()
                  << "; fit check " << (fitCheck.Passed() ? "passed" : "FAILED") << std::endl;
        for (const std::string& finding : fitCheck.findings)
          std::cout << "  " << finding << std::endl;
      }
    }
    if (wantMeasurements)
    {
      std::cout << "Proximal site (" << ToString(measurements.site.source) << ") at "
                << FormatReturnValue(measurements.site.abscissaMm) << " mm along the aorta" << std::endl;
      for (const Measurement& m : measurements.values)
        std::cout << "  " << m.name << " = "
                  << (std::isfinite(m.value) ? FormatReturnValue(m.value) + " " + m.unit : std::string("not measured"))
                  << std::endl;
    }
    return EXIT_SUCCESS;
  }
  catch (const std::exception& e)
  {
    std::cerr << "ERROR: " << sgp::clp::OneLine(e.what()) << std::endl;
    return EXIT_FAILURE;
  }
}
