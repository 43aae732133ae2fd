/// \file WritePlanOutputs.h
/// A RepairPlan's files: which outputs a front end asked for (paths; empty = not asked), the
/// stages those outputs need (PlanRequestFor), and the writing of each through an
/// OutputTransaction, so that a run leaves every requested output or none.
///
/// Models are written in LPS with SPACE=LPS; tables as CSV; the report as JSON
/// (`StentGraftPlanner.report/1`); the return-parameter file with every return value
/// (PlanValues.h). Needs a plan that reached the stage each asked output depends on (the plan
/// made from PlanRequestFor(paths) does).
/// \throws InputError naming the path when a file cannot be written; std::logic_error when the
///         plan did not reach a stage an asked output needs.
#pragma once

#include <string>

#include "IO/OutputTransaction.h"
#include "Pipeline/PlanRepair.h"

namespace sgp
{

struct PlanOutputPaths
{
  std::string labelMap;          ///< the lumen, on the input's grid
  std::string wallLabelMap;      ///< lumen 1, thrombus and wall 2, calcium 3, on the input's grid
  std::string outerWallModel;    ///< the traced outer wall, .vtp
  std::string centerlines;       ///< .vtp
  std::string landmarks;         ///< .mrk.json
  std::string stentModel;        ///< the fitted surface
  std::string initialStentModel; ///< the surface before the fit
  /// The simulated graft with its components and fit check as point data: Component (index into
  /// the report's deployment.components), ComponentRole (OrderRole: 0 main body, 1 ipsilateral
  /// limb, 2 contralateral limb, 3 iliac extension, 4 aortic cuff), InnerComponent (−1 outside
  /// overlaps), NominalRadius (mm), Oversizing (%), Apposition (mm), HealthyWall (1, 0, −1 not
  /// traced), ThrombusUnder (mm, NaN not traced), Calcified (1, 0, −1), Sealing (0/1).
  std::string simulatedStentModel;
  std::string measurements;    ///< the table, .csv
  std::string diameterProfile; ///< per ring, .csv
  std::string report;          ///< the whole plan, .json
  std::string reportHtml;      ///< the visual report, self-contained .html (ReportHtml.h)
  /// The configuration simulated, in the format --configuration reads (ConfigurationFile.h); not
  /// written (a warning in the plan's report) when none was configured.
  std::string configuration;
  std::string straightenedVolume;     ///< the CT straightened along aorta → right iliac (ResliceCt.h)
  std::string straightenedLeftVolume; ///< likewise along aorta → left iliac
  std::string returnParameterFile;    ///< SEM return values; asks for the whole plan
};

/// What the report says of the run beside the plan.
struct PlanRunInfo
{
  std::string inputVolume;
  std::string deviceCatalog; ///< the catalogue's path
  std::string neckRules;     ///< the hostile-neck rules' path
};

/// The stages `paths` need: the whole plan for the return values (Slicer always asks for them,
/// and its panel keeps stale values of any that is missing), the measurements table or the
/// report (JSON or HTML; the HTML one keeps the CT crop for its images); measurements for the
/// diameter profile, the wall outputs and the straightened volumes (with the CT crop); the fitted surface for the stent
/// models; centerlines for centerlines or landmarks; else the segmentation only.
PlanRequest PlanRequestFor(const PlanOutputPaths& paths);

/// Why the configuration file cannot be written (no configuration was made: a result, so the front
/// end warns and leaves the output out), a sentence; "" when it can.
std::string ConfigurationNotWritten(const RepairPlan& plan);

/// Writes every output named in `paths` except the label map (the front end writes that as soon
/// as the lumen is final; see PlanObserver) to `outputs`' staged paths; Commit() is the caller's.
void WritePlanOutputs(const RepairPlan& plan,
                      const PlanOutputPaths& paths,
                      const PlanRunInfo& run,
                      OutputTransaction& outputs);

} // namespace sgp
