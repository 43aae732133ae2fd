#include "Stent/WallDistanceField.h"

#include <algorithm>
#include <cmath>
#include <future>
#include <limits>

#include <Eigen/Dense>

#include "Common/CheckRange.h"
#include "Common/DistanceInsideMask.h"
#include "Common/Errors.h"
#include "Common/ImageGeometry.h"
#include "Common/IndexBox.h"
#include "Common/MaskGrid.h"

namespace sgp
{

namespace
{

/// The index box of the lumen voxels that lie inside any of the balls: one pass over the lumen
/// voxels (inside the balls' common bounding box), each tested against the balls until one holds it.
IndexBox ForegroundBoxWithin(const LabelImage& lumen, const std::vector<Ball>& region)
{
  const auto size = lumen.GetLargestPossibleRegion().GetSize();
  const IndexBox all = ForegroundBox(lumen);
  Point3 lower = Point3::Constant(std::numeric_limits<double>::infinity()), upper = -lower;
  for (const Ball& ball : region)
  {
    lower = lower.cwiseMin(ball.centre - Point3::Constant(ball.radiusMm));
    upper = upper.cwiseMax(ball.centre + Point3::Constant(ball.radiusMm));
  }
  itk::Point<double, 3> origin;
  lumen.TransformIndexToPhysicalPoint(itk::Index<3>{ { 0, 0, 0 } }, origin);
  Eigen::Matrix3d indexToLps;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      indexToLps(r, c) = lumen.GetDirection()(r, c) * lumen.GetSpacing()[c];
  const Point3 o(origin[0], origin[1], origin[2]);
  std::array<long, 3> lo{ long(size[0]), long(size[1]), long(size[2]) }, hi{ -1, -1, -1 };
  const unsigned char* buffer = lumen.GetBufferPointer();
  for (long k = all.first[2]; k < all.first[2] + all.size[2]; ++k)
    for (long j = all.first[1]; j < all.first[1] + all.size[1]; ++j)
      for (long i = all.first[0]; i < all.first[0] + all.size[0]; ++i)
      {
        if (!buffer[i + long(size[0]) * (j + long(size[1]) * k)])
          continue;
        if (i >= lo[0] && i <= hi[0] && j >= lo[1] && j <= hi[1] && k >= lo[2] && k <= hi[2])
          continue; // already inside the box: cannot grow it
        const Point3 p = o + indexToLps * Eigen::Vector3d(double(i), double(j), double(k));
        if ((p.array() < lower.array()).any() || (p.array() > upper.array()).any())
          continue;
        for (const Ball& ball : region)
          if ((p - ball.centre).squaredNorm() <= ball.radiusMm * ball.radiusMm)
          {
            lo = { std::min(lo[0], i), std::min(lo[1], j), std::min(lo[2], k) };
            hi = { std::max(hi[0], i), std::max(hi[1], j), std::max(hi[2], k) };
            break;
          }
      }
  IndexBox box;
  for (unsigned a = 0; a < 3; ++a)
  {
    box.first[a] = lo[a];
    box.size[a] = hi[a] >= lo[a] ? hi[a] - lo[a] + 1 : 0;
  }
  return box;
}

} // namespace

WallDistanceField WallDistanceField::FromLumen(const LabelImage& lumen, double bandMm)
{
  return FromLumen(lumen, bandMm, {});
}

WallDistanceField WallDistanceField::FromLumen(const LabelImage& lumen, double bandMm, const std::vector<Ball>& region)
{
  CheckRange("bandMm", bandMm, 1.0, 100.0, "mm");
  const auto spacing = lumen.GetSpacing();
  std::array<long, 3> pad{};
  for (unsigned a = 0; a < 3; ++a)
    pad[a] = static_cast<long>(std::ceil(bandMm / spacing[a])) + 1;
  const IndexBox found = region.empty() ? ForegroundBox(lumen) : ForegroundBoxWithin(lumen, region);
  if (found.Empty())
    throw InputError(region.empty() ? "The lumen mask is empty (no non-zero voxel); there is no vessel wall to fit to."
                                    : "No lumen voxel lies near the stent's rings; there is no vessel wall to fit to.");
  // The band may reach beyond the image: voxels there are not lumen.
  IndexBox box;
  for (unsigned a = 0; a < 3; ++a)
  {
    box.first[a] = found.first[a] - pad[a];
    box.size[a] = found.size[a] + 2 * pad[a];
  }
  MaskGrid inside(box.size), outside(box.size);
  const auto size = lumen.GetLargestPossibleRegion().GetSize();
  const unsigned char* buffer = lumen.GetBufferPointer();
  for (long k = 0, flat = 0; k < box.size[2]; ++k)
    for (long j = 0; j < box.size[1]; ++j)
    {
      const long gj = box.first[1] + j, gk = box.first[2] + k;
      const bool rowInImage = gj >= 0 && gk >= 0 && gj < long(size[1]) && gk < long(size[2]);
      for (long i = 0; i < box.size[0]; ++i, ++flat)
      {
        const long gi = box.first[0] + i;
        const bool inImage = rowInImage && gi >= 0 && gi < long(size[0]);
        inside.voxels[flat] = inImage && buffer[gi + long(size[0]) * (gj + long(size[1]) * gk)] ? 1 : 0;
        outside.voxels[flat] = inside.voxels[flat] ? 0 : 1;
      }
    }
  const std::array<double, 3> s{ spacing[0], spacing[1], spacing[2] };
  // The two propagations are independent: the inner one runs on a second thread (the machine
  // we plan on has two cores; the result does not depend on the order).
  const float reach = static_cast<float>(bandMm + 2.0 * s[2]);
  std::future<DistanceField> inFuture =
    std::async(std::launch::async, [&inside, &s, reach] { return DistanceInsideMask(inside, s, true, reach); });
  const DistanceField out = DistanceInsideMask(outside, s, false, reach);
  const DistanceField in = inFuture.get();

  WallDistanceField field;
  field.m_Size = box.size;
  field.m_Band = bandMm;
  field.m_FoundFirst = found.first;
  field.m_FoundSize = found.size;
  field.m_Phi.resize(inside.voxels.size());
  // A voxel farther than the band plus half a voxel is ±band whatever its direction.
  const double farMm = bandMm + 0.5 * std::max({ s[0], s[1], s[2] });
  for (long k = 0, flat = 0; k < box.size[2]; ++k)
    for (long j = 0; j < box.size[1]; ++j)
      for (long i = 0; i < box.size[0]; ++i, ++flat)
      {
        const bool lumenVoxel = inside.voxels[flat] != 0;
        const DistanceField& d = lumenVoxel ? in : out;
        const double distance = d.distanceMm[flat];
        if (distance >= farMm)
        {
          field.m_Phi[flat] = static_cast<float>(lumenVoxel ? -bandMm : bandMm);
          continue;
        }
        const auto& q = d.nearestBackground[flat];
        const Eigen::Vector3d u((q[0] - i) * s[0], (q[1] - j) * s[1], (q[2] - k) * s[2]);
        const double halfVoxel =
          u.norm() > 0 ? 0.5 * (u[0] * u[0] * s[0] + u[1] * u[1] * s[1] + u[2] * u[2] * s[2]) / u.squaredNorm() : 0.0;
        const double phi = lumenVoxel ? -(distance - halfVoxel) : distance - halfVoxel;
        field.m_Phi[flat] = static_cast<float>(std::clamp(phi, -bandMm, bandMm));
      }
  itk::ContinuousIndex<double, 3> first;
  for (unsigned a = 0; a < 3; ++a)
    first[a] = double(box.first[a]);
  itk::Point<double, 3> origin;
  lumen.TransformContinuousIndexToPhysicalPoint(first, origin);
  field.m_Origin = Point3(origin[0], origin[1], origin[2]);
  const auto& direction = lumen.GetDirection();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      field.m_IndexToLps(r, c) = direction(r, c) * spacing[c];
  field.m_LpsToIndex = field.m_IndexToLps.inverse();
  return field;
}

double WallDistanceField::Sample(const Point3& lps, Eigen::Vector3d* gradient) const
{
  const Eigen::Vector3d x = m_LpsToIndex * (lps - m_Origin);
  std::array<long, 3> i0{};
  std::array<double, 3> f{};
  for (int a = 0; a < 3; ++a)
  {
    const double c = std::floor(x[a]);
    i0[a] = static_cast<long>(c);
    f[a] = x[a] - c;
    if (i0[a] < 0 || i0[a] + 1 >= m_Size[a])
    {
      if (gradient)
        gradient->setZero();
      return m_Band;
    }
  }
  const auto at = [&](int di, int dj, int dk)
  { return double(m_Phi[(i0[0] + di) + m_Size[0] * ((i0[1] + dj) + m_Size[1] * (i0[2] + dk))]); };
  double value = 0.0;
  Eigen::Vector3d g = Eigen::Vector3d::Zero(); // ∂φ/∂(index)
  for (int c = 0; c < 8; ++c)
  {
    const int di = c & 1, dj = (c >> 1) & 1, dk = (c >> 2) & 1;
    const double wi = di ? f[0] : 1 - f[0], wj = dj ? f[1] : 1 - f[1], wk = dk ? f[2] : 1 - f[2];
    const double v = at(di, dj, dk);
    value += wi * wj * wk * v;
    g[0] += (di ? 1.0 : -1.0) * wj * wk * v;
    g[1] += (dj ? 1.0 : -1.0) * wi * wk * v;
    g[2] += (dk ? 1.0 : -1.0) * wi * wj * v;
  }
  if (gradient)
    *gradient = m_LpsToIndex.transpose() * g; // chain rule: index = M⁻¹(lps − origin)
  return value;
}

bool WallDistanceField::Covers(const LabelImage& lumen, double bandMm, const std::vector<Ball>& region) const
{
  if (bandMm != m_Band)
    return false;
  const IndexBox found = region.empty() ? ForegroundBox(lumen) : ForegroundBoxWithin(lumen, region);
  if (found.Empty())
    return false; // FromLumen would throw: let it
  for (unsigned a = 0; a < 3; ++a)
    if (found.first[a] < m_FoundFirst[a] || found.first[a] + found.size[a] > m_FoundFirst[a] + m_FoundSize[a])
      return false;
  return true;
}

const WallDistanceField& WallDistanceField::SharedOrOwn(const WallDistanceField& shared,
                                                        const LabelImage& lumen,
                                                        double bandMm,
                                                        const std::vector<Ball>& region,
                                                        std::optional<WallDistanceField>& own)
{
  if (shared.Covers(lumen, bandMm, region))
    return shared;
  own = FromLumen(lumen, bandMm, region);
  return *own;
}

} // namespace sgp
