/// \file MeasureDiameters.h
/// Diameters of the fitted stent surface's rings — the cross-sections perpendicular to the
/// centerline on which Egger et al. (2007, section 2.2) read the sizing diameters.
///
/// For a ring of n vertices (n even) in j order: the n/2 diameters |V_j − V_{j+n/2}| give the
/// **mean** (the reported value), **min** and **max**; the **area-equivalent** diameter is
/// 2·√(A/π), A the area of the ring polygon projected on the ring's plane (⊥ its centerline
/// tangent). On a circle of radius r the diameters are exactly 2r, while the area of an inscribed
/// n-gon is (n/2π)·sin(2π/n) of the disc's (−1.3 % in diameter for n = 16).
///
/// **Branch mouths.** A ring at a side branch's ostium (the ring at the proximal site lies at the
/// lowest renal's lower edge by definition) has vertices that the balloon pushed into the branch:
/// a vertex more than `BranchMouthRadiusFactor` × the ring's median vertex radius from its
/// centerline point is *in a branch mouth*. The diameters through such a vertex are left out of
/// mean, min and max, and for the area the vertex counts at the median radius; `mouthVertices`
/// says how many there were (0 on a ring that meets no branch).
///
/// Input: the StentMesh (rings, ring abscissae, axes) and the surface V (#V×3, LPS mm), usually
/// the active contour's result. Output: one profile per segment, rings in order, mm.
/// Errors: InputError when V's row count differs from the mesh's.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "Stent/StentMesh.h"

namespace sgp
{

struct RingDiameters
{
  double abscissaMm = 0.0;        ///< along the segment's centerline (aorta from its top, iliac from the bifurcation)
  double meanMm = 0.0;            ///< mean of the n/2 vertex-to-opposite-vertex diameters
  double minMm = 0.0;             ///< smallest of them
  double maxMm = 0.0;             ///< largest of them
  double areaMm = 0.0;            ///< area-equivalent diameter of the ring polygon
  Point3 centre = Point3::Zero(); ///< the ring's centerline point, LPS mm
  int mouthVertices = 0;          ///< vertices in a branch mouth, left out (the file comment)
};

/// A vertex beyond this multiple of its ring's median radius lies in a branch mouth. A vessel's own
/// shape stays well below it: an ellipse of aspect 1.5 reaches 1.2 × its median radius, a
/// centerline 5 mm off-centre in a 66 mm sac 1.15 ×; a renal mouth on a neck reaches about 2 ×.
constexpr double BranchMouthRadiusFactor = 1.3;

struct DiameterProfile
{
  std::string vessel; ///< aorta, rightIliac or leftIliac
  std::vector<RingDiameters> rings;
  /// The ring values interpolated linearly in abscissa at `s` (clamped to the first/last ring);
  /// `mouthVertices` is the larger of the two rings'.
  RingDiameters At(double s) const;
};

/// Profiles of the trunk (aorta), the right leg (rightIliac) and the left leg (leftIliac), in
/// StentSegment order.
std::array<DiameterProfile, 3> MeasureRingDiameters(const StentMesh& mesh, const Points& V);

} // namespace sgp
