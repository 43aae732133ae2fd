#include "Phantom/AorticPhantom.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <random>

#include <Eigen/Dense>

#include "Common/CheckRange.h"
#include "Common/Errors.h"
#include "Common/Format.h"
#include "Phantom/AorticWall.h"

namespace sgp
{

namespace
{

constexpr double pi = 3.14159265358979323846;
constexpr double renalRadiusMm = 3.0;
constexpr double renalHilumLateralMm = 64.0, renalHilumPosteriorMm = 10.0; ///< from the renal's origin
constexpr double visceralRadiusMm = 3.5;
constexpr double accessoryRenalRadiusMm = 2.0;
constexpr double imaRadiusMm = 1.75;
constexpr double renalBranchRadiusMm = 2.2;
constexpr double renalBranchTurnDeg = 25.0;
constexpr double distalNeckLengthMm = 20.0;
constexpr double commonIliacAngleDeg = 25.0;
constexpr double kinkFromBifurcationMm = 10.0; ///< where a kinked common iliac bends
constexpr double vertebraRadiusMm = 20.0;
constexpr double corticalThicknessMm = 2.0;
constexpr double corticalHu = 1100.0; // blurred by 1 mm, the 2 mm shell peaks near 800 HU
constexpr double cancellousHu = 250.0;
constexpr double marginMm = 10.0;

/// A vessel to voxelize: an axis polyline and the radius as a function of arc length from its
/// first vertex.
struct Tube
{
  std::string name;
  std::vector<Point3> axis;
  std::function<double(double)> radiusAt;
  double maxRadius = 0.0;
};

struct Ellipsoid
{
  Point3 centre;
  Point3 semiAxes;
};

struct Anatomy
{
  std::vector<Tube> tubes;          ///< lumens
  std::vector<Tube> wallTubes;      ///< the iliacs' outer walls (drawn at wallHu; their lumens override)
  std::unique_ptr<AorticWall> wall; ///< the aorta's wall, thrombus, calcium and neighbours, if any
  double siteZ = 0.0;               ///< the proximal implantation site's height (bolus gradient reference)
  std::vector<Ellipsoid> kidneys;
  bool column = false;
  double columnY = 0.0; ///< centre of the vertebral column (x = 0), LPS mm
  PhantomTruth truth;
};

/// Standard normal CDF, with the hard step for an unblurred edge.
double EdgeProfile(double signedDistance, double sigma)
{
  if (sigma <= 0.0)
  {
    return signedDistance < 0.0 ? 1.0 : (signedDistance > 0.0 ? 0.0 : 0.5);
  }
  return 0.5 * std::erfc(signedDistance / (sigma * std::sqrt(2.0)));
}

Point3 Unit(double x, double y, double z)
{
  return Point3(x, y, z).normalized();
}

Tube StraightTube(const std::string& name, const std::vector<Point3>& axis, double radius)
{
  return { name, axis, [radius](double) { return radius; }, radius };
}

/// The LPS box {min, max} of a tube's voxels, its radius and `reach` (the blur) around its axis.
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

Anatomy BuildAnatomy(const PhantomParams& p)
{
  Anatomy anatomy;
  PhantomTruth& truth = anatomy.truth;
  const double rNeck = p.neckDiameterMm / 2, rDistal = p.distalNeckDiameterMm / 2;
  const double sacBottom = distalNeckLengthMm, sacTop = sacBottom + p.aneurysmLengthMm;
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
    siteZ + OstiumLowerEdgeDepthMm(siteLumenRadius, renalRadiusMm, rightRenalDirection, neckDirection);
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

  const double angle = commonIliacAngleDeg * pi / 180.0;
  Point3 iliacEnd[2];
  const char* sideName[2] = { "right", "left" };
  const double iliacRadius[2] = { p.rightIliacDiameterMm / 2, p.leftIliacDiameterMm / 2 };
  const double commonIliacLengthMm[2] = { p.rightCommonIliacLengthMm, p.leftCommonIliacLengthMm };
  for (int side = 0; side < 2; ++side)
  {
    const double lateral = side == 0 ? -1.0 : 1.0; // patient right is -x in LPS
    const std::string prefix = sideName[side];
    const double r = iliacRadius[side]; // outer; the lumen lies the wall's thickness inside
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
    anatomy.tubes.push_back(StraightTube(prefix + "InternalIliac", internal, lumenOf(0.55 * r)));
    (side == 0 ? truth.sizing.rightInternalIliacRadius : truth.sizing.leftInternalIliacRadius) = lumenOf(0.55 * r);
    // The internal iliac's ostium on the common iliac's wall: its most upstream point along the
    // common iliac's axis (the branch leaves that axis at its end; an oblique branch's ostium starts
    // there, where the common iliac divides).
    const Eigen::Vector3d commonAxis = (common.back() - common[common.size() - 2]).normalized();
    (side == 0 ? truth.sizing.rightInternalIliacOstium : truth.sizing.leftInternalIliacOstium) =
      commonIliacLengthMm[side] -
      OstiumLowerEdgeDepthMm(r - wallMm, lumenOf(0.55 * r), (internal[1] - internal[0]).normalized(), commonAxis);
    if (wallMm > 0.0)
    {
      anatomy.wallTubes.push_back(StraightTube(prefix + "IliacWall", common, r));
      anatomy.wallTubes.push_back(StraightTube(prefix + "ExternalIliacWall", external, 0.75 * r));
      anatomy.wallTubes.push_back(StraightTube(prefix + "InternalIliacWall", internal, 0.55 * r));
    }
    const double renalZ = side == 0 ? rightRenalZ : leftRenalZ;
    const Point3 hilum = onAxis(renalZ) + renalCourse(lateral);
    if (p.includeRenals)
      AddRenal(anatomy, prefix + "Renal", onAxis(renalZ), hilum, renalRadiusMm, siteLumenRadius, p);
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
  // On the aneurysm lumen's axis at mid-sac (off the vessel's axis where there is a thrombus).
  const double seedH = 0.5 * (sacTop + sacBottom);
  truth.seedLps = Point3(0, 0, seedH);
  if (wall)
  {
    const auto frame = wall->Frame(seedH);
    const Eigen::Vector2d c = wall->LumenCentre(seedH);
    truth.seedLps += c.x() * frame[0] + c.y() * frame[1];
  }
  return anatomy;
}

/// Samples each tube's axis every 1 mm (and at its end) with the radius there.
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
                          Eigen::VectorXd(radii.size()) };
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
    truth.vessels.push_back(vessel);
  }
}

/// LPS bounding box {min, max} of the anatomy plus the margin.
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

/// The voxel grid: LPS of voxel (i,j,k) is origin + direction · diag(spacing) · (i,j,k).
struct Grid
{
  Point3 origin;
  Eigen::Matrix3d direction;
  Eigen::Vector3d spacing;
  std::array<long, 3> size;
  Eigen::Matrix3d IndexToLps() const { return direction * spacing.asDiagonal(); }
  long Flat(long i, long j, long k) const { return i + size[0] * (j + size[1] * k); }
};

Grid MakeGrid(const PhantomParams& p, const std::array<Point3, 2>& bounds)
{
  Grid grid;
  grid.direction = p.directionLps;
  grid.spacing = Eigen::Vector3d(p.spacingMm[0], p.spacingMm[1], p.spacingMm[2]);
  Eigen::Vector3d uMin = Eigen::Vector3d::Constant(1e18), uMax = -uMin;
  for (int corner = 0; corner < 8; ++corner)
  {
    const Point3 c((corner & 1 ? bounds[1] : bounds[0]).x(), (corner & 2 ? bounds[1] : bounds[0]).y(),
                   (corner & 4 ? bounds[1] : bounds[0]).z());
    const Eigen::Vector3d u = grid.direction.transpose() * c;
    uMin = uMin.cwiseMin(u);
    uMax = uMax.cwiseMax(u);
  }
  Eigen::Vector3d first = uMin;
  for (int a = 0; a < 3; ++a)
  {
    if (p.sizeVoxels[a] > 0)
    {
      grid.size[a] = p.sizeVoxels[a];
      first[a] = 0.5 * (uMin[a] + uMax[a]) - 0.5 * (grid.size[a] - 1) * grid.spacing[a];
    }
    else
    {
      grid.size[a] = static_cast<long>(std::ceil((uMax[a] - uMin[a]) / grid.spacing[a])) + 1;
    }
  }
  grid.origin = grid.direction * first;
  return grid;
}

/// Calls f(flat, lps) for every voxel of the grid whose centre may lie within the LPS box.
template<typename Function>
void ForEachVoxelNear(const Grid& grid, const Point3& lo, const Point3& hi, Function f)
{
  const Eigen::Matrix3d toIndex = grid.IndexToLps().inverse();
  Eigen::Vector3d iMin = Eigen::Vector3d::Constant(1e18), iMax = -iMin;
  for (int corner = 0; corner < 8; ++corner)
  {
    const Point3 c((corner & 1 ? hi : lo).x(), (corner & 2 ? hi : lo).y(), (corner & 4 ? hi : lo).z());
    const Eigen::Vector3d index = toIndex * (c - grid.origin);
    iMin = iMin.cwiseMin(index);
    iMax = iMax.cwiseMax(index);
  }
  std::array<long, 3> first{}, last{};
  for (int a = 0; a < 3; ++a)
  {
    first[a] = std::max(0L, static_cast<long>(std::floor(iMin[a])));
    last[a] = std::min(grid.size[a] - 1, static_cast<long>(std::ceil(iMax[a])));
  }
  const Eigen::Matrix3d m = grid.IndexToLps();
  for (long k = first[2]; k <= last[2]; ++k)
  {
    for (long j = first[1]; j <= last[1]; ++j)
    {
      for (long i = first[0]; i <= last[0]; ++i)
      {
        f(grid.Flat(i, j, k), Point3(grid.origin + m * Eigen::Vector3d(double(i), double(j), double(k))));
      }
    }
  }
}

/// Signed distance to a tube's surface by the closest-axis-point rule (see the header), for the
/// voxels of a grid visited in order. The closest point is the first axis segment (in axis order)
/// at the least distance, as a plain scan of every segment finds it, and every value is computed
/// by the same arithmetic, so the phantom is the same voxel for voxel; what changes is the cost:
/// segments are grouped in runs of `RunLength` inside bounding spheres, the run that held the
/// previous voxel's closest point is scanned first, and a run whose sphere lies farther than the
/// best distance so far is skipped.
class TubeDistance
{
public:
  explicit TubeDistance(const Tube& tube)
    : m_Tube(tube)
  {
    double start = 0.0;
    for (std::size_t k = 0; k + 1 < tube.axis.size(); ++k)
    {
      Segment segment;
      segment.a = tube.axis[k];
      segment.ab = tube.axis[k + 1] - segment.a;
      segment.length = segment.ab.norm();
      segment.start = start;
      m_Segments.push_back(segment);
      start += segment.length;
    }
    for (std::size_t first = 0; first < m_Segments.size(); first += RunLength)
    {
      const std::size_t end = std::min(m_Segments.size(), first + RunLength);
      Point3 lo = m_Segments[first].a, hi = lo;
      for (std::size_t k = first; k < end; ++k)
        for (const Point3& v : { m_Segments[k].a, Point3(m_Segments[k].a + m_Segments[k].ab) })
        {
          lo = lo.cwiseMin(v);
          hi = hi.cwiseMax(v);
        }
      Run run{ first, end, 0.5 * (lo + hi), 0.0 };
      for (std::size_t k = first; k < end; ++k)
        run.radius = std::max({ run.radius, (m_Segments[k].a - run.centre).norm(),
                                (m_Segments[k].a + m_Segments[k].ab - run.centre).norm() });
      m_Runs.push_back(run);
    }
  }

  double SignedDistance(const Point3& x)
  {
    Closest closest;
    if (m_Runs.empty())
    {
      return closest.distance - m_Tube.radiusAt(0.0); // no segment: farther than any voxel
    }
    Scan(m_Runs[m_HintRun], x, closest);
    for (std::size_t r = 0; r < m_Runs.size(); ++r)
    {
      // A margin far above the rounding of these few operations: a run is skipped only when each
      // of its points lies strictly farther than the best so far.
      if (r != m_HintRun && (x - m_Runs[r].centre).norm() - m_Runs[r].radius <= closest.distance + 1e-6)
      {
        Scan(m_Runs[r], x, closest);
      }
    }
    m_HintRun = closest.segment / RunLength;
    return closest.distance - m_Tube.radiusAt(closest.s);
  }

private:
  static constexpr std::size_t RunLength = 16;
  struct Segment
  {
    Point3 a, ab;
    double length = 0.0, start = 0.0;
  };
  struct Run
  {
    std::size_t first = 0, end = 0;
    Point3 centre;
    double radius = 0.0;
  };
  struct Closest
  {
    double distance = 1e18, s = 0.0;
    std::size_t segment = std::numeric_limits<std::size_t>::max();
  };

  void Scan(const Run& run, const Point3& x, Closest& closest) const
  {
    for (std::size_t k = run.first; k < run.end; ++k)
    {
      const Segment& g = m_Segments[k];
      const double t = std::clamp((x - g.a).dot(g.ab) / (g.length * g.length), 0.0, 1.0);
      const double d = (x - (g.a + t * g.ab)).norm();
      // The first segment in axis order among those at the least distance.
      if (d < closest.distance || (d == closest.distance && k < closest.segment))
      {
        closest.distance = d;
        closest.s = g.start + t * g.length;
        closest.segment = k;
      }
    }
  }

  const Tube& m_Tube;
  std::vector<Segment> m_Segments;
  std::vector<Run> m_Runs;
  std::size_t m_HintRun = 0;
};

double EllipsoidSignedDistance(const Ellipsoid& e, const Point3& x)
{
  const Eigen::Vector3d q = (x - e.centre).cwiseQuotient(e.semiAxes);
  const double f = q.norm();
  if (f < 1e-9)
  {
    return -e.semiAxes.minCoeff();
  }
  const double gradient = (q.cwiseQuotient(e.semiAxes) / f).norm();
  return (f - 1.0) / gradient;
}

/// The aorta's outer body (thrombus HU), wall, calcification and neighbour pads (AorticWall.h),
/// each blurred like every other edge and the brightest taken where they meet. Labels by
/// priority: calcium, wall, thrombus, neighbours (the lumens, drawn after, override them all).
void DrawAorticWall(const AorticWall& wall,
                    const PhantomParams& p,
                    const Grid& grid,
                    double reach,
                    std::vector<float>& contrast,
                    std::vector<unsigned char>& labels)
{
  const double outward = wall.ReachMm() + reach;
  const auto [lo, hi] = wall.BoundsLps(reach);
  const double sigma = p.blurSigmaMm;
  ForEachVoxelNear(grid, lo, hi,
                   [&](long flat, const Point3& x)
                   {
                     const AorticWall::Coordinates c = wall.At(x);
                     if (c.rho > outward || c.beyondMm > reach)
                       return;
                     const double ends = c.beyondMm; // past the aorta's top or below the bifurcation
                     const double outer = std::max(wall.OuterSignedDistance(c), ends);
                     const double shell = std::max(wall.WallSignedDistance(c), ends);
                     float value = contrast[flat];
                     unsigned char label = labels[flat];
                     const auto take = [&](double hu, double sd, unsigned char l, bool inside)
                     {
                       value = std::max(value, float((hu - p.tissueHu) * EdgeProfile(sd, sigma)));
                       if (inside && sd < 0.0)
                         label = l;
                     };
                     // Lowest priority first: each later label overwrites.
                     for (const WallNeighbour& n : wall.Neighbours())
                       take(n.hu, std::max(wall.NeighbourSignedDistance(c, n), ends), n.label, true);
                     if (wall.HasThrombus())
                       take(p.thrombusHu, outer, ThrombusLabel, true);
                     take(p.wallHu, shell, WallLabel, true);
                     for (const WallCalcification& w : wall.Calcifications())
                       take(p.calcificationHu, std::max(wall.CalcificationSignedDistance(c, w), ends), CalciumLabel,
                            true);
                     contrast[flat] = value;
                     labels[flat] = label;
                   });
}

} // namespace

void ValidatePhantomParams(const PhantomParams& p)
{
  const auto check = CheckRange;
  const char* axes[3] = { "i", "j", "k" };
  int sized = 0;
  for (int a = 0; a < 3; ++a)
  {
    check(std::string("spacingMm (") + axes[a] + ")", p.spacingMm[a], 0.2, 5.0, "mm");
    if (p.sizeVoxels[a] != 0)
    {
      check(std::string("sizeVoxels (") + axes[a] + ")", p.sizeVoxels[a], 16, 2048, "voxels");
      ++sized;
    }
  }
  if (sized != 0 && sized != 3)
  {
    throw InputError("sizeVoxels must be 0,0,0 (fit the anatomy) or three sizes; got " +
                     std::to_string(p.sizeVoxels[0]) + "," + std::to_string(p.sizeVoxels[1]) + "," +
                     std::to_string(p.sizeVoxels[2]) + ".");
  }
  const double orthonormalError = (p.directionLps.transpose() * p.directionLps - Eigen::Matrix3d::Identity()).norm();
  if (!(orthonormalError < 1e-4))
  {
    throw InputError("directionLps is not orthonormal (|DᵀD − I| = " + FormatNumber(orthonormalError, 4) +
                     "); give three unit, mutually perpendicular axis directions.");
  }
  check("neckDiameterMm", p.neckDiameterMm, 12, 40, "mm");
  check("neckLengthMm", p.neckLengthMm, 2, 60, "mm");
  check("maxAneurysmDiameterMm", p.maxAneurysmDiameterMm, std::max(p.neckDiameterMm, p.distalNeckDiameterMm), 100,
        "mm");
  check("aneurysmLengthMm", p.aneurysmLengthMm, 20, 200, "mm");
  check("distalNeckDiameterMm", p.distalNeckDiameterMm, 10, 40, "mm");
  check("rightIliacDiameterMm", p.rightIliacDiameterMm, 5, 30, "mm");
  check("leftIliacDiameterMm", p.leftIliacDiameterMm, 5, 30, "mm");
  check("rightCommonIliacLengthMm", p.rightCommonIliacLengthMm, 10, 80, "mm");
  check("leftCommonIliacLengthMm", p.leftCommonIliacLengthMm, 10, 80, "mm");
  check("lumenHu", p.lumenHu, 100, 1000, "HU");
  check("tissueHu", p.tissueHu, -200, 100, "HU");
  check("blurSigmaMm", p.blurSigmaMm, 0, 3, "mm");
  check("noiseSigmaHu", p.noiseSigmaHu, 0, 200, "HU");
  check("noiseSeed", p.noiseSeed, 0, 2147483647.0, "");
  check("boneGapMm", p.boneGapMm, 0.5, 50, "mm");
  check("kidneyHu", p.kidneyHu, 50, 400, "HU");
  check("neckAngleDeg", p.neckAngleDeg, 0, 75, "degrees");
  check("wallThicknessMm", p.wallThicknessMm, 0, 4, "mm");
  check("wallHu", p.wallHu, -200, 400, "HU");
  check("thrombusMaxThicknessMm", p.thrombusMaxThicknessMm, 0, 40, "mm");
  check("thrombusHu", p.thrombusHu, -200, 400, "HU");
  check("neckThrombusThicknessMm", p.neckThrombusThicknessMm, 0, 15, "mm");
  check("neckThrombusLengthMm", p.neckThrombusLengthMm, 3, 60, "mm");
  check("calcificationHu", p.calcificationHu, 200, 3000, "HU");
  check("sacCalcificationArcDeg", p.sacCalcificationArcDeg, 0, 360, "degrees");
  check("neckCalcificationArcDeg", p.neckCalcificationArcDeg, 0, 360, "degrees");
  check("psoasHu", p.psoasHu, -200, 400, "HU");
  check("ivcHu", p.ivcHu, -200, 400, "HU");
  check("duodenumHu", p.duodenumHu, -200, 400, "HU");
  check("leftRenalVeinHu", p.leftRenalVeinHu, -200, 400, "HU");
  check("ivcArcDeg", p.ivcArcDeg, 72, 180, "degrees");
  check("sacAxisRatio", p.sacAxisRatio, 1, 1.5, "");
  check("bolusGradientHuPerCm", p.bolusGradientHuPerCm, -10, 10, "HU/cm");
  check("aortaAboveSiteMm", p.aortaAboveSiteMm, 20, 400, "mm");
  check("renalDescentDeg", p.renalDescentDeg, 0, 65, "degrees");
  check("renalTakeoffDeg", p.renalTakeoffDeg, -60, 60, "degrees");
  check("renalStubMm", p.renalStubMm, 0, 60, "mm");
  check("renalDivisionMm", p.renalDivisionMm, 0, 40, "mm");
  check("accessoryRenalOffsetMm", p.accessoryRenalOffsetMm, -40, 40, "mm");
  check("commonIliacKinkDeg", p.commonIliacKinkDeg, 0, 60, "degrees");
  if (p.accessoryRenalOffsetMm != 0.0 && std::abs(p.accessoryRenalOffsetMm) < 8.0)
    throw InputError("accessoryRenalOffsetMm is " + FormatNumber(p.accessoryRenalOffsetMm) +
                     " mm; expected 0 (none) or at least 8 mm above or below the right renal.");
  const bool needsWall = p.thrombusMaxThicknessMm > 0 || p.neckThrombusThicknessMm > 0 ||
                         p.sacCalcificationArcDeg > 0 || p.neckCalcificationArcDeg > 0 || p.includePsoas ||
                         p.includeIvc || p.includeDuodenum || p.includeLeftRenalVein;
  if (needsWall && !(p.wallThicknessMm > 0))
    throw InputError("Thrombus, calcification and the neighbours lie in or against the vessel wall; wallThicknessMm is "
                     "0 — give a wall (e.g. 1.5 mm).");
  if (p.sacAxisRatio > 1.0 && !(p.thrombusMaxThicknessMm > 0))
    throw InputError("sacAxisRatio is " + FormatNumber(p.sacAxisRatio) +
                     "; an elliptical sac is filled by thrombus around its round lumen — give "
                     "thrombusMaxThicknessMm > 0 (or sacAxisRatio 1).");
  // The lumen must keep at least a quarter of the inner wall's radius where the thrombus is thickest.
  const double innerSac = p.maxAneurysmDiameterMm / 2 - p.wallThicknessMm;
  const double sacThrombus = (p.thrombusConcentric ? 1.0 : 0.5) * p.thrombusMaxThicknessMm;
  if (p.thrombusMaxThicknessMm > 0 && innerSac - sacThrombus < 0.25 * innerSac)
    throw InputError("thrombusMaxThicknessMm (" + FormatNumber(p.thrombusMaxThicknessMm) +
                     " mm) leaves less than a quarter of the sac's inner radius (" + FormatNumber(innerSac) +
                     " mm) as lumen; give a thinner thrombus or a wider sac.");
  const double innerNeck = p.neckDiameterMm / 2 - p.wallThicknessMm;
  if (p.neckThrombusThicknessMm > 0.75 * innerNeck ||
      p.wallThicknessMm > 0.25 * std::min(p.rightIliacDiameterMm, p.leftIliacDiameterMm))
    throw InputError("The wall and neck thrombus leave too little lumen (neck inner radius " + FormatNumber(innerNeck) +
                     " mm, neckThrombusThicknessMm " + FormatNumber(p.neckThrombusThicknessMm) +
                     " mm, wallThicknessMm " + FormatNumber(p.wallThicknessMm) + " mm); make them thinner.");
}

double SideDegrees(PhantomSide side)
{
  switch (side)
  {
    case PhantomSide::Anterior:
      return 0.0;
    case PhantomSide::Left:
      return 90.0;
    case PhantomSide::Posterior:
      return 180.0;
    case PhantomSide::Right:
      return 270.0;
  }
  return 0.0;
}

PhantomSide ParsePhantomSide(const std::string& text, const std::string& parameter)
{
  if (text == "anterior")
    return PhantomSide::Anterior;
  if (text == "left")
    return PhantomSide::Left;
  if (text == "posterior")
    return PhantomSide::Posterior;
  if (text == "right")
    return PhantomSide::Right;
  throw InputError(parameter + " is '" + text + "'; expected anterior, left, posterior or right.");
}

AorticPhantom GenerateAorticPhantom(const PhantomParams& p, const ProgressCallback& progress)
{
  ValidatePhantomParams(p);
  Anatomy anatomy = BuildAnatomy(p);
  SampleVessels(anatomy, anatomy.truth);
  const Grid grid = MakeGrid(p, AnatomyBounds(anatomy));
  const long count = grid.size[0] * grid.size[1] * grid.size[2];
  std::vector<float> contrast(static_cast<std::size_t>(count), 0.0f);
  std::vector<unsigned char> labels(static_cast<std::size_t>(count), TissueLabel);
  const double reach = 4.0 * p.blurSigmaMm + grid.spacing.norm();

  if (anatomy.wall)
  {
    ReportProgress(progress, 0.0, "Vessel wall");
    DrawAorticWall(*anatomy.wall, p, grid, reach, contrast, labels);
    for (const Tube& tube : anatomy.wallTubes)
    {
      const auto [lo, hi] = TubeBox(tube, reach);
      TubeDistance distance(tube);
      ForEachVoxelNear(grid, lo, hi,
                       [&](long flat, const Point3& x)
                       {
                         const double sd = distance.SignedDistance(x);
                         contrast[flat] =
                           std::max(contrast[flat], float((p.wallHu - p.tissueHu) * EdgeProfile(sd, p.blurSigmaMm)));
                         if (sd < 0.0 && labels[flat] == TissueLabel)
                           labels[flat] = WallLabel;
                       });
    }
  }

  for (std::size_t t = 0; t < anatomy.tubes.size(); ++t)
  {
    ReportProgress(progress, 0.7 * double(t) / anatomy.tubes.size(), "Vessels");
    const Tube& tube = anatomy.tubes[t];
    const auto [lo, hi] = TubeBox(tube, reach);
    TubeDistance distance(tube);
    ForEachVoxelNear(grid, lo, hi,
                     [&](long flat, const Point3& x)
                     {
                       const double sd = distance.SignedDistance(x);
                       // The bolus's cranio-caudal gradient, from the site's level (0 by default).
                       const double lumenContrast =
                         p.lumenHu + p.bolusGradientHuPerCm * (x.z() - anatomy.siteZ) / 10.0 - p.tissueHu;
                       contrast[flat] = std::max(contrast[flat], float(lumenContrast * EdgeProfile(sd, p.blurSigmaMm)));
                       if (sd < 0.0)
                       {
                         labels[flat] = LumenLabel;
                       }
                     });
  }
  for (const Ellipsoid& kidney : anatomy.kidneys)
  {
    ForEachVoxelNear(grid, kidney.centre - kidney.semiAxes - Point3::Constant(reach),
                     kidney.centre + kidney.semiAxes + Point3::Constant(reach),
                     [&](long flat, const Point3& x)
                     {
                       const double sd = EllipsoidSignedDistance(kidney, x);
                       contrast[flat] =
                         std::max(contrast[flat], float((p.kidneyHu - p.tissueHu) * EdgeProfile(sd, p.blurSigmaMm)));
                       if (sd < 0.0 && labels[flat] == TissueLabel)
                       {
                         labels[flat] = KidneyLabel;
                       }
                     });
  }
  if (anatomy.column)
  {
    ReportProgress(progress, 0.75, "Vertebral column");
    const double r = vertebraRadiusMm + reach;
    ForEachVoxelNear(grid, Point3(-r, anatomy.columnY - r, -1e6), Point3(r, anatomy.columnY + r, 1e6),
                     [&](long flat, const Point3& x)
                     {
                       const double rho = std::hypot(x.x(), x.y() - anatomy.columnY);
                       const double outer = rho - vertebraRadiusMm, inner = outer + corticalThicknessMm;
                       const double bone = (corticalHu - p.tissueHu) * EdgeProfile(outer, p.blurSigmaMm) -
                                           (corticalHu - cancellousHu) * EdgeProfile(inner, p.blurSigmaMm);
                       contrast[flat] = std::max(contrast[flat], float(bone));
                       if (outer < 0.0 && labels[flat] == TissueLabel)
                       {
                         labels[flat] = BoneLabel;
                       }
                     });
  }

  ReportProgress(progress, 0.8, "Noise");
  AorticPhantom phantom;
  const auto makeImage = [&](auto image)
  {
    typename decltype(image)::ObjectType::RegionType region;
    region.SetSize(
      { { itk::SizeValueType(grid.size[0]), itk::SizeValueType(grid.size[1]), itk::SizeValueType(grid.size[2]) } });
    image->SetRegions(region);
    image->SetSpacing(grid.spacing.data());
    image->SetOrigin(grid.origin.data());
    typename decltype(image)::ObjectType::DirectionType direction;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        direction(r, c) = grid.direction(r, c);
    image->SetDirection(direction);
    image->Allocate();
    return image;
  };
  phantom.ct = makeImage(CtImage::New());
  phantom.labels = makeImage(LabelImage::New());
  std::mt19937 generator(static_cast<std::mt19937::result_type>(p.noiseSeed));
  std::normal_distribution<double> noise(0.0, p.noiseSigmaHu > 0 ? p.noiseSigmaHu : 1.0);
  short* ct = phantom.ct->GetBufferPointer();
  long lumenVoxels = 0;
  for (long flat = 0; flat < count; ++flat)
  {
    const double value = p.tissueHu + contrast[flat] + (p.noiseSigmaHu > 0 ? noise(generator) : 0.0);
    ct[flat] = static_cast<short>(std::lround(std::clamp(value, -1024.0, 3071.0)));
    phantom.labels->GetBufferPointer()[flat] = labels[flat];
    lumenVoxels += labels[flat] == LumenLabel ? 1 : 0;
  }
  phantom.truth = anatomy.truth;
  phantom.truth.lumenVolumeMl = lumenVoxels * grid.spacing.prod() / 1000.0;
  ReportProgress(progress, 1.0, "Done");
  return phantom;
}

} // namespace sgp
