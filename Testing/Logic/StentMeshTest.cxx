// The initial bifurcated stent surface: rings, frames, the connection element, closure.
#include <map>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include "Common/Errors.h"
#include "Stent/StentMesh.h"
#include "YPhantom.h"

namespace sgp
{
namespace
{

StentMesh YMesh(const StentMeshParams& params = {})
{
  return BuildStentMesh(testing::MakeYPhantom(2.0).tree, params);
}

TEST(StentMesh, Rings_PerpendicularAtStartRadiusWithoutTwist)
{
  StentMeshParams p;
  p.startRadiusMm = 4.0;
  const StentMesh mesh = YMesh(p);
  const int n = mesh.verticesPerRing;
  EXPECT_EQ(mesh.V.rows(), n * (mesh.RingsIn(0) + mesh.RingsIn(1) + mesh.RingsIn(2)));
  for (Eigen::Index i = 0; i < mesh.V.rows(); ++i)
  {
    const Eigen::Vector3d d = (mesh.V.row(i) - mesh.centre.row(i)).transpose();
    EXPECT_NEAR(d.norm(), 4.0, 1e-9);
    EXPECT_NEAR(d.dot(mesh.axis.row(i).transpose()), 0.0, 1e-9); // in the ring's plane
  }
  // No twist: along the straight trunk, column 0 keeps its direction (toward the patient's left).
  for (int k = 0; k < mesh.RingsIn(TrunkSegment); ++k)
  {
    const Eigen::Vector3d d = (mesh.V.row(mesh.Id(0, k, 0)) - mesh.centre.row(mesh.Id(0, k, 0))).transpose();
    EXPECT_GT(d.normalized().x(), 0.999);
    const Eigen::Vector3d a = (mesh.V.row(mesh.Id(0, k, n / 4)) - mesh.centre.row(mesh.Id(0, k, n / 4))).transpose();
    EXPECT_LT(a.normalized().y(), -0.999); // column n/4 is anterior (−y in LPS)
  }
  // Each leg: column n/2 lateral (away from the other leg), n/4 anterior.
  const Eigen::Vector3d rightLateral =
    (mesh.V.row(mesh.Id(1, 0, n / 2)) - mesh.centre.row(mesh.Id(1, 0, n / 2))).transpose();
  const Eigen::Vector3d leftLateral =
    (mesh.V.row(mesh.Id(2, 0, n / 2)) - mesh.centre.row(mesh.Id(2, 0, n / 2))).transpose();
  EXPECT_LT(rightLateral.x(), -3.0);
  EXPECT_GT(leftLateral.x(), 3.0);
  EXPECT_LT((mesh.V.row(mesh.Id(2, 0, n / 4)) - mesh.centre.row(mesh.Id(2, 0, n / 4)))(1), -3.9);
}

TEST(StentMesh, Surface_ClosedExceptTheThreeTubeEnds)
{
  const StentMesh mesh = YMesh();
  std::map<std::pair<int, int>, int> edges;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int e = 0; e < 3; ++e)
    {
      const int a = mesh.F(f, e), b = mesh.F(f, (e + 1) % 3);
      ++edges[std::minmax(a, b)];
    }
  int boundary = 0, overShared = 0;
  for (const auto& [edge, count] : edges)
  {
    boundary += count == 1;
    overShared += count > 2;
  }
  EXPECT_EQ(overShared, 0);
  EXPECT_EQ(boundary, 3 * mesh.verticesPerRing); // the trunk's top ring and the legs' last rings
  // Euler characteristic of a pair of pants (a sphere with three holes): V − E + F = −1.
  EXPECT_EQ(mesh.V.rows() - long(edges.size()) + mesh.F.rows(), -1);
}

/// Whether segment pq crosses triangle abc (Möller–Trumbore, strictly inside both).
bool SegmentCrossesTriangle(const Point3& p, const Point3& q, const Point3& a, const Point3& b, const Point3& c)
{
  const Eigen::Vector3d d = q - p, e1 = b - a, e2 = c - a, h = d.cross(e2);
  const double det = e1.dot(h);
  if (std::abs(det) < 1e-12)
    return false;
  const Eigen::Vector3d s = p - a;
  const double u = s.dot(h) / det;
  const Eigen::Vector3d qv = s.cross(e1);
  const double v = d.dot(qv) / det, t = e2.dot(qv) / det;
  return u > 1e-9 && v > 1e-9 && u + v < 1 - 1e-9 && t > 1e-9 && t < 1 - 1e-9;
}

TEST(StentMesh, Crotch_NoSelfIntersection)
{
  const StentMesh mesh = YMesh();
  const auto near = [&](int v) { // the connection element and the rings next to it
    return (mesh.segment[v] == TrunkSegment && mesh.ring[v] >= mesh.RingsIn(0) - 2) ||
           (mesh.segment[v] != TrunkSegment && mesh.ring[v] <= 1);
  };
  std::vector<int> faces;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    if (near(mesh.F(f, 0)) || near(mesh.F(f, 1)) || near(mesh.F(f, 2)))
      faces.push_back(int(f));
  ASSERT_GT(faces.size(), 100u);
  int crossings = 0;
  for (int f : faces)
    for (int e = 0; e < 3; ++e)
    {
      const int a = mesh.F(f, e), b = mesh.F(f, (e + 1) % 3);
      for (int g : faces)
      {
        const int x = mesh.F(g, 0), y = mesh.F(g, 1), z = mesh.F(g, 2);
        if (a == x || a == y || a == z || b == x || b == y || b == z)
          continue;
        crossings +=
          SegmentCrossesTriangle(mesh.V.row(a).transpose(), mesh.V.row(b).transpose(), mesh.V.row(x).transpose(),
                                 mesh.V.row(y).transpose(), mesh.V.row(z).transpose());
      }
    }
  EXPECT_EQ(crossings, 0);
}

TEST(StentMesh, Chains_EveryVertexOnOneChainTwoStepsDeepAcrossTheJunction)
{
  const StentMesh mesh = YMesh();
  const int n = mesh.verticesPerRing, last = mesh.RingsIn(0) - 1;
  std::vector<int> onChains(mesh.V.rows(), 0);
  std::map<int, std::pair<int, int>> place; // leg vertex → (chain, position)
  for (int c = 0; c < int(mesh.chains.size()); ++c)
    for (int i = 0; i < int(mesh.chains[c].size()); ++i)
    {
      ++onChains[mesh.chains[c][i]];
      place[mesh.chains[c][i]] = { c, i };
    }
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
    EXPECT_GE(onChains[v], 1);
  // Every first-ring leg vertex has two chain neighbours on each side.
  for (int seg : { 1, 2 })
    for (int j = 0; j < n; ++j)
    {
      const auto [c, i] = place[mesh.Id(seg, 0, j)];
      EXPECT_GE(i, 2);
      EXPECT_LE(i + 2, int(mesh.chains[c].size()) - 1);
    }
  // The right half of the trunk continues into the right leg, the crotch joins the legs.
  const auto follows = [&](int a, int b)
  {
    for (const auto& chain : mesh.chains)
      for (std::size_t i = 0; i + 1 < chain.size(); ++i)
        if (chain[i] == a && chain[i + 1] == b)
          return true;
    return false;
  };
  EXPECT_TRUE(follows(mesh.Id(0, last, n / 2), mesh.Id(1, 0, n / 2)));
  EXPECT_TRUE(follows(mesh.Id(0, last, 0), mesh.Id(2, 0, n / 2)));
  EXPECT_TRUE(follows(mesh.Id(1, 0, 0), mesh.Id(2, 0, 0)));
}

TEST(StentMesh, ParameterOutOfRange_InputError)
{
  StentMeshParams p;
  p.verticesPerRing = 18;
  EXPECT_THROW(YMesh(p), InputError); // not a multiple of 4
  p = {};
  p.ringSpacingMm = 0.1;
  EXPECT_THROW(YMesh(p), InputError);
  p = {};
  p.ringSpacingMm = 19.0;
  p.legLengthMm = 5.0; // one ring per leg
  EXPECT_THROW(YMesh(p), InputError);
}

} // namespace
} // namespace sgp
