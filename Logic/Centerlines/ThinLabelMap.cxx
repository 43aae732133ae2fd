#include "Centerlines/ThinLabelMap.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include "Centerlines/SimplePoint.h"
#include "Common/DistanceInsideMask.h"
#include "Common/Errors.h"
#include "Common/HugePages.h"
#include "Common/ImageGeometry.h"
#include "Common/IndexBox.h"
#include "Common/MaskGrid.h"

namespace sgp
{

namespace
{

/// The 27-bit neighbourhood of an interior voxel (the box is padded, so every foreground voxel
/// is interior).
std::uint32_t Neighbourhood(const MaskGrid& grid, long flat)
{
  const long sj = grid.size[0], sk = grid.size[0] * grid.size[1];
  std::uint32_t bits = 0;
  int bit = 0;
  for (int dk = -1; dk <= 1; ++dk)
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di, ++bit)
        if (grid.voxels[flat + di + dj * sj + dk * sk])
          bits |= 1u << bit;
  return bits;
}

/// Voxels by which the image's border layer `layer` along `axis` is repeated outward: a little
/// more than the radius of what the border cuts (half the larger in-plane extent of the layer's
/// foreground, at most 40 mm) plus two voxels, so that the closed-off end of the extension —
/// where a skeleton bends — lies a radius outside the image; 0 when nothing touches that layer.
long BorderExtension(const LabelImage& mask, const IndexBox& found, unsigned axis, long layer)
{
  const auto size = mask.GetLargestPossibleRegion().GetSize();
  const unsigned u = (axis + 1) % 3, w = (axis + 2) % 3;
  std::array<long, 3> lo{ long(size[0]), long(size[1]), long(size[2]) }, hi{ -1, -1, -1 };
  std::array<long, 3> g{};
  g[axis] = layer;
  for (g[w] = found.first[w]; g[w] < found.first[w] + found.size[w]; ++g[w])
    for (g[u] = found.first[u]; g[u] < found.first[u] + found.size[u]; ++g[u])
      if (mask.GetBufferPointer()[g[0] + long(size[0]) * (g[1] + long(size[1]) * g[2])])
        for (const unsigned a : { u, w })
          lo[a] = std::min(lo[a], g[a]), hi[a] = std::max(hi[a], g[a]);
  if (hi[u] < 0)
    return 0;
  const auto spacing = mask.GetSpacing();
  const double extentMm = std::max((hi[u] - lo[u] + 1) * spacing[u], (hi[w] - lo[w] + 1) * spacing[w]);
  return static_cast<long>(std::ceil(std::min(0.5 * extentMm, 40.0) / spacing[axis])) + 2;
}

/// One voxel of `box` per cut face the extensions carry: in the outermost repeated layer of each
/// extension, for every 8-connected piece of that layer, the voxel farthest (in-plane) from the
/// piece's rim. The thinning never removes these, so every vessel the border cuts keeps a curve
/// through the extension to its own anchor. Without them a cut vessel whose stub is short can
/// vanish: along a repeated layer the distance is constant, the voxels are taken in index order,
/// and where the axis is two voxels wide (a tie) the stub peels from its closed end in one sweep
/// (AVT D4 cut 10 mm below its bifurcation lost its right iliac that way).
std::vector<long> CutFaceAnchors(const MaskGrid& box,
                                 const std::array<long, 3>& before,
                                 const std::array<long, 3>& after,
                                 const std::array<double, 3>& spacingMm)
{
  std::vector<long> anchors;
  for (unsigned a = 0; a < 3; ++a)
    for (const bool low : { true, false })
    {
      if ((low ? before[a] : after[a]) == 0)
        continue;
      const long at = low ? 1 : box.size[a] - 2; // the box's shell is background
      const unsigned u = (a + 1) % 3, w = (a + 2) % 3;
      std::array<long, 3> layerSize = box.size;
      layerSize[a] = 1;
      MaskGrid layer(layerSize);
      const auto boxFlat = [&](long iu, long iw)
      {
        std::array<long, 3> g{};
        g[a] = at, g[u] = iu, g[w] = iw;
        return box.Flat(g[0], g[1], g[2]);
      };
      const auto layerFlat = [&](long iu, long iw)
      {
        std::array<long, 3> g{};
        g[u] = iu, g[w] = iw;
        return layer.Flat(g[0], g[1], g[2]);
      };
      for (long iw = 0; iw < box.size[w]; ++iw)
        for (long iu = 0; iu < box.size[u]; ++iu)
          layer.voxels[layerFlat(iu, iw)] = box.voxels[boxFlat(iu, iw)];
      std::array<double, 3> inPlane = spacingMm;
      inPlane[a] = 1e6; // no rim across the layer
      const DistanceField field = DistanceInsideMask(layer, inPlane);
      std::vector<bool> seen(std::size_t(layer.Count()), false);
      for (long iw = 0; iw < box.size[w]; ++iw)
        for (long iu = 0; iu < box.size[u]; ++iu)
        {
          if (!layer.voxels[layerFlat(iu, iw)] || seen[std::size_t(layerFlat(iu, iw))])
            continue;
          std::vector<std::array<long, 2>> piece{ { iu, iw } }; // 8-connected in the layer
          seen[std::size_t(layerFlat(iu, iw))] = true;
          std::array<long, 2> best = piece[0];
          for (std::size_t head = 0; head < piece.size(); ++head)
          {
            const auto [pu, pw] = piece[head];
            if (field.distanceMm[layerFlat(pu, pw)] > field.distanceMm[layerFlat(best[0], best[1])])
              best = piece[head];
            for (long dw = -1; dw <= 1; ++dw)
              for (long du = -1; du <= 1; ++du)
              {
                const long nu = pu + du, nw = pw + dw;
                if (nu < 0 || nw < 0 || nu >= box.size[u] || nw >= box.size[w])
                  continue;
                const long n = layerFlat(nu, nw);
                if (layer.voxels[n] && !seen[std::size_t(n)])
                {
                  seen[std::size_t(n)] = true;
                  piece.push_back({ nu, nw });
                }
              }
          }
          anchors.push_back(boxFlat(best[0], best[1]));
        }
    }
  return anchors;
}

} // namespace

Skeleton ThinLabelMap(const LabelImage& mask, const ProgressCallback& progress)
{
  const IndexBox found = ForegroundBox(mask);
  if (found.Empty())
  {
    throw InputError("The lumen mask is empty (no non-zero voxel); nothing to thin.");
  }
  // A vessel the image's border cuts continues beyond it: its voxels on the border layer are
  // repeated outward (BorderExtension), so that its skeleton runs on its axis to the border and
  // its radius there is its own, not the distance to the border. Closed off at the border, a cut
  // vessel thins into a curve that ends a radius short of it and bends toward the cut face's rim
  // — or, cut less than a radius above a branch, into no curve at all, and the aorta's skeleton
  // ran on into the coeliac. Then one voxel of background on every side, so that every
  // foreground voxel has a full neighbourhood inside the box.
  const auto size = mask.GetLargestPossibleRegion().GetSize();
  const auto spacing = mask.GetSpacing();
  std::array<long, 3> before{}, after{}, boxSize{}, base{};
  for (unsigned a = 0; a < 3; ++a)
  {
    before[a] = found.first[a] == 0 ? BorderExtension(mask, found, a, 0) : 0;
    after[a] = found.first[a] + found.size[a] == long(size[a]) ? BorderExtension(mask, found, a, long(size[a]) - 1) : 0;
    boxSize[a] = found.size[a] + before[a] + after[a] + 2;
    base[a] = found.first[a] - before[a] - 1; // image index of the box's voxel 0
  }
  MaskGrid box(boxSize);
  const unsigned char* data = mask.GetBufferPointer();
  for (long k = 1; k + 1 < boxSize[2]; ++k)
    for (long j = 1; j + 1 < boxSize[1]; ++j)
      for (long i = 1; i + 1 < boxSize[0]; ++i)
      {
        std::array<long, 3> g{ base[0] + i, base[1] + j, base[2] + k };
        for (unsigned a = 0; a < 3; ++a)
          g[a] = std::clamp(g[a], 0L, long(size[a]) - 1); // the extensions repeat the border layer
        box.voxels[box.Flat(i, j, k)] = data[g[0] + long(size[0]) * (g[1] + long(size[1]) * g[2])] ? 1 : 0;
      }
  ReportProgress(progress, 0.05, "Distance map");
  const std::array<double, 3> spacingMm{ spacing[0], spacing[1], spacing[2] };
  const DistanceField field = DistanceInsideMask(box, spacingMm);

  std::vector<long> order;
  for (long v = 0; v < box.Count(); ++v)
    if (box.voxels[v])
      order.push_back(v);
  std::stable_sort(order.begin(), order.end(),
                   [&](long a, long b) { return field.distanceMm[a] < field.distanceMm[b]; });

  std::vector<std::uint8_t> anchored(std::size_t(box.Count()), 0);
  for (const long v : CutFaceAnchors(box, before, after, spacingMm))
    anchored[std::size_t(v)] = 1;

  ReportProgress(progress, 0.3, "Thinning");
  for (int sweep = 0;; ++sweep)
  {
    long removed = 0;
    for (const long v : order)
    {
      if (!box.voxels[v] || anchored[std::size_t(v)])
        continue;
      const std::uint32_t n = Neighbourhood(box, v);
      if (CountNeighbours(n) != 1 && IsSimplePoint(n))
      {
        box.voxels[v] = 0;
        ++removed;
      }
    }
    ReportProgress(progress, std::min(0.9, 0.5 + 0.1 * sweep), "Thinning");
    if (removed == 0)
      break;
    order.erase(std::remove_if(order.begin(), order.end(), [&](long v) { return !box.voxels[v]; }), order.end());
  }

  // The skeleton of the extensions goes. What it leaves inside the image in pieces of its own,
  // every voxel within an extension's length of the border, is the skeleton of the extension
  // (an oblique vessel's elongated cut, repeated outward, thins into a surface whose border-layer
  // remnants are not a vessel) and goes too.
  const auto nearBorder = [&](const std::array<long, 3>& b)
  {
    for (unsigned a = 0; a < 3; ++a)
    {
      const long g = base[a] + b[a];
      if ((before[a] > 0 && g < before[a]) || (after[a] > 0 && long(size[a]) - 1 - g < after[a]))
        return true;
    }
    return false;
  };
  const auto insideImage = [&](const std::array<long, 3>& b)
  {
    for (unsigned a = 0; a < 3; ++a)
      if (base[a] + b[a] < 0 || base[a] + b[a] >= long(size[a]))
        return false;
    return true;
  };
  MaskGrid kept(box.size);
  for (const long v : order)
    kept.voxels[v] = box.voxels[v] && insideImage(box.Ijk(v)) ? 1 : 0;
  if (before != std::array<long, 3>{ 0, 0, 0 } || after != std::array<long, 3>{ 0, 0, 0 })
  {
    std::vector<bool> seen(std::size_t(kept.Count()), false);
    for (const long start : order)
    {
      if (!kept.voxels[start] || seen[std::size_t(start)])
        continue;
      std::vector<long> piece{ start }; // its 26-connected piece, breadth first
      seen[std::size_t(start)] = true;
      for (std::size_t head = 0; head < piece.size(); ++head)
      {
        const auto b = kept.Ijk(piece[head]);
        for (long dk = -1; dk <= 1; ++dk)
          for (long dj = -1; dj <= 1; ++dj)
            for (long di = -1; di <= 1; ++di)
            {
              const long n = kept.Flat(b[0] + di, b[1] + dj, b[2] + dk); // the box's shell is background
              if (kept.voxels[n] && !seen[std::size_t(n)])
              {
                seen[std::size_t(n)] = true;
                piece.push_back(n);
              }
            }
      }
      if (std::all_of(piece.begin(), piece.end(), [&](long v) { return nearBorder(kept.Ijk(v)); }))
        for (const long v : piece)
          kept.voxels[v] = 0;
    }
  }

  Skeleton skeleton;
  for (const long v : order)
  {
    if (!kept.voxels[v])
      continue;
    const auto b = box.Ijk(v);
    const itk::Index<3> index{ { base[0] + b[0], base[1] + b[1], base[2] + b[2] } };
    const auto& q = field.nearestBackground[v];
    const itk::Index<3> background{ { base[0] + q[0], base[1] + q[1], base[2] + q[2] } };
    skeleton.voxels.push_back(index);
    skeleton.pointsLps.push_back(IndexToLps(mask, index));
    skeleton.radiusMm.push_back(field.distanceMm[v]);
    skeleton.nearestBackgroundLps.push_back(IndexToLps(mask, background));
  }
  ReportProgress(progress, 1.0, "Done");
  return skeleton;
}

LabelImage::Pointer SkeletonToImage(const Skeleton& skeleton, const LabelImage& reference)
{
  auto image = LabelImage::New();
  image->CopyInformation(&reference);
  image->SetRegions(reference.GetLargestPossibleRegion());
  AllocateAdvised(*image, true);
  for (const auto& index : skeleton.voxels)
    image->SetPixel(index, 1);
  return image;
}

} // namespace sgp
