#include "Views/RenderScene.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "Common/Errors.h"

namespace sgp
{
namespace
{

constexpr double ambient = 0.3;

/// A projected vertex: pixel coordinates, depth, and its shaded colour (its Lambert intensity
/// times its colour; the intensity alone, in every channel, when the triangle has its own colour).
struct Projected
{
  double x = 0.0, y = 0.0, depth = 0.0;
  Eigen::Vector3d colour = Eigen::Vector3d::Zero();
};

void CheckMesh(const SceneMesh& mesh)
{
  if (mesh.faceRgb.rows() != 0 && mesh.faceRgb.rows() != mesh.F.rows())
    throw InputError("Scene mesh '" + mesh.name + "' has " + std::to_string(mesh.faceRgb.rows()) +
                     " triangle colours for " + std::to_string(mesh.F.rows()) +
                     " triangles; expected one per triangle, or none.");
  if (mesh.faceRgb.rows() == 0 && mesh.rgb.rows() != mesh.V.rows())
    throw InputError("Scene mesh '" + mesh.name + "' has " + std::to_string(mesh.rgb.rows()) + " colours for " +
                     std::to_string(mesh.V.rows()) + " vertices; expected one colour per vertex.");
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int c = 0; c < 3; ++c)
      if (mesh.F(f, c) < 0 || mesh.F(f, c) >= mesh.V.rows())
        throw InputError("Scene mesh '" + mesh.name + "' triangle " + std::to_string(f) + " refers to vertex " +
                         std::to_string(mesh.F(f, c)) + "; expected 0 to " + std::to_string(mesh.V.rows() - 1) + ".");
}

/// Rasterizes one triangle with barycentric interpolation of depth and colour; `blend` < 0:
/// opaque (z-buffered), else the opacity to blend with in front of the z-buffer.
void DrawTriangle(const Projected& a,
                  const Projected& b,
                  const Projected& c,
                  const Eigen::Vector3d& tint,
                  double blend,
                  RenderedImage& image,
                  std::vector<double>& depth,
                  std::vector<Eigen::Vector3d>& colour)
{
  const double area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
  if (std::abs(area) < 1e-12)
    return;
  const int x0 = std::max(0, int(std::floor(std::min({ a.x, b.x, c.x }))));
  const int x1 = std::min(image.width - 1, int(std::ceil(std::max({ a.x, b.x, c.x }))));
  const int y0 = std::max(0, int(std::floor(std::min({ a.y, b.y, c.y }))));
  const int y1 = std::min(image.height - 1, int(std::ceil(std::max({ a.y, b.y, c.y }))));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x)
    {
      const double px = x + 0.5, py = y + 0.5; // pixel centre
      const double wa = ((b.x - px) * (c.y - py) - (c.x - px) * (b.y - py)) / area;
      const double wb = ((c.x - px) * (a.y - py) - (a.x - px) * (c.y - py)) / area;
      const double wc = 1.0 - wa - wb;
      if (wa < 0.0 || wb < 0.0 || wc < 0.0)
        continue;
      const double z = wa * a.depth + wb * b.depth + wc * c.depth;
      const std::size_t i = std::size_t(y) * std::size_t(image.width) + std::size_t(x);
      if (z >= depth[i])
        continue;
      const Eigen::Vector3d shade = (wa * a.colour + wb * b.colour + wc * c.colour).cwiseProduct(tint);
      if (blend < 0.0)
      {
        depth[i] = z;
        colour[i] = shade;
      }
      else
        colour[i] = (1.0 - blend) * colour[i] + blend * shade;
    }
}

} // namespace

SceneView AnteriorView()
{
  return { "anterior", Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY() };
}

SceneView LeftLateralView()
{
  return { "left lateral", Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitX() };
}

Points VertexNormals(const Points& V, const Triangles& F)
{
  Points N = Points::Zero(V.rows(), 3);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
  {
    const Eigen::Vector3d a = V.row(F(f, 0)).transpose(), b = V.row(F(f, 1)).transpose(),
                          c = V.row(F(f, 2)).transpose();
    const Eigen::Vector3d n = (b - a).cross(c - a); // twice the area, along the normal
    for (int k = 0; k < 3; ++k)
      N.row(F(f, k)) += n.transpose();
  }
  for (Eigen::Index i = 0; i < N.rows(); ++i)
  {
    const double length = N.row(i).norm();
    if (length > 0.0)
      N.row(i) /= length;
  }
  return N;
}

RenderedImage RenderScene(const std::vector<SceneMesh>& meshes, const SceneView& view, int widthPx, double marginMm)
{
  const Eigen::Matrix3d axes =
    (Eigen::Matrix3d() << view.right.transpose(), view.up.transpose(), view.forward.transpose()).finished();
  if (!(axes * axes.transpose()).isApprox(Eigen::Matrix3d::Identity(), 1e-9))
    throw InputError("The view '" + view.name +
                     "' has axes that are not orthonormal; expected right, up and forward "
                     "unit vectors at right angles.");
  double xMin = std::numeric_limits<double>::infinity(), xMax = -xMin, yMin = xMin, yMax = -xMin;
  for (const SceneMesh& mesh : meshes)
  {
    CheckMesh(mesh);
    for (Eigen::Index i = 0; i < mesh.V.rows(); ++i)
    {
      const Eigen::Vector3d p = mesh.V.row(i).transpose();
      xMin = std::min(xMin, p.dot(view.right));
      xMax = std::max(xMax, p.dot(view.right));
      yMin = std::min(yMin, p.dot(view.up));
      yMax = std::max(yMax, p.dot(view.up));
    }
  }
  if (!std::isfinite(xMin))
    throw InputError("The 3-D view '" + view.name + "' was given no vertices to draw.");
  xMin -= marginMm;
  xMax += marginMm;
  yMin -= marginMm;
  yMax += marginMm;
  RenderedImage image;
  image.width = std::max(1, widthPx);
  image.pixelMm = (xMax - xMin) / image.width;
  image.height = std::max(1, int(std::ceil((yMax - yMin) / image.pixelMm)));
  const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
  std::vector<double> depth(pixels, std::numeric_limits<double>::infinity());
  std::vector<Eigen::Vector3d> colour(pixels, Eigen::Vector3d::Ones());
  for (const bool opaquePass : { true, false })
    for (const SceneMesh& mesh : meshes)
    {
      if ((mesh.opacity >= 1.0) != opaquePass)
        continue;
      const Points normals = VertexNormals(mesh.V, mesh.F);
      const bool flat = mesh.faceRgb.rows() != 0;
      std::vector<Projected> projected(std::size_t(mesh.V.rows()));
      for (Eigen::Index i = 0; i < mesh.V.rows(); ++i)
      {
        const Eigen::Vector3d p = mesh.V.row(i).transpose();
        Projected& q = projected[std::size_t(i)];
        q.x = (p.dot(view.right) - xMin) / image.pixelMm;
        q.y = (yMax - p.dot(view.up)) / image.pixelMm;
        q.depth = p.dot(view.forward);
        const double lambert = std::abs(normals.row(i).dot(view.forward.transpose()));
        const double intensity = ambient + (1.0 - ambient) * lambert;
        q.colour =
          flat ? Eigen::Vector3d::Constant(intensity) : Eigen::Vector3d(intensity * mesh.rgb.row(i).transpose());
      }
      for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
        DrawTriangle(projected[std::size_t(mesh.F(f, 0))], projected[std::size_t(mesh.F(f, 1))],
                     projected[std::size_t(mesh.F(f, 2))],
                     flat ? Eigen::Vector3d(mesh.faceRgb.row(f).transpose()) : Eigen::Vector3d::Ones(),
                     opaquePass ? -1.0 : mesh.opacity, image, depth, colour);
    }
  image.rgb.resize(pixels * 3);
  for (std::size_t i = 0; i < pixels; ++i)
    for (int c = 0; c < 3; ++c)
      image.rgb[i * 3 + std::size_t(c)] = std::uint8_t(std::lround(std::clamp(colour[i][c], 0.0, 1.0) * 255.0));
  return image;
}

} // namespace sgp
