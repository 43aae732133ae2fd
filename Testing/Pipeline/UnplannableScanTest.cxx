// Scans the plan cannot serve, named for what they are (issue 33 item 8): a post-EVAR scan (an
// endograft's metal struts in the aorta's lumen) and a dissection whose two channels run side by
// side to the scan's lower border (not an aortic bifurcation). Each is the generated phantom with
// the device or the flap drawn into its CT; without them the same phantom plans as before.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <itkImageRegionConstIteratorWithIndex.h>

#include "Common/Errors.h"
#include "Phantom/AorticPhantom.h"
#include "Pipeline/PlanRepair.h"
#include "Segmentation/FindEndograft.h"
#include "Segmentation/GrowLumenRegion.h"
#include "CropSupport.h"
#include "PhantomTestSupport.h"
#include "ShippedPlanParams.h"

namespace sgp
{
namespace
{

constexpr double pi = 3.14159265358979323846;

double LandmarkZ(const PhantomTruth& truth, const std::string& name)
{
  for (const PhantomLandmark& l : truth.landmarks)
    if (l.name == name)
      return l.lps.z();
  ADD_FAILURE() << "no landmark " << name;
  return 0.0;
}

/// The point of the aorta's truth axis nearest to height z (LPS mm).
Point3 AxisAt(const PhantomTruth& truth, double z)
{
  const Points& axis = truth.vessels.front().axis;
  Eigen::Index best = 0;
  for (Eigen::Index r = 1; r < axis.rows(); ++r)
    if (std::abs(axis(r, 2) - z) < std::abs(axis(best, 2) - z))
      best = r;
  return axis.row(best).transpose();
}

/// Sets the voxel nearest to `p` to at least `hu` (a wire a voxel thick, as a strut blooms in CT).
void Paint(CtImage& ct, const Point3& p, double hu)
{
  itk::Point<double, 3> x;
  for (int a = 0; a < 3; ++a)
    x[a] = p[a];
  CtImage::IndexType index;
  if (ct.TransformPhysicalPointToIndex(x, index))
    ct.SetPixel(index, std::max<short>(ct.GetPixel(index), static_cast<short>(hu)));
}

/// Z-stent rings of a stent graft's body, `radiusMm` around the aorta's truth axis, from `topZ`
/// down to `bottomZ`: rings 10 mm high, 4 mm apart, 8 apices each, struts of `hu` (its fabric is
/// not visible in CT). In the sac the graft hangs in the lumen on the axis; in the neck it lies on
/// the wall.
void DrawStentGraft(CtImage& ct, const PhantomTruth& truth, double topZ, double bottomZ, double radiusMm, double hu)
{
  constexpr double ringMm = 10.0, gapMm = 4.0, apices = 8.0;
  for (double ringTop = topZ; ringTop - ringMm >= bottomZ; ringTop -= ringMm + gapMm)
    for (double t = 0.0; t < 1.0; t += 0.0002)
    {
      const double phase = std::fmod(apices * t, 1.0); // a zigzag: up and down once per apex
      const double z = ringTop - ringMm * (phase < 0.5 ? 2.0 * phase : 2.0 - 2.0 * phase);
      const Point3 centre = AxisAt(truth, z);
      Paint(ct,
            Point3(centre.x() + radiusMm * std::cos(2.0 * pi * t), centre.y() + radiusMm * std::sin(2.0 * pi * t), z),
            hu);
    }
}

/// A 10 mm stent over 30 mm of the right common iliac, 5 mm below the bifurcation, struts of 3,000 HU.
void DrawIliacStent(AorticPhantom& phantom)
{
  const double bifurcationZ = LandmarkZ(phantom.truth, "aorticBifurcation");
  for (const PhantomVessel& v : phantom.truth.vessels)
    if (v.name == "rightIliac")
    {
      PhantomTruth iliac;
      iliac.vessels.push_back(v);
      DrawStentGraft(*phantom.ct, iliac, bifurcationZ - 5.0, bifurcationZ - 35.0, 4.0, 3000.0);
    }
}

/// The default anatomy (0.8 × 0.8 × 1.0 mm, noise 20 HU, renal arteries, a vertebra).
AorticPhantom Default(double spacingZ = 1.0)
{
  PhantomParams p;
  p.includeBone = true;
  p.spacingMm = { 0.8, 0.8, spacingZ };
  return GenerateAorticPhantom(p);
}

PlanRequest Through(PlanStage stage)
{
  PlanRequest request;
  request.through = stage;
  return request;
}

/// Struts of 1,500 HU (the least) and 3,000 HU, on 1 and 2.5 mm slices, and their names.
auto StrutAndSliceValues()
{
  return ::testing::Combine(::testing::Values(1500.0, 3000.0), ::testing::Values(1.0, 2.5));
}

std::string StrutsAndSlicesName(const ::testing::TestParamInfo<std::tuple<double, double>>& info)
{
  return std::to_string(int(std::get<0>(info.param))) + "HU_" + std::to_string(int(10 * std::get<1>(info.param))) +
         "tenthsMm";
}

// A stent graft in the aorta, from 2 mm above the lowest renal to the bifurcation, struts of
// 1,500 HU (the least) and 3,000 HU, on 1 and 2.5 mm slices: the plan stops at once with
// an error that names the endograft, for every stage asked for.
class EndograftInTheAorta : public ::testing::TestWithParam<std::tuple<double, double>>
{
};

TEST_P(EndograftInTheAorta, IsNamedAsAnEndograft)
{
  const auto [strutHu, sliceMm] = GetParam();
  AorticPhantom phantom = Default(sliceMm);
  const double siteZ = LandmarkZ(phantom.truth, "rightRenalOstium");
  const double bifurcationZ = LandmarkZ(phantom.truth, "aorticBifurcation");
  const double neckRadius = phantom.truth.sizing.proximalNeckDiameter / 2.0;
  DrawStentGraft(*phantom.ct, phantom.truth, siteZ + 2.0, bifurcationZ, neckRadius - 0.5, strutHu);
  for (PlanStage stage : { PlanStage::Centerlines, PlanStage::Device })
  {
    try
    {
      PlanRepair(phantom.ct, phantom.truth.seedLps, Through(stage), testing::ShippedPlanParams());
      ADD_FAILURE() << "a post-EVAR scan was planned";
    }
    catch (const InputError& e)
    {
      const std::string message = e.what();
      EXPECT_NE(message.find("an endograft or another metal device is already in place"), std::string::npos) << message;
      EXPECT_NE(message.find("pre-operative"), std::string::npos) << message;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(StrutsAndSlices, EndograftInTheAorta, StrutAndSliceValues(), StrutsAndSlicesName);

/// A post-EVAR scan whose graft's lumen cannot be grown from a seed inside it (issue 46 item 8):
/// the graft of DrawStentGraft from 2 mm above the lowest renal to the bifurcation, its sac
/// excluded (the lumen and its blurred edge outside the graft's radius, between the site and the
/// bifurcation, at thrombus HU), and every 4 mm from its top down (its rings' apices, the struts
/// between) a slice of metal streaks across the graft's lumen — alternating dark (−100 HU) and
/// bright (1,200 HU) diagonal lines a voxel wide, the beam hardening of struts seen edge-on —
/// which the growing cannot cross (dark voxels lie below its window, bright ones above its calcium
/// limit). Returns the heights of the rings' tops (LPS z).
std::vector<double> DrawUngrowableEndograft(AorticPhantom& phantom, double strutHu)
{
  const double siteZ = LandmarkZ(phantom.truth, "rightRenalOstium");
  const double bifurcationZ = LandmarkZ(phantom.truth, "aorticBifurcation");
  const double radius = phantom.truth.sizing.proximalNeckDiameter / 2.0 - 0.5;
  std::vector<double> tops;
  for (double top = siteZ + 2.0; top - 10.0 >= bifurcationZ; top -= 14.0) // DrawStentGraft's rings
    tops.push_back(top);
  const auto spacing = phantom.ct->GetSpacing();
  const auto region = phantom.ct->GetLargestPossibleRegion();
  // The sac's lumen and its blurred edge, out to 3 mm beyond the widest sac (three blur widths).
  const double sacReach = phantom.truth.sizing.maxAneurysmDiameter / 2.0 + 3.0;
  for (itk::ImageRegionConstIteratorWithIndex<LabelImage> it(phantom.labels, region); !it.IsAtEnd(); ++it)
  {
    if (it.Get() != LumenLabel && it.Get() != TissueLabel)
      continue;
    itk::Point<double, 3> x;
    phantom.ct->TransformIndexToPhysicalPoint(it.GetIndex(), x);
    if (x[2] > siteZ + 2.0 || x[2] < bifurcationZ)
      continue;
    const Point3 centre = AxisAt(phantom.truth, x[2]);
    const double r = std::hypot(x[0] - centre.x(), x[1] - centre.y());
    if (r > radius)
    {
      if (r <= sacReach && phantom.ct->GetPixel(it.GetIndex()) > 45)
        phantom.ct->SetPixel(it.GetIndex(), 45); // the excluded sac: thrombus
      continue;
    }
    // Streaks 4 mm apart from the graft's top down; a slice each (the one nearest each level).
    const double fromTop = siteZ + 2.0 - x[2];
    if (std::abs(fromTop - 4.0 * std::round(fromTop / 4.0)) <= spacing[2] / 2.0)
      phantom.ct->SetPixel(it.GetIndex(), (it.GetIndex()[0] + it.GetIndex()[1]) % 2 ? -100 : 1200);
  }
  DrawStentGraft(*phantom.ct, phantom.truth, siteZ + 2.0, bifurcationZ, radius, strutHu);
  return tops;
}

// The seed in the gap between two rings of the graft's body, on 1 and 2.5 mm slices, struts of
// 1,500 and 3,000 HU: the lumen grown from it is a few millimetres long (or none is grown), too
// little for the check beside the lumen, and the plan still names the endograft — from the rings
// around the seed, found over the graft's whole length.
class EndograftThatStopsTheGrowing : public ::testing::TestWithParam<std::tuple<double, double>>
{
};

TEST_P(EndograftThatStopsTheGrowing, IsNamedAsAnEndograft)
{
  const auto [strutHu, sliceMm] = GetParam();
  AorticPhantom phantom = Default(sliceMm);
  const std::vector<double> tops = DrawUngrowableEndograft(phantom, strutHu);
  ASSERT_GE(tops.size(), 5u);
  const Point3 seed = AxisAt(phantom.truth, tops[tops.size() / 2] - 6.0); // in a ring, between two streaks

  // The class: the lumen grown from this seed is one gap between streaks (3 mm on 1 mm slices, as
  // on the real scan), too short for FindEndograft beside it, which needs 10 mm of rings.
  try
  {
    const LumenSegmentation lumen = GrowLumenRegion(*phantom.ct, seed, testing::ShippedPlanParams().growing);
    const IndexBox grown = ForegroundBox(*lumen.mask);
    EXPECT_LE(double(grown.size[2]) * phantom.ct->GetSpacing()[2], 4.0) << "the streaks did not stop it";
    EXPECT_FALSE(FindEndograft(*phantom.ct, *lumen.mask, lumen.box).found);
  }
  catch (const std::exception& e) // no lumen at all: as much the class
  {
    SUCCEED() << e.what();
  }

  const EndograftEvidence metal = FindEndograftAroundSeed(*phantom.ct, seed);
  EXPECT_TRUE(metal.found);
  EXPECT_TRUE(metal.aroundSeed);
  // The walk follows the graft from its top ring to its lowest: each end within a slice and a half
  // (a ring's apex is drawn to the voxel nearest it, a bin is one slice).
  EXPECT_NEAR(metal.ringToZ, tops.front(), 1.5 * sliceMm);
  EXPECT_NEAR(metal.ringFromZ, tops.back() - 10.0, 1.5 * sliceMm);
  // The rings' 10 mm each, the 4 mm gaps not: within a slice per ring (binning of each ring's ends).
  EXPECT_NEAR(metal.ringLengthMm, 10.0 * double(tops.size()), sliceMm * double(tops.size()));

  for (PlanStage stage : { PlanStage::Segmentation, PlanStage::Device })
  {
    try
    {
      PlanRepair(phantom.ct, seed, Through(stage), testing::ShippedPlanParams());
      ADD_FAILURE() << "a post-EVAR scan was planned";
    }
    catch (const InputError& e)
    {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind("The aorta holds metal around the seed", 0), 0u) << message;
      EXPECT_NE(message.find("an endograft or another metal device is already in place"), std::string::npos) << message;
    }
    catch (const std::exception& e)
    {
      ADD_FAILURE() << "not named as an endograft: " << e.what();
    }
  }
}

INSTANTIATE_TEST_SUITE_P(StrutsAndSlices, EndograftThatStopsTheGrowing, StrutAndSliceValues(), StrutsAndSlicesName);

// What is not an endograft: the same phantom without it (no metal beside the lumen at all);
// calcified plaque at its brightest (1,200 HU) over three quarters of the neck and the sac; a
// vertebra touching the vessel; and a stent in one common iliac (a ring 4 mm in radius, too narrow
// for the aorta): each plans to the centerlines.
TEST(Endograft, CalciumBoneAndAnIliacStent_AreNotOne)
{
  PhantomParams calcified = testing::WithWallInFat(PhantomParams{});
  calcified.includeBone = true;
  calcified.boneGapMm = 0.5; // the least: the vertebra against the wall
  calcified.calcificationHu = 1200.0;
  calcified.neckCalcificationArcDeg = 270.0;
  calcified.sacCalcificationArcDeg = 270.0;
  for (const PhantomParams& p : { PhantomParams{}, calcified })
  {
    AorticPhantom phantom = GenerateAorticPhantom(p);
    if (&p == &calcified)
    {
      DrawIliacStent(phantom);
    }
    const LumenSegmentation lumen =
      GrowLumenRegion(*phantom.ct, phantom.truth.seedLps, testing::ShippedPlanParams().growing);
    const EndograftEvidence metal = FindEndograft(*phantom.ct, *lumen.mask, lumen.box);
    EXPECT_FALSE(metal.found) << metal.ringLengthMm << " mm of rings";
    EXPECT_EQ(metal.ringBins, 0);
    if (&p == &calcified)
    {
      EXPECT_GT(metal.metalVoxels, 0); // the iliac stent's struts are seen, and are not a ring of the aorta
    }
    else
    {
      EXPECT_EQ(metal.metalVoxels, 0);
    }
    EXPECT_NO_THROW(
      PlanRepair(phantom.ct, phantom.truth.seedLps, Through(PlanStage::Centerlines), testing::ShippedPlanParams()));
  }
}

// What the walk around the seed must not take for rings: a vertebra against the wall whose
// cortex reads 1,800 HU (above metalHu; the phantom's 1,100 raised), a stent in the right common
// iliac (3,000 HU), the seed on the axis and 2 mm from the posterior wall (nearest the vertebra),
// from the neck to the bifurcation. Seen from inside the aorta, the vertebra fills at most a few of
// the 8 sectors and the iliac stent lies outside the aorta; no ring, and the plan goes on.
TEST(Endograft, DenseBoneAndAnIliacStentAroundTheSeed_AreNotOne)
{
  PhantomParams p;
  p.includeBone = true;
  p.boneGapMm = 0.5;
  AorticPhantom phantom = GenerateAorticPhantom(p);
  const auto region = phantom.ct->GetLargestPossibleRegion();
  int dense = 0;
  for (itk::ImageRegionConstIteratorWithIndex<LabelImage> it(phantom.labels, region); !it.IsAtEnd(); ++it)
    if (it.Get() == BoneLabel && phantom.ct->GetPixel(it.GetIndex()) > 700)
    {
      phantom.ct->SetPixel(it.GetIndex(), 1800);
      ++dense;
    }
  ASSERT_GT(dense, 1000); // the cortex was there to raise
  const double siteZ = LandmarkZ(phantom.truth, "rightRenalOstium");
  const double bifurcationZ = LandmarkZ(phantom.truth, "aorticBifurcation");
  DrawIliacStent(phantom);
  int seeds = 0;
  for (double z = siteZ; z > bifurcationZ + 5.0; z -= 10.0)
    for (const double fromWall : { -1.0, 2.0 }) // −1: the axis
    {
      Point3 seed = AxisAt(phantom.truth, z);
      if (fromWall > 0.0)
      {
        // The lumen's posterior wall (+y in LPS) along the ray from the axis, from the labels.
        double r = 0.0;
        for (;; r += 0.2)
        {
          itk::Point<double, 3> x;
          x[0] = seed.x(), x[1] = seed.y() + r + 0.2, x[2] = z;
          LabelImage::IndexType index;
          if (!phantom.labels->TransformPhysicalPointToIndex(x, index) || phantom.labels->GetPixel(index) != LumenLabel)
            break;
        }
        seed.y() += std::max(0.0, r - fromWall);
      }
      const EndograftEvidence metal = FindEndograftAroundSeed(*phantom.ct, seed);
      EXPECT_FALSE(metal.found) << "seed at z " << z << ": " << metal.ringLengthMm << " mm of rings";
      EXPECT_EQ(metal.ringBins, 0) << "seed at z " << z;
      EXPECT_GT(metal.metalVoxels, 0); // the cortex and the iliac stent are seen, and are no ring around the seed
      ++seeds;
    }
  EXPECT_GE(seeds, 10);
  EXPECT_NO_THROW(
    PlanRepair(phantom.ct, phantom.truth.seedLps, Through(PlanStage::Centerlines), testing::ShippedPlanParams()));
}

/// A dissection flap: a septum `thicknessMm` thick through the aorta's axis, turned `angleDeg` from
/// the sagittal plane, from `topZ` down to the image's end, at `hu` where the lumen was (the
/// phantom's label map says where). The true and the false lumen run side by side below it.
void DrawDissectionFlap(AorticPhantom& phantom, double topZ, double angleDeg, double thicknessMm, double hu)
{
  const Point3 normal(std::cos(angleDeg * pi / 180.0), std::sin(angleDeg * pi / 180.0), 0.0);
  const auto region = phantom.ct->GetLargestPossibleRegion();
  for (itk::ImageRegionConstIteratorWithIndex<LabelImage> it(phantom.labels, region); !it.IsAtEnd(); ++it)
  {
    if (it.Get() != LumenLabel)
      continue;
    itk::Point<double, 3> x;
    phantom.ct->TransformIndexToPhysicalPoint(it.GetIndex(), x);
    if (x[2] > topZ)
      continue;
    const Point3 centre = AxisAt(phantom.truth, x[2]);
    const Point3 p(x[0], x[1], x[2]);
    // Only the aorta: within its radius of its axis (the renal arteries keep their lumen).
    if (std::hypot(p.x() - centre.x(), p.y() - centre.y()) > phantom.truth.sizing.proximalNeckDiameter)
      continue;
    if (std::abs((p - centre).dot(normal)) <= thicknessMm / 2.0)
      phantom.ct->SetPixel(it.GetIndex(), static_cast<short>(hu));
  }
}

// A dissection that reaches the scan's lower border above the visceral arteries (issue 33's real
// case ends at the superior mesenteric): the aorta 200 mm above the renal arteries, split by a
// 1.5 mm flap from 100 mm above them down, the scan cut 45 mm above them (the coeliac trunk leaves
// at 35) — two channels, side by side, 55 mm to the border. No Y: the plan and the centerlines
// alike stop with the no-bifurcation error, which says what the two channels are.
class DissectionToTheBorder : public ::testing::TestWithParam<double>
{
};

TEST_P(DissectionToTheBorder, IsNoBifurcation)
{
  // Turned 30°, the flap's top is a junction of a Y's shape and the side-by-side rule refuses it
  // (LimbDivergence.h: 2.2° over 40 mm, lumens 2.4 mm apart), which the error names; at 0° the
  // channels' skeleton makes no Y-shaped junction at all.
  const bool namesTheChannels = GetParam() == 30.0;
  PhantomParams p;
  p.aortaAboveSiteMm = 200.0;
  AorticPhantom phantom = GenerateAorticPhantom(p);
  const double siteZ = LandmarkZ(phantom.truth, "rightRenalOstium");
  DrawDissectionFlap(phantom, siteZ + 100.0, GetParam(), 1.5, 40.0);
  const CtImage::Pointer cut = testing::CropBelow(*phantom.ct, siteZ + 45.0);
  for (PlanStage stage : { PlanStage::Centerlines, PlanStage::Device })
  {
    try
    {
      const RepairPlan plan =
        PlanRepair(cut, AxisAt(phantom.truth, siteZ + 150.0), Through(stage), testing::ShippedPlanParams());
      ADD_FAILURE() << "a Y was taken (partial: " << plan.centerlines.Partial() << ", coverage "
                    << plan.centerlines.iliacCoverageMm[0] << " and " << plan.centerlines.iliacCoverageMm[1] << " mm)";
    }
    catch (const AlgorithmError& e)
    {
      const std::string message = e.what();
      EXPECT_NE(message.find("No aortic bifurcation found"), std::string::npos) << message;
      EXPECT_EQ(message.find("run on side by side") != std::string::npos, namesTheChannels) << message;
      EXPECT_EQ(message.find("dissection") != std::string::npos, namesTheChannels) << message;
    }
  }
}

// The flap turned 0° (the channels right and left of each other) and 30°.
INSTANTIATE_TEST_SUITE_P(FlapAngles,
                         DissectionToTheBorder,
                         ::testing::Values(0.0, 30.0),
                         [](const auto& info) { return std::to_string(int(info.param)) + "deg"; });

} // namespace
} // namespace sgp
