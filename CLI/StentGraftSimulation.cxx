// StentGraftSimulation: the SEM command-line module of StentGraftPlanner.
// Sequence (STYLE.md B7): PARSE_ARGS, ValidateParameters, read, convert the seed once, run the
// stages in DESIGN.md's order with progress, write every output at once, return.
#include <cmath>
#include <cstdlib>
#include <iostream>
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
#include "IO/WriteImage.h"
#include "IO/WriteMeasurements.h"
#include "IO/WriteReturnParameters.h"
#include "IO/WriteStentModel.h"
#include "IO/WriteTextFile.h"
#include "MeasureAnatomy.h"
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

/// A measurement as a return value: −1 when it could not be measured (every such value is
/// positive when measured; the XML says so).
std::string ReturnMeasurement(const sgp::Measurements& m, const std::string& name)
{
  const double value = m.Value(name);
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
    const bool wantMeasurements =
      !outputMeasurements.empty() || !outputDiameterProfile.empty() || !outputReport.empty();
    const bool wantStent = wantMeasurements || !outputStentModel.empty() || !outputInitialStentModel.empty();
    const bool wantCenterlines = wantStent || !outputCenterlines.empty() || !outputLandmarks.empty();
    SlicerProgress progress(std::cout, { { "ReadVolume", 2.0 },
                                         { "SegmentLumen", 4.0 },
                                         { "ThinLumen", 2.0 },
                                         { "ExtractCenterlines", 1.0 },
                                         { "FitStent", 2.0 },
                                         { "MeasureAnatomy", 0.2 },
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
    StentMesh mesh;
    ActiveContourResult fit;
    Measurements measurements;
    Eigen::VectorXd initialRadius, initialWallDistance;
    if (wantStent)
    {
      progress.Begin("FitStent", "Fitting the bifurcated stent surface (active contour)");
      const ProximalSite site = FindProximalSite(centerlines, lowestRenalOstiumLps);
      if (!site.warning.empty())
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
        for (std::size_t i = site.warning.empty() ? 0 : 1; i < measurements.warnings.size(); ++i)
          std::cerr << "WARNING: " << measurements.warnings[i] << std::endl;
      }
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
    if (!outputInitialStentModel.empty())
    {
      WriteStentModel(mesh, mesh.V, initialRadius, initialWallDistance, outputs.Stage(outputInitialStentModel));
    }
    if (!outputStentModel.empty())
    {
      WriteStentModel(mesh, fit.V, fit.radiusMm, fit.wallDistanceMm, outputs.Stage(outputStentModel));
    }
    if (!outputMeasurements.empty())
    {
      WriteMeasurementsTable(measurements, outputs.Stage(outputMeasurements));
    }
    if (!outputDiameterProfile.empty())
    {
      WriteDiameterProfiles(measurements, outputs.Stage(outputDiameterProfile));
    }
    if (!outputReport.empty())
    {
      nlohmann::json report = MeasurementsToJson(measurements);
      report["format"] = "StentGraftPlanner.report/1";
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
        for (const Measurement& m : measurements.values)
          values.emplace_back(m.name, ReturnMeasurement(measurements, m.name));
        values.emplace_back("proximalSiteSource", ToString(measurements.site.source));
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
