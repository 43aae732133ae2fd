// The straightened view, the straightened volume and the cross-section against analytic truth: a
// tilted straight tube of known radius on an oblique grid (issue 15, "What must show").
#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <itkImageRegionIteratorWithIndex.h>

#include "Common/Errors.h"
#include "Common/ImageGeometry.h"
#include "Views/ResliceCt.h"
#include "Views/VesselPath.h"
#include "YPhantom.h"

namespace sgp
{
namespace
{

constexpr double TubeRadiusMm = 7.8; // not a multiple of the 0.5 mm pixel: no edge falls on a pixel centre
constexpr double LumenHu = 400.0;
constexpr double RampMm = 1.0; // the edge: a linear ramp 1 mm wide centred on the radius

/// A CT (0.8 × 0.8 × 1.0 mm, direction cosines rotated 20° about z and 10° about x) holding an
/// infinite tube of TubeRadiusMm along `axis` through `centre`: HU 400 inside, 0 outside, a linear
/// ramp across the edge (so the 200 HU level lies exactly at the radius).
struct TiltedTube
{
  CtImage::Pointer ct;
  Point3 centre;
  Eigen::Vector3d axis;
};

TiltedTube MakeTiltedTube()
{
  TiltedTube tube;
  tube.ct = CtImage::New();
  CtImage::RegionType region;
  region.SetSize({ 110, 110, 140 });
  tube.ct->SetRegions(region);
  const double spacing[3] = { 0.8, 0.8, 1.0 };
  tube.ct->SetSpacing(spacing);
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(20 * M_PI / 180, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(10 * M_PI / 180, Eigen::Vector3d::UnitX()))
                              .toRotationMatrix();
  CtImage::DirectionType d;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      d[r][c] = R(r, c);
  tube.ct->SetDirection(d);
  CtImage::PointType origin;
  origin[0] = 12.0;
  origin[1] = -30.0;
  origin[2] = 50.0;
  tube.ct->SetOrigin(origin);
  tube.ct->Allocate();
  const Eigen::Vector3d halfExtent(110 * 0.8 / 2, 110 * 0.8 / 2, 140 * 1.0 / 2);
  tube.centre = Point3(origin[0], origin[1], origin[2]) + R * halfExtent;
  tube.axis = Eigen::Vector3d(0.25, -0.15, -1.0).normalized();
  itk::ImageRegionIteratorWithIndex<CtImage> it(tube.ct, region);
  for (; !it.IsAtEnd(); ++it)
  {
    const Point3 p = IndexToLps(*tube.ct, it.GetIndex());
    const Eigen::Vector3d q = p - tube.centre;
    const double dist = (q - q.dot(tube.axis) * tube.axis).norm();
    it.Set(static_cast<short>(std::lround(LumenHu * std::clamp(0.5 - (dist - TubeRadiusMm) / RampMm, 0.0, 1.0))));
  }
  return tube;
}

/// The tube's axis as an "aorta" above the centre and an "iliac" below it, 40 mm each.
VesselPath TubePath(const TiltedTube& tube, double stepMm)
{
  const Centerline aorta = testing::StraightCenterline("aorta", tube.centre - 40 * tube.axis, tube.centre, 10);
  const Centerline iliac = testing::StraightCenterline("rightIliac", tube.centre, tube.centre + 40 * tube.axis, 10);
  return SampleVesselPath(aorta, iliac, stepMm);
}

TEST(VesselPath, FrameOrthonormalStepsEvenAndTheIliacContinuesTheAorta)
{
  const TiltedTube tube = MakeTiltedTube();
  const VesselPath path = TubePath(tube, 0.5);
  ASSERT_EQ(path.points.rows(), 161); // 80 mm / 0.5 mm + 1
  EXPECT_NEAR(path.iliacStartMm, 40.0, 1e-9);
  EXPECT_NEAR(path.PathAbscissa("rightIliac", 12.5), 52.5, 1e-9);
  EXPECT_TRUE(std::isnan(path.PathAbscissa("leftIliac", 1.0)));
  for (Eigen::Index k = 0; k < path.points.rows(); ++k)
  {
    const Eigen::Vector3d t = path.tangent.row(k), u = path.u.row(k), v = path.v.row(k);
    EXPECT_NEAR(t.dot(tube.axis), 1.0, 1e-9) << k;
    EXPECT_NEAR(u.norm(), 1.0, 1e-12);
    EXPECT_NEAR(u.dot(t), 0.0, 1e-12);
    EXPECT_NEAR((v - u.cross(t)).norm(), 0.0, 1e-12);
    // u is the patient's left made perpendicular to t: in the plane of x and t, towards +x.
    EXPECT_NEAR(u.dot(Eigen::Vector3d::UnitX().cross(t)), 0.0, 1e-12);
    EXPECT_GT(u.x(), 0.0);
    if (k > 0) // samples every 0.5 mm of arc length along a straight path
    {
      EXPECT_NEAR((path.points.row(k) - path.points.row(k - 1)).norm(), 0.5, 1e-9);
    }
  }
  double distance = 0.0;
  EXPECT_NEAR(path.Project(tube.centre + 10 * tube.axis + Eigen::Vector3d(0, 0, 0), &distance), 50.0, 1e-9);
  EXPECT_NEAR(distance, 0.0, 1e-9);
}

TEST(StraightenAlongPath, TiltedTube_ABandOfConstantWidth2r)
{
  const TiltedTube tube = MakeTiltedTube();
  const VesselPath path = TubePath(tube, 0.5);
  const PlaneImage image = StraightenAlongPath(*tube.ct, path, 20.0);
  ASSERT_EQ(image.width, 81);
  ASSERT_EQ(image.height, 161);
  for (int row = 0; row < image.height; ++row)
  {
    int inside = 0;
    for (int col = 0; col < image.width; ++col)
      inside += image.At(col, row) >= LumenHu / 2 ? 1 : 0;
    // The bound: a band of width 2r within one pixel.
    EXPECT_NEAR(inside * image.pixelMm, 2 * TubeRadiusMm, image.pixelMm) << "row " << row;
    // …centred on the centerline: the two edges are mirror images (the band's middle pixel is inside).
    EXPECT_GE(image.At(image.width / 2, row), LumenHu - 1) << row;
    EXPECT_NEAR(image.At(image.width / 2 - 12, row), image.At(image.width / 2 + 12, row), 2.0) << row;
  }
}

TEST(CrossSection, TiltedTube_ACircleOfTheTruthsDiameter)
{
  const TiltedTube tube = MakeTiltedTube();
  const VesselPath path = TubePath(tube, 0.5);
  for (const Eigen::Index k : { 20, 80, 140 })
  {
    const PlaneImage section = CrossSection(*tube.ct, path.points.row(k).transpose(), path.u.row(k).transpose(),
                                            path.v.row(k).transpose(), 15.0, 0.25);
    double area = 0.0;
    for (const float hu : section.hu)
      area += std::clamp(hu / LumenHu, 0.0, 1.0) * section.pixelMm * section.pixelMm;
    // The ramp is linear across the edge and trilinear interpolation reproduces a linear field, so
    // the grey-level area equals the disc's up to the ramp's curvature (w²/(12 r²) ≈ 0.1 %) and the
    // short-integer rounding of the CT: 0.05 mm in diameter.
    EXPECT_NEAR(2 * std::sqrt(area / M_PI), 2 * TubeRadiusMm, 0.05) << "sample " << k;
    // Round, not an ellipse: a plane tilted by θ from the perpendicular would stretch one axis by
    // 1/cos θ (5° already adds 0.06 mm, 10° 0.24 mm); both axes are 2r within one pixel.
    int alongU = 0, alongV = 0;
    const int c = section.width / 2;
    for (int i = 0; i < section.width; ++i)
    {
      alongU += section.At(i, c) >= LumenHu / 2 ? 1 : 0;
      alongV += section.At(c, i) >= LumenHu / 2 ? 1 : 0;
    }
    EXPECT_NEAR(alongU * section.pixelMm, 2 * TubeRadiusMm, section.pixelMm);
    EXPECT_NEAR(alongV * section.pixelMm, 2 * TubeRadiusMm, section.pixelMm);
  }
}

TEST(StraightenVolume, GeometryAsDocumented_AxialSlicesAreTheCrossSections)
{
  const TiltedTube tube = MakeTiltedTube();
  const VesselPath path = TubePath(tube, 0.5);
  const CtImage::Pointer volume = StraightenVolume(*tube.ct, path, 10.0);
  const auto size = volume->GetLargestPossibleRegion().GetSize();
  ASSERT_EQ(size[0], 41u);
  ASSERT_EQ(size[1], 41u);
  ASSERT_EQ(size[2], 161u);
  EXPECT_DOUBLE_EQ(volume->GetSpacing()[2], 0.5);
  EXPECT_DOUBLE_EQ(volume->GetDirection()[2][2], -1.0);
  EXPECT_DOUBLE_EQ(volume->GetOrigin()[0], -10.0);
  // Slice k's LPS z is −k·Δ: minus the path abscissa.
  itk::Index<3> index{ { 20, 20, 60 } };
  EXPECT_NEAR(IndexToLps(*volume, index).z(), -30.0, 1e-9);
  const PlaneImage plane = StraightenAlongPath(*tube.ct, path, 10.0);
  for (const long k : { 0L, 60L, 160L })
  {
    const PlaneImage section = CrossSection(*tube.ct, path.points.row(k).transpose(), path.u.row(k).transpose(),
                                            path.v.row(k).transpose(), 10.0, 0.5);
    for (long j = 0; j < 41; j += 5)
      for (long i = 0; i < 41; i += 5)
        EXPECT_NEAR(volume->GetPixel({ { i, j, k } }), section.At(static_cast<int>(i), static_cast<int>(j)), 0.5);
    for (long i = 0; i < 41; ++i) // the middle coronal slice is the straightened view
      EXPECT_NEAR(volume->GetPixel({ { i, 20, k } }), plane.At(static_cast<int>(i), static_cast<int>(k)), 0.5);
  }
}

TEST(ResliceCt, OutsideTheImageReadsTheFillValue_BadSizesAreInputErrors)
{
  const TiltedTube tube = MakeTiltedTube();
  const PlaneImage far = CrossSection(*tube.ct, tube.centre + Eigen::Vector3d(500, 0, 0), Eigen::Vector3d::UnitX(),
                                      Eigen::Vector3d::UnitY(), 5.0, 1.0, -1024.0f);
  for (const float hu : far.hu)
    EXPECT_EQ(hu, -1024.0f);
  EXPECT_THROW(CrossSection(*tube.ct, tube.centre, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 0.0, 1.0),
               InputError);
  EXPECT_THROW(CrossSection(*tube.ct, tube.centre, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 5.0, 0.0),
               InputError);
  const Centerline one = testing::StraightCenterline("aorta", tube.centre, tube.centre, 1);
  EXPECT_THROW(SampleVesselPath(one, one, 0.5), InputError);
}

} // namespace
} // namespace sgp
