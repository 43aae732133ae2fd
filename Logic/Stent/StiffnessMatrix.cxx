#include "Stent/StiffnessMatrix.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include "Common/CheckRange.h"

namespace sgp
{

namespace
{

/// Accumulates stencil rows of a difference operator.
struct RowBuilder
{
  std::vector<Eigen::Triplet<double>> entries;
  int rows = 0;
  void Add(std::initializer_list<std::pair<int, double>> stencil)
  {
    for (const auto& [column, value] : stencil)
      entries.emplace_back(rows, column, value);
    ++rows;
  }
  SparseMatrix Build(int columns) const
  {
    SparseMatrix D(rows, columns);
    D.setFromTriplets(entries.begin(), entries.end()); // duplicates (a vertex twice in a stencil) add up
    return D;
  }
};

} // namespace

DifferenceOperators BuildDifferenceOperators(const StentMesh& mesh)
{
  const int count = static_cast<int>(mesh.V.rows());
  // The next vertex around each vertex's ring.
  std::vector<int> next(count, -1);
  for (const auto& ring : mesh.rings)
    for (std::size_t j = 0; j < ring.size(); ++j)
      next[ring[j]] = ring[(j + 1) % ring.size()];
  RowBuilder ds, dt, dss, dtt, dst;
  // Each s-edge and s-triple once, however many chains run through it (chains share their first
  // rings at the junction); read backwards a stencil is the same row up to its sign.
  std::set<std::pair<int, int>> edges;
  std::set<std::array<int, 3>> triples;
  for (const auto& chain : mesh.chains)
  {
    for (std::size_t i = 0; i + 1 < chain.size(); ++i)
    {
      const int a = chain[i], b = chain[i + 1];
      if (!edges.insert(std::minmax(a, b)).second)
        continue;
      ds.Add({ { b, 1.0 }, { a, -1.0 } });
      dst.Add({ { next[b], 1.0 }, { b, -1.0 }, { next[a], -1.0 }, { a, 1.0 } });
    }
    for (std::size_t i = 0; i + 2 < chain.size(); ++i)
    {
      const int a = chain[i], c = chain[i + 2];
      if (!triples.insert({ std::min(a, c), chain[i + 1], std::max(a, c) }).second)
        continue;
      dss.Add({ { a, 1.0 }, { chain[i + 1], -2.0 }, { c, 1.0 } });
    }
  }
  for (const auto& ring : mesh.rings)
  {
    const std::size_t n = ring.size();
    for (std::size_t j = 0; j < n; ++j)
    {
      dt.Add({ { ring[(j + 1) % n], 1.0 }, { ring[j], -1.0 } });
      dtt.Add({ { ring[(j + n - 1) % n], 1.0 }, { ring[j], -2.0 }, { ring[(j + 1) % n], 1.0 } });
    }
  }
  return { ds.Build(count), dt.Build(count), dss.Build(count), dtt.Build(count), dst.Build(count) };
}

SparseMatrix AssembleStiffnessMatrix(const StentMesh& mesh, const StiffnessWeights& w)
{
  const double weights[5] = { w.w1, w.w2, w.w3, w.w4, w.w5 };
  for (int k = 0; k < 5; ++k)
    CheckRange("w" + std::to_string(k + 1), weights[k], 0.0, 1e6, "");
  const DifferenceOperators d = BuildDifferenceOperators(mesh);
  const SparseMatrix* operators[5] = { &d.Ds, &d.Dt, &d.Dss, &d.Dtt, &d.Dst };
  SparseMatrix K(mesh.V.rows(), mesh.V.rows());
  for (int k = 0; k < 5; ++k)
    if (weights[k] > 0.0)
      K += weights[k] * SparseMatrix(operators[k]->transpose() * *operators[k]);
  K.makeCompressed();
  return K;
}

double InternalEnergy(const SparseMatrix& K, const Points& V)
{
  double energy = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    const Eigen::VectorXd x = V.col(c);
    energy += 0.5 * x.dot(K * x);
  }
  return energy;
}

} // namespace sgp
