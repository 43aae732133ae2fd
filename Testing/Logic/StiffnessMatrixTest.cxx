// The stiffness matrix against the mathematics it must satisfy (STYLE.md B6, "Stiffness matrix").
#include <algorithm>
#include <random>
#include <set>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "Common/Errors.h"
#include "Stent/StiffnessMatrix.h"
#include "YPhantom.h"

namespace sgp
{
namespace
{

const StiffnessWeights weights{ 0.3, 0.7, 1.1, 1.3, 0.5 };

StentMesh SmallMesh()
{
  StentMeshParams p;
  p.verticesPerRing = 8;
  p.ringSpacingMm = 12.0;
  return BuildStentMesh(testing::MakeYPhantom(2.0).tree, p);
}

/// E_int written out from the definition of the five operators (the header's table), without
/// the sparse matrices: ½ Σ_k w_k Σ_rows ‖stencil · V‖².
double EnergyFromDefinition(const StentMesh& mesh, const Points& V)
{
  const auto sq = [](const Eigen::RowVector3d& x) { return x.squaredNorm(); };
  std::vector<int> next(mesh.V.rows());
  for (const auto& ring : mesh.rings)
    for (std::size_t j = 0; j < ring.size(); ++j)
      next[ring[j]] = ring[(j + 1) % ring.size()];
  double e = 0.0;
  std::set<std::vector<int>> seen; // each s-pair and s-triple once, in either direction
  const auto first = [&](std::vector<int> stencil)
  {
    if (stencil.back() < stencil.front())
      std::reverse(stencil.begin(), stencil.end());
    return seen.insert(stencil).second;
  };
  for (const auto& chain : mesh.chains)
  {
    for (std::size_t i = 0; i + 1 < chain.size(); ++i)
    {
      const int a = chain[i], b = chain[i + 1];
      if (!first({ a, b }))
        continue;
      e += weights.w1 * sq(V.row(b) - V.row(a));
      e += weights.w5 * sq(V.row(next[b]) - V.row(b) - V.row(next[a]) + V.row(a));
    }
    for (std::size_t i = 0; i + 2 < chain.size(); ++i)
      if (first({ chain[i], chain[i + 1], chain[i + 2] }))
        e += weights.w3 * sq(V.row(chain[i]) - 2 * V.row(chain[i + 1]) + V.row(chain[i + 2]));
  }
  for (const auto& ring : mesh.rings)
    for (std::size_t j = 0; j < ring.size(); ++j)
    {
      const std::size_t n = ring.size();
      e += weights.w2 * sq(V.row(ring[(j + 1) % n]) - V.row(ring[j]));
      e += weights.w4 * sq(V.row(ring[(j + n - 1) % n]) - 2 * V.row(ring[j]) + V.row(ring[(j + 1) % n]));
    }
  return 0.5 * e;
}

TEST(StiffnessMatrix, Symmetric)
{
  const SparseMatrix K = AssembleStiffnessMatrix(SmallMesh(), weights);
  EXPECT_LT(SparseMatrix(K - SparseMatrix(K.transpose())).norm(), 1e-12 * K.norm());
}

TEST(StiffnessMatrix, PositiveSemiDefiniteOnRandomVectors)
{
  const SparseMatrix K = AssembleStiffnessMatrix(SmallMesh(), weights);
  std::mt19937 generator(0);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 200; ++trial)
  {
    Eigen::VectorXd x(K.rows());
    for (Eigen::Index i = 0; i < x.size(); ++i)
      x[i] = normal(generator);
    EXPECT_GE(x.dot(K * x), -1e-9 * x.squaredNorm()); // rounding only
  }
  // And the smallest eigenvalue of the dense copy is zero (translations) up to rounding.
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen{ Eigen::MatrixXd(K) };
  EXPECT_GT(eigen.eigenvalues().minCoeff(), -1e-9 * eigen.eigenvalues().maxCoeff());
  EXPECT_LT(std::abs(eigen.eigenvalues().minCoeff()), 1e-9 * eigen.eigenvalues().maxCoeff());
}

TEST(StiffnessMatrix, TranslationsCostNothing)
{
  const SparseMatrix K = AssembleStiffnessMatrix(SmallMesh(), weights);
  EXPECT_LT((K * Eigen::VectorXd::Ones(K.rows())).norm(), 1e-12);
}

TEST(StiffnessMatrix, EqualsFiniteDifferenceHessianOfTheInternalEnergy)
{
  const StentMesh mesh = SmallMesh();
  const SparseMatrix K = AssembleStiffnessMatrix(mesh, weights);
  const Eigen::MatrixXd dense(K);
  std::mt19937 generator(1);
  std::uniform_real_distribution<double> uniform(-20, 20);
  Points V = mesh.V;
  for (Eigen::Index i = 0; i < V.rows(); ++i)
    for (int c = 0; c < 3; ++c)
      V(i, c) += uniform(generator); // a random, crumpled mesh
  EXPECT_NEAR(InternalEnergy(K, V), EnergyFromDefinition(mesh, V), 1e-9 * EnergyFromDefinition(mesh, V));
  // E is quadratic, so the central second difference is exact up to rounding: with h = 1 mm on
  // energies of ~1e5, rounding is ~1e-10 relative, i.e. ~1e-5 absolute on an entry.
  const double h = 1.0;
  const Eigen::Index n = V.rows();
  double worst = 0.0;
  for (Eigen::Index i = 0; i < n; i += 3)
    for (Eigen::Index j = 0; j < n; j += 5)
    {
      const auto energy = [&](double di, double dj)
      {
        Points W = V;
        W(i, 0) += di;
        W(j, 0) += dj;
        return EnergyFromDefinition(mesh, W);
      };
      const double fd = (energy(h, h) - energy(h, -h) - energy(-h, h) + energy(-h, -h)) / (4 * h * h);
      worst = std::max(worst, std::abs(fd - dense(i, j)));
    }
  EXPECT_LT(worst, 1e-4);
}

TEST(StiffnessMatrix, JunctionStencilsTouchTheVerticesAcrossIt)
{
  const StentMesh mesh = SmallMesh();
  const SparseMatrix K = AssembleStiffnessMatrix(mesh, { 0, 0, 1, 0, 0 }); // ∂²/∂s² only
  const Eigen::MatrixXd dense(K);
  const int n = mesh.verticesPerRing, last = mesh.RingsIn(0) - 1;
  // D_ss couples vertices up to two chain steps apart on either side, so K is non-zero up to
  // four steps: the right leg's lateral column continues the trunk's right half...
  for (int depth = 0; depth <= 1; ++depth)
  {
    EXPECT_NE(dense(mesh.Id(1, 0, n / 2), mesh.Id(0, last - depth, n / 2)), 0.0);
    // ...the left leg's lateral column continues the trunk's left side (column 0 → n/2)...
    EXPECT_NE(dense(mesh.Id(2, 0, n / 2), mesh.Id(0, last - depth, 0)), 0.0);
    // ...and the crotch joins the legs' medial columns.
    EXPECT_NE(dense(mesh.Id(1, 0, 0), mesh.Id(2, depth, 0)), 0.0);
  }
  // Not coupled: the right leg's lateral vertex and the left leg's lateral vertex.
  EXPECT_EQ(dense(mesh.Id(1, 0, n / 2), mesh.Id(2, 0, n / 2)), 0.0);
}

TEST(StiffnessMatrix, EquallyStiffAllRoundEveryTrunkRing)
{
  // On the straight trunk every column is alike, so K's diagonal (the sum of the squared
  // coefficients of every stencil through a vertex) must be the same all round a ring — down to
  // the rings whose stencils reach the junction (two chain steps for D_ss, so the last three).
  // A trunk column on two chains (it was: n/4 and 3n/4 also start the left leg's chains) doubles
  // its stiffness along the whole trunk and dents the fitted sac there.
  const StentMesh mesh = SmallMesh();
  const int n = mesh.verticesPerRing, last = mesh.RingsIn(0) - 1;
  ASSERT_GE(last, 5); // enough trunk rings above the junction for the check to mean something
  for (const StiffnessWeights& w : { StiffnessWeights{ 1, 0, 0, 0, 0 }, StiffnessWeights{ 0, 0, 1, 0, 0 },
                                     StiffnessWeights{ 0, 0, 0, 0, 1 }, weights })
  {
    const SparseMatrix K = AssembleStiffnessMatrix(mesh, w);
    for (int k = 0; k + 3 <= last; ++k)
      for (int j = 1; j < n; ++j)
        EXPECT_NEAR(K.coeff(mesh.Id(0, k, j), mesh.Id(0, k, j)), K.coeff(mesh.Id(0, k, 0), mesh.Id(0, k, 0)), 1e-12)
          << "ring " << k << ", column " << j; // exact sums of small integers times weights
  }
}

TEST(StiffnessMatrix, NegativeWeight_InputError)
{
  EXPECT_THROW(AssembleStiffnessMatrix(SmallMesh(), { 1, -1, 0, 0, 0 }), InputError);
}

} // namespace
} // namespace sgp
