// The visual report on the 512 × 512 × 400 phantom (issue 15: report, straightened views and
// cross-sections together under 0.5 s): the two straightened views, the six cross-sections, their
// PNG encoding and the HTML page, from a plan made once outside the timing (with the CT crop the
// CLI keeps for the report). The straightened volumes, a separate output, are timed beside it.
#include <benchmark/benchmark.h>

#include "IO/ReadDeviceCatalog.h"
#include "IO/ReadNeckRules.h"
#include "IO/ReportHtml.h"
#include "LargePhantom.h"
#include "Pipeline/PlanRepair.h"
#include "Views/ReportFigures.h"
#include "Views/ResliceCt.h"
#include "Views/VesselPath.h"

namespace
{

const sgp::RepairPlan& LargePlan()
{
  static const sgp::RepairPlan plan = []
  {
    const sgp::AorticPhantom& phantom = sgp::benchmarks::LargePhantom();
    sgp::PlanParams params;
    params.catalog = sgp::ReadDeviceCatalog(SGP_DEVICES_JSON);
    params.neckRules = sgp::ReadNeckRules(SGP_NECK_RULES_JSON);
    sgp::PlanRequest request;
    request.ctAroundLumen = true;
    return sgp::PlanRepair(phantom.ct, phantom.truth.seedLps, request, params);
  }();
  return plan;
}

void BM_VisualReport_512x512x400(benchmark::State& state)
{
  const sgp::RepairPlan& plan = LargePlan();
  std::size_t bytes = 0;
  for (auto _ : state)
  {
    const sgp::ReportFigures figures = sgp::BuildReportFigures(plan, *plan.ctAroundLumen);
    bytes = sgp::ReportHtml(plan, figures, { "phantom", "devices.json", "rules.json", "now", "0" }).size();
  }
  state.counters["bytes"] = double(bytes);
}

void BM_StraightenedVolumes_512x512x400(benchmark::State& state)
{
  const sgp::RepairPlan& plan = LargePlan();
  for (auto _ : state)
    for (const sgp::Centerline* iliac : { &plan.centerlines.rightIliac, &plan.centerlines.leftIliac })
    {
      const sgp::VesselPath path = sgp::SampleVesselPath(plan.centerlines.aorta, *iliac, 0.7);
      benchmark::DoNotOptimize(sgp::StraightenVolume(*plan.ctAroundLumen, path, 40.0));
    }
}

} // namespace

BENCHMARK(BM_VisualReport_512x512x400)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();
BENCHMARK(BM_StraightenedVolumes_512x512x400)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();
