#include "Measurement/SectionTilt.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace sgp
{
namespace
{

constexpr double pi = 3.14159265358979323846;
constexpr double stepMm = 0.1, farthestMm = 100.0;

/// A unit vector ⊥ `n`.
Eigen::Vector3d Perpendicular(const Eigen::Vector3d& n)
{
  const Eigen::Vector3d other = std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  return n.cross(other).normalized();
}

/// Whether the voxel holding `lps` is lumen (outside the image: not).
bool InLumen(const LabelImage& lumen, const Point3& lps)
{
  LabelImage::PointType point;
  for (unsigned a = 0; a < 3; ++a)
    point[a] = lps[a];
  LabelImage::IndexType index;
  return lumen.TransformPhysicalPointToIndex(point, index) && lumen.GetPixel(index) != 0;
}

/// Distance from `centre` along `direction` to the first point outside the lumen, mm (0.1 mm steps).
double BoundaryDistance(const LabelImage& lumen, const Point3& centre, const Eigen::Vector3d& direction)
{
  double r = 0.0;
  while (r < farthestMm && InLumen(lumen, centre + (r + stepMm) * direction))
    r += stepMm;
  return r;
}

} // namespace

double LumenMeanDiameterMm(const LabelImage& lumen,
                           const Point3& centre,
                           const Eigen::Vector3d& normal,
                           int diameterCount)
{
  const Eigen::Vector3d n = normal.normalized(), u = Perpendicular(n), v = n.cross(u);
  double sum = 0.0;
  for (int k = 0; k < diameterCount; ++k)
  {
    const double angle = pi * k / diameterCount;
    const Eigen::Vector3d e = std::cos(angle) * u + std::sin(angle) * v;
    sum += BoundaryDistance(lumen, centre, e) + BoundaryDistance(lumen, centre, -e);
  }
  return sum / diameterCount;
}

double TiltSensitivityMm(const LabelImage& lumen, const Point3& centre, const Eigen::Vector3d& normal, double tiltDeg)
{
  const Eigen::Vector3d n = normal.normalized(), u = Perpendicular(n), v = n.cross(u);
  const double here = LumenMeanDiameterMm(lumen, centre, n);
  double largest = 0.0;
  for (const Eigen::Vector3d& axis : { u, v })
    for (double sign : { -1.0, 1.0 })
    {
      const Eigen::Vector3d tilted = Eigen::AngleAxisd(sign * tiltDeg * pi / 180.0, axis) * n;
      largest = std::max(largest, std::abs(LumenMeanDiameterMm(lumen, centre, tilted) - here));
    }
  return largest;
}

} // namespace sgp
