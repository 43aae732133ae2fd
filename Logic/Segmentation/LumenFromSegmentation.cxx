#include "Segmentation/LumenFromSegmentation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "Common/Errors.h"
#include "Common/Format.h"
#include "Common/HugePages.h"
#include "Common/ImageGeometry.h"
#include "Common/IndexBox.h"
#include "Common/MaskGrid.h"
#include "Common/Median.h"
#include "Segmentation/LumenGrowthSteps.h"

namespace sgp
{
namespace
{

/// Index → LPS as one affine map: p = origin + M · index.
struct Affine
{
  Eigen::Matrix3d M;
  Eigen::Vector3d origin;
};

Affine IndexToLpsMap(const itk::ImageBase<3>& image)
{
  Affine a;
  for (int r = 0; r < 3; ++r)
  {
    a.origin[r] = image.GetOrigin()[r];
    for (int c = 0; c < 3; ++c)
      a.M(r, c) = image.GetDirection()(r, c) * image.GetSpacing()[c];
  }
  return a;
}

std::string Extent(const itk::ImageBase<3>& image)
{
  const std::array<double, 6> b = ImageBoundsLps(image);
  return "x " + FormatNumber(b[0]) + " to " + FormatNumber(b[1]) + ", y " + FormatNumber(b[2]) + " to " +
         FormatNumber(b[3]) + ", z " + FormatNumber(b[4]) + " to " + FormatNumber(b[5]) + " mm LPS";
}

/// The given mask's foreground on the CT's grid, each CT voxel taking its nearest segmentation
/// voxel (file comment, step 1); only CT voxels within the foreground box's physical extent are
/// visited. On the CT's own grid the given image itself, its foreground set to 1.
LabelImage::Pointer OntoCtGrid(const LabelImage::Pointer& given, const IndexBox& foreground, const CtImage& ct)
{
  const Affine seg = IndexToLpsMap(*given), grid = IndexToLpsMap(ct);
  // The same grid (the plan's own label map, a segmentation made on this CT): each voxel is its
  // own nearest, and the given buffer is the mask (1e-6 mm: the files' printed precision).
  const itk::Size<3> ctSize = ct.GetLargestPossibleRegion().GetSize();
  if (given->GetLargestPossibleRegion().GetSize() == ctSize && (seg.M - grid.M).cwiseAbs().maxCoeff() < 1e-6 &&
      (seg.origin - grid.origin).cwiseAbs().maxCoeff() < 1e-6)
  {
    unsigned char* voxels = given->GetBufferPointer();
    ForEachInBox(foreground, ctSize, [&](long, long image) { voxels[image] = voxels[image] ? 1 : 0; });
    given->CopyInformation(&ct); // within 1e-6 mm: the CT's own numbers
    return given;
  }
  auto out = LabelImage::New();
  out->CopyInformation(&ct);
  out->SetRegions(ct.GetLargestPossibleRegion());
  AllocateAdvised(*out, true);
  const Eigen::Matrix3d ctFromLps = grid.M.inverse();
  // The CT index box spanned by the foreground box's corners (half a voxel beyond its centres).
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (int corner = 0; corner < 8; ++corner)
  {
    Eigen::Vector3d index;
    for (int a = 0; a < 3; ++a)
      index[a] = (corner >> a & 1) ? foreground.first[std::size_t(a)] + foreground.size[std::size_t(a)] - 0.5
                                   : foreground.first[std::size_t(a)] - 0.5;
    const Eigen::Vector3d c = ctFromLps * (seg.origin + seg.M * index - grid.origin);
    lo = lo.cwiseMin(c);
    hi = hi.cwiseMax(c);
  }
  std::array<long, 3> first{}, last{};
  for (int a = 0; a < 3; ++a)
  {
    first[std::size_t(a)] = std::max(0L, static_cast<long>(std::floor(lo[a])));
    last[std::size_t(a)] = std::min(long(ctSize[std::size_t(a)]) - 1, static_cast<long>(std::ceil(hi[a])));
    if (last[std::size_t(a)] < first[std::size_t(a)])
      throw InputError("The lumen segmentation does not overlap the CT: its lumen lies at " + Extent(*given) +
                       " and the CT spans " + Extent(ct) +
                       "; expected a segmentation of this CT (the same patient and frame).");
  }
  // Segmentation continuous index of CT index c: A c + b.
  const Eigen::Matrix3d A = seg.M.inverse() * grid.M;
  const Eigen::Vector3d b = seg.M.inverse() * (grid.origin - seg.origin);
  const itk::Size<3> segSize = given->GetLargestPossibleRegion().GetSize();
  const unsigned char* in = given->GetBufferPointer();
  unsigned char* dst = out->GetBufferPointer();
  for (long k = first[2]; k <= last[2]; ++k)
    for (long j = first[1]; j <= last[1]; ++j)
    {
      const Eigen::Vector3d row = A * Eigen::Vector3d(0.0, double(j), double(k)) + b;
      for (long i = first[0]; i <= last[0]; ++i)
      {
        const Eigen::Vector3d c = row + A.col(0) * double(i);
        long s[3];
        bool inside = true;
        for (int a = 0; a < 3 && inside; ++a)
        {
          s[a] = static_cast<long>(std::floor(c[a] + 0.5)); // ties up, as ITK's nearest neighbour
          inside = s[a] >= 0 && s[a] < long(segSize[std::size_t(a)]);
        }
        if (inside && in[s[0] + long(segSize[0]) * (s[1] + long(segSize[1]) * s[2])])
          dst[i + long(ctSize[0]) * (j + long(ctSize[1]) * k)] = 1;
      }
    }
  return out;
}

/// The mask's foreground within `box` as a MaskGrid.
MaskGrid Crop(const LabelImage& mask, const IndexBox& box)
{
  MaskGrid grid(box.size);
  const unsigned char* in = mask.GetBufferPointer();
  ForEachInBox(box, mask.GetLargestPossibleRegion().GetSize(),
               [&](long flat, long image) { grid.voxels[std::size_t(flat)] = in[image] ? 1 : 0; });
  return grid;
}

double VoxelMl(const itk::ImageBase<3>& image)
{
  const auto s = image.GetSpacing();
  return s[0] * s[1] * s[2] / 1000.0;
}

/// Keeps the piece of file comment step 2; warns about the others.
void KeepOnePiece(MaskGrid& grid,
                  const IndexBox& box,
                  const LabelImage& mask,
                  const std::optional<Point3>& seedLps,
                  LumenSegmentation& lumen)
{
  std::vector<long> sizes;
  const std::vector<int> labels = LabelComponents(grid, sizes);
  if (sizes.size() <= 1)
    return;
  int keep = 0; // label − 1
  for (std::size_t p = 1; p < sizes.size(); ++p)
    if (sizes[p] > sizes[std::size_t(keep)])
      keep = int(p);
  std::string why = "the largest";
  if (seedLps)
  {
    itk::ContinuousIndex<double, 3> c;
    mask.TransformPhysicalPointToContinuousIndex(itk::Point<double, 3>(seedLps->data()), c);
    long ijk[3];
    bool inside = true;
    for (int a = 0; a < 3 && inside; ++a)
    {
      ijk[a] = static_cast<long>(std::floor(c[a] + 0.5)) - box.first[std::size_t(a)];
      inside = ijk[a] >= 0 && ijk[a] < box.size[std::size_t(a)];
    }
    if (inside && labels[std::size_t(grid.Flat(ijk[0], ijk[1], ijk[2]))] > 0)
    {
      keep = labels[std::size_t(grid.Flat(ijk[0], ijk[1], ijk[2]))] - 1;
      why = "the one holding the seed";
    }
  }
  for (std::size_t v = 0; v < labels.size(); ++v)
    grid.voxels[v] = labels[v] == keep + 1 ? 1 : 0;
  std::vector<long> left;
  for (std::size_t p = 0; p < sizes.size(); ++p)
    if (int(p) != keep)
      left.push_back(sizes[p]);
  std::sort(left.rbegin(), left.rend());
  const double ml = VoxelMl(mask);
  double total = 0.0;
  std::string listed;
  for (std::size_t p = 0; p < left.size(); ++p)
  {
    total += double(left[p]) * ml;
    if (p < 5)
      listed += (p ? ", " : "") + FormatNumber(double(left[p]) * ml, 2) + " mL";
  }
  lumen.warnings.push_back(
    "The lumen segmentation has " + std::to_string(sizes.size()) + " separate pieces; the plan keeps " + why + " (" +
    FormatNumber(double(sizes[std::size_t(keep)]) * ml, 1) + " mL) and leaves out " + std::to_string(left.size()) +
    " (" + FormatNumber(total, 2) + " mL: " + listed + (left.size() > 5 ? ", …" : "") + ").");
}

/// A lumen voxel to pick the core's piece by (LumenCore): the seed's voxel when it is lumen, else
/// the lumen voxel nearest the centroid of the slice with the most lumen (the sac, in an AAA).
CtImage::IndexType CoreSeed(const MaskGrid& grid,
                            const IndexBox& box,
                            const CtImage& ct,
                            const std::optional<Point3>& seed)
{
  if (seed)
  {
    itk::Index<3> index;
    if (ct.TransformPhysicalPointToIndex(itk::Point<double, 3>(seed->data()), index))
    {
      long ijk[3];
      bool inside = true;
      for (int a = 0; a < 3 && inside; ++a)
      {
        ijk[a] = index[unsigned(a)] - box.first[std::size_t(a)];
        inside = ijk[a] >= 0 && ijk[a] < box.size[std::size_t(a)];
      }
      if (inside && grid.voxels[std::size_t(grid.Flat(ijk[0], ijk[1], ijk[2]))])
        return index;
    }
  }
  std::vector<long> perSlice(std::size_t(grid.size[2]), 0);
  for (long flat = 0; flat < grid.Count(); ++flat)
    perSlice[std::size_t(grid.Ijk(flat)[2])] += grid.voxels[std::size_t(flat)];
  const long k = long(std::max_element(perSlice.begin(), perSlice.end()) - perSlice.begin());
  double ci = 0.0, cj = 0.0;
  for (long j = 0; j < grid.size[1]; ++j)
    for (long i = 0; i < grid.size[0]; ++i)
      if (grid.voxels[std::size_t(grid.Flat(i, j, k))])
        ci += double(i), cj += double(j);
  ci /= double(std::max(1L, perSlice[std::size_t(k)]));
  cj /= double(std::max(1L, perSlice[std::size_t(k)]));
  double best = std::numeric_limits<double>::infinity();
  CtImage::IndexType index{ { box.first[0], box.first[1], box.first[2] + k } };
  for (long j = 0; j < grid.size[1]; ++j)
    for (long i = 0; i < grid.size[0]; ++i)
      if (grid.voxels[std::size_t(grid.Flat(i, j, k))] && (i - ci) * (i - ci) + (j - cj) * (j - cj) < best)
      {
        best = (i - ci) * (i - ci) + (j - cj) * (j - cj);
        index = { { box.first[0] + i, box.first[1] + j, box.first[2] + k } };
      }
  return index;
}

/// The window of file comment step 4.
void WindowFromCt(const MaskGrid& grid,
                  const IndexBox& box,
                  const CtImage& ct,
                  const std::optional<Point3>& seed,
                  LumenSegmentation& lumen)
{
  std::vector<short> hu(std::size_t(grid.Count()));
  const short* in = ct.GetBufferPointer();
  ForEachInBox(box, ct.GetLargestPossibleRegion().GetSize(),
               [&](long flat, long image) { hu[std::size_t(flat)] = in[image]; });
  // The interior's median and σ, for the summary (the region growing's seed statistics).
  std::vector<double> interior;
  const long steps[3] = { 1, grid.size[0], grid.size[0] * grid.size[1] };
  for (long flat = 0; flat < grid.Count(); ++flat)
  {
    if (!grid.voxels[std::size_t(flat)])
      continue;
    const auto ijk = grid.Ijk(flat);
    bool inner = true;
    for (int a = 0; a < 3 && inner; ++a)
      inner = ijk[std::size_t(a)] > 0 && ijk[std::size_t(a)] + 1 < grid.size[std::size_t(a)] &&
              grid.voxels[std::size_t(flat + steps[a])] && grid.voxels[std::size_t(flat - steps[a])];
    if (inner)
      interior.push_back(hu[std::size_t(flat)]);
  }
  if (interior.empty())
    return;
  const double m = Median(interior);
  std::vector<double> deviations(interior.size());
  for (std::size_t v = 0; v < interior.size(); ++v)
    deviations[v] = std::abs(interior[v] - m);
  lumen.seedMedianHu = m;
  lumen.seedSigmaHu = 1.4826 * Median(deviations);
  // The window: the region growing's step 1b on this lumen's core, slab by slab; where the lumen
  // has no core (small vessels only), the interior's median ± its rule.
  const lumen_growth::LumenLevels levels = lumen_growth::MeasureLumenLevels(
    ct, lumen_growth::LumenCore(ct, grid, box, CoreSeed(grid, box, ct, seed)), hu, box);
  if (levels.slabs > 0)
    lumen_growth::WindowsFromLevels(levels, RegionGrowingParams{}, lumen.lowerHu, lumen.upperHu);
  else
  {
    const double h = std::max(3.0 * lumen.seedSigmaHu, RegionGrowingParams{}.minimumHalfWindowHu);
    lumen.lowerHu = m - h;
    lumen.upperHu = m + 2.0 * h;
  }
  lumen.calciumHu = lumen.upperHu + 0.25 * (lumen.upperHu - lumen.lowerHu); // as GrowLumenRegion
}

} // namespace

LumenSegmentation LumenFromSegmentation(const LabelImage::Pointer& given,
                                        const CtImage* ct,
                                        const std::optional<Point3>& seedLps,
                                        const std::string& description)
{
  const IndexBox givenBox = ForegroundBox(*given);
  if (givenBox.Empty())
    throw InputError("The lumen segmentation " + description +
                     " holds no lumen voxel; expected a label map of the "
                     "aorta and the iliac arteries.");
  LumenSegmentation lumen;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  lumen.lowerHu = lumen.upperHu = lumen.edgeHu = lumen.calciumHu = nan;
  lumen.seedMedianHu = lumen.seedSigmaHu = lumen.tissueHu = nan;
  if (ct)
    lumen.mask = OntoCtGrid(given, givenBox, *ct);
  else
  {
    // Without a CT the given grid is the plan's, and its image the mask.
    lumen.mask = given;
    unsigned char* voxels = given->GetBufferPointer();
    ForEachInBox(givenBox, given->GetLargestPossibleRegion().GetSize(),
                 [&](long, long image) { voxels[image] = voxels[image] ? 1 : 0; });
  }
  // Padded so that every foreground voxel has neighbours in the box (the thinning's rule). Where
  // the given image is the mask its foreground box is known; only a resampled mask is scanned.
  const std::array<long, 3> pad{ 3, 3, 3 };
  const IndexBox box =
    lumen.mask == given
      ? PaddedBox(givenBox.first,
                  { givenBox.first[0] + givenBox.size[0] - 1, givenBox.first[1] + givenBox.size[1] - 1,
                    givenBox.first[2] + givenBox.size[2] - 1 },
                  pad, given->GetLargestPossibleRegion().GetSize())
      : ForegroundBox(*lumen.mask, pad);
  if (box.Empty())
    throw InputError("The lumen segmentation " + description + " lies at " + Extent(*given) +
                     " and no voxel of it falls on the CT's grid (" + Extent(*ct) +
                     "); expected a segmentation of this CT.");
  MaskGrid grid = Crop(*lumen.mask, box);
  KeepOnePiece(grid, box, *lumen.mask, seedLps, lumen);
  FillHoles(grid);
  unsigned char* out = lumen.mask->GetBufferPointer();
  ForEachInBox(box, lumen.mask->GetLargestPossibleRegion().GetSize(),
               [&](long flat, long image) { out[image] = grid.voxels[std::size_t(flat)]; });
  lumen.box = box;
  lumen.volumeMl = double(grid.CountForeground()) * VoxelMl(*lumen.mask);
  if (ct)
    WindowFromCt(grid, box, *ct, seedLps, lumen);
  lumen.windowSource = "the lumen segmentation given, " + description + " (no region growing)";
  return lumen;
}

} // namespace sgp
