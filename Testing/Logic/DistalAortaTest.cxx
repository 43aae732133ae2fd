// (d) below the trunk's last ring (Measurement/DistalAorta.h): when a profile still narrows at its
// end, and the lumen's narrowest section read down a funnel to B, against analytic profiles and a
// voxelized cone whose sections are known circles.
#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <itkImageRegionIteratorWithIndex.h>

#include "Measurement/DistalAorta.h"

namespace sgp
{
namespace
{

constexpr double pi = 3.14159265358979323846;

/// Readings every `stepMm` from 0 to `lengthMm`, diameter d0 − slope · s plus `wobble` ·
/// sin(s) (a ring's noise, ±wobble).
std::vector<AbscissaDiameter> Profile(double d0, double slope, double lengthMm, double stepMm, double wobble = 0.0)
{
  std::vector<AbscissaDiameter> p;
  for (double s = 0.0; s <= lengthMm + 1e-9; s += stepMm)
    p.push_back({ s, d0 - slope * s + wobble * std::sin(1.7 * s) });
  return p;
}

TEST(DistalAorta, AFunnelStillNarrowsAtItsEnd)
{
  // A sac's floor falls by 0.5-2 mm of diameter per mm (DistalAorta.h); rings every 6 mm.
  EXPECT_TRUE(StillNarrowingAtItsEnd(Profile(40.0, 0.5, 30.0, 6.0)));
  EXPECT_TRUE(StillNarrowingAtItsEnd(Profile(40.0, 2.0, 12.0, 6.0)));
  // Just above and below the threshold (0.15 mm per mm), no noise.
  EXPECT_TRUE(StillNarrowingAtItsEnd(Profile(20.0, NarrowingPerMm + 0.02, 20.0, 5.0)));
  EXPECT_FALSE(StillNarrowingAtItsEnd(Profile(20.0, NarrowingPerMm - 0.02, 20.0, 5.0)));
}

TEST(DistalAorta, AStraightDistalNeckDoesNot)
{
  // A cylinder's rings with ±0.2 mm of noise: no trend, whatever the last ring reads.
  EXPECT_FALSE(StillNarrowingAtItsEnd(Profile(18.0, 0.0, 30.0, 6.0, 0.2)));
  // Narrowest before the end (a neck that widens again toward the bifurcation).
  std::vector<AbscissaDiameter> dip = Profile(30.0, 1.0, 12.0, 6.0);
  dip.push_back({ 18.0, 19.0 });
  EXPECT_FALSE(StillNarrowingAtItsEnd(dip));
  // Readings closer together than the window: not enough to judge a trend.
  EXPECT_FALSE(StillNarrowingAtItsEnd(Profile(30.0, 2.0, 3.0, 1.0)));
  EXPECT_FALSE(StillNarrowingAtItsEnd({}));
}

/// A voxelized cone along unit `axis` through the origin: radius r0 + k · t at height t along the
/// axis (t from -30 to 30 mm); 0.8 mm pixels and `sliceMm` slices.
LabelImage::Pointer Cone(const Eigen::Vector3d& axis, double r0, double k, double sliceMm)
{
  auto image = LabelImage::New();
  LabelImage::RegionType region;
  const double spacing[3] = { 0.8, 0.8, sliceMm };
  region.SetSize({ { 100, 100, static_cast<LabelImage::SizeValueType>(std::lround(80.0 / sliceMm)) } });
  image->SetRegions(region);
  image->SetSpacing(spacing);
  const double origin[3] = { -40.0, -40.0, -40.0 };
  image->SetOrigin(origin);
  image->Allocate(true);
  for (itk::ImageRegionIteratorWithIndex<LabelImage> it(image, region); !it.IsAtEnd(); ++it)
  {
    LabelImage::PointType p;
    image->TransformIndexToPhysicalPoint(it.GetIndex(), p);
    const Point3 x(p[0], p[1], p[2]);
    const double t = x.dot(axis);
    it.Set(std::abs(t) <= 30.0 && (x - t * axis).norm() < r0 + k * t ? 1 : 0);
  }
  return image;
}

class DistalSections : public ::testing::TestWithParam<double>
{
};

/// The cones' radius slope (mm per mm) and the bar on a section's diameter: 0.4 mm (the
/// interpolated edge of a voxelized disc, as SectionPlanesTest's cylinders), or the cone's change of
/// diameter over half a slice where that is more — between slice centres the interpolated edge
/// lies between the two slices' circles (on 3 mm slices 1.5 mm; read 1.0 mm off at a third of the
/// way between them).
constexpr double coneSlope = 0.5;
double SectionBar(double sliceMm)
{
  return std::max(0.4, 2.0 * coneSlope * 0.5 * sliceMm);
}

TEST_P(DistalSections, ReadDownTheFunnelToB)
{
  // The funnel narrows by 1 mm of diameter per mm down to B at the origin (diameter 20 mm) and on
  // below it: the narrowest section read is B's own, 15 mm below the start, whatever lies below.
  // Its mean within SectionBar of 20 mm (slices to 3 mm, the axis 20° off the slices' normal).
  const Eigen::Vector3d axis =
    Eigen::AngleAxisd(20.0 * pi / 180.0, Eigen::Vector3d::UnitX()) * Eigen::Vector3d::UnitZ();
  const auto image = Cone(axis, 10.0, coneSlope, GetParam());
  const Point3 from = 15.0 * axis;
  const DistalSection d = NarrowestLumenSectionBelow(*image, from, 100.0, -axis, 15.0, nullptr);
  ASSERT_TRUE(d.found);
  EXPECT_NEAR(d.section.abscissaMm, 115.0, 1e-9);
  EXPECT_NEAR(d.section.meanMm, 20.0, SectionBar(GetParam()));
  EXPECT_NEAR(d.section.areaMm, 20.0, SectionBar(GetParam()));
  EXPECT_LE(d.section.minMm, d.section.meanMm);
  EXPECT_GE(d.section.maxMm, d.section.meanMm);
  EXPECT_LT((d.section.centre - Point3::Zero()).norm(), 1e-9);
}

TEST_P(DistalSections, NotPastTheFlowDivider)
{
  // A divider 5 mm above B: no section at or below its level; the last read lies 6 mm above B
  // (1 mm steps from 15 mm above), 26 mm across.
  const Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  const auto image = Cone(axis, 10.0, coneSlope, GetParam());
  const Point3 divider = 5.0 * axis + Eigen::Vector3d(3.0, 0.0, 0.0); // off the axis: only its level counts
  const DistalSection d = NarrowestLumenSectionBelow(*image, Point3(15.0 * axis), 100.0, -axis, 15.0, &divider);
  ASSERT_TRUE(d.found);
  EXPECT_NEAR(d.section.abscissaMm, 109.0, 1e-9);
  EXPECT_NEAR(d.section.meanMm, 26.0, SectionBar(GetParam()));
}

TEST_P(DistalSections, BsOwnLevelLessThanAStepBelow)
{
  // The last ring 0.6 mm above B: the one section read is B's (a ring within a millimetre of B on
  // a steep funnel read 18.9 for 17.4 mm on issue 46's sweep); at B itself, nothing below.
  const auto image = Cone(Eigen::Vector3d::UnitZ(), 10.0, coneSlope, GetParam());
  const DistalSection d =
    NarrowestLumenSectionBelow(*image, Point3(0.0, 0.0, 0.6), 100.0, -Eigen::Vector3d::UnitZ(), 0.6, nullptr);
  ASSERT_TRUE(d.found);
  EXPECT_NEAR(d.section.abscissaMm, 100.6, 1e-9);
  EXPECT_NEAR(d.section.meanMm, 20.0, SectionBar(GetParam()));
  EXPECT_FALSE(
    NarrowestLumenSectionBelow(*image, Point3::Zero(), 100.0, -Eigen::Vector3d::UnitZ(), 0.0, nullptr).found);
}

INSTANTIATE_TEST_SUITE_P(Slices,
                         DistalSections,
                         ::testing::Values(1.0, 3.0),
                         [](const auto& info)
                         { return info.param < 2.0 ? std::string("Fine") : std::string("Thick"); });

} // namespace
} // namespace sgp
