// Real anatomy without a seed (issue 16 item 1): each AVT mask painted into CT (AvtSupport.h,
// lumen 400 HU at the scan's top falling to 300 HU at its bottom) — the automatic seed lies in the
// aortic lumen, and the plan grown from it equals the plan from the case's own seed (seeds.json)
// within 0.2 mm on (a)–(f).
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
  const testing::MeasuredPlan reference = testing::MeasureFromCt(*ct, own);
  const testing::MeasuredPlan automatic = testing::MeasureFromCt(*ct, found.lps);
  // In the aorta (not an iliac or a branch): within the aorta's inscribed radius of its centerline.
  double off = 0.0;
  const double s = ProjectOntoCenterline(reference.tree.aorta, found.lps, &off);
  const Eigen::Index nearest =
    std::min<Eigen::Index>(reference.tree.aorta.Size() - 1,
                           static_cast<Eigen::Index>(std::lround(s / std::max(1e-9, reference.tree.aorta.LengthMm()) *
                                                                 double(reference.tree.aorta.Size() - 1))));
  EXPECT_LT(off, reference.tree.aorta.radiusMm[nearest] + 1.0) << "on the aorta, " << off << " mm off its centerline";
  // Where no renal artery is found (D4) the site is the aorta's top in the scan and (a) is read on
  // the fitted surface's free first ring at the image border: not a sizing level (the plan warns
  // that the site is the top), and that ring moves with the fit (24.2 mm from one seed, 26.1 mm from
  // the other), so (a)
  // is compared only at a real site.
  const bool atTheTop = reference.site.source == ProximalSiteSource::Top;
  EXPECT_EQ(automatic.site.source, reference.site.source);
  for (const char* level : { "proximalNeckLumenDiameter", "neckLumenDiameter15mm", "maxAneurysmLumenDiameter",
                             "distalNeckMinLumenDiameter", "rightIliacLumenDiameter", "leftIliacLumenDiameter" })
  {
    if (atTheTop && std::string(level) == "proximalNeckLumenDiameter")
      continue;
    const double a = reference.measurements.Value(level), b = automatic.measurements.Value(level);
    EXPECT_EQ(std::isnan(a), std::isnan(b)) << level;
    if (!std::isnan(a) && !std::isnan(b))
    {
      EXPECT_NEAR(b, a, SameDiameterMm) << level;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(RealAnatomy, AvtAutomaticSeed, ::testing::Values("D1", "D2", "D3", "D4"));

} // namespace
} // namespace sgp
