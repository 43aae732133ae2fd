// The active contour on phantoms whose radii are known (STYLE.md B6, "Active contour").
#include <gtest/gtest.h>

#include "Common/Errors.h"
#include "Phantom/AorticPhantom.h"
#include "PipelineSupport.h"
#include "Stent/ActiveContour.h"
#include "YPhantom.h"

namespace sgp
{
namespace
{

/// Mean radius of the rings of `segment` from `firstRing` to the last but `skipAtEnd`.
double MeanRadius(const StentMesh& mesh, const ActiveContourResult& r, int segment, int firstRing, int skipAtEnd)
{
  double sum = 0.0;
  int count = 0;
  for (Eigen::Index i = 0; i < mesh.V.rows(); ++i)
    if (mesh.segment[i] == segment && mesh.ring[i] >= firstRing && mesh.ring[i] < mesh.RingsIn(segment) - skipAtEnd)
    {
      sum += r.radiusMm[i];
      ++count;
    }
  return sum / count;
}

class YPhantomFit : public ::testing::Test
{
protected:
  static void SetUpTestSuite()
  {
    y = new testing::YPhantom(testing::MakeYPhantom(0.8));
    StentMeshParams p;
    p.proximalAbscissaMm = 15.0; // clear of the capsule's round top
    p.legLengthMm = 50.0;
    mesh = new StentMesh(BuildStentMesh(y->tree, p));
    wall = new WallDistanceField(WallDistanceField::FromLumen(*y->mask));
    measure = new ActiveContourResult(FitActiveContour(*mesh, *wall, ActiveContourParams::Measure()));
  }
  static void TearDownTestSuite()
  {
    delete measure;
    delete wall;
    delete mesh;
    delete y;
  }
  static testing::YPhantom* y;
  static StentMesh* mesh;
  static WallDistanceField* wall;
  static ActiveContourResult* measure;
};
testing::YPhantom* YPhantomFit::y = nullptr;
StentMesh* YPhantomFit::mesh = nullptr;
WallDistanceField* YPhantomFit::wall = nullptr;
ActiveContourResult* YPhantomFit::measure = nullptr;

// A quarter of a voxel (0.8 mm): the bar for a straight tube.
constexpr double quarterVoxel = 0.25 * 0.8;

TEST_F(YPhantomFit, MeasureMode_StraightTrunkReachesItsRadius)
{
  EXPECT_TRUE(measure->converged);
  // The trunk's rings, the two nearest the junction aside (where the lumen widens into the Y).
  EXPECT_NEAR(MeanRadius(*mesh, *measure, TrunkSegment, 0, 2), 10.0, quarterVoxel);
}

TEST_F(YPhantomFit, MeasureMode_BothLegsReachTheirRadii)
{
  // Away from the flow divider (the first two rings, where the two iliac lumens overlap).
  EXPECT_NEAR(MeanRadius(*mesh, *measure, RightLegSegment, 2, 0), 6.0, quarterVoxel);
  EXPECT_NEAR(MeanRadius(*mesh, *measure, LeftLegSegment, 2, 0), 6.0, quarterVoxel);
}

TEST_F(YPhantomFit, OneFactorizationAndTinyResiduals)
{
  EXPECT_GT(measure->iterations, 10);    // many steps…
  EXPECT_EQ(measure->factorizations, 1); // …one factorization
  EXPECT_LT(measure->maxRelativeResidual, 1e-10);
}

TEST_F(YPhantomFit, SimulateModeBelowTheVesselRadius_StopsAtR)
{
  // A stent of 16 mm trunk and 8 mm legs in a 20 mm aorta and 12 mm iliacs: it cannot reach the
  // wall, and it cannot over-expand.
  auto params = ActiveContourParams::Simulate({ 16.0, 8.0, 8.0 });
  const ActiveContourResult r = FitActiveContour(*mesh, *wall, params);
  EXPECT_TRUE(r.converged);
  const double radius[3] = { 8.0, 4.0, 4.0 };
  for (Eigen::Index i = 0; i < mesh->V.rows(); ++i)
  {
    // Never beyond R, nor touching the wall — except at the junction, where the 16 mm trunk
    // tapers into the 8 mm legs through the connection element and the legs meet at the crotch;
    // that pull of the wider trunk fades within three rings (12 mm).
    const bool junction = (mesh->segment[i] == TrunkSegment && mesh->ring[i] >= mesh->RingsIn(0) - 3) ||
                          (mesh->segment[i] != TrunkSegment && mesh->ring[i] < 3);
    if (!junction)
    {
      ASSERT_LE(r.radiusMm[i], radius[mesh->segment[i]] + 1e-6);
      ASSERT_LT(r.wallDistanceMm[i], 0.0);
    }
  }
  // The ring's own stiffness holds it a little inside R: within 0.3 mm here.
  EXPECT_NEAR(MeanRadius(*mesh, r, TrunkSegment, 1, 3), 8.0, 0.3);
  EXPECT_NEAR(MeanRadius(*mesh, r, RightLegSegment, 3, 1), 4.0, 0.3);
  EXPECT_NEAR(MeanRadius(*mesh, r, LeftLegSegment, 3, 1), 4.0, 0.3);
  // The energy of the run never increases: a semi-implicit gradient step on a smooth energy.
  for (std::size_t i = 1; i < r.energy.size(); ++i)
    ASSERT_LE(r.energy[i], r.energy[i - 1] + 1e-12 * std::abs(r.energy.front())) << "step " << i;
}

TEST_F(YPhantomFit, MeasureMode_EnergyNeverIncreases)
{
  for (std::size_t i = 1; i < measure->energy.size(); ++i)
    ASSERT_LE(measure->energy[i], measure->energy[i - 1] + 1e-12 * std::abs(measure->energy.front())) << "step " << i;
  EXPECT_LT(measure->energy.back(), 0.2 * measure->energy.front());
}

class AneurysmNeckAngle : public ::testing::TestWithParam<double>
{
};

TEST_P(AneurysmNeckAngle, SurfaceFollowsTheSacToItsWidest)
{
  PhantomParams pp;             // 0.8 × 0.8 × 1.0 mm, noise 20 HU
  pp.neckAngleDeg = GetParam(); // 40°: the trunk bends through the neck–sac junction
  const AorticPhantom phantom = GenerateAorticPhantom(pp);
  const LabelImage::Pointer lumen = GrowLumenRegion(*phantom.ct, phantom.truth.seedLps, RegionGrowingParams{}).mask;
  const CenterlineTree tree = testing::CenterlinesFromMask(*lumen);
  const StentMesh mesh = BuildStentMesh(tree); // the trunk starts below the lowest renal artery
  const WallDistanceField wall = WallDistanceField::FromLumen(*lumen);
  const ActiveContourResult r = FitActiveContour(mesh, wall, ActiveContourParams::Measure());
  // The widest ring's mean diameter against the sac's 55 mm: within 1 mm (the segmented wall
  // lies within half a voxel of the analytic one, and the ring nearest the widest level may sit
  // up to 2 mm from it, where the sac is 0.1 mm narrower).
  double widest = 0.0;
  for (int k = 0; k < mesh.RingsIn(TrunkSegment); ++k)
  {
    double sum = 0.0;
    for (int j = 0; j < mesh.verticesPerRing; ++j)
      sum += r.radiusMm[mesh.Id(TrunkSegment, k, j)];
    widest = std::max(widest, 2.0 * sum / mesh.verticesPerRing);
  }
  EXPECT_NEAR(widest, phantom.truth.sizing.maxAneurysmDiameter, 1.0);
  EXPECT_TRUE(r.converged);
}

INSTANTIATE_TEST_SUITE_P(ActiveContour, AneurysmNeckAngle, ::testing::Values(0.0, 40.0));

TEST(ActiveContour, ParameterOutOfRange_InputError)
{
  auto p = ActiveContourParams::Measure();
  p.tau = 0.0;
  EXPECT_THROW(ValidateActiveContourParams(p), InputError);
  p = ActiveContourParams::Measure();
  p.balloonRadiusMm[1] = -3.0;
  EXPECT_THROW(ValidateActiveContourParams(p), InputError);
  EXPECT_THROW(WallDistanceField::FromLumen(*testing::MakeYPhantom(2.0).mask, 0.5), InputError);
  auto empty = LabelImage::New();
  LabelImage::RegionType region;
  region.SetSize({ { 4, 4, 4 } });
  empty->SetRegions(region);
  empty->Allocate(true);
  EXPECT_THROW(WallDistanceField::FromLumen(*empty), InputError);
}

} // namespace
} // namespace sgp
