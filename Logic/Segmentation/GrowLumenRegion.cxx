#include "Segmentation/GrowLumenRegion.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <stdexcept>
#include <utility>

#include "Common/CheckRange.h"
#include "Common/DistanceInsideMask.h"
#include "Common/Errors.h"
#include "Common/Format.h"
#include "Common/ImageGeometry.h"
#include "Common/IndexBox.h"
#include "Common/MaskGrid.h"
#include "Common/Median.h"
#include "Segmentation/ContinueThinBranches.h"

namespace sgp
{

namespace
{

struct SeedStatistics
{
  double medianHu = 0.0;
  double sigmaHu = 0.0;
  std::vector<CtImage::IndexType> voxels; ///< the neighbourhood, nearest to the seed first
};

/// Median and 1.4826·MAD of the voxels whose centres lie within `radiusMm` of the seed (at least
/// the seed voxel's 3×3×3 neighbourhood on coarse grids).
SeedStatistics MeasureSeedNeighbourhood(const CtImage& ct,
                                        const CtImage::IndexType& seed,
                                        const Point3& seedLps,
                                        double radiusMm)
{
  const auto spacing = ct.GetSpacing();
  const auto region = ct.GetLargestPossibleRegion();
  std::vector<std::pair<double, CtImage::IndexType>> found;
  std::array<long, 3> reach{};
  for (unsigned a = 0; a < 3; ++a)
  {
    reach[a] = std::max(1L, static_cast<long>(std::ceil(radiusMm / spacing[a])));
  }
  for (long dk = -reach[2]; dk <= reach[2]; ++dk)
  {
    for (long dj = -reach[1]; dj <= reach[1]; ++dj)
    {
      for (long di = -reach[0]; di <= reach[0]; ++di)
      {
        CtImage::IndexType index = seed;
        index[0] += di;
        index[1] += dj;
        index[2] += dk;
        if (!region.IsInside(index))
        {
          continue;
        }
        const double distance = (IndexToLps(ct, index) - seedLps).norm();
        const bool inCube = std::abs(di) <= 1 && std::abs(dj) <= 1 && std::abs(dk) <= 1;
        if (distance <= radiusMm || inCube)
        {
          found.emplace_back(distance, index);
        }
      }
    }
  }
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  SeedStatistics stats;
  std::vector<double> values;
  for (const auto& [distance, index] : found)
  {
    stats.voxels.push_back(index);
    values.push_back(ct.GetPixel(index));
  }
  stats.medianHu = Median(values);
  for (double& v : values)
  {
    v = std::abs(v - stats.medianHu);
  }
  stats.sigmaHu = 1.4826 * Median(values);
  return stats;
}

/// Calls `f(k, hu)` for each tissue sample: the voxel `depth[axis]` voxels outside the region
/// along an axis from each boundary face (k: the sample's slice in the crop).
template<class F>
void ForEachTissueSample(const MaskGrid& mask, const std::vector<short>& hu, const std::array<long, 3>& depth, F&& f)
{
  for (long flat = 0; flat < mask.Count(); ++flat)
  {
    if (!mask.voxels[flat])
    {
      continue;
    }
    const auto ijk = mask.Ijk(flat);
    for (int axis = 0; axis < 3; ++axis)
    {
      for (int sign : { -1, 1 })
      {
        auto n = ijk;
        n[axis] += sign;
        auto far = ijk;
        far[axis] += sign * depth[axis];
        if (far[axis] < 0 || far[axis] >= mask.size[axis] || mask.voxels[mask.Flat(n[0], n[1], n[2])])
        {
          continue;
        }
        const long farFlat = mask.Flat(far[0], far[1], far[2]);
        if (!mask.voxels[farFlat])
        {
          f(far[2], hu[farFlat]);
        }
      }
    }
  }
}

/// Median HU `depth[axis]` voxels outside the region, sampled along the axes from its boundary.
double MeasureTissueHu(const MaskGrid& mask, const std::vector<short>& hu, const std::array<long, 3>& depth)
{
  std::vector<double> samples;
  ForEachTissueSample(mask, hu, depth, [&](long, short v) { samples.push_back(v); });
  return samples.empty() ? std::numeric_limits<double>::quiet_NaN() : Median(samples);
}

short ClampToShort(double value)
{
  return static_cast<short>(
    std::clamp(value, double(std::numeric_limits<short>::min()), double(std::numeric_limits<short>::max())));
}

/// Fraction of `stats.voxels` outside [low, high] HU.
double FractionOutside(const CtImage& ct, const SeedStatistics& stats, double low, double high)
{
  long outside = 0;
  for (const auto& index : stats.voxels)
  {
    const double v = ct.GetPixel(index);
    outside += v < low || v > high;
  }
  return stats.voxels.empty() ? 0.0 : double(outside) / double(stats.voxels.size());
}

/// True when the straight line from `seed` to `centre` stays in voxels of at least `minimumHu`
/// beyond its first `skipMm` (a seed placed on a flap or on the wall's edge lies in dark voxels
/// itself): the two lie in one lumen, not across a wall or flap.
bool JoinedThroughLumen(const CtImage& ct,
                        const CtImage::IndexType& seed,
                        const CtImage::IndexType& centre,
                        double distanceMm,
                        double minimumHu,
                        double skipMm)
{
  const int steps = std::max(1, static_cast<int>(std::ceil(distanceMm / 0.5)));
  for (int s = 1; s <= steps; ++s)
  {
    const double t = double(s) / steps;
    if (t * distanceMm < skipMm)
      continue;
    CtImage::IndexType index;
    for (unsigned a = 0; a < 3; ++a)
      index[a] = seed[a] + std::lround(t * double(centre[a] - seed[a]));
    if (ct.GetPixel(index) < minimumHu)
      return false;
  }
  return true;
}

/// Step 1a (Auto): the neighbourhood the window is taken from. The seed's own ball, unless more
/// than 2 % of its voxels lie outside ±4 σ (at least ± minimumHalfWindowHu) of the lumen's own
/// spread near it — a wall, plaque or dissection flap inside the ball. The lumen's spread is the
/// median and σ of the most homogeneous fifth of the candidate balls: centred on a ~1 mm lattice
/// within `seedSearchRadiusMm` of the seed, each with a median of at least `seedMinimumHu` and
/// joined to the seed by a straight line through lumen (JoinedThroughLumen, the seed's own ball
/// radius skipped). Then the nearest candidate that is clean by the same test is used. Sets the
/// window's source in `result` and, when it moved, a warning.
SeedStatistics ChooseWindowNeighbourhood(const CtImage& ct,
                                         const CtImage::IndexType& seed,
                                         const Point3& seedLps,
                                         const RegionGrowingParams& params,
                                         LumenSegmentation& result)
{
  const double ball = params.seedNeighbourhoodRadiusMm;
  SeedStatistics own = MeasureSeedNeighbourhood(ct, seed, seedLps, ball);
  result.windowCentreLps = seedLps;
  result.windowSource = "the seed's neighbourhood";
  if (params.thresholdMode != ThresholdMode::Auto)
    result.windowSource = "the seed's neighbourhood; the window as given (thresholdMode manual)";
  if (params.thresholdMode != ThresholdMode::Auto || params.seedSearchRadiusMm <= 0.0)
    return own;
  const auto spacing = ct.GetSpacing();
  const auto region = ct.GetLargestPossibleRegion();
  struct Candidate
  {
    double distanceMm;
    Point3 lps;
    SeedStatistics stats;
  };
  std::vector<Candidate> candidates;
  std::array<long, 3> stride{}, reach{};
  for (unsigned a = 0; a < 3; ++a)
  {
    stride[a] = std::max(1L, std::lround(1.0 / spacing[a]));
    reach[a] = static_cast<long>(std::floor(params.seedSearchRadiusMm / spacing[a]));
  }
  for (long dk = -(reach[2] / stride[2]) * stride[2]; dk <= reach[2]; dk += stride[2])
    for (long dj = -(reach[1] / stride[1]) * stride[1]; dj <= reach[1]; dj += stride[1])
      for (long di = -(reach[0] / stride[0]) * stride[0]; di <= reach[0]; di += stride[0])
      {
        CtImage::IndexType index = seed;
        index[0] += di;
        index[1] += dj;
        index[2] += dk;
        if (!region.IsInside(index))
          continue;
        const Point3 lps = IndexToLps(ct, index);
        const double distance = (lps - seedLps).norm();
        if (distance > params.seedSearchRadiusMm ||
            !JoinedThroughLumen(ct, seed, index, distance, params.seedMinimumHu, ball))
          continue;
        SeedStatistics s = MeasureSeedNeighbourhood(ct, index, lps, ball);
        if (s.medianHu >= params.seedMinimumHu)
          candidates.push_back({ distance, lps, std::move(s) });
      }
  if (candidates.empty())
    return own; // the seed checks that follow report it
  // The lumen's own spread: the lowest σ of many 65-voxel balls is biased low (the minimum of
  // noisy estimates), so the reference is the cleanest fifth of the candidates: its σ and median.
  std::vector<double> sigmas;
  for (const Candidate& c : candidates)
    sigmas.push_back(c.stats.sigmaHu);
  std::sort(sigmas.begin(), sigmas.end());
  const double sigma = sigmas[sigmas.size() / 5];
  std::vector<double> medians;
  for (const Candidate& c : candidates)
    if (c.stats.sigmaHu <= sigma)
      medians.push_back(c.stats.medianHu);
  const double half = std::max(4.0 * sigma, params.minimumHalfWindowHu);
  const double low = Median(medians) - half, high = Median(medians) + half;
  constexpr double cleanFraction = 0.02; // Gaussian noise leaves 0.006 % beyond 4 σ
  const double ownOutside = FractionOutside(ct, own, low, high);
  if (own.medianHu >= params.seedMinimumHu && ownOutside <= cleanFraction)
    return own;
  std::sort(candidates.begin(), candidates.end(),
            [](const auto& a, const auto& b) { return a.distanceMm < b.distanceMm; });
  for (Candidate& c : candidates)
  {
    if (FractionOutside(ct, c.stats, low, high) <= cleanFraction)
    {
      const Point3 lps = c.lps;
      result.windowCentreLps = lps;
      result.windowSource = "a neighbourhood " + FormatNumber(c.distanceMm, 1) + " mm from the seed, at " +
                            FormatPoint(lps) + " mm LPS (" + FormatNumber(100.0 * ownOutside, 0) +
                            " % of the voxels around the seed itself lie outside " + FormatNumber(low, 0) + " to " +
                            FormatNumber(high, 0) +
                            " HU, the range of the most homogeneous fifth of the lumen within " +
                            FormatNumber(params.seedSearchRadiusMm, 0) + " mm: wall, plaque or a flap beside the seed)";
      result.warnings.push_back("The seed's neighbourhood is not homogeneous lumen; the HU window was taken from " +
                                result.windowSource + ".");
      return std::move(c.stats);
    }
  }
  return own; // no clean neighbourhood: the seed's own, whose checks follow
}

/// Step 1: the window from the seed's neighbourhood, or a cleaner one near it (Auto), or as given
/// (Manual), with the seed checks; sets the window and seed statistics of `result`.
SeedStatistics EstimateWindow(const CtImage& ct,
                              const CtImage::IndexType& seed,
                              const Point3& seedLps,
                              const RegionGrowingParams& params,
                              LumenSegmentation& result)
{
  SeedStatistics stats = ChooseWindowNeighbourhood(ct, seed, seedLps, params, result);
  result.seedMedianHu = stats.medianHu;
  result.seedSigmaHu = stats.sigmaHu;
  const std::string seedText = "Seed " + FormatPoint(seedLps) + " mm LPS";
  if (stats.medianHu < params.seedMinimumHu)
  {
    throw InputError(
      seedText + " lies in tissue of " + FormatNumber(stats.medianHu, 0) + " HU (median of " +
      std::to_string(stats.voxels.size()) + " voxels around it); expected contrast-filled lumen of at least " +
      FormatNumber(params.seedMinimumHu, 0) + " HU (seedMinimumHu); move the seed into the aortic lumen.");
  }
  if (params.thresholdMode == ThresholdMode::Auto)
  {
    const double half = std::max(params.windowSigmas * stats.sigmaHu, params.minimumHalfWindowHu);
    result.lowerHu = stats.medianHu - half;
    result.upperHu = stats.medianHu + 2.0 * half;
  }
  else
  {
    result.lowerHu = params.lowerHu;
    result.upperHu = params.upperHu;
    if (stats.medianHu < params.lowerHu || stats.medianHu > params.upperHu)
    {
      throw InputError(seedText + " has a median of " + FormatNumber(stats.medianHu, 0) +
                       " HU, outside the manual window " + FormatNumber(params.lowerHu, 0) + " to " +
                       FormatNumber(params.upperHu, 0) + " HU; widen the window or use thresholdMode auto.");
    }
  }
  // Calcium and bone: half the window's width above it (Auto: m + 3.5 h, ~10 σ above the lumen,
  // so noise never reaches it; arterial-phase plaque reads 600–1200 HU, vessel-wall.md §2).
  result.calciumHu = result.upperHu + 0.25 * (result.upperHu - result.lowerHu);
  return stats;
}

/// One bit per voxel of the CT's grid (1/16 of the CT's size): the region growing's marks.
class VoxelBits
{
public:
  explicit VoxelBits(long count)
    : m_Words(static_cast<std::size_t>((count + 63) / 64), 0)
  {
  }
  bool Test(long flat) const { return (m_Words[flat >> 6] >> (flat & 63)) & 1u; }
  void Set(long flat) { m_Words[flat >> 6] |= std::uint64_t(1) << (flat & 63); }

private:
  std::vector<std::uint64_t> m_Words;
};

/// Step 2: the face-connected (6-neighbour) region of voxels with HU in the window, from the
/// neighbourhood voxel nearest the seed that lies in it (noise may put the seed voxel itself just
/// outside) — the region ITK's ConnectedThresholdImageFilter grows with face connectivity, marked
/// in one bit per voxel instead of its full-size output and scratch images. Returns the marks and
/// sets `box` to the region's bounding box grown by `pad` voxels (clipped to the image).
/// Per slice k of the CT: the window's lower and upper HU (step 1b); empty: result's one window.
struct SliceWindows
{
  std::vector<short> lower, upper;
};

VoxelBits GrowFromSeed(const CtImage& ct,
                       const SeedStatistics& stats,
                       const LumenSegmentation& result,
                       const std::array<long, 3>& pad,
                       IndexBox& box,
                       const SliceWindows& slices = {})
{
  const auto start = std::find_if(stats.voxels.begin(), stats.voxels.end(),
                                  [&](const auto& index)
                                  {
                                    const short v = ct.GetPixel(index);
                                    if (!slices.lower.empty())
                                      return v >= slices.lower[static_cast<size_t>(index[2])] &&
                                             v <= slices.upper[static_cast<size_t>(index[2])];
                                    return v >= result.lowerHu && v <= result.upperHu;
                                  });
  if (start == stats.voxels.end())
  {
    // Cannot happen: the median is one of the neighbourhood's values and lies in the window.
    throw std::logic_error("GrowLumenRegion: no seed-neighbourhood voxel in the window");
  }
  const short lower = ClampToShort(std::ceil(result.lowerHu)), upper = ClampToShort(std::floor(result.upperHu));
  const short calcium = ClampToShort(std::floor(result.calciumHu));
  const auto size = ct.GetLargestPossibleRegion().GetSize();
  const long nx = long(size[0]), ny = long(size[1]), nz = long(size[2]), slice = nx * ny;
  const short* hu = ct.GetBufferPointer();
  // Beside calcium or bone (a face neighbour above calciumHu) lies its blurred rim, whose HU
  // passes through the lumen's window: not grown into (file comment, step 2).
  const auto besideCalcium = [&](long flat, long i, long j, long k)
  {
    return (i > 0 && hu[flat - 1] > calcium) || (i + 1 < nx && hu[flat + 1] > calcium) ||
           (j > 0 && hu[flat - nx] > calcium) || (j + 1 < ny && hu[flat + nx] > calcium) ||
           (k > 0 && hu[flat - slice] > calcium) || (k + 1 < nz && hu[flat + slice] > calcium);
  };
  VoxelBits inRegion(slice * nz);
  std::array<long, 3> lo{ nx, ny, nz }, hi{ -1, -1, -1 };
  std::vector<long> stack{ (*start)[0] + nx * ((*start)[1] + ny * (*start)[2]) };
  inRegion.Set(stack.back());
  const auto visit = [&](long flat)
  {
    const long k = flat / slice;
    const short lo = slices.lower.empty() ? lower : slices.lower[k],
                up = slices.upper.empty() ? upper : slices.upper[k];
    if (!inRegion.Test(flat) && hu[flat] >= lo && hu[flat] <= up &&
        !besideCalcium(flat, flat % nx, (flat / nx) % ny, flat / slice))
    {
      inRegion.Set(flat);
      stack.push_back(flat);
    }
  };
  while (!stack.empty())
  {
    const long flat = stack.back();
    stack.pop_back();
    const long k = flat / slice, j = (flat - k * slice) / nx, i = flat - k * slice - j * nx;
    lo = { std::min(lo[0], i), std::min(lo[1], j), std::min(lo[2], k) };
    hi = { std::max(hi[0], i), std::max(hi[1], j), std::max(hi[2], k) };
    if (i > 0)
      visit(flat - 1);
    if (i + 1 < nx)
      visit(flat + 1);
    if (j > 0)
      visit(flat - nx);
    if (j + 1 < ny)
      visit(flat + nx);
    if (k > 0)
      visit(flat - slice);
    if (k + 1 < nz)
      visit(flat + slice);
  }
  box = PaddedBox(lo, hi, pad, size);
  return inRegion;
}

/// Step 1b's window half-width at least this share of the slab's lumen level: 70 HU at 350 HU,
/// what 3.5 σ of a 20 HU noise gives, and what the seed balls gave before step 1b (3 × 23–25 HU).
constexpr double lumenHalfWindowFraction = 0.2;

/// Step 1b's growths at most: on the automatic-seed tests' 27 phantoms the windows stop changing
/// after one to three (the first moves them from the seed ball's estimate, the rest by an HU or two
/// of rounding as the region settles), or fall into a cycle of two (below).
constexpr int maximumLumenWindowPasses = 6;

/// The sum of a window's widths over its slices (HU): of the windows of a cycle the narrowest wins.
long TotalWidth(const SliceWindows& w)
{
  long total = 0;
  for (std::size_t k = 0; k < w.lower.size(); ++k)
    total += long(w.upper[k]) - long(w.lower[k]);
  return total;
}

/// Core voxels per slab, at least, for the slab's median to count.
constexpr long minimumSlabVoxels = 200;
/// The slabs' thickness along k, mm: a bolus changes the lumen's HU by up to ~10 HU/cm.
constexpr double slabMm = 20.0;

/// Step 1b measures the lumen this far inside its edge, mm: beyond the partial-volume rim, and
/// deeper than the radius of a renal artery (5–7 mm across) by more than the blocks the core is
/// found on (lumenCoreBlockMm), so that a kidney the region reached through one (its parenchyma
/// 150–250 HU inside the window of a low-contrast scan) is a core of its own and does not lower
/// the aorta's level. The aorta (at least 16 mm across) keeps a core; the iliacs from 10 mm.
constexpr double lumenCoreDepthMm = 5.0;
/// The core is found on blocks of about this size (whole voxels per axis, at least one): its depth
/// needs no finer grid, and the distance transform on blocks costs an eighth of one on voxels.
constexpr double lumenCoreBlockMm = 2.0;

/// The lumen's core: the voxels of `region` whose block (lumenCoreBlockMm) lies at least
/// lumenCoreDepthMm inside the region, in the 6-connected piece of blocks nearest the seed (the
/// seed ball's first voxel; the aorta and the iliacs for a seed in either). A block belongs to the
/// region when more than three quarters of its voxels do, and the region's cavities are filled
/// first: noise puts voxels outside the window inside the lumen (step 6 fills them later), and as
/// background they would riddle the distance field and break the core into pieces. Empty when no
/// block is that deep (a lumen of small vessels only). `region` is on `box`.
MaskGrid LumenCore(const CtImage& ct, const MaskGrid& region, const IndexBox& box, const CtImage::IndexType& seed)
{
  const auto spacing = ct.GetSpacing();
  // The blocks lie on a grid fixed in space (voxel g along axis a, counted from the physical
  // origin of that axis, is in block floor(g / block)), not on the region's box: a scan cut lower,
  // or a region a little wider, then has the same blocks, so the same core where the lumen is the
  // same.
  const auto floorDiv = [](long a, long b) { return a >= 0 ? a / b : -((-a + b - 1) / b); };
  std::array<long, 3> block{}, coarseSize{}, shift{}, firstBlock{};
  std::array<double, 3> coarseSpacing{};
  for (unsigned a = 0; a < 3; ++a)
  {
    block[a] = std::max(1L, static_cast<long>(std::floor(lumenCoreBlockMm / spacing[a] + 1e-9)));
    double along = 0.0; // the image origin's position along axis a, mm
    for (unsigned b = 0; b < 3; ++b)
      along += ct.GetOrigin()[b] * ct.GetDirection()[b][a];
    shift[a] = static_cast<long>(std::lround(along / spacing[a])) + box.first[a];
    firstBlock[a] = floorDiv(shift[a], block[a]);
    coarseSize[a] = floorDiv(shift[a] + region.size[a] - 1, block[a]) - firstBlock[a] + 1;
    coarseSpacing[a] = double(block[a]) * spacing[a];
  }
  // The block of crop voxel i along axis a.
  const auto blockOf = [&](unsigned a, long i) { return floorDiv(shift[a] + i, block[a]) - firstBlock[a]; };
  MaskGrid coarse(coarseSize);
  std::vector<int> inside(static_cast<size_t>(coarse.Count()), 0), total(inside.size(), 0);
  for (long k = 0; k < region.size[2]; ++k)
    for (long j = 0; j < region.size[1]; ++j)
      for (long i = 0; i < region.size[0]; ++i)
      {
        const size_t c = static_cast<size_t>(coarse.Flat(blockOf(0, i), blockOf(1, j), blockOf(2, k)));
        ++total[c];
        inside[c] += region.voxels[region.Flat(i, j, k)];
      }
  for (size_t c = 0; c < inside.size(); ++c)
    coarse.voxels[c] = 4 * inside[c] > 3 * total[c] ? 1 : 0;
  FillHoles(coarse);
  const DistanceField field = DistanceInsideMask(coarse, coarseSpacing, true, float(lumenCoreDepthMm + 1.0));
  MaskGrid deep(coarseSize);
  long nearest = -1;
  double nearestMm2 = std::numeric_limits<double>::infinity();
  for (long c = 0; c < deep.Count(); ++c)
  {
    if (field.distanceMm[static_cast<size_t>(c)] < lumenCoreDepthMm)
      continue;
    deep.voxels[c] = 1;
    const auto ijk = deep.Ijk(c);
    double d2 = 0.0;
    for (unsigned a = 0; a < 3; ++a)
    {
      const long firstVoxel = (firstBlock[a] + ijk[a]) * block[a] - shift[a] + box.first[a]; // CT index
      const double d = (double(firstVoxel) + 0.5 * double(block[a] - 1) - double(seed[a])) * spacing[a];
      d2 += d * d;
    }
    if (d2 < nearestMm2)
    {
      nearestMm2 = d2;
      nearest = c;
    }
  }
  MaskGrid core(region.size);
  if (nearest < 0)
    return core;
  const MaskGrid piece = ConnectedComponent(deep, nearest);
  for (long k = 0; k < region.size[2]; ++k)
    for (long j = 0; j < region.size[1]; ++j)
      for (long i = 0; i < region.size[0]; ++i)
      {
        const long f = region.Flat(i, j, k);
        core.voxels[f] = region.voxels[f] && piece.voxels[piece.Flat(blockOf(0, i), blockOf(1, j), blockOf(2, k))];
      }
  return core;
}

/// The lumen's core voxels (LumenCore) in slabs `slabMm` thick along k, placed on the k axis's own
/// physical coordinate (so a scan cut shorter keeps the same slabs): each slab's median (NaN: too
/// few core voxels), the overall median, and the noise σ (the median of the slabs' 1.4826 × MAD).
/// Seeds anywhere in one lumen grow nearly the same region, so these are nearly the same for all
/// of them, where the seed ball's 30–100 voxels move the median by a few HU with their noise and
/// place. `core` and `hu` are on `box`.
struct LumenLevels
{
  std::vector<double> sliceMedianHu; ///< per slice k of the CT: its slab's median, NaN where unknown
  double medianHu = 0.0, sigmaHu = 0.0;
  int slabs = 0;
};

/// The slab (slabMm thick, at fixed heights along k) that CT slice k lies in: its physical
/// position along its own axis, origin · d_k + k · spacing_k, over slabMm, rounded down.
long SlabOfSlice(const CtImage& ct, long k)
{
  double origin = 0.0;
  for (unsigned a = 0; a < 3; ++a)
    origin += ct.GetOrigin()[a] * ct.GetDirection()[a][2];
  return static_cast<long>(std::floor((origin + double(k) * ct.GetSpacing()[2]) / slabMm));
}

LumenLevels MeasureLumenLevels(const CtImage& ct,
                               const MaskGrid& core,
                               const std::vector<short>& hu,
                               const IndexBox& box)
{
  const long nz = static_cast<long>(ct.GetLargestPossibleRegion().GetSize()[2]);
  const long bx = core.size[0], by = core.size[1], bz = core.size[2];
  const auto slabOf = [&](long k) { return SlabOfSlice(ct, k); };
  LumenLevels levels;
  levels.sliceMedianHu.assign(static_cast<size_t>(nz), std::numeric_limits<double>::quiet_NaN());
  std::vector<double> slab, sigmas, medians;
  const long kFirst = 0, kLast = bz - 1;
  long slabStart = box.first[2] + kFirst;
  const auto closeSlab = [&](long kEnd) // kEnd: the CT slice after the slab
  {
    if (static_cast<long>(slab.size()) >= minimumSlabVoxels)
    {
      const double m = Median(slab);
      for (double& v : slab)
        v = std::abs(v - m);
      sigmas.push_back(1.4826 * Median(slab));
      medians.push_back(m);
      for (long k = slabStart; k < kEnd; ++k)
        levels.sliceMedianHu[static_cast<size_t>(k)] = m;
    }
    slab.clear();
    slabStart = kEnd;
  };
  for (long k = kFirst; k <= kLast; ++k)
  {
    const long kImage = box.first[2] + k;
    if (k > kFirst && slabOf(kImage) != slabOf(kImage - 1))
      closeSlab(kImage);
    for (long f = core.Flat(0, 0, k), end = f + bx * by; f < end; ++f)
      if (core.voxels[f])
        slab.push_back(hu[f]);
  }
  closeSlab(box.first[2] + kLast + 1);
  levels.slabs = static_cast<int>(medians.size());
  if (medians.empty())
    return levels;
  levels.medianHu = Median(medians);
  levels.sigmaHu = Median(sigmas);
  // Slices without a slab level take the nearest slab's (thin vessels only, or beyond the region).
  std::vector<double>& m = levels.sliceMedianHu;
  for (long k = 0, last = -1; k < nz; ++k)
    if (!std::isnan(m[k]))
    {
      for (long q = last + 1; q < k; ++q)
        m[q] = (last < 0 || k - q <= q - last) ? m[k] : m[last];
      last = k;
    }
    else if (k == nz - 1 && last >= 0)
      for (long q = last + 1; q < nz; ++q)
        m[q] = m[last];
  return levels;
}

/// Step 1b's window per CT slice from the lumen's levels, and its overall extent.
SliceWindows WindowsFromLevels(const LumenLevels& lumen,
                               const RegionGrowingParams& params,
                               double& lowest,
                               double& highest)
{
  SliceWindows windows;
  lowest = std::numeric_limits<double>::infinity();
  highest = -lowest;
  for (const double m : lumen.sliceMedianHu)
  {
    // The core's σ is the noise alone, where a seed ball's also holds some of the lumen's own
    // variation (measured: 19 against 25 HU in one 20 HU-noise phantom); k σ of the noise alone
    // cuts the partial-volume core of a 5–7 mm branch (an internal iliac) off, so the half-width
    // is at least lumenHalfWindowFraction of the level.
    const double half =
      std::max({ params.windowSigmas * lumen.sigmaHu, params.minimumHalfWindowHu, lumenHalfWindowFraction * m });
    windows.lower.push_back(ClampToShort(std::ceil(m - half)));
    windows.upper.push_back(ClampToShort(std::floor(m + 2.0 * half)));
    lowest = std::min(lowest, m - half);
    highest = std::max(highest, m + 2.0 * half);
  }
  return windows;
}

/// The grown region's padded bounding box, with the region and the CT's HU copied into it: every
/// later step works on this box only.
struct CroppedRegion
{
  IndexBox box;
  MaskGrid region;
  std::vector<short> hu;
};

CroppedRegion CropToRegion(const CtImage& ct, const VoxelBits& inRegion, const IndexBox& box)
{
  CroppedRegion crop;
  crop.box = box;
  crop.region = MaskGrid(crop.box.size);
  crop.hu.resize(static_cast<std::size_t>(crop.region.Count()));
  ForEachInBox(crop.box, ct.GetLargestPossibleRegion().GetSize(),
               [&](long flat, long image)
               {
                 crop.region.voxels[flat] = inRegion.Test(image) ? 1 : 0;
                 crop.hu[flat] = ct.GetBufferPointer()[image];
               });
  return crop;
}

/// The opening's ball per axis, rounded down so that it never reaches further than
/// leakOpeningRadiusMm: a coarse axis (2–3 mm slices) is not eroded at all rather than by a whole
/// slice too many.
std::array<int, 3> OpeningBallIjk(const CtImage::SpacingType& spacing, double radiusMm)
{
  std::array<int, 3> openIjk{};
  for (unsigned a = 0; a < 3; ++a)
    openIjk[a] = static_cast<int>(std::floor(radiusMm / spacing[a] + 1e-9));
  return openIjk;
}

/// The region after leak cutting, and its interior (the opening's eroded seed component).
struct CutRegion
{
  MaskGrid lumen;
  MaskGrid interior;
};

/// Step 3: opening with the ball, keeping the seed's component; cut-off pieces under
/// leakMinimumPieceMl go back, larger ones stay cut and are reported in `result`.
CutRegion CutLeaks(const CtImage& ct,
                   const CroppedRegion& crop,
                   const SeedStatistics& stats,
                   const std::array<int, 3>& openIjk,
                   const std::string& seedText,
                   const RegionGrowingParams& params,
                   double voxelMl,
                   LumenSegmentation& result)
{
  const MaskGrid& core = crop.region;
  const IndexBox& box = crop.box;
  CutRegion out{ core, core };
  if (openIjk[0] + openIjk[1] + openIjk[2] == 0)
    return out;
  const auto ball = BallOffsets(openIjk);
  const MaskGrid eroded = Erode(core, ball);
  // The component of the eroded voxel nearest the seed: a noise pit next to the seed voxel may
  // erode the seed voxel itself.
  long interiorSeed = -1;
  for (const auto& index : stats.voxels)
  {
    const std::array<long, 3> b{ index[0] - box.first[0], index[1] - box.first[1], index[2] - box.first[2] };
    if (b[0] < 0 || b[1] < 0 || b[2] < 0 || b[0] >= box.size[0] || b[1] >= box.size[1] || b[2] >= box.size[2])
      continue;
    const long flat = core.Flat(b[0], b[1], b[2]);
    if (eroded.voxels[flat])
    {
      interiorSeed = flat;
      break;
    }
  }
  out.interior = ConnectedComponent(eroded, interiorSeed);
  if (out.interior.CountForeground() == 0)
  {
    throw InputError(seedText + " lies in a vessel narrower than the leak-cutting opening (" +
                     FormatNumber(2 * params.leakOpeningRadiusMm, 1) +
                     " mm across); place the seed in the aorta, or lower leakOpeningRadiusMm.");
  }
  out.lumen = Dilate(out.interior, ball);
  MaskGrid cut(core.size);
  for (long flat = 0; flat < core.Count(); ++flat)
  {
    out.lumen.voxels[flat] = out.lumen.voxels[flat] && core.voxels[flat];
    cut.voxels[flat] = core.voxels[flat] && !out.lumen.voxels[flat];
  }
  // Pieces below leakMinimumPieceMl are vessels that narrow below the ball (small branches, a
  // stenosis) and go back; larger ones are what a leak into bone, kidney or bowel looks like.
  std::vector<long> sizes;
  const std::vector<int> pieces = LabelComponents(cut, sizes);
  long largest = 0, largestVoxel = -1;
  for (long flat = 0; flat < cut.Count(); ++flat)
  {
    if (!pieces[flat])
      continue;
    const long size = sizes[pieces[flat] - 1];
    if (size * voxelMl < params.leakMinimumPieceMl)
    {
      out.lumen.voxels[flat] = 1;
      cut.voxels[flat] = 0;
    }
    else if (size > largest)
    {
      largest = size;
      largestVoxel = flat;
    }
  }
  result.cutVolumeMl = cut.CountForeground() * voxelMl;
  if (largestVoxel >= 0)
  {
    const auto ijk = cut.Ijk(largestVoxel);
    CtImage::IndexType where{ { box.first[0] + ijk[0], box.first[1] + ijk[1], box.first[2] + ijk[2] } };
    result.warnings.push_back("Leak cut: " + FormatNumber(result.cutVolumeMl, 1) +
                              " mL joined to the lumen only through bridges thinner than " +
                              FormatNumber(2 * params.leakOpeningRadiusMm, 1) + " mm was removed (the largest piece " +
                              FormatNumber(largest * voxelMl, 1) + " mL, near " + FormatPoint(IndexToLps(ct, where)) +
                              " mm LPS); check for bone or bowel there.");
  }
  return out;
}

/// Step 4: the tissue level just outside the region; more than darkLeakLimitMl of the interior
/// darker than tissue + 0.7·(m − tissue) means a flood into another tissue class.
void CheckForDarkFlood(const CutRegion& region,
                       const std::vector<short>& hu,
                       const std::array<long, 3>& tissueDepth,
                       const SeedStatistics& stats,
                       const RegionGrowingParams& params,
                       double voxelMl,
                       LumenSegmentation& result)
{
  result.tissueHu = MeasureTissueHu(region.lumen, hu, tissueDepth);
  if (std::isnan(result.tissueHu))
  {
    result.tissueHu = std::min(params.seedMinimumHu, result.lowerHu);
  }
  const double darkHu = result.tissueHu + 0.7 * (stats.medianHu - result.tissueHu);
  long dark = 0;
  for (long flat = 0; flat < region.interior.Count(); ++flat)
  {
    dark += (region.interior.voxels[flat] && hu[flat] < darkHu) ? 1 : 0;
  }
  if (dark * voxelMl > params.darkLeakLimitMl)
  {
    // The advice fits the mode: an automatic window is narrowed through windowSigmas or replaced
    // by a manual one; a manual window's lower end is raised, or the automatic one tried.
    const std::string remedy =
      params.thresholdMode == ThresholdMode::Auto
        ? "the automatic window's lower end is " + FormatNumber(result.lowerHu, 0) + " HU: lower windowSigmas (now " +
            FormatNumber(params.windowSigmas, 1) + "), or use thresholdMode manual with lowerHu above " +
            FormatNumber(darkHu, 0) + " HU."
        : "raise the lower threshold (now " + FormatNumber(result.lowerHu, 0) + " HU) or use thresholdMode auto.";
    throw AlgorithmError("Region growing leaked into darker tissue: " + FormatNumber(dark * voxelMl, 1) +
                         " mL deep inside the region is below " + FormatNumber(darkHu, 0) +
                         " HU, while the lumen at the " + "seed is " + FormatNumber(stats.medianHu, 0) +
                         " HU (likely kidney, bowel or marrow); " + remedy);
  }
}

/// Step 5's edge level on each slice of the crop (`firstSlice` its first CT slice): half-way
/// between the lumen and the tissue around it. Without step 1b's levels (`sliceLevelHu` empty) one
/// level, the seed's median and the tissue median around the whole region. With them each slice's
/// own: its slab's lumen level, and the tissue median of its slab's samples (MeasureTissueHu's
/// samples on that slab's slices, when at least minimumSlabVoxels), else the whole region's; so a
/// bolus fading down the body keeps each level's half-maximum, and what lies around the lumen far
/// from a level — a heart in view 70 mm above the renal arteries, a scan cut lower — does not move
/// its edge.
std::vector<double> EdgeLevels(const CtImage& ct,
                               const MaskGrid& mask,
                               const std::vector<short>& hu,
                               const std::array<long, 3>& depth,
                               long firstSlice,
                               const std::vector<double>& sliceLevelHu,
                               double medianHu,
                               double tissueHu)
{
  const long nz = mask.size[2];
  std::vector<double> edge(static_cast<std::size_t>(nz), 0.5 * (medianHu + tissueHu));
  if (sliceLevelHu.empty())
    return edge;
  std::vector<long> slabOfK(static_cast<std::size_t>(nz));
  for (long k = 0; k < nz; ++k)
    slabOfK[static_cast<std::size_t>(k)] = SlabOfSlice(ct, firstSlice + k);
  std::map<long, std::vector<double>> samples; // by slab
  ForEachTissueSample(mask, hu, depth,
                      [&](long k, short v) { samples[slabOfK[static_cast<std::size_t>(k)]].push_back(v); });
  std::map<long, double> tissue;
  for (auto& [slab, values] : samples)
    if (static_cast<long>(values.size()) >= minimumSlabVoxels)
      tissue[slab] = Median(values);
  for (long k = 0; k < nz; ++k)
  {
    const long image = firstSlice + k;
    if (image < 0 || image >= static_cast<long>(sliceLevelHu.size()))
      continue;
    const auto t = tissue.find(slabOfK[static_cast<std::size_t>(k)]);
    edge[static_cast<std::size_t>(k)] =
      0.5 * (sliceLevelHu[static_cast<std::size_t>(image)] + (t != tissue.end() ? t->second : tissueHu));
  }
  return edge;
}

/// Steps 5 and 6: the boundary moved to the half-maximum edge level, `edge[k]` on crop slice k
/// (EdgeLevels), then pits and holes filled.
void RefineBoundary(MaskGrid& lumen,
                    const std::vector<short>& hu,
                    int refineSteps,
                    const std::vector<std::array<int, 3>>& reachBall,
                    const std::vector<double>& edge,
                    LumenSegmentation& result)
{
  std::vector<bool> accept(static_cast<std::size_t>(lumen.Count()));
  const long nx = lumen.size[0], ny = lumen.size[1], nz = lumen.size[2], slice = nx * ny;
  // Within refineDistanceMm of the grown region in millimetres, on every axis: counted in face
  // steps of the finest spacing, the reach along 2.5 mm slices was 3 slices, 7.5 mm — into an
  // enhancing renal vein above or below the lumen (16 % of it on 0.7 × 0.7 × 2.5 mm).
  // Only the few voxels in the window outside the lumen look for a lumen voxel within the ball
  // (no box-sized dilated copy of the lumen, which cost 38 MiB of peak memory on 512 × 512 × 1000).
  const auto withinReach = [&](long flat)
  {
    const long i = flat % nx, j = (flat / nx) % ny, k = flat / slice;
    for (const auto& d : reachBall)
    {
      const long a = i + d[0], b = j + d[1], c = k + d[2];
      if (a >= 0 && b >= 0 && c >= 0 && a < nx && b < ny && c < nz && lumen.voxels[a + nx * (b + ny * c)])
        return true;
    }
    return false;
  };
  for (long flat = 0; flat < lumen.Count(); ++flat)
  {
    accept[flat] = !lumen.voxels[flat] && hu[flat] >= edge[static_cast<std::size_t>(flat / slice)] &&
                   hu[flat] <= result.upperHu && withinReach(flat);
  }
  // Not into a calcium's or bone's blurred rim either (as GrowFromSeed).
  for (long flat = 0; flat < lumen.Count(); ++flat)
    if (hu[flat] > result.calciumHu)
    {
      const long i = flat % nx, j = (flat / nx) % ny, k = flat / slice;
      accept[flat] = false;
      if (i > 0)
        accept[flat - 1] = false;
      if (i + 1 < nx)
        accept[flat + 1] = false;
      if (j > 0)
        accept[flat - nx] = false;
      if (j + 1 < ny)
        accept[flat + nx] = false;
      if (k > 0)
        accept[flat - slice] = false;
      if (k + 1 < nz)
        accept[flat + slice] = false;
    }
  GrowConstrained(lumen, accept, refineSteps);
  // Noise leaves single-voxel pits in the boundary (a voxel just inside the wall drawn below the
  // edge level); the inscribed-sphere radius of the centerlines is the distance to the nearest of
  // them, so they are filled: a background voxel with 5 or 6 lumen faces becomes lumen.
  FillSurfacePits(lumen, 5);
  FillHoles(lumen);
}

/// The cropped lumen pasted into a mask on the CT's grid.
LabelImage::Pointer PasteOnGrid(const CtImage& ct, const MaskGrid& lumen, const IndexBox& box)
{
  LabelImage::Pointer mask = LabelImage::New();
  mask->CopyInformation(&ct);
  mask->SetRegions(ct.GetLargestPossibleRegion());
  mask->Allocate(true);
  ForEachInBox(box, ct.GetLargestPossibleRegion().GetSize(),
               [&](long flat, long image) { mask->GetBufferPointer()[image] = lumen.voxels[flat]; });
  return mask;
}

} // namespace

void ValidateRegionGrowingParams(const RegionGrowingParams& params)
{
  const auto check = CheckRange;
  check("lowerHu", params.lowerHu, -1024, 3071, "HU");
  check("upperHu", params.upperHu, -1024, 3071, "HU");
  check("windowSigmas", params.windowSigmas, 1, 10, "standard deviations");
  check("seedMinimumHu", params.seedMinimumHu, -1024, 3071, "HU");
  check("leakOpeningRadiusMm", params.leakOpeningRadiusMm, 0, 5, "mm");
  check("maximumLumenVolumeMl", params.maximumLumenVolumeMl, 1, 20000, "mL");
  check("seedNeighbourhoodRadiusMm", params.seedNeighbourhoodRadiusMm, 0, 20, "mm");
  check("seedSearchRadiusMm", params.seedSearchRadiusMm, 0, 20, "mm");
  check("minimumHalfWindowHu", params.minimumHalfWindowHu, 0, 1000, "HU");
  check("refineDistanceMm", params.refineDistanceMm, 0, 10, "mm");
  check("tissueDepthMm", params.tissueDepthMm, 0, 20, "mm");
  check("thinBranchRadiusMm", params.thinBranchRadiusMm, 0, 20, "mm");
  check("thinBranchReachMm", params.thinBranchReachMm, 0, 50, "mm");
  if (params.thresholdMode == ThresholdMode::Manual && !(params.lowerHu < params.upperHu))
  {
    throw InputError("lowerHu (" + FormatNumber(params.lowerHu, 1) + " HU) must be less than upperHu (" +
                     FormatNumber(params.upperHu, 1) + " HU); swap them or widen the window.");
  }
}

LumenSegmentation GrowLumenRegion(const CtImage& ct,
                                  const Point3& seedLps,
                                  const RegionGrowingParams& params,
                                  const ProgressCallback& progress)
{
  ValidateRegionGrowingParams(params);
  const CtImage::IndexType seed = LpsToIndexInside(ct, seedLps, "Seed");
  const auto spacing = ct.GetSpacing();
  const double voxelMl = spacing[0] * spacing[1] * spacing[2] / 1000.0;
  const std::string seedText = "Seed " + FormatPoint(seedLps) + " mm LPS";
  LumenSegmentation result;

  ReportProgress(progress, 0.0, "Estimating the HU window at the seed");
  SeedStatistics stats = EstimateWindow(ct, seed, seedLps, params, result);

  // The box every later step works in: the grown region padded by the opening, the boundary
  // refinement's reach and the tissue depth.
  const std::array<int, 3> openIjk = OpeningBallIjk(spacing, params.leakOpeningRadiusMm);
  const double minSpacing = std::min({ spacing[0], spacing[1], spacing[2] });
  const int refineSteps = static_cast<int>(std::ceil(params.refineDistanceMm / minSpacing));
  // Tissue is sampled beyond the blur of the edge: tissueDepthMm outside, at least 3 voxels.
  std::array<long, 3> tissueDepth{}, pad{};
  for (unsigned a = 0; a < 3; ++a)
  {
    tissueDepth[a] = std::max(3L, static_cast<long>(std::ceil(params.tissueDepthMm / spacing[a])));
    pad[a] = openIjk[a] + refineSteps + tissueDepth[a] + 2;
  }

  ReportProgress(progress, 0.05, "Region growing");
  CroppedRegion crop;
  std::vector<double> sliceLevelHu; // step 1b's levels slice by slice, when it ran
  {
    IndexBox box;
    const VoxelBits grown = GrowFromSeed(ct, stats, result, pad, box);
    crop = CropToRegion(ct, grown, box);
  } // the marks are freed here: only the CT and box-sized buffers are held until the mask is pasted
  if (params.thresholdMode == ThresholdMode::Auto && params.windowFromLumen)
  {
    // Step 1b: the window again, slab by slab from the lumen's own core, and the region grown again
    // with it until the windows no longer change (file comment): the plan no longer depends on
    // where in the lumen the seed lies, and a bolus that fades down the body keeps each level's
    // own window. The core needs no leak cutting: a leak joins through a bridge thinner than it.
    ReportProgress(progress, 0.2, "Estimating the HU window from the lumen");
    // Each growth's windows and what they came from. Integer HU make the core's σ move in steps
    // of 1.48 HU (its MAD is a whole or half HU), and a window's edge that takes a kidney at 230 HU
    // in or out moves the core's σ by one such step: the windows can alternate between two values,
    // and then which of them the last growth used depended on where the seed started. A window
    // met again ends the loop on the narrowest of the cycle, the same from every start.
    struct Growth
    {
      SliceWindows windows;
      LumenLevels lumen;
      double lowest = 0.0, highest = 0.0;
    };
    std::vector<Growth> growths;
    const CtImage::IndexType& seedVoxel = stats.voxels.front();
    const short seedHu = ct.GetPixel(seedVoxel);
    const size_t seedK = static_cast<size_t>(seedVoxel[2]);
    const auto grow = [&](const Growth& g)
    {
      result.lowerHu = g.lowest; // GrowFromSeed's start voxel and calcium level
      result.upperHu = g.highest;
      result.calciumHu = g.highest + 0.25 * (g.highest - g.lowest);
      IndexBox box;
      const VoxelBits grown = GrowFromSeed(ct, stats, result, pad, box, g.windows);
      crop = CropToRegion(ct, grown, box);
    };
    for (int pass = 0; pass < maximumLumenWindowPasses; ++pass)
    {
      Growth next;
      next.lumen = MeasureLumenLevels(ct, LumenCore(ct, crop.region, crop.box, seedVoxel), crop.hu, crop.box);
      if (next.lumen.slabs == 0)
        break; // no core: a lumen of small vessels only; the seed's window stays
      next.windows = WindowsFromLevels(next.lumen, params, next.lowest, next.highest);
      const auto same = [&](const Growth& g)
      { return g.windows.lower == next.windows.lower && g.windows.upper == next.windows.upper; };
      if (!growths.empty() && same(growths.back()))
        break; // the fixed point: growing again gives the same region
      const auto met = std::find_if(growths.begin(), growths.end(), same);
      if (met != growths.end())
      {
        // Narrowest first, then the higher lower ends: an order of the windows themselves, not of
        // the cycle's phase (two windows of one width, one shifted, would otherwise be told apart
        // by which came first, i.e. by the seed).
        const auto narrowest = std::min_element(met, growths.end(),
                                                [](const Growth& x, const Growth& y)
                                                {
                                                  const long wx = TotalWidth(x.windows), wy = TotalWidth(y.windows);
                                                  return wx != wy ? wx < wy : x.windows.lower > y.windows.lower;
                                                });
        if (narrowest != growths.end() - 1)
        {
          Growth chosen = *narrowest;
          grow(chosen);
          growths.push_back(std::move(chosen));
        }
        break;
      }
      if (seedHu < next.windows.lower[seedK] || seedHu > next.windows.upper[seedK])
        break; // the seed's voxel is not lumen by the lumen's own levels: keep what it grew
      grow(next);
      growths.push_back(std::move(next));
    }
    std::string source;
    if (!growths.empty())
    {
      const Growth& last = growths.back();
      stats.medianHu = last.lumen.medianHu;
      stats.sigmaHu = last.lumen.sigmaHu;
      sliceLevelHu = last.lumen.sliceMedianHu;
      const std::size_t n = growths.size();
      source = ", then slab by slab from the lumen's core (" + std::to_string(last.lumen.slabs) + " slabs of 20 mm, " +
               FormatNumber(lumenCoreDepthMm, 0) + " mm inside its edge, median " +
               FormatNumber(last.lumen.medianHu, 0) + " HU, noise sigma " + FormatNumber(last.lumen.sigmaHu, 0) +
               " HU; " + std::to_string(n) + (n == 1 ? " growth)" : " growths)");
    }
    result.windowSource += source;
  }
  ReportProgress(progress, 0.4, "Cutting leaks");
  CutRegion region = CutLeaks(ct, crop, stats, openIjk, seedText, params, voxelMl, result);

  ReportProgress(progress, 0.6, "Checking for leaks");
  CheckForDarkFlood(region, crop.hu, tissueDepth, stats, params, voxelMl, result);

  ReportProgress(progress, 0.7, "Refining the boundary");
  result.edgeHu = 0.5 * (stats.medianHu + result.tissueHu);
  const std::vector<double> edge = EdgeLevels(ct, region.lumen, crop.hu, tissueDepth, crop.box.first[2], sliceLevelHu,
                                              stats.medianHu, result.tissueHu);
  RefineBoundary(region.lumen, crop.hu, refineSteps,
                 PhysicalBallOffsets({ spacing[0], spacing[1], spacing[2] }, params.refineDistanceMm), edge, result);

  result.volumeMl = region.lumen.CountForeground() * voxelMl;
  if (result.volumeMl > params.maximumLumenVolumeMl)
  {
    throw AlgorithmError("Region growing leaked: " + FormatNumber(result.volumeMl, 0) + " mL segmented, limit " +
                         FormatNumber(params.maximumLumenVolumeMl, 0) + " mL (maximumLumenVolumeMl); lower the upper " +
                         "threshold (now " + FormatNumber(result.upperHu, 0) + " HU) or move the seed.");
  }

  ReportProgress(progress, 0.9, "Writing the mask");
  // Free what is no longer needed before the full-grid mask is allocated.
  region.interior = MaskGrid();
  crop.region = MaskGrid();
  std::vector<short>().swap(crop.hu);
  result.mask = PasteOnGrid(ct, region.lumen, crop.box);
  result.box = crop.box; // step 7 adds only inside it

  // Step 7: narrow branches the window lost, followed on at the edge level (ContinueThinBranches.h).
  if (params.thinBranchRadiusMm > 0.0)
  {
    ReportProgress(progress, 0.95, "Following narrow branches");
    ThinBranchParams thin;
    thin.maxRadiusMm = params.thinBranchRadiusMm;
    thin.minReachMm = params.thinBranchReachMm;
    thin.maxPieceMl = params.leakMinimumPieceMl;
    const long firstSlice = crop.box.first[2], slices = static_cast<long>(edge.size());
    const ThinBranchResult added = ContinueThinBranches(
      ct, *result.mask, crop.box,
      [&](long k) { return edge[static_cast<std::size_t>(std::clamp(k - firstSlice, 0L, slices - 1))]; },
      [&](long k)
      {
        return sliceLevelHu.empty()
                 ? stats.medianHu
                 : sliceLevelHu[static_cast<std::size_t>(std::clamp(k, 0L, long(sliceLevelHu.size()) - 1))];
      },
      result.upperHu, result.calciumHu, thin);
    result.thinBranchPieces = added.pieces;
    result.thinBranchMl = added.addedMl;
    result.volumeMl += added.addedMl;
  }
  ReportProgress(progress, 1.0, "Done");
  return result;
}

} // namespace sgp
