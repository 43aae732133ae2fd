/// \file StentMesh.h
/// The initial bifurcated stent surface: a trunk along the aorta, two legs along the iliacs, and
/// the connection element that joins them (Egger et al. 2007, section 2 and figure 2).
///
/// Each segment is a tube of rings perpendicular to its centerline, `verticesPerRing` vertices a
/// ring (a multiple of 4), rings `ringSpacingMm` apart, at `startRadiusMm` from the centerline.
/// Ring frames are rotation-minimizing (double reflection, W. Wang et al., ACM TOG 27, 2008), so
/// the surface has no twist. Vertex j of a ring sits at angle θ = 2πj/n from the frame's u axis
/// toward its v axis; all three segments use the same convention at the junction: u toward the
/// patient's left for the trunk and toward the other leg (medial) for each leg, v anterior. So
/// j = n/4 is anterior, j = 3n/4 posterior, j = n/2 the right side of the trunk and the lateral
/// side of each leg.
///
/// The trunk runs from `proximalAbscissaMm` along the aorta (by default the proximal implantation
/// site, the lower edge of the lowest renal ostium: FindProximalSite) down to 3 × startRadiusMm
/// above the bifurcation, its rings evenly spaced at most `ringSpacingMm` apart so that the first
/// lies exactly at the site (measurement (a) is read there); each leg starts 3 × startRadiusMm
/// down its iliac (so the two first leg rings do not touch) and runs
/// `legLengthMm` (0: to 5 mm above the internal iliac origin where the axes meet — VesselOrigins.h —, or 60 mm
/// without one; a common iliac too short for two rings that way gets two rings ending there, the
/// first moved up toward the junction, but at least startRadiusMm down the iliac). On an iliac the scan cuts short
/// (CenterlineTree::iliacCoverageMm, a partial plan) with no room for that, the leg's rings are evenly spaced over the
/// stretch in view instead (from min(3 × startRadiusMm, L/3) to L − min(1 mm, L/3), at most ringSpacingMm apart; L its
/// centerline's length): the leg only carries the connection element, nothing is read off it.
///
/// **Connection element.** Stiffness acts along *s-chains* (vertex sequences along the vessel)
/// and around *rings*. Across the junction the chains continue: the trunk's right half
/// (j = n/4 … 3n/4) into the right leg's lateral half (same j); its left half (j = 3n/4+1 … n/4−1)
/// into the left leg's lateral half (j ↦ (n/2 − j) mod n); the two legs' medial halves into each
/// other through the crotch (right leg upward, then left leg downward, same j); and the left
/// leg's anterior and posterior columns from the trunk's last two rings (the trunk's columns
/// there continue into the right leg; the stiffness counts a shared pair once, StiffnessMatrix.h).
/// Every vertex thus has s-neighbours two steps away on either side unless it ends a chain,
/// which is what fourth-order derivatives in the Euler–Lagrange equation (4) need there. The
/// triangulation (for display) follows the same element: the two trunk–leg strips, the crotch
/// strip and one triangle anteriorly and one posteriorly close the surface without gaps.
///
/// Input: a CenterlineTree (LPS mm). Output: StentMesh (below).
/// Errors: InputError for parameters out of range or vessels too short for one ring.
#pragma once

#include <array>
#include <limits>
#include <vector>

#include "Centerlines/Centerlines.h"
#include "Common/Types.h"

namespace sgp
{

enum StentSegment : int
{
  TrunkSegment = 0,
  RightLegSegment = 1,
  LeftLegSegment = 2
};

/// A leg's length below its start where no internal iliac origin ends it (legLengthMm 0), mm.
constexpr double DefaultLegLengthMm = 60.0;

struct StentMeshParams
{
  int verticesPerRing = 16;   ///< n, a multiple of 4 in [8, 256]
  double ringSpacingMm = 4.0; ///< in [0.5, 20]
  double startRadiusMm = 3.0; ///< in [0.5, 30]
  /// Where the trunk starts, as arc length along the aorta from its top, mm (≥ 0); negative: the
  /// proximal implantation site detected from the renal branches (FindProximalSite), or the top.
  double proximalAbscissaMm = -1.0;
  double legLengthMm =
    0.0; ///< 0 = to the internal iliac origin (without one: IliacNarrowingAbscissa, else DefaultLegLengthMm)
  /// Where each leg's last ring lies, as arc length along its iliac (right, left), mm; NaN: by
  /// legLengthMm. Given (a graft whose limbs end there: DeployGraft.h), the leg's rings are evenly
  /// spaced, at most ringSpacingMm apart, from 3 × startRadiusMm (or, for a leg shorter than one
  /// spacing beyond that, from one spacing above its end, but at least startRadiusMm down the
  /// iliac) to exactly there; beyond the iliac's end in view it is an InputError.
  std::array<double, 2> legEndAbscissaMm{ std::numeric_limits<double>::quiet_NaN(),
                                          std::numeric_limits<double>::quiet_NaN() };
  /// Where the trunk's last ring lies along the aorta, mm; NaN: 3 × startRadiusMm above the aortic
  /// centerline's end. Given (DeployGraft.h: a component ending nearer the bifurcation), at most
  /// 1 mm above that end.
  double trunkEndAbscissaMm = std::numeric_limits<double>::quiet_NaN();
  /// Where each leg with legEndAbscissaMm starts along its iliac, mm; NaN: 3 × startRadiusMm down
  /// it (or less on a short leg, as said there). Given, at least LegStartMinimumMm down it.
  std::array<double, 2> legStartAbscissaMm{ std::numeric_limits<double>::quiet_NaN(),
                                            std::numeric_limits<double>::quiet_NaN() };
  /// Per segment, abscissae (along its centerline, mm) at which a ring must lie — a graft's
  /// component ends (DeployGraft.h). Those strictly inside the segment's stretch (more than
  /// `RequiredRingSnapMm` from its ends and from each other; a closer one is dropped) get a ring,
  /// and the rings between are evenly spaced, at most ringSpacingMm apart. Ignored on a leg
  /// without legEndAbscissaMm.
  std::array<std::vector<double>, 3> requiredRingAbscissaMm;
};

/// Required ring positions this close to a segment's end or to each other are one ring, mm.
constexpr double RequiredRingSnapMm = 0.5;
/// The nearest a leg given its start may begin to its iliac's first point, mm: the two legs' first
/// rings stay apart there (the crotch plane holds their medial sides: ActiveContour.h).
constexpr double LegStartMinimumMm = 1.0;

struct StentMesh
{
  Points V;                ///< #V×3 vertex positions, LPS mm
  Triangles F;             ///< #F×3, for display
  Points centre;           ///< #V×3: each vertex's point on its centerline, LPS mm
  Points axis;             ///< #V×3: the unit centerline tangent there (downstream)
  Eigen::VectorXi segment; ///< #V: StentSegment
  Eigen::VectorXi ring;    ///< #V: ring number within its segment, from the top / the junction
  Eigen::VectorXi column;  ///< #V: j, the position on the ring
  int verticesPerRing = 0;
  std::vector<std::vector<int>> rings;  ///< vertex ids of each ring, in j order (periodic)
  std::vector<std::vector<int>> chains; ///< s-chains, vertex ids in order along s
  /// Vertex id of (segment, ring, column).
  int Id(int segmentId, int ringId, int columnId) const;
  int RingsIn(int segmentId) const { return ringCount[segmentId]; }
  /// The plane midway between the legs' first rings, where the two legs of the graft meet at the
  /// flow divider: a point on it and its unit normal, pointing from the right leg to the left.
  Point3 crotchPoint = Point3::Zero();
  Eigen::Vector3d crotchNormal = Eigen::Vector3d::UnitX();
  std::array<int, 3> ringCount{ 0, 0, 0 };
  /// Per segment, each ring's arc length along its centerline (the aorta from its top for the
  /// trunk, the iliac from the bifurcation for a leg), mm, in ring order.
  std::array<std::vector<double>, 3> ringAbscissaMm;
  std::array<int, 3> firstVertex{ 0, 0, 0 };
};

void ValidateStentMeshParams(const StentMeshParams& params);

StentMesh BuildStentMesh(const CenterlineTree& tree, const StentMeshParams& params = {});

/// The centre of ring k of `segment` of a surface on `mesh` (V: #V×3, the mesh's own or a fitted
/// one): the mean of its vertices, LPS mm.
Point3 RingCentroid(const StentMesh& mesh, const Points& V, int segment, int k);

/// Where the stent's surface can go while it is fitted: a ball around each ring's centre of
/// radius 1.5 × the vessel's inscribed radius there (a cross-section may be elliptical) + 10 mm
/// (the wall field's 5 mm band, two voxels, margin) — the region for WallDistanceField (LPS mm).
std::vector<Ball> StentReach(const StentMesh& mesh, const CenterlineTree& tree);

/// The band of the wall field the stent fits share (WallDistanceField::FromLumen), mm.
constexpr double SharedWallBandMm = 5.0;

/// The region of the wall field the measure-mode fit and the deployed graft share: StentReach,
/// and where the ordered graft goes beyond it — each leg 16 mm further down its iliac (the measured
/// legs end 5 mm above the internal iliac origin, a planned distal edge at most at its ostium), the
/// trunk up by a negative deployment offset (mm below the proximal site). A graft that still
/// reaches past it (a limb a length step over the ostium, the fallback of ConfigureDevice) gets a
/// field of its own (WallDistanceField::SharedOrOwn).
std::vector<Ball> SharedFieldReach(const StentMesh& mesh, const CenterlineTree& tree, double deploymentOffsetMm);

} // namespace sgp
