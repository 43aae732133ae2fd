#include "Measurement/SectionTilt.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Geometry>

#include "Common/PlaneDiameters.h"
#include "Common/SmoothMask.h"

namespace sgp
{
namespace
{

constexpr double pi = 3.14159265358979323846;
constexpr double stepMm = 0.1, farthestMm = 100.0;

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

/// One plane's diameters through `centre`: their mean, smallest and largest.
struct PlaneReading
{
  double meanMm = 0.0, minMm = 0.0, maxMm = 0.0;
};

PlaneReading ReadPlane(const SmoothMask& mask, const Point3& centre, const Eigen::Vector3d& normal, int count)
{
  const std::vector<double> d =
    DiametersInPlane(normal, count, [&](const Eigen::Vector3d& e) { return SmoothBoundaryDistance(mask, centre, e); });
  double sum = 0.0;
  for (double x : d)
    sum += x;
  const auto [low, high] = std::minmax_element(d.begin(), d.end());
  return { sum / count, *low, *high };
}

} // namespace

double SmoothBoundaryDistance(const SmoothMask& mask, const Point3& centre, const Eigen::Vector3d& e)
{
  double in = 0.0, out = 0.5;
  while (out < farthestMm && mask(centre + out * e) >= 0.5)
  {
    in = out;
    out += 0.5;
  }
  while (out - in > 0.01)
  {
    const double mid = 0.5 * (in + out);
    (mask(centre + mid * e) >= 0.5 ? in : out) = mid;
  }
  return 0.5 * (in + out);
}

double LumenMeanDiameterMm(const LabelImage& lumen,
                           const Point3& centre,
                           const Eigen::Vector3d& normal,
                           int diameterCount)
{
  return MeanDiameterInPlane(normal, diameterCount,
                             [&](const Eigen::Vector3d& e) { return BoundaryDistance(lumen, centre, e); });
}

double TiltSensitivityMm(const LabelImage& lumen, const Point3& centre, const Eigen::Vector3d& normal, double tiltDeg)
{
  const Eigen::Vector3d n = normal.normalized(), u = PerpendicularTo(n), v = n.cross(u);
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

NarrowestSection FindNarrowestSection(const LabelImage& lumen,
                                      const Point3& centre,
                                      const Eigen::Vector3d& normal,
                                      double maxTiltDeg,
                                      int diameterCount)
{
  const SmoothMask mask(lumen);
  const Eigen::Vector3d n = normal.normalized(), u = PerpendicularTo(n), v = n.cross(u);
  // The normal tilted by `tiltDeg` toward the in-plane direction at `azimuthDeg`.
  const auto tilted = [&](double tiltDeg, double azimuthDeg)
  {
    const double a = azimuthDeg * pi / 180.0;
    const Eigen::Vector3d toward = std::cos(a) * u + std::sin(a) * v;
    return Eigen::Vector3d(Eigen::AngleAxisd(tiltDeg * pi / 180.0, n.cross(toward)) * n);
  };
  const PlaneReading given = ReadPlane(mask, centre, n, diameterCount);
  PlaneReading narrowest = given;
  NarrowestSection best;
  best.normal = n;
  double bestAzimuth = 0.0;
  const auto consider = [&](double tiltDeg, double azimuthDeg)
  {
    if (tiltDeg < 0.0 || tiltDeg > maxTiltDeg + 1e-9)
      return;
    const Eigen::Vector3d candidate = tilted(tiltDeg, azimuthDeg);
    const PlaneReading reading = ReadPlane(mask, centre, candidate, diameterCount);
    if (reading.meanMm < narrowest.meanMm)
    {
      narrowest = reading;
      best.normal = candidate;
      best.tiltDeg = tiltDeg;
      bestAzimuth = azimuthDeg;
    }
  };
  for (double tilt = 3.0; tilt <= maxTiltDeg + 1e-9; tilt += 3.0)
    for (double azimuth = 0.0; azimuth < 360.0; azimuth += 20.0)
      consider(tilt, azimuth);
  const double tilt0 = best.tiltDeg, azimuth0 = bestAzimuth;
  if (tilt0 > 0.0)
    for (double dt = -1.5; dt <= 1.5 + 1e-9; dt += 0.5)
      for (double da = -10.0; da <= 10.0 + 1e-9; da += 2.5)
        consider(tilt0 + dt, azimuth0 + da);
  best.meanMm = narrowest.meanMm;
  best.minMm = narrowest.minMm;
  best.maxMm = narrowest.maxMm;
  best.givenPlaneMeanMm = given.meanMm;
  best.givenPlaneMinMm = given.minMm;
  best.givenPlaneMaxMm = given.maxMm;
  return best;
}

} // namespace sgp
