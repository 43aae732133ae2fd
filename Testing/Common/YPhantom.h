/// \file YPhantom.h
/// A Y of capsules — the aorta (radius 10 mm) from z = 140 down to the bifurcation at z = 40, the
/// iliacs (6 mm) to (∓30, 0, −40) — with its analytic centerlines, for the stent and ACM tests.
#pragma once

#include "Centerlines/Centerlines.h"
#include "MaskPhantoms.h"

namespace sgp::testing
{

struct YPhantom
{
  std::vector<Capsule> capsules;
  CenterlineTree tree;
  LabelImage::Pointer mask;
};

inline Centerline StraightCenterline(const std::string& name, const Point3& a, const Point3& b, double r)
{
  std::vector<Point3> points;
  std::vector<double> radii;
  const int n = static_cast<int>(std::ceil((b - a).norm()));
  for (int i = 0; i <= n; ++i)
  {
    points.push_back(a + (b - a) * (double(i) / n));
    radii.push_back(r);
  }
  return MakeCenterline(name, points, radii);
}

inline YPhantom MakeYPhantom(double spacingMm, double aortaRadius = 10.0, double iliacRadius = 6.0)
{
  YPhantom y;
  const Point3 top(0, 0, 140), bifurcation(0, 0, 40), right(-30, 0, -40), left(30, 0, -40);
  y.capsules = { { top, bifurcation, aortaRadius },
                 { bifurcation, right, iliacRadius },
                 { bifurcation, left, iliacRadius } };
  y.tree.aorta = StraightCenterline("aorta", top, bifurcation, aortaRadius);
  y.tree.rightIliac = StraightCenterline("rightIliac", bifurcation, right, iliacRadius);
  y.tree.leftIliac = StraightCenterline("leftIliac", bifurcation, left, iliacRadius);
  y.tree.landmarks.push_back({ "aorticBifurcation", bifurcation });
  y.mask = PaintCapsules(y.capsules, { spacingMm, spacingMm, spacingMm });
  return y;
}

} // namespace sgp::testing
