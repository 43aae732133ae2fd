/// \file Centerlines.h
/// The vessel centerlines of the aorto-iliac tree (STYLE.md B2: CenterlineTree).
///
/// Every point is LPS mm; "right" and "left" are the patient's (right = −x in LPS).
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "Common/Types.h"

namespace sgp
{

/// One vessel's centerline, from its start (the proximal end, or the branching point) on.
struct Centerline
{
  std::string name;           ///< aorta, rightIliac, leftIliac, rightRenal, …
  Points points;              ///< n×3, LPS mm
  Eigen::VectorXd radiusMm;   ///< n, inscribed-sphere radius, mm
  Eigen::VectorXd abscissaMm; ///< n, arc length from the first point, mm
  /// A side branch of the aorta: why it has its name (or none) — the side it leaves from, its
  /// course, calibre and height, and the rule (LabelAortoIliacTree.h, step 4); else empty.
  std::string evidence;
  /// A renal artery: the distance from its fitted axis at its mouth to its upstream and its
  /// downstream wall (along the parent's direction), measured on the CT (MeasureRenalMouthWalls,
  /// ProximalSite.h), mm; NaN: not measured, and its ostium's edges use its inscribed radius.
  std::array<double, 2> mouthWallMm{ std::numeric_limits<double>::quiet_NaN(),
                                     std::numeric_limits<double>::quiet_NaN() };
  /// The walls were read on the CT but put the ostium's edges within half a voxel of the inscribed
  /// radius's, which stands (mouthWallMm NaN): by how much they differ, mm; NaN: not read.
  double mouthEdgeAgreementMm = std::numeric_limits<double>::quiet_NaN();

  Eigen::Index Size() const { return points.rows(); }
  double LengthMm() const { return Size() ? abscissaMm[Size() - 1] : 0.0; }
};

/// A named point: a bifurcation or an ostium on a centerline.
struct Landmark
{
  std::string name;
  Point3 lps;
};

/// The labelled Y and its side branches.
///  - aorta: from its top in the volume down to the aortic bifurcation;
///  - rightIliac, leftIliac: from the aortic bifurcation through the common and external iliac
///    arteries to their distal ends;
///  - side branches: rightRenal, leftRenal, superiorMesenteric, coeliac, rightInternalIliac,
///    leftInternalIliac, ascendingAorta, and numbered others (aorticBranch1, rightIliacBranch1, …);
///  - landmarks: aorticBifurcation, rightIliacBifurcation, leftIliacBifurcation (internal iliac
///    origins), rightRenalOstium, leftRenalOstium, superiorMesentericOstium, coeliacOstium — each
///    the branching point on the parent vessel's centerline.
struct CenterlineTree
{
  Centerline aorta;
  Centerline rightIliac;
  Centerline leftIliac;
  std::vector<Centerline> sideBranches;
  std::vector<Landmark> landmarks;
  /// Per iliac (0 right, 1 left): how many mm of it the scan holds below the aortic bifurcation
  /// (where the axes meet; LabelAortoIliacTree.h) when the scan's inferior border cuts it before it can be followed as
  /// a whole (a partial Y, LabelAortoIliacTree.h): the values that need more of it are not measured. NaN: whole.
  std::array<double, 2> iliacCoverageMm{ std::numeric_limits<double>::quiet_NaN(),
                                         std::numeric_limits<double>::quiet_NaN() };
  /// The scan's extent along LPS z (its voxel centres' lowest and highest z, mm); NaN: not known.
  double scanLowestZMm = std::numeric_limits<double>::quiet_NaN();
  double scanHighestZMm = std::numeric_limits<double>::quiet_NaN();
  /// The scan's coarsest voxel spacing, mm; NaN: not known.
  double largestSpacingMm = std::numeric_limits<double>::quiet_NaN();
  /// Landmarks a person gave (GivenLandmarks.h), which replace the ones found: the aortic
  /// bifurcation (LPS mm; unset: found) and each internal iliac origin as an abscissa along its
  /// iliac (right, left; mm; NaN: found).
  std::optional<Point3> givenBifurcationLps;
  std::array<double, 2> givenInternalIliacAbscissaMm{ std::numeric_limits<double>::quiet_NaN(),
                                                      std::numeric_limits<double>::quiet_NaN() };
  /// The scan cuts an iliac short: the plan is partial.
  bool Partial() const { return std::isfinite(iliacCoverageMm[0]) || std::isfinite(iliacCoverageMm[1]); }

  /// The vessel called `name` (main or side branch), or nullptr.
  const Centerline* FindVessel(const std::string& name) const;
  /// The landmark called `name`, or nullptr.
  const Landmark* FindLandmark(const std::string& name) const;
};

/// The point at arc length `s` along the centerline (linear between its points; clamped to its
/// ends). Needs at least two points.
Point3 PositionAt(const Centerline& c, double s);

/// Arc length of the point of `c` nearest to `p` (projected onto the nearest segment), mm; and
/// the distance from `p` to it through `distanceMm` when given. Needs at least two points.
double ProjectOntoCenterline(const Centerline& c, const Point3& p, double* distanceMm = nullptr);

/// The unit tangent of `c` at arc length `s` (downstream; the segment containing s).
Eigen::Vector3d TangentAt(const Centerline& c, double s);

/// The centerline's inscribed radius at arc length `s` (linear between points; clamped), mm.
double RadiusAt(const Centerline& c, double s);

/// Builds a Centerline from points (n×3) and radii, computing the abscissa.
Centerline MakeCenterline(const std::string& name, const std::vector<Point3>& points, const std::vector<double>& radii);

} // namespace sgp
