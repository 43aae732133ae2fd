// The outer wall (issue 12, item 2) against the wall phantom's analytic outer wall: its diameter
// plane by plane, where it rests when neighbours touch the vessel, and its support flags.
#include <cmath>
#include <iostream>
#include <ostream>
#include <string>

#include <gtest/gtest.h>

#include "Common/Errors.h"
#include "Phantom/AorticPhantom.h"
#include "PipelineSupport.h"
#include "Wall/SegmentOuterWall.h"
#include "Wall/VesselWall.h"

namespace sgp
{
namespace
{

/// 1.0 mm: the issue's bar for outer diameters on 0.8 × 0.8 × 1.0 mm voxels (the half-maximum edge
/// of a blurred step lies on the analytic surface; noise moves each ray's crossing by a few
/// tenths, which the circle fit averages).
constexpr double outerDiameterMm = 1.0;

constexpr double degreesPerRadian = 180.0 / 3.14159265358979323846;

/// The default anatomy with a 25 mm outer neck, a 1.5 mm wall, an anterior crescent of sac
/// thrombus 15 mm thick, in fat (−100 HU), noise 20 HU.
PhantomParams WallPhantom()
{
  PhantomParams p;
  p.neckDiameterMm = 25.0;
  p.wallThicknessMm = 1.5;
  p.thrombusMaxThicknessMm = 15.0;
  p.tissueHu = -100.0;
  return p;
}

/// A phantom, its centerlines and the outer wall traced along its aorta.
struct Traced
{
  AorticPhantom phantom;
  CenterlineTree tree;
  OuterWall wall;
  LabelImage::Pointer lumen;
};

Traced Trace(const PhantomParams& p, const OuterWallParams& params = {})
{
  Traced t{ GenerateAorticPhantom(p), {}, {}, nullptr };
  t.lumen = GrowLumenRegion(*t.phantom.ct, t.phantom.truth.seedLps, RegionGrowingParams{}).mask;
  t.tree = testing::CenterlinesFromMask(*t.lumen);
  t.wall = SegmentOuterWall(*t.phantom.ct, *t.lumen, t.tree.aorta, 0.0, t.tree.aorta.LengthMm(), params);
  return t;
}

/// The plane whose centre lies nearest height z (the aorta's centerline runs from its top down).
const OuterWallPlane& PlaneAtHeight(const OuterWall& wall, double z)
{
  const OuterWallPlane* best = &wall.planes.front();
  for (const OuterWallPlane& p : wall.planes)
    if (std::abs(p.centreLps.z() - z) < std::abs(best->centreLps.z() - z))
      best = &p;
  return *best;
}

TEST(SegmentOuterWall, ThrombusInFat_OuterDiametersAtNeckAndSacWithinTheBar)
{
  const Traced t = Trace(WallPhantom());
  const PhantomSizing& s = t.phantom.truth.sizing;
  const double site = s.proximalSiteToBifurcationLength;
  // (a) at the site, the neck 10 mm lower, and Dmax at mid-sac (z = 60 mm).
  const OuterWallPlane& a = PlaneAtHeight(t.wall, site);
  EXPECT_NEAR(a.areaDiameterMm, s.outerProximalNeckDiameter, outerDiameterMm);
  const OuterWallPlane& neck = PlaneAtHeight(t.wall, site - 10.0);
  EXPECT_NEAR(neck.areaDiameterMm, 25.0, outerDiameterMm);
  const OuterWallPlane& sac = PlaneAtHeight(t.wall, 60.0);
  EXPECT_NEAR(sac.areaDiameterMm, s.outerMaxAneurysmDiameter, outerDiameterMm);
  EXPECT_NEAR(sac.maxCaliperMm, s.outerMaxAneurysmDiameter, outerDiameterMm);
  // The lumen lies off-centre in the thrombus, yet the outer wall is round: every ray found it.
  EXPECT_GT(sac.supportedFraction, 0.95);
  // The lumen diameter there is 37 mm: sizing on it would miss the outer wall by 18 mm.
  EXPECT_GT(sac.areaDiameterMm - s.maxAneurysmDiameter, 15.0);
}

TEST(SegmentOuterWall, NeighboursWithoutAFatPlane_WallStaysOnTheVesselAndSaysSo)
{
  PhantomParams p = WallPhantom();
  p.includePsoas = p.includeIvc = true;
  const Traced t = Trace(p);
  const PhantomSizing& s = t.phantom.truth.sizing;
  // Mid-sac: both psoas (2 × 80°) and the IVC (80°, 35° of it over the right psoas) lie against
  // the sac: about 200° of its circumference shows no outer boundary.
  const OuterWallPlane& sac = PlaneAtHeight(t.wall, 60.0);
  EXPECT_LT(sac.supportedFraction, 0.6);
  EXPECT_GT(sac.supportedFraction, 0.3);
  EXPECT_NEAR(sac.areaDiameterMm, s.outerMaxAneurysmDiameter, outerDiameterMm);
  // Nowhere does the contour follow a neighbour out: every ray within the bar of the true wall.
  for (Eigen::Index k = 0; k < sac.contourLps.rows(); ++k)
  {
    const Point3 x = sac.contourLps.row(k).transpose();
    EXPECT_NEAR(std::hypot(x.x(), x.y()), 0.5 * s.outerMaxAneurysmDiameter, outerDiameterMm)
      << "ray " << k << (sac.supported[k] ? " supported" : " from the circle") << ", centre "
      << sac.centreLps.transpose() << ", supported " << sac.supportedFraction << ", area diameter "
      << sac.areaDiameterMm;
  }
}

/// An elliptical sac (issue 31, item 5): axis ratio, the major axis's side, and the IVC against a
/// quarter of the circumference or not.
struct EllipticalSac
{
  double ratio;
  PhantomSide major;
  bool ivcQuarter;
};

void PrintTo(const EllipticalSac& c, std::ostream* os)
{
  *os << "ratio " << c.ratio << ", major axis " << SideDegrees(c.major) << " deg, IVC "
      << (c.ivcQuarter ? "90 deg" : "none");
}

std::string SacName(const ::testing::TestParamInfo<EllipticalSac>& info)
{
  const EllipticalSac& c = info.param;
  return "Ratio" + std::to_string(int(std::lround(c.ratio * 100))) +
         (c.major == PhantomSide::Left ? "Transverse" : "AnteroPosterior") + (c.ivcQuarter ? "IvcQuarter" : "InFat");
}

/// The largest maximum caliper over the traced planes from the bifurcation to the site.
double TracedDmax(const Traced& t, const OuterWallPlane** widest = nullptr)
{
  const double site = t.phantom.truth.sizing.proximalSiteToBifurcationLength;
  const OuterWallPlane* best = nullptr;
  for (const OuterWallPlane& p : t.wall.planes)
    if (p.Usable() && p.centreLps.z() >= 0.0 && p.centreLps.z() <= site &&
        (!best || p.maxCaliperMm > best->maxCaliperMm))
      best = &p;
  if (widest)
    *widest = best;
  return best ? best->maxCaliperMm : 0.0;
}

/// The wall phantom with an elliptical sac.
PhantomParams EllipticalSacPhantom(double ratio, PhantomSide major)
{
  PhantomParams p = WallPhantom();
  p.sacAxisRatio = ratio;
  p.sacMajorAxis = major;
  return p;
}

class EllipticalSacTest : public ::testing::TestWithParam<EllipticalSac>
{
};

TEST_P(EllipticalSacTest, DmaxWithinTheBar)
{
  const EllipticalSac& c = GetParam();
  PhantomParams p = EllipticalSacPhantom(c.ratio, c.major);
  p.includeIvc = c.ivcQuarter;
  p.ivcArcDeg = 90.0; // a quarter of the circumference without a fat plane, on the right
  OuterWallParams params;
  const Traced t = Trace(p, params);
  const PhantomSizing& s = t.phantom.truth.sizing;
  // The truth is the ellipse's major axis near mid-sac: 55 mm × the ratio (0.2 mm: the profile's
  // widest level lies a little off the stretch's peak at mid-sac, where the product peaks).
  ASSERT_NEAR(s.outerMaxAneurysmDiameter, 55.0 * c.ratio, 0.2);
  const OuterWallPlane* widest = nullptr;
  // 1.5 mm: the issue's bar for Dmax with a quarter of the wall invisible (0.8 × 0.8 × 1 mm voxels,
  // noise 20 HU; the round sac reads within 1.0 mm, and the ellipse extrapolated across the
  // quarter adds its fit's error there).
  EXPECT_NEAR(TracedDmax(t, &widest), s.outerMaxAneurysmDiameter, 1.5);
  ASSERT_NE(widest, nullptr);
  // The ellipse completes the plane only where a neighbour hides an arc; in fat every ray is traced.
  EXPECT_EQ(widest->elliptical, c.ivcQuarter);
  // The round lumen inside: the area-equivalent diameter is not Dmax (the ellipse's area).
  EXPECT_NEAR(widest->areaDiameterMm, 55.0 * std::sqrt(c.ratio), 1.5);
  // The neck stays round: the circle's, within the round bar.
  const OuterWallPlane& neck = PlaneAtHeight(t.wall, s.proximalSiteToBifurcationLength - 10.0);
  EXPECT_NEAR(neck.areaDiameterMm, 25.0, outerDiameterMm);
  // The circle alone (no ellipse taken): where a neighbour hides a quarter, the circle completes
  // it and under-reads Dmax beyond the bar — the bug; in fat every ray is traced and the contour
  // is the candidates' (the circle only decides which are kept), so it reads right there too.
  params.maxAxisRatio = 1.0;
  Traced round{ t.phantom, t.tree,
                SegmentOuterWall(*t.phantom.ct, *t.lumen, t.tree.aorta, 0.0, t.tree.aorta.LengthMm(), params),
                t.lumen };
  if (c.ivcQuarter)
    EXPECT_LT(TracedDmax(round), s.outerMaxAneurysmDiameter - 1.5);
  else
    EXPECT_NEAR(TracedDmax(round), s.outerMaxAneurysmDiameter, 1.5);
}

INSTANTIATE_TEST_SUITE_P(Issue31,
                         EllipticalSacTest,
                         ::testing::Values(EllipticalSac{ 1.2, PhantomSide::Left, false },
                                           EllipticalSac{ 1.2, PhantomSide::Left, true },
                                           EllipticalSac{ 1.2, PhantomSide::Anterior, true },
                                           EllipticalSac{ 1.1, PhantomSide::Left, true }),
                         SacName);

/// An elliptical sac in fat with a thin crescent (issue 46 item 9, seed 346 #23: 53.6 mm, ratio
/// 1.13, 4.5 mm of thrombus on the right; Dmax 55.0 for 60.6): the major ends lie 1–4 mm outside
/// the best circle, nothing is hidden, and the circle keeps only the arcs about the minor axis.
/// (Not every such sac: with the crescent on other sides — 60 mm 1.2 left/anterior, 70 mm 1.15
/// anterior/left, 45 mm 1.2 left/right — the circle keeps every ray and reads Dmax right alone.)
struct SacInFat
{
  double sacMm, ratio;
  PhantomSide major, thrombusSide;
};

void PrintTo(const SacInFat& c, std::ostream* os)
{
  *os << c.sacMm << " mm sac, ratio " << c.ratio << ", major axis " << SideDegrees(c.major) << " deg, thrombus side "
      << SideDegrees(c.thrombusSide) << " deg";
}

std::string SacInFatName(const ::testing::TestParamInfo<SacInFat>& info)
{
  const SacInFat& c = info.param;
  const bool transverse = c.major == PhantomSide::Left || c.major == PhantomSide::Right;
  return "Sac" + std::to_string(int(std::lround(c.sacMm * 10))) + "Tenths_Ratio" +
         std::to_string(int(std::lround(c.ratio * 100))) + (transverse ? "Transverse" : "AnteroPosterior");
}

class EllipticalSacInFatTest : public ::testing::TestWithParam<SacInFat>
{
};

TEST_P(EllipticalSacInFatTest, TheEllipseCompletesWhatTheCircleCannotKeep)
{
  const SacInFat& c = GetParam();
  PhantomParams p = EllipticalSacPhantom(c.ratio, c.major);
  p.maxAneurysmDiameterMm = c.sacMm;
  p.thrombusMaxThicknessMm = 4.5;
  p.thrombusSide = c.thrombusSide;
  OuterWallParams params;
  const Traced first = Trace(p, params);
  const PhantomSizing& s = first.phantom.truth.sizing;
  ASSERT_NEAR(s.outerMaxAneurysmDiameter, c.sacMm * c.ratio, 0.3); // the ellipse's major axis
  // The second pass, as VesselWall traces: planes ⊥ the axis through the first pass's contours.
  const Centerline axis = OuterWallAxis(first.wall, "aorta", VesselWallParams{}.axisHalfWindowMm);
  ASSERT_GE(axis.Size(), 2);
  const auto second = [&](const OuterWallParams& q)
  {
    return Traced{ first.phantom, first.tree,
                   SegmentOuterWall(*first.phantom.ct, *first.lumen, first.tree.aorta, 0.0, first.tree.aorta.LengthMm(),
                                    q, &axis),
                   first.lumen };
  };
  const OuterWallPlane* widest = nullptr;
  // 1.5 mm: the issue's bar for Dmax (0.8 × 0.8 × 1 mm voxels, noise 20 HU).
  const Traced traced = second(params); // kept: `widest` points into its planes
  EXPECT_NEAR(TracedDmax(traced, &widest), s.outerMaxAneurysmDiameter, 1.5);
  ASSERT_NE(widest, nullptr);
  // 60 %: the issue's share under which a level is an estimate; in fat the wall shows all round.
  EXPECT_GE(widest->supportedFraction, 0.6);
  // The circle alone where nothing is hidden (the bug): the major ends are the circle's, Dmax
  // short by more than the bar, and the widest plane an estimate.
  params.circleMinimumShare = 0.0;
  const OuterWallPlane* widestRound = nullptr;
  const Traced round = second(params);
  EXPECT_LT(TracedDmax(round, &widestRound), s.outerMaxAneurysmDiameter - 1.5);
  ASSERT_NE(widestRound, nullptr);
  EXPECT_LT(widestRound->supportedFraction, 0.6);
}

INSTANTIATE_TEST_SUITE_P(Issue46,
                         EllipticalSacInFatTest,
                         ::testing::Values(SacInFat{ 53.6, 1.13, PhantomSide::Anterior, PhantomSide::Right },
                                           SacInFat{ 60.0, 1.1, PhantomSide::Left, PhantomSide::Posterior }),
                         SacInFatName);

TEST(SegmentOuterWall, AxisThroughAnEccentricThrombus_StaysOnTheSacsAxis)
{
  // Issue 46 item 3: the axis the second pass's planes are ⊥ to. The phantom's sac is round about
  // the vertical line through B (x = y = 0, AorticWall.h) while its 15 mm anterior crescent moves the
  // lumen, the rays' origin, up to 7.5 mm posterior and tilts the lumen's centerline by up to 17°
  // where the crescent thickens. Traced along the lumen's centerline (the first pass), the axis
  // through the contours must stay on the sac's axis: the mean of the contour's points lay 3.8 mm
  // toward the lumen at mid-sac, and on the shoulders, where a plane tilted by θ cuts a wall
  // widening k mm per mm off-centre by k·R·tan θ, the centroids tilted the axis 5–20°.
  const PhantomParams p = WallPhantom();
  const Traced t = Trace(p);
  const Centerline axis = OuterWallAxis(t.wall, "aorta", 5.0);
  ASSERT_GE(axis.Size(), 2);
  const double sacBottom = p.distalNeckLengthMm, sacTop = sacBottom + p.aneurysmLengthMm;
  int checked = 0;
  double farthest = 0.0, steepest = 0.0;
  for (Eigen::Index i = 1; i + 1 < axis.points.rows(); ++i)
  {
    const Point3 x = axis.points.row(i).transpose();
    // The sac and 10 mm of each neck; 10 mm short of the aorta's ends (the lumen's centerline
    // bends into an iliac there, its contours cut the iliacs' origins).
    if (x.z() < sacBottom - 10.0 || x.z() > sacTop + 10.0)
      continue;
    ++checked;
    // 1.0 mm: a shoulder's planes are traced on half their rays (the fat beyond a wall the plane
    // cuts at a grazing angle follows the edge too slowly) and its centroids stray by up to 3 mm;
    // weighed by the shift their tilt can cause they move the axis 0.7 mm. Every centroid weighing
    // alike: 1.01 mm; the mean of the contour's points: 3.8 mm at mid-sac.
    farthest = std::max(farthest, x.head<2>().norm());
    EXPECT_LT(x.head<2>().norm(), 1.0) << "axis point at height " << x.z() << " mm";
    const Eigen::Vector3d tangent = (axis.points.row(i + 1) - axis.points.row(i - 1)).transpose().normalized();
    // 4°: a plane tilted θ across a shoulder widening k per mm cuts it off-centre by k·R·tan θ,
    // under 1.4 mm here (k ≤ 1 where R ≤ 20 mm). Weighed: 3.0°; every centroid alike: 4.3°; before
    // (the points' mean, a ±5 mm average) the planes tilted 5–20°.
    const double tilt = std::acos(std::min(1.0, std::abs(tangent.z()))) * degreesPerRadian;
    steepest = std::max(steepest, tilt);
    EXPECT_LT(tilt, 4.0) << "axis tangent at height " << x.z() << " mm";
  }
  EXPECT_GT(checked, 80); // the 80 mm sac and its necks' first 10 mm, every 1 mm
  std::cout << "[ axis     ] farthest " << farthest << " mm off the sac's axis, steepest " << steepest << "°\n";
}

TEST(SegmentOuterWall, NoFatAnywhere_NoPlanesOrFlagged)
{
  // The default phantom's tissue (40 HU) is not fat: there is no outer boundary to see.
  PhantomParams p = WallPhantom();
  p.tissueHu = 40.0;
  const Traced t = Trace(p);
  for (const OuterWallPlane& plane : t.wall.planes)
    EXPECT_TRUE(plane.flagged) << plane.abscissaMm;
}

TEST(SegmentOuterWall, BadInput_InputError)
{
  const AorticPhantom phantom = GenerateAorticPhantom(PhantomParams{});
  Centerline one;
  one.name = "aorta";
  EXPECT_THROW(SegmentOuterWall(*phantom.ct, *phantom.labels, one, 0.0, 10.0), InputError);
  OuterWallParams params;
  params.rays = 4;
  EXPECT_THROW(ValidateOuterWallParams(params), InputError);
  params = OuterWallParams{};
  params.circleMinimumShare = 1.5; // a share: [0, 1]
  EXPECT_THROW(ValidateOuterWallParams(params), InputError);
}

} // namespace
} // namespace sgp
