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

} // namespace

EndograftEvidence FindEndograft(const CtImage& ct,
                                const LabelImage& lumen,
                                const IndexBox& box,
                                const EndograftParams& params)
{
  CheckRange("metalHu", params.metalHu, 1000.0, 3071.0, "HU");
  CheckRange("nearLumenMm", params.nearLumenMm, 1.0, 10.0, "mm");
  CheckRange("minimumRingSectors", params.minimumRingSectors, 4, sectors, "");
  CheckRange("minimumRingRadiusMm", params.minimumRingRadiusMm, 2.0, 30.0, "mm");
  CheckRange("minimumRingLengthMm", params.minimumRingLengthMm, 1.0, 200.0, "mm");
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

  // The slice thickness along z: each bin is one slice of the acquisition (any orientation).
  const auto& direction = ct.GetDirection();
  double binMm = 0.0;
  for (unsigned a = 0; a < 3; ++a)
    binMm = std::max(binMm, std::abs(direction(2, a)) * spacing[a]);
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

  bool first = true;
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
      const double angle = std::atan2(dy, dx) + pi; // [0, 2π]
      filled[std::size_t(std::min(sectors - 1, int(angle / (2.0 * pi / sectors))))] = true;
    }
    meanRadius /= double(bin.points.size());
    if (std::count(filled.begin(), filled.end(), true) < params.minimumRingSectors ||
        meanRadius < params.minimumRingRadiusMm)
      continue;
    ++evidence.ringBins;
    const double z = double(key) * binMm;
    evidence.ringFromZ = first ? z : std::min(evidence.ringFromZ, z);
    evidence.ringToZ = first ? z : std::max(evidence.ringToZ, z);
    first = false;
  }
  evidence.ringLengthMm = evidence.ringBins * binMm;
  evidence.found = evidence.ringLengthMm >= params.minimumRingLengthMm;
  return evidence;
}

} // namespace sgp
