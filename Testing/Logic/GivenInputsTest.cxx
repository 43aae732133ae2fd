// Issue 45: what a person gives enters at the pipeline's door — a lumen segmentation on any grid
// (LumenFromSegmentation.h) and landmarks put into the labelled tree (GivenLandmarks.h) — tested
// against their analytic truth: ITK's own nearest-voxel rounding as the oracle for the resampling,
// straight centerlines for the landmarks.
#include <cmath>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <itkImageRegionIteratorWithIndex.h>

#include "Centerlines/GivenLandmarks.h"
#include "Centerlines/VesselOrigins.h"
#include "Common/ImageGeometry.h"
#include "Common/Errors.h"
#include "Segmentation/LumenFromSegmentation.h"
#include "MaskPhantoms.h"
#include "YPhantom.h"

namespace sgp
{
namespace
{

template<typename Image>
typename Image::Pointer MakeImage(const std::array<long, 3>& size,
                                  const std::array<double, 3>& spacing,
                                  const Point3& origin,
                                  const Eigen::Matrix3d& direction = Eigen::Matrix3d::Identity())
{
  auto image = Image::New();
  typename Image::RegionType region;
  for (unsigned a = 0; a < 3; ++a)
    region.SetSize(a, static_cast<itk::SizeValueType>(size[a]));
  image->SetRegions(region);
  typename Image::SpacingType s;
  typename Image::PointType o;
  typename Image::DirectionType d;
  for (unsigned a = 0; a < 3; ++a)
  {
    s[a] = spacing[a];
    o[a] = origin[a];
    for (unsigned b = 0; b < 3; ++b)
      d(a, b) = direction(a, b);
  }
  image->SetSpacing(s);
  image->SetOrigin(o);
  image->SetDirection(d);
  image->Allocate(true);
  return image;
}

/// Balls (centre, radius mm) painted into a mask on its grid.
void PaintBalls(LabelImage& mask, const std::vector<std::pair<Point3, double>>& balls)
{
  itk::ImageRegionIteratorWithIndex<LabelImage> it(&mask, mask.GetLargestPossibleRegion());
  for (; !it.IsAtEnd(); ++it)
  {
    itk::Point<double, 3> p;
    mask.TransformIndexToPhysicalPoint(it.GetIndex(), p);
    for (const auto& [c, r] : balls)
      if ((Point3(p[0], p[1], p[2]) - c).norm() <= r)
        it.Set(1);
  }
}

Eigen::Matrix3d RotationZ(double degrees)
{
  return Eigen::AngleAxisd(degrees * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

/// On another grid (anisotropic, rotated 30° about z, shifted origin), every CT voxel takes the
/// value of the segmentation voxel ITK's TransformPhysicalPointToIndex (nearest, ties rounded up)
/// names for its centre — the oracle — and voxels outside the segmentation are background.
TEST(LumenFromSegmentation, EachCtVoxelTakesItsNearestSegmentationVoxel)
{
  auto given = MakeImage<LabelImage>({ 60, 60, 24 }, { 0.7, 0.7, 2.5 }, Point3(-20, -20, -30));
  PaintBalls(*given, { { Point3(0.3, 0.2, 0.1), 11.0 } });
  // The ball's centre near the CT's index (25.3, 24.6, 35.2): wholly inside its 50 × 50 × 70 mm.
  const Point3 ctOrigin = -(RotationZ(30.0) * Point3(25.3, 24.6, 35.2));
  auto ct = MakeImage<CtImage>({ 50, 50, 70 }, { 1.0, 1.0, 1.0 }, ctOrigin, RotationZ(30.0));
  const LumenSegmentation lumen = LumenFromSegmentation(given, ct.GetPointer(), std::nullopt, "test");
  ASSERT_TRUE(lumen.mask);
  EXPECT_EQ(lumen.mask->GetLargestPossibleRegion(), ct->GetLargestPossibleRegion());
  long mismatches = 0, lumenVoxels = 0;
  itk::ImageRegionIteratorWithIndex<LabelImage> it(lumen.mask, lumen.mask->GetLargestPossibleRegion());
  for (; !it.IsAtEnd(); ++it)
  {
    itk::Point<double, 3> p;
    ct->TransformIndexToPhysicalPoint(it.GetIndex(), p);
    itk::Index<3> nearest;
    const bool inside = given->TransformPhysicalPointToIndex(p, nearest);
    const unsigned char expected = inside ? given->GetPixel(nearest) : 0;
    mismatches += it.Get() != expected;
    lumenVoxels += it.Get();
  }
  EXPECT_EQ(mismatches, 0);
  // The ball's volume (5.58 mL) within the segmentation grid's partial voxels (a 2.5 mm slab at
  // each pole and a 0.7 mm shell: about 10 %).
  EXPECT_NEAR(lumen.volumeMl, 4.0 / 3.0 * M_PI * 11.0 * 11.0 * 11.0 / 1000.0, 0.6);
  EXPECT_NEAR(lumen.volumeMl, double(lumenVoxels) / 1000.0, 1e-9);
  EXPECT_NE(lumen.windowSource.find("no region growing"), std::string::npos) << lumen.windowSource;
}

/// On the CT's own grid (the plan's label map given back) the mask is copied voxel for voxel.
TEST(LumenFromSegmentation, OnTheCtsGridEveryVoxelKept)
{
  auto given = MakeImage<LabelImage>({ 40, 30, 20 }, { 0.7, 0.8, 2.5 }, Point3(-5, 3, -40), RotationZ(30.0));
  PaintBalls(*given, { { IndexToLps(*given, { { 20, 15, 10 } }), 7.0 } });
  auto ct = MakeImage<CtImage>({ 40, 30, 20 }, { 0.7, 0.8, 2.5 }, Point3(-5, 3, -40), RotationZ(30.0));
  const LabelImage::Pointer before = testing::CopyMask(*given);
  const LumenSegmentation lumen = LumenFromSegmentation(given, ct.GetPointer(), std::nullopt, "test");
  EXPECT_EQ(lumen.mask.GetPointer(), given.GetPointer()); // handed over: no second full-size mask
  long differ = 0, count = 0;
  for (std::size_t v = 0; v < ct->GetLargestPossibleRegion().GetNumberOfPixels(); ++v)
  {
    differ += lumen.mask->GetBufferPointer()[v] != before->GetBufferPointer()[v];
    count += before->GetBufferPointer()[v];
  }
  EXPECT_GT(count, 100);
  EXPECT_EQ(differ, 0);
}

/// Two pieces: the larger is kept without a seed, the seed's with one; the warning names the
/// pieces and the volume left out.
TEST(LumenFromSegmentation, KeepsOnePieceAndNamesTheOthers)
{
  auto given = MakeImage<LabelImage>({ 80, 40, 40 }, { 1.0, 1.0, 1.0 }, Point3(0, 0, 0));
  PaintBalls(*given, { { Point3(20, 20, 20), 12.0 }, { Point3(60, 20, 20), 5.0 } });
  const LumenSegmentation larger = LumenFromSegmentation(testing::CopyMask(*given), nullptr, std::nullopt, "test");
  EXPECT_NEAR(larger.volumeMl, 4.0 / 3.0 * M_PI * 12.0 * 12.0 * 12.0 / 1000.0, 0.2);
  ASSERT_EQ(larger.warnings.size(), 1u);
  EXPECT_NE(larger.warnings[0].find("2 separate pieces"), std::string::npos) << larger.warnings[0];
  EXPECT_NE(larger.warnings[0].find("the largest"), std::string::npos) << larger.warnings[0];
  EXPECT_NE(larger.warnings[0].find("0.52 mL"), std::string::npos) << larger.warnings[0]; // the small ball
  EXPECT_EQ(larger.mask->GetPixel({ { 60, 20, 20 } }), 0);
  const LumenSegmentation seeded =
    LumenFromSegmentation(testing::CopyMask(*given), nullptr, Point3(60, 20, 20), "test");
  EXPECT_EQ(seeded.mask->GetPixel({ { 60, 20, 20 } }), 1);
  EXPECT_EQ(seeded.mask->GetPixel({ { 20, 20, 20 } }), 0);
  EXPECT_NE(seeded.warnings[0].find("holding the seed"), std::string::npos) << seeded.warnings[0];
}

/// A cavity inside the given lumen becomes lumen (as region growing's step 6).
TEST(LumenFromSegmentation, FillsCavities)
{
  auto given = MakeImage<LabelImage>({ 40, 40, 40 }, { 1.0, 1.0, 1.0 }, Point3(0, 0, 0));
  PaintBalls(*given, { { Point3(20, 20, 20), 12.0 } });
  for (long k = 18; k <= 22; ++k)
    given->SetPixel({ { 20, 20, k } }, 0);
  const LumenSegmentation lumen = LumenFromSegmentation(given, nullptr, std::nullopt, "test");
  EXPECT_EQ(lumen.mask->GetPixel({ { 20, 20, 20 } }), 1);
  EXPECT_TRUE(lumen.warnings.empty());
}

/// The window from the CT: the interior's median and σ as the seed statistics; the window the
/// region growing would take from this lumen's core (step 1b), checked against GrowLumenRegion on
/// the same CT; calcium above its top plus a quarter of its width.
TEST(LumenFromSegmentation, WindowFromTheCtInside)
{
  auto given = MakeImage<LabelImage>({ 60, 60, 60 }, { 1.0, 1.0, 1.0 }, Point3(0, 0, 0));
  PaintBalls(*given, { { Point3(30, 30, 30), 16.0 } });
  auto ct = MakeImage<CtImage>({ 60, 60, 60 }, { 1.0, 1.0, 1.0 }, Point3(0, 0, 0));
  ct->FillBuffer(40);
  for (std::size_t v = 0; v < ct->GetLargestPossibleRegion().GetNumberOfPixels(); ++v)
    if (given->GetBufferPointer()[v])
      ct->GetBufferPointer()[v] = static_cast<short>(300 + (v % 3 == 0 ? 20 : v % 3 == 1 ? -20 : 0));
  const LumenSegmentation lumen = LumenFromSegmentation(given, ct.GetPointer(), std::nullopt, "test");
  EXPECT_NEAR(lumen.seedMedianHu, 300.0, 1e-9);
  EXPECT_NEAR(lumen.seedSigmaHu, 1.4826 * 20.0, 1e-9); // the MAD of ±20 and 0 in thirds
  const LumenSegmentation grown = GrowLumenRegion(*ct, Point3(30, 30, 30), RegionGrowingParams{});
  EXPECT_NEAR(lumen.lowerHu, grown.lowerHu, 1e-9);
  EXPECT_NEAR(lumen.upperHu, grown.upperHu, 1e-9);
  EXPECT_NEAR(lumen.calciumHu, grown.calciumHu, 1e-9);
  EXPECT_TRUE(std::isnan(lumen.edgeHu));
}

/// A segmentation of another place: one ERROR naming both extents.
TEST(LumenFromSegmentation, NoOverlapNamesBothExtents)
{
  auto given = MakeImage<LabelImage>({ 20, 20, 20 }, { 1.0, 1.0, 1.0 }, Point3(500, 0, 0));
  PaintBalls(*given, { { Point3(510, 10, 10), 5.0 } });
  auto ct = MakeImage<CtImage>({ 20, 20, 20 }, { 1.0, 1.0, 1.0 }, Point3(0, 0, 0));
  try
  {
    LumenFromSegmentation(given, ct.GetPointer(), std::nullopt, "test");
    FAIL() << "no error";
  }
  catch (const InputError& e)
  {
    const std::string what = e.what();
    EXPECT_NE(what.find("does not overlap"), std::string::npos) << what;
    EXPECT_NE(what.find("x 499.5 to 519.5"), std::string::npos) << what; // the segmentation's
    EXPECT_NE(what.find("x -0.5 to 19.5"), std::string::npos) << what;   // the CT's
  }
  auto empty = MakeImage<LabelImage>({ 20, 20, 20 }, { 1.0, 1.0, 1.0 }, Point3(0, 0, 0));
  EXPECT_THROW(LumenFromSegmentation(empty, ct.GetPointer(), std::nullopt, "test"), InputError);
}

/// A Y of straight centerlines (YPhantom.h: B at z = 40, iliacs to (∓30, 0, −40)) with two branches
/// on the right iliac: the labelling's internal iliac 40 mm along it and a branch 15 mm along it.
CenterlineTree TreeWithTwoRightBranches()
{
  const testing::YPhantom y = testing::MakeYPhantom(2.0);
  CenterlineTree tree = y.tree;
  const Centerline& iliac = tree.rightIliac;
  const Point3 at40 = PositionAt(iliac, 40.0), at15 = PositionAt(iliac, 15.0);
  tree.sideBranches.push_back(testing::StraightCenterline("rightInternalIliac", at40, at40 + Point3(-5, 20, -20), 3));
  tree.sideBranches.push_back(testing::StraightCenterline("rightIliacBranch1", at15, at15 + Point3(-5, 20, -20), 3));
  tree.landmarks.push_back({ "rightIliacBifurcation", at40 });
  return tree;
}

/// A given origin near another branch: that branch becomes the internal iliac (the labelling's is
/// numbered), the origin is the given point's abscissa, the landmark moves to the branch's junction.
TEST(GivenLandmarks, InternalIliacOriginNamesTheBranchThere)
{
  CenterlineTree tree = TreeWithTwoRightBranches();
  const Point3 at15 = PositionAt(tree.rightIliac, 15.0);
  ASSERT_NEAR(InternalIliacOriginAbscissa(tree, 0), 40.0, 1e-6);
  GivenLandmarks given;
  given.internalIliacOriginLps[0] = PositionAt(tree.rightIliac, 17.0) + Point3(0, 4.0, 0); // 4 mm behind the axis
  ApplyGivenLandmarks(tree, given);
  EXPECT_NEAR(InternalIliacOriginAbscissa(tree, 0), 17.0, 1e-6);
  ASSERT_NE(tree.FindVessel("rightInternalIliac"), nullptr);
  EXPECT_NEAR((Point3(tree.FindVessel("rightInternalIliac")->points.row(0).transpose()) - at15).norm(), 0.0, 1e-9);
  EXPECT_NE(tree.FindVessel("rightIliacBranch2"), nullptr); // the labelling's, numbered
  EXPECT_NEAR((tree.FindLandmark("rightIliacBifurcation")->lps - at15).norm(), 0.0, 1e-9);
  // The left and B as found.
  EXPECT_TRUE(std::isnan(InternalIliacOriginAbscissa(tree, 1)));
  EXPECT_FALSE(FindAorticBifurcation(tree).given);
}

/// A given origin with no branch within SnapBranchMm: no internal iliac centerline is kept.
TEST(GivenLandmarks, InternalIliacOriginWithNoBranchNear)
{
  CenterlineTree tree = TreeWithTwoRightBranches();
  GivenLandmarks given;
  given.internalIliacOriginLps[0] = PositionAt(tree.rightIliac, 70.0);
  ApplyGivenLandmarks(tree, given);
  EXPECT_NEAR(InternalIliacOriginAbscissa(tree, 0), 70.0, 1e-6);
  EXPECT_EQ(tree.FindVessel("rightInternalIliac"), nullptr);
}

/// The bifurcation is used where it is given; its abscissa along the aorta's end tangent.
TEST(GivenLandmarks, BifurcationUsedWhereGiven)
{
  CenterlineTree tree = TreeWithTwoRightBranches();
  GivenLandmarks given;
  given.aorticBifurcationLps = Point3(1.0, 2.0, 35.0); // 5 mm below the centerline's end (z 40)
  ApplyGivenLandmarks(tree, given);
  const AorticBifurcation b = FindAorticBifurcation(tree);
  EXPECT_TRUE(b.given);
  EXPECT_NEAR((b.lps - Point3(1.0, 2.0, 35.0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(b.abscissaMm, 100.0 + 5.0, 1e-9);                  // the aorta runs 100 mm from z 140 to 40
  EXPECT_NEAR(InternalIliacOriginAbscissa(tree, 0), 40.0, 1e-6); // unchanged
}

std::string ErrorOf(const GivenLandmarks& given)
{
  CenterlineTree tree = TreeWithTwoRightBranches();
  try
  {
    ApplyGivenLandmarks(tree, given);
  }
  catch (const InputError& e)
  {
    return e.what();
  }
  return "";
}

/// Each bad landmark: one message naming the distance and the centerline.
TEST(GivenLandmarks, BadPointsNameTheDistanceAndTheCenterline)
{
  const testing::YPhantom y = testing::MakeYPhantom(2.0);
  GivenLandmarks far;
  far.internalIliacOriginLps[0] = PositionAt(y.tree.rightIliac, 30.0) + Point3(0, 12.0, 0);
  std::string what = ErrorOf(far);
  EXPECT_NE(what.find("12.0 mm from the right iliac centerline"), std::string::npos) << what;
  EXPECT_NE(what.find("within 10 mm"), std::string::npos) << what;

  GivenLandmarks wrongSide; // a right origin placed on the left iliac
  wrongSide.internalIliacOriginLps[0] = PositionAt(y.tree.leftIliac, 30.0);
  what = ErrorOf(wrongSide);
  EXPECT_NE(what.find("rightInternalIliacOrigin"), std::string::npos) << what;
  EXPECT_NE(what.find("on the patient's left"), std::string::npos) << what;
  GivenLandmarks wrongSideLeft;
  wrongSideLeft.internalIliacOriginLps[1] = PositionAt(y.tree.rightIliac, 30.0);
  what = ErrorOf(wrongSideLeft);
  EXPECT_NE(what.find("on the patient's right"), std::string::npos) << what;

  GivenLandmarks farBifurcation;
  farBifurcation.aorticBifurcationLps = Point3(0, 0, 60.0); // 20 mm above the aorta's end
  what = ErrorOf(farBifurcation);
  EXPECT_NE(what.find("20.0 mm from the aortic centerline's lower end"), std::string::npos) << what;
  EXPECT_NE(what.find("within 15 mm"), std::string::npos) << what;

  GivenLandmarks near; // within every bound: no error
  near.aorticBifurcationLps = Point3(0, 0, 50.0);
  near.internalIliacOriginLps[1] = PositionAt(y.tree.leftIliac, 30.0) + Point3(0, 9.0, 0);
  EXPECT_EQ(ErrorOf(near), "");
}

} // namespace
} // namespace sgp
