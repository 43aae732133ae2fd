// The plan from the automatic seed equals the plan from the truth's seed (issue 16 item 1: within
// 0.2 mm on (a)–(f)): with the lumen's own window (step 1b of GrowLumenRegion, windowFromLumen) on
// every phantom the seed tests generate — rotated and flipped grids, bone and kidneys, thick
// slices, a wall in fat with thrombus, calcium, a bolus gradient, and random anatomies over the
// sweep's ranges; with the default window on three of them. The return values say which seed was
// used.
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
  EXPECT_GE(compared, 6) << "at least the lumen's (a)–(f) are measured";
  return 0;
}

/// The plan's parameters with step 1b of the region growing (GrowLumenRegion.h): the window from
/// the lumen's own core, the same from any seed in it.
PlanParams WithWindowFromLumen()
{
  PlanParams params;
  params.growing.windowFromLumen = true;
  return params;
}

TEST(AutomaticSeed, DefaultWindow_SamePlanOnThreePhantoms)
{
  // With the default window (the seed's ball) the two seeds' windows differ by their noise
  // samples; on these three the plans still agree within the bound. Not the class: the lumen
  // window's tests below are (README, "The automatic seed").
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
    stopped += ExpectSamePlan(v, PlanParams{});
  EXPECT_EQ(stopped, 0);
}

TEST(AutomaticSeed, WindowFromLumen_EveryTestPhantom_SamePlanAsTheTruthsSeed)
{
  int stopped = 0;
  for (const testing::SeedPhantom& v : testing::SeedTestPhantoms())
    stopped += ExpectSamePlan(v, WithWindowFromLumen());
  EXPECT_EQ(stopped, 0) << "every named phantom is planned";
}

TEST(AutomaticSeed, WindowFromLumen_RandomAnatomies_SamePlanAsTheTruthsSeed)
{
  // The 20 draws the seed finder's test uses. Two of them (draws 10 and 14: a right internal
  // iliac origin found within a few mm of the bifurcation, so the leg has no room for two rings)
  // stop in the stent stage from either seed — noticed here, not this class — and are
  // compared by their error; the others are planned.
  int stopped = 0;
  for (const testing::SeedPhantom& v : testing::RandomSeedPhantoms(20))
    stopped += ExpectSamePlan(v, WithWindowFromLumen());
  EXPECT_LE(stopped, 2) << "at most the two known stops";
}

} // namespace
} // namespace sgp
