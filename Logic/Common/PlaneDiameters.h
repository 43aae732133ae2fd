/// \file PlaneDiameters.h
/// The mean diameter of a section through a point: the mean over `count` diameters, equally
/// spaced over 180° in the plane through the point ⊥ `normal`, each the sum of the distances from
/// the point to the section's edge along a direction and its opposite. Shared by the phantom's
/// truth near its bend (Phantom/KinkSection.h) and the plan's section checks
/// (Measurement/SectionTilt.h), which differ only in how they find an edge.
///
/// Input: LPS mm; `normal` need not be unit; `edgeDistance(e)` the distance from the point along the
/// unit direction e to the edge, mm. The diameters start at PerpendicularTo(normal).
/// Errors: none.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Geometry>

namespace sgp
{

/// A unit vector ⊥ `n` (n × x, or n × y when n lies within 26° of x).
inline Eigen::Vector3d PerpendicularTo(const Eigen::Vector3d& n)
{
  const Eigen::Vector3d other = std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  return n.cross(other).normalized();
}

/// The `count` diameters themselves, in order from PerpendicularTo(normal).
template<class EdgeDistance>
std::vector<double> DiametersInPlane(const Eigen::Vector3d& normal, int count, const EdgeDistance& edgeDistance)
{
  constexpr double pi = 3.14159265358979323846;
  const Eigen::Vector3d n = normal.normalized(), u = PerpendicularTo(n), v = n.cross(u);
  std::vector<double> diameters(static_cast<std::size_t>(std::max(count, 0)));
  for (int k = 0; k < count; ++k)
  {
    const double angle = pi * k / count;
    const Eigen::Vector3d e = std::cos(angle) * u + std::sin(angle) * v;
    diameters[static_cast<std::size_t>(k)] = edgeDistance(e) + edgeDistance(Eigen::Vector3d(-e));
  }
  return diameters;
}

template<class EdgeDistance>
double MeanDiameterInPlane(const Eigen::Vector3d& normal, int count, const EdgeDistance& edgeDistance)
{
  double sum = 0.0;
  for (double d : DiametersInPlane(normal, count, edgeDistance))
    sum += d;
  return sum / count;
}

} // namespace sgp
