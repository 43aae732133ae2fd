// The phantom CLI's XML defaults, as PARSE_ARGS gives them, must equal PhantomParams' defaults
// (STYLE.md B4). Read after a parse, so that the test holds against SEM's generated header too:
// SEM declares a vector parameter (spacingMm, directionLps, sizeVoxels) empty and fills it,
// default included, only when PARSE_ARGS parses.
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "SyntheticAorticPhantomCLP.h"
#include "SyntheticAorticPhantomParameters.h"

namespace sgp
{
namespace
{

/// PARSE_ARGS on argv (the required output volume only), then every parsed value against
/// PhantomParams. A function of its own: PARSE_ARGS returns an int on --xml and on a parse error.
int ExpectParsedDefaultsEqualPhantomParams(int argc, char* argv[])
{
  PARSE_ARGS;
  EXPECT_EQ(outputVolume, "phantom.nrrd");
  const PhantomParams fromXml = MakePhantomParams(spacingMm, directionLps, sizeVoxels);
  const PhantomParams d;
  for (int a = 0; a < 3; ++a)
  {
    EXPECT_EQ(fromXml.spacingMm[a], d.spacingMm[a]);
    EXPECT_EQ(fromXml.sizeVoxels[a], d.sizeVoxels[a]);
  }
  EXPECT_EQ(fromXml.directionLps, d.directionLps);
  EXPECT_EQ(neckDiameterMm, d.neckDiameterMm);
  EXPECT_EQ(neckLengthMm, d.neckLengthMm);
  EXPECT_EQ(neckAngleDeg, d.neckAngleDeg);
  EXPECT_EQ(maxAneurysmDiameterMm, d.maxAneurysmDiameterMm);
  EXPECT_EQ(aneurysmLengthMm, d.aneurysmLengthMm);
  EXPECT_EQ(distalNeckDiameterMm, d.distalNeckDiameterMm);
  EXPECT_EQ(rightIliacDiameterMm, d.rightIliacDiameterMm);
  EXPECT_EQ(leftIliacDiameterMm, d.leftIliacDiameterMm);
  EXPECT_EQ(rightCommonIliacLengthMm, d.rightCommonIliacLengthMm);
  EXPECT_EQ(leftCommonIliacLengthMm, d.leftCommonIliacLengthMm);
  EXPECT_EQ(lumenHu, d.lumenHu);
  EXPECT_EQ(tissueHu, d.tissueHu);
  EXPECT_EQ(blurSigmaMm, d.blurSigmaMm);
  EXPECT_EQ(noiseSigmaHu, d.noiseSigmaHu);
  EXPECT_EQ(noiseSeed, d.noiseSeed);
  EXPECT_EQ(includeBone, d.includeBone);
  EXPECT_EQ(boneGapMm, d.boneGapMm);
  EXPECT_EQ(includeKidneys, d.includeKidneys);
  EXPECT_EQ(kidneyHu, d.kidneyHu);
  EXPECT_EQ(wallThicknessMm, d.wallThicknessMm);
  EXPECT_EQ(wallHu, d.wallHu);
  EXPECT_EQ(thrombusMaxThicknessMm, d.thrombusMaxThicknessMm);
  EXPECT_EQ(thrombusShape == "concentric", d.thrombusConcentric);
  EXPECT_EQ(ParsePhantomSide(thrombusSide, "thrombusSide"), d.thrombusSide);
  EXPECT_EQ(thrombusHu, d.thrombusHu);
  EXPECT_EQ(neckThrombusThicknessMm, d.neckThrombusThicknessMm);
  EXPECT_EQ(neckThrombusLengthMm, d.neckThrombusLengthMm);
  EXPECT_EQ(ParsePhantomSide(neckThrombusSide, "neckThrombusSide"), d.neckThrombusSide);
  EXPECT_EQ(calcificationHu, d.calcificationHu);
  EXPECT_EQ(sacCalcificationArcDeg, d.sacCalcificationArcDeg);
  EXPECT_EQ(ParsePhantomSide(sacCalcificationSide, "sacCalcificationSide"), d.sacCalcificationSide);
  EXPECT_EQ(neckCalcificationArcDeg, d.neckCalcificationArcDeg);
  EXPECT_EQ(ParsePhantomSide(neckCalcificationSide, "neckCalcificationSide"), d.neckCalcificationSide);
  EXPECT_EQ(includePsoas, d.includePsoas);
  EXPECT_EQ(psoasHu, d.psoasHu);
  EXPECT_EQ(includeIvc, d.includeIvc);
  EXPECT_EQ(ivcHu, d.ivcHu);
  EXPECT_EQ(includeDuodenum, d.includeDuodenum);
  EXPECT_EQ(duodenumHu, d.duodenumHu);
  EXPECT_EQ(includeLeftRenalVein, d.includeLeftRenalVein);
  EXPECT_EQ(leftRenalVeinHu, d.leftRenalVeinHu);
  EXPECT_EQ(bolusGradientHuPerCm, d.bolusGradientHuPerCm);
  EXPECT_EQ(neckLumenPerLevel, d.neckLumenPerLevel);
  EXPECT_EQ(0.5 * renalDiameterMm, d.renalRadiusMm);
  EXPECT_EQ(ivcArcDeg, d.ivcArcDeg);
  EXPECT_EQ(sacAxisRatio, d.sacAxisRatio);
  EXPECT_EQ(ParsePhantomSide(sacMajorAxis, "sacMajorAxis"), d.sacMajorAxis);
  EXPECT_EQ(rightCommonIliacAngleDeg, d.rightCommonIliacAngleDeg);
  EXPECT_EQ(leftCommonIliacAngleDeg, d.leftCommonIliacAngleDeg);
  EXPECT_EQ(distalNeckLengthMm, d.distalNeckLengthMm);
  EXPECT_EQ(!omitRightInternalIliac, d.rightInternalIliac);
  EXPECT_EQ(!omitLeftInternalIliac, d.leftInternalIliac);
  return EXIT_SUCCESS;
}

TEST(SyntheticAorticPhantomXml, Defaults_EqualPhantomParams)
{
  std::string program = "SyntheticAorticPhantom";
  std::string volume = "phantom.nrrd"; // the one required argument; nothing is written
  char* argv[] = { program.data(), volume.data(), nullptr };
  EXPECT_EQ(ExpectParsedDefaultsEqualPhantomParams(2, argv), EXIT_SUCCESS);
}

} // namespace
} // namespace sgp
