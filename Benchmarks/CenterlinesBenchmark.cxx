// Thinning and skeleton graph of the lumen of the 512 × 512 × 400 phantom (the centerline issue:
// under 1 s, and faster than scikit-image's skeletonize_3d on the same mask, which
// run_benchmarks.py times beside it). The labelling of the Y is timed separately.
#include <benchmark/benchmark.h>

#include "Centerlines/LabelAortoIliacTree.h"
#include "LargePhantom.h"
#include "Segmentation/GrowLumenRegion.h"

namespace
{

const sgp::LabelImage& LargeLumen()
{
  static const sgp::LabelImage::Pointer mask = []
  {
    const sgp::AorticPhantom& phantom = sgp::benchmarks::LargePhantom();
    return sgp::GrowLumenRegion(*phantom.ct, phantom.truth.seedLps, sgp::RegionGrowingParams{}).mask;
  }();
  return *mask;
}

void BM_ThinAndBuildGraph_512x512x400(benchmark::State& state)
{
  const sgp::LabelImage& mask = LargeLumen();
  std::size_t nodes = 0, voxels = 0;
  for (auto _ : state)
  {
    const sgp::Skeleton skeleton = sgp::ThinLabelMap(mask);
    const sgp::SkeletonGraph graph = sgp::BuildSkeletonGraph(skeleton, mask);
    nodes = graph.nodes.size();
    voxels = skeleton.voxels.size();
  }
  state.counters["skeleton_voxels"] = double(voxels);
  state.counters["graph_nodes"] = double(nodes);
}
BENCHMARK(BM_ThinAndBuildGraph_512x512x400)->Unit(benchmark::kMillisecond)->MinTime(3.0)->UseRealTime();

void BM_LabelAortoIliacTree(benchmark::State& state)
{
  const sgp::LabelImage& mask = LargeLumen();
  const sgp::SkeletonGraph graph = sgp::BuildSkeletonGraph(sgp::ThinLabelMap(mask), mask);
  for (auto _ : state)
    benchmark::DoNotOptimize(sgp::LabelAortoIliacTree(graph).sideBranches.size());
}
BENCHMARK(BM_LabelAortoIliacTree)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
