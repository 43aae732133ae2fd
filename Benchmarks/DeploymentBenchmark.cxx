// The deployment simulation on the 512 × 512 × 400 phantom with a wall (issue 30: under 0.5 s),
// as PlanRepair's SimulateGraft stage runs it: the ordered configuration laid out at its target
// (LayOutGraft), the lumen's wall distance over the graft's reach (the measure-mode fit's when it
// covers it), the active contour with every
// ring held in its plane (DeployGraft) and the fit check on healthy wall (CheckGraftFit). The
// plan up to the configuration is made once, outside the timing.
#include <benchmark/benchmark.h>

#include <optional>
#include <stdexcept>
#include <vector>

#include "Device/DeployGraft.h"
#include "Device/FitCheck.h"
#include "IO/ReadDeviceCatalog.h"
#include "IO/ReadNeckRules.h"
#include "LargePhantom.h"
#include "Pipeline/PlanRepair.h"
#include "Pipeline/PlanTolerance.h"
#include "Stent/WallDistanceField.h"

namespace
{

struct Prepared
{
  sgp::PlanParams params;
  sgp::RepairPlan plan;
  std::optional<sgp::WallDistanceField> measureWall; ///< the measure-mode fit's, as PlanRepair keeps it
};

/// The wall benchmark's grid (0.7 × 0.7 × 1.0 mm, 1.5 mm wall, 12 mm crescent of sac thrombus, a
/// 90° sac plaque, in fat), planned through the device stage.
const Prepared& ConfiguredLargePlan()
{
  static const Prepared prepared = []
  {
    const sgp::AorticPhantom phantom = sgp::GenerateAorticPhantom(sgp::benchmarks::LargeWallPhantomParams());
    Prepared r;
    r.params.catalog = sgp::ReadDeviceCatalog(SGP_DEVICES_JSON);
    r.params.neckRules = sgp::ReadNeckRules(SGP_NECK_RULES_JSON);
    r.plan = sgp::PlanRepair(phantom.ct, phantom.truth.seedLps, sgp::PlanRequest{}, r.params);
    if (r.plan.Configuration() == nullptr || !r.plan.HasGraft())
      throw std::runtime_error("the benchmark phantom's plan has no configured graft to deploy");
    // The measure-mode fit's field over the same region as PlanRepair makes it.
    r.measureWall = sgp::WallDistanceField::FromLumen(
      *r.plan.lumen.mask, sgp::SharedWallBandMm,
      sgp::SharedFieldReach(r.plan.mesh, r.plan.centerlines, r.params.deploymentOffsetMm));
    return r;
  }();
  return prepared;
}

/// The fit check's context as PlanRepair's SimulateGraft stage fills it.
sgp::FitCheckContext FitContext(const Prepared& p)
{
  const sgp::RepairPlan& plan = p.plan;
  const sgp::FamilyEvaluation& family = plan.selection.families[std::size_t(plan.orderedFamily)];
  const sgp::DeviceFamily& catalogued = p.params.catalog.families[std::size_t(family.catalogIndex)];
  sgp::FitCheckContext context;
  context.family = family.family;
  context.minimumIliacSealMm = catalogued.ifu.iliacSealLengthMm.min;
  context.minimumOverlapMm = catalogued.junctions.overlapMm.min;
  context.configurationFindings = plan.Configuration()->findings;
  return context;
}

void BM_DeployGraft_512x512x400(benchmark::State& state)
{
  const Prepared& p = ConfiguredLargePlan();
  const sgp::RepairPlan& plan = p.plan;
  const sgp::DeviceConfiguration& configuration = *plan.Configuration();
  const sgp::FitCheckContext context = FitContext(p);
  std::size_t vertices = 0;
  bool covered = false;
  for (auto _ : state)
  {
    sgp::GraftLayout layout = sgp::LayOutGraft(plan.centerlines, plan.measurements, configuration,
                                               plan.deploymentTargetAbscissaMm, p.params.mesh);
    vertices = std::size_t(layout.mesh.V.rows());
    // The measure-mode field when it covers the graft's reach, else the graft's own (PlanRepair).
    std::optional<sgp::WallDistanceField> own;
    const sgp::WallDistanceField& wall = sgp::WallDistanceField::SharedOrOwn(
      *p.measureWall, *plan.lumen.mask, sgp::SharedWallBandMm, sgp::StentReach(layout.mesh, plan.centerlines), own);
    covered = !own;
    const sgp::DeployedGraft graft = sgp::DeployGraft(std::move(layout), wall, p.params.graft);
    benchmark::DoNotOptimize(sgp::CheckGraftFit(graft, plan.measurements, plan.centerlines, &plan.vesselWall, context));
  }
  state.counters["vertices"] = double(vertices);
  state.counters["measureFieldReused"] = covered ? 1.0 : 0.0;
}

// Issue 47: on top of the deployment, the tolerance analysis (PlanTolerance.h: each component
// displaced up and down until the fit check fails, one fit per displacement): ≤ 0.5 s.
void BM_DeploymentTolerance_512x512x400(benchmark::State& state)
{
  const Prepared& p = ConfiguredLargePlan();
  const sgp::RepairPlan& plan = p.plan;
  const sgp::FitCheckContext context = FitContext(p);
  int simulations = 0;
  bool assessed = false;
  for (auto _ : state)
  {
    const sgp::DeploymentTolerance t = sgp::AssessPlanTolerance(plan, p.params, *p.measureWall, context);
    simulations = t.simulations;
    assessed = t.assessed;
  }
  if (!assessed)
    state.SkipWithError("the benchmark phantom's planned graft does not pass: no tolerance to assess");
  state.counters["simulations"] = double(simulations);
}

} // namespace

BENCHMARK(BM_DeployGraft_512x512x400)->Unit(benchmark::kMillisecond)->MinTime(3.0)->UseRealTime();
BENCHMARK(BM_DeploymentTolerance_512x512x400)->Unit(benchmark::kMillisecond)->MinTime(3.0)->UseRealTime();
