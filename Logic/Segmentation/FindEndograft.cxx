#include "Segmentation/FindEndograft.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "Common/CheckRange.h"
#include "Common/MaskGrid.h"

namespace sgp
{

namespace
{

constexpr double pi = 3.14159265358979323846;
constexpr int sectors = 8;

struct Bin
{
  std::vector<Point3> points; ///< metal voxels beside the lumen, LPS mm
};

void CheckParams(const EndograftParams& params)
{
  CheckRange("metalHu", params.metalHu, 1000.0, 3071.0, "HU");
  CheckRange("nearLumenMm", params.nearLumenMm, 1.0, 10.0, "mm");
  CheckRange("minimumRingSectors", params.minimumRingSectors, 4, sectors, "");
  CheckRange("minimumRingRadiusMm", params.minimumRingRadiusMm, 2.0, 30.0, "mm");
  CheckRange("minimumRingLengthMm", params.minimumRingLengthMm, 1.0, 200.0, "mm");
  CheckRange("seedSearchRadiusMm", params.seedSearchRadiusMm, 10.0, 80.0, "mm");
  CheckRange("seedSearchHeightMm", params.seedSearchHeightMm, 10.0, 500.0, "mm");
  CheckRange("maximumRingGapMm", params.maximumRingGapMm, 0.0, 30.0, "mm");
}

/// The slice thickness along z: each bin is one slice of the acquisition (any orientation), mm.
double BinMm(const CtImage& ct)
{
  const auto spacing = ct.GetSpacing();
  const auto& direction = ct.GetDirection();
  double binMm = 0.0;
  for (unsigned a = 0; a < 3; ++a)
    binMm = std::max(binMm, std::abs(direction(2, a)) * spacing[a]);
  return binMm;
}

/// Sector of 2π / n that (dx, dy) points into, in [0, n).
int Sector(double dx, double dy, int n)
{
  const double angle = std::atan2(dy, dx) + pi; // [0, 2π]
  return std::min(n - 1, int(angle / (2.0 * pi / n)));
}

/// Adds a ring bin at height `z` to the evidence.
void AddRing(double z, EndograftEvidence& evidence)
{
  evidence.ringFromZ = evidence.ringBins == 0 ? z : std::min(evidence.ringFromZ, z);
  evidence.ringToZ = evidence.ringBins == 0 ? z : std::max(evidence.ringToZ, z);
  ++evidence.ringBins;
}

/// Seen from `centre` (LPS x, y), does `points` hold a ring (the file comment's "around the seed")?
/// On success `centre` moves to the ring's centroid.
bool RingAround(const std::vector<Point3>& points, const EndograftParams& params, double radiusMm, Point3& centre)
{
  constexpr int fine = 32;
  std::array<bool, sectors> filled{};
  std::array<const Point3*, fine> nearest{};
  std::array<double, fine> distance{};
  for (const Point3& p : points)
  {
    const double dx = p.x() - centre.x(), dy = p.y() - centre.y(), d = std::hypot(dx, dy);
    if (d > radiusMm)
      continue;
    filled[std::size_t(Sector(dx, dy, sectors))] = true;
    const auto f = std::size_t(Sector(dx, dy, fine));
    if (!nearest[f] || d < distance[f])
    {
      nearest[f] = &p;
      distance[f] = d;
    }
  }
  if (std::count(filled.begin(), filled.end(), true) < params.minimumRingSectors)
    return false;
  Point3 centroid = Point3::Zero();
  int n = 0;
  for (const Point3* p : nearest)
    if (p)
    {
      centroid += *p;
      ++n;
    }
  centroid /= double(n);
  double meanRadius = 0.0;
  for (const Point3* p : nearest)
    if (p)
      meanRadius += std::hypot(p->x() - centroid.x(), p->y() - centroid.y());
  if (meanRadius / double(n) < params.minimumRingRadiusMm)
    return false;
  centre = centroid;
  return true;
}

} // namespace

EndograftEvidence FindEndograft(const CtImage& ct,
                                const LabelImage& lumen,
                                const IndexBox& box,
                                const EndograftParams& params)
{
  CheckParams(params);
  EndograftEvidence evidence;
  if (box.Empty())
    return evidence;
  const auto size = ct.GetLargestPossibleRegion().GetSize();
  const auto spacing = ct.GetSpacing();
  const short* hu = ct.GetBufferPointer();
  const unsigned char* mask = lumen.GetBufferPointer();
  const auto ball = PhysicalBallOffsets({ spacing[0], spacing[1], spacing[2] }, params.nearLumenMm);
  const long sx = long(size[0]), sxy = long(size[0]) * long(size[1]);
  const short threshold = static_cast<short>(std::ceil(params.metalHu));
  const double binMm = BinMm(ct);
  std::map<long, Bin> bins;

  ForEachInBox(box, size,
               [&](long, long flat)
               {
                 if (hu[flat] < threshold)
                   return;
                 const long k = flat / sxy, j = (flat % sxy) / sx, i = flat % sx;
                 bool beside = false;
                 for (const auto& o : ball)
                 {
                   const long ii = i + o[0], jj = j + o[1], kk = k + o[2];
                   if (ii < 0 || jj < 0 || kk < 0 || ii >= long(size[0]) || jj >= long(size[1]) || kk >= long(size[2]))
                     continue;
                   if (mask[ii + sx * jj + sxy * kk] != 0)
                   {
                     beside = true;
                     break;
                   }
                 }
                 if (!beside)
                   return;
                 ++evidence.metalVoxels;
                 evidence.maximumHu = std::max(evidence.maximumHu, double(hu[flat]));
                 itk::Point<double, 3> p;
                 ct.TransformIndexToPhysicalPoint(CtImage::IndexType{ { i, j, k } }, p);
                 bins[std::lround(p[2] / binMm)].points.push_back(Point3(p[0], p[1], p[2]));
               });

  for (const auto& [key, bin] : bins)
  {
    if (bin.points.size() < std::size_t(params.minimumRingSectors))
      continue;
    Point3 centre = Point3::Zero();
    for (const Point3& p : bin.points)
      centre += p;
    centre /= double(bin.points.size());
    std::array<bool, sectors> filled{};
    double meanRadius = 0.0;
    for (const Point3& p : bin.points)
    {
      const double dx = p.x() - centre.x(), dy = p.y() - centre.y();
      meanRadius += std::hypot(dx, dy);
      filled[std::size_t(Sector(dx, dy, sectors))] = true;
    }
    meanRadius /= double(bin.points.size());
    if (std::count(filled.begin(), filled.end(), true) < params.minimumRingSectors ||
        meanRadius < params.minimumRingRadiusMm)
      continue;
    AddRing(double(key) * binMm, evidence);
  }
  evidence.ringLengthMm = evidence.ringBins * binMm;
  evidence.found = evidence.ringLengthMm >= params.minimumRingLengthMm;
  return evidence;
}

EndograftEvidence FindEndograftAroundSeed(const CtImage& ct, const Point3& seedLps, const EndograftParams& params)
{
  CheckParams(params);
  EndograftEvidence evidence;
  evidence.aroundSeed = true;
  const auto size = ct.GetLargestPossibleRegion().GetSize();
  itk::ContinuousIndex<double, 3> seedIndex;
  if (!ct.TransformPhysicalPointToContinuousIndex(itk::Point<double, 3>(seedLps.data()), seedIndex))
    return evidence;
  // The box of index space holding the cylinder's bounding box (its eight corners).
  std::array<long, 3> lo{ long(size[0]), long(size[1]), long(size[2]) }, hi{ -1, -1, -1 };
  for (int corner = 0; corner < 8; ++corner)
  {
    const Point3 offset((corner & 1 ? 1 : -1) * params.seedSearchRadiusMm,
                        (corner & 2 ? 1 : -1) * params.seedSearchRadiusMm,
                        (corner & 4 ? 1 : -1) * params.seedSearchHeightMm);
    itk::ContinuousIndex<double, 3> c;
    ct.TransformPhysicalPointToContinuousIndex(itk::Point<double, 3>(Point3(seedLps + offset).data()), c);
    for (int a = 0; a < 3; ++a)
    {
      lo[std::size_t(a)] = std::min(lo[std::size_t(a)], long(std::floor(c[a])));
      hi[std::size_t(a)] = std::max(hi[std::size_t(a)], long(std::ceil(c[a])));
    }
  }
  for (int a = 0; a < 3; ++a)
  {
    lo[std::size_t(a)] = std::max(0L, lo[std::size_t(a)]);
    hi[std::size_t(a)] = std::min(long(size[std::size_t(a)]) - 1, hi[std::size_t(a)]);
  }
  const IndexBox box = PaddedBox(lo, hi, { 0, 0, 0 }, size);
  const short* hu = ct.GetBufferPointer();
  const long sx = long(size[0]), sxy = long(size[0]) * long(size[1]);
  const short threshold = static_cast<short>(std::ceil(params.metalHu));
  const double binMm = BinMm(ct);
  std::map<long, Bin> bins;
  ForEachInBox(
    box, size,
    [&](long, long flat)
    {
      if (hu[flat] < threshold)
        return;
      itk::Point<double, 3> p;
      ct.TransformIndexToPhysicalPoint(CtImage::IndexType{ { flat % sx, (flat % sxy) / sx, flat / sxy } }, p);
      if (std::hypot(p[0] - seedLps.x(), p[1] - seedLps.y()) > params.seedSearchRadiusMm ||
          std::abs(p[2] - seedLps.z()) > params.seedSearchHeightMm)
        return;
      ++evidence.metalVoxels;
      evidence.maximumHu = std::max(evidence.maximumHu, double(hu[flat]));
      bins[std::lround(p[2] / binMm)].points.push_back(Point3(p[0], p[1], p[2]));
    });

  // Walk up, then down, from the seed's bin, each from the seed; a gap of more than
  // maximumRingGapMm without a ring ends a walk.
  const long seedBin = std::lround(seedLps.z() / binMm);
  const long maximumMisses = long(std::floor(params.maximumRingGapMm / binMm));
  const long reach = long(std::ceil(params.seedSearchHeightMm / binMm));
  static const std::vector<Point3> none;
  for (const long step : { 1L, -1L })
  {
    Point3 centre = seedLps;
    long misses = 0;
    for (long key = step > 0 ? seedBin : seedBin - 1; std::abs(key - seedBin) <= reach; key += step)
    {
      const auto bin = bins.find(key);
      if (RingAround(bin == bins.end() ? none : bin->second.points, params, params.seedSearchRadiusMm, centre))
      {
        AddRing(double(key) * binMm, evidence);
        misses = 0;
      }
      else if (++misses > maximumMisses)
        break;
    }
  }
  evidence.ringLengthMm = evidence.ringBins * binMm;
  evidence.found = evidence.ringLengthMm >= params.minimumRingLengthMm;
  return evidence;
}

} // namespace sgp
