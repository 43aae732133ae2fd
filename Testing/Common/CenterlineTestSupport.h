/// \file CenterlineTestSupport.h
/// Distances between computed centerlines and the phantom's analytic axes.
#pragma once

#include <algorithm>
#include <limits>

#include "Centerlines/Centerlines.h"
#include "Phantom/AorticPhantom.h"

namespace sgp::testing
{

/// Distance from p to the polyline `axis` (n×3), and the index of the nearest vertex.
inline std::pair<double, Eigen::Index> DistanceToAxis(const Point3& p, const Points& axis)
{
  double best = std::numeric_limits<double>::max();
  for (Eigen::Index i = 0; i + 1 < axis.rows(); ++i)
  {
    const Point3 a = axis.row(i).transpose(), b = axis.row(i + 1).transpose();
    const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    best = std::min(best, (p - (a + t * (b - a))).norm());
  }
  Eigen::Index nearest = 0;
  (axis.rowwise() - p.transpose()).rowwise().squaredNorm().minCoeff(&nearest);
  return { best, nearest };
}

/// Per centerline point: distance to the nearest of the named truth vessels' axes, and the
/// difference between its radius and the analytic inscribed-sphere radius there.
struct AxisAgreement
{
  double meanDistanceMm = 0.0, maxDistanceMm = 0.0;
  double meanRadiusErrorMm = 0.0, maxRadiusErrorMm = 0.0;
  double meanSignedRadiusErrorMm = 0.0;
};

inline AxisAgreement CompareWithAxes(const Centerline& c,
                                     const PhantomTruth& truth,
                                     const std::vector<std::string>& vessels,
                                     double skipFromStartMm = 0.0,
                                     double skipFromEndMm = 0.0)
{
  AxisAgreement a;
  int counted = 0;
  for (Eigen::Index i = 0; i < c.Size(); ++i)
  {
    if (c.abscissaMm[i] < skipFromStartMm || c.abscissaMm[i] > c.LengthMm() - skipFromEndMm)
      continue;
    const Point3 p = c.points.row(i).transpose();
    double best = std::numeric_limits<double>::max(), radius = 0.0;
    for (const PhantomVessel& v : truth.vessels)
      if (std::find(vessels.begin(), vessels.end(), v.name) != vessels.end())
      {
        const auto [d, nearest] = DistanceToAxis(p, v.axis);
        if (d < best)
          best = d, radius = v.inscribedRadiusMm[nearest];
      }
    const double radiusError = std::abs(c.radiusMm[i] - radius);
    a.meanDistanceMm += best;
    a.maxDistanceMm = std::max(a.maxDistanceMm, best);
    a.meanRadiusErrorMm += radiusError;
    a.meanSignedRadiusErrorMm += c.radiusMm[i] - radius;
    a.maxRadiusErrorMm = std::max(a.maxRadiusErrorMm, radiusError);
    ++counted;
  }
  a.meanDistanceMm /= std::max(counted, 1);
  a.meanRadiusErrorMm /= std::max(counted, 1);
  a.meanSignedRadiusErrorMm /= std::max(counted, 1);
  return a;
}

} // namespace sgp::testing
