// The active contour's linear algebra at the paper's size (624 vertices) and beyond, side by side
// with the paper's own approach — a dense inverse of I + τK, here computed with Eigen. Targets (the
// ACM issue): factorization under 10 ms and one iteration under 1 ms at 624 vertices (the paper:
// 80 s for the inverse, "less than one second" a step), and time per iteration growing linearly
// with the vertex count (10,000 and 50,000 vertices).
#include <map>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <benchmark/benchmark.h>

#include "Stent/ActiveContour.h"
#include "YPhantom.h"

namespace
{

struct Case
{
  sgp::StentMesh mesh;
  sgp::SparseMatrix A; ///< I + τK
  std::unique_ptr<sgp::WallDistanceField> wall;
};

/// A long Y (aorta 900 mm, iliacs 450 mm; radii 10 and 6 mm, 2 mm voxels) on which meshes of
/// 16 vertices a ring reach 50,000 vertices at the smallest ring spacing: the ring size, and so
/// the bandwidth of I + τK, stays the same at every size.
const sgp::testing::YPhantom& LongY()
{
  static const sgp::testing::YPhantom y = []
  {
    sgp::testing::YPhantom long_;
    const sgp::Point3 top(0, 0, 1000), bifurcation(0, 0, 100), right(-150, 0, -330), left(150, 0, -330);
    long_.capsules = { { top, bifurcation, 10.0 }, { bifurcation, right, 6.0 }, { bifurcation, left, 6.0 } };
    long_.tree.aorta = sgp::testing::StraightCenterline("aorta", top, bifurcation, 10.0);
    long_.tree.rightIliac = sgp::testing::StraightCenterline("rightIliac", bifurcation, right, 6.0);
    long_.tree.leftIliac = sgp::testing::StraightCenterline("leftIliac", bifurcation, left, 6.0);
    long_.mask = sgp::testing::PaintCapsules(long_.capsules, { 2.0, 2.0, 2.0 });
    return long_;
  }();
  return y;
}

/// A bifurcated mesh of about `vertices` vertices, 16 a ring, on the long Y.
Case& CaseOf(int vertices)
{
  static std::map<int, Case> cases;
  auto found = cases.find(vertices);
  if (found != cases.end())
    return found->second;
  const sgp::testing::YPhantom& y = LongY();
  sgp::StentMeshParams p;
  p.proximalAbscissaMm = 0.0;
  p.legLengthMm = 400.0;
  const int rings = vertices / p.verticesPerRing;
  // Trunk, right leg, left leg: about 891 + 2 × 401 mm of rings for `rings` rings.
  p.ringSpacingMm = std::max(0.5, (891.0 + 2 * 401.0) / std::max(rings - 3, 1));
  // The paper's case is shorter than the long Y: for it, the trunk and legs are trimmed instead.
  if (p.ringSpacingMm > 20.0)
  {
    p.ringSpacingMm = 8.0;
    p.legLengthMm = 8.0 * (rings / 4);
    p.proximalAbscissaMm = 891.0 - 8.0 * (rings / 2 - 1);
  }
  Case c;
  c.mesh = sgp::BuildStentMesh(y.tree, p);
  const auto params = sgp::ActiveContourParams::Measure();
  const sgp::SparseMatrix K = sgp::AssembleStiffnessMatrix(c.mesh, params.weights);
  c.A.resize(K.rows(), K.cols());
  c.A.setIdentity();
  c.A += params.tau * K;
  c.wall = std::make_unique<sgp::WallDistanceField>(sgp::WallDistanceField::FromLumen(*y.mask));
  return cases.emplace(vertices, std::move(c)).first->second;
}

void BM_FactorizeSparseLDLT(benchmark::State& state)
{
  Case& c = CaseOf(static_cast<int>(state.range(0)));
  for (auto _ : state)
  {
    Eigen::SimplicialLDLT<sgp::SparseMatrix> solver(c.A);
    benchmark::DoNotOptimize(solver.info());
  }
  state.counters["vertices"] = double(c.mesh.V.rows());
}
BENCHMARK(BM_FactorizeSparseLDLT)->Arg(624)->Arg(10000)->Arg(50000)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_IterateSparse(benchmark::State& state)
{
  Case& c = CaseOf(static_cast<int>(state.range(0)));
  const auto params = sgp::ActiveContourParams::Measure();
  Eigen::SimplicialLDLT<sgp::SparseMatrix> solver(c.A);
  std::vector<bool> contact(static_cast<std::size_t>(c.mesh.V.rows()), false);
  Eigen::MatrixXd V = c.mesh.V;
  for (auto _ : state)
  {
    const Eigen::MatrixXd b =
      V + params.tau * Eigen::MatrixXd(sgp::ActiveContourForces(c.mesh, *c.wall, params, contact, V));
    V = solver.solve(b);
  }
  state.counters["vertices"] = double(c.mesh.V.rows());
  state.counters["us_per_vertex"] = benchmark::Counter(
    double(c.mesh.V.rows()), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_IterateSparse)->Arg(624)->Arg(10000)->Arg(50000)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_InvertDense_PaperApproach(benchmark::State& state)
{
  Case& c = CaseOf(static_cast<int>(state.range(0)));
  const Eigen::MatrixXd dense(c.A);
  for (auto _ : state)
  {
    Eigen::MatrixXd inverse = dense.inverse();
    benchmark::DoNotOptimize(inverse.data());
  }
  state.counters["vertices"] = double(c.mesh.V.rows());
}
BENCHMARK(BM_InvertDense_PaperApproach)->Arg(624)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_IterateDense_PaperApproach(benchmark::State& state)
{
  Case& c = CaseOf(static_cast<int>(state.range(0)));
  const auto params = sgp::ActiveContourParams::Measure();
  const Eigen::MatrixXd inverse = Eigen::MatrixXd(c.A).inverse();
  std::vector<bool> contact(static_cast<std::size_t>(c.mesh.V.rows()), false);
  Eigen::MatrixXd V = c.mesh.V;
  for (auto _ : state)
  {
    const Eigen::MatrixXd b =
      V + params.tau * Eigen::MatrixXd(sgp::ActiveContourForces(c.mesh, *c.wall, params, contact, V));
    V = inverse * b;
  }
  state.counters["vertices"] = double(c.mesh.V.rows());
}
BENCHMARK(BM_IterateDense_PaperApproach)->Arg(624)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace
