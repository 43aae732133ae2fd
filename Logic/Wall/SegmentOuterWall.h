/// \file SegmentOuterWall.h
/// The outer wall of a vessel (aorta or common iliac) around its lumen, plane by plane along the
/// lumen's centerline: the radial-model approach of Macía et al. (IDEAL 2009; vessel-wall.md §1),
/// rays from the lumen centre, a boundary candidate on each, and a robust model fitted to the
/// candidates that stands in where a sector shows no boundary.
///
/// Per plane (every `stepMm` of arc length, ⊥ the centerline's tangent):
///  1. `rays` rays from the centerline point, evenly spaced; HU sampled trilinearly every
///     `sampleMm` from the lumen's edge (the first sample outside the lumen mask) out to
///     `maxRadiusMm`.
///  2. The plane's two levels: the vessel's (median HU `insideMm` beyond the lumen's edge: wall
///     or thrombus) and the fat's (median of the samples below `fatBelowHu`); the boundary
///     threshold is their mean — the half-maximum of the wall-to-fat edge, as the lumen's boundary
///     is the half-maximum of lumen-to-tissue.
///  3. Candidate on each ray: the first crossing of the threshold downward at least
///     `minimumWallMm` beyond the lumen's edge (linear between samples), where fat follows within
///     `fatSupportMm` — a visible outer boundary.
///  4. A circle fitted to the candidates (least squares, Kåsa), then repeatedly refitted without
///     the candidates more than `outlierMm` outside it: a neighbour that touches the vessel
///     without a fat plane (psoas, IVC, duodenum, a vein) moves the first fat edge outward, never
///     inward, so the outliers are those beyond the circle; the rays beside an outlier sector go
///     too (they still see the neighbour's blurred edge), and the circle is fitted once more. The
///     candidates kept are *supported*; on every other ray the boundary is the circle's.
/// The plane records the share of its rays that were supported; with fewer than
/// `minimumSupport` the whole plane is the fitted circle's and is flagged.
///
/// Input: the CT in HU and the lumen mask on one grid (LPS), the vessel's centerline (LPS mm),
/// the stretch [fromMm, toMm] of its abscissa. Output: per plane, the outer contour (`rays` points,
/// LPS mm), its area-equivalent and largest caliper diameters (mm), the supported share.
/// Errors: InputError for parameters out of range, grids that differ, or a centerline shorter
/// than two points.
#pragma once

#include <vector>

#include "Centerlines/Centerlines.h"
#include "Common/Types.h"

namespace sgp
{

struct OuterWallParams
{
  double stepMm = 1.0;          ///< plane spacing along the centerline, (0, 20]
  int rays = 72;                ///< rays per plane, [16, 360]
  double sampleMm = 0.25;       ///< along a ray, (0, 2]
  double maxRadiusMm = 45.0;    ///< how far a ray reaches beyond the centerline, (5, 100]
  double insideMm = 1.0;        ///< where the wall/thrombus level is read beyond the lumen's edge
  double fatBelowHu = -30.0;    ///< adipose tissue lies below (vessel-wall.md: −190 … −30 HU)
  double minimumWallMm = 0.5;   ///< the boundary lies at least this far beyond the lumen's edge
  double fatSupportMm = 3.0;    ///< fat must follow the boundary within this
  double outlierMm = 1.0;       ///< candidates this far outside the fitted circle are not the wall
  double minimumSupport = 0.25; ///< below this share of supported rays the plane is flagged
};

struct OuterWallPlane
{
  double abscissaMm = 0.0;
  Point3 centreLps = Point3::Zero(); ///< the centerline point
  Points contourLps;                 ///< rays × 3
  std::vector<bool> supported;       ///< per ray
  Eigen::VectorXd lumenRadiusMm;     ///< per ray, from the centre to the lumen's edge
  Eigen::VectorXd outerRadiusMm;     ///< per ray, from the centre to the outer wall
  double supportedFraction = 0.0;
  double areaDiameterMm = 0.0; ///< of the contour polygon
  double maxCaliperMm = 0.0;   ///< largest distance between two contour points
  bool flagged = false;        ///< fewer supported rays than minimumSupport
};

struct OuterWall
{
  std::vector<OuterWallPlane> planes;
  /// The plane nearest abscissa s (nullptr when there is none).
  const OuterWallPlane* Nearest(double s) const;
};

void ValidateOuterWallParams(const OuterWallParams& params);

/// See the file comment.
OuterWall SegmentOuterWall(const CtImage& ct,
                           const LabelImage& lumen,
                           const Centerline& vessel,
                           double fromMm,
                           double toMm,
                           const OuterWallParams& params = {});

} // namespace sgp
