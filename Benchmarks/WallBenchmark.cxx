// The wall stage on the 512 × 512 × 400 phantom with a wall (issue 12: under 1 s): the CT crop
// around the lumen and the outer wall of the aorta and both common iliacs (two passes each),
// with the thrombus and calcium, as PlanRepair runs it. Segmentation, thinning and the proximal
// site are prepared once, outside the timing.
#include <benchmark/benchmark.h>

#include "Centerlines/ProximalSite.h"
#include "LargePhantom.h"
#include "PipelineSupport.h"
#include "Wall/VesselWall.h"

namespace
{

struct Prepared
{
  sgp::AorticPhantom phantom;
  sgp::LumenSegmentation lumen;
  sgp::CenterlineTree tree;
  sgp::ProximalSite site;
};

/// The benchmarks' 512 × 512 × 400 grid (0.7 × 0.7 × 1.0 mm) with a 1.5 mm wall, a 12 mm crescent
/// of sac thrombus and a 90° sac plaque, in fat.
const Prepared& LargeWallPlan()
{
  static const Prepared prepared = []
  {
    Prepared r{ sgp::GenerateAorticPhantom(sgp::benchmarks::LargeWallPhantomParams()), {}, {}, {} };
    r.lumen = sgp::GrowLumenRegion(*r.phantom.ct, r.phantom.truth.seedLps, sgp::RegionGrowingParams{});
    r.tree = sgp::testing::CenterlinesFromMask(*r.lumen.mask);
    r.site = sgp::FindProximalSite(r.tree);
    return r;
  }();
  return prepared;
}

void BM_WallStage_512x512x400(benchmark::State& state)
{
  const Prepared& p = LargeWallPlan();
  std::size_t planes = 0;
  for (auto _ : state)
  {
    const sgp::CtImage::Pointer crop = sgp::CropAroundLumen(*p.phantom.ct, *p.lumen.mask, 45.0);
    sgp::VesselWallParams params;
    params.calciumHu = std::min(p.lumen.calciumHu, params.calciumHu);
    const sgp::VesselWall wall = sgp::TraceVesselWall(*crop, *p.lumen.mask, p.tree, p.site.abscissaMm, params);
    planes = wall.vessels[0].planes.size() + wall.vessels[1].planes.size() + wall.vessels[2].planes.size();
  }
  state.counters["planes"] = double(planes);
}

} // namespace

BENCHMARK(BM_WallStage_512x512x400)->Unit(benchmark::kMillisecond)->MinTime(3.0)->UseRealTime();
