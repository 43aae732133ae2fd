#include "Device/SelectDevice.h"

#include <algorithm>
#include <limits>
#include <optional>
#include <tuple>

#include "Common/CheckRange.h"
#include "Common/Errors.h"
#include "Common/Format.h"
#include "Common/Text.h"

namespace sgp
{

namespace
{

constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
/// Oversizing limits are inclusive; this absorbs rounding in (D / d − 1) × 100 (e.g. 30 / 25).
constexpr double OversizingSlackPercent = 1e-9;

double Middle(double lo, double hi)
{
  return 0.5 * (lo + hi);
}

std::string RangePercentText(double lo, double hi)
{
  return RequirementText(lo, hi, "%");
}

/// The sizing check of one choice: pass / fail on its oversizing, or the nearest size on a miss.
CriterionCheck SizingCheck(const std::string& name,
                           const std::string& what,
                           const SizeChoice& choice,
                           const std::vector<DeviceSize>& sizes,
                           double vesselMm,
                           double lo,
                           double hi)
{
  if (std::isnan(vesselMm))
    return CheckCriterion(name, NaN, lo, hi, "%", "", name + " (" + what + " diameter)");
  if (choice.Chosen())
  {
    CriterionCheck check =
      CheckCriterion(name, choice.oversizingPercent, lo, hi, "%", "",
                     name + " (" + CompactNumber(choice.diameterMm) + " mm" + (choice.forced ? ", forced" : "") + ")");
    // On a limit up to rounding (30 / 25 − 1): inside, as ChooseDeviceSize counted it.
    if (check.margin < 0.0 && check.margin >= -OversizingSlackPercent)
    {
      check.margin = 0.0;
      check.status = CheckStatus::Pass;
    }
    return check;
  }
  // Nearest miss: the size whose oversizing lies closest to the range.
  const DeviceSize* nearest = nullptr;
  double best = std::numeric_limits<double>::infinity();
  for (const DeviceSize& s : sizes)
  {
    const double o = OversizingPercent(s.diameterMm, vesselMm);
    const double distance = std::max(lo - o, o - hi);
    if (distance < best)
    {
      best = distance;
      nearest = &s;
    }
  }
  return CheckCriterion(name, OversizingPercent(nearest->diameterMm, vesselMm), lo, hi, "%", "",
                        name + " (no size fits; nearest " + CompactNumber(nearest->diameterMm) + " mm for a " +
                          QuantityText(vesselMm, "mm") + " " + what + ")");
}

std::string TierCondition(const NeckLengthTier& tier)
{
  return "β ≤ " + CompactNumber(tier.maxBetaDeg) + "°";
}

/// Neck length against the tier that admits β (see the header for β not measured).
CriterionCheck NeckLengthCheck(const DeviceIfu& ifu, double lengthMm, double betaDeg)
{
  const std::vector<NeckLengthTier>& tiers = ifu.neckLengthTiers;
  // With one tier its angle is the β criterion's business, not a condition of the length.
  auto condition = [&](const NeckLengthTier& t) { return tiers.size() > 1 ? TierCondition(t) : std::string(); };
  CriterionCheck check;
  if (std::isnan(betaDeg) && !std::isnan(lengthMm) && lengthMm < tiers.back().minLengthMm &&
      lengthMm >= tiers.front().minLengthMm)
  {
    std::string needs;
    for (const NeckLengthTier& t : tiers)
      needs += (needs.empty() ? "" : ", ") + RequirementText(t.minLengthMm, NaN, "mm") + " if " + TierCondition(t);
    check = CheckCriterion("neck length", lengthMm, tiers.front().minLengthMm, NaN, "mm");
    check.status = CheckStatus::Indeterminate;
    check.margin = NaN;
    check.requirement = needs;
    check.text = "neck length " + QuantityText(lengthMm, "mm") + ", needs " + needs + "; β not measured: indeterminate";
  }
  else
  {
    // β unmeasured: the first tier decides a fail, the last a pass. β measured: the first tier
    // admitting it (lengths are non-decreasing), or the last when β exceeds every tier.
    const NeckLengthTier* tier =
      std::isnan(betaDeg) && lengthMm >= tiers.back().minLengthMm ? &tiers.back() : &tiers.front();
    if (!std::isnan(betaDeg))
    {
      tier = &tiers.back();
      for (const NeckLengthTier& t : tiers)
        if (betaDeg <= t.maxBetaDeg)
        {
          tier = &t;
          break;
        }
    }
    check = CheckCriterion("neck length", lengthMm, tier->minLengthMm, NaN, "mm", condition(*tier));
  }
  check.evidence = ifu.neckLengthEvidence;
  return check;
}

/// A decided check whose margin lies within ±`uncertainty` of its limit becomes indeterminate:
/// the measurement cannot tell which side of the limit the anatomy is on.
void WithinUncertainty(CriterionCheck& check, double uncertainty)
{
  if (check.status == CheckStatus::Indeterminate || !(uncertainty > 0.0) || std::abs(check.margin) > uncertainty)
    return;
  check.status = CheckStatus::Indeterminate;
  check.text +=
    ", within the measurement's uncertainty (±" + QuantityText(uncertainty, check.unit) + "): indeterminate";
}

CriterionCheck WithEvidence(CriterionCheck check, const std::string& evidence)
{
  check.evidence = evidence;
  return check;
}

double LargestProfile(const std::vector<DeviceSize>& sizes)
{
  double largest = 0.0;
  for (const DeviceSize& s : sizes)
    largest = std::max(largest, s.profileFr);
  return largest;
}

/// An access check: the vessel's minimum diameter against the delivery profile in mm (Fr / 3).
CriterionCheck AccessCheck(const std::string& name, const std::string& side, double diameterMm, double profileFr)
{
  const std::string label = side.empty() ? name : name + " (" + side + ")";
  return CheckCriterion(name, diameterMm, profileFr / 3.0, NaN, "mm", CompactNumber(profileFr) + " Fr", label);
}

void AddAccessChecks(const SizingAnatomy& a,
                     const DeviceFamily& family,
                     const DeviceSelectionParams& p,
                     FamilyEvaluation& e)
{
  const double right = a.rightAccessMinDiameterMm, left = a.leftAccessMinDiameterMm;
  e.ipsilateral =
    ChooseIpsilateralSide(p.ipsilateralSide, { right, left }, { a.rightIliacTortuosity, a.leftIliacTortuosity });
  const bool rightIpsi = e.ipsilateral.side == 0;
  e.mainBodyAccessSide = rightIpsi ? "right" : "left";
  const double ipsiMm = rightIpsi ? right : left;
  const double contraMm = rightIpsi ? left : right;
  const std::string contraSide = rightIpsi ? "left" : "right";
  const SizeChoice& contraLimb = rightIpsi ? e.leftLimb : e.rightLimb;
  const double bodyFr = e.mainBody.Chosen() ? e.mainBody.profileFr : LargestProfile(family.mainBodies.sizes);
  const double limbFr = contraLimb.Chosen() ? contraLimb.profileFr : LargestProfile(family.limbs.sizes);
  e.checks.push_back(
    WithEvidence(AccessCheck("main-body access", e.mainBodyAccessSide, ipsiMm, bodyFr), family.mainBodies.evidence));
  e.checks.push_back(
    WithEvidence(AccessCheck("contralateral access", contraSide, contraMm, limbFr), family.limbs.evidence));
}

void AddSideChecks(const std::string& side,
                   double iliacMm,
                   double sealMm,
                   const SizeChoice& limb,
                   const DeviceFamily& family,
                   const DeviceSelectionParams& p,
                   FamilyEvaluation& e)
{
  const DeviceIfu& ifu = family.ifu;
  e.checks.push_back(WithEvidence(
    CheckCriterion(side + " iliac diameter", iliacMm, ifu.iliacDiameterMm.min, ifu.iliacDiameterMm.max, "mm"),
    ifu.iliacDiameterMm.evidence));
  e.checks.push_back(WithEvidence(SizingCheck(side + " limb oversizing", side + " iliac", limb, family.limbs.sizes,
                                              iliacMm, p.limbOversizingMinPercent, p.limbOversizingMaxPercent),
                                  family.limbs.evidence));
  e.checks.push_back(
    WithEvidence(CheckCriterion(side + " iliac seal length", sealMm, ifu.iliacSealLengthMm.min, NaN, "mm"),
                 ifu.iliacSealLengthMm.evidence));
}

/// The checks that read a diameter sized on the lumen become indeterminate (the IFU states the
/// outer wall, which was not measured there), saying so.
void MarkEstimatedChecks(FamilyEvaluation& e)
{
  const std::pair<const char*, std::vector<std::string>> readers[] = {
    { "(a)", { "main body oversizing", "neck diameter" } },
    { "(b)", { "neck diameter 15 mm below" } },
    { "(e)", { "right iliac diameter", "right limb oversizing" } },
    { "(f)", { "left iliac diameter", "left limb oversizing" } },
  };
  for (const auto& [level, names] : readers)
  {
    if (std::find(e.estimatedFromLumen.begin(), e.estimatedFromLumen.end(), level) == e.estimatedFromLumen.end())
      continue;
    for (CriterionCheck& check : e.checks)
      if (std::find(names.begin(), names.end(), check.name) != names.end())
      {
        check.status = CheckStatus::Indeterminate;
        check.text += "; " + std::string(level) +
                      " sized on the lumen, the outer wall not traced there: estimated (lumen), indeterminate";
      }
  }
}

FamilyEvaluation EvaluateFamily(const SizingAnatomy& anatomy,
                                const DeviceCatalog& catalog,
                                int index,
                                const DeviceSelectionParams& p,
                                double forcedDiameterMm,
                                const ResolvedConfiguration* given = nullptr)
{
  const DeviceFamily& family = catalog.families[size_t(index)];
  // The diameters on the wall this family's IFU is stated on.
  const SizingAnatomy a = anatomy.On(family.diameterReference);
  const DeviceIfu& ifu = family.ifu;
  FamilyEvaluation e;
  e.family = family.name;
  e.catalogIndex = index;
  const double lo = p.proximalOversizingMinPercent, hi = p.proximalOversizingMaxPercent;
  if (std::isnan(forcedDiameterMm))
    e.mainBody = ChooseDeviceSize(family.mainBodies.sizes, a.proximalNeckDiameterMm, lo, hi);
  else
  {
    for (const DeviceSize& s : family.mainBodies.sizes)
      if (std::abs(s.diameterMm - forcedDiameterMm) <= ForcedDiameterToleranceMm)
      {
        e.mainBody.diameterMm = s.diameterMm;
        e.mainBody.profileFr = s.profileFr;
      }
    e.mainBody.forced = true;
    e.mainBody.oversizingPercent = OversizingPercent(e.mainBody.diameterMm, a.proximalNeckDiameterMm);
  }
  const double limbLo = p.limbOversizingMinPercent, limbHi = p.limbOversizingMaxPercent;
  e.rightLimb = ChooseDeviceSize(family.limbs.sizes, a.rightIliacDiameterMm, limbLo, limbHi);
  e.leftLimb = ChooseDeviceSize(family.limbs.sizes, a.leftIliacDiameterMm, limbLo, limbHi);
  // The surgeon's limbs: what lands on each side given (the extension, else the limb).
  for (int side = 0; given && side < 2; ++side)
    if (given->limb[std::size_t(side)].Given())
    {
      const ResolvedComponent& last = given->extension[std::size_t(side)].Given() ? given->extension[std::size_t(side)]
                                                                                  : given->limb[std::size_t(side)];
      SizeChoice& limb = side == 0 ? e.rightLimb : e.leftLimb;
      limb = SizeChoice{};
      limb.diameterMm = last.item->distalDiameterMm;
      limb.profileFr = given->limb[std::size_t(side)].item->profileFr;
      limb.forced = true;
      limb.oversizingPercent =
        OversizingPercent(limb.diameterMm, side == 0 ? a.rightIliacDiameterMm : a.leftIliacDiameterMm);
    }

  e.checks.push_back(WithEvidence(
    SizingCheck("main body oversizing", "neck", e.mainBody, family.mainBodies.sizes, a.proximalNeckDiameterMm, lo, hi),
    family.mainBodies.evidence));
  const IfuLimit& neck = ifu.neckDiameterMm;
  e.checks.push_back(
    WithEvidence(CheckCriterion("neck diameter", a.proximalNeckDiameterMm, neck.min, neck.max, "mm"), neck.evidence));
  e.checks.push_back(WithEvidence(
    CheckCriterion("neck diameter 15 mm below", a.neckDiameter15mmMm, neck.min, neck.max, "mm"), neck.evidence));
  e.checks.push_back(NeckLengthCheck(ifu, a.proximalNeckLengthMm, a.neckAngleBetaDeg));
  WithinUncertainty(e.checks.back(), a.proximalNeckLengthUncertaintyMm);
  e.checks.push_back(
    WithEvidence(CheckCriterion("neck angle β", a.neckAngleBetaDeg, NaN, ifu.neckLengthTiers.back().maxBetaDeg, "deg"),
                 ifu.neckLengthEvidence));
  if (!std::isnan(ifu.neckAngleAlphaDeg.max))
    e.checks.push_back(
      WithEvidence(CheckCriterion("neck angle α", a.neckAngleAlphaDeg, NaN, ifu.neckAngleAlphaDeg.max, "deg"),
                   ifu.neckAngleAlphaDeg.evidence));
  AddSideChecks("right", a.rightIliacDiameterMm, a.rightIliacSealLengthMm, e.rightLimb, family, p, e);
  AddSideChecks("left", a.leftIliacDiameterMm, a.leftIliacSealLengthMm, e.leftLimb, family, p, e);
  AddAccessChecks(a, family, p, e);
  if (!family.mainBodies.lengthToFlowDividerMm.empty())
    e.checks.push_back(WithEvidence(CheckCriterion("proximal site to bifurcation", a.proximalSiteToBifurcationLengthMm,
                                                   family.mainBodies.lengthToFlowDividerMm.front(), NaN, "mm",
                                                   "shortest main body to the flow divider"),
                                    family.mainBodies.evidence));
  e.estimatedFromLumen = a.estimatedFromLumen;
  MarkEstimatedChecks(e);
  return e;
}

std::string ChoiceText(const std::string& what, const SizeChoice& c)
{
  if (!c.Chosen())
    return what + " none";
  return what + " " + CompactNumber(c.diameterMm) + " mm" +
         (std::isnan(c.oversizingPercent) ? "" : " (" + QuantityText(c.oversizingPercent, "%") + ")");
}

/// How far a family's configuration is from one that can be ordered: 0 every constraint met (or
/// no lengths were given to configure with), 1 a constraint failed (it can be ordered, its
/// findings name what to weigh), 2 not configured (lengths unknown: nothing to order).
int ConfigurationRank(const FamilyEvaluation& e, bool configuring)
{
  if (!configuring)
    return 0;
  if (!e.configuration.configured)
    return 2;
  return e.configuration.Feasible() ? 0 : 1;
}

/// Picks the recommendation among `s.families` and writes summary and reasons.
void Recommend(DeviceSelection& s, bool configuring)
{
  int best = -1;
  auto rank = [&](const FamilyEvaluation& e)
  {
    const double distance = e.mainBody.Chosen() && !std::isnan(e.mainBody.oversizingPercent)
                              ? std::abs(e.mainBody.oversizingPercent - s.proximalTargetPercent)
                              : std::numeric_limits<double>::infinity();
    return std::make_tuple(ConfigurationRank(e, configuring), e.Count(CheckStatus::Indeterminate) > 0, distance);
  };
  for (int i = 0; i < int(s.families.size()); ++i)
    if (s.forced || (s.families[size_t(i)].WithinIfu() && s.families[size_t(i)].mainBody.Chosen() &&
                     (best < 0 || rank(s.families[size_t(i)]) < rank(s.families[size_t(best)]))))
      best = i;
  s.recommended = best;
  if (best < 0)
  {
    const bool anyFail =
      std::any_of(s.families.begin(), s.families.end(), [](const FamilyEvaluation& e) { return !e.WithinIfu(); });
    s.ifuStatus = anyFail ? CheckStatus::Fail : CheckStatus::Indeterminate;
    s.summary = anyFail ? "no device within IFU" : "no device sized";
    for (const FamilyEvaluation& e : s.families)
      for (const CriterionCheck& c : e.checks)
        if (c.status == CheckStatus::Fail)
          s.reasons.push_back(e.family + ": " + c.text);
    for (const FamilyEvaluation& e : s.families)
      if (e.WithinIfu() && !e.mainBody.Chosen())
        s.reasons.push_back(e.family + ": no main body sized (" + e.mainBody.reason + ")");
    return;
  }
  const FamilyEvaluation& e = s.families[size_t(best)];
  s.recommendedWithinIfu = e.WithinIfu();
  s.recommendedFullyChecked = s.recommendedWithinIfu && e.Count(CheckStatus::Indeterminate) == 0;
  s.ifuStatus = e.IfuStatus();
  const int fails = e.Count(CheckStatus::Fail), unknown = e.Count(CheckStatus::Indeterminate);
  std::string verdict = "within IFU";
  if (fails > 0)
    verdict = "OUTSIDE IFU (" + std::to_string(fails) + " failing check" + (fails > 1 ? "s" : "") + ")";
  if (unknown > 0)
    verdict += (fails > 0 ? ", " : " except ") + std::to_string(unknown) + " indeterminate check" +
               (unknown > 1 ? "s" : "") + (e.EstimatedOnLumen() ? "" : " (measurement missing)");
  if (e.EstimatedOnLumen())
    verdict = "estimated (lumen): sized on the lumen at " + JoinWithCommas(e.estimatedFromLumen) +
              " where the outer wall was not traced; IFU " + (fails > 0 ? verdict : "indeterminate, " + verdict);
  s.summary = e.family +
              (s.given    ? " (given configuration)"
               : s.forced ? " (forced)"
                          : "") +
              ": " + ChoiceText("main body", e.mainBody) + ", " + ChoiceText("right limb", e.rightLimb) + ", " +
              ChoiceText("left limb", e.leftLimb) + "; " + verdict;
  for (const CriterionCheck& c : e.checks)
    if (c.status != CheckStatus::Pass)
      s.reasons.push_back(e.family + ": " + c.text);
}

void CheckMeasurement(const std::string& name, double value, double lo, double hi, bool open, const std::string& unit)
{
  if (std::isnan(value))
    return;
  if (!(value >= lo && value <= hi && !(open && value == lo)))
    throw InputError(name + " is " + FormatNumber(value, 2) + " " + unit + "; expected " + (open ? "more than " : "") +
                     FormatNumber(lo, 1) + (open ? " and at most " : " to ") + FormatNumber(hi, 1) + " " + unit +
                     ", or NaN when not measured; check the measurement.");
}

} // namespace

int FamilyEvaluation::Count(CheckStatus status) const
{
  return int(std::count_if(checks.begin(), checks.end(), [&](const CriterionCheck& c) { return c.status == status; }));
}

CheckStatus FamilyEvaluation::IfuStatus() const
{
  if (Count(CheckStatus::Fail) > 0)
    return CheckStatus::Fail;
  return Count(CheckStatus::Indeterminate) > 0 ? CheckStatus::Indeterminate : CheckStatus::Pass;
}

double OversizingPercent(double deviceDiameterMm, double vesselDiameterMm)
{
  return (deviceDiameterMm / vesselDiameterMm - 1.0) * 100.0;
}

SizeChoice ChooseDeviceSize(const std::vector<DeviceSize>& sizes,
                            double vesselDiameterMm,
                            double minPercent,
                            double maxPercent)
{
  SizeChoice choice;
  if (std::isnan(vesselDiameterMm))
  {
    choice.reason = "vessel diameter not measured";
    return choice;
  }
  const double target = Middle(minPercent, maxPercent);
  double best = std::numeric_limits<double>::infinity();
  for (const DeviceSize& s : sizes)
  {
    const double o = OversizingPercent(s.diameterMm, vesselDiameterMm);
    if (o < minPercent - OversizingSlackPercent || o > maxPercent + OversizingSlackPercent)
      continue;
    // Strictly nearer only (beyond rounding): on a tie the earlier, smaller size stays.
    if (std::abs(o - target) < best - OversizingSlackPercent)
    {
      best = std::abs(o - target);
      choice.diameterMm = s.diameterMm;
      choice.profileFr = s.profileFr;
      choice.oversizingPercent = o;
    }
  }
  if (!choice.Chosen())
    choice.reason = "no size of " + DiametersText(sizes) + " gives " + RangePercentText(minPercent, maxPercent) +
                    " oversizing of " + QuantityText(vesselDiameterMm, "mm");
  return choice;
}

void ValidateDeviceSelectionParams(const DeviceSelectionParams& p)
{
  CheckRange("proximalOversizingMinPercent", p.proximalOversizingMinPercent, 0.0, 100.0, "%");
  CheckRange("proximalOversizingMaxPercent", p.proximalOversizingMaxPercent, p.proximalOversizingMinPercent, 100.0,
             "%");
  CheckRange("limbOversizingMinPercent", p.limbOversizingMinPercent, 0.0, 100.0, "%");
  CheckRange("limbOversizingMaxPercent", p.limbOversizingMaxPercent, p.limbOversizingMinPercent, 100.0, "%");
}

void ValidateSizingAnatomy(const SizingAnatomy& a)
{
  const double big = 1000.0; // mm: beyond any aorto-iliac anatomy; catches unit slips and infinities
  CheckMeasurement("proximalNeckDiameterMm", a.proximalNeckDiameterMm, 0.0, big, true, "mm");
  CheckMeasurement("neckDiameter15mmMm", a.neckDiameter15mmMm, 0.0, big, true, "mm");
  CheckMeasurement("proximalNeckLengthMm", a.proximalNeckLengthMm, 0.0, big, false, "mm");
  CheckMeasurement("neckAngleBetaDeg", a.neckAngleBetaDeg, 0.0, 180.0, false, "deg");
  CheckMeasurement("neckAngleAlphaDeg", a.neckAngleAlphaDeg, 0.0, 180.0, false, "deg");
  CheckMeasurement("rightIliacDiameterMm", a.rightIliacDiameterMm, 0.0, big, true, "mm");
  CheckMeasurement("leftIliacDiameterMm", a.leftIliacDiameterMm, 0.0, big, true, "mm");
  CheckMeasurement("proximalNeckLumenDiameterMm", a.proximalNeckLumenDiameterMm, 0.0, big, true, "mm");
  CheckMeasurement("neckLumenDiameter15mmMm", a.neckLumenDiameter15mmMm, 0.0, big, true, "mm");
  CheckMeasurement("rightIliacLumenDiameterMm", a.rightIliacLumenDiameterMm, 0.0, big, true, "mm");
  CheckMeasurement("leftIliacLumenDiameterMm", a.leftIliacLumenDiameterMm, 0.0, big, true, "mm");
  CheckMeasurement("rightIliacSealLengthMm", a.rightIliacSealLengthMm, 0.0, big, false, "mm");
  CheckMeasurement("leftIliacSealLengthMm", a.leftIliacSealLengthMm, 0.0, big, false, "mm");
  CheckMeasurement("rightAccessMinDiameterMm", a.rightAccessMinDiameterMm, 0.0, big, true, "mm");
  CheckMeasurement("leftAccessMinDiameterMm", a.leftAccessMinDiameterMm, 0.0, big, true, "mm");
  CheckMeasurement("rightIliacTortuosity", a.rightIliacTortuosity, 0.0, big, true, "");
  CheckMeasurement("leftIliacTortuosity", a.leftIliacTortuosity, 0.0, big, true, "");
  CheckMeasurement("proximalSiteToBifurcationLengthMm", a.proximalSiteToBifurcationLengthMm, 0.0, big, false, "mm");
}

DeviceSelection SelectDevice(const SizingAnatomy& anatomy,
                             const DeviceCatalog& catalog,
                             const DeviceSelectionParams& params,
                             const ConfigurationAnatomy* lengths)
{
  ValidateDeviceSelectionParams(params);
  ValidateSizingAnatomy(anatomy);
  ValidateDeviceCatalog(catalog);
  DeviceSelection s;
  s.proximalTargetPercent = Middle(params.proximalOversizingMinPercent, params.proximalOversizingMaxPercent);
  s.limbTargetPercent = Middle(params.limbOversizingMinPercent, params.limbOversizingMaxPercent);
  s.forced = !params.forcedDevice.empty() || params.configuration.has_value();
  std::optional<ResolvedConfiguration> given;
  DeviceSelectionParams p = params;
  if (params.configuration)
  {
    given = ResolveGivenConfiguration(*params.configuration, catalog);
    if (given->mainBodySide >= 0)
      p.ipsilateralSide = given->mainBodySide == 0 ? IpsilateralSide::Right : IpsilateralSide::Left;
    s.families.push_back(
      EvaluateFamily(anatomy, catalog, given->familyIndex, p, given->mainBody.item->diameterMm, &*given));
    s.given = true;
    if (given->mainBodySide >= 0)
      s.families.back().ipsilateral.reason =
        std::string(given->mainBodySide == 0 ? "right" : "left") + ", as the configuration gives it";
  }
  else if (s.forced)
  {
    const ForcedDevice forced = ParseForcedDevice(params.forcedDevice, catalog);
    s.families.push_back(EvaluateFamily(anatomy, catalog, forced.familyIndex, params, forced.mainBodyDiameterMm));
  }
  else
  {
    for (int i = 0; i < int(catalog.families.size()); ++i)
      s.families.push_back(EvaluateFamily(anatomy, catalog, i, params, NaN));
  }
  for (FamilyEvaluation& e : s.families)
  {
    if (!lengths)
    {
      e.configuration.family = e.family;
      e.configuration.unknownReason = "no lengths were given to configure with";
      continue;
    }
    const DeviceFamily& family = catalog.families[std::size_t(e.catalogIndex)];
    ChosenDiameters chosen;
    chosen.mainBodyMm = e.mainBody.diameterMm;
    chosen.limbMm = { e.rightLimb.diameterMm, e.leftLimb.diameterMm };
    chosen.limbOversizingMinPercent = params.limbOversizingMinPercent;
    chosen.limbOversizingMaxPercent = params.limbOversizingMaxPercent;
    ConfigurationAnatomy onWall = *lengths;
    const SizingAnatomy a = anatomy.On(family.diameterReference);
    onWall.iliacDiameterMm = { a.rightIliacDiameterMm, a.leftIliacDiameterMm };
    if (given)
    {
      e.configuration =
        ConfigureGivenDevice(family, *given, chosen, onWall, e.ipsilateral, params.deploymentToleranceMm);
      continue;
    }
    e.configuration = ConfigureDevice(family, chosen, onWall, e.ipsilateral, params.deploymentToleranceMm);
    if (e.configuration.configured)
    {
      const std::vector<SizeAlternative> diameters = DiameterAlternatives(anatomy, family, e, params);
      e.configuration.alternatives.insert(e.configuration.alternatives.begin(), diameters.begin(), diameters.end());
    }
  }
  Recommend(s, lengths != nullptr);
  return s;
}

SizingAnatomy SizingAnatomy::On(DiameterReference reference) const
{
  SizingAnatomy a = *this;
  a.estimatedFromLumen.clear();
  const std::tuple<const char*, double*, double> levels[] = {
    { "(a)", &a.proximalNeckDiameterMm, proximalNeckLumenDiameterMm },
    { "(b)", &a.neckDiameter15mmMm, neckLumenDiameter15mmMm },
    { "(e)", &a.rightIliacDiameterMm, rightIliacLumenDiameterMm },
    { "(f)", &a.leftIliacDiameterMm, leftIliacLumenDiameterMm },
  };
  for (const auto& [level, value, lumen] : levels)
    if (reference == DiameterReference::Lumen)
      *value = lumen;
    else if (std::isnan(*value) && !std::isnan(lumen))
    {
      *value = lumen;
      a.estimatedFromLumen.push_back(level);
    }
  return a;
}

std::vector<SizeAlternative> DiameterAlternatives(const SizingAnatomy& anatomy,
                                                  const DeviceFamily& family,
                                                  const FamilyEvaluation& e,
                                                  const DeviceSelectionParams& p)
{
  const SizingAnatomy a = anatomy.On(family.diameterReference);
  const bool lumen = family.diameterReference == DiameterReference::Lumen || !a.estimatedFromLumen.empty();
  const double uncertainty = lumen ? LumenDiameterUncertaintyMm : OuterDiameterUncertaintyMm;
  std::vector<SizeAlternative> alternatives;
  const auto consider = [&](const std::string& component, const std::string& level, const SizeChoice& chosen,
                            const std::vector<DeviceSize>& sizes, double vesselMm, double lo, double hi)
  {
    if (!chosen.Chosen() || chosen.forced || !std::isfinite(vesselMm))
      return;
    for (double shift : { -uncertainty, uncertainty })
    {
      const SizeChoice other = ChooseDeviceSize(sizes, vesselMm + shift, lo, hi);
      if (!other.Chosen() || other.diameterMm == chosen.diameterMm)
        continue;
      const std::string alternative = CompactNumber(other.diameterMm) + " mm";
      if (std::any_of(alternatives.begin(), alternatives.end(),
                      [&](const SizeAlternative& x)
                      { return x.component == component && x.alternative == alternative; }))
        continue;
      alternatives.push_back({ component, CompactNumber(chosen.diameterMm) + " mm", alternative,
                               "the " + component + " would be " + alternative + " if " + level + " were " +
                                 QuantityText(vesselMm + shift, "mm") + " (measured " + QuantityText(vesselMm, "mm") +
                                 ", uncertainty ±" + QuantityText(uncertainty, "mm") +
                                 (lumen ? " on the lumen)" : " on the outer wall)") });
    }
  };
  consider("main body", "(a)", e.mainBody, family.mainBodies.sizes, a.proximalNeckDiameterMm,
           p.proximalOversizingMinPercent, p.proximalOversizingMaxPercent);
  consider("right limb", "(e)", e.rightLimb, family.limbs.sizes, a.rightIliacDiameterMm, p.limbOversizingMinPercent,
           p.limbOversizingMaxPercent);
  consider("left limb", "(f)", e.leftLimb, family.limbs.sizes, a.leftIliacDiameterMm, p.limbOversizingMinPercent,
           p.limbOversizingMaxPercent);
  return alternatives;
}

SizingAnatomy SizingFromMeasurements(const Measurements& m)
{
  SizingAnatomy a;
  a.proximalNeckDiameterMm = m.Value("proximalNeckDiameter");
  a.neckDiameter15mmMm = m.Value("neckDiameter15mm");
  a.proximalNeckLengthMm = m.Value("proximalNeckLength");
  a.neckAngleBetaDeg = m.Value("neckAngleBeta");
  a.neckAngleAlphaDeg = m.Value("neckAngleAlpha");
  a.rightIliacDiameterMm = m.Value("rightIliacDiameter");
  a.leftIliacDiameterMm = m.Value("leftIliacDiameter");
  a.proximalNeckLumenDiameterMm = m.Value("proximalNeckLumenDiameter");
  a.neckLumenDiameter15mmMm = m.Value("neckLumenDiameter15mm");
  a.rightIliacLumenDiameterMm = m.Value("rightIliacLumenDiameter");
  a.leftIliacLumenDiameterMm = m.Value("leftIliacLumenDiameter");
  a.rightIliacSealLengthMm = m.Value("rightIliacLength");
  a.leftIliacSealLengthMm = m.Value("leftIliacLength");
  a.rightAccessMinDiameterMm = m.Value("rightAccessMinDiameter");
  a.leftAccessMinDiameterMm = m.Value("leftAccessMinDiameter");
  a.rightIliacTortuosity = m.Value("rightIliacTortuosity");
  a.leftIliacTortuosity = m.Value("leftIliacTortuosity");
  a.proximalSiteToBifurcationLengthMm = m.Value("proximalSiteToBifurcationLength");
  a.proximalNeckLengthUncertaintyMm = NeckLengthUncertaintyMm;
  return a;
}

} // namespace sgp
