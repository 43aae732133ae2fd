#include "Pipeline/PlanRepair.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <future>
#include <limits>
#include <utility>

#include "Centerlines/AssignInscribedRadii.h"
#include "Centerlines/ThinLabelMap.h"
#include "Common/Errors.h"
#include "Common/Format.h"
#include "Common/Median.h"
#include "Segmentation/FindAorticSeed.h"
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
  const ProgressCallback& Callback() const { return m_Observer.progress; }
  void Warn(const std::string& warning) const
  {
    m_Plan.warnings.push_back(warning);
    if (m_Observer.warn)
      m_Observer.warn(warning);
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
  for (const std::string& w : plan.lumen.warnings)
    report.Warn(w);
  report.LumenReady(plan.lumen);
}

void ExtractCenterlines(const PlanParams& params, const StageReporter& report, RepairPlan& plan)
{
  report.Begin("ThinLumen", "Thinning the lumen into its skeleton");
  const Skeleton skeleton = ThinLabelMap(*plan.lumen.mask, report.Callback());
  report.Begin("ExtractCenterlines", "Labelling the aorta, the iliac arteries and their branches");
  const SkeletonGraph graph = BuildSkeletonGraph(skeleton, *plan.lumen.mask, params.graph);
  report.Progress(0.3);
  plan.centerlines = LabelAortoIliacTree(graph, params.centerlines);
  AssignInscribedRadii(plan.centerlines, skeleton);
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
  WallDistanceField wall = WallDistanceField::FromLumen(*plan.lumen.mask, 5.0, StentReach(plan.mesh, plan.centerlines));
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
};

TracedWall TraceWall(const CtImage& ct, const PlanRequest& request, const PlanParams& params, const RepairPlan& plan)
{
  VesselWallParams wallParams = params.wall;
  // Nothing outside the lumen above its window is blood (VesselWall.h).
  wallParams.calciumHu = std::min(plan.lumen.calciumHu, params.wall.calciumHu);
  TracedWall traced;
  traced.wall = TraceVesselWall(ct, *plan.lumen.mask, plan.centerlines, plan.site.abscissaMm, wallParams);
  if (request.wallLabelMap)
    traced.labels = WallLabelMap(traced.wall, *plan.lumen.mask, ct);
  return traced;
}

/// Takes the traced wall into the plan, with its warnings.
void ReportWall(TracedWall traced, const PlanParams& params, const StageReporter& report, RepairPlan& plan)
{
  report.Begin("SegmentOuterWall", "Tracing the outer wall, the thrombus and the calcium");
  plan.vesselWall = std::move(traced.wall);
  plan.wallLabels = traced.labels;
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
  plan.measurements = MeasureAnatomy(plan.centerlines, plan.mesh, measureV, plan.site, &plan.vesselWall);
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

/// The simulated device's sizes as table rows, on the wall its IFU names.
void AddDeviceRows(const DeviceCatalog& catalog, RepairPlan& plan)
{
  const FamilyEvaluation& family = plan.selection.families[plan.simulatedFamily];
  const bool outer =
    catalog.families[std::size_t(family.catalogIndex)].diameterReference == DiameterReference::OuterWall;
  const std::string wall = outer ? "outer" : "lumen";
  const std::string over = outer ? " % over the outer-wall " : " % over the lumen's ";
  const std::string name = family.family + (!plan.fitCheck.Complete() ? " (main body only: partial plan)"
                                            : plan.selection.recommended == plan.simulatedFamily ? ""
                                                                                                 : " (outside IFU)");
  const StentMesh& mesh = plan.mesh;
  plan.rows.push_back({ "mainBodyDiameter", family.mainBody.diameterMm, "mm",
                        name + " main body, " + FormatNumber(family.mainBody.oversizingPercent) + over + "(a)", "aorta",
                        plan.measurements.site.abscissaMm });
  plan.rows.push_back({ "rightLimbDiameter", family.rightLimb.diameterMm, "mm",
                        name + " right limb, " + FormatNumber(family.rightLimb.oversizingPercent) + over + "(e)",
                        "rightIliac", mesh.ringAbscissaMm[RightLegSegment].back() });
  plan.rows.push_back({ "leftLimbDiameter", family.leftLimb.diameterMm, "mm",
                        name + " left limb, " + FormatNumber(family.leftLimb.oversizingPercent) + over + "(f)",
                        "leftIliac", mesh.ringAbscissaMm[LeftLegSegment].back() });
  for (std::size_t i = plan.rows.size() - 3; i < plan.rows.size(); ++i)
    plan.rows[i].wall = wall;
  for (const Measurement& m : FitCheckRows(plan.fitCheck, mesh))
    plan.rows.push_back(m);
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
    report.Warn("The plan is partial: the scan ends above the iliac landing zones, so the limbs cannot be sized, "
                "and no catalogue main body fits the neck (" +
                plan.selection.summary +
                "); no graft is simulated, so its sizes, seal lengths, oversizing and fit "
                "check are not available.");
    return;
  }
  report.Begin("SimulateGraft", "Simulating the chosen main body in the aorta (partial plan)");
  const FamilyEvaluation& family = plan.selection.families[std::size_t(chosen)];
  const SizeChoice* limbs[2] = { &family.rightLimb, &family.leftLimb };
  plan.graftDiametersMm = { family.mainBody.diameterMm, std::numeric_limits<double>::quiet_NaN(),
                            std::numeric_limits<double>::quiet_NaN() };
  ActiveContourParams graftParams = params.graft;
  graftParams.balloonRadiusMm[TrunkSegment] = family.mainBody.diameterMm / 2.0;
  for (int side = 0; side < 2; ++side)
  {
    const int seg = 1 + side;
    if (limbs[side]->Chosen())
    {
      plan.graftDiametersMm[std::size_t(seg)] = limbs[side]->diameterMm;
      graftParams.balloonRadiusMm[std::size_t(seg)] = limbs[side]->diameterMm / 2.0;
      continue;
    }
    std::vector<double> means;
    for (const RingDiameters& r : plan.measurements.profiles[std::size_t(seg)].rings)
      if (std::isfinite(r.meanMm))
        means.push_back(r.meanMm);
    graftParams.balloonRadiusMm[std::size_t(seg)] =
      means.empty() ? params.graft.balloonRadiusMm[std::size_t(seg)] : Median(means) / 2.0;
  }
  plan.graft = FitActiveContour(plan.mesh, wall, graftParams, report.Callback());
  plan.fitCheck = CheckGraftFit(plan.mesh, plan.graft.V, plan.graft.wallDistanceMm, plan.measurements, plan.centerlines,
                                plan.graftDiametersMm, FitCheckParams{}, &plan.vesselWall);
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

void ChooseAndSimulateDevice(const WallDistanceField& wall,
                             const PlanRequest& request,
                             const PlanParams& params,
                             const StageReporter& report,
                             RepairPlan& plan)
{
  report.Begin("SelectDevice", "Choosing the stent graft from the device catalogue");
  plan.selection = SelectDevice(SizingFromMeasurements(plan.measurements), params.catalog, params.selection);
  plan.simulatedFamily = FamilyToSimulate(plan.selection);
  // A partial plan whose scan ends above a limb's landing zone: nothing to size that limb on.
  const bool limbUnsized = std::isnan(plan.measurements.Value("rightIliacLumenDiameter")) ||
                           std::isnan(plan.measurements.Value("leftIliacLumenDiameter"));
  if (plan.simulatedFamily < 0 && plan.centerlines.Partial() && limbUnsized)
  {
    if (request.requireSimulatedGraft)
      throw AlgorithmError("The plan is partial: the scan ends above the iliac landing zones, so the limbs cannot be "
                           "sized and no graft is simulated for outputSimulatedStentModel; give a scan that covers "
                           "the common iliac arteries to their bifurcations.");
    SimulateTheMainBodyOnly(wall, params, report, plan);
    return;
  }
  if (plan.simulatedFamily < 0)
  {
    const std::string why = "No catalogue device has a main body and both limbs within the oversizing ranges (" +
                            plan.selection.summary + ")";
    if (request.requireSimulatedGraft)
      throw AlgorithmError(why + ", so there is no graft to simulate for outputSimulatedStentModel; widen "
                                 "proximalOversizingRange or limbOversizingRange, or force one with --device.");
    report.Warn(why + "; no graft was simulated, so its sizes, seal lengths, oversizing and fit check are not "
                      "available.");
    return;
  }
  report.Begin("SimulateGraft", "Simulating the chosen stent graft in the vessel");
  const FamilyEvaluation& family = plan.selection.families[plan.simulatedFamily];
  plan.graftDiametersMm = { family.mainBody.diameterMm, family.rightLimb.diameterMm, family.leftLimb.diameterMm };
  ActiveContourParams graftParams = params.graft;
  for (int s = 0; s < 3; ++s)
    graftParams.balloonRadiusMm[s] = plan.graftDiametersMm[s] / 2.0;
  plan.graft = FitActiveContour(plan.mesh, wall, graftParams, report.Callback());
  plan.fitCheck = CheckGraftFit(plan.mesh, plan.graft.V, plan.graft.wallDistanceMm, plan.measurements, plan.centerlines,
                                plan.graftDiametersMm, FitCheckParams{}, &plan.vesselWall);
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
  if (!ct)
    throw InputError("PlanRepair was given no CT volume; expected a 3-D image in HU.");
  RepairPlan plan;
  const StageReporter report(observer, plan);
  if (seedLps)
  {
    plan.seedLps = *seedLps;
    plan.seedAutomatic = false;
  }
  else
  {
    report.Begin("FindSeed", "Finding the aorta for an automatic seed");
    AorticSeedParams search;
    search.minimumHu = params.growing.seedMinimumHu;
    const AorticSeed found = FindAorticSeed(*ct, search);
    plan.seedLps = found.lps;
    plan.seedAutomatic = true;
    plan.seedDescription = found.description;
  }
  SegmentLumen(*ct, plan.seedLps, params, report, plan);
  // Only the wall stage reads HU after segmentation, and only within its rays' reach of the lumen:
  // keep that crop and free the input if the caller handed it over.
  CtImage::Pointer around = request.through >= PlanStage::Measurements
                              ? CropAroundLumen(*ct, *plan.lumen.mask, params.wall.outer.maxRadiusMm)
                              : nullptr;
  ct = nullptr;
  plan.reached = PlanStage::Segmentation;
  if (request.through < PlanStage::Centerlines)
    return plan;

  ExtractCenterlines(params, report, plan);
  plan.reached = PlanStage::Centerlines;
  if (request.through < PlanStage::StentSurface)
    return plan;

  // The wall stage needs the site, not the fit: it runs on the second core while the stent
  // surface is fitted (declared after `around` and `plan`, so it is waited for before either goes).
  std::future<TracedWall> traced;
  const auto startWall = [&]
  {
    if (around)
      traced = std::async(std::launch::async, [&] { return TraceWall(*around, request, params, plan); });
  };
  const WallDistanceField wall = FitStentSurface(request, params, report, plan, startWall);
  plan.reached = PlanStage::StentSurface;
  if (request.through < PlanStage::Measurements)
    return plan;

  ReportWall(traced.get(), params, report, plan);
  if (request.ctAroundLumen)
    plan.ctAroundLumen = around;
  around = nullptr;
  Measure(wall, params, report, plan);
  plan.reached = PlanStage::Measurements;
  if (request.through < PlanStage::Device)
    return plan;

  ChooseAndSimulateDevice(wall, request, params, report, plan);
  plan.reached = PlanStage::Device;
  return plan;
}

} // namespace sgp
