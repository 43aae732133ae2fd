// The plan from the automatic seed equals the plan from the truth's seed (issue 16 item 1: within
// 0.2 mm on (a)–(f)) on every phantom the seed tests generate — rotated and flipped grids, bone and
// kidneys, thick slices, a wall in fat with thrombus, calcium, a bolus gradient, and random
// anatomies over the sweep's ranges — with the default region growing, whose window is the
// lumen's own (step 1b of GrowLumenRegion, windowFromLumen); with the seed's window alone
// (windowFromLumen off) on three of them. The return values say which seed was used.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "Common/Format.h"
#include "Phantom/AorticPhantom.h"
#include "Pipeline/PlanRepair.h"
#include "Pipeline/PlanValues.h"
#include "SeedPhantoms.h"

namespace sgp
{
namespace
{

/// The bound.
constexpr double SameDiameterMm = 0.2;

const char* const Levels[] = { "proximalNeckDiameter",       "neckDiameter15mm",        "maxAneurysmDiameter",
                               "distalNeckMinDiameter",      "rightIliacDiameter",      "leftIliacDiameter",
                               "proximalNeckLumenDiameter",  "neckLumenDiameter15mm",   "maxAneurysmLumenDiameter",
                               "distalNeckMinLumenDiameter", "rightIliacLumenDiameter", "leftIliacLumenDiameter" };

std::string Value(const RepairPlan& plan, const std::string& name)
{
  for (const PlanValue& v : PlanReturnValues(plan))
    if (v.name == name)
      return v.text;
  return "";
}

/// The plan from `seed` (nullopt: the automatic seed), or the error it stopped with.
struct Outcome
{
  RepairPlan plan;
  std::string error;
};

Outcome Plan(const AorticPhantom& phantom, const std::optional<Point3>& seed, const PlanParams& params)
{
  PlanRequest request;
  request.through = PlanStage::Measurements;
  Outcome out;
  try
  {
    out.plan = PlanRepair(phantom.ct, seed, request, params);
  }
  catch (const std::exception& e)
  {
    out.error = e.what();
  }
  return out;
}

/// Plans from the truth's seed and from none; returns how many of them ended in an error (the same
/// one from both seeds, else a failure).
int ExpectSamePlan(const testing::SeedPhantom& variant, const PlanParams& params)
{
  SCOPED_TRACE(variant.name);
  const AorticPhantom phantom = GenerateAorticPhantom(variant.params);
  const Outcome userOutcome = Plan(phantom, phantom.truth.seedLps, params),
                automaticOutcome = Plan(phantom, std::nullopt, params);
  // A plan that stops (a later stage's error) stops the same way from either seed: the lumen, and
  // so everything after it, is the same.
  EXPECT_EQ(automaticOutcome.error, userOutcome.error);
  if (!userOutcome.error.empty() || !automaticOutcome.error.empty())
  {
    std::printf("%s: both seeds stop with \"%s\"\n", variant.name.c_str(), userOutcome.error.c_str());
    return 1;
  }
  const RepairPlan &user = userOutcome.plan, &automatic = automaticOutcome.plan;
  EXPECT_FALSE(user.seedAutomatic);
  EXPECT_TRUE(automatic.seedAutomatic);
  EXPECT_EQ(Value(user, "seedSource"), "user");
  EXPECT_EQ(Value(automatic, "seedSource"), "automatic");
  const Point3 s = automatic.seedLps;
  EXPECT_EQ(Value(automatic, "seedUsed"),
            FormatReturnValue(-s.x()) + "," + FormatReturnValue(-s.y()) + "," + FormatReturnValue(s.z())); // RAS
  int compared = 0;
  double worst = 0.0;
  std::string worstName;
  for (const char* name : Levels)
  {
    const double a = user.measurements.Value(name), b = automatic.measurements.Value(name);
    EXPECT_EQ(std::isnan(a), std::isnan(b)) << name;
    if (std::isnan(a) || std::isnan(b))
      continue;
    ++compared;
    if (std::abs(b - a) > worst)
    {
      worst = std::abs(b - a);
      worstName = name;
    }
    EXPECT_NEAR(b, a, SameDiameterMm) << name << " (automatic seed " << automatic.seedDescription << ")";
  }
  std::printf("%s: seeds %.1f mm apart, windows [%.0f, %.0f] and [%.0f, %.0f] HU, largest difference %.3f mm%s%s\n",
              variant.name.c_str(), (automatic.seedLps - user.seedLps).norm(), user.lumen.lowerHu, user.lumen.upperHu,
              automatic.lumen.lowerHu, automatic.lumen.upperHu, worst, worstName.empty() ? "" : " in ",
              worstName.c_str());
  // (b) may be left out where its level lies on a bend (issue 32: MeasureAnatomy's
  // SectionTiltMaxMm), with its warning; the same in both plans (the isnan check above).
  const bool bOnABend = std::isnan(user.measurements.Value("neckLumenDiameter15mm")) &&
                        std::any_of(user.warnings.begin(), user.warnings.end(),
                                    [](const std::string& w) { return w.rfind("(b) is not measured", 0) == 0; });
  EXPECT_GE(compared, bOnABend ? 5 : 6) << "at least the lumen's (a)–(f) are measured";
  return 0;
}

/// The plan's parameters with the region growing's window from the seed's ball alone (step 1b of
/// GrowLumenRegion.h off).
PlanParams WithTheSeedsWindow()
{
  PlanParams params;
  params.growing.windowFromLumen = false;
  return params;
}

TEST(AutomaticSeed, SeedsWindow_SamePlanOnThreePhantoms)
{
  // With the seed's ball's window alone the two seeds' windows differ by their noise samples; on
  // these three the plans still agree within the bound, on two of the seven named phantoms they
  // did not (3.1 and 5.0 mm: README, "The automatic seed"). Not the class: the default's tests
  // below are.
  PhantomParams oblique;
  oblique.directionLps = testing::ObliqueFlippedDirection();
  oblique.includeBone = true;
  oblique.includeKidneys = true;
  PhantomParams thick = testing::WithWallInFat(PhantomParams{});
  thick.spacingMm = { 0.7, 0.7, 2.0 };
  thick.rightIliacDiameterMm = thick.leftIliacDiameterMm = 14.0;
  thick.thrombusMaxThicknessMm = 10.0;
  int stopped = 0;
  for (const testing::SeedPhantom& v : { testing::SeedPhantom{ "default", PhantomParams{} },
                                         testing::SeedPhantom{ "oblique flipped grid, bone and kidneys", oblique },
                                         testing::SeedPhantom{ "wall in fat, 2 mm slices, thrombus", thick } })
    stopped += ExpectSamePlan(v, WithTheSeedsWindow());
  EXPECT_EQ(stopped, 0);
}

TEST(AutomaticSeed, EveryTestPhantom_SamePlanAsTheTruthsSeed)
{
  int stopped = 0;
  for (const testing::SeedPhantom& v : testing::SeedTestPhantoms())
    stopped += ExpectSamePlan(v, PlanParams{});
  EXPECT_EQ(stopped, 0) << "every named phantom is planned";
}

TEST(AutomaticSeed, RandomAnatomies_SamePlanAsTheTruthsSeed)
{
  // The 20 draws the seed finder's test uses. One of them (draw 14: 31 HU noise, a spur of the
  // skeleton 8 mm below the bifurcation taken for the left internal iliac, so the leg has no room
  // for two rings) stops in the stent stage from either seed — not this class; draws 6 and
  // 10 stopped so too until a loop of the skeleton across the crotch was no longer taken for an
  // internal iliac (LabelAortoIliacTree.h, step 3) — and is compared by its error; the others are
  // planned.
  int stopped = 0;
  for (const testing::SeedPhantom& v : testing::RandomSeedPhantoms(20))
    stopped += ExpectSamePlan(v, PlanParams{});
  EXPECT_LE(stopped, 1) << "at most the one known stop";
}

} // namespace
} // namespace sgp
