#include "Wall/VesselWall.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <future>

#include <Eigen/Dense>

#include "Centerlines/VesselOrigins.h"
#include "Common/CheckRange.h"
#include "Common/HugePages.h"
#include "Common/IndexBox.h"
#include "Common/Median.h"

namespace sgp
{
namespace
{

constexpr double pi = 3.14159265358979323846;
constexpr double typicalWallMm = 1.5; ///< vessel-wall.md §2: the aortic wall is 1.5–2.3 mm on CT

/// The wall thickness where the aorta has no thrombus (file comment), or NaN.
double EstimateWallThickness(const OuterWall& aorta, double fromMm, double toMm)
{
  std::vector<double> perPlane;
  for (const OuterWallPlane& plane : aorta.planes)
  {
    if (plane.abscissaMm < fromMm || plane.abscissaMm > toMm || plane.flagged)
      continue;
    std::vector<double> layer;
    for (Eigen::Index k = 0; k < plane.outerRadiusMm.size(); ++k)
      if (plane.supported[k])
        layer.push_back(plane.outerRadiusMm[k] - plane.lumenRadiusMm[k]);
    if (layer.size() < 8)
      continue;
    perPlane.push_back(Median(layer));
  }
  return perPlane.size() >= 3 ? Median(perPlane) : std::numeric_limits<double>::quiet_NaN();
}

/// The aorta's centerline, carried straight on along its last direction to `bifurcationMm` where B
/// lies beyond its end (the skeleton's junction lies above B on thick slices: 4.5 mm on a 30 mm
/// distal aorta on 2.5 mm slices), so that the wall is traced down to B — (d) is read there
/// where the sac narrows into the bifurcation (DistalAorta.h). The same centerline otherwise.
Centerline ReachingBifurcation(const Centerline& aorta, double bifurcationMm)
{
  const double L = aorta.LengthMm();
  if (!(bifurcationMm > L + 0.5) || aorta.Size() < 2)
    return aorta;
  const Eigen::Vector3d down = TangentAt(aorta, L);
  std::vector<Point3> points;
  std::vector<double> radii;
  for (Eigen::Index k = 0; k < aorta.Size(); ++k)
  {
    points.push_back(aorta.points.row(k).transpose());
    radii.push_back(aorta.radiusMm[k]);
  }
  const Point3 end = points.back();
  const int steps = static_cast<int>(std::ceil(bifurcationMm - L));
  for (int k = 1; k <= steps; ++k)
  {
    points.push_back(end + std::min(double(k), bifurcationMm - L) * down);
    radii.push_back(radii.back());
  }
  Centerline extended = MakeCenterline(aorta.name, points, radii);
  extended.evidence = aorta.evidence;
  return extended;
}

} // namespace

VesselWall TraceVesselWall(const CtImage& ct,
                           const LabelImage& lumen,
                           const CenterlineTree& tree,
                           double siteAbscissaMm,
                           const VesselWallParams& params)
{
  CheckRange("aboveSiteMm", params.aboveSiteMm, 0, 50, "mm");
  CheckRange("axisHalfWindowMm", params.axisHalfWindowMm, 1e-3, 50, "mm");
  if (params.wallThicknessMm > 5.0)
    CheckRange("wallThicknessMm", params.wallThicknessMm, 0, 5, "mm");
  VesselWall wall;
  OuterWallParams outer = params.outer;
  outer.calciumHu = params.calciumHu;
  wall.calciumHu = params.calciumHu;
  wall.stepMm = outer.stepMm;
  const double bifurcation = FindAorticBifurcation(tree).abscissaMm;
  // Twice: along the lumen's centerline, then in planes ⊥ the axis through the first pass's
  // contours (SegmentOuterWall.h).
  const auto trace = [&](const Centerline& vessel, double from, double to)
  {
    const OuterWall first = SegmentOuterWall(ct, lumen, vessel, from, to, outer);
    const Centerline axis = OuterWallAxis(first, vessel.name, params.axisHalfWindowMm);
    return axis.Size() >= 2 ? SegmentOuterWall(ct, lumen, vessel, from, to, outer, &axis) : first;
  };
  // The three vessels are traced independently: the iliacs on another thread beside the aorta
  // (in the pipeline this stage runs beside the stent fit, which usually ends first; its core then
  // takes the iliacs). Each trace reads the CT, the lumen and its centerline only.
  std::future<void> iliacsTraced =
    std::async(std::launch::async,
               [&]
               {
                 const Centerline* iliacs[2] = { &tree.rightIliac, &tree.leftIliac };
                 for (int side = 0; side < 2; ++side)
                   if (iliacs[side]->Size() >= 2)
                   {
                     const double origin = InternalIliacOriginAbscissa(tree, side);
                     wall.vessels[1 + side] =
                       trace(*iliacs[side], 0.0, std::isfinite(origin) ? origin : iliacs[side]->LengthMm());
                   }
               });
  const Centerline aorta = ReachingBifurcation(tree.aorta, bifurcation);
  wall.vessels[0] = trace(aorta, siteAbscissaMm - params.aboveSiteMm, std::min(bifurcation, aorta.LengthMm()));
  iliacsTraced.get();
  if (params.wallThicknessMm >= 0.0)
    wall.wallThicknessMm = params.wallThicknessMm;
  else
  {
    const double estimate =
      EstimateWallThickness(wall.vessels[0], siteAbscissaMm - params.aboveSiteMm, siteAbscissaMm + 5.0);
    wall.wallThicknessEstimated = std::isfinite(estimate);
    wall.wallThicknessMm = wall.wallThicknessEstimated ? estimate : typicalWallMm;
  }
  for (OuterWall& vessel : wall.vessels)
    for (OuterWallPlane& plane : vessel.planes)
      plane.thrombusMm =
        ((plane.outerRadiusMm - plane.lumenRadiusMm).array() - wall.wallThicknessMm).cwiseMax(0.0).matrix();
  return wall;
}

CtImage::Pointer CropAroundLumen(const CtImage& ct, const LabelImage& lumen, double marginMm)
{
  const itk::Size<3> size = lumen.GetLargestPossibleRegion().GetSize();
  std::array<long, 3> margin{};
  for (int a = 0; a < 3; ++a)
    margin[a] = static_cast<long>(std::ceil(marginMm / ct.GetSpacing()[a]));
  IndexBox box = ForegroundBox(lumen, margin);
  if (box.Empty()) // no lumen: the margin around the first voxel
    box = PaddedBox({ 0, 0, 0 }, { 0, 0, 0 }, margin, size);
  itk::Index<3> start;
  itk::Size<3> cropSize;
  for (int a = 0; a < 3; ++a)
  {
    start[a] = box.first[a];
    cropSize[a] = static_cast<itk::SizeValueType>(box.size[a]);
  }
  CtImage::Pointer crop = CtImage::New();
  itk::Point<double, 3> origin;
  ct.TransformIndexToPhysicalPoint(start, origin);
  crop->SetOrigin(origin);
  crop->SetSpacing(ct.GetSpacing());
  crop->SetDirection(ct.GetDirection());
  crop->SetRegions(cropSize);
  AllocateAdvised(*crop);
  const itk::Size<3> full = ct.GetLargestPossibleRegion().GetSize();
  const short* in = ct.GetBufferPointer();
  short* out = crop->GetBufferPointer();
  for (itk::SizeValueType k = 0; k < cropSize[2]; ++k)
    for (itk::SizeValueType j = 0; j < cropSize[1]; ++j)
      std::copy_n(in + start[0] + (start[1] + j) * full[0] + (start[2] + k) * full[0] * full[1], cropSize[0],
                  out + j * cropSize[0] + k * cropSize[0] * cropSize[1]);
  return crop;
}

LabelImage::Pointer WallLabelMap(const VesselWall& wall, const LabelImage& lumen, const CtImage& ct)
{
  LabelImage::Pointer labels = LabelImage::New();
  labels->CopyInformation(&lumen);
  labels->SetRegions(lumen.GetLargestPossibleRegion());
  AllocateAdvised(*labels);
  const itk::Size<3> size = lumen.GetLargestPossibleRegion().GetSize();
  const std::size_t count = size[0] * size[1] * size[2];
  const unsigned char* m = lumen.GetBufferPointer();
  unsigned char* out = labels->GetBufferPointer();
  for (std::size_t n = 0; n < count; ++n)
    out[n] = m[n] ? 1 : 0;
  // index → LPS: x = origin + D·diag(spacing)·index
  Eigen::Matrix3d toLps;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      toLps(r, c) = lumen.GetDirection()(r, c) * lumen.GetSpacing()[c];
  const Eigen::Matrix3d toIndex = toLps.inverse();
  const Eigen::Vector3d origin(lumen.GetOrigin()[0], lumen.GetOrigin()[1], lumen.GetOrigin()[2]);
  // Each voxel by the plane it lies nearest to (the slabs of planes one step apart tile the
  // vessel); a wider slab would give a voxel between two planes the larger contour, which on a
  // sloping wall (the sac's shoulders) reaches into what touches the wall.
  const double halfSlab = 0.5 * wall.stepMm + 1e-6;
  // The CT (a crop on the same lattice) starts `offset` voxels into the lumen's grid.
  const Eigen::Vector3d ctOrigin(ct.GetOrigin()[0], ct.GetOrigin()[1], ct.GetOrigin()[2]);
  const Eigen::Vector3d offsetIndex = toIndex * (ctOrigin - origin);
  const itk::Index<3> ctStart = { std::lround(offsetIndex[0]), std::lround(offsetIndex[1]),
                                  std::lround(offsetIndex[2]) };
  const itk::Size<3> ctSize = ct.GetBufferedRegion().GetSize();
  for (const OuterWall& vessel : wall.vessels)
    for (std::size_t p = 0; p < vessel.planes.size(); ++p)
    {
      const OuterWallPlane& plane = vessel.planes[p];
      if (!plane.Usable())
        continue;
      // The planes one step before and after, when they have contours: a voxel between two planes
      // takes the contour interpolated between them (on a sloping wall — the sac's shoulders — the
      // nearer plane's contour alone would reach a slope × ½ step into what touches the wall).
      const auto neighbour = [&](int side) -> const OuterWallPlane*
      {
        const std::size_t q = p + std::size_t(side);
        if ((side < 0 && p == 0) || q >= vessel.planes.size())
          return nullptr;
        const OuterWallPlane& other = vessel.planes[q];
        return other.Usable() && std::abs(other.abscissaMm - plane.abscissaMm) <= 1.5 * wall.stepMm ? &other : nullptr;
      };
      const OuterWallPlane* before = neighbour(-1);
      const OuterWallPlane* after = neighbour(+1);
      const Eigen::Index K = plane.outerRadiusMm.size();
      const Eigen::Vector3d t = plane.uLps.cross(plane.vLps);
      Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
      for (Eigen::Index k = 0; k < K; ++k)
        for (const double side : { -halfSlab, halfSlab })
        {
          const Eigen::Vector3d index = toIndex * (plane.contourLps.row(k).transpose() + side * t - origin);
          lo = lo.cwiseMin(index);
          hi = hi.cwiseMax(index);
        }
      long from[3], to[3];
      for (int a = 0; a < 3; ++a)
      {
        from[a] = std::max(0L, static_cast<long>(std::floor(lo[a])));
        to[a] = std::min(long(size[a]) - 1, static_cast<long>(std::ceil(hi[a])));
      }
      for (long k = from[2]; k <= to[2]; ++k)
        for (long j = from[1]; j <= to[1]; ++j)
          for (long i = from[0]; i <= to[0]; ++i)
          {
            const std::size_t n = std::size_t(i) + std::size_t(j) * size[0] + std::size_t(k) * size[0] * size[1];
            if (out[n] == 1 || out[n] == 3)
              continue;
            const Eigen::Vector3d x = origin + toLps * Eigen::Vector3d(double(i), double(j), double(k));
            const double along = (x - plane.centreLps).dot(t);
            if (std::abs(along) > halfSlab)
              continue;
            const OuterWallPlane* other = along < 0 ? before : after;
            // The fraction of the way to the other plane, along the normal.
            const double w = other ? std::clamp(std::abs(along) / wall.stepMm, 0.0, 1.0) : 0.0;
            const Eigen::Vector3d centre =
              other ? Eigen::Vector3d((1 - w) * plane.centreLps + w * other->centreLps) : plane.centreLps;
            Eigen::Vector3d d = x - centre;
            d -= d.dot(t) * t; // in the plane
            const double r = d.norm();
            const double radius =
              r > 0 ? (1 - w) * OuterRadiusToward(plane, d / r) + (other ? w * OuterRadiusToward(*other, d / r) : 0.0)
                    : 1.0;
            if (r > radius)
              continue;
            long c[3] = { i - ctStart[0], j - ctStart[1], k - ctStart[2] };
            bool inCrop = true;
            for (int axis = 0; axis < 3; ++axis)
              inCrop = inCrop && c[axis] >= 0 && c[axis] < long(ctSize[axis]);
            const double hu = inCrop ? ct.GetBufferPointer()[std::size_t(c[0]) + std::size_t(c[1]) * ctSize[0] +
                                                             std::size_t(c[2]) * ctSize[0] * ctSize[1]]
                                     : 0.0;
            out[n] = hu >= wall.calciumHu ? 3 : 2;
          }
    }
  return labels;
}

} // namespace sgp
