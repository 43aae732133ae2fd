#include "Centerlines/AssignInscribedRadii.h"

#include <algorithm>
#include <numeric>

namespace sgp
{

void AssignInscribedRadii(CenterlineTree& tree, const Skeleton& skeleton, double searchMm)
{
  std::vector<std::size_t> byZ(skeleton.pointsLps.size());
  std::iota(byZ.begin(), byZ.end(), 0);
  std::sort(byZ.begin(), byZ.end(),
            [&](std::size_t a, std::size_t b) { return skeleton.pointsLps[a].z() < skeleton.pointsLps[b].z(); });
  std::vector<double> zs;
  for (std::size_t i : byZ)
    zs.push_back(skeleton.pointsLps[i].z());

  const auto assign = [&](Centerline& c)
  {
    for (Eigen::Index i = 0; i < c.Size(); ++i)
    {
      const Point3 p = c.points.row(i).transpose();
      const auto first = std::lower_bound(zs.begin(), zs.end(), p.z() - searchMm);
      const auto last = std::upper_bound(zs.begin(), zs.end(), p.z() + searchMm);
      double best = -1.0;
      for (auto it = first; it != last; ++it)
      {
        const std::size_t v = byZ[std::size_t(it - zs.begin())];
        if ((skeleton.pointsLps[v] - p).norm() > searchMm)
          continue;
        const double d = (skeleton.nearestBackgroundLps[v] - p).norm();
        if (best < 0.0 || d < best)
          best = d;
      }
      if (best > 0.0)
        c.radiusMm[i] = best;
    }
  };
  assign(tree.aorta);
  assign(tree.rightIliac);
  assign(tree.leftIliac);
  for (Centerline& c : tree.sideBranches)
    assign(c);
}

} // namespace sgp
