/// \file ThinLabelMap.h
/// Reduces a lumen mask to its curve skeleton: one voxel thick, 26-connected, homotopic to the
/// mask, inside it, and centred, with the inscribed-sphere radius at every skeleton voxel.
///
/// Egger et al. (2007), section 2: "a skeleton algorithm determines the three vessel centerlines
/// ... by iterative erosion of the segmentation mask". We erode the mask one *simple point* at a
/// time (a voxel whose removal changes no connected component, cavity or tunnel; see
/// SimplePoint.h), as Lee, Kashyap and Chu (1994, "Building skeleton models via 3-D medial
/// surface/axis thinning algorithms", CVGIP 56) do, but in order of increasing Euclidean distance
/// to the background in mm (distance-ordered homotopic thinning, after C. Pudney, "Distance-ordered
/// homotopic thinning", CVIU 72, 1998) instead of by directional sub-iterations over index layers.
/// The order makes the skeleton centred on anisotropic voxels (2–3 mm slices), where peeling one
/// index layer removes 0.7 mm in-plane but 3 mm along z. Voxels with exactly one neighbour (curve
/// ends) are kept, so every vessel keeps its skeleton up to its end. Sweeps repeat until none
/// removes a voxel.
///
/// Input: any non-zero voxel of `mask` is foreground (any grid; spacing honoured). The work is
/// done in the mask's bounding box. Where the foreground touches the image's border, the border
/// layer is repeated outward by a little more than the radius it cuts, and the skeleton found
/// there dropped: a vessel the scan cuts keeps its skeleton on its axis up to the border (its
/// end voxel lies on the border layer) with its own radius, instead of a closed-off end that
/// thins a radius short of the border, bent toward the rim of the cut. Each piece of a cut face
/// anchors the skeleton at its in-plane centre in the extension's outermost layer (never removed),
/// so that no cut vessel's curve can peel away, however short its stub inside the image. Output: skeleton voxels (image index and LPS mm)
/// with the radius in mm — the distance to the nearest background voxel centre — and that background voxel's centre
/// (AssignInscribedRadii uses it to measure radii off the voxel grid).
///
/// Guarantees: skeleton ⊂ mask; every skeleton voxel is non-simple or a curve end (so no 2×2×2
/// block survives in practice, which the tests check); same number of 26-connected components
/// as the mask. Short spurs from surface noise remain: SkeletonGraph prunes them.
/// Errors: InputError when the mask is empty.
/// Complexity: O(n log n) for n foreground voxels (distance ordering), times the sweeps (2–4).
#pragma once

#include <vector>

#include "Common/Types.h"

namespace sgp
{

struct Skeleton
{
  std::vector<itk::Index<3>> voxels;        ///< in the mask's index space
  std::vector<Point3> pointsLps;            ///< voxel centres, LPS mm
  std::vector<double> radiusMm;             ///< inscribed-sphere radius at each voxel, mm
  std::vector<Point3> nearestBackgroundLps; ///< centre of the nearest background voxel, LPS mm
};

Skeleton ThinLabelMap(const LabelImage& mask, const ProgressCallback& progress = {});

/// A label image on `reference`'s grid with 1 at the skeleton's voxels.
LabelImage::Pointer SkeletonToImage(const Skeleton& skeleton, const LabelImage& reference);

} // namespace sgp
