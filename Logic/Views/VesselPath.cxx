#include "Views/VesselPath.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Geometry>

#include "Common/Errors.h"

namespace sgp
{

double VesselPath::PathAbscissa(const std::string& vessel, double abscissaMm) const
{
  if (vessel == "aorta")
    return abscissaMm;
  if (vessel == iliac)
    return iliacStartMm + abscissaMm;
  return std::numeric_limits<double>::quiet_NaN();
}

double VesselPath::Project(const Point3& p, double* distanceMm) const
{
  double best = std::numeric_limits<double>::infinity(), bestS = 0.0;
  for (Eigen::Index k = 0; k + 1 < points.rows(); ++k)
  {
    const Point3 a = points.row(k).transpose(), b = points.row(k + 1).transpose();
    const Eigen::Vector3d d = b - a;
    const double t = d.squaredNorm() > 0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    const double dist = (a + t * d - p).norm();
    if (dist < best)
    {
      best = dist;
      bestS = (static_cast<double>(k) + t) * stepMm;
    }
  }
  if (distanceMm)
    *distanceMm = best;
  return bestS;
}

Eigen::Vector3d CoronalAxis(const Eigen::Vector3d& t, const Eigen::Vector3d* previous)
{
  Eigen::Vector3d u = Eigen::Vector3d::UnitX() - t.x() * t;
  if (u.norm() < 0.5)
    u = previous ? Eigen::Vector3d(*previous - previous->dot(t) * t)
                 : Eigen::Vector3d(Eigen::Vector3d::UnitY() - t.y() * t);
  return u.normalized();
}

VesselPath SampleVesselPath(const Centerline& aorta, const Centerline& iliac, double stepMm)
{
  if (aorta.Size() < 2 || iliac.Size() < 2)
    throw InputError("A straightened view needs the aorta and the " + iliac.name +
                     " with at least two centerline points each; got " + std::to_string(aorta.Size()) + " and " +
                     std::to_string(iliac.Size()) + ".");
  if (!(stepMm > 0.0 && stepMm <= 10.0))
    throw InputError("The straightened view's step is " + std::to_string(stepMm) + " mm; expected (0, 10] mm.");
  // The polyline aorta + iliac with its arc length; the iliac starts where the aorta ends (a gap
  // between them is bridged straight and counted).
  std::vector<Point3> poly;
  std::vector<double> arc;
  const auto add = [&](const Point3& p)
  {
    if (!poly.empty() && (p - poly.back()).norm() < 1e-9)
      return;
    arc.push_back(poly.empty() ? 0.0 : arc.back() + (p - poly.back()).norm());
    poly.push_back(p);
  };
  for (Eigen::Index i = 0; i < aorta.Size(); ++i)
    add(aorta.points.row(i).transpose());
  VesselPath path;
  path.name = "aorta → " + iliac.name;
  path.iliac = iliac.name;
  path.stepMm = stepMm;
  path.iliacStartMm = arc.back() + (iliac.points.row(0).transpose() - poly.back()).norm();
  for (Eigen::Index i = 0; i < iliac.Size(); ++i)
    add(iliac.points.row(i).transpose());

  const auto rows = static_cast<Eigen::Index>(std::floor(arc.back() / stepMm)) + 1;
  path.points.resize(rows, 3);
  size_t seg = 0;
  for (Eigen::Index k = 0; k < rows; ++k)
  {
    const double s = static_cast<double>(k) * stepMm;
    while (seg + 2 < poly.size() && arc[seg + 1] < s)
      ++seg;
    const double len = arc[seg + 1] - arc[seg];
    const double t = len > 0 ? std::clamp((s - arc[seg]) / len, 0.0, 1.0) : 0.0;
    path.points.row(k) = ((1 - t) * poly[seg] + t * poly[seg + 1]).transpose();
  }
  path.tangent.resize(rows, 3);
  path.u.resize(rows, 3);
  path.v.resize(rows, 3);
  for (Eigen::Index k = 0; k < rows; ++k)
  {
    const Eigen::Index a = std::max<Eigen::Index>(k - 1, 0), b = std::min<Eigen::Index>(k + 1, rows - 1);
    Eigen::Vector3d t = (path.points.row(b) - path.points.row(a)).transpose();
    if (t.norm() < 1e-12)
      t = k > 0 ? path.tangent.row(k - 1).transpose() : Eigen::Vector3d(0, 0, -1);
    t.normalize();
    const Eigen::Vector3d previous =
      k > 0 ? Eigen::Vector3d(path.u.row(k - 1).transpose()) : Eigen::Vector3d(Eigen::Vector3d::Zero());
    const Eigen::Vector3d u = CoronalAxis(t, k > 0 ? &previous : nullptr);
    path.tangent.row(k) = t.transpose();
    path.u.row(k) = u.transpose();
    path.v.row(k) = u.cross(t).transpose();
  }
  return path;
}

} // namespace sgp
