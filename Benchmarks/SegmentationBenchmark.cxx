// Lumen segmentation of the 512 × 512 × 400 phantom. Target (foundation issue): under 2 s on the
// project's 2-core machine, by default (the window from the lumen's core, step 1b) and with the seed's window alone.
// Counters: voxels per second, Dice against the truth, lumen mL.
#include <benchmark/benchmark.h>

#include "LargePhantom.h"
#include "PhantomTestSupport.h"
#include "Segmentation/GrowLumenRegion.h"

namespace
{

void BM_GrowLumenRegion_512x512x400(benchmark::State& state)
{
  const sgp::AorticPhantom& phantom = sgp::benchmarks::LargePhantom();
  sgp::LumenSegmentation lumen;
  for (auto _ : state)
  {
    lumen = sgp::GrowLumenRegion(*phantom.ct, phantom.truth.seedLps, sgp::RegionGrowingParams{});
    benchmark::DoNotOptimize(lumen.mask.GetPointer());
  }
  const double voxels = double(phantom.ct->GetLargestPossibleRegion().GetNumberOfPixels());
  state.counters["voxels_per_s"] = benchmark::Counter(voxels, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["dice"] = sgp::testing::CompareWithTruth(*lumen.mask, *phantom.labels).Dice();
  state.counters["lumen_ml"] = lumen.volumeMl;
}
BENCHMARK(BM_GrowLumenRegion_512x512x400)->Unit(benchmark::kMillisecond)->MinTime(3.0)->UseRealTime();

/// The same without step 1b (windowFromLumen off: the seed's window only, one growth), for the
/// side-by-side table.
void BM_GrowLumenRegionSeedsWindow_512x512x400(benchmark::State& state)
{
  const sgp::AorticPhantom& phantom = sgp::benchmarks::LargePhantom();
  sgp::RegionGrowingParams params;
  params.windowFromLumen = false;
  sgp::LumenSegmentation lumen;
  for (auto _ : state)
  {
    lumen = sgp::GrowLumenRegion(*phantom.ct, phantom.truth.seedLps, params);
    benchmark::DoNotOptimize(lumen.mask.GetPointer());
  }
  state.counters["dice"] = sgp::testing::CompareWithTruth(*lumen.mask, *phantom.labels).Dice();
  state.counters["lumen_ml"] = lumen.volumeMl;
}
BENCHMARK(BM_GrowLumenRegionSeedsWindow_512x512x400)->Unit(benchmark::kMillisecond)->MinTime(3.0)->UseRealTime();

} // namespace
