// What a person reads (STYLE.md B10): every value in words and at clinical precision — 0.1 mm,
// 0.1°, 1 %, 0.01 for a ratio, 0.1 mL — and never "-0" for a value that rounds to zero.
#include <gtest/gtest.h>

#include <limits>

#include "Common/Format.h"
#include "Pipeline/ValueText.h"

namespace sgp
{
namespace
{

TEST(ClinicalText, EachUnitAtItsClinicalPrecision)
{
  EXPECT_EQ(ClinicalText(22.149, "mm"), "22.1 mm");
  EXPECT_EQ(ClinicalText(34.56, "deg"), "34.6°");
  EXPECT_EQ(ClinicalText(17.2, "%"), "17 %");
  EXPECT_EQ(ClinicalText(1.0149, "ratio"), "1.01");
  EXPECT_EQ(ClinicalText(135.44, "mL"), "135.4 mL");
  EXPECT_EQ(ClinicalText(std::numeric_limits<double>::quiet_NaN(), "mm"), "not measured");
}

TEST(ClinicalText, NoNegativeZero)
{
  // A conicity of −0.2 % rounds to 0 %: "-0 %" would read as a sign that is not there.
  EXPECT_EQ(ClinicalText(-0.2, "%"), "0 %");
  EXPECT_EQ(ClinicalText(-0.04, "mm"), "0.0 mm");
  EXPECT_EQ(ClinicalText(-0.0, "deg"), "0.0°");
  EXPECT_EQ(FormatNumber(-0.004, 2), "0.00");
  // A value that does not round to zero keeps its sign.
  EXPECT_EQ(ClinicalText(-0.6, "%"), "-1 %");
  EXPECT_EQ(FormatNumber(-0.06, 1), "-0.1");
  EXPECT_EQ(FormatNumber(-10.0, 0), "-10");
}

TEST(ValueLabel, WordsForEveryMeasurementAndSplitCapitalsOtherwise)
{
  EXPECT_EQ(ValueLabel("proximalNeckDiameter"), "(a) neck diameter at the proximal site, outer wall");
  EXPECT_EQ(ValueLabel("leftIliacLumenDiameter"), "(f) left common iliac diameter, lumen");
  EXPECT_EQ(ValueLabel("mainBodyLength"), "main body length");
  EXPECT_EQ(ValueLabel("someNewValue"), "some new value");
}

} // namespace
} // namespace sgp
