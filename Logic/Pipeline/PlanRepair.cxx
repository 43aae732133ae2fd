#include "Pipeline/PlanRepair.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <future>
#include <limits>
#include <optional>
#include <utility>

#include "Centerlines/AssignInscribedRadii.h"
#include "Centerlines/ThinLabelMap.h"
#include "Common/Errors.h"
#include "Common/Format.h"
#include "Common/Median.h"
#include "Common/Text.h"
#include "Device/ConfigurationLengths.h"
#include "Device/DeployGraft.h"
#include "Pipeline/PlanRows.h"
#include "Pipeline/PlanTolerance.h"
#include "Segmentation/FindAorticSeed.h"
#include "Segmentation/FindEndograft.h"
#include "Segmentation/LumenFromSegmentation.h"
#include "Stent/WallDistanceField.h"

namespace sgp
{
namespace
{

/// The observer, and the plan's warnings list that every warning also goes to.
class StageReporter
{
public:
  StageReporter(const PlanObserver& observer, RepairPlan& plan)
    : m_Observer(observer)
    , m_Plan(plan)
  {
  }
  void Begin(std::string_view name, std::string_view description) const
  {
    if (m_Observer.begin)
      m_Observer.begin(name, description);
  }
  void Progress(double fraction) const { ReportProgress(m_Observer.progress, fraction, ""); }
  void OwnTime(double seconds) const
  {
    if (m_Observer.ownTime)
      m_Observer.ownTime(seconds);
  }
  const ProgressCallback& Callback() const { return m_Observer.progress; }
  void Warn(const std::string& warning) const
  {
    m_Plan.warnings.push_back(warning);
    if (m_Observer.warn)
      m_Observer.warn(warning);
  }

  void WallLabelsReady(const LabelImage::Pointer& labels) const
  {
    if (m_Observer.wallLabelsReady && labels)
      m_Observer.wallLabelsReady(labels);
  }
  void LumenReady(const LumenSegmentation& lumen) const
  {
    if (m_Observer.lumenReady)
      m_Observer.lumenReady(lumen);
  }

private:
  const PlanObserver& m_Observer;
  RepairPlan& m_Plan;
};

void SegmentLumen(const CtImage& ct,
                  const Point3& seedLps,
                  const PlanParams& params,
                  const StageReporter& report,
                  RepairPlan& plan)
{
  report.Begin("SegmentLumen", "Segmenting the aortic lumen by region growing");
  plan.lumen = GrowLumenRegion(ct, seedLps, params.growing, report.Callback());
}

/// A post-EVAR scan: its graft's struts break the lumen, and the plan would fail later with a wrong
/// cause (or measure the graft); says what it is instead (FindEndograft.h).
void NoEndograft(const EndograftEvidence& metal)
{
  if (metal.found)
    throw InputError(
      std::string(metal.aroundSeed ? "The aorta holds metal around the seed" : "The aorta's lumen holds metal") +
      ": stent rings up to " + FormatNumber(metal.maximumHu, 0) + " HU all around it over " +
      FormatNumber(metal.ringLengthMm, 0) + " mm (z " + FormatNumber(metal.ringFromZ, 0) + " to " +
      FormatNumber(metal.ringToZ, 0) +
      " mm LPS), so an endograft or another metal device is already in place; this plan is for "
      "pre-operative CT angiograms of an unrepaired aorta.");
}

void ExtractCenterlines(const PlanRequest& request,
                        const PlanParams& params,
                        const StageReporter& report,
                        RepairPlan& plan)
{
  report.Begin("ThinLumen", "Thinning the lumen into its skeleton");
  const Skeleton skeleton = ThinLabelMap(*plan.lumen.mask, report.Callback());
  report.Begin("ExtractCenterlines", "Labelling the aorta, the iliac arteries and their branches");
  try
  {
    const SkeletonGraph graph = BuildSkeletonGraph(skeleton, *plan.lumen.mask, params.graph);
    report.Progress(0.3);
    plan.centerlines = LabelAortoIliacTree(graph, params.centerlines);
  }
  catch (const AlgorithmError& e)
  {
    // A given lumen that is no aorto-iliac Y is the input's fault, and the message says which input.
    if (!plan.lumenGiven)
      throw;
    throw InputError("The lumen segmentation given (" + request.givenLumenDescription +
                     ") forms no aorto-iliac Y: " + e.what() +
                     " Expected the aorta and both common iliac arteries in the labels chosen (lumenLabels).");
  }
  AssignInscribedRadii(plan.centerlines, skeleton);
  ApplyGivenLandmarks(plan.centerlines, request.landmarks);
}

/// The proximal site, the mesh, the wall field and the fit in acmMode; returns the wall field,
/// which the later fits share.
WallDistanceField FitStentSurface(const PlanRequest& request,
                                  const PlanParams& params,
                                  const StageReporter& report,
                                  RepairPlan& plan,
                                  const std::function<void()>& siteFound)
{
  report.Begin("FitStent", "Fitting the bifurcated stent surface (active contour)");
  plan.site = FindProximalSite(plan.centerlines, request.lowestRenalOstiumLps);
  if (!plan.site.warning.empty())
    report.Warn(plan.site.warning);
  siteFound();
  StentMeshParams meshParams = params.mesh;
  if (meshParams.proximalAbscissaMm < 0.0)
    meshParams.proximalAbscissaMm = plan.site.abscissaMm;
  plan.mesh = BuildStentMesh(plan.centerlines, meshParams);
  WallDistanceField wall = WallDistanceField::FromLumen(
    *plan.lumen.mask, SharedWallBandMm, SharedFieldReach(plan.mesh, plan.centerlines, params.deploymentOffsetMm));
  if (request.initialSurfaceValues)
  {
    const Eigen::Index n = plan.mesh.V.rows();
    plan.initialRadiusMm = Eigen::VectorXd::Constant(n, meshParams.startRadiusMm);
    plan.initialWallDistanceMm.resize(n);
    for (Eigen::Index i = 0; i < n; ++i)
      plan.initialWallDistanceMm[i] = wall.Sample(plan.mesh.V.row(i).transpose());
  }
  plan.fitInMeasureMode = !params.simulate.has_value();
  plan.fit = FitActiveContour(plan.mesh, wall, params.simulate ? *params.simulate : params.measure, report.Callback());
  if (!plan.fit.converged)
    report.Warn("The active contour did not converge within " + std::to_string(plan.fit.iterations) +
                " iterations (acmMaxIterations); the surface written is the last one.");
  return wall;
}

/// The outer wall, thrombus and calcium of the aorta and both common iliacs, from the CT crop.
/// The wall stage's results, computed off the plan (on the second core while the stent surface is
/// fitted): it reads the CT crop, the lumen, the centerlines and the site, none of which the fit
/// changes.
struct TracedWall
{
  VesselWall wall;
  LabelImage::Pointer labels;
  double seconds = 0.0; ///< its own time, on the second core
};

TracedWall TraceWall(const CtImage& ct, const PlanRequest& request, const PlanParams& params, const RepairPlan& plan)
{
  const auto start = std::chrono::steady_clock::now();
  VesselWallParams wallParams = params.wall;
  // Nothing outside the lumen above its window is blood (VesselWall.h).
  // (A given lumen's window is NaN where the CT held no interior voxel: the default then.)
  if (std::isfinite(plan.lumen.calciumHu))
    wallParams.calciumHu = std::min(plan.lumen.calciumHu, params.wall.calciumHu);
  TracedWall traced;
  traced.wall = TraceVesselWall(ct, *plan.lumen.mask, plan.centerlines, plan.site.abscissaMm, wallParams);
  if (request.wallLabelMap)
    traced.labels = WallLabelMap(traced.wall, *plan.lumen.mask, ct);
  traced.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return traced;
}

/// Takes the traced wall into the plan, with its warnings.
void ReportWall(std::future<TracedWall>& tracing,
                const PlanParams& params,
                const StageReporter& report,
                RepairPlan& plan)
{
  report.Begin("SegmentOuterWall", "Tracing the outer wall, the thrombus and the calcium");
  if (!tracing.valid()) // no CT: nothing to trace the wall on
  {
    report.Warn("No CT was given, only the lumen segmentation: the outer wall, the thrombus and the calcium are "
                "not traced, so the outer-wall diameters and thrombus values are not measured and the device is "
                "sized on the lumen (estimated).");
    return;
  }
  TracedWall traced = tracing.get();
  report.OwnTime(traced.seconds);
  plan.vesselWall = std::move(traced.wall);
  plan.wallLabels = traced.labels;
  report.WallLabelsReady(plan.wallLabels);
  if (plan.vesselWall.Empty())
    report.Warn("No outer wall was found around the lumen (no fat outside the vessel in any plane?): the "
                "outer-wall diameters, the thrombus values and the sizing on them are not measured.");
  else if (!plan.vesselWall.wallThicknessEstimated && params.wall.wallThicknessMm < 0.0)
    report.Warn("The wall thickness could not be measured above the neck; the thrombus is measured with a wall of " +
                FormatNumber(plan.vesselWall.wallThicknessMm) + " mm.");
}

void Measure(const WallDistanceField& wall, const PlanParams& params, const StageReporter& report, RepairPlan& plan)
{
  report.Begin("MeasureAnatomy", "Measuring diameters, lengths and angles");
  // Measurements are always read off a measure-mode fit (paper, section 2.2).
  const Points measureV = plan.fitInMeasureMode ? plan.fit.V : FitActiveContour(plan.mesh, wall, params.measure).V;
  plan.measurements =
    MeasureAnatomy(plan.centerlines, plan.mesh, measureV, plan.site, &plan.vesselWall, plan.lumen.mask.GetPointer());
  for (const std::string& w : plan.measurements.warnings)
    if (w != plan.site.warning) // reported with the stent surface already
      report.Warn(w);
  plan.rows = plan.measurements.values;
  if (!params.neckRules.rules.empty())
  {
    plan.neck = AssessNeck(NeckFromMeasurements(plan.measurements), params.neckRules);
    if (!plan.neck.determinate && !plan.neck.hostile)
      report.Warn("Hostile neck not determined: " + plan.neck.summary + ".");
  }
}

/// A partial plan whose limbs cannot be sized: the proximal part of the fit check (proximal seal,
/// proximal oversizing, covered aortic ostia) with the main body of the family FamilyForMainBody
/// picks. Each leg takes the limb the selection chose for it where that side was sized, else the
/// lumen's own diameter there (the median of its measured rings: it neither presses on the wall
/// nor hangs free, and carries only the connection element): nothing distal is read off it.
void SimulateTheMainBodyOnly(const WallDistanceField& wall,
                             const PlanParams& params,
                             const StageReporter& report,
                             RepairPlan& plan)
{
  const int chosen = FamilyForMainBody(plan.selection);
  if (chosen < 0)
  {
    plan.notSimulatedReason = "The plan is partial: the scan ends above the iliac landing zones, so the limbs cannot "
                              "be sized, and no catalogue main body fits the neck (" +
                              plan.selection.summary + ")";
    report.Warn(plan.notSimulatedReason +
                "; no graft is simulated, so its sizes, seal lengths, oversizing and fit check are not available.");
    return;
  }
  report.Begin("SimulateGraft", "Simulating the chosen main body in the aorta (partial plan)");
  const FamilyEvaluation& family = plan.selection.families[std::size_t(chosen)];
  const SizeChoice* limbs[2] = { &family.rightLimb, &family.leftLimb };
  plan.graftDiametersMm = { family.mainBody.diameterMm, std::numeric_limits<double>::quiet_NaN(),
                            std::numeric_limits<double>::quiet_NaN() };
  std::array<double, 2> fallback{ 0.0, 0.0 };
  for (int side = 0; side < 2; ++side)
  {
    const int seg = 1 + side;
    if (limbs[side]->Chosen())
      plan.graftDiametersMm[std::size_t(seg)] = limbs[side]->diameterMm;
    std::vector<double> means;
    for (const RingDiameters& r : plan.measurements.profiles[std::size_t(seg)].rings)
      if (std::isfinite(r.meanMm))
        means.push_back(r.meanMm);
    fallback[std::size_t(side)] = means.empty() ? 2.0 * params.graft.balloonRadiusMm[std::size_t(seg)] : Median(means);
  }
  GraftLayout layout =
    LayOutOnMeasureMesh(plan.mesh, plan.measurements, family.family, plan.graftDiametersMm, fallback);
  plan.graft = DeployGraft(std::move(layout), wall, params.graft, report.Callback());
  FitCheckContext context;
  context.voxelAlongAortaMm = VoxelAlongAortaMm(plan);
  context.family = family.family;
  context.limbSized = { limbs[0]->Chosen(), limbs[1]->Chosen() };
  context.minimumIliacSealMm = params.catalog.families[std::size_t(family.catalogIndex)].ifu.iliacSealLengthMm.min;
  plan.fitCheck = CheckGraftFit(plan.graft, plan.measurements, plan.centerlines, &plan.vesselWall, context);
  plan.simulatedFamily = chosen;
  std::string findings;
  for (const std::string& f : plan.fitCheck.findings)
    findings += "; " + f;
  report.Warn("Partial plan: the proximal part of the fit check is made with the " + family.family + " main body (" +
              FormatNumber(family.mainBody.diameterMm) + " mm, " + FormatNumber(family.mainBody.oversizingPercent) +
              " % over (a)): proximal seal " + FormatNumber(plan.fitCheck.proximalSealLengthMm) +
              " mm, covered aortic ostia: " + plan.fitCheck.CoveredOstia() + findings +
              ". The limbs the scan does not size, their seal zones and the internal iliac ostia are not checked, "
              "so fitCheckPassed and withinIfu are false.");
  AddDeviceRows(params.catalog, plan);
}

/// The ordered configuration deployed at its target (DeployGraft.h) and its fit check, with the
/// configuration's findings. The measure-mode fit's wall field serves when it covers the graft's
/// reach (the graft lies within the measured extents: the usual case); else one is made for it.
void SimulateTheConfiguration(const WallDistanceField& measureWall,
                              const PlanParams& params,
                              const StageReporter& report,
                              RepairPlan& plan)
{
  report.Begin("SimulateGraft", "Deploying the ordered stent graft in the vessel");
  plan.simulatedFamily = plan.orderedFamily;
  const FamilyEvaluation& family = plan.selection.families[std::size_t(plan.orderedFamily)];
  const DeviceConfiguration& configuration = family.configuration;
  plan.graftDiametersMm = { configuration.components.front().item.diameterMm, std::numeric_limits<double>::quiet_NaN(),
                            std::numeric_limits<double>::quiet_NaN() };
  for (const ConfiguredComponent& part : configuration.components)
    if (part.role != OrderRole::MainBody &&
        part.distalMm >= configuration.coveredLengthMm[std::size_t(part.side)] - 1e-9)
      plan.graftDiametersMm[std::size_t(1 + part.side)] = part.item.distalDiameterMm;
  const int ipsi = configuration.ipsilateralSide;
  if (std::isnan(plan.graftDiametersMm[std::size_t(1 + ipsi)])) // the main body's own leg lands
    plan.graftDiametersMm[std::size_t(1 + ipsi)] = configuration.components.front().item.distalDiameterMm;
  // Fabric does not shorten (issue 46 item 5; DeployGraft.h): laid out again along the fit's axes.
  FabricDeployment deployed =
    DeployTheFabric(plan.centerlines, plan.measurements, configuration, plan.deploymentTargetAbscissaMm, params.mesh,
                    [&](GraftLayout layout)
                    {
                      std::optional<WallDistanceField> ownWall;
                      const WallDistanceField& wall =
                        WallDistanceField::SharedOrOwn(measureWall, *plan.lumen.mask, SharedWallBandMm,
                                                       StentReach(layout.mesh, plan.centerlines), ownWall);
                      return DeployGraft(std::move(layout), wall, params.graft, report.Callback());
                    });
  plan.graft = std::move(deployed.graft);
  const std::array<GraftAxis, 2>& axes = deployed.axes;
  for (int side = 0; side < 2; ++side)
  {
    const std::size_t s = std::size_t(side);
    plan.graftFabricLengthMm[s] = configuration.coveredLengthMm[s];
    plan.graftAxisLengthMm[s] = axes[s].LengthMm();
    plan.graftPathLengthMm[s] = axes[s].pathMm.back();
    plan.distalEdgeShiftMm[s] = plan.graftPathLengthMm[s] - configuration.coveredLengthMm[s];
    if (std::abs(plan.graftAxisLengthMm[s] - plan.graftFabricLengthMm[s]) > FabricLengthToleranceMm)
      report.Warn(std::string("The simulated graft's ") + (side == 0 ? "right" : "left") + " axis is " +
                  FormatNumber(plan.graftAxisLengthMm[s]) + " mm long against the " +
                  FormatNumber(plan.graftFabricLengthMm[s]) + " mm of fabric ordered" +
                  (deployed.carried
                     ? " (it did not settle within " + std::to_string(FabricLengthPasses) + " layouts)."
                     : std::string(": its distal edge could not be carried further (the iliac in view ends).")));
  }
  if (!plan.graft.fit.converged)
    report.Warn("The simulated graft did not converge within " + std::to_string(plan.graft.fit.iterations) +
                " iterations; the surface written is the last one.");
  const DeviceFamily& catalogued = params.catalog.families[std::size_t(family.catalogIndex)];
  FitCheckContext context;
  context.voxelAlongAortaMm = VoxelAlongAortaMm(plan);
  context.family = family.family;
  context.minimumIliacSealMm = catalogued.ifu.iliacSealLengthMm.min;
  context.minimumOverlapMm = catalogued.junctions.overlapMm.min;
  context.configurationFindings = configuration.findings;
  plan.fitCheck = CheckGraftFit(plan.graft, plan.measurements, plan.centerlines, &plan.vesselWall, context);
  plan.graftAxes = axes;
  if (params.assessDeploymentTolerance)
    plan.deploymentTolerance = AssessPlanTolerance(plan, params, measureWall, context);
  if (plan.selection.recommended < 0)
    report.Warn("No device is within its instructions for use; the graft simulated is the nearest, " + family.family +
                " (outside its IFU).");
  AddDeviceRows(params.catalog, plan);
}

/// One warning naming the levels sized on the lumen (the outer wall not traced there).
void WarnSizedOnLumen(const DeviceSelection& selection, const StageReporter& report)
{
  std::vector<std::string> levels;
  for (const FamilyEvaluation& e : selection.families)
    for (const std::string& level : e.estimatedFromLumen)
      if (std::find(levels.begin(), levels.end(), level) == levels.end())
        levels.push_back(level);
  if (levels.empty())
    return;
  std::string names;
  for (const std::string& level : levels)
    names += (names.empty() ? "" : ", ") + level;
  report.Warn("The outer wall was not traced at " + names +
              ": the device is sized on the lumen there, so its sizes are estimated (lumen) and the IFU result is "
              "indeterminate.");
}

void ChooseAndSimulateDevice(const WallDistanceField& wall,
                             const PlanParams& params,
                             const StageReporter& report,
                             RepairPlan& plan)
{
  report.Begin("SelectDevice", "Choosing the stent graft from the device catalogue and its components");
  const SizingAnatomy sizing = SizingFromMeasurements(plan.measurements);
  // No site, no target: the catalogue is checked on the values that were measured (the neck's
  // criteria indeterminate), nothing is configured or simulated.
  const bool siteKnown = plan.measurements.site.Known();
  plan.deploymentMarginMm = SiteMarginMm(plan.measurements.site);
  plan.deploymentTargetAbscissaMm =
    siteKnown ? plan.measurements.site.abscissaMm + plan.deploymentMarginMm + params.deploymentOffsetMm
              : std::numeric_limits<double>::quiet_NaN();
  std::optional<ConfigurationAnatomy> lengths;
  if (siteKnown)
    lengths = ConfigurationLengths(plan.centerlines, plan.measurements, plan.deploymentTargetAbscissaMm);
  const double recommendedTargetMm = plan.deploymentTargetAbscissaMm;
  if (params.selection.configuration)
  {
    // The plan's own recommendation first, to compare the surgeon's with; then the surgeon's, at
    // the main body's position given (else the plan's).
    DeviceSelectionParams own = params.selection;
    own.configuration.reset();
    plan.recommendation = SelectDevice(sizing, params.catalog, own, lengths ? &*lengths : nullptr);
    for (const GivenComponent& c : params.selection.configuration->components)
      if (siteKnown && c.role == ComponentRole::MainBody && std::isfinite(c.proximalEdgeBelowLowestRenalMm))
      {
        plan.deploymentTargetAbscissaMm = plan.measurements.site.abscissaMm + c.proximalEdgeBelowLowestRenalMm;
        lengths = ConfigurationLengths(plan.centerlines, plan.measurements, plan.deploymentTargetAbscissaMm);
      }
  }
  plan.selection = SelectDevice(sizing, params.catalog, params.selection, lengths ? &*lengths : nullptr);
  WarnSizedOnLumen(plan.selection, report);
  plan.orderedFamily = FamilyForMainBody(plan.selection);
  if (plan.recommendation)
  {
    const int recommended = FamilyForMainBody(*plan.recommendation);
    if (recommended >= 0 && plan.Configuration())
      plan.configurationDifferences = CompareConfigurations(
        *plan.Configuration(), plan.recommendation->families[std::size_t(recommended)].configuration,
        plan.deploymentTargetAbscissaMm - recommendedTargetMm);
  }
  AddOrderRows(plan);
  if (!siteKnown)
  {
    plan.notSimulatedReason = "The proximal implantation site is not known (no renal artery in view), so there is "
                              "no deployment target";
    report.Warn(plan.notSimulatedReason + ": no graft is simulated; give --lowestRenalOstium.");
    return;
  }
  const DeviceConfiguration* configuration = plan.Configuration();
  if (configuration && configuration->configured)
  {
    SimulateTheConfiguration(wall, params, report, plan);
    return;
  }
  plan.simulatedFamily = FamilyToSimulate(plan.selection);
  // A partial plan whose scan ends above a limb's landing zone: nothing to size that limb on.
  const bool limbUnsized = std::isnan(plan.measurements.Value("rightIliacLumenDiameter")) ||
                           std::isnan(plan.measurements.Value("leftIliacLumenDiameter"));
  if (plan.simulatedFamily < 0 && plan.centerlines.Partial() && limbUnsized)
  {
    SimulateTheMainBodyOnly(wall, params, report, plan);
    return;
  }
  if (plan.simulatedFamily < 0)
  {
    plan.notSimulatedReason = "No catalogue device has a main body and both limbs within the oversizing ranges (" +
                              plan.selection.summary + ")";
    report.Warn(plan.notSimulatedReason + "; no graft was simulated, so its sizes, seal lengths, oversizing and fit "
                                          "check are not available (widen proximalOversizingRange or "
                                          "limbOversizingRange, or force a device with --device).");
    return;
  }
  // The lengths could not be configured: the chosen diameters on the measured landing zones.
  report.Begin("SimulateGraft", "Simulating the chosen diameters in the vessel (lengths not configured)");
  const FamilyEvaluation& family = plan.selection.families[plan.simulatedFamily];
  plan.graftDiametersMm = { family.mainBody.diameterMm, family.rightLimb.diameterMm, family.leftLimb.diameterMm };
  GraftLayout layout = LayOutOnMeasureMesh(plan.mesh, plan.measurements, family.family, plan.graftDiametersMm,
                                           { family.rightLimb.diameterMm, family.leftLimb.diameterMm });
  plan.graft = DeployGraft(std::move(layout), wall, params.graft, report.Callback());
  FitCheckContext context;
  context.voxelAlongAortaMm = VoxelAlongAortaMm(plan);
  context.family = family.family;
  context.minimumIliacSealMm = params.catalog.families[std::size_t(family.catalogIndex)].ifu.iliacSealLengthMm.min;
  plan.fitCheck = CheckGraftFit(plan.graft, plan.measurements, plan.centerlines, &plan.vesselWall, context);
  report.Warn("The " + family.family + " components' lengths could not be configured (" +
              family.configuration.unknownReason +
              "): the graft simulated has the chosen diameters over the measured landing zones, not the lengths "
              "of a device that can be ordered.");
  if (plan.selection.recommended < 0)
    report.Warn("No device is within its instructions for use; the graft simulated is the nearest, " + family.family +
                " (outside its IFU).");
  AddDeviceRows(params.catalog, plan);
}

} // namespace

NeckAnatomy NeckFromMeasurements(const Measurements& m)
{
  NeckAnatomy neck;
  neck.neckLengthMm = m.Value("proximalNeckLength");
  neck.neckDiameterMm = m.Value("proximalNeckDiameter");
  neck.neckAngleBetaDeg = m.Value("neckAngleBeta");
  neck.neckAngleAlphaDeg = m.Value("neckAngleAlpha");
  neck.neckThrombusArcPercent = m.Value("neckThrombusArc");
  neck.neckCalcificationArcPercent = m.Value("neckCalcificationArc");
  neck.reverseTaper10mmMm = m.reverseTaperMm[0];
  neck.reverseTaper15mmMm = m.reverseTaperMm[1];
  neck.neckLengthUncertaintyMm = NeckLengthUncertaintyMm;
  return neck;
}

namespace
{

/// The recommended family if it is `usable`, else the usable one with the fewest failing checks;
/// −1 when none is usable.
template<typename Usable>
int BestFamily(const DeviceSelection& selection, const Usable& usable)
{
  if (selection.recommended >= 0 && usable(selection.families[std::size_t(selection.recommended)]))
    return selection.recommended;
  int best = -1;
  for (int i = 0; i < static_cast<int>(selection.families.size()); ++i)
    if (usable(selection.families[std::size_t(i)]) &&
        (best < 0 || selection.families[std::size_t(i)].Count(CheckStatus::Fail) <
                       selection.families[std::size_t(best)].Count(CheckStatus::Fail)))
      best = i;
  return best;
}

} // namespace

int FamilyForMainBody(const DeviceSelection& selection)
{
  return BestFamily(selection, [](const FamilyEvaluation& f) { return f.mainBody.Chosen(); });
}

int FamilyToSimulate(const DeviceSelection& selection)
{
  return BestFamily(selection, [](const FamilyEvaluation& f)
                    { return f.mainBody.Chosen() && f.rightLimb.Chosen() && f.leftLimb.Chosen(); });
}

RepairPlan PlanRepair(CtImage::ConstPointer ct,
                      const std::optional<Point3>& seedLps,
                      const PlanRequest& request,
                      const PlanParams& params,
                      const PlanObserver& observer)
{
  if (!ct && !request.givenLumen)
    throw InputError("PlanRepair was given no CT volume; expected a 3-D image in HU.");
  RepairPlan plan;
  const StageReporter report(observer, plan);
  plan.lumenGiven = bool(request.givenLumen);
  plan.ctGiven = bool(ct);
  if (seedLps)
  {
    plan.seedLps = *seedLps;
    plan.seedAutomatic = false;
    plan.seedGiven = true;
  }
  else if (!request.givenLumen)
  {
    report.Begin("FindSeed", "Finding the aorta for an automatic seed");
    AorticSeedParams search;
    search.minimumHu = params.growing.seedMinimumHu;
    const AorticSeed found = FindAorticSeed(*ct, search);
    plan.seedLps = found.lps;
    plan.seedAutomatic = true;
    plan.seedDescription = found.description;
  }
  // A seed inside an endograft: the growing may stop at its struts and leave too little lumen for
  // the check beside the lumen below (FindEndograft.h, "around the seed"); one box of HU.
  if (ct && (seedLps || !request.givenLumen))
    NoEndograft(FindEndograftAroundSeed(*ct, plan.seedLps));
  if (request.givenLumen)
  {
    report.Begin("SegmentLumen", "Taking the lumen from the segmentation given");
    plan.lumen = LumenFromSegmentation(request.givenLumen, ct.GetPointer(), seedLps, request.givenLumenDescription);
  }
  else
    SegmentLumen(*ct, plan.seedLps, params, report, plan);
  CtImage::Pointer around;
  if (ct)
  {
    // The endograft check on the second core beside the crop of the CT the wall stage reads (only
    // it reads HU after segmentation, and only within its rays' reach of the lumen); both only
    // read the CT and the final mask. Then the input is freed, if the caller handed it over, before
    // the thinning's buffers are added to the peak.
    std::future<EndograftEvidence> metal =
      std::async(std::launch::async, [&] { return FindEndograft(*ct, *plan.lumen.mask, plan.lumen.box); });
    around = request.through >= PlanStage::StentSurface
               ? CropAroundLumen(*ct, *plan.lumen.mask, params.wall.outer.maxRadiusMm)
               : nullptr;
    NoEndograft(metal.get());
  }
  ct = nullptr;
  for (const std::string& w : plan.lumen.warnings) // a post-EVAR scan gets its error alone
    report.Warn(w);
  report.LumenReady(plan.lumen);
  plan.reached = PlanStage::Segmentation;
  if (request.through < PlanStage::Centerlines)
    return plan;

  ExtractCenterlines(request, params, report, plan);
  plan.reached = PlanStage::Centerlines;
  if (request.through < PlanStage::StentSurface)
    return plan;

  // The wall stage needs the site, not the fit: it runs on the second core while the stent
  // surface is fitted (declared after `around` and `plan`, so it is waited for before either goes).
  std::future<TracedWall> traced;
  if (around) // the renals' walls on the CT, for the site and the coverage check (ProximalSite.h)
    MeasureRenalMouthWalls(plan.centerlines, *around);
  const auto startWall = [&]
  {
    if (around && request.through >= PlanStage::Measurements)
      traced = std::async(std::launch::async, [&] { return TraceWall(*around, request, params, plan); });
  };
  const WallDistanceField wall = FitStentSurface(request, params, report, plan, startWall);
  plan.reached = PlanStage::StentSurface;
  if (request.through < PlanStage::Measurements)
    return plan;

  ReportWall(traced, params, report, plan);
  if (request.ctAroundLumen)
    plan.ctAroundLumen = around;
  around = nullptr;
  Measure(wall, params, report, plan);
  plan.reached = PlanStage::Measurements;
  if (request.through < PlanStage::Device)
    return plan;

  ChooseAndSimulateDevice(wall, params, report, plan);
  plan.reached = PlanStage::Device;
  return plan;
}

} // namespace sgp
