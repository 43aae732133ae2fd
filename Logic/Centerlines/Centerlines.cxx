#include "Centerlines/Centerlines.h"

#include <algorithm>
#include <limits>

namespace sgp
{

const Centerline* CenterlineTree::FindVessel(const std::string& name) const
{
  for (const Centerline* c : { &aorta, &rightIliac, &leftIliac })
    if (c->name == name)
      return c;
  for (const Centerline& c : sideBranches)
    if (c.name == name)
      return &c;
  return nullptr;
}

const Landmark* CenterlineTree::FindLandmark(const std::string& name) const
{
  for (const Landmark& l : landmarks)
    if (l.name == name)
      return &l;
  return nullptr;
}

namespace
{

/// The segment [i, i+1] that contains arc length s (clamped to the ends).
Eigen::Index SegmentAt(const Centerline& c, double s)
{
  Eigen::Index i = 0;
  while (i + 2 < c.Size() && c.abscissaMm[i + 1] < s)
    ++i;
  return i;
}

} // namespace

double ProjectOntoCenterline(const Centerline& c, const Point3& p, double* distanceMm)
{
  double best = std::numeric_limits<double>::infinity(), bestS = 0.0;
  for (Eigen::Index i = 0; i + 1 < c.Size(); ++i)
  {
    const Point3 a = c.points.row(i).transpose(), b = c.points.row(i + 1).transpose();
    const Eigen::Vector3d ab = b - a;
    const double length2 = ab.squaredNorm();
    const double t = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
    const double d = (a + t * ab - p).norm();
    if (d < best)
    {
      best = d;
      bestS = c.abscissaMm[i] + t * (c.abscissaMm[i + 1] - c.abscissaMm[i]);
    }
  }
  if (distanceMm)
    *distanceMm = best;
  return bestS;
}

Eigen::Vector3d TangentAt(const Centerline& c, double s)
{
  const Eigen::Index i = SegmentAt(c, std::clamp(s, 0.0, c.LengthMm()));
  return (c.points.row(i + 1) - c.points.row(i)).transpose().normalized();
}

double RadiusAt(const Centerline& c, double s)
{
  s = std::clamp(s, 0.0, c.LengthMm());
  const Eigen::Index i = SegmentAt(c, s);
  const double s0 = c.abscissaMm[i], s1 = c.abscissaMm[i + 1];
  const double t = s1 > s0 ? (s - s0) / (s1 - s0) : 0.0;
  return (1 - t) * c.radiusMm[i] + t * c.radiusMm[i + 1];
}

Point3 PositionAt(const Centerline& c, double s)
{
  s = std::clamp(s, 0.0, c.LengthMm());
  const Eigen::Index i = SegmentAt(c, s);
  const double s0 = c.abscissaMm[i], s1 = c.abscissaMm[i + 1];
  const double t = s1 > s0 ? (s - s0) / (s1 - s0) : 0.0;
  return ((1 - t) * c.points.row(i) + t * c.points.row(i + 1)).transpose();
}

Centerline MakeCenterline(const std::string& name, const std::vector<Point3>& points, const std::vector<double>& radii)
{
  Centerline c;
  c.name = name;
  const auto n = static_cast<Eigen::Index>(points.size());
  c.points.resize(n, 3);
  c.radiusMm.resize(n);
  c.abscissaMm.resize(n);
  double s = 0.0;
  for (Eigen::Index i = 0; i < n; ++i)
  {
    if (i > 0)
      s += (points[i] - points[i - 1]).norm();
    c.points.row(i) = points[i].transpose();
    c.radiusMm[i] = radii[i];
    c.abscissaMm[i] = s;
  }
  return c;
}

} // namespace sgp
