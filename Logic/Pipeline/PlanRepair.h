/// \file PlanRepair.h
/// The whole planning job as one pure function: DESIGN.md's data flow chained into a RepairPlan
/// that every front end (the CLI and through it the Slicer panel, reports, cohort runs) consumes.
///
///   CT ──► GrowLumenRegion ──► ThinLabelMap ──► BuildSkeletonGraph ──► LabelAortoIliacTree
///      ──► AssignInscribedRadii ──► FindProximalSite ──► BuildStentMesh ──► WallDistanceField
///      ──► FitActiveContour (acmMode) [──► FitActiveContour (measure) when acmMode is simulate]
///      ──► TraceVesselWall (outer wall, thrombus, calcium) [──► WallLabelMap when asked]
///      ──► MeasureAnatomy ──► SelectDevice (with ConfigureDevice: the components' lengths)
///      ──► FitActiveContour (simulate, the device's radii) ──► CheckGraftFit
///
/// `PlanRequest::through` says how far to go; each stage needs those before it. Stage names (the
/// `name` passed to PlanObserver::begin, in this order): FindSeed (only without a seed), SegmentLumen, ThinLumen,
/// ExtractCenterlines, FitStent, SegmentOuterWall, MeasureAnatomy, SelectDevice, SimulateGraft (the
/// last only when a family has all three sizes).
///
/// The wall stage runs on a second thread while the stent surface is fitted (it needs the site,
/// not the fit); its stage is begun, and its warnings reported, after the fit.
///
/// The simulated graft expands against the lumen (it presses on the thrombus, not through it);
/// sizing uses the diameters each family's IFU names (outer wall for the shipped catalogue).
/// A **partial plan** (the scan ends 10–40 mm below the bifurcation: LabelAortoIliacTree.h,
/// MeasureAnatomy.h) has no limb sizes: the main body alone is simulated, for the proximal part of
/// the fit check; a warning says so, and the limb checks are indeterminate.
///
/// Memory: the CT is taken by pointer and this function drops its reference once the lumen is
/// segmented, keeping (when the plan goes on to the measurements) only a crop around the lumen,
/// grown by the outer-wall rays' reach, for the wall stage; the crop goes once the wall is traced.
/// So a caller that hands over its only reference (std::move) frees the full-resolution input
/// before thinning starts. With PlanRequest::ctAroundLumen the crop is kept in the plan.
///
/// Frames and units: every point LPS mm, diameters and lengths mm, angles degrees.
/// Errors: InputError and AlgorithmError from the stages (their messages name the value seen and
/// what was expected). A plan with no graft to simulate (no family fits, the site unknown) is a
/// result, not an error: RepairPlan::notSimulatedReason says why. On an exception nothing is
/// returned; warnings already reported through PlanObserver::warn stay reported.
#pragma once

#include <array>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "Centerlines/GivenLandmarks.h"
#include "Centerlines/LabelAortoIliacTree.h"
#include "Centerlines/ProximalSite.h"
#include "Centerlines/SkeletonGraph.h"
#include "Common/Types.h"
#include "Device/DeviceCatalog.h"
#include "Device/DeployGraft.h"
#include "Device/DeploymentTolerance.h"
#include "Device/FitCheck.h"
#include "Device/HostileNeck.h"
#include "Device/CompareConfigurations.h"
#include "Device/SelectDevice.h"
#include "Measurement/MeasureAnatomy.h"
#include "Segmentation/GrowLumenRegion.h"
#include "Stent/ActiveContour.h"
#include "Stent/StentMesh.h"
#include "Wall/VesselWall.h"

namespace sgp
{

/// The stages in the order they run; a plan that reaches one has every one before it.
enum class PlanStage
{
  Segmentation = 0, ///< the lumen label map
  Centerlines,      ///< the labelled Y, its side branches and landmarks
  StentSurface,     ///< the proximal site, the stent mesh and its active-contour fit (acmMode)
  Measurements,     ///< (a)–(f), lengths and angles off a measure-mode fit
  Device            ///< device selection, the simulated graft and its fit check
};

/// What to compute: decided at the front end from what the user asked for (never output paths).
struct PlanRequest
{
  PlanStage through = PlanStage::Device;
  /// The initial surface's per-vertex radius and wall distance (only an output of it needs them).
  bool initialSurfaceValues = false;
  /// The user's lowest renal ostium (LPS mm); empty: found from the renal branches.
  std::optional<Point3> lowestRenalOstiumLps;
  /// The user's aortic bifurcation and internal iliac origins (LPS mm; GivenLandmarks.h); empty:
  /// found.
  GivenLandmarks landmarks;
  /// A lumen the user gave (on its own grid, non-zero = lumen; LumenFromSegmentation.h), taken
  /// instead of region growing; null: grown from the seed. With it the CT may be null: the plan
  /// then runs on the lumen alone (no outer wall: sized on the lumen, marked estimated). Handed
  /// over: on the CT's grid its buffer becomes the plan's lumen mask (and is changed).
  LabelImage::Pointer givenLumen;
  std::string givenLumenDescription; ///< what it is, for messages ("labels 52, 65 of 'x.nii.gz'")
  /// The wall label map (WallLabelMap: lumen, thrombus and wall, calcium), when the plan reaches
  /// the measurements.
  bool wallLabelMap = false;
  /// Keep the CT crop around the lumen (the wall stage's) in RepairPlan::ctAroundLumen, for the
  /// views a report draws; needs a plan that reaches the measurements.
  bool ctAroundLumen = false;
};

/// Every stage's parameters; defaults equal the XML defaults of StentGraftSimulation.
struct PlanParams
{
  RegionGrowingParams growing;
  SkeletonGraphParams graph;
  CenterlineParams centerlines;
  /// proximalAbscissaMm < 0: the trunk starts at the proximal site found by FindProximalSite.
  StentMeshParams mesh;
  /// The outer wall; its calcium threshold is set from the lumen's window (VesselWall.h).
  VesselWallParams wall;
  /// The measure-mode fit the measurements are read off (paper, section 2.2).
  ActiveContourParams measure = ActiveContourParams::Measure();
  /// Set (acmMode simulate): the stent surface is fitted with these instead, and the measurements
  /// come from a second, measure-mode fit.
  std::optional<ActiveContourParams> simulate;
  /// The simulated graft: weights, pressure, step and stopping rule; its balloon radii are set
  /// from the chosen device's diameters.
  ActiveContourParams graft = ActiveContourParams::Simulate({ 24.0, 14.0, 14.0 });
  DeviceSelectionParams selection;
  /// Where the main body's proximal edge is deployed: this far below the proximal site (the lower
  /// edge of the lowest renal ostium) and its margin (SiteMarginMm, FitCheck.h: the edge's
  /// uncertainty less the overlap an ostium's edge tolerates) along the aorta, mm (negative: above
  /// it), in [−30, 60].
  double deploymentOffsetMm = 0.0;
  /// Whether to deploy the configuration again with each component displaced up to twice
  /// selection.deploymentToleranceMm (DeploymentTolerance.h; a few dozen deployments).
  bool assessDeploymentTolerance = true;
  /// The device catalogue (read and validated at the edge); needed when the plan reaches Device.
  DeviceCatalog catalog;
  /// The hostile-neck rules (read and validated at the edge); empty: the neck is not assessed.
  NeckRuleSet neckRules;
};

/// Stage boundaries, progress within a stage, and warnings as they arise. Each is optional.
struct PlanObserver
{
  std::function<void(std::string_view name, std::string_view description)> begin;
  ProgressCallback progress; ///< fraction of the current stage
  std::function<void(const std::string& warning)> warn;
  /// The stage just begun did its work on the second core, beside the stages before it, in this
  /// many seconds (the wall stage): a front end reports that as the stage's own time.
  std::function<void(double seconds)> ownTime;
  /// Called once the lumen is final, before the later stages run (a front end may start writing
  /// the label map on another core); the mask is not changed afterwards.
  std::function<void(const LumenSegmentation& lumen)> lumenReady;
  /// Called once the wall label map is final (PlanRequest::wallLabelMap), before the measurements
  /// (a front end may write it on another core); it is not changed afterwards.
  std::function<void(const LabelImage::Pointer& labels)> wallLabelsReady;
};

/// The plan: each stage's result (empty where the plan did not reach it).
struct RepairPlan
{
  PlanStage reached = PlanStage::Segmentation;

  Point3 seedLps = Point3::Zero(); ///< the seed the lumen was grown from, LPS mm
  bool seedAutomatic = false;      ///< found by FindAorticSeed (no seed was given)
  bool seedGiven = false;          ///< a seed was given (else seedLps is the automatic one, or 0 with a given lumen)
  bool lumenGiven = false;         ///< the lumen is the user's (PlanRequest::givenLumen), not grown
  bool ctGiven = true;             ///< false: planned on a given lumen without a CT
  std::string seedDescription;     ///< what the automatic seed is (FindAorticSeed), else empty
  LumenSegmentation lumen;         ///< its mask is on the input's grid
  CenterlineTree centerlines;

  ProximalSite site;
  StentMesh mesh;
  Eigen::VectorXd initialRadiusMm;       ///< #V, when PlanRequest::initialSurfaceValues
  Eigen::VectorXd initialWallDistanceMm; ///< #V, likewise
  ActiveContourResult fit;               ///< the stent surface, fitted in acmMode
  bool fitInMeasureMode = true;

  VesselWall vesselWall;          ///< when the plan reaches the measurements
  LabelImage::Pointer wallLabels; ///< on the input's grid, when PlanRequest::wallLabelMap
  /// The CT within the outer wall's ray reach (VesselWallParams: 45 mm) of the lumen's bounding
  /// box, HU, when PlanRequest::ctAroundLumen (else null).
  CtImage::Pointer ctAroundLumen;
  Measurements measurements;
  NeckAssessment neck; ///< the hostile-neck rules on the measurements (empty without rules)

  DeviceSelection selection;
  int simulatedFamily = -1; ///< index into selection.families; −1: no graft simulated
  /// Main body (proximal), right and left landing diameters of the simulated graft, mm.
  std::array<double, 3> graftDiametersMm{ 0.0, 0.0, 0.0 };
  DeployedGraft graft; ///< the simulated graft: its layout (components per vertex) and fitted surface
  /// A configured graft's length per side (right, left), mm (issue 46 item 5; NaN otherwise): the
  /// fabric ordered (DeviceConfiguration::coveredLengthMm: the components less their overlaps), the
  /// simulated graft's own axis from its proximal to its distal edge (GraftAxis: within
  /// FabricLengthToleranceMm of the fabric), the centerline path it covers, and how much further
  /// down that path its distal edge lies than the fabric's length read along the centerline
  /// (positive where the graft runs straighter than the centerline, through a sac).
  std::array<double, 2> graftFabricLengthMm{ std::numeric_limits<double>::quiet_NaN(),
                                             std::numeric_limits<double>::quiet_NaN() };
  std::array<double, 2> graftAxisLengthMm{ std::numeric_limits<double>::quiet_NaN(),
                                           std::numeric_limits<double>::quiet_NaN() };
  std::array<double, 2> graftPathLengthMm{ std::numeric_limits<double>::quiet_NaN(),
                                           std::numeric_limits<double>::quiet_NaN() };
  std::array<double, 2> distalEdgeShiftMm{ std::numeric_limits<double>::quiet_NaN(),
                                           std::numeric_limits<double>::quiet_NaN() };
  FitCheck fitCheck;
  /// How far each component may land from its plan (issue 47; DeploymentTolerance.h): assessed
  /// for a configured graft that passes its fit check, with PlanParams::assessDeploymentTolerance.
  DeploymentTolerance deploymentTolerance;
  /// The simulated ordered graft's right and left axes (GraftAxisOf), when it was configured.
  std::array<GraftAxis, 2> graftAxes;
  /// With a configuration given (DeviceSelectionParams::configuration): the selection the plan
  /// would have made without it (its recommendation), and every way the given one differs from
  /// that recommendation's configuration (CompareConfigurations.h; empty: the same).
  std::optional<DeviceSelection> recommendation;
  std::vector<ConfigurationDifference> configurationDifferences;
  /// Why no graft was simulated (a sentence without a final full stop), when the plan reached the
  /// device stage without one; else empty.
  std::string notSimulatedReason;

  /// Every warning, in the order they arose (also passed to PlanObserver::warn).
  std::vector<std::string> warnings;
  /// The table: the measurements, then the simulated device's sizes and its fit check.
  std::vector<Measurement> rows;

  bool Reached(PlanStage stage) const { return static_cast<int>(reached) >= static_cast<int>(stage); }
  bool HasGraft() const { return simulatedFamily >= 0; }
  /// Where the main body's proximal edge is deployed: along the aorta from its top, mm (the
  /// proximal site + deploymentMarginMm + PlanParams::deploymentOffsetMm), when the plan reaches
  /// the device; NaN when the site is not known (ProximalSite::Known).
  double deploymentTargetAbscissaMm = 0.0;
  /// Below the lowest renal's lower edge as read, so that the fabric covers none of the ostium
  /// wherever the edge lies within its uncertainty (SiteMarginMm), mm; 0 for a person's point.
  double deploymentMarginMm = 0.0;
  /// The family whose components the plan orders (FamilyForMainBody: the recommended one, else the
  /// nearest with a main body); −1 when no family has a main body.
  int orderedFamily = -1;
  /// Its configuration (the order list), or nullptr when no family has a main body.
  const DeviceConfiguration* Configuration() const
  {
    return orderedFamily >= 0 ? &selection.families[std::size_t(orderedFamily)].configuration : nullptr;
  }
};

/// Runs the stages up to `request.through`; see the file comment. Without a seed the aorta is
/// found first (FindAorticSeed, stage FindSeed; its AlgorithmError when none is found), unless
/// the lumen is given (PlanRequest::givenLumen: stage SegmentLumen takes it instead; `ct` may then
/// be null). Given landmarks (PlanRequest::landmarks) enter after the labelling (ApplyGivenLandmarks).
/// \throws InputError also when a given lumen forms no aorto-iliac Y (what the labelling found).
RepairPlan PlanRepair(CtImage::ConstPointer ct,
                      const std::optional<Point3>& seedLps,
                      const PlanRequest& request,
                      const PlanParams& params,
                      const PlanObserver& observer = {});

/// The hostile-neck quantities from the measurements: neck length (with NeckLengthUncertaintyMm),
/// outer (a), β, α, the neck's thrombus and calcification arcs, the reverse taper over 10 and 15 mm.
NeckAnatomy NeckFromMeasurements(const Measurements& measurements);

/// The family to simulate: the recommended one, else the one with all three sizes chosen and the
/// fewest failing checks (so that a plan outside every IFU still shows how the nearest graft
/// sits); −1 when no family has all three sizes.
int FamilyToSimulate(const DeviceSelection& selection);

/// The family whose main body a partial plan simulates (its limbs cannot be sized): the
/// recommended one if it has a main body, else the one with a main body chosen and the fewest
/// failing checks; −1 when no family has a main body for the neck.
int FamilyForMainBody(const DeviceSelection& selection);

} // namespace sgp
