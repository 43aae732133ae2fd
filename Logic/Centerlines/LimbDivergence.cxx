#include "Centerlines/LimbDivergence.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sgp
{

namespace
{

double Length(const std::vector<Point3>& path)
{
  double length = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i)
    length += (path[i] - path[i - 1]).norm();
  return length;
}

/// The point at arc length s along the path (its end beyond it) and the radius there.
std::pair<Point3, double> At(const std::vector<Point3>& path, const std::vector<double>& radii, double s)
{
  for (std::size_t i = 1; i < path.size(); ++i)
  {
    const double step = (path[i] - path[i - 1]).norm();
    if (s <= step && step > 0.0)
    {
      const double t = s / step;
      return { path[i - 1] + t * (path[i] - path[i - 1]), (1.0 - t) * radii[i - 1] + t * radii[i] };
    }
    s -= step;
  }
  return { path.back(), radii.back() };
}

} // namespace

LimbDivergence MeasureLimbDivergence(const std::vector<Point3>& a,
                                     const std::vector<double>& radiiA,
                                     const std::vector<Point3>& b,
                                     const std::vector<double>& radiiB,
                                     double reachMm)
{
  constexpr double shortestMm = 4.0;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  LimbDivergence result{ nan, nan, 0.0 };
  if (a.empty() || b.empty() || radiiA.size() != a.size() || radiiB.size() != b.size())
    return result;
  result.reachMm = std::min({ Length(a), Length(b), reachMm });
  if (result.reachMm < shortestMm)
    return result;
  const double s = result.reachMm;
  const auto [a1, ra1] = At(a, radiiA, s);
  const auto [b1, rb1] = At(b, radiiB, s);
  const auto [a2, ra2] = At(a, radiiA, s / 2);
  const auto [b2, rb2] = At(b, radiiB, s / 2);
  const double far = (a1 - b1).norm(), half = (a2 - b2).norm();
  result.angleDeg = 2.0 * std::asin(std::clamp((far - half) / s, -1.0, 1.0)) * 180.0 / 3.14159265358979323846;
  result.septumMm = far - ra1 - rb1;
  return result;
}

} // namespace sgp
