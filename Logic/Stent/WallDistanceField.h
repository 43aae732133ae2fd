/// \file WallDistanceField.h
/// The vessel wall as a field for the active contour's external force: φ, the signed distance in
/// mm to the lumen boundary, negative inside, with its gradient, by trilinear interpolation.
///
/// φ is sampled at voxel centres in the lumen's bounding box plus `bandMm`: inside the lumen
/// −(distance to the nearest background voxel centre) + h/2, outside +(distance to the nearest
/// lumen voxel centre) − h/2, h the voxel's extent toward that nearest voxel. Between a lumen and
/// a background neighbour, φ is then ∓h/2 and its interpolated zero lies midway: on the boundary
/// the half-maximum segmentation placed. The force of Egger et al. (2007), equation 3, uses
/// D = max(φ, 0), "0 inside, the distance outside"; its gradient is ∇φ outside and 0 inside.
/// Deeper than the band inside the lumen φ is −`bandMm`; beyond it outside, `bandMm` with gradient 0
/// (only the shell around the wall is computed: the forces act there).
///
/// The field may be limited to a region — balls around the places a surface can reach (the
/// stent's rings, StentReach in StentMesh.h): then the box is the bounding box of the lumen voxels
/// inside those balls (plus the band), which on a whole aorto-iliac tree is a few times smaller
/// than the lumen's. Where the lumen crosses that box's faces the face acts as a wall for φ
/// inside, so the balls must reach well past (≥ band + 2 voxels) anywhere a vertex can go.
///
/// Input: a lumen LabelImage (non-zero = lumen; any grid; spacing and direction honoured);
/// optionally the region, balls in LPS mm.
/// Errors: InputError for an empty mask (or no lumen voxel in the region) or a band outside
/// [1, 100] mm.
#pragma once

#include <optional>
#include <vector>

#include "Common/Types.h"

namespace sgp
{

class WallDistanceField
{
public:
  static WallDistanceField FromLumen(const LabelImage& lumen, double bandMm = 5.0);
  /// The field over the lumen within `region` only (see above); an empty region means the whole lumen.
  static WallDistanceField FromLumen(const LabelImage& lumen, double bandMm, const std::vector<Ball>& region);

  /// φ at `lps` (mm); writes ∇φ (LPS, dimensionless) to `gradient` when it is given.
  double Sample(const Point3& lps, Eigen::Vector3d* gradient = nullptr) const;

  /// Whether this field answers for FromLumen(lumen, bandMm, region): the same lumen (the caller's
  /// promise: the mask this field was made from), the same band, and the lumen voxels within
  /// `region` inside the box of lumen voxels this field was built around. Then φ is the same
  /// distance over the same voxels, its box only larger (cutting the lumen no closer to the
  /// region). One pass over the lumen's box; no distance is computed.
  bool Covers(const LabelImage& lumen, double bandMm, const std::vector<Ball>& region) const;

  /// `shared` when it Covers(lumen, bandMm, region), else FromLumen(lumen, bandMm, region) made into
  /// `own` (which the returned reference then points to; `own` must outlive its use).
  static const WallDistanceField& SharedOrOwn(const WallDistanceField& shared,
                                              const LabelImage& lumen,
                                              double bandMm,
                                              const std::vector<Ball>& region,
                                              std::optional<WallDistanceField>& own);

private:
  std::array<long, 3> m_Size{};
  std::vector<float> m_Phi;                                   ///< m_Size[0]·m_Size[1]·m_Size[2], i fastest
  Point3 m_Origin = Point3::Zero();                           ///< LPS of box voxel (0, 0, 0)
  Eigen::Matrix3d m_IndexToLps = Eigen::Matrix3d::Identity(); ///< direction · diag(spacing)
  Eigen::Matrix3d m_LpsToIndex = Eigen::Matrix3d::Identity();
  double m_Band = 5.0;
  std::array<long, 3> m_FoundFirst{}; ///< the lumen voxels' box it was built around (image index), before the band
  std::array<long, 3> m_FoundSize{};
};

} // namespace sgp
