// The outer wall (issue 12, item 2) against the wall phantom's analytic outer wall: its diameter
// plane by plane, where it rests when neighbours touch the vessel, and its support flags.
#include <cmath>

#include <gtest/gtest.h>

#include "Common/Errors.h"
#include "Phantom/AorticPhantom.h"
#include "PipelineSupport.h"
#include "Wall/SegmentOuterWall.h"

namespace sgp
{
namespace
{

/// 1.0 mm: the bar for outer diameters on 0.8 × 0.8 × 1.0 mm voxels (the half-maximum edge
/// of a blurred step lies on the analytic surface; noise moves each ray's crossing by a few
/// tenths, which the circle fit averages).
constexpr double outerDiameterMm = 1.0;

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
};

Traced Trace(const PhantomParams& p)
{
  Traced t{ GenerateAorticPhantom(p), {}, {} };
  const LabelImage::Pointer lumen = GrowLumenRegion(*t.phantom.ct, t.phantom.truth.seedLps, RegionGrowingParams{}).mask;
  t.tree = testing::CenterlinesFromMask(*lumen);
  t.wall = SegmentOuterWall(*t.phantom.ct, *lumen, t.tree.aorta, 0.0, t.tree.aorta.LengthMm());
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
}

} // namespace
} // namespace sgp
