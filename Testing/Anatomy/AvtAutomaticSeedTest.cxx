// Real anatomy without a seed (issue 16 item 1): each AVT mask painted into CT (AvtSupport.h,
// lumen 400 HU at the scan's top falling to 300 HU at its bottom) — the automatic seed lies in the
// aortic lumen, and the plan grown from it equals the plan from the case's own seed (seeds.json)
// within 0.2 mm on (a)–(f), with the default window, the lumen's own (all of them), and with the
// seed's window alone (windowFromLumen off: D4's (a) at the top of its aorta left out).
#include <cmath>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "AvtSupport.h"
#include "Common/ImageGeometry.h"
#include "IO/ReadCtImage.h"
#include "PipelineSupport.h"
#include "Segmentation/FindAorticSeed.h"

namespace sgp
{
namespace
{

/// The bound.
constexpr double SameDiameterMm = 0.2;

class AvtAutomaticSeed : public ::testing::TestWithParam<std::string>
{
};

TEST_P(AvtAutomaticSeed, SeedInTheAortaAndThePlanOfTheCasesSeed)
{
  const std::string name = GetParam();
  const auto mask = ReadLabelMap(testing::AvtMaskPath(name));
  const CtImage::Pointer ct = testing::PaintAvtCt(*mask, static_cast<unsigned>(name[1] - '0'));
  const Point3 own = IndexToLps(*mask, testing::AvtSeed(name));
  const AorticSeed found = FindAorticSeed(*ct);
  std::cout << name << ": automatic seed LPS " << found.lps.transpose() << " (the case's " << own.transpose()
            << "): " << found.description << std::endl;
  EXPECT_GT(mask->GetPixel(LpsToIndexInside(*mask, found.lps, "seed")), 0) << "in the painted lumen";
  RegionGrowingParams seedsWindow;
  seedsWindow.windowFromLumen = false;
  for (const bool lumenWindow : { false, true })
  {
    SCOPED_TRACE(lumenWindow ? "default window, from the lumen's core" : "the seed's window alone");
    const RegionGrowingParams growing = lumenWindow ? RegionGrowingParams{} : seedsWindow;
    const testing::MeasuredPlan reference = testing::MeasureFromCt(*ct, own, {}, growing);
    const testing::MeasuredPlan automatic = testing::MeasureFromCt(*ct, found.lps, {}, growing);
    // In the aorta (not an iliac or a branch): within the aorta's inscribed radius of its centerline.
    double off = 0.0;
    const double s = ProjectOntoCenterline(reference.tree.aorta, found.lps, &off);
    const Eigen::Index nearest =
      std::min<Eigen::Index>(reference.tree.aorta.Size() - 1,
                             static_cast<Eigen::Index>(std::lround(s / std::max(1e-9, reference.tree.aorta.LengthMm()) *
                                                                   double(reference.tree.aorta.Size() - 1))));
    EXPECT_LT(off, reference.tree.aorta.radiusMm[nearest] + 1.0) << "on the aorta, " << off << " mm off its centerline";
    // D4 has no renal artery in view, so its site is the aorta's top in the scan and (a) is read on
    // the fitted surface's first ring, on the closing cap of its segmented aorta. With the seed's
    // window alone that ring reads 24.2 mm from one seed and 26.1 mm from the other (the two
    // windows differ), so there (a) is left out; with the lumen's window (the default, the same
    // from both seeds) it is compared like the rest.
    const bool skipTopA = !lumenWindow && reference.site.source == ProximalSiteSource::Top;
    EXPECT_EQ(automatic.site.source, reference.site.source);
    for (const char* level : { "proximalNeckLumenDiameter", "neckLumenDiameter15mm", "maxAneurysmLumenDiameter",
                               "distalNeckMinLumenDiameter", "rightIliacLumenDiameter", "leftIliacLumenDiameter" })
    {
      if (skipTopA && std::string(level) == "proximalNeckLumenDiameter")
        continue;
      const double a = reference.measurements.Value(level), b = automatic.measurements.Value(level);
      EXPECT_EQ(std::isnan(a), std::isnan(b)) << level;
      if (!std::isnan(a) && !std::isnan(b))
      {
        EXPECT_NEAR(b, a, SameDiameterMm) << level;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(RealAnatomy, AvtAutomaticSeed, ::testing::Values("D1", "D2", "D3", "D4"));

} // namespace
} // namespace sgp
