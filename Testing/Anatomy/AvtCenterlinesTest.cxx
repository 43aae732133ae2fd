// Real anatomy: the AVT dataset's manual aortic-tree masks (four CTA patients, 2.5–3 mm slices,
// the aorta from the arch down through the iliac bifurcation; ../shared/data/avt/README.md).
// Each mask is painted into a CT-like volume at test time — lumen enhancement falling from 400 HU
// at the top of the scan to 300 HU at its bottom (the bolus), soft tissue 40 HU, noise σ 15 HU from
// std::mt19937(case number) — and the pipeline runs from the case's seed. The labelled Y must come
// out on every case, with the iliacs on the patient's sides.
#include <algorithm>

#include <gtest/gtest.h>

#include "AvtSupport.h"
#include "Common/ImageGeometry.h"
#include "IO/ReadCtImage.h"
#include "PipelineSupport.h"
#include "Stent/ActiveContour.h"

namespace sgp
{
namespace
{

class AvtCase : public ::testing::TestWithParam<std::string>
{
};

TEST_P(AvtCase, LabelledYWithIliacsOnThePatientsSides)
{
  const std::string name = GetParam();
  const auto mask = ReadLabelMap(testing::AvtMaskPath(name));
  const auto ct = testing::PaintAvtCt(*mask, static_cast<unsigned>(name[1] - '0'));
  const Point3 seed = IndexToLps(*mask, testing::AvtSeed(name));
  const LabelImage::Pointer lumen = GrowLumenRegion(*ct, seed, RegionGrowingParams{}).mask;
  const CenterlineTree tree = testing::CenterlinesFromMask(*lumen);

  const Point3 bifurcation = tree.FindLandmark("aorticBifurcation")->lps;
  const Point3 rightEnd = tree.rightIliac.points.row(tree.rightIliac.Size() - 1).transpose();
  const Point3 leftEnd = tree.leftIliac.points.row(tree.leftIliac.Size() - 1).transpose();
  std::cout << name << ": bifurcation " << bifurcation.transpose() << "; aorta " << tree.aorta.LengthMm()
            << " mm, right iliac " << tree.rightIliac.LengthMm() << " mm, left iliac " << tree.leftIliac.LengthMm()
            << " mm; branches:";
  for (const Centerline& c : tree.sideBranches)
    std::cout << " " << c.name;
  std::cout << std::endl;
  // Patient right is −x in LPS: each iliac ends on its own side of the bifurcation, 20 mm or more
  // (common and external iliacs together run 100 mm or more, diverging).
  EXPECT_LT(rightEnd.x(), bifurcation.x() - 20.0);
  EXPECT_GT(leftEnd.x(), bifurcation.x() + 20.0);
  EXPECT_LT(rightEnd.z(), bifurcation.z());
  EXPECT_LT(leftEnd.z(), bifurcation.z());
  // The masks reach from the arch: the aorta rises well above the bifurcation.
  EXPECT_GT(tree.aorta.points(0, 2), bifurcation.z() + 150.0);
  EXPECT_GT(tree.rightIliac.LengthMm(), 40.0);
  EXPECT_GT(tree.leftIliac.LengthMm(), 40.0);
  // A non-aneurysmal adult aorta: radius 5–20 mm along its abdominal part (infrarenal 15–20 mm
  // across in these cases, per the README).
  for (Eigen::Index i = 0; i < tree.aorta.Size(); ++i)
    if (tree.aorta.points(i, 2) < bifurcation.z() + 100.0 && tree.aorta.points(i, 2) > bifurcation.z() + 20.0)
    {
      EXPECT_GT(tree.aorta.radiusMm[i], 5.0);
      EXPECT_LT(tree.aorta.radiusMm[i], 20.0);
    }
}

TEST_P(AvtCase, MeasureModeStentSurfaceSettlesOnTheWallAndMeasuresPlausibly)
{
  const std::string name = GetParam();
  const auto mask = ReadLabelMap(testing::AvtMaskPath(name));
  const auto ct = testing::PaintAvtCt(*mask, static_cast<unsigned>(name[1] - '0'));
  // As the CLI runs it: site, mesh from the site, wall field around the rings, fit, measurements.
  const testing::MeasuredPlan plan = testing::MeasureFromCt(*ct, IndexToLps(*mask, testing::AvtSeed(name)));
  const ActiveContourResult& r = plan.fit;
  std::cout << name << ": " << plan.mesh.V.rows() << " vertices, " << r.iterations << " iterations, site from "
            << ToString(plan.site.source) << std::endl;
  EXPECT_TRUE(r.converged);
  // On the wall: within 1.5 mm of it (half a 3 mm slice) for 90 % of the vertices or more — the
  // rest sit at ostia and at the flow divider, where there is no wall to lie on.
  long onWall = 0;
  for (Eigen::Index i = 0; i < r.wallDistanceMm.size(); ++i)
    onWall += std::abs(r.wallDistanceMm[i]) < 1.5;
  EXPECT_GT(double(onWall) / double(r.wallDistanceMm.size()), 0.9);
  // No truth here, so plausibility for adult, non-aneurysmal vessels: common iliacs 6–16 mm across,
  // a distal aorta 10–25 mm, common iliacs 20–100 mm long to the internal iliac origin.
  const Measurements& m = plan.measurements;
  for (const char* iliac : { "rightIliacLumenDiameter", "leftIliacLumenDiameter" })
  {
    EXPECT_GT(m.Value(iliac), 6.0) << iliac;
    EXPECT_LT(m.Value(iliac), 16.0) << iliac;
  }
  EXPECT_GT(m.Value("distalNeckMinLumenDiameter"), 10.0);
  EXPECT_LT(m.Value("distalNeckMinLumenDiameter"), 25.0);
  for (const char* length : { "rightIliacLength", "leftIliacLength" })
  {
    EXPECT_GT(m.Value(length), 20.0) << length;
    EXPECT_LT(m.Value(length), 100.0) << length;
  }

  // The README's claims about these cases. D1 and D4 are chest scans whose renal arteries the
  // masks do not label: their site is not known (issue 31: never a neck measured in the chest),
  // the values measured from it are not measured, and a warning asks for the point.
  const bool chest = name == "D1" || name == "D4";
  EXPECT_EQ(plan.site.source, chest ? ProximalSiteSource::None : ProximalSiteSource::Renal);
  if (chest)
  {
    for (const char* value : { "proximalNeckLumenDiameter", "neckLumenDiameter15mm", "proximalNeckLength",
                               "proximalSiteToBifurcationLength", "neckAngleBeta", "neckAngleAlpha" })
      EXPECT_TRUE(std::isnan(m.Value(value))) << value << " = " << m.Value(value);
    // The surface the sac and the iliacs are read on starts on the abdominal aorta, at most
    // MaximumRenalHeightMm above the bifurcation (1 mm centerline steps).
    EXPECT_LE(plan.site.lps.z() - plan.tree.aorta.points(plan.tree.aorta.Size() - 1, 2), MaximumRenalHeightMm + 1.0);
  }
  else
  {
    EXPECT_GT(m.Value("proximalSiteToBifurcationLength"), 50.0);
  }
  const auto warned = [&](const std::string& part) { return testing::AnyWarningContains(m.warnings, part); };
  if (chest)
  {
    ASSERT_FALSE(plan.site.warning.empty());
    EXPECT_TRUE(warned(plan.site.warning)) << plan.site.warning;
  }
  // D4's tortuous right iliac folds the fitted rings of its landing zone: (e) is the centerline's
  // inscribed diameter there, the definition says so, and a warning names the value.
  const Measurement* e = m.Find("rightIliacLumenDiameter");
  ASSERT_NE(e, nullptr);
  const bool fallback = e->definition.find("inscribed-sphere diameter of the centerline") != std::string::npos;
  EXPECT_EQ(fallback, name == "D4") << e->definition;
  EXPECT_EQ(warned("rightIliacLumenDiameter is the centerline's inscribed diameter"), name == "D4");
}

INSTANTIATE_TEST_SUITE_P(RealAnatomy, AvtCase, ::testing::Values("D1", "D2", "D3", "D4"));

} // namespace
} // namespace sgp
