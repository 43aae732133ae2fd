#include "Centerlines/FlowDivider.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "Common/SmoothMask.h"

namespace sgp
{
namespace
{

constexpr double levelStepMm = 0.25, sampleStepMm = 0.2, reachMm = 60.0, refinedMm = 0.01;
constexpr double persistMm[2] = { 1.0, 2.0 }; ///< the gap must still show this far lower

/// Where `iliac` first reaches depth t below `origin` along d; none when it starts below that depth or
/// never reaches it.
std::optional<Point3> AtDepth(const Centerline& iliac, const Point3& origin, const Eigen::Vector3d& d, double t)
{
  const auto depth = [&](Eigen::Index k) { return (Point3(iliac.points.row(k).transpose()) - origin).dot(d); };
  if (depth(0) > t)
    return std::nullopt;
  for (Eigen::Index k = 1; k < iliac.points.rows(); ++k)
    if (depth(k) >= t)
    {
      const double a = depth(k - 1), b = depth(k), w = b > a ? (t - a) / (b - a) : 1.0;
      const Point3 p0 = iliac.points.row(k - 1).transpose(), p1 = iliac.points.row(k).transpose();
      return Point3(p0 + w * (p1 - p0));
    }
  return std::nullopt;
}

struct Level
{
  bool reached = false; ///< both iliacs reach the level
  bool divided = false;
  Point3 gap = Point3::Zero();
};

Level LookAt(const SmoothMask& mask,
             const CenterlineTree& tree,
             const Point3& origin,
             const Eigen::Vector3d& d,
             double t)
{
  Level level;
  const auto right = AtDepth(tree.rightIliac, origin, d, t), left = AtDepth(tree.leftIliac, origin, d, t);
  if (!right || !left)
    return level;
  level.reached = true;
  const Eigen::Vector3d across = *left - *right;
  const int samples = std::max(2, int(std::ceil(across.norm() / sampleStepMm)));
  double lowest = 1.0;
  for (int k = 1; k < samples; ++k)
  {
    const Point3 q = *right + (double(k) / samples) * across;
    const double value = mask(q);
    if (value < lowest)
    {
      lowest = value;
      level.gap = q;
    }
  }
  level.divided = lowest < 0.5;
  return level;
}

} // namespace

FlowDivider FindFlowDivider(const LabelImage& lumen, const CenterlineTree& tree)
{
  FlowDivider out;
  const Centerline& aorta = tree.aorta;
  if (aorta.Size() < 2 || tree.rightIliac.Size() < 2 || tree.leftIliac.Size() < 2)
  {
    out.reason = "the aorta or an iliac centerline has fewer than two points";
    return out;
  }
  const double end = aorta.LengthMm();
  const Point3 origin = PositionAt(aorta, end); // the skeleton's junction: the levels start there
  Eigen::Vector3d d = PositionAt(aorta, end - 5.0) - PositionAt(aorta, end - 25.0);
  if (d.norm() < 1e-6)
    d = TangentAt(aorta, end);
  d.normalize();
  const SmoothMask mask(lumen);
  const auto firstDepth = [&](const Centerline& c) { return (Point3(c.points.row(0).transpose()) - origin).dot(d); };
  const double top = std::max({ firstDepth(tree.rightIliac), firstDepth(tree.leftIliac), 0.0 });
  const auto persists = [&](double t)
  {
    return LookAt(mask, tree, origin, d, t + persistMm[0]).divided &&
           LookAt(mask, tree, origin, d, t + persistMm[1]).divided;
  };
  if (LookAt(mask, tree, origin, d, top).divided)
  {
    out.reason = "the iliac lumens are already apart where both iliac centerlines begin";
    return out;
  }
  double above = top, below = top + levelStepMm;
  for (Level level = LookAt(mask, tree, origin, d, below); !(level.divided && persists(below));
       level = LookAt(mask, tree, origin, d, below))
  {
    if (!level.reached || below > top + reachMm)
    {
      out.reason = "the lumen does not divide within " + std::to_string(int(reachMm)) +
                   " mm below where both iliac centerlines begin";
      return out;
    }
    above = below;
    below += levelStepMm;
  }
  while (below - above > refinedMm)
  {
    const double mid = 0.5 * (above + below);
    (LookAt(mask, tree, origin, d, mid).divided ? below : above) = mid;
  }
  const Level level = LookAt(mask, tree, origin, d, below);
  out.found = true;
  out.lps = level.gap;
  out.aorticDirection = d;
  const auto spacing = lumen.GetSpacing();
  out.uncertaintyMm = 0.5 * std::max({ spacing[0], spacing[1], spacing[2] });
  // Each iliac's cross-section through the divider: the first that is the iliac's alone (the
  // rings above it open medially into the other iliac's lumen).
  out.iliacAbscissaMm = { ProjectOntoCenterline(tree.rightIliac, out.lps),
                          ProjectOntoCenterline(tree.leftIliac, out.lps) };
  return out;
}

double FlowDivider::DepthBelowMm(const Point3& bifurcationLps) const
{
  return found ? (lps - bifurcationLps).dot(aorticDirection) : std::numeric_limits<double>::quiet_NaN();
}

} // namespace sgp
