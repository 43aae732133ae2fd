// Drawing the synthetic phantom on its grid (PhantomRaster.h).
#include "Phantom/PhantomRaster.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>

#include <Eigen/Dense>

#include "Common/Errors.h"
#include "Common/Format.h"

namespace sgp::phantom
{

double EdgeProfile(double signedDistance, double sigma)
{
  if (sigma <= 0.0)
  {
    return signedDistance < 0.0 ? 1.0 : (signedDistance > 0.0 ? 0.0 : 0.5);
  }
  return 0.5 * std::erfc(signedDistance / (sigma * std::sqrt(2.0)));
}

double SaturatedEdgeProfile(double signedDistance, double sigma)
{
  // Beyond 8.5 σ the profile is 1 to double precision on the inside (0.5·erfc(−6.01) rounds to
  // 1.0) and under 1.2e-17 on the outside, below any HU the phantom can round to: exact 1 and 0,
  // without the erfc (most voxels a box visits lie there).
  const double cutoff = 8.5 * sigma;
  if (signedDistance >= cutoff)
    return 0.0;
  if (signedDistance <= -cutoff)
    return 1.0;
  return EdgeProfile(signedDistance, sigma);
}

Grid MakeGrid(const PhantomParams& p, const std::array<Point3, 2>& bounds)
{
  Grid grid;
  grid.direction = p.directionLps;
  grid.spacing = Eigen::Vector3d(p.spacingMm[0], p.spacingMm[1], p.spacingMm[2]);
  Eigen::Vector3d uMin = Eigen::Vector3d::Constant(1e18), uMax = -uMin;
  for (int corner = 0; corner < 8; ++corner)
  {
    const Point3 c((corner & 1 ? bounds[1] : bounds[0]).x(), (corner & 2 ? bounds[1] : bounds[0]).y(),
                   (corner & 4 ? bounds[1] : bounds[0]).z());
    const Eigen::Vector3d u = grid.direction.transpose() * c;
    uMin = uMin.cwiseMin(u);
    uMax = uMax.cwiseMax(u);
  }
  Eigen::Vector3d first = uMin;
  for (int a = 0; a < 3; ++a)
  {
    if (p.sizeVoxels[a] > 0)
    {
      grid.size[a] = p.sizeVoxels[a];
      first[a] = 0.5 * (uMin[a] + uMax[a]) - 0.5 * (grid.size[a] - 1) * grid.spacing[a];
    }
    else
    {
      grid.size[a] = static_cast<long>(std::ceil((uMax[a] - uMin[a]) / grid.spacing[a])) + 1;
    }
  }
  grid.origin = grid.direction * first;
  return grid;
}

double EllipsoidSignedDistance(const Ellipsoid& e, const Point3& x)
{
  const Eigen::Vector3d q = (x - e.centre).cwiseQuotient(e.semiAxes);
  const double f = q.norm();
  if (f < 1e-9)
  {
    return -e.semiAxes.minCoeff();
  }
  const double gradient = (q.cwiseQuotient(e.semiAxes) / f).norm();
  return (f - 1.0) / gradient;
}

void DrawAorticWall(const AorticWall& wall,
                    const PhantomParams& p,
                    const Grid& grid,
                    double reach,
                    std::vector<float>& contrast,
                    std::vector<unsigned char>& labels,
                    std::vector<unsigned char>& layer)
{
  const double outward = wall.ReachMm() + reach;
  const auto [lo, hi] = wall.BoundsLps(reach);
  const double sigma = p.blurSigmaMm;
  ForEachVoxelNear(
    grid, lo, hi,
    [&](long flat, const Point3& x)
    {
      const AorticWall::Coordinates c = wall.At(x);
      if (c.rho > outward || c.beyondMm > reach)
        return;
      const double ends = c.beyondMm; // past the aorta's top or below the bifurcation
      const double outer = std::max(wall.OuterSignedDistance(c), ends);
      const double shell = std::max(wall.WallSignedDistance(c), ends);
      float value = contrast[flat];
      unsigned char label = labels[flat];
      const auto take = [&](double hu, double sd, unsigned char l, bool inside)
      {
        value = std::max(value, float((hu - p.tissueHu) * EdgeProfile(sd, sigma)));
        if (inside && sd < 0.0)
          label = l;
      };
      // Lowest priority first: each later label overwrites.
      for (const WallNeighbour& n : wall.Neighbours())
        take(n.hu, std::max(wall.NeighbourSignedDistance(c, n), ends), n.label, true);
      // The wall and the thrombus inside it: nested solids, blurred linearly.
      const double inner = std::max(c.rho - wall.InnerRadius(c.h, c.thetaDeg), ends);
      double layered = (p.wallHu - p.tissueHu) * EdgeProfile(outer, sigma);
      if (wall.HasThrombus())
        layered += (p.thrombusHu - p.wallHu) * EdgeProfile(inner, sigma);
      const bool padBrighter = value > float(layered);
      value = std::max(value, float(layered));
      if (wall.HasThrombus() && outer < 0.0)
        label = ThrombusLabel;
      if (shell < 0.0)
        label = WallLabel;
      if (outer < 0.0)
        layer[flat] =
          static_cast<unsigned char>(wall.HasThrombus() && inner < 0.0 ? UnderLumen::Thrombus : UnderLumen::Wall);
      if (padBrighter)
        layer[flat] = static_cast<unsigned char>(UnderLumen::Brighter);
      const float beforeCalcium = value;
      for (const WallCalcification& w : wall.Calcifications())
        take(p.calcificationHu, std::max(wall.CalcificationSignedDistance(c, w), ends), CalciumLabel, true);
      if (value > beforeCalcium)
        layer[flat] = static_cast<unsigned char>(UnderLumen::Brighter);
      contrast[flat] = value;
      labels[flat] = label;
    });
}

} // namespace sgp::phantom
