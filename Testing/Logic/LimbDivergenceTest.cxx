// LimbDivergence against straight limbs whose answer is analytic.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "Centerlines/LimbDivergence.h"

namespace sgp
{
namespace
{

constexpr double pi = 3.14159265358979323846;

/// A straight limb from `start` along `direction` (unit), `lengthMm` long, sampled every 0.5 mm,
/// of constant inscribed radius.
std::vector<Point3> Limb(const Point3& start, const Point3& direction, double lengthMm)
{
  std::vector<Point3> points;
  for (double s = 0.0; s <= lengthMm + 1e-9; s += 0.5)
    points.push_back(start + s * direction);
  return points;
}

Point3 Down(double halfAngleDeg, double side)
{
  const double a = halfAngleDeg * pi / 180.0;
  return Point3(side * std::sin(a), 0.0, -std::cos(a));
}

// Two limbs from one point at ±θ/2 from the vertical part by θ: the measure gives θ (to 0.01°:
// the sampling is exact on straight lines), and the septum is D(S) less both radii.
TEST(LimbDivergence, StraightLimbsFromOnePoint_GiveTheAngleBetweenThem)
{
  for (double angle : { 10.0, 30.0, 60.0, 90.0 })
  {
    const auto a = Limb(Point3::Zero(), Down(angle / 2, -1), 60.0);
    const auto b = Limb(Point3::Zero(), Down(angle / 2, +1), 60.0);
    const LimbDivergence d =
      MeasureLimbDivergence(a, std::vector<double>(a.size(), 5.0), b, std::vector<double>(b.size(), 4.0), 40.0);
    EXPECT_NEAR(d.angleDeg, angle, 0.01) << angle;
    EXPECT_NEAR(d.reachMm, 40.0, 1e-9);
    EXPECT_NEAR(d.septumMm, 2.0 * 40.0 * std::sin(angle / 2 * pi / 180.0) - 9.0, 1e-6) << angle;
  }
}

// A dissection's channels: each moves 5.5 mm aside over its first 5 mm, then both run straight
// down side by side: 0° and a septum of 11 − 2 × 4.8 mm.
TEST(LimbDivergence, ChannelsSideBySide_DivergeByNothing)
{
  std::vector<Point3> a{ Point3::Zero() }, b{ Point3::Zero() };
  for (const auto& [path, side] : { std::pair{ &a, -1.0 }, std::pair{ &b, 1.0 } })
    for (double s = 0.5; s <= 80.0; s += 0.5)
      path->push_back(Point3(side * 5.5 * std::min(1.0, s / 5.0), 0.0, -s));
  const LimbDivergence d =
    MeasureLimbDivergence(a, std::vector<double>(a.size(), 4.8), b, std::vector<double>(b.size(), 4.8), 40.0);
  EXPECT_NEAR(d.angleDeg, 0.0, 0.5); // arc length vs depth over the first 5 mm: well under 0.5°
  EXPECT_NEAR(d.septumMm, 11.0 - 9.6, 0.05);
}

// Converging limbs give a negative angle; limbs under 4 mm give NaN; the reach is the shorter limb.
TEST(LimbDivergence, ConvergingShortAndUnequal)
{
  const auto a = Limb(Point3(-10, 0, 0), Down(10.0, +1), 30.0), b = Limb(Point3(10, 0, 0), Down(10.0, -1), 30.0);
  const std::vector<double> r(a.size(), 3.0);
  EXPECT_LT(MeasureLimbDivergence(a, r, b, r, 40.0).angleDeg, -15.0);
  const auto shortLimb = Limb(Point3::Zero(), Down(20.0, 1), 3.5);
  EXPECT_TRUE(
    std::isnan(MeasureLimbDivergence(a, r, shortLimb, std::vector<double>(shortLimb.size(), 3.0), 40.0).angleDeg));
  const auto c = Limb(Point3::Zero(), Down(15.0, -1), 60.0), d = Limb(Point3::Zero(), Down(15.0, 1), 22.0);
  const LimbDivergence u =
    MeasureLimbDivergence(c, std::vector<double>(c.size(), 3.0), d, std::vector<double>(d.size(), 3.0), 40.0);
  EXPECT_NEAR(u.reachMm, 22.0, 1e-9);
  EXPECT_NEAR(u.angleDeg, 30.0, 0.01);
}

} // namespace
} // namespace sgp
