/// \file AssignInscribedRadii.h
/// Measures the inscribed-sphere radius at every point of smoothed centerlines.
///
/// A smoothed centerline runs between voxel centres, so the radius is not read at a voxel: for
/// each point p it is the distance from p to the nearest background voxel centre among those
/// that are nearest to the skeleton voxels within `searchMm` of p. Each candidate is a background
/// voxel, so the estimate never undercuts the true distance, and the nearest one around the
/// centerline is among them. Where the skeleton voxel itself lies off the axis (half a voxel on
/// a staircase), this removes the bias that reading the radius at the voxel would carry.
///
/// Input: the tree (LPS mm) and the Skeleton it came from. Output: the tree's radii replaced;
/// points with no skeleton voxel within `searchMm` keep theirs.
/// Complexity: O(points × skeleton voxels within the z-band of searchMm).
#pragma once

#include "Centerlines/Centerlines.h"
#include "Centerlines/ThinLabelMap.h"

namespace sgp
{

void AssignInscribedRadii(CenterlineTree& tree, const Skeleton& skeleton, double searchMm = 3.0);

} // namespace sgp
