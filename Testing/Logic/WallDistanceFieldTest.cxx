// The wall distance field limited to a region, and when one field answers for another (issue 30:
// the deployed graft reuses the measure-mode fit's field when it lies within the measured reach).
#include <gtest/gtest.h>

#include "MaskPhantoms.h"
#include "Stent/WallDistanceField.h"

namespace sgp
{
namespace
{

/// A straight tube of radius 10 mm along z from 0 to 120 mm, on 0.8 mm voxels.
const LabelImage& Tube()
{
  static const LabelImage::Pointer tube =
    testing::PaintCapsules({ { Point3(0, 0, 0), Point3(0, 0, 120), 10.0 } }, { 0.8, 0.8, 0.8 });
  return *tube;
}

/// Balls of radius 25 mm (1.5 × 10 + 10, as StentReach makes them) every 4 mm on the axis from
/// `fromZ` to `toZ`.
std::vector<Ball> Reach(double fromZ, double toZ)
{
  std::vector<Ball> balls;
  for (double z = fromZ; z <= toZ + 1e-9; z += 4.0)
    balls.push_back({ Point3(0, 0, z), 25.0 });
  return balls;
}

TEST(WallDistanceField, CoversARegionWithinItsOwnAndNothingBeyond)
{
  const WallDistanceField field = WallDistanceField::FromLumen(Tube(), 5.0, Reach(40.0, 80.0));
  EXPECT_TRUE(field.Covers(Tube(), 5.0, Reach(40.0, 80.0)));  // itself
  EXPECT_TRUE(field.Covers(Tube(), 5.0, Reach(50.0, 70.0)));  // a shorter stretch
  EXPECT_FALSE(field.Covers(Tube(), 5.0, Reach(30.0, 70.0))); // 10 mm higher at one end
  EXPECT_FALSE(field.Covers(Tube(), 5.0, Reach(50.0, 84.0))); // one ring lower at the other
  EXPECT_FALSE(field.Covers(Tube(), 4.0, Reach(50.0, 70.0))); // another band
  EXPECT_FALSE(field.Covers(Tube(), 5.0, {}));                // the whole lumen
  const WallDistanceField whole = WallDistanceField::FromLumen(Tube(), 5.0);
  EXPECT_TRUE(whole.Covers(Tube(), 5.0, Reach(0.0, 120.0)));
  EXPECT_TRUE(whole.Covers(Tube(), 5.0, {}));
}

TEST(WallDistanceField, TheCoveringFieldIsTheOwnFieldAwayFromItsBoxFaces)
{
  // Where a field's box cuts the lumen, the face acts as a wall for φ inside; 25 mm and more from
  // the smaller box's faces (its lumen box is z 15–95 mm: the balls reach 25 mm past 40 and 70)
  // both fields hold the same exact distances, to float precision.
  const WallDistanceField covering = WallDistanceField::FromLumen(Tube(), 5.0, Reach(20.0, 100.0));
  const WallDistanceField own = WallDistanceField::FromLumen(Tube(), 5.0, Reach(40.0, 70.0));
  ASSERT_TRUE(covering.Covers(Tube(), 5.0, Reach(40.0, 70.0)));
  double largest = 0.0;
  int samples = 0;
  for (double z = 40.0; z <= 70.0; z += 1.3)
    for (double r = 0.0; r <= 16.0; r += 0.7)
      for (double angle = 0.0; angle < 6.28; angle += 0.5)
      {
        const Point3 p(r * std::cos(angle), r * std::sin(angle), z);
        Eigen::Vector3d g1, g2;
        largest = std::max(largest, std::abs(covering.Sample(p, &g1) - own.Sample(p, &g2)));
        largest = std::max(largest, (g1 - g2).norm());
        ++samples;
      }
  EXPECT_GT(samples, 5000);
  EXPECT_LT(largest, 1e-5); // float storage
}

} // namespace
} // namespace sgp
