// Real anatomy from a segmentation made elsewhere (issue 45): each AVT case's manual `.seg.nrrd`
// given as the lumen (ReadLumenSegmentation: one segment, every non-zero voxel), with the mask
// painted into CT (AvtSupport.h) and without any CT. The Y is labelled on the patient's sides, and
// every diameter both plans measure lies within 1 mm of the plan that segments the painted CT
// itself (the bar).
#include <cmath>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "AvtSupport.h"
#include "MaskPhantoms.h"
#include "Common/ImageGeometry.h"
#include "IO/ReadCtImage.h"
#include "IO/ReadLumenSegmentation.h"
#include "Pipeline/PlanRepair.h"

namespace sgp
{
namespace
{

PlanParams Params()
{
  return PlanParams{}; // measurements only: no catalogue needed
}

/// The Y on the patient's sides: each iliac ends on its own side of the aorta's lower end (right =
/// −x in LPS), and within 10 mm of where the reference plan's ends (the same vessel: the AVT
/// iliacs run 60–150 mm, their ends cut by the scan or the segmentation).
void ExpectTheYOnItsSides(const CenterlineTree& tree, const CenterlineTree& reference, const std::string& what)
{
  const double aortaEndX = tree.aorta.points(tree.aorta.Size() - 1, 0);
  const Centerline* iliacs[2] = { &tree.rightIliac, &tree.leftIliac };
  const Centerline* referenceIliacs[2] = { &reference.rightIliac, &reference.leftIliac };
  for (int side = 0; side < 2; ++side)
  {
    const Centerline& c = *iliacs[side];
    ASSERT_GE(c.Size(), 2) << what;
    const Point3 end = c.points.row(c.Size() - 1).transpose();
    const Point3 referenceEnd = referenceIliacs[side]->points.row(referenceIliacs[side]->Size() - 1).transpose();
    if (side == 0)
      EXPECT_LT(end.x(), aortaEndX) << what << ": the right iliac ends on the patient's left";
    else
      EXPECT_GT(end.x(), aortaEndX) << what << ": the left iliac ends on the patient's right";
    EXPECT_LT((end - referenceEnd).norm(), 10.0) << what << (side == 0 ? " right" : " left");
  }
}

/// Every diameter (mm) measured on both plans, within 1 mm.
void ExpectDiametersWithin1mm(const Measurements& given, const Measurements& reference, const std::string& what)
{
  int compared = 0;
  for (const Measurement& m : reference.values)
  {
    if (m.unit != "mm" || m.name.find("Diameter") == std::string::npos)
      continue;
    const double g = given.Value(m.name);
    if (std::isnan(g) || std::isnan(m.value))
      continue;
    ++compared;
    EXPECT_NEAR(g, m.value, 1.0) << what << ": " << m.name;
    std::cout << what << " " << m.name << ": " << g << " given, " << m.value << " own (" << g - m.value << ")"
              << std::endl;
  }
  EXPECT_GE(compared, 4) << what << ": too few diameters measured on both to compare";
}

class AvtGivenLumen : public ::testing::TestWithParam<const char*>
{
};

TEST_P(AvtGivenLumen, PlansFromTheSegNrrdWithAndWithoutTheCt)
{
  const std::string name = GetParam();
  const std::string path = testing::AvtMaskPath(name);
  const GivenLumenFile file = ReadLumenSegmentation(path, "");
  const auto mask = ReadLabelMap(path);
  const CtImage::Pointer ct = testing::PaintAvtCt(*mask, static_cast<unsigned>(name[1] - '0'));
  const Point3 seed = IndexToLps(*mask, testing::AvtSeed(name));
  PlanRequest request;
  request.through = PlanStage::Measurements;
  const RepairPlan own = PlanRepair(ct, seed, request, Params());

  request.givenLumenDescription = file.description;
  request.givenLumen = testing::CopyMask(*file.mask); // handed over to each plan
  const RepairPlan withCt = PlanRepair(ct, std::nullopt, request, Params());
  request.givenLumen = file.mask;
  const RepairPlan alone = PlanRepair(nullptr, std::nullopt, request, Params());
  for (const RepairPlan* plan : { &withCt, &alone })
  {
    const std::string what = name + (plan == &withCt ? " with the painted CT" : " without a CT");
    EXPECT_TRUE(plan->lumenGiven) << what;
    ASSERT_TRUE(plan->Reached(PlanStage::Measurements)) << what;
    ExpectTheYOnItsSides(plan->centerlines, own.centerlines, what);
    ExpectDiametersWithin1mm(plan->measurements, own.measurements, what);
    EXPECT_EQ(plan->measurements.site.source, own.measurements.site.source) << what;
  }
  EXPECT_FALSE(alone.ctGiven);
  EXPECT_TRUE(alone.vesselWall.Empty());
}

INSTANTIATE_TEST_SUITE_P(RealAnatomy, AvtGivenLumen, ::testing::Values("D1", "D2", "D3", "D4"));

} // namespace
} // namespace sgp
