// The synthetic phantom's anatomy: tubes, kidneys, column and wall, and their truth (PhantomAnatomy.h).
#include "Phantom/PhantomAnatomy.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>

#include <Eigen/Dense>

#include "Common/Errors.h"
#include "Common/Format.h"
#include "Phantom/KinkSection.h"
#include "Phantom/PhantomRaster.h"

namespace sgp::phantom
{

namespace
{

Point3 Unit(double x, double y, double z)
{
  return Point3(x, y, z).normalized();
}

Tube StraightTube(const std::string& name, const std::vector<Point3>& axis, double radius)
{
  return { name, axis, [radius](double) { return radius; }, radius };
}

/// A tube along a sampled curve whose radius is given at each vertex (linear in arc length between).
Tube SampledTube(const std::string& name, const std::vector<Point3>& axis, const std::vector<double>& radii)
{
  std::vector<double> s(axis.size(), 0.0);
  for (std::size_t k = 1; k < axis.size(); ++k)
    s[k] = s[k - 1] + (axis[k] - axis[k - 1]).norm();
  const double largest = *std::max_element(radii.begin(), radii.end());
  return { name, axis,
           [s, radii](double at)
           {
             const auto upper = std::upper_bound(s.begin(), s.end(), at);
             if (upper == s.begin())
               return radii.front();
             if (upper == s.end())
               return radii.back();
             const std::size_t k = static_cast<std::size_t>(upper - s.begin());
             const double t = (at - s[k - 1]) / (s[k] - s[k - 1]);
             return (1 - t) * radii[k - 1] + t * radii[k];
           },
           largest };
}

/// How far below the point where a branch of radius `rho` leaves a vessel's axis (direction `a`,
/// lumen radius `R` there) the lowest point of its ostium on the vessel's wall lies, along `a`:
/// the lowest point, over the branch's surface (p = t·d + ρ·e, e ⊥ d, at every 0.1° of e) where it
/// crosses the vessel's wall cylinder (|p − (p·a)a| = R, the outer root in t). ρ exactly for a
/// branch perpendicular to the vessel.
double OstiumLowerEdgeDepthMm(double R, double rho, const Eigen::Vector3d& d, const Eigen::Vector3d& a)
{
  const Eigen::Vector3d e1 = d.unitOrthogonal(), e2 = d.cross(e1);
  const auto radial = [&a](const Eigen::Vector3d& v) { return Eigen::Vector3d(v - v.dot(a) * a); };
  const Eigen::Vector3d pd = radial(d);
  double lowest = 0.0;
  for (int k = 0; k < 3600; ++k)
  {
    const double psi = 2.0 * pi * k / 3600.0;
    const Eigen::Vector3d e = std::cos(psi) * e1 + std::sin(psi) * e2, pe = radial(e);
    const double qa = pd.squaredNorm(), qb = 2.0 * rho * pd.dot(pe), qc = rho * rho * pe.squaredNorm() - R * R;
    const double t = (-qb + std::sqrt(std::max(0.0, qb * qb - 4.0 * qa * qc))) / (2.0 * qa);
    lowest = std::min(lowest, t * d.dot(a) + rho * e.dot(a));
  }
  return -lowest;
}

/// Where the mouth of a straight branch tube that leaves from the end of `parents`' first tube
/// begins: the least projection on `axis`, from the branch's first axis point, of the branch's
/// lateral surface where it lies outside every parent (the surface the lumen shows, whose rim is
/// the mouth), mm — sampled every 0.02 mm along the branch's first 25 mm and every 0.5° round it.
/// At a division (the internal iliac leaving where the common iliac ends, the external iliac going
/// on) the mouth opens below the division, not at it (2.6 mm on the default anatomy): the parent's
/// round end and the external iliac hide the branch's first millimetres. 25 mm when no surface
/// there shows.
double MouthUpstreamEdgeMm(const Tube& branch, const std::vector<Tube>& parents, const Eigen::Vector3d& axis)
{
  const Point3 o = branch.axis.front();
  const Eigen::Vector3d d = (branch.axis[1] - o).normalized(), e1 = d.unitOrthogonal(), e2 = d.cross(e1);
  const double rho = branch.radiusAt(0.0);
  std::vector<TubeDistance> parentDistances(parents.begin(), parents.end());
  const auto outside = [&](const Point3& x)
  {
    return std::all_of(parentDistances.begin(), parentDistances.end(),
                       [&](TubeDistance& parent) { return parent.SignedDistance(x) > 0.0; });
  };
  double upstream = 25.0;
  for (int k = 0; k < 720; ++k)
  {
    const double psi = pi * k / 360.0;
    const Eigen::Vector3d radial = rho * (std::cos(psi) * e1 + std::sin(psi) * e2);
    for (double t = 0.0; t <= 25.0; t += 0.02)
    {
      const Point3 x = o + t * d + radial;
      if (outside(x))
      {
        upstream = std::min(upstream, (x - o).dot(axis));
        break; // farther along this generator lies farther downstream (d · axis > 0)
      }
    }
  }
  return upstream;
}

/// A renal artery from `origin` (on the aortic axis) toward `hilum`: whole, cut `renalStubMm`
/// outside the aortic lumen (radius `aorticRadius`), or dividing `renalDivisionMm` outside it into
/// an upper and a lower branch turned ±renalBranchTurnDeg in the vertical plane of its course.
void AddRenal(Anatomy& anatomy,
              const std::string& name,
              const Point3& origin,
              const Point3& hilum,
              double radius,
              double aorticRadius,
              const PhantomParams& p)
{
  const Eigen::Vector3d d = (hilum - origin).normalized();
  // Along the course, the lumen's wall lies where the horizontal distance reaches the aortic radius.
  const double horizontal = std::hypot(d.x(), d.y());
  const double toWall = aorticRadius / std::max(horizontal, 1e-6);
  if (p.renalStubMm > 0.0)
  {
    anatomy.tubes.push_back(StraightTube(name, { origin, origin + (toWall + p.renalStubMm) * d }, radius));
    return;
  }
  if (p.renalDivisionMm > 0.0)
  {
    const Point3 division = origin + (toWall + p.renalDivisionMm) * d;
    const double rest = (hilum - division).norm();
    // The vertical plane of the course: its horizontal part and z.
    const Eigen::Vector3d h = Eigen::Vector3d(d.x(), d.y(), 0.0).normalized();
    const double angle = std::atan2(d.z(), horizontal), turn = renalBranchTurnDeg * pi / 180.0;
    anatomy.tubes.push_back(StraightTube(name, { origin, division }, radius));
    for (const double sign : { 1.0, -1.0 })
    {
      const double a = angle + sign * turn;
      const Eigen::Vector3d b = std::cos(a) * h + Eigen::Vector3d(0.0, 0.0, std::sin(a));
      anatomy.tubes.push_back(
        StraightTube(name + (sign > 0 ? "Upper" : "Lower"), { division, division + rest * b }, renalBranchRadiusMm));
    }
    return;
  }
  anatomy.tubes.push_back(StraightTube(name, { origin, hilum }, radius));
}

/// (d)'s truth where a common iliac's lumen is wider than the distal aorta's at B: each iliac's
/// tube starts at B with a round end (TubeDistance), whose cap rises up to its radius above B and
/// out beyond the aorta's disc, so the narrowest level of the solid as drawn lies above B, not at it
/// (issue 46's sweep: 17.1 mm iliacs on a 15 mm distal aorta, 11.2 mm of lumen at B by the radius
/// profile; the solid's narrowest section, at B, is 14.1 mm). There the truth is the smallest mean diameter
/// (16 directions) of the lumen's union sections ⊥ z through the aortic lumen's centre, every
/// 0.1 mm from B up to the widest iliac's radius; otherwise (the caps inside the aorta's disc) the
/// radius profile's minimum stands.
void DistalNeckWithWideIliacs(const Anatomy& anatomy,
                              const std::function<double(double)>& lumenRadius,
                              double widestH,
                              const AorticWall* wall,
                              PhantomSizing& sizing)
{
  std::vector<std::size_t> tubes{ 0 };
  double widestIliac = 0.0;
  for (std::size_t t = 0; t < anatomy.tubes.size(); ++t)
    if (anatomy.tubes[t].name == "rightIliac" || anatomy.tubes[t].name == "leftIliac")
    {
      tubes.push_back(t);
      widestIliac = std::max(widestIliac, anatomy.tubes[t].radiusAt(0.0));
    }
  if (widestIliac <= lumenRadius(0.0))
    return;
  std::vector<TubeDistance> distances;
  for (const std::size_t t : tubes)
    distances.emplace_back(anatomy.tubes[t]);
  const auto inLumen = [&](const Point3& x)
  {
    for (std::size_t k = 0; k < tubes.size(); ++k)
      if (LumenSignedDistance(anatomy, tubes[k], distances[k], x) < 0.0)
        return true;
    return false;
  };
  double narrowest = std::numeric_limits<double>::infinity();
  for (double h = widestIliac; h <= widestH; h += 0.01)
    narrowest = std::min(narrowest, 2.0 * lumenRadius(h));
  for (double h = 0.0; h <= std::min(widestIliac, widestH); h += 0.1)
  {
    const Point3 centre = wall ? wall->LumenCentreLps(h) : Point3(0, 0, h);
    narrowest = std::min(narrowest, SectionMeanDiameterMm(inLumen, centre, Eigen::Vector3d::UnitZ(), 16));
  }
  sizing.distalNeckMinDiameter = narrowest;
}

/// (b) near the neck's bend (KinkSection.h): where the bend's other straight piece reaches the
/// plane at level h, the lumen's and the outer (b) are the smallest mean diameters of the phantom's
/// own solids through the level's centres (the lumen's: off the axis where a thrombus moves it),
/// over planes between the two pieces' normals. Elsewhere the nominal values stay.
template<class RadiusAtZ, class OnAxis>
void NeckBendSectionTruth(const Anatomy& anatomy,
                          const PhantomParams& p,
                          const RadiusAtZ& radiusAtZ,
                          double sacTop,
                          double h,
                          const OnAxis& onAxis,
                          const Eigen::Vector3d& neckDirection,
                          PhantomSizing& sizing)
{
  const double beta = p.neckAngleDeg * pi / 180.0;
  // Along the neck piece (h above the sac's top) the sac piece reaches the plane, and vice versa.
  const double reach = h >= sacTop ? KinkReachMm([&](double u) { return radiusAtZ(sacTop - u); }, beta)
                                   : KinkReachMm([&](double u) { return radiusAtZ(sacTop + u); }, beta);
  if (!(std::abs(h - sacTop) < reach))
    return;
  const Eigen::Vector3d neck = -neckDirection, sac(0.0, 0.0, -1.0); // downward along the aorta
  const AorticWall* wall = anatomy.wall.get();
  TubeDistance lumenTube(anatomy.tubes.front());
  const auto inLumen = [&](const Point3& x) { return LumenSignedDistance(anatomy, 0, lumenTube, x) < 0.0; };
  const Point3 lumenCentre = wall ? wall->LumenCentreLps(h) : onAxis(h);
  sizing.neckDiameter15mm = SmallestSectionMeanDiameterMm(inLumen, lumenCentre, neck, sac);
  if (wall)
  {
    const auto inOuter = [&](const Point3& x) { return wall->OuterSignedDistance(wall->At(x)) < 0.0; };
    sizing.outerNeckDiameter15mm = SmallestSectionMeanDiameterMm(inOuter, onAxis(h), neck, sac);
  }
  else
    sizing.outerNeckDiameter15mm = sizing.neckDiameter15mm;
}

/// Arc length along `axis` (a polyline from B) of its point nearest to `x`, mm.
double NearestArcLength(const std::vector<Point3>& axis, const Point3& x)
{
  double best = std::numeric_limits<double>::infinity(), arc = 0.0, start = 0.0;
  for (std::size_t k = 0; k + 1 < axis.size(); ++k)
  {
    const Eigen::Vector3d ab = axis[k + 1] - axis[k];
    const double t = std::clamp((x - axis[k]).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    const double d = (axis[k] + t * ab - x).norm();
    if (d < best)
    {
      best = d;
      arc = start + t * ab.norm();
    }
    start += ab.norm();
  }
  return arc;
}

/// The flow divider's truth (PhantomSizing): at height z below B, the lumen has divided when a
/// point of the frontal plane between the two common iliacs' first axis pieces (extended) lies
/// outside every lumen tube. Divided is monotone in depth below B (the iliacs diverge), so the
/// highest such z is found by bisection to 1 nm, after a 0.25 mm descent finds the first divided
/// level.
void FlowDividerTruth(Anatomy& anatomy, const std::vector<Point3> (&commonAxes)[2])
{
  PhantomSizing& sizing = anatomy.truth.sizing;
  sizing.proximalSiteToFlowDividerLength = sizing.rightIliacLengthFromFlowDivider =
    sizing.leftIliacLengthFromFlowDivider = std::numeric_limits<double>::quiet_NaN();
  std::vector<TubeDistance> lumens(anatomy.tubes.begin(), anatomy.tubes.end());
  const Eigen::Vector3d first[2] = { (commonAxes[0][1] - commonAxes[0][0]).normalized(),
                                     (commonAxes[1][1] - commonAxes[1][0]).normalized() };
  // At height z, the point between the axes farthest outside every lumen (0.05 mm samples, then a
  // ternary search around the best to 1e-7 mm) and how far outside it lies (> 0: divided there).
  const auto outside = [&](double x, double z)
  {
    double least = std::numeric_limits<double>::infinity();
    for (TubeDistance& t : lumens)
      least = std::min(least, t.SignedDistance(Point3(x, 0.0, z)));
    return least;
  };
  const auto gapAt = [&](double z)
  {
    const double xRight = z / first[0].z() * first[0].x(), xLeft = z / first[1].z() * first[1].x();
    double best = xRight, bestValue = -std::numeric_limits<double>::infinity();
    for (double x = xRight; x <= xLeft; x += 0.05)
      if (const double v = outside(x, z); v > bestValue)
      {
        bestValue = v;
        best = x;
      }
    double lo = std::max(xRight, best - 0.05), hi = std::min(xLeft, best + 0.05);
    while (hi - lo > 1e-7)
    {
      const double a = lo + (hi - lo) / 3.0, b = hi - (hi - lo) / 3.0;
      if (outside(a, z) < outside(b, z))
        lo = a;
      else
        hi = b;
    }
    const double x = 0.5 * (lo + hi);
    return std::make_pair(Point3(x, 0.0, z), outside(x, z));
  };
  double above = 0.0, below = -0.25;
  while (gapAt(below).second <= 0.0)
  {
    above = below;
    below -= 0.25;
    if (below < -80.0)
      return; // no division in reach: the truth's flow-divider values stay NaN
  }
  while (above - below > 1e-6)
  {
    const double mid = 0.5 * (above + below);
    (gapAt(mid).second <= 0.0 ? above : below) = mid;
  }
  const Point3 divider = gapAt(below).first;
  anatomy.truth.landmarks.push_back({ "flowDivider", divider });
  sizing.proximalSiteToFlowDividerLength = sizing.proximalSiteToBifurcationLength - divider.z();
  sizing.rightIliacLengthFromFlowDivider = sizing.rightIliacLength - NearestArcLength(commonAxes[0], divider);
  sizing.leftIliacLengthFromFlowDivider = sizing.leftIliacLength - NearestArcLength(commonAxes[1], divider);
}

} // namespace

double LumenSignedDistance(const Anatomy& anatomy, std::size_t tube, TubeDistance& distance, const Point3& x)
{
  if (tube == 0 && anatomy.wall && anatomy.wall->DrawsNeckLumenPerLevel())
    if (const double d = anatomy.wall->NeckLumenSignedDistance(anatomy.wall->At(x)); std::isfinite(d))
      return d;
  return distance.SignedDistance(x);
}

Anatomy BuildAnatomy(const PhantomParams& p)
{
  Anatomy anatomy;
  PhantomTruth& truth = anatomy.truth;
  const double rNeck = p.neckDiameterMm / 2, rDistal = p.distalNeckDiameterMm / 2;
  const double sacBottom = p.distalNeckLengthMm, sacTop = sacBottom + p.aneurysmLengthMm;
  const double siteZ = sacTop + p.neckLengthMm; // lower edge of the lowest (right) renal ostium
  const double smaZ = siteZ + 20.0, coeliacZ = siteZ + 35.0, topZ = siteZ + p.aortaAboveSiteMm;
  const double amplitude = p.maxAneurysmDiameterMm / 2 - 0.5 * (rNeck + rDistal);
  const auto radiusAtZ = [=](double z)
  {
    if (z >= sacTop)
      return rNeck;
    if (z < sacBottom)
      return rDistal;
    const double u = (sacTop - z) / (sacTop - sacBottom);
    // A half sine: the sac starts at a shoulder (slope πA/L), so the neck has a definite end.
    return rNeck + (rDistal - rNeck) * u + amplitude * std::sin(pi * u);
  };
  double rMax = 0.0, zMax = sacTop;
  for (double z = sacBottom; z <= sacTop; z += 0.01)
  {
    if (radiusAtZ(z) > rMax)
    {
      rMax = radiusAtZ(z);
      zMax = z;
    }
  }
  // The sac's axis is vertical; above the sac the neck leans anteriorly by the neck angle β.
  // onAxis(h) is the point at height h along the straight model, carried onto the bent axis (arc
  // length is kept, so the radius profile and every length along the aorta are unchanged).
  const double beta = p.neckAngleDeg * pi / 180.0;
  const Eigen::Vector3d neckDirection(0.0, -std::sin(beta), std::cos(beta));
  const auto onAxis = [=](double h)
  { return h <= sacTop ? Point3(0, 0, h) : Point3(Point3(0, 0, sacTop) + (h - sacTop) * neckDirection); };
  anatomy.siteZ = siteZ;
  const double wallMm = p.wallThicknessMm;
  if (wallMm > 0.0)
    anatomy.wall = std::make_unique<AorticWall>(p, radiusAtZ, sacBottom, sacTop, siteZ, topZ, beta);
  const AorticWall* wall = anatomy.wall.get();
  // The renals run horizontally to their hila; the right one leaves the neck's axis so that its
  // ostium's lowest point on the lumen's wall is at the site.
  // A variant's renal is turned by the takeoff angle about the vertical (anterior: toward −y) and
  // tilted down by the descent; at 0° both are the exact identity.
  const double takeoff = p.renalTakeoffDeg * pi / 180.0, descent = p.renalDescentDeg * pi / 180.0;
  const auto renalCourse = [=](double lateral)
  {
    const Point3 h(lateral * renalHilumLateralMm, renalHilumPosteriorMm, 0.0);
    const double turn = -lateral * takeoff; // rotates the right (−x) and the left (+x) renal toward −y
    const Point3 turned(h.x() * std::cos(turn) - h.y() * std::sin(turn),
                        h.x() * std::sin(turn) + h.y() * std::cos(turn), 0.0);
    return Point3(std::cos(descent) * turned + Point3(0.0, 0.0, -std::sin(descent) * turned.norm()));
  };
  const Eigen::Vector3d rightRenalDirection = renalCourse(-1.0).normalized();
  const double siteLumenRadius = wall ? wall->LumenRadius(siteZ) : rNeck;
  const double rightRenalZ =
    siteZ + OstiumLowerEdgeDepthMm(siteLumenRadius, p.renalRadiusMm, rightRenalDirection, neckDirection);
  const double leftRenalZ = rightRenalZ + 6.0;
  if (wall && wall->HasThrombus())
  {
    // The lumen off-centre in the thrombus: a tube along its own centerline (2 mm samples; the
    // offset is a half-sine, so the chords stay within 0.01 mm of the curve).
    std::vector<Point3> lumenAxis;
    std::vector<double> lumenRadii;
    wall->SampleLumen(2.0, lumenAxis, lumenRadii);
    anatomy.tubes.push_back(SampledTube("aorta", lumenAxis, lumenRadii));
  }
  else
  {
    anatomy.tubes.push_back({ "aorta",
                              { onAxis(topZ), onAxis(sacTop), Point3(0, 0, 0) },
                              [=](double s) { return radiusAtZ(topZ - s) - wallMm; },
                              std::max({ rNeck, rDistal, rMax }) - wallMm });
  }

  Point3 iliacEnd[2];
  std::vector<Point3> commonAxes[2];
  const char* sideName[2] = { "right", "left" };
  const double iliacRadius[2] = { p.rightIliacDiameterMm / 2, p.leftIliacDiameterMm / 2 };
  const double commonIliacLengthMm[2] = { p.rightCommonIliacLengthMm, p.leftCommonIliacLengthMm };
  for (int side = 0; side < 2; ++side)
  {
    const double lateral = side == 0 ? -1.0 : 1.0; // patient right is -x in LPS
    const std::string prefix = sideName[side];
    const double r = iliacRadius[side]; // outer; the lumen lies the wall's thickness inside
    const double angle = (side == 0 ? p.rightCommonIliacAngleDeg : p.leftCommonIliacAngleDeg) * pi / 180.0;
    iliacEnd[side] = commonIliacLengthMm[side] * Point3(lateral * std::sin(angle), 0, -std::cos(angle));
    std::vector<Point3> common{ Point3::Zero(), iliacEnd[side] };
    if (p.commonIliacKinkDeg > 0.0 && commonIliacLengthMm[side] > kinkFromBifurcationMm + 5.0)
    {
      // 10 mm at the usual angle, then the rest turned outward by the kink (the length kept).
      const double turned = angle + p.commonIliacKinkDeg * pi / 180.0;
      const Point3 kink = kinkFromBifurcationMm * Point3(lateral * std::sin(angle), 0, -std::cos(angle));
      iliacEnd[side] = kink + (commonIliacLengthMm[side] - kinkFromBifurcationMm) *
                                Point3(lateral * std::sin(turned), 0, -std::cos(turned));
      common = { Point3::Zero(), kink, iliacEnd[side] };
    }
    commonAxes[side] = common;
    const std::vector<Point3> external{ iliacEnd[side], iliacEnd[side] + 70.0 * Unit(lateral * 0.17, -0.15, -0.97) };
    const std::vector<Point3> internal{
      iliacEnd[side], iliacEnd[side] + 40.0 * (p.posteriorInternalIliac ? Unit(lateral * 0.15, 0.85, -0.5)
                                                                        : Unit(lateral * 0.45, 0.55, -0.7))
    };
    // The smaller branches' walls at most a third of their radius (a 2 mm wall would close a
    // 3 mm internal iliac).
    const auto lumenOf = [wallMm](double outer) { return outer - std::min(wallMm, outer / 3.0); };
    anatomy.tubes.push_back(StraightTube(prefix + "Iliac", common, r - wallMm));
    anatomy.tubes.push_back(StraightTube(prefix + "ExternalIliac", external, lumenOf(0.75 * r)));
    const bool internalDrawn = side == 0 ? p.rightInternalIliac : p.leftInternalIliac;
    if (internalDrawn)
      anatomy.tubes.push_back(StraightTube(prefix + "InternalIliac", internal, lumenOf(0.55 * r)));
    if (side == 0 && p.rightIliacDecoyBranchMm > 0.0)
    {
      const Point3 from = common[0] + p.rightIliacDecoyBranchMm * (common[1] - common[0]).normalized();
      anatomy.tubes.push_back(
        StraightTube("rightIliacDecoy", { from, from + 35.0 * Unit(lateral * 0.7, 0.65, -0.3) }, lumenOf(0.55 * r)));
    }
    (side == 0 ? truth.sizing.rightInternalIliacRadius : truth.sizing.leftInternalIliacRadius) = lumenOf(0.55 * r);
    // The internal iliac's ostium: the most upstream point, along the common iliac's last axis
    // piece, of its mouth as drawn (MouthUpstreamEdgeMm).
    const Eigen::Vector3d commonAxis = (common.back() - common[common.size() - 2]).normalized();
    (side == 0 ? truth.sizing.rightInternalIliacOstium : truth.sizing.leftInternalIliacOstium) =
      commonIliacLengthMm[side] +
      MouthUpstreamEdgeMm(StraightTube("", internal, lumenOf(0.55 * r)),
                          { StraightTube("", common, r - wallMm), StraightTube("", external, lumenOf(0.75 * r)) },
                          commonAxis);
    if (wallMm > 0.0)
    {
      anatomy.wallTubes.push_back(StraightTube(prefix + "IliacWall", common, r));
      anatomy.wallTubes.push_back(StraightTube(prefix + "ExternalIliacWall", external, 0.75 * r));
      if (internalDrawn)
        anatomy.wallTubes.push_back(StraightTube(prefix + "InternalIliacWall", internal, 0.55 * r));
    }
    const double renalZ = side == 0 ? rightRenalZ : leftRenalZ;
    const Point3 hilum = onAxis(renalZ) + renalCourse(lateral);
    if (p.includeRenals)
      AddRenal(anatomy, prefix + "Renal", onAxis(renalZ), hilum, p.renalRadiusMm, siteLumenRadius, p);
    if (p.includeKidneys)
    {
      anatomy.kidneys.push_back({ onAxis(renalZ) + Point3(lateral * 80.0, 15.0, -10.0), Point3(22.0, 18.0, 50.0) });
    }
    truth.landmarks.push_back({ prefix + "RenalOstium", onAxis(renalZ) + Point3(lateral * rNeck, 0, 0) });
    truth.landmarks.push_back({ prefix + "IliacBifurcation", iliacEnd[side] });
  }
  if (p.accessoryRenalOffsetMm != 0.0)
  {
    const double z = rightRenalZ + p.accessoryRenalOffsetMm;
    anatomy.tubes.push_back(
      StraightTube("rightAccessoryRenal", { onAxis(z), onAxis(z) + Point3(-55.0, 5.0, 0.0) }, accessoryRenalRadiusMm));
  }
  if (p.parallelSuperiorMesenteric) // leaves forward, turns down within 10 mm, 5 mm of tissue from the aorta
    anatomy.tubes.push_back(StraightTube("superiorMesenteric",
                                         { onAxis(smaZ), onAxis(smaZ) + Point3(0, -(rNeck + 9.0), -6.0),
                                           onAxis(smaZ) + Point3(0, -(rNeck + 10.0), -30.0),
                                           onAxis(smaZ) + Point3(0, -(rNeck + 30.0), -70.0) },
                                         visceralRadiusMm));
  else
    anatomy.tubes.push_back(StraightTube(
      "superiorMesenteric", { onAxis(smaZ), onAxis(smaZ) + Point3(0, -35, -5), onAxis(smaZ) + Point3(0, -45, -60) },
      visceralRadiusMm));
  if (p.includeInferiorMesenteric) // from the sac's front at a third of its height, down and to the left
  {
    const double z = sacBottom + (sacTop - sacBottom) / 3.0;
    const double front = radiusAtZ(z);
    anatomy.tubes.push_back(StraightTube(
      "inferiorMesenteric",
      { Point3(0, 0, z), Point3(0, -front - 8.0, z - 6.0), Point3(25.0, -front - 12.0, z - 60.0) }, imaRadiusMm));
    truth.landmarks.push_back({ "inferiorMesentericOstium", Point3(0, -front, z) });
  }
  anatomy.tubes.push_back(
    StraightTube("coeliac", { onAxis(coeliacZ), onAxis(coeliacZ) + Point3(0, -30, 5) }, visceralRadiusMm));
  if (p.includeBone)
  {
    anatomy.column = true;
    anatomy.columnY = rMax + p.boneGapMm + vertebraRadiusMm;
  }

  truth.landmarks.push_back({ "aorticBifurcation", Point3::Zero() });
  truth.landmarks.push_back({ "proximalImplantationSite", onAxis(siteZ) });
  truth.landmarks.push_back({ "superiorMesentericOstium", onAxis(smaZ) + Point3(0, -rNeck, 0) });
  truth.landmarks.push_back({ "coeliacOstium", onAxis(coeliacZ) + Point3(0, -rNeck, 0) });
  truth.landmarks.push_back({ "maxAneurysmDiameterLevel", Point3(0, 0, zMax) });
  PhantomSizing& sizing = truth.sizing;
  sizing.outerProximalNeckDiameter = 2 * radiusAtZ(siteZ);
  sizing.outerNeckDiameter15mm = 2 * radiusAtZ(siteZ - 15.0);
  sizing.outerMaxAneurysmDiameter = wall ? std::max(2 * rMax, wall->MaxCaliperMm(0.0, siteZ)) : 2 * rMax;
  sizing.outerDistalNeckMinDiameter = 2 * rDistal;
  sizing.outerRightIliacDiameter = p.rightIliacDiameterMm;
  sizing.outerLeftIliacDiameter = p.leftIliacDiameterMm;
  // The lumen: the outer wall less the wall, less the thrombus where there is one.
  const auto lumenRadius = [&](double h) { return wall ? wall->LumenRadius(h) : radiusAtZ(h); };
  sizing.proximalNeckDiameter = 2 * lumenRadius(siteZ);
  sizing.neckDiameter15mm = 2 * lumenRadius(siteZ - 15.0);
  NeckBendSectionTruth(anatomy, p, radiusAtZ, sacTop, siteZ - 15.0, onAxis, neckDirection, sizing);
  double widestLumen = 0.0, widestH = siteZ;
  for (double h = 0.0; h <= siteZ; h += 0.01)
    if (lumenRadius(h) > widestLumen)
    {
      widestLumen = lumenRadius(h);
      widestH = h;
    }
  sizing.maxAneurysmDiameter = 2 * widestLumen;
  double narrowestLumen = widestLumen;
  for (double h = 0.0; h <= widestH; h += 0.01)
    narrowestLumen = std::min(narrowestLumen, lumenRadius(h));
  sizing.distalNeckMinDiameter = 2 * narrowestLumen;
  DistalNeckWithWideIliacs(anatomy, lumenRadius, widestH, wall, sizing);
  sizing.rightIliacDiameter = p.rightIliacDiameterMm - 2 * wallMm;
  sizing.leftIliacDiameter = p.leftIliacDiameterMm - 2 * wallMm;
  if (wall)
  {
    sizing.thrombusVolumeMl = wall->ThrombusVolumeMl();
    sizing.maxThrombusThicknessMm = wall->MaxThrombusThicknessMm();
    sizing.neckThrombusArcPercent = wall->NeckThrombusArcPercent();
    sizing.neckCalcificationArcPercent = wall->NeckCalcificationArcPercent();
  }
  // The clinical neck length (vessel-wall.md, the rule-engine convention): from the site to the
  // first level where the diameter exceeds (a) by 10 %; past the sac's top by the shoulder's
  // rise (about 1.6 mm on the default sac), found on the exact radius profile to 1 µm.
  double z10 = sacTop;
  while (z10 > sacBottom && radiusAtZ(z10) < 1.1 * rNeck)
    z10 -= 0.001;
  sizing.proximalNeckLength = siteZ - z10;
  // The healthy neck (the seal a graft can get) and where the neck thrombus covers a quarter.
  sizing.healthyNeckLength = sizing.proximalNeckLength;
  sizing.neckThrombusBelowSite = std::numeric_limits<double>::infinity();
  if (wall)
  {
    bool healthyEnded = false;
    for (double h = siteZ; h >= z10; h -= 0.01)
    {
      int thick = 0;
      for (int k = 0; k < 720; ++k) // 0.5° steps
        thick += wall->ThrombusThicknessAt(h, 0.5 * k) > 2.0 ? 1 : 0;
      if (!healthyEnded && thick > 0.10 * 720)
      {
        sizing.healthyNeckLength = siteZ - h;
        healthyEnded = true;
      }
      if (thick >= 0.25 * 720)
      {
        sizing.neckThrombusBelowSite = siteZ - h;
        break;
      }
    }
  }
  sizing.proximalSiteToBifurcationLength = siteZ;
  sizing.rightIliacLength = p.rightCommonIliacLengthMm;
  sizing.leftIliacLength = p.leftCommonIliacLengthMm;
  sizing.neckAngleBetaDeg = p.neckAngleDeg;
  FlowDividerTruth(anatomy, commonAxes);
  // On the aneurysm lumen's axis at mid-sac (off the vessel's axis where there is a thrombus).
  const double seedH = 0.5 * (sacTop + sacBottom);
  truth.seedLps = wall ? wall->LumenCentreLps(seedH) : Point3(0, 0, seedH);
  // The side branches' own walls (renal, mesenteric, coeliac arteries): a quarter of their radius,
  // at most the aorta's wall. Every artery's lumen meets its wall, not the fat beyond it; without
  // one a branch's edge is a lumen-to-fat step the lumen's half-maximum against its wall misses
  // (issue 32).
  if (wallMm > 0.0)
  {
    const std::size_t branches = anatomy.tubes.size();
    for (std::size_t t = 0; t < branches; ++t)
    {
      const Tube& tube = anatomy.tubes[t];
      if (tube.name == "aorta" || tube.name.find("Iliac") != std::string::npos)
        continue; // the aorta's wall is AorticWall's, the iliacs' wallTubes above
      const double thickness = std::min(wallMm, 0.25 * tube.maxRadius);
      const auto radius = tube.radiusAt;
      anatomy.wallTubes.push_back({ tube.name + "Wall", tube.axis,
                                    [radius, thickness](double s) { return radius(s) + thickness; },
                                    tube.maxRadius + thickness });
    }
  }
  return anatomy;
}

void SampleVessels(const Anatomy& anatomy, PhantomTruth& truth)
{
  for (const Tube& tube : anatomy.tubes)
  {
    std::vector<Point3> points;
    std::vector<double> radii, abscissa;
    double start = 0.0;
    for (std::size_t k = 0; k + 1 < tube.axis.size(); ++k)
    {
      const Point3 a = tube.axis[k], b = tube.axis[k + 1];
      const double length = (b - a).norm();
      for (double s = 0.0; s < length; s += 1.0)
      {
        points.push_back(a + (b - a) * (s / length));
        radii.push_back(tube.radiusAt(start + s));
        abscissa.push_back(start + s);
      }
      start += length;
    }
    points.push_back(tube.axis.back());
    radii.push_back(tube.radiusAt(start));
    abscissa.push_back(start);
    PhantomVessel vessel{ tube.name, Points(points.size(), 3), Eigen::VectorXd(radii.size()),
                          Eigen::VectorXd(radii.size()), Eigen::VectorXd() };
    // The largest sphere centred on the axis at s touches the wall where sqrt((s' − s)² + r(s')²)
    // is smallest (exact on straight pieces; the bent vessels have a constant radius).
    std::vector<double> fine;
    for (double s = 0.0; s <= start; s += 0.05)
      fine.push_back(tube.radiusAt(s));
    for (std::size_t i = 0; i < points.size(); ++i)
    {
      vessel.axis.row(i) = points[i].transpose();
      vessel.radiusMm[i] = radii[i];
      const double si = abscissa[i];
      double inscribed = radii[i];
      for (std::size_t j = 0; j < fine.size(); ++j)
        inscribed = std::min(inscribed, std::hypot(0.05 * double(j) - si, fine[j]));
      vessel.inscribedRadiusMm[i] = inscribed;
    }
    if (tube.name == "aorta" && anatomy.wall)
    {
      vessel.outerRadiusMm.resize(radii.size());
      for (std::size_t i = 0; i < points.size(); ++i)
        vessel.outerRadiusMm[i] = anatomy.wall->OuterRadius(anatomy.wall->At(points[i]).h);
    }
    truth.vessels.push_back(vessel);
  }
}

std::array<Point3, 2> AnatomyBounds(const Anatomy& anatomy)
{
  Point3 lo = Point3::Constant(1e9), hi = Point3::Constant(-1e9);
  for (const Tube& tube : anatomy.tubes)
  {
    for (const Point3& v : tube.axis)
    {
      lo = lo.cwiseMin(v - Point3::Constant(tube.maxRadius));
      hi = hi.cwiseMax(v + Point3::Constant(tube.maxRadius));
    }
  }
  for (const Ellipsoid& e : anatomy.kidneys)
  {
    lo = lo.cwiseMin(e.centre - e.semiAxes);
    hi = hi.cwiseMax(e.centre + e.semiAxes);
  }
  if (anatomy.wall)
  {
    const auto [wallLo, wallHi] = anatomy.wall->BoundsLps(0.0);
    lo = lo.cwiseMin(wallLo);
    hi = hi.cwiseMax(wallHi);
  }
  if (anatomy.column)
  {
    lo = lo.cwiseMin(Point3(-vertebraRadiusMm, anatomy.columnY - vertebraRadiusMm, lo.z()));
    hi = hi.cwiseMax(Point3(vertebraRadiusMm, anatomy.columnY + vertebraRadiusMm, hi.z()));
  }
  return { lo - Point3::Constant(marginMm), hi + Point3::Constant(marginMm) };
}

std::array<Point3, 2> TubeBox(const Tube& tube, double reach)
{
  Point3 lo = Point3::Constant(1e9), hi = Point3::Constant(-1e9);
  for (const Point3& v : tube.axis)
  {
    lo = lo.cwiseMin(v - Point3::Constant(tube.maxRadius + reach));
    hi = hi.cwiseMax(v + Point3::Constant(tube.maxRadius + reach));
  }
  return { lo, hi };
}

} // namespace sgp::phantom
