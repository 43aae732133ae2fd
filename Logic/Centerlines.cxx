#include "Centerlines.h"

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
