// Google Benchmark of the lumen segmentation on a 512 × 512 × 400 phantom (the foundation issue's
// size: a typical abdominal CTA), with bone and enhancing kidneys. Target: under 2 s on the
// project's 2-core machine. Counters: voxels per second, Dice against the phantom's truth, lumen mL.
#include <benchmark/benchmark.h>

#include "GrowLumenRegion.h"
#include "Phantom/AorticPhantom.h"
#include "PhantomTestSupport.h"

namespace
{

const sgp::AorticPhantom& LargePhantom()
{
  static const sgp::AorticPhantom phantom = [] {
    sgp::PhantomParams p;
    p.spacingMm = { 0.7, 0.7, 1.0 };
    p.sizeVoxels = { 512, 512, 400 };
    p.includeBone = true;
    p.includeKidneys = true;
    return sgp::GenerateAorticPhantom(p);
  }();
  return phantom;
}

void BM_GrowLumenRegion_512x512x400(benchmark::State& state)
{
  const sgp::AorticPhantom& phantom = LargePhantom();
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

} // namespace

BENCHMARK_MAIN();
