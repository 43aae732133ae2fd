// The automatic seed (issue 16 item 1) on the phantoms the tests generate — rotated and flipped
// grids, thick slices, bone, enhancing kidneys, a wall in fat with thrombus, the IVC, psoas,
// duodenum and left renal vein against the aorta, angulated necks, small and large sacs, low
// contrast — lies in the aortic lumen; a non-contrast scan and a scan without an aorta are one
// clean AlgorithmError saying what was looked for.
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "Common/Errors.h"
#include "Common/ImageGeometry.h"
#include "Phantom/AorticPhantom.h"
#include "Segmentation/FindAorticSeed.h"
#include "SeedPhantoms.h"

namespace sgp
{
namespace
{

/// Distance from `p` to the truth aorta's axis and the lumen radius there.
std::pair<double, double> OffAorticAxis(const PhantomTruth& truth, const Point3& p)
{
  const PhantomVessel& aorta = truth.vessels.front();
  double best = 1e300, radius = 0.0;
  for (Eigen::Index i = 0; i < aorta.axis.rows(); ++i)
  {
    const double d = (aorta.axis.row(i).transpose() - p).norm();
    if (d < best)
    {
      best = d;
      radius = aorta.radiusMm[i];
    }
  }
  return { best, radius };
}

TEST(FindAorticSeed, EveryTestPhantom_TheSeedLiesInTheAorticLumen)
{
  for (const testing::SeedPhantom& v : testing::SeedTestPhantoms())
  {
    SCOPED_TRACE(v.name);
    const AorticPhantom phantom = GenerateAorticPhantom(v.params);
    AorticSeed seed;
    ASSERT_NO_THROW(seed = FindAorticSeed(*phantom.ct)) << v.name;
    const auto index = LpsToIndexInside(*phantom.labels, seed.lps, "seed");
    EXPECT_EQ(phantom.labels->GetPixel(index), LumenLabel) << seed.description;
    const auto [off, radius] = OffAorticAxis(phantom.truth, seed.lps);
    // In the aorta, not an iliac or a branch: nearer its axis than its lumen radius there (and so
    // more than a voxel inside the lumen's edge, where a window estimate would mix in the wall).
    EXPECT_LT(off, radius - 1.5) << seed.description;
    EXPECT_NE(seed.description.find("round contrast-filled cross-section"), std::string::npos);
  }
}

TEST(FindAorticSeed, RandomAnatomies_TheSeedLiesInTheAorticLumen)
{
  // The class, not seven cases: 20 draws over the random-anatomy sweep's ranges (SeedPhantoms.h).
  for (const testing::SeedPhantom& v : testing::RandomSeedPhantoms(20))
  {
    SCOPED_TRACE(v.name);
    const AorticPhantom phantom = GenerateAorticPhantom(v.params);
    AorticSeed seed;
    ASSERT_NO_THROW(seed = FindAorticSeed(*phantom.ct));
    EXPECT_EQ(phantom.labels->GetPixel(LpsToIndexInside(*phantom.labels, seed.lps, "seed")), LumenLabel)
      << seed.description;
    const auto [off, radius] = OffAorticAxis(phantom.truth, seed.lps);
    EXPECT_LT(off, radius - 1.5) << seed.description; // as above: in the aorta, off its edge
  }
}

/// `phantom` with every lumen voxel at `hu` (noise σ kept by adding the phantom's own deviation
/// from its lumen level), kidneys too when `kidneys` is set.
void ReplaceLumen(AorticPhantom& phantom, const PhantomParams& p, double hu, bool kidneys)
{
  short* ct = phantom.ct->GetBufferPointer();
  const unsigned char* labels = phantom.labels->GetBufferPointer();
  for (size_t i = 0; i < phantom.ct->GetLargestPossibleRegion().GetNumberOfPixels(); ++i)
    if (labels[i] == LumenLabel || (kidneys && labels[i] == KidneyLabel))
      ct[i] = static_cast<short>(std::lround(hu + (ct[i] - (labels[i] == LumenLabel ? p.lumenHu : p.kidneyHu))));
}

TEST(FindAorticSeed, NonContrastScan_OneErrorSayingWhatWasLookedFor)
{
  // Unenhanced blood is 30–60 HU (vessel-wall.md): the lumen and the kidneys at 45 HU, the bone kept.
  PhantomParams p;
  p.includeBone = true;
  p.includeKidneys = true;
  AorticPhantom phantom = GenerateAorticPhantom(p);
  ReplaceLumen(phantom, p, 45.0, true);
  try
  {
    FindAorticSeed(*phantom.ct);
    FAIL() << "a non-contrast scan gave a seed";
  }
  catch (const AlgorithmError& e)
  {
    const std::string m = e.what();
    EXPECT_NE(m.find("No aorta found for an automatic seed"), std::string::npos) << m;
    EXPECT_NE(m.find("contrast-filled (≥ 150 HU)"), std::string::npos) << m;
    EXPECT_NE(m.find("Place --seed"), std::string::npos) << m;
    // The nearest miss named: the vertebra, the one bright round thing left.
    EXPECT_NE(m.find("bone: its rim"), std::string::npos) << m;
  }
  // Without bone no piece reaches 150 HU (the lumen's blurred edge keeps a few bright voxels, too
  // few to be a cross-section): the message says so.
  PhantomParams soft;
  AorticPhantom plain = GenerateAorticPhantom(soft);
  ReplaceLumen(plain, soft, 45.0, false);
  try
  {
    FindAorticSeed(*plain.ct);
    FAIL() << "a non-contrast scan gave a seed";
  }
  catch (const AlgorithmError& e)
  {
    EXPECT_NE(std::string(e.what()).find("a scan without contrast?"), std::string::npos) << e.what();
  }
}

TEST(FindAorticSeed, NoAorta_KidneysAndBoneAreNotTakenForIt)
{
  // The enhancing kidneys (80 mm lateral, elliptic) and the vertebra (a cortical ring) stay.
  PhantomParams p;
  p.includeBone = true;
  p.includeKidneys = true;
  AorticPhantom phantom = GenerateAorticPhantom(p);
  ReplaceLumen(phantom, p, p.tissueHu, false);
  EXPECT_THROW(FindAorticSeed(*phantom.ct), AlgorithmError);
}

} // namespace
} // namespace sgp
