/// \file SegmentOuterWall.h
/// The outer wall of a vessel (aorta or common iliac) around its lumen, plane by plane along the
/// lumen's centerline: the radial-model approach of Macía et al. (IDEAL 2009; vessel-wall.md §1),
/// rays from the lumen centre, a boundary candidate on each, and a robust model fitted to the
/// candidates that stands in where a sector shows no boundary.
///
/// Per plane (every `stepMm` of arc length, ⊥ the centerline's tangent — or, given an `axis`, ⊥
/// that axis's tangent where the centerline point projects onto it: an eccentric thrombus tilts
/// the lumen's centerline off the vessel's axis, and a plane ⊥ the lumen then cuts the outer wall
/// obliquely, its area larger by 1/cos θ):
///  1. `rays` rays from the centerline point, evenly spaced; HU sampled trilinearly every
///     `sampleMm` from the lumen's edge (the first sample outside the lumen mask) out to
///     `maxRadiusMm`.
///  2. The plane's two levels: the vessel's (median HU `insideMm` beyond the lumen's edge: wall
///     or thrombus; at least `layerHu`) and the fat's (median of the samples below `fatBelowHu`);
///     the boundary threshold is their mean — the half-maximum of the wall-to-fat edge, as the lumen's boundary
///     is the half-maximum of lumen-to-tissue.
///  3. Candidate on each ray: the first crossing of the threshold downward at least
///     `minimumWallMm` beyond the lumen's edge (linear between samples), where fat follows within
///     `fatSupportMm` — a visible outer boundary. On a ray with calcium (a sample ≥ `calciumHu`
///     from 1 mm inside the lumen's edge to the first fat) the crossing is of the ray's own
///     half-maximum between its peak and the fat, beyond the peak: calcium anchors the wall.
///  4. A circle fitted to the candidates of the thinner half of the rays (candidate − lumen
///     radius at most its median: a neighbour that touches the vessel without a fat plane —
///     psoas, IVC, duodenum, a vein — moves the first fat edge outward by its own thickness,
///     never inward), least squares (Kåsa), then repeatedly refitted without the candidates more
///     than `outlierMm` outside it; then every candidate is judged against that circle (kept when
///     at most `outlierMm` outside) and the circle refitted. The rays beside an unsupported sector
///     go too (they still see the neighbour's blurred edge), and the circle is fitted once more.
///  5. Where a neighbour hides an arc (`hiddenArcShare` of the rays without a candidate or with
///     one more than `hiddenBeyondMm` outside the circle), an ellipse (the algebraic conic through
///     the kept candidates, the lumen's centre inside) grown from the circle's kept candidates —
///     or, given an `axis` and nothing hidden, where the circle keeps under `circleMinimumShare`
///     of the candidates (an elliptical sac in fat: only the arcs about its minor axis lie within
///     `outlierMm` of the best circle), grown from all of them: refitted with every candidate at
///     most `outlierMm` outside it, until the kept set holds. It completes the plane instead of
///     the circle when it explains the candidates better (Bayesian information criterion), keeps
///     at least as many, at least `ellipseMinimumSupport` of the rays, with its axes' ratio at
///     most `maxAxisRatio` — the circle completing an elliptical sac's hidden arc under-reads Dmax
///     by up to the axes' difference.
///     The candidates kept are *supported*; on every other ray the boundary is the model's
///     (circle or ellipse).
/// The plane records the share of its rays that were supported; with fewer than
/// `minimumSupport` it is flagged, and takes the contours of the traced planes above and below,
/// ray by ray, when they are at most `interpolateWithinMm` apart (`interpolated`; otherwise, or
/// without one on each side: no contour — never extrapolated).
/// A ray's outer radius is never inside the lumen — except where the lumen runs out along a
/// branch, which counts only up to the fitted circle.
///
/// Input: the CT in HU and the lumen mask on one grid (LPS), the vessel's centerline (LPS mm),
/// the stretch [fromMm, toMm] of its abscissa. Output: per plane, the outer contour (`rays` points,
/// LPS mm), its area-equivalent and largest caliper diameters (mm), the supported share.
/// The contour's radii are then averaged over 2·smoothRays + 1 neighbouring rays, never inside the
/// lumen; the contour's calipers come from 180 directions.
///
/// The CT may be a crop of the lumen's grid (any buffered region; HU beyond it is the nearest
/// edge voxel's).
/// Errors: InputError for parameters out of range or a centerline shorter than two points.
#pragma once

#include <array>
#include <limits>
#include <vector>

#include "Centerlines/Centerlines.h"
#include "Common/Types.h"

namespace sgp
{

struct OuterWallParams
{
  double stepMm = 1.0;       ///< plane spacing along the centerline, (0, 20]
  int rays = 72;             ///< rays per plane, [16, 360]
  double sampleMm = 0.25;    ///< along a ray, (0, 2]
  double maxRadiusMm = 45.0; ///< how far a ray reaches beyond the centerline, (5, 100]
  double insideMm = 1.0;     ///< where the wall/thrombus level is read beyond the lumen's edge
  double fatBelowHu = -30.0; ///< adipose tissue lies below (vessel-wall.md: −190 … −30 HU)
  /// The vessel layer's level is at least this (vessel-wall.md §2: wall 60–90 HU, thrombus 30–60):
  /// a 1.5 mm wall under a 0.5 mm blur reads 20 HU a millimetre beyond the lumen, which would put
  /// the half-maximum 0.4 mm outside the wall. Once the lumen's tail is taken off (RemoveLumenTail)
  /// a wall of 1–2 mm never shows its plateau, so this is the wall's level at the outer edge: each
  /// 10 HU it lies below the real wall's moves the edge 0.07 mm outward (σ 1 mm, fat −100 HU).
  double layerHu = 60.0;
  /// The lumen's edge is half-way between the lumen and this level (the lumen segmentation's
  /// border floor, GrowLumenRegion.h): the mirror of the lumen's blurred step is centred there
  /// (RemoveLumenTail in SegmentOuterWall.cxx). Between the lumen's and the layer's level halves,
  /// the fat's tail inside a thin wall lowers the real edge's value by (wall − fat)·Φ(−w/σ),
  /// 11 HU for 1.5 mm and σ 1 mm, and a mirror centred 0.1 mm too deep under-reads the tail.
  double lumenBorderHu = 40.0;
  double minimumWallMm = 0.5;   ///< the boundary lies at least this far beyond the lumen's edge
  double fatSupportMm = 3.0;    ///< fat must follow the boundary within this
  double outlierMm = 1.0;       ///< candidates this far outside the fitted circle are not the wall
  double minimumSupport = 0.25; ///< below this share of supported rays the plane is flagged
  int smoothRays = 2;           ///< the contour's radii averaged over 2·smoothRays + 1 rays, [0, rays/4]
  /// A flagged plane takes the contours of the traced planes above and below when they are at most
  /// this far apart, [0, 100] mm.
  double interpolateWithinMm = 20.0;
  /// HU at or above which a sample between the lumen's edge and the outer wall (+0.5 mm) is
  /// calcium; +∞: none is looked for.
  double calciumHu = std::numeric_limits<double>::infinity();
  /// The ellipse stands in for the circle only with at least this share of the rays kept: five
  /// parameters extrapolated over more than 40 % of the circumference are a guess; [0.3, 1].
  double ellipseMinimumSupport = 0.6;
  double maxAxisRatio = 1.5; ///< the most elliptical outer wall taken, major / minor; [1, 3]
  /// A plane has a hidden arc (the ellipse is tried) when this share of its rays has no candidate
  /// or one more than `hiddenBeyondMm` outside the circle — a neighbour without a fat plane; [0, 1].
  double hiddenArcShare = 0.1;
  double hiddenBeyondMm = 5.0;
  /// Given an axis and no hidden arc, the ellipse is tried too where the circle keeps under this
  /// share of the candidates — an elliptical sac in fat, its major ends outside the circle; [0, 1],
  /// 0: never.
  double circleMinimumShare = 0.6;
};

struct OuterWallPlane
{
  double abscissaMm = 0.0;           ///< along the lumen's centerline
  double axisAbscissaMm = 0.0;       ///< along the plane-orienting axis (the lumen's centerline without one)
  Point3 centreLps = Point3::Zero(); ///< the centerline point
  Points contourLps;                 ///< rays × 3
  std::vector<bool> supported;       ///< per ray
  Eigen::VectorXd lumenRadiusMm;     ///< per ray, from the centre to the lumen's edge
  Eigen::VectorXd outerRadiusMm;     ///< per ray, from the centre to the outer wall (smoothed, ≥ the lumen's)
  std::vector<bool> calcified;       ///< per ray: calcium between the lumen and the outer wall
  Eigen::VectorXd thrombusMm;        ///< per ray, thrombus thickness (set by TraceVesselWall; empty here)
  Eigen::Vector3d uLps = Eigen::Vector3d::UnitX(),
                  vLps = Eigen::Vector3d::UnitY(); ///< the plane's axes (ray 0 along u)
  double supportedFraction = 0.0;
  double areaMm2 = 0.0; ///< inside the outer contour
  /// The contour's area centroid (LPS mm): the vessel's centre in this plane. Not the mean of the
  /// contour's points: the rays leave from the lumen's centre, which an eccentric thrombus moves
  /// off the vessel's axis, and their ends crowd on the near side (3.8 mm toward the lumen in a
  /// 62 mm sac with a 15 mm crescent).
  Point3 centroidLps = Point3::Zero();
  double lumenAreaMm2 = 0.0;   ///< inside the lumen's edge along the rays
  double areaDiameterMm = 0.0; ///< of the contour polygon, 2·√(area/π)
  double minCaliperMm = 0.0;   ///< smallest width of the contour (over 180 directions)
  double maxCaliperMm = 0.0;   ///< largest width of the contour (its maximum caliper)
  /// The rays at the two ends of the largest width (their contour points touch its two tangents).
  std::array<int, 2> maxCaliperRays{ 0, 0 };
  bool elliptical = false;   ///< the model standing in on unsupported rays was the ellipse
  bool flagged = false;      ///< fewer supported rays than minimumSupport: not traced in this plane
  bool interpolated = false; ///< flagged, its contour from the traced planes above and below
  /// Has a contour: traced, or interpolated between traced planes.
  bool Usable() const { return !flagged || interpolated; }
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
                           const OuterWallParams& params = {},
                           const Centerline* axis = nullptr);

/// The outer radius of a plane with a contour along the in-plane direction of `d` (LPS, unit;
/// projected on the plane; linear between rays), mm.
double OuterRadiusToward(const OuterWallPlane& plane, const Eigen::Vector3d& d);

/// The vessel's axis through the outer contours, one point per plane (flagged ones too): the
/// smoothing spline (Whittaker: weighted squares plus λ·second differences, λ = (halfWindowMm /
/// step)⁴, about ±halfWindowMm of smoothing) through the traced planes' area centroids, twice: all
/// weighing alike, then each weighing by how far its plane's tilt off that first axis can have
/// moved it — 1 / (1 + (k·R·tan θ / 0.5 mm)²), k the change of the area radius R per mm: across a
/// sac's shoulders, where the lumen's centerline leans through an eccentric crescent, the axis
/// runs on from the necks and the sac's middle. Empty (no points) with fewer than two traced planes.
Centerline OuterWallAxis(const OuterWall& wall, const std::string& name, double halfWindowMm);

} // namespace sgp
