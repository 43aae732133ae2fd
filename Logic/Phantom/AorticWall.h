/// \file AorticWall.h
/// The aorta of the synthetic phantom as a vessel with a wall: the outer wall, the wall, the
/// intraluminal thrombus (ILT) of the sac and of the lower neck, wall calcification and the
/// neighbours pressed against the vessel — in coordinates of the vessel's axis, with the analytic
/// truth of each (vessel-wall.md §2–3 for the HU and shapes).
///
/// Coordinates: the vessel axis runs from the bifurcation (h = 0) straight up (+z, LPS) to the
/// sac's top, then leans anteriorly by β (AorticPhantom.h); h is the arc length along it. A point
/// x has the axis point A(h) nearest to it and in-plane coordinates q = (anterior, left) in the
/// plane ⊥ the axis there: anterior = −y rotated with the neck, left = +x (the patient's left in
/// LPS). An angle θ on the cross-section is measured from anterior toward the patient's left:
/// anterior 0°, left 90°, posterior 180°, right 270°.
///
/// Per level h (all mm):
///  - outer radius Ro(h): the vessel's radius profile (AorticPhantom.h's r(z)); in the sac, with
///    sacAxisRatio q > 1, the outer cross-section is the ellipse with semi-axes Ro·(1 + (q − 1)·
///    sin(π u)) along the major axis's side and Ro across it, Ro(h, θ) its radius along θ;
///  - inner wall radius Ri = Ro − wallThicknessMm (along θ: Ro(h, θ) − wallThicknessMm, so the
///    thrombus fills the ellipse's ends around the round lumen);
///  - thrombus thickness T(h): in the sac T_max · sin(π u) (u from the sac's top, 0…1); in the lower
///    neck, from the sac's top up `neckThrombusLengthMm`, T_neck with 3 mm cosine tapers at both
///    ends; 0 elsewhere. Its side is the ILT's thick side;
///  - lumen: a disc of radius rl in the plane, centred e from the axis away from the thick side:
///    eccentric rl = Ri − T/2, e = T/2 (the thrombus is a crescent, T thick on its side, 0 opposite);
///    concentric rl = Ri − T, e = 0 (in the sac only: the neck's thrombus is always a crescent).
///    The lumen is a tube around the curve A(h) + e(h)·(−side), so
///    its cross-section ⊥ its own centerline is the disc rl exactly;
///  - calcification: an arc of `…CalcificationArcDeg` centred on its side, radially from Ri − 1 mm
///    to Ro (intimal calcium at the outer wall under the ILT), in the neck from the proximal site
///    down 15 mm, in the sac over its middle third;
///  - neighbours (psoas, IVC, duodenum, left renal vein): pads conforming to the outer wall over
///    their contact arc (each at least a fifth of the circumference), from Ro out by their
///    thickness, over their stretch of h — organs pressed against the vessel without a fat plane.
///
/// Errors: none here (AorticPhantom validates the parameters). Complexity: O(1) per point.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "Common/Types.h"

namespace sgp
{

struct PhantomParams;

/// A neighbour pad: where it touches the aorta and how far it reaches out.
struct WallNeighbour
{
  std::string name;
  unsigned char label = 0;
  double hu = 0.0;
  double fromH = 0.0, toH = 0.0; ///< its stretch along the vessel axis, mm
  double sideDeg = 0.0;          ///< centre of the contact arc
  double arcDeg = 0.0;           ///< contact arc
  double thicknessMm = 0.0;      ///< from the outer wall outward
};

/// A calcified arc of the wall.
struct WallCalcification
{
  double fromH = 0.0, toH = 0.0;
  double sideDeg = 0.0;
  double arcDeg = 0.0;
};

class AorticWall
{
public:
  /// `outerRadius(h)` the vessel's radius profile; the sac spans [sacBottomH, sacTopH]; the proximal
  /// implantation site is at siteH; the aorta ends at topH; `betaRad` the neck's lean.
  AorticWall(const PhantomParams& p,
             std::function<double(double)> outerRadius,
             double sacBottomH,
             double sacTopH,
             double siteH,
             double topH,
             double betaRad);

  struct Coordinates
  {
    double h = 0.0;                              ///< arc length along the vessel axis, clamped to [0, top]
    Eigen::Vector2d q = Eigen::Vector2d::Zero(); ///< (anterior, left) in the plane there, mm
    double rho = 0.0;                            ///< |q|
    double thetaDeg = 0.0;                       ///< [0, 360)
    double beyondMm = 0.0; ///< how far x lies below the bifurcation or above the top (negative between)
  };
  Coordinates At(const Point3& x) const;

  Point3 AxisPoint(double h) const;
  /// The in-plane unit directions at h, LPS: anterior and left.
  std::array<Eigen::Vector3d, 2> Frame(double h) const;

  /// The round profile (the ellipse's minor semi-axis in an elliptical sac).
  double OuterRadius(double h) const { return m_Outer(h); }
  double InnerRadius(double h) const { return m_Outer(h) - m_WallMm; }
  /// Along the in-plane direction θ (degrees from anterior toward the left).
  double OuterRadius(double h, double thetaDeg) const;
  double InnerRadius(double h, double thetaDeg) const { return OuterRadius(h, thetaDeg) - m_WallMm; }
  /// The largest caliper of the outer cross-section over h in [fromH, toH] (0.01 mm steps), mm.
  double MaxCaliperMm(double fromH, double toH) const;
  double ThrombusThickness(double h) const;
  /// Whether the thrombus at level h is concentric: the sac's, when thrombusConcentric.
  bool ConcentricAt(double h) const;
  /// The lumen disc at h: its centre in the plane (anterior, left) and its radius.
  Eigen::Vector2d LumenCentre(double h) const;
  /// The same centre in LPS: the axis point at h moved by LumenCentre in the plane's frame.
  Point3 LumenCentreLps(double h) const;
  double LumenRadius(double h) const;
  /// The thrombus's thickness at h along the in-plane direction θ: from the lumen's edge to the
  /// inner wall (0 where the lumen touches the wall).
  double ThrombusThicknessAt(double h, double thetaDeg) const;

  /// The lumen centerline sampled every `stepMm` of h (LPS), with its radius.
  void SampleLumen(double stepMm, std::vector<Point3>& points, std::vector<double>& radii) const;
  /// With PhantomParams::neckLumenPerLevel (else NaN everywhere): the lumen's signed distance at
  /// `c` where it is drawn level by level — the neck thrombus's stretch and 6 mm beyond either
  /// end, h in (sac top − 6, sac top + neckThrombusLengthMm + 6) — and NaN elsewhere, where the
  /// lumen is the tube round its centre curve (SampleLumen). Per level: the in-plane distance to that
  /// level's lumen disc, |q − centre(h)| − radius(h), over the gradient norm √(1 + (∂/∂h)²) (a
  /// first-order signed distance, mm, negative inside). Over the neck crescent's 3 mm tapers the
  /// centre moves up to half the thrombus sideways; a tube round that curve (its radius at the
  /// nearest curve point) put the thrombus's onset about 2.6 mm lower than the truth's discs
  /// (issue 46 item 2). Drawn so, the image's neck lumen is the truth's.
  double NeckLumenSignedDistance(const Coordinates& c) const;

  /// Signed distances (negative inside) at x of: the outer wall's disc, the wall annulus, one
  /// calcification (its index), one neighbour (its index).
  double OuterSignedDistance(const Coordinates& c) const { return c.rho - OuterRadius(c.h, c.thetaDeg); }
  double WallSignedDistance(const Coordinates& c) const;
  double CalcificationSignedDistance(const Coordinates& c, const WallCalcification& w) const;
  double NeighbourSignedDistance(const Coordinates& c, const WallNeighbour& n) const;

  bool HasWall() const { return m_WallMm > 0.0; }
  bool HasThrombus() const { return m_SacThrombusMm > 0.0 || m_NeckThrombusMm > 0.0; }
  /// Whether NeckLumenSignedDistance draws anywhere (the option on and a neck thrombus).
  bool DrawsNeckLumenPerLevel() const { return m_NeckLumenPerLevel && m_NeckThrombusMm > 0.0; }
  double WallMm() const { return m_WallMm; }
  double TopH() const { return m_TopH; }
  double MaxOuterRadius() const { return m_MaxOuter; }
  /// How far from the axis anything of the wall reaches: the widest outer wall plus the thickest
  /// neighbour pad, mm.
  double ReachMm() const;
  /// The LPS box {min, max} of everything of the wall, grown by `marginMm`. (The axis runs
  /// monotonically in each coordinate, so its two ends bound it.)
  std::array<Point3, 2> BoundsLps(double marginMm) const;
  const std::vector<WallCalcification>& Calcifications() const { return m_Calcifications; }
  const std::vector<WallNeighbour>& Neighbours() const { return m_Neighbours; }

  /// Truth, site to bifurcation (h in [0, siteH]): thrombus volume (mL), the largest thrombus
  /// thickness (mm); over the neck from the site to 15 mm below: the largest share of the
  /// circumference (%) where the thrombus is thicker than 2 mm, and where the wall is calcified.
  double ThrombusVolumeMl() const;
  double MaxThrombusThicknessMm() const;
  double NeckThrombusArcPercent() const;
  double NeckCalcificationArcPercent() const;

private:
  double Taper(double h) const; ///< the neck thrombus's profile, 0…1
  Eigen::Vector2d SideVector(double deg) const;

  std::function<double(double)> m_Outer;
  double m_WallMm, m_SacBottom, m_SacTop, m_Site, m_TopH, m_Beta, m_MaxOuter;
  double m_SacThrombusMm, m_NeckThrombusMm, m_NeckThrombusLengthMm;
  bool m_NeckLumenPerLevel = false;
  double m_SacThrombusSideDeg, m_NeckThrombusSideDeg;
  bool m_Concentric;
  double m_SacAxisRatio, m_SacMajorDeg;
  double Stretch(double h) const; ///< the major semi-axis over the minor at h, ≥ 1
  std::vector<WallCalcification> m_Calcifications;
  std::vector<WallNeighbour> m_Neighbours;
};

} // namespace sgp
