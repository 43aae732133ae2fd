// Tests of GrowLumenRegion against the analytic truth of the synthetic phantom (STYLE.md B6).
#include <cmath>
#include <random>
#include <tuple>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "Common/Errors.h"
#include "Phantom/AorticPhantom.h"
#include "PhantomTestSupport.h"
#include "Segmentation/GrowLumenRegion.h"

namespace sgp
{
namespace
{

using testing::CompareWithTruth;
using testing::ObliqueFlippedDirection;

/// The Dice bar of the foundation issue: boundary voxels of a lumen a few voxels across.
constexpr double minimumDice = 0.95;

std::string MessageOf(const std::function<void()>& f)
{
  try
  {
    f();
  }
  catch (const std::exception& e)
  {
    return e.what();
  }
  return "(no exception)";
}

TEST(GrowLumenRegion, NoisyPhantom08x08x10_DiceAbove095)
{
  PhantomParams p; // 0.8 × 0.8 × 1.0 mm, noise 20 HU, blur 1 mm
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const LumenSegmentation lumen = GrowLumenRegion(*phantom.ct, phantom.truth.seedLps, RegionGrowingParams{});
  const auto overlap = CompareWithTruth(*lumen.mask, *phantom.labels);
  EXPECT_GE(overlap.Dice(), minimumDice);
  // Volume: a boundary shift of a quarter voxel over the whole surface is about 3 %.
  EXPECT_NEAR(lumen.volumeMl, phantom.truth.lumenVolumeMl, 0.03 * phantom.truth.lumenVolumeMl);
  // The window is centred on the lumen HU with the noise it was given (20 HU):
  // median within 10 HU, robust sigma within 25 %.
  EXPECT_NEAR(lumen.seedMedianHu, p.lumenHu, 10.0);
  EXPECT_NEAR(lumen.seedSigmaHu, p.noiseSigmaHu, 0.25 * p.noiseSigmaHu);
  // The boundary is placed at the half-maximum between lumen and tissue (tissue within 15 HU).
  EXPECT_NEAR(lumen.tissueHu, p.tissueHu, 15.0);
  EXPECT_TRUE(lumen.warnings.empty());
}

TEST(GrowLumenRegion, AnisotropicObliqueFlippedGrid_DiceAbove095)
{
  PhantomParams p;
  p.spacingMm = { 0.7, 0.7, 2.0 };
  p.directionLps = ObliqueFlippedDirection();
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  for (int r = 0; r < 3; ++r) // the grid is the oblique, flipped one that was asked for
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(phantom.ct->GetDirection()(r, c), p.directionLps(r, c), 1e-12);
  const LumenSegmentation lumen = GrowLumenRegion(*phantom.ct, phantom.truth.seedLps, RegionGrowingParams{});
  EXPECT_GE(CompareWithTruth(*lumen.mask, *phantom.labels).Dice(), minimumDice);
  // The mask is on the exact grid of the input.
  EXPECT_EQ(lumen.mask->GetLargestPossibleRegion(), phantom.ct->GetLargestPossibleRegion());
  EXPECT_EQ(lumen.mask->GetDirection(), phantom.ct->GetDirection());
  EXPECT_EQ(lumen.mask->GetOrigin(), phantom.ct->GetOrigin());
  EXPECT_EQ(lumen.mask->GetSpacing(), phantom.ct->GetSpacing());
}

TEST(GrowLumenRegion, VertebraTwoMillimetresFromSac_NoBoneInLumen)
{
  PhantomParams p;
  p.includeBone = true;
  p.boneGapMm = 2.0;
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const auto before = CompareWithTruth(*phantom.labels, *phantom.labels);
  ASSERT_GT(before.labelCount[BoneLabel], 0); // the phantom has bone to leak into
  const LumenSegmentation lumen = GrowLumenRegion(*phantom.ct, phantom.truth.seedLps, RegionGrowingParams{});
  const auto overlap = CompareWithTruth(*lumen.mask, *phantom.labels);
  // Not one bone voxel: bone begins 2 mm (2.5 voxels) beyond the lumen, so any is a leak.
  EXPECT_EQ(overlap.perLabel[BoneLabel], 0);
  EXPECT_GE(overlap.Dice(), minimumDice);
}

class EnhancingKidneys : public ::testing::TestWithParam<double>
{
};

TEST_P(EnhancingKidneys, AtTheRenalArteryEnds_NotFlooded)
{
  PhantomParams p;
  p.includeKidneys = true;
  p.kidneyHu = GetParam();
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const LumenSegmentation lumen = GrowLumenRegion(*phantom.ct, phantom.truth.seedLps, RegionGrowingParams{});
  const auto overlap = CompareWithTruth(*lumen.mask, *phantom.labels);
  ASSERT_GT(overlap.labelCount[KidneyLabel], 0);
  // Below 1 % of the parenchyma: only the voxels the boundary refinement may take around the
  // renal artery's end (its 1.6 mm reach), never the organ.
  EXPECT_LT(overlap.FractionOf(KidneyLabel), 0.01);
  EXPECT_GE(overlap.Dice(), minimumDice);
}

INSTANTIATE_TEST_SUITE_P(GrowLumenRegion, EnhancingKidneys, ::testing::Values(150.0, 200.0));

/// An enhancing vein against the aorta: its HU and the wall's thickness (mm), on the default grid
/// (0.8 × 0.8 × 1 mm, 20 HU).
class EnhancingVeinAgainstTheWall : public ::testing::TestWithParam<std::tuple<double, double>>
{
};

TEST_P(EnhancingVeinAgainstTheWall, BoundaryRefinementStaysWithinItsReach)
{
  // The left renal vein (≈ 150–250 HU in the arterial phase, vessel-wall.md §2) crossing in front
  // of the aorta, separated from the lumen only by the wall, which the blur leaves brighter than
  // the edge level: the refinement (voxels in [edge, upper] within its reach) runs through the
  // wall into the vein as far as its reach goes. Before, the reach was counted in face steps of
  // the finest spacing (on 2.5 mm slices three slices, 7.5 mm) and was 2 mm where the lumen is
  // complete at 1.6 mm: 2.1–3.5 % of the vein inside on 0.8 × 0.8 × 1 mm, 3.9 % in the wall plan.
  PhantomParams p;
  p.leftRenalVeinHu = std::get<0>(GetParam());
  p.wallThicknessMm = std::get<1>(GetParam());
  p.includeLeftRenalVein = true;
  p.tissueHu = -100.0;
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  const LumenSegmentation lumen = GrowLumenRegion(*phantom.ct, phantom.truth.seedLps, RegionGrowingParams{});
  const auto overlap = CompareWithTruth(*lumen.mask, *phantom.labels);
  ASSERT_GT(overlap.labelCount[RenalVeinLabel], 1000);
  // Issue 12's bar for a neighbour inside the vessel: under 2 % of its voxels.
  EXPECT_LT(overlap.FractionOf(RenalVeinLabel), 0.02) << 100.0 * overlap.FractionOf(RenalVeinLabel) << " %";
  EXPECT_GE(overlap.Dice(), minimumDice);
}

INSTANTIATE_TEST_SUITE_P(GrowLumenRegion,
                         EnhancingVeinAgainstTheWall,
                         ::testing::Values(std::make_tuple(150.0, 0.5),
                                           std::make_tuple(150.0, 1.5),
                                           std::make_tuple(200.0, 0.5),
                                           std::make_tuple(200.0, 1.5),
                                           std::make_tuple(250.0, 0.5),
                                           std::make_tuple(250.0, 1.5)));
// Not asserted on thick noisy slices (0.7 × 0.7 × 2.5 mm, 30 HU): there 4.5 % of a 200 HU vein is
// taken (noise carries the refinement through the blurred wall; issue 12's note).

TEST(GrowLumenRegion, ThickSlices_RefinementReachIsMillimetresNotSlices)
{
  // A lumen disc on 0.7 × 0.7 × 2.5 mm slices ending against a plateau of 200 HU (between the
  // edge level, 195 HU, and the window's lower end): the refinement reaches 1.6 mm, less than
  // one slice, so not one voxel of the plateau. Counted in face steps of the finest spacing it
  // reached three slices (7.5 mm) into it.
  auto ct = CtImage::New();
  CtImage::RegionType region;
  region.SetSize({ { 40, 40, 30 } });
  ct->SetRegions(region);
  ct->SetSpacing(CtImage::SpacingType(std::array<double, 3>{ 0.7, 0.7, 2.5 }.data()));
  ct->Allocate();
  ct->FillBuffer(40);
  for (long k = 0; k < 30; ++k)
    for (long j = 0; j < 40; ++j)
      for (long i = 0; i < 40; ++i)
        if ((i - 20) * (i - 20) + (j - 20) * (j - 20) <= 100)
          ct->SetPixel({ { i, j, k } }, k < 15 ? 350 : 200);
  const LumenSegmentation lumen = GrowLumenRegion(*ct, Point3(14.0, 14.0, 15.0), RegionGrowingParams{});
  ASSERT_NEAR(lumen.edgeHu, 195.0, 1.0); // half-way from 350 to the 40 HU around
  long plateau = 0, disc = 0;
  for (long k = 0; k < 30; ++k)
    for (long j = 0; j < 40; ++j)
      for (long i = 0; i < 40; ++i)
        (k < 15 ? disc : plateau) += lumen.mask->GetPixel({ { i, j, k } });
  EXPECT_EQ(plateau, 0);
  EXPECT_GT(disc, 15 * 300); // the disc itself (317 voxels a slice) is lumen
}

TEST(GrowLumenRegion, ManualWindowBelowKidneyHu_FloodDetected)
{
  PhantomParams p;
  p.includeKidneys = true;
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  RegionGrowingParams params;
  params.thresholdMode = ThresholdMode::Manual;
  params.lowerHu = 120.0; // below the kidneys' 180 HU: growing floods them through the renal arteries
  params.upperHu = 600.0;
  const std::string message = MessageOf([&] { GrowLumenRegion(*phantom.ct, phantom.truth.seedLps, params); });
  EXPECT_NE(message.find("leaked into darker tissue"), std::string::npos) << message;
  EXPECT_NE(message.find("now 120 HU"), std::string::npos) << message;
  EXPECT_THROW(GrowLumenRegion(*phantom.ct, phantom.truth.seedLps, params), AlgorithmError);
}

/// A cylinder of lumen joined to a block of the same HU (13.8 mL, the size of a vertebral body's
/// marrow) by a bridge one voxel thick: the leak phantom of STYLE.md B6.
TEST(GrowLumenRegion, AutomaticWindowBelowKidneyHu_FloodDetectedWithAdviceForAuto)
{
  // The same flood from an automatic window made wide (350 − 10 × 20 HU ≈ 150–180 HU) into kidneys
  // of 250 HU (under the flood test's 40 + 0.7 × 310 = 257 HU): the advice is for the automatic
  // mode (windowSigmas, or a manual lowerHu), not "use thresholdMode auto", which a low-contrast
  // scan in the random sweep was told while in it.
  PhantomParams p;
  p.includeKidneys = true;
  p.kidneyHu = 250.0;
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  RegionGrowingParams params;
  params.windowSigmas = 10.0;
  const std::string message = MessageOf([&] { GrowLumenRegion(*phantom.ct, phantom.truth.seedLps, params); });
  EXPECT_NE(message.find("leaked into darker tissue"), std::string::npos) << message;
  EXPECT_NE(message.find("lower windowSigmas (now 10.0)"), std::string::npos) << message;
  EXPECT_EQ(message.find("use thresholdMode auto"), std::string::npos) << message;
}

TEST(GrowLumenRegion, BlockBehindOneVoxelBridge_CutAndWarned)
{
  auto ct = CtImage::New();
  CtImage::RegionType region;
  region.SetSize({ { 80, 80, 60 } });
  ct->SetRegions(region);
  ct->Allocate();
  ct->FillBuffer(40);
  long blockVoxels = 0;
  for (long k = 0; k < 60; ++k)
    for (long j = 0; j < 80; ++j)
      for (long i = 0; i < 80; ++i)
      {
        const bool cylinder = (i - 25) * (i - 25) + (j - 40) * (j - 40) <= 64;          // radius 8 mm
        const bool block = i >= 50 && i < 74 && j >= 28 && j < 52 && k >= 18 && k < 42; // 13.8 mL
        const bool bridge = i > 32 && i < 50 && j == 40 && k == 30;                     // 1 × 1 voxel
        blockVoxels += block;
        if (cylinder || block || bridge)
        {
          ct->SetPixel({ { i, j, k } }, 350);
        }
      }
  const LumenSegmentation lumen = GrowLumenRegion(*ct, Point3(25, 40, 30), RegionGrowingParams{});
  long inBlock = 0;
  for (long k = 18; k < 42; ++k)
    for (long j = 28; j < 52; ++j)
      for (long i = 50; i < 74; ++i)
        inBlock += lumen.mask->GetPixel({ { i, j, k } });
  EXPECT_EQ(inBlock, 0);
  ASSERT_EQ(lumen.warnings.size(), 1u);
  EXPECT_NE(lumen.warnings[0].find("the largest piece 13.8 mL"), std::string::npos) << lumen.warnings[0];
  // All that was cut: the block and the part of the bridge that hangs on it (the opening's
  // small trims of the disc's outline are pieces under leakMinimumPieceMl, and go back).
  EXPECT_GE(lumen.cutVolumeMl, blockVoxels / 1000.0);
  EXPECT_LE(lumen.cutVolumeMl, (blockVoxels + 17) / 1000.0);
  // The cylinder itself is whole: 60 slices of the 197-voxel disc of radius 8.
  EXPECT_NEAR(lumen.volumeMl, 60 * 197 / 1000.0, 0.05);
}

TEST(GrowLumenRegion, DarkVoxelBesideTheSeed_GrowsFromTheNearestInteriorVoxel)
{
  // A noise-free tube with one voxel below the window right beside the seed: the opening's erosion
  // removes the seed voxel, and growing must go on from the interior voxel nearest to it.
  auto ct = CtImage::New();
  CtImage::RegionType region;
  region.SetSize({ { 40, 40, 40 } });
  ct->SetRegions(region);
  ct->Allocate();
  ct->FillBuffer(40);
  for (long k = 0; k < 40; ++k)
    for (long j = 0; j < 40; ++j)
      for (long i = 0; i < 40; ++i)
        if ((i - 20) * (i - 20) + (j - 20) * (j - 20) <= 64)
          ct->SetPixel({ { i, j, k } }, 350);
  ct->SetPixel({ { 21, 20, 20 } }, 100); // beside the seed voxel (20, 20, 20)
  const LumenSegmentation lumen = GrowLumenRegion(*ct, Point3(20, 20, 20), RegionGrowingParams{});
  EXPECT_EQ(lumen.mask->GetPixel({ { 21, 20, 20 } }), 1); // the cavity is filled
  EXPECT_NEAR(lumen.volumeMl, 40 * 197 / 1000.0, 0.01);   // the whole tube, 40 slices of 197 voxels
}

TEST(GrowLumenRegion, RunOffBeyondAStenosisNarrowerThanTheBall_Kept)
{
  // A wide tube, a one-voxel stenosis 2 mm long, then a narrow 1.4 mL run-off: the opening cuts
  // the run-off off, and it must come back (a vessel, not a leak), without a warning.
  auto ct = CtImage::New();
  CtImage::RegionType region;
  region.SetSize({ { 40, 40, 60 } });
  ct->SetRegions(region);
  ct->Allocate();
  ct->FillBuffer(40);
  long runOff = 0;
  for (long k = 0; k < 60; ++k)
    for (long j = 0; j < 40; ++j)
      for (long i = 0; i < 40; ++i)
      {
        const long d2 = (i - 20) * (i - 20) + (j - 20) * (j - 20);
        const bool lumen = (k < 30 && d2 <= 64) || ((k == 30 || k == 31) && d2 == 0) || (k >= 32 && d2 <= 16);
        runOff += k >= 32 && d2 <= 16;
        if (lumen)
          ct->SetPixel({ { i, j, k } }, 350);
      }
  const LumenSegmentation lumen = GrowLumenRegion(*ct, Point3(20, 20, 10), RegionGrowingParams{});
  EXPECT_EQ(lumen.mask->GetPixel({ { 20, 20, 50 } }), 1);
  EXPECT_TRUE(lumen.warnings.empty());
  EXPECT_NEAR(lumen.volumeMl, (30 * 197 + 2 + runOff) / 1000.0, 0.005); // every lumen voxel
}

TEST(GrowLumenRegion, LumenOverVolumeLimit_AlgorithmErrorNamesLimit)
{
  PhantomParams p;
  p.spacingMm = { 1.5, 1.5, 2.0 };
  const AorticPhantom phantom = GenerateAorticPhantom(p);
  RegionGrowingParams params;
  params.maximumLumenVolumeMl = 50.0; // the phantom's lumen is about 165 mL
  const std::string message = MessageOf([&] { GrowLumenRegion(*phantom.ct, phantom.truth.seedLps, params); });
  EXPECT_NE(message.find("limit 50 mL"), std::string::npos) << message;
  EXPECT_THROW(GrowLumenRegion(*phantom.ct, phantom.truth.seedLps, params), AlgorithmError);
}

class SmallPhantom : public ::testing::Test
{
protected:
  static void SetUpTestSuite()
  {
    PhantomParams p;
    p.spacingMm = { 1.5, 1.5, 2.0 };
    phantom = new AorticPhantom(GenerateAorticPhantom(p));
  }
  static void TearDownTestSuite() { delete phantom; }
  static AorticPhantom* phantom;
};
AorticPhantom* SmallPhantom::phantom = nullptr;

TEST_F(SmallPhantom, SeedOutsideImage_InputErrorNamesSeedAndBounds)
{
  const std::string message =
    MessageOf([&] { GrowLumenRegion(*phantom->ct, Point3(5000, 0, 60), RegionGrowingParams{}); });
  EXPECT_NE(message.find("Seed (5000.0, 0.0, 60.0) mm LPS lies outside the image (x "), std::string::npos) << message;
  EXPECT_THROW(GrowLumenRegion(*phantom->ct, Point3(5000, 0, 60), RegionGrowingParams{}), InputError);
}

TEST_F(SmallPhantom, SeedInTissue_InputErrorNamesHu)
{
  const Point3 tissue(0, -45, 60); // anterior to the sac, 17 mm outside its wall
  const std::string message = MessageOf([&] { GrowLumenRegion(*phantom->ct, tissue, RegionGrowingParams{}); });
  EXPECT_NE(message.find("lies in tissue of"), std::string::npos) << message;
  EXPECT_NE(message.find("at least 150 HU"), std::string::npos) << message;
  EXPECT_THROW(GrowLumenRegion(*phantom->ct, tissue, RegionGrowingParams{}), InputError);
}

TEST_F(SmallPhantom, InvertedManualWindow_InputErrorNamesBoth)
{
  RegionGrowingParams params;
  params.thresholdMode = ThresholdMode::Manual;
  params.lowerHu = 600;
  params.upperHu = 200;
  const std::string message = MessageOf([&] { GrowLumenRegion(*phantom->ct, phantom->truth.seedLps, params); });
  EXPECT_EQ(message, "lowerHu (600.0 HU) must be less than upperHu (200.0 HU); swap them or widen the window.");
  EXPECT_THROW(GrowLumenRegion(*phantom->ct, phantom->truth.seedLps, params), InputError);
}

TEST_F(SmallPhantom, SeedOutsideManualWindow_InputError)
{
  RegionGrowingParams params;
  params.thresholdMode = ThresholdMode::Manual;
  params.lowerHu = 500; // the lumen is 350 HU
  params.upperHu = 900;
  const std::string message = MessageOf([&] { GrowLumenRegion(*phantom->ct, phantom->truth.seedLps, params); });
  EXPECT_NE(message.find("outside the manual window 500 to 900 HU"), std::string::npos) << message;
  EXPECT_THROW(GrowLumenRegion(*phantom->ct, phantom->truth.seedLps, params), InputError);
}

TEST_F(SmallPhantom, SeedInVesselNarrowerThanOpening_InputError)
{
  RegionGrowingParams params;
  params.leakOpeningRadiusMm = 5.0; // a 10 mm ball cannot fit in the 6 mm renal artery
  // 30 mm out along the horizontal renal (64 mm lateral, 10 mm posterior to the hilum).
  const Point3 inRightRenal(-30, 10.0 * 30 / 64, phantom->truth.landmarks[0].lps.z());
  ASSERT_EQ(phantom->truth.landmarks[0].name, "rightRenalOstium");
  const std::string message = MessageOf([&] { GrowLumenRegion(*phantom->ct, inRightRenal, params); });
  EXPECT_NE(message.find("narrower than the leak-cutting opening (10.0 mm across)"), std::string::npos) << message;
  EXPECT_THROW(GrowLumenRegion(*phantom->ct, inRightRenal, params), InputError);
}

TEST_F(SmallPhantom, ParameterOutOfRange_InputErrorNamesParameterAndValue)
{
  const std::vector<std::pair<std::string, std::function<void(RegionGrowingParams&)>>> cases{
    { "lowerHu is -2000.00 HU", [](auto& p) { p.lowerHu = -2000; } },
    { "upperHu is 4000.00 HU", [](auto& p) { p.upperHu = 4000; } },
    { "windowSigmas is 0.50", [](auto& p) { p.windowSigmas = 0.5; } },
    { "seedMinimumHu is 5000.00 HU", [](auto& p) { p.seedMinimumHu = 5000; } },
    { "leakOpeningRadiusMm is -1.00 mm", [](auto& p) { p.leakOpeningRadiusMm = -1; } },
    { "maximumLumenVolumeMl is 0.00 mL", [](auto& p) { p.maximumLumenVolumeMl = 0; } },
    { "seedNeighbourhoodRadiusMm is 50.00 mm", [](auto& p) { p.seedNeighbourhoodRadiusMm = 50; } },
    { "seedSearchRadiusMm is 30.00 mm", [](auto& p) { p.seedSearchRadiusMm = 30; } },
    { "minimumHalfWindowHu is -1.00 HU", [](auto& p) { p.minimumHalfWindowHu = -1; } },
    { "refineDistanceMm is 11.00 mm", [](auto& p) { p.refineDistanceMm = 11; } },
    { "tissueDepthMm is 30.00 mm", [](auto& p) { p.tissueDepthMm = 30; } },
    { "windowSigmas is nan", [](auto& p) { p.windowSigmas = std::nan(""); } },
  };
  for (const auto& [expected, plant] : cases)
  {
    RegionGrowingParams params;
    plant(params);
    const std::string message = MessageOf([&] { GrowLumenRegion(*phantom->ct, phantom->truth.seedLps, params); });
    EXPECT_EQ(message.rfind(expected, 0), 0u) << message;
    EXPECT_THROW(ValidateRegionGrowingParams(params), InputError);
  }
}

TEST_F(SmallPhantom, SameSeedTwice_IdenticalResult)
{
  const auto a = GrowLumenRegion(*phantom->ct, phantom->truth.seedLps, RegionGrowingParams{});
  const auto b = GrowLumenRegion(*phantom->ct, phantom->truth.seedLps, RegionGrowingParams{});
  const auto overlap = CompareWithTruth(*a.mask, *b.mask);
  EXPECT_EQ(overlap.truthLumen, overlap.segmented);
  EXPECT_EQ(overlap.both, overlap.segmented);
}

/// What lies beside the seed in the tube of SeedBesideADisturbance.
enum class BesideTheSeed
{
  Wall,   ///< the seed on the lumen's edge voxel
  Plaque, ///< a 4 mm thick 900 HU plaque on the wall 1 mm from the seed
  Flap    ///< a one-voxel dissection flap (60 HU) 1 mm from the seed, splitting the lumen in two
};

/// A noisy tube (1 mm voxels, radius 10 mm, lumen 350 ± 20 HU in tissue 40 ± 20 HU) with a seed
/// whose 2.5 mm ball holds wall, plaque or flap: the window must be that of a seed in clean lumen
/// of the same compartment (the class of "a seed near the wall, a plaque or a flap", issue 13).
class SeedBesideADisturbance : public ::testing::TestWithParam<BesideTheSeed>
{
protected:
  static constexpr long n = 48, length = 60, centre = 24;
  static CtImage::Pointer MakeTube(BesideTheSeed kind)
  {
    auto ct = CtImage::New();
    CtImage::RegionType region;
    region.SetSize({ { n, n, length } });
    ct->SetRegions(region);
    ct->Allocate();
    std::mt19937 random(17);
    std::normal_distribution<double> noise(0.0, 20.0);
    for (long k = 0; k < length; ++k)
      for (long j = 0; j < n; ++j)
        for (long i = 0; i < n; ++i)
        {
          const long x = i - centre, y = j - centre;
          const long r2 = x * x + y * y;
          double hu = r2 <= 100 ? 350.0 : 40.0;
          if (kind == BesideTheSeed::Plaque && r2 >= 36 && r2 <= 100 && x > 0 && std::abs(y) <= 3 &&
              std::abs(k - 30) <= 3)
            hu = 900.0;
          if (kind == BesideTheSeed::Flap && r2 <= 100 && x == 0)
            hu = 60.0;
          ct->SetPixel({ { i, j, k } }, static_cast<short>(std::lround(hu + noise(random))));
        }
    return ct;
  }
  /// The seed with the disturbance in its ball, and one in clean lumen of the same compartment.
  static std::pair<Point3, Point3> Seeds(BesideTheSeed kind)
  {
    switch (kind)
    {
      case BesideTheSeed::Wall:
        return { Point3(centre + 10, centre, 30), Point3(centre, centre, 30) };
      case BesideTheSeed::Plaque:
        return { Point3(centre + 5, centre, 30), Point3(centre - 2, centre, 30) };
      case BesideTheSeed::Flap:
        break;
    }
    return { Point3(centre + 1, centre, 30), Point3(centre + 5, centre, 30) };
  }
};

TEST_P(SeedBesideADisturbance, WindowAndLumenAsFromCleanLumen)
{
  const auto ct = MakeTube(GetParam());
  const auto [seed, clean] = Seeds(GetParam());
  // Step 1's window (the seed's ball, or the nearest clean one) on its own (the default; step 1b,
  // which replaces it by the lumen's own levels, is checked at the end).
  RegionGrowingParams stepOne;
  stepOne.windowFromLumen = false;
  const LumenSegmentation reference = GrowLumenRegion(*ct, clean, stepOne);
  ASSERT_EQ(reference.windowSource, "the seed's neighbourhood");
  const LumenSegmentation lumen = GrowLumenRegion(*ct, seed, stepOne);
  // The window of the lumen's own HU (350 ± 20): m within 5 HU and σ within ±33 % (two standard
  // errors of the robust σ of a 65-voxel ball, 17 %) put m − 3σ in [265, 315] and m + 6σ in
  // [425, 515]; wall, flap (40–60 HU) and plaque (900 HU) lie far outside either.
  const auto lumenWindow = [](const LumenSegmentation& l)
  { return l.lowerHu >= 265.0 && l.lowerHu <= 315.0 && l.upperHu >= 425.0 && l.upperHu <= 515.0; };
  EXPECT_TRUE(lumenWindow(reference)) << reference.lowerHu << " to " << reference.upperHu;
  EXPECT_TRUE(lumenWindow(lumen)) << lumen.lowerHu << " to " << lumen.upperHu;
  // The same lumen: the boundary refinement places the edge at the half-maximum either way.
  EXPECT_NEAR(lumen.volumeMl, reference.volumeMl, 0.01 * reference.volumeMl);
  ASSERT_EQ(lumen.warnings.size(), 1u);
  EXPECT_NE(lumen.warnings[0].find("mm from the seed"), std::string::npos) << lumen.warnings[0];
  EXPECT_LE((lumen.windowCentreLps - seed).norm(), 5.0); // within seedSearchRadiusMm
  if (GetParam() == BesideTheSeed::Flap)
  {
    EXPECT_GT(lumen.windowCentreLps.x(), double(centre));               // the seed's side of the flap
    EXPECT_EQ(lumen.mask->GetPixel({ { centre - 5, centre, 30 } }), 0); // the other lumen not entered
  }

  // The case is a real one: from the seed's own ball the window is not the lumen's (what the
  // search is for).
  RegionGrowingParams ownBall = stepOne;
  ownBall.seedSearchRadiusMm = 0.0;
  try
  {
    const LumenSegmentation old = GrowLumenRegion(*ct, seed, ownBall);
    EXPECT_FALSE(lumenWindow(old)) << old.lowerHu << " to " << old.upperHu;
  }
  catch (const std::exception&)
  {
    SUCCEED(); // a leak error from the seed's own ball: just as wrong
  }

  // With step 1b the window comes from the lumen's core, wherever the seed lies in it: the same
  // window and the same voxels from the disturbed seed as from the clean one. Not behind the flap:
  // its half-lumens are 10 mm across, at the limit of a core 5 mm inside the edge, which one first
  // window's region holds and the other's does not (README, "The automatic seed").
  if (GetParam() == BesideTheSeed::Flap)
    return;
  RegionGrowingParams fromLumen;
  fromLumen.windowFromLumen = true;
  const LumenSegmentation cleanDefault = GrowLumenRegion(*ct, clean, fromLumen);
  const LumenSegmentation disturbedDefault = GrowLumenRegion(*ct, seed, fromLumen);
  EXPECT_NE(cleanDefault.windowSource.find("slab by slab from the lumen's core"), std::string::npos)
    << cleanDefault.windowSource;
  EXPECT_EQ(disturbedDefault.lowerHu, cleanDefault.lowerHu);
  EXPECT_EQ(disturbedDefault.upperHu, cleanDefault.upperHu);
  EXPECT_TRUE(lumenWindow(cleanDefault)) << cleanDefault.lowerHu << " to " << cleanDefault.upperHu;
  long differ = 0;
  const long n = static_cast<long>(ct->GetLargestPossibleRegion().GetNumberOfPixels());
  for (long i = 0; i < n; ++i)
    differ += cleanDefault.mask->GetBufferPointer()[i] != disturbedDefault.mask->GetBufferPointer()[i] ? 1 : 0;
  EXPECT_EQ(differ, 0) << "voxels labelled differently from the two seeds";
}

INSTANTIATE_TEST_SUITE_P(GrowLumenRegion,
                         SeedBesideADisturbance,
                         ::testing::Values(BesideTheSeed::Wall, BesideTheSeed::Plaque, BesideTheSeed::Flap),
                         [](const auto& info)
                         {
                           switch (info.param)
                           {
                             case BesideTheSeed::Wall:
                               return std::string("Wall");
                             case BesideTheSeed::Plaque:
                               return std::string("Plaque");
                             case BesideTheSeed::Flap:
                               break;
                           }
                           return std::string("Flap");
                         });

class SeedOutsideTheTube : public SeedBesideADisturbance
{
};

TEST_F(SeedOutsideTheTube, OneMillimetreOut_MovedIn_SixOut_Refused)
{
  // A seed 1 mm outside the lumen's edge (its ball mostly tissue, median below seedMinimumHu)
  // is moved into the lumen it touches, with the warning; 6 mm out, past the skipped ball and
  // through tissue, it is refused as before.
  const auto ct = MakeTube(BesideTheSeed::Wall);
  const LumenSegmentation reference = GrowLumenRegion(*ct, Point3(centre, centre, 30), RegionGrowingParams{});
  const LumenSegmentation lumen = GrowLumenRegion(*ct, Point3(centre + 11, centre, 30), RegionGrowingParams{});
  EXPECT_NEAR(lumen.volumeMl, reference.volumeMl, 0.01 * reference.volumeMl); // as above
  ASSERT_EQ(lumen.warnings.size(), 1u);
  const std::string message =
    MessageOf([&] { GrowLumenRegion(*ct, Point3(centre + 16, centre, 30), RegionGrowingParams{}); });
  EXPECT_NE(message.find("lies in tissue of"), std::string::npos) << message;
}

} // namespace
} // namespace sgp
