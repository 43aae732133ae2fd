#include "Views/SceneMeshes.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace sgp
{
namespace
{

/// The index box of `mask` covering the LPS box {lo, hi} (clamped to the grid), as first and
/// one-past-last index per axis.
std::array<std::array<long, 2>, 3> IndexBox(const LabelImage& mask, const Point3& lo, const Point3& hi)
{
  const auto size = mask.GetLargestPossibleRegion().GetSize();
  std::array<std::array<long, 2>, 3> box{};
  for (int a = 0; a < 3; ++a)
    box[std::size_t(a)] = { long(size[a]), 0 };
  for (int corner = 0; corner < 8; ++corner)
  {
    LabelImage::PointType p;
    p[0] = (corner & 1) ? hi.x() : lo.x();
    p[1] = (corner & 2) ? hi.y() : lo.y();
    p[2] = (corner & 4) ? hi.z() : lo.z();
    const auto index = mask.TransformPhysicalPointToContinuousIndex<double>(p);
    for (int a = 0; a < 3; ++a)
    {
      box[std::size_t(a)][0] = std::min(box[std::size_t(a)][0], long(std::floor(index[a])));
      box[std::size_t(a)][1] = std::max(box[std::size_t(a)][1], long(std::ceil(index[a])) + 1);
    }
  }
  for (int a = 0; a < 3; ++a)
  {
    box[std::size_t(a)][0] = std::clamp(box[std::size_t(a)][0], 0L, long(size[a]));
    box[std::size_t(a)][1] = std::clamp(box[std::size_t(a)][1], 0L, long(size[a]));
  }
  return box;
}

SceneMesh Coloured(SceneMesh mesh, const Eigen::Vector3d& rgb, double opacity)
{
  mesh.rgb.resize(mesh.V.rows(), 3);
  for (Eigen::Index i = 0; i < mesh.V.rows(); ++i)
    mesh.rgb.row(i) = rgb.transpose();
  mesh.opacity = opacity;
  return mesh;
}

} // namespace

SceneMesh LumenSurface(const LabelImage& mask, const Point3& lo, const Point3& hi, int smoothing)
{
  SceneMesh mesh;
  mesh.name = "lumen";
  const auto box = IndexBox(mask, lo, hi);
  const long nx = box[0][1] - box[0][0], ny = box[1][1] - box[1][0], nz = box[2][1] - box[2][0];
  if (nx < 2 || ny < 2 || nz < 2)
    return Coloured(mesh, Eigen::Vector3d(0.85, 0.25, 0.25), 0.3);
  const auto inside = [&](long i, long j, long k)
  {
    if (i < 0 || j < 0 || k < 0 || i >= nx || j >= ny || k >= nz)
      return false;
    return mask.GetPixel({ { i + box[0][0], j + box[1][0], k + box[2][0] } }) != 0;
  };
  // Cells are the cubes between voxel centres (i, j, k) … (i + 1, j + 1, k + 1), i from −1 to nx − 1,
  // so that the boundary is closed at the box's faces.
  const auto cellKey = [&](long i, long j, long k) { return ((k + 1) * (ny + 1) + (j + 1)) * (nx + 1) + (i + 1); };
  std::unordered_map<long, int> cellVertex;
  std::vector<Eigen::Vector3d> vertices;
  const auto vertexOf = [&](long i, long j, long k)
  {
    const long key = cellKey(i, j, k);
    const auto found = cellVertex.find(key);
    if (found != cellVertex.end())
      return found->second;
    // The mean of the crossed edges' midpoints, in continuous index space.
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    int crossings = 0;
    for (int a = 0; a < 3; ++a)
      for (int u = 0; u < 2; ++u)
        for (int v = 0; v < 2; ++v)
        {
          long p[3] = { i, j, k }, q[3] = { i, j, k };
          const int b = (a + 1) % 3, c = (a + 2) % 3;
          p[b] += u;
          p[c] += v;
          q[b] += u;
          q[c] += v;
          q[a] += 1;
          if (inside(p[0], p[1], p[2]) != inside(q[0], q[1], q[2]))
          {
            sum += 0.5 * (Eigen::Vector3d(double(p[0]), double(p[1]), double(p[2])) +
                          Eigen::Vector3d(double(q[0]), double(q[1]), double(q[2])));
            ++crossings;
          }
        }
    vertices.push_back(crossings ? Eigen::Vector3d(sum / crossings)
                                 : Eigen::Vector3d(double(i) + 0.5, double(j) + 0.5, double(k) + 0.5));
    cellVertex.emplace(key, int(vertices.size()) - 1);
    return int(vertices.size()) - 1;
  };
  std::vector<Eigen::Vector3i> triangles;
  // Every voxel edge along axis a whose two ends differ gets a quad of the four cells around it.
  for (long k = -1; k < nz; ++k)
    for (long j = -1; j < ny; ++j)
      for (long i = -1; i < nx; ++i)
        for (int a = 0; a < 3; ++a)
        {
          long q[3] = { i, j, k };
          q[a] += 1;
          if (inside(i, j, k) == inside(q[0], q[1], q[2]))
            continue;
          const int b = (a + 1) % 3, c = (a + 2) % 3;
          int corner[4];
          for (int n = 0; n < 4; ++n)
          {
            long cell[3] = { i, j, k };
            cell[b] -= (n == 1 || n == 2) ? 1 : 0;
            cell[c] -= (n >= 2) ? 1 : 0;
            corner[n] = vertexOf(cell[0], cell[1], cell[2]);
          }
          triangles.emplace_back(corner[0], corner[1], corner[2]);
          triangles.emplace_back(corner[0], corner[2], corner[3]);
        }
  // Smoothing: each vertex half-way to its neighbours' mean.
  std::vector<std::vector<int>> neighbours(vertices.size());
  for (const Eigen::Vector3i& t : triangles)
    for (int e = 0; e < 3; ++e)
    {
      neighbours[std::size_t(t[e])].push_back(t[(e + 1) % 3]);
      neighbours[std::size_t(t[(e + 1) % 3])].push_back(t[e]);
    }
  for (int round = 0; round < smoothing; ++round)
  {
    std::vector<Eigen::Vector3d> next = vertices;
    for (std::size_t v = 0; v < vertices.size(); ++v)
    {
      if (neighbours[v].empty())
        continue;
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      for (int n : neighbours[v])
        mean += vertices[std::size_t(n)];
      next[v] = 0.5 * (vertices[v] + mean / double(neighbours[v].size()));
    }
    vertices.swap(next);
  }
  mesh.V.resize(Eigen::Index(vertices.size()), 3);
  for (std::size_t v = 0; v < vertices.size(); ++v)
  {
    itk::ContinuousIndex<double, 3> index;
    for (int a = 0; a < 3; ++a)
      index[a] = vertices[v][a] + double(box[std::size_t(a)][0]);
    LabelImage::PointType p;
    mask.TransformContinuousIndexToPhysicalPoint(index, p);
    mesh.V.row(Eigen::Index(v)) << p[0], p[1], p[2];
  }
  mesh.F.resize(Eigen::Index(triangles.size()), 3);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    mesh.F.row(Eigen::Index(t)) = triangles[t].transpose();
  return Coloured(mesh, Eigen::Vector3d(0.85, 0.25, 0.25), 0.3);
}

SceneMesh OuterWallSurface(const VesselWall& wall)
{
  SceneMesh mesh;
  mesh.name = "outer wall";
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> triangles;
  for (const OuterWall& vessel : wall.vessels)
  {
    const OuterWallPlane* previous = nullptr;
    int previousFirst = 0;
    for (const OuterWallPlane& plane : vessel.planes)
    {
      if (!plane.Usable() || plane.contourLps.rows() < 3)
      {
        previous = nullptr;
        continue;
      }
      const int first = int(vertices.size());
      for (Eigen::Index k = 0; k < plane.contourLps.rows(); ++k)
        vertices.push_back(plane.contourLps.row(k).transpose());
      if (previous && previous->contourLps.rows() == plane.contourLps.rows())
      {
        const int K = int(plane.contourLps.rows());
        for (int k = 0; k < K; ++k)
        {
          const int a = previousFirst + k, b = previousFirst + (k + 1) % K, c = first + (k + 1) % K, d = first + k;
          triangles.emplace_back(a, b, c);
          triangles.emplace_back(a, c, d);
        }
      }
      previous = &plane;
      previousFirst = first;
    }
  }
  mesh.V.resize(Eigen::Index(vertices.size()), 3);
  for (std::size_t v = 0; v < vertices.size(); ++v)
    mesh.V.row(Eigen::Index(v)) = vertices[v].transpose();
  mesh.F.resize(Eigen::Index(triangles.size()), 3);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    mesh.F.row(Eigen::Index(t)) = triangles[t].transpose();
  return Coloured(mesh, Eigen::Vector3d(0.85, 0.7, 0.45), 0.15);
}

Eigen::Vector3d ComponentColour(const ConfiguredComponent& component)
{
  switch (component.role)
  {
    case OrderRole::MainBody:
      return { 0.15, 0.35, 0.85 };
    case OrderRole::IpsilateralLimb:
      return { 0.1, 0.65, 0.25 };
    case OrderRole::ContralateralLimb:
      return { 0.95, 0.55, 0.05 };
    case OrderRole::IliacExtension:
      return { 0.55, 0.25, 0.75 };
    case OrderRole::AorticCuff:
      return { 0.0, 0.6, 0.6 };
  }
  return { 0.5, 0.5, 0.5 };
}

SceneMesh GraftSurface(const DeployedGraft& graft)
{
  SceneMesh mesh;
  mesh.name = "graft";
  mesh.V = graft.fit.V;
  mesh.F = graft.layout.mesh.F;
  // Flat per triangle, the component of its first vertex — the quad's corner both its triangles
  // share (StentMesh.h) — so that components do not blend into each other and their borders follow
  // the rings and columns.
  mesh.faceRgb.resize(mesh.F.rows(), 3);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    mesh.faceRgb.row(f) =
      ComponentColour(graft.layout.components[std::size_t(graft.layout.component[mesh.F(f, 0)])]).transpose();
  mesh.opacity = 1.0;
  return mesh;
}

std::array<Point3, 2> GraftBox(const DeployedGraft& graft, double marginMm)
{
  const Points& V = graft.fit.V;
  Point3 lo = V.colwise().minCoeff().transpose(), hi = V.colwise().maxCoeff().transpose();
  return { Point3(lo - Point3::Constant(marginMm)), Point3(hi + Point3::Constant(marginMm)) };
}

} // namespace sgp
