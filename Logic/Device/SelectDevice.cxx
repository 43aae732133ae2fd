#include "Device/SelectDevice.h"

#include <algorithm>
#include <limits>

#include "Common/CheckRange.h"
#include "Common/Errors.h"
#include "Common/Format.h"

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

void AddAccessChecks(const SizingAnatomy& a, const DeviceFamily& family, FamilyEvaluation& e)
{
  const double right = a.rightAccessMinDiameterMm, left = a.leftAccessMinDiameterMm;
  // The main body goes up the wider side (a measured side beats an unmeasured one).
  const bool rightIpsi = !std::isnan(right) && (std::isnan(left) || right >= left);
  const bool leftIpsi = !rightIpsi && !std::isnan(left);
  e.mainBodyAccessSide = rightIpsi ? "right" : (leftIpsi ? "left" : "");
  const double ipsiMm = rightIpsi ? right : (leftIpsi ? left : NaN);
  const double contraMm = rightIpsi ? left : (leftIpsi ? right : NaN);
  const std::string contraSide = rightIpsi ? "left" : (leftIpsi ? "right" : "");
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

FamilyEvaluation EvaluateFamily(const SizingAnatomy& anatomy,
                                const DeviceCatalog& catalog,
                                int index,
                                const DeviceSelectionParams& p,
                                double forcedDiameterMm)
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
  AddAccessChecks(a, family, e);
  if (!family.mainBodies.lengthToFlowDividerMm.empty())
    e.checks.push_back(WithEvidence(CheckCriterion("proximal site to bifurcation", a.proximalSiteToBifurcationLengthMm,
                                                   family.mainBodies.lengthToFlowDividerMm.front(), NaN, "mm",
                                                   "shortest main body to the flow divider"),
                                    family.mainBodies.evidence));
  return e;
}

std::string ChoiceText(const std::string& what, const SizeChoice& c)
{
  if (!c.Chosen())
    return what + " none";
  return what + " " + CompactNumber(c.diameterMm) + " mm" +
         (std::isnan(c.oversizingPercent) ? "" : " (" + QuantityText(c.oversizingPercent, "%") + ")");
}

/// Picks the recommendation among `s.families` and writes summary and reasons.
void Recommend(DeviceSelection& s)
{
  int best = -1;
  auto rank = [&](const FamilyEvaluation& e)
  {
    const double distance = e.mainBody.Chosen() && !std::isnan(e.mainBody.oversizingPercent)
                              ? std::abs(e.mainBody.oversizingPercent - s.proximalTargetPercent)
                              : std::numeric_limits<double>::infinity();
    return std::make_pair(e.Count(CheckStatus::Indeterminate) > 0, distance);
  };
  for (int i = 0; i < int(s.families.size()); ++i)
    if (s.forced || (s.families[size_t(i)].WithinIfu() && s.families[size_t(i)].mainBody.Chosen() &&
                     (best < 0 || rank(s.families[size_t(i)]) < rank(s.families[size_t(best)]))))
      best = i;
  s.recommended = best;
  if (best < 0)
  {
    s.summary = "no device within IFU";
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
  const int fails = e.Count(CheckStatus::Fail), unknown = e.Count(CheckStatus::Indeterminate);
  std::string verdict = "within IFU";
  if (fails > 0)
    verdict = "OUTSIDE IFU (" + std::to_string(fails) + " failing check" + (fails > 1 ? "s" : "") + ")";
  if (unknown > 0)
    verdict += (fails > 0 ? ", " : " except ") + std::to_string(unknown) + " indeterminate check" +
               (unknown > 1 ? "s" : "") + " (measurement missing)";
  s.summary = e.family + (s.forced ? " (forced)" : "") + ": " + ChoiceText("main body", e.mainBody) + ", " +
              ChoiceText("right limb", e.rightLimb) + ", " + ChoiceText("left limb", e.leftLimb) + "; " + verdict;
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
  CheckMeasurement("proximalSiteToBifurcationLengthMm", a.proximalSiteToBifurcationLengthMm, 0.0, big, false, "mm");
}

DeviceSelection SelectDevice(const SizingAnatomy& anatomy,
                             const DeviceCatalog& catalog,
                             const DeviceSelectionParams& params)
{
  ValidateDeviceSelectionParams(params);
  ValidateSizingAnatomy(anatomy);
  ValidateDeviceCatalog(catalog);
  DeviceSelection s;
  s.proximalTargetPercent = Middle(params.proximalOversizingMinPercent, params.proximalOversizingMaxPercent);
  s.limbTargetPercent = Middle(params.limbOversizingMinPercent, params.limbOversizingMaxPercent);
  s.forced = !params.forcedDevice.empty();
  if (s.forced)
  {
    const ForcedDevice forced = ParseForcedDevice(params.forcedDevice, catalog);
    s.families.push_back(EvaluateFamily(anatomy, catalog, forced.familyIndex, params, forced.mainBodyDiameterMm));
  }
  else
  {
    for (int i = 0; i < int(catalog.families.size()); ++i)
      s.families.push_back(EvaluateFamily(anatomy, catalog, i, params, NaN));
  }
  Recommend(s);
  return s;
}

SizingAnatomy SizingAnatomy::On(DiameterReference reference) const
{
  SizingAnatomy a = *this;
  if (reference == DiameterReference::Lumen)
  {
    a.proximalNeckDiameterMm = proximalNeckLumenDiameterMm;
    a.neckDiameter15mmMm = neckLumenDiameter15mmMm;
    a.rightIliacDiameterMm = rightIliacLumenDiameterMm;
    a.leftIliacDiameterMm = leftIliacLumenDiameterMm;
  }
  return a;
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
  a.proximalSiteToBifurcationLengthMm = m.Value("proximalSiteToBifurcationLength");
  a.proximalNeckLengthUncertaintyMm = NeckLengthUncertaintyMm;
  return a;
}

} // namespace sgp
