/// \file DistanceInsideMask.h
/// Euclidean distance, in mm, from every foreground voxel of a mask box to the nearest background
/// voxel centre, honouring anisotropic spacing.
///
/// Computed by propagating, from the background voxels next to the foreground, the position of
/// the nearest background voxel through 26-neighbours in order of increasing distance (Danielsson
/// 1980; O. Cuisenaire and B. Macq, "Fast Euclidean distance transformation by propagation using
/// multiple neighborhoods", CVIU 76, 1999). Only foreground voxels are visited, so the cost is
/// O(n log n) in the foreground's size rather than in the box's; the propagated distance is exact
/// except in rare configurations where it exceeds the true one by a small fraction of a voxel.
/// Voxels outside the box count as background, so the box should be padded by one voxel.
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
/// \param maximumDistanceMm    propagation stops beyond it; farther voxels get this value
DistanceField DistanceInsideMask(const MaskGrid& mask,
                                 const std::array<double, 3>& spacingMm,
                                 bool outsideIsBackground = true,
                                 float maximumDistanceMm = 1e30f);

} // namespace sgp
