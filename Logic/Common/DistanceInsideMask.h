/// \file DistanceInsideMask.h
/// Euclidean distance, in mm, from every foreground voxel of a mask box to the nearest background
/// voxel centre, honouring anisotropic spacing.
///
/// Exact: separable passes along i, j and k, each the lower envelope of parabolas on a line
/// (Felzenszwalb & Huttenlocher, Theory of Computing 8, 2012), carrying each voxel's nearest site
/// (the feature transform of Maurer, Qi & Raghavan, IEEE PAMI 25, 2003). Linear in the box's
/// voxels, on two cores (TwoCores.h; the result is the same as one core's); 4 + 12 bytes per voxel
/// plus a line of scratch per core. When `outsideIsBackground`, the
/// one-voxel shell around the box is background too (its sites may lie just outside the box).
///
/// Input: `mask` (MaskGrid, 0/1), `spacingMm` (the i, j, k spacing). Output, per voxel of the box:
/// the distance (0 for background, at least the smallest spacing for foreground) and the box
/// index (i, j, k) of the nearest background voxel (which may lie just outside the box).
#pragma once

#include <array>
#include <vector>

#include "Common/MaskGrid.h"

namespace sgp
{

struct DistanceField
{
  std::vector<float> distanceMm;
  std::vector<std::array<int, 3>> nearestBackground;
};

/// \param outsideIsBackground  whether voxels outside the box count as background (sites)
/// \param maximumDistanceMm    distances are clipped to it (also a foreground without any site)
DistanceField DistanceInsideMask(const MaskGrid& mask,
                                 const std::array<double, 3>& spacingMm,
                                 bool outsideIsBackground = true,
                                 float maximumDistanceMm = 1e30f);

} // namespace sgp
