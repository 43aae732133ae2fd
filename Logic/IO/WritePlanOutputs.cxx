#include "IO/WritePlanOutputs.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "IO/ConfigurationFile.h"
#include "IO/DeploymentToJson.h"
#include "IO/DeviceSelectionToJson.h"
#include "IO/ReportHtml.h"
#include "IO/WriteCenterlines.h"
#include "IO/WriteImage.h"
#include "IO/WriteMeasurements.h"
#include "IO/WriteOuterWallModel.h"
#include "IO/WriteReturnParameters.h"
#include "IO/WriteStentModel.h"
#include "IO/WriteTextFile.h"
#include "Pipeline/PlanValues.h"
#include "Views/ReportFigures.h"
#include "Views/ResliceCt.h"
#include "Views/VesselPath.h"

namespace sgp
{
namespace
{

void Require(const RepairPlan& plan, PlanStage stage, const char* output)
{
  if (!plan.Reached(stage))
    throw std::logic_error(std::string("WritePlanOutputs: ") + output + " was asked for, but the plan stopped earlier");
}

nlohmann::json PlanReportJson(const RepairPlan& plan, const PlanRunInfo& run)
{
  nlohmann::json report = MeasurementsToJson(plan.measurements);
  report["format"] = "StentGraftPlanner.report/1";
  report["notes"] = { "(a)-(f) are outer wall to outer wall, perpendicular to the centerline, as instructions for "
                      "use and guidelines size; the lumen values are listed beside them. Each measurement's wall "
                      "field says which it is; estimated marks an outer diameter where less than 60 % of the "
                      "circumference showed a visible outer boundary.",
                      "Device figures come from the catalogue " + run.deviceCatalog +
                        ": public defaults, verify them against the current instructions for use." };
  report["hostileNeck"] =
    plan.neck.checks.empty() ? nlohmann::json(nullptr) : NeckAssessmentToJson(plan.neck, run.neckRules);
  report["device"] = DeviceSelectionToJson(plan.selection);
  report["device"]["simulated"] =
    plan.HasGraft() ? nlohmann::json(plan.selection.families[plan.simulatedFamily].family) : nlohmann::json(nullptr);
  // Why no graft was simulated (the simulated model is then empty); null when one was.
  report["device"]["notSimulated"] =
    plan.HasGraft()
      ? nlohmann::json(nullptr)
      : nlohmann::json(plan.notSimulatedReason.empty() ? "No graft was simulated" : plan.notSimulatedReason);
  report["deployment"] = DeploymentToJson(plan);
  report["fitCheck"] = plan.HasGraft() ? FitCheckToJson(plan.fitCheck) : nlohmann::json(nullptr);
  const VesselWall& wall = plan.vesselWall;
  nlohmann::json planes = nlohmann::json::object();
  for (int v = 0; v < 3; ++v)
  {
    nlohmann::json rows = nlohmann::json::array();
    for (const OuterWallPlane& p : wall.vessels[v].planes)
      rows.push_back({ p.abscissaMm, p.areaDiameterMm, p.minCaliperMm, p.maxCaliperMm, p.supportedFraction,
                       p.thrombusMm.size() > 0 ? p.thrombusMm.maxCoeff() : 0.0,
                       2.0 * std::sqrt(p.lumenAreaMm2 / 3.14159265358979323846), p.centreLps.x(), p.centreLps.y(),
                       p.centreLps.z() });
    planes[wall.names[v]] = rows;
  }
  report["outerWall"] = { { "method", "radial model: rays from the lumen centerline, half-maximum wall-to-fat edge, "
                                      "robust circle where no fat plane shows (Macia et al. 2009)" },
                          { "wallThicknessMm", wall.wallThicknessMm },
                          { "wallThicknessMeasured", wall.wallThicknessEstimated },
                          { "calciumHu", wall.calciumHu },
                          { "planeColumns",
                            { "abscissaMm", "areaDiameterMm", "minCaliperMm", "maxCaliperMm", "supportedFraction",
                              "maxThrombusMm", "lumenAreaDiameterMm", "centreX", "centreY", "centreZ" } },
                          { "planes", planes } };
  report["run"] = { { "inputVolume", run.inputVolume },
                    { "lumenVolumeMl", plan.lumen.volumeMl },
                    { "lumenSource", plan.lumenGiven ? "given" : "grown" },
                    { "lumenFrom", plan.lumen.windowSource },
                    { "acmIterations", plan.fit.iterations },
                    { "acmConverged", plan.fit.converged } };
  return report;
}

const CtImage& CtOf(const RepairPlan& plan)
{
  if (!plan.ctAroundLumen)
    throw std::logic_error("WritePlanOutputs: a view of the CT was asked for, but PlanRequest::ctAroundLumen was not");
  return *plan.ctAroundLumen;
}

/// The straightened volume's voxel: the CT's finest spacing, at least 0.5 mm (finer only adds
/// interpolated voxels), at most 1 mm.
double StraightenedStepMm(const CtImage& ct)
{
  const auto sp = ct.GetSpacing();
  return std::clamp(std::min({ sp[0], sp[1], sp[2] }), 0.5, 1.0);
}

/// Across the straightened volume: ±40 mm holds a 66 mm sac with its wall.
constexpr double StraightenedHalfWidthMm = 40.0;

/// The simulated graft: its components per vertex and the fit check's values (WriteStentModel.h).
void WriteSimulatedGraft(const RepairPlan& plan, const std::string& path)
{
  const GraftLayout& layout = plan.graft.layout;
  Eigen::VectorXd role(layout.component.size());
  for (Eigen::Index i = 0; i < role.size(); ++i)
    role[i] = double(int(layout.components[std::size_t(layout.component[i])].role));
  WriteStentModel(layout.mesh, plan.graft.fit.V, plan.graft.fit.radiusMm, plan.graft.fit.wallDistanceMm,
                  { { "Component", layout.component.cast<double>() },
                    { "ComponentRole", role },
                    { "InnerComponent", layout.innerComponent.cast<double>() },
                    { "NominalRadius", layout.nominalRadiusMm },
                    { "Oversizing", plan.fitCheck.oversizingPercent },
                    { "Apposition", plan.fitCheck.appositionMm },
                    { "HealthyWall", plan.fitCheck.healthyWall.cast<double>() },
                    { "ThrombusUnder", plan.fitCheck.thrombusUnderMm },
                    { "Calcified", plan.fitCheck.calcified.cast<double>() },
                    { "Sealing", plan.fitCheck.sealing.cast<double>() } },
                  path);
}

} // namespace

PlanRequest PlanRequestFor(const PlanOutputPaths& paths)
{
  PlanRequest request;
  const bool straightened = !paths.straightenedVolume.empty() || !paths.straightenedLeftVolume.empty();
  if (!paths.returnParameterFile.empty() || !paths.simulatedStentModel.empty() || !paths.report.empty() ||
      !paths.reportHtml.empty() || !paths.measurements.empty() || !paths.configuration.empty())
    request.through = PlanStage::Device;
  else if (!paths.diameterProfile.empty() || !paths.wallLabelMap.empty() || !paths.outerWallModel.empty() ||
           straightened)
    request.through = PlanStage::Measurements;
  else if (!paths.stentModel.empty() || !paths.initialStentModel.empty())
    request.through = PlanStage::StentSurface;
  else if (!paths.centerlines.empty() || !paths.landmarks.empty())
    request.through = PlanStage::Centerlines;
  else
    request.through = PlanStage::Segmentation;
  request.initialSurfaceValues = !paths.initialStentModel.empty();
  request.wallLabelMap = !paths.wallLabelMap.empty();
  request.ctAroundLumen = straightened || !paths.reportHtml.empty();
  return request;
}

std::string ConfigurationNotWritten(const RepairPlan& plan)
{
  const DeviceConfiguration* c = plan.Configuration();
  if (c && c->configured)
    return "";
  return "No configuration was made (" +
         (c                                 ? c->unknownReason
          : plan.notSimulatedReason.empty() ? std::string("no family has a main body for this neck")
                                            : plan.notSimulatedReason) +
         "), so outputConfiguration is not written.";
}

void WritePlanOutputs(const RepairPlan& plan,
                      const PlanOutputPaths& paths,
                      const PlanRunInfo& run,
                      OutputTransaction& outputs)
{
  if (!paths.centerlines.empty())
  {
    Require(plan, PlanStage::Centerlines, "outputCenterlines");
    WriteCenterlines(plan.centerlines, outputs.Stage(paths.centerlines));
  }
  if (!paths.landmarks.empty())
  {
    Require(plan, PlanStage::Centerlines, "outputLandmarks");
    WriteLandmarks(plan.centerlines, outputs.Stage(paths.landmarks),
                   plan.Reached(PlanStage::Measurements) ? &plan.measurements : nullptr);
  }
  if (!paths.initialStentModel.empty())
  {
    Require(plan, PlanStage::StentSurface, "outputInitialStentModel");
    WriteStentModel(plan.mesh, plan.mesh.V, plan.initialRadiusMm, plan.initialWallDistanceMm,
                    outputs.Stage(paths.initialStentModel));
  }
  if (!paths.stentModel.empty())
  {
    Require(plan, PlanStage::StentSurface, "outputStentModel");
    WriteStentModel(plan.mesh, plan.fit.V, plan.fit.radiusMm, plan.fit.wallDistanceMm, outputs.Stage(paths.stentModel));
  }
  if (!paths.measurements.empty())
  {
    Require(plan, PlanStage::Device, "outputMeasurements");
    WriteMeasurementsTable(plan.rows, outputs.Stage(paths.measurements));
  }
  if (!paths.simulatedStentModel.empty())
  {
    Require(plan, PlanStage::Device, "outputSimulatedStentModel");
    if (!plan.HasGraft())
      WriteNotSimulatedModel(plan.notSimulatedReason.empty() ? "No graft was simulated" : plan.notSimulatedReason,
                             outputs.Stage(paths.simulatedStentModel));
    else
      WriteSimulatedGraft(plan, outputs.Stage(paths.simulatedStentModel));
  }
  if (!paths.wallLabelMap.empty())
  {
    Require(plan, PlanStage::Measurements, "outputWallLabelMap");
    if (!plan.wallLabels)
      throw std::logic_error(
        "WritePlanOutputs: outputWallLabelMap was asked for, but PlanRequest::wallLabelMap was not");
    WriteLabelMap(*plan.wallLabels, outputs.Stage(paths.wallLabelMap));
  }
  if (!paths.outerWallModel.empty())
  {
    Require(plan, PlanStage::Measurements, "outputOuterWallModel");
    WriteOuterWallModel(plan.vesselWall, outputs.Stage(paths.outerWallModel));
  }
  if (!paths.diameterProfile.empty())
  {
    Require(plan, PlanStage::Measurements, "outputDiameterProfile");
    WriteDiameterProfiles(plan.measurements, outputs.Stage(paths.diameterProfile));
  }
  if (!paths.report.empty())
  {
    Require(plan, PlanStage::Device, "outputReport");
    WriteTextFile(PlanReportJson(plan, run).dump(2) + "\n", outputs.Stage(paths.report), "planning report");
  }
  const std::string* straightened[2] = { &paths.straightenedVolume, &paths.straightenedLeftVolume };
  for (int side = 0; side < 2; ++side)
    if (!straightened[side]->empty())
    {
      Require(plan, PlanStage::Measurements, side == 0 ? "outputStraightenedVolume" : "outputStraightenedLeftVolume");
      const CtImage& ct = CtOf(plan);
      const Centerline& iliac = side == 0 ? plan.centerlines.rightIliac : plan.centerlines.leftIliac;
      const VesselPath path = SampleVesselPath(plan.centerlines.aorta, iliac, StraightenedStepMm(ct));
      WriteCtImage(*StraightenVolume(ct, path, StraightenedHalfWidthMm), outputs.Stage(*straightened[side]));
    }
  if (!paths.reportHtml.empty())
  {
    Require(plan, PlanStage::Device, "outputReportHtml");
    const ReportFigures figures = BuildReportFigures(plan, CtOf(plan));
    const ReportRun about{ run.inputVolume, run.deviceCatalog, run.neckRules, ReportDateNow(), SGP_VERSION };
    WriteTextFile(ReportHtml(plan, figures, about), outputs.Stage(paths.reportHtml), "visual planning report");
  }
  if (!paths.configuration.empty())
  {
    Require(plan, PlanStage::Device, "outputConfiguration");
    if (!ConfigurationNotWritten(plan).empty())
      throw std::logic_error("WritePlanOutputs: outputConfiguration was asked for, but no configuration was made "
                             "(the front end leaves it out: ConfigurationNotWritten)");
    const DeviceConfiguration* c = plan.Configuration();
    WriteTextFile(
      ConfigurationJson(GivenFromConfiguration(*c, plan.deploymentTargetAbscissaMm - plan.measurements.site.abscissaMm),
                        std::string(c->given ? "Given" : "Recommended") + " configuration for " + run.inputVolume),
      outputs.Stage(paths.configuration), "configuration");
  }
  if (!paths.returnParameterFile.empty())
  {
    ReturnValues values;
    for (const PlanValue& v : PlanReturnValues(plan))
      values.emplace_back(v.name, v.text);
    WriteReturnParameters(values, outputs.Stage(paths.returnParameterFile));
  }
}

} // namespace sgp
