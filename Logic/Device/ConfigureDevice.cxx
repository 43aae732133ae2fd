#include "Device/ConfigureDevice.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>

#include "Common/Errors.h"
#include "Common/Format.h"
#include "Common/Text.h"
#include "Device/CriterionCheck.h"
#include "Device/GivenConfiguration.h"
#include "Device/LimbOptions.h"

namespace sgp
{
namespace
{

constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
constexpr double Infinity = std::numeric_limits<double>::infinity();
/// The crotch is compared with the aorta this far above and below the flow divider
/// (device-configuration.md §2.1: D_FD over the flow-divider level ± 10 mm).
constexpr double CrotchLevelMm = 10.0;
/// Tortuosities closer than this tell the sides apart no better than the measurement: paths that
/// differ by under 5 % of their length [K].
constexpr double TortuosityToleranceRatio = 0.05;
/// Narrow and extremely narrow distal aortas (device-configuration.md §1.7, the NAB study [S]).
constexpr double NarrowAortaMm = 20.0, ExtremelyNarrowAortaMm = 16.0;

const char* SideName(int side)
{
  return side == 0 ? "right" : "left";
}

std::string Mm(double value)
{
  return FormatNumber(value) + " mm";
}

/// The limb diameter a side lands with: the chosen one, else — no size within the oversizing
/// window — the widest (a bell-bottom limb, for an iliac too wide), the smallest (an iliac too
/// narrow) or, between two sizes, the one whose oversizing lies nearest the window; with its
/// finding.
double LandingDiameter(const DeviceFamily& family,
                       const ChosenDiameters& chosen,
                       const ConfigurationAnatomy& anatomy,
                       int side,
                       std::vector<ConfigurationFinding>& findings)
{
  if (std::isfinite(chosen.limbMm[side]))
    return chosen.limbMm[side];
  const std::vector<DeviceSize>& sizes = family.limbs.sizes;
  const double iliac = anatomy.iliacDiameterMm[side];
  if (sizes.empty() || !std::isfinite(iliac))
    return NaN;
  const double lo = chosen.limbOversizingMinPercent, hi = chosen.limbOversizingMaxPercent;
  const auto oversizing = [&](double d) { return (d / iliac - 1.0) * 100.0; };
  const auto percent = [&](double d) { return FormatNumber(oversizing(d)) + " %"; };
  const double widest = sizes.back().diameterMm, smallest = sizes.front().diameterMm;
  const std::string name = SideName(side);
  const std::string common = name + " common iliac " + Mm(iliac);
  const std::string window = FormatNumber(lo, 0) + "–" + FormatNumber(hi, 0) + " %";
  if (oversizing(widest) < lo)
  {
    findings.push_back(
      { "iliacTooWide", side,
        common + " is wider than " + family.name + "'s widest limb allows: " + CompactNumber(widest) + " mm gives " +
          percent(widest) + " oversizing, needs " + window + "; the " + CompactNumber(widest) +
          " mm limb is planned as a bell-bottom (flared) limb",
        "a bell-bottom (flared) limb sealing in the ectatic common iliac, or an extension into the " + name +
          " external iliac artery that covers the internal iliac (embolise it first, or an iliac branch device)" });
    return widest;
  }
  if (oversizing(smallest) > hi)
  {
    findings.push_back({ "iliacTooNarrow", side,
                         common + " is narrower than " + family.name +
                           "'s smallest limb allows: " + CompactNumber(smallest) + " mm gives " + percent(smallest) +
                           " oversizing, needs " + window + "; the " + CompactNumber(smallest) + " mm limb is planned",
                         "accept the oversizing (infolding risk), or a family with narrower limbs" });
    return smallest;
  }
  double nearest = smallest, best = Infinity;
  for (const DeviceSize& size : sizes)
  {
    const double distance = std::max(lo - oversizing(size.diameterMm), oversizing(size.diameterMm) - hi);
    if (distance < best)
    {
      best = distance;
      nearest = size.diameterMm;
    }
  }
  std::string between;
  for (const DeviceSize& size : sizes)
    if (std::abs(oversizing(size.diameterMm) - 0.5 * (lo + hi)) < 40.0)
      between += (between.empty() ? "" : ", ") + CompactNumber(size.diameterMm) + " mm " + percent(size.diameterMm);
  findings.push_back({ "iliacBetweenSizes", side,
                       common + " falls between " + family.name + "'s limb sizes: no limb gives " + window +
                         " oversizing (" + between + "); the " + CompactNumber(nearest) +
                         " mm limb, nearest the window, is planned",
                       "accept the nearest size's oversizing, or a family whose limb sizes fit this iliac" });
  return nearest;
}

/// The smallest aortic lumen diameter within ±CrotchLevelMm of `levelMm` (NaN: no ring there).
double AortaNarrowestNear(const ConfigurationAnatomy& anatomy, double levelMm)
{
  double narrowest = Infinity;
  for (std::size_t k = 0; k < anatomy.aortaProfileMm.size() && k < anatomy.aortaMinDiameterMm.size(); ++k)
    if (std::abs(anatomy.aortaProfileMm[k] - levelMm) <= CrotchLevelMm && std::isfinite(anatomy.aortaMinDiameterMm[k]))
      narrowest = std::min(narrowest, anatomy.aortaMinDiameterMm[k]);
  return std::isfinite(narrowest) ? narrowest : NaN;
}

/// A whole configuration for one main body, scored for the choice between bodies.
struct Candidate
{
  DeviceConfiguration configuration;
  /// Failed constraints, the sides' landings (0 in the window, 1 short, 2 covering, summed), the
  /// gate's shortfall below its clearance (mm), the narrower side's margin negated (mm), components, the distal edges'
  /// distance from W_hi (mm), the ipsilateral leg's mismatch with what lands in or below it (mm): lower is better.
  std::tuple<int, int, double, double, std::size_t, double, double> score{ 0, 0, 0.0, 0.0, 0, 0.0, 0.0 };
};

/// The findings of one side's landing.
void LandingFindings(const DeviceFamily& family,
                     const ConfigurationAnatomy& anatomy,
                     int side,
                     const SideOption& option,
                     bool given,
                     DeviceConfiguration& c)
{
  const std::string name = SideName(side);
  const double seal = option.distalMm - anatomy.SealFromMm(side);
  const double lo = c.landingLowMm[side], hi = c.landingHighMm[side];
  const double sealMin = family.ifu.iliacSealLengthMm.min;
  const double commonIliac = hi - anatomy.SealFromMm(side);
  const std::string from = std::isfinite(anatomy.targetToFlowDividerMm[side]) ? "flow divider" : "aortic bifurcation";
  const std::string lands =
    option.landing == Landing::Covers
      ? "its shortest combination ends " + Mm(option.distalMm - hi) + " past the internal iliac ostium (covers it)"
      : "the " + name + " limb lands " + Mm(hi - option.distalMm) + " above the internal iliac ostium with a " +
          Mm(seal) + " seal";
  if (commonIliac < sealMin)
    c.findings.push_back(
      { "commonIliacTooShort", side,
        name + " common iliac too short for " + family.name + "'s minimum iliac seal: " + Mm(commonIliac) +
          " from the " + from + " to the internal iliac ostium (" + Mm(anatomy.targetToInternalIliacMm[side] - hi) +
          " above the internal iliac origin), needs ≥ " + CompactNumber(sealMin) + " mm; " + lands,
        "an iliac extension into the " + name +
          " external iliac artery that covers the internal iliac (embolise it first), or an iliac branch device" });
  else if (given && option.landing == Landing::Covers)
    c.findings.push_back({ "internalIliacCovered", side,
                           "the " + name + " side as given ends " + Mm(option.distalMm - hi) + " past the " + name +
                             " internal iliac ostium: it covers the ostium by " + Mm(option.distalMm - hi),
                           "a shorter limb or extension, or placing it higher (deeper in what it goes into)" });
  else if (given && option.landing == Landing::Short)
    c.findings.push_back({ "iliacSealShort", side,
                           "the " + name + " side as given ends " + Mm(lo - option.distalMm) + " short of " +
                             family.name + "'s " + CompactNumber(sealMin) + " mm minimum iliac seal (" + Mm(seal) + ")",
                           "a longer limb, an iliac extension, or placing it lower" });
  else if (option.landing == Landing::Covers)
    c.findings.push_back({ "internalIliacCovered", side,
                           "no " + family.name + " combination on the " + name +
                             " side ends above its internal "
                             "iliac ostium: " +
                             lands,
                           "embolise the internal iliac and land in the external iliac, or a family with shorter "
                           "limbs" });
  else if (option.landing == Landing::Short)
    c.findings.push_back({ "iliacSealShort", side,
                           "the " + name + " side's longest combination ends " + Mm(lo - option.distalMm) +
                             " short of the " + CompactNumber(sealMin) + " mm minimum iliac seal (" + Mm(seal) + ")",
                           "an iliac extension, or a longer limb from another family" });
}

/// A given side's overlaps outside the family's window: under the minimum (the junction may come
/// apart: a type III endoleak) or over the maximum the catalogue gives.
void OverlapFindings(const DeviceFamily& family, int side, const SideOption& option, DeviceConfiguration& c)
{
  const IfuLimit& window = family.junctions.overlapMm;
  for (std::size_t k = 0; k < option.parts.size(); ++k)
  {
    const double ov = option.overlapMm[k];
    const std::string part = option.parts[k].RoleText() + " " + option.parts[k].item.CodeText();
    if (ov < window.min - 1e-9)
      c.findings.push_back({ "overlapShort", side,
                             "the " + part + " as given overlaps " + Mm(ov) + ", under " + family.name + "'s " +
                               CompactNumber(window.min) +
                               " mm minimum overlap (the junction may come apart: a "
                               "type III endoleak)",
                             "insert it deeper, or a longer component" });
    else if (std::isfinite(window.max) && ov > window.max + 1e-9)
      c.findings.push_back({ "overlapLong", side,
                             "the " + part + " as given overlaps " + Mm(ov) + ", over " + family.name + "'s " +
                               CompactNumber(window.max) + " mm maximum overlap",
                             "insert it less deep, or a shorter component" });
  }
}

/// Completes the configuration of one main body on both sides; nullopt when a side has no option.
std::optional<Candidate> ConfigureBody(const DeviceFamily& family,
                                       const CatalogueComponent& body,
                                       const std::array<double, 2>& landingDiameter,
                                       const ConfigurationAnatomy& anatomy,
                                       const DeviceConfiguration& base,
                                       const ResolvedConfiguration* given)
{
  const double tolerance = base.deploymentToleranceMm;
  Candidate candidate;
  DeviceConfiguration& c = candidate.configuration;
  c = base;
  const int ipsi = c.ipsilateralSide, contra = 1 - ipsi;
  c.flowDividerMm = body.flowDividerMm;
  c.gateEndMm = body.gateEndMm;
  c.gateClearanceMm = anatomy.targetToBifurcationMm - body.gateEndMm;
  c.components.push_back(Place(OrderRole::MainBody, body, ipsi, 0.0));
  std::optional<SideOption> bodyAlone;
  if (body.distalDiameterMm == landingDiameter[ipsi] || (given && given->bodyLegLandsAlone))
  {
    bodyAlone = BodyLegOption(body.lengthMm, c.landingLowMm[ipsi], c.landingHighMm[ipsi], tolerance);
  }
  // A side the surgeon gave is completed exactly so; the others by the rule.
  const auto complete = [&](OrderRole role, int side, double stubEnd, const std::optional<SideOption>& alone)
  {
    if (given && given->limb[std::size_t(side)].Given())
      return std::optional<SideOption>(
        GivenSideOption(family, role, side, body.flowDividerMm, stubEnd, given->limb[std::size_t(side)],
                        given->extension[std::size_t(side)], c.landingLowMm[side], c.landingHighMm[side], tolerance));
    return BestSide(LimbOptions(family, role, side, body.flowDividerMm, stubEnd, landingDiameter[side],
                                c.landingLowMm[side], c.landingHighMm[side], tolerance),
                    alone);
  };
  const std::optional<SideOption> ipsiSide = given && given->bodyLegLandsAlone
                                               ? bodyAlone
                                               : complete(OrderRole::IpsilateralLimb, ipsi, body.lengthMm, bodyAlone);
  const std::optional<SideOption> contraSide =
    complete(OrderRole::ContralateralLimb, contra, body.gateEndMm, std::nullopt);
  if (!ipsiSide || !contraSide)
    return std::nullopt;
  const std::pair<int, const SideOption*> sides[2] = { { ipsi, &*ipsiSide }, { contra, &*contraSide } };
  for (const auto& [side, option] : sides)
  {
    int outer = 0; // the main body
    for (std::size_t k = 0; k < option->parts.size(); ++k)
    {
      c.components.push_back(option->parts[k]);
      ConfiguredComponent& placed = c.components.back();
      placed.holdsAboveMm = option->holds[k].aboveMm;
      placed.holdsBelowMm = option->holds[k].belowMm;
      placed.holdsAboveLimit = option->holds[k].aboveLimit;
      placed.holdsBelowLimit = option->holds[k].belowLimit;
      const int inner = int(c.components.size()) - 1;
      const bool inBody = k == 0;
      const std::string what = option->parts[k].role == OrderRole::IliacExtension ? "iliac extension in the limb"
                               : side == ipsi ? "ipsilateral limb in the main body's ipsilateral leg"
                                              : "contralateral limb in the gate";
      c.overlaps.push_back({ std::string(SideName(side)) + " " + what, side, inBody ? 0 : outer, inner,
                             option->overlapMm[k], family.junctions.overlapMm.min, option->overlapMaxMm[k] });
      outer = inner;
    }
    c.coveredLengthMm[side] = option->distalMm;
    c.sealLengthMm[side] = option->distalMm - anatomy.SealFromMm(side);
    c.marginToInternalIliacMm[side] = c.landingHighMm[side] - option->distalMm;
    const bool givenSide =
      given && (given->limb[std::size_t(side)].Given() || (side == ipsi && given->bodyLegLandsAlone));
    LandingFindings(family, anatomy, side, *option, givenSide, c);
    if (givenSide)
      OverlapFindings(family, side, *option, c);
  }
  const double clearance = family.junctions.gateClearanceMm.min;
  if (c.gateClearanceMm < (std::isnan(clearance) ? 0.0 : clearance))
    c.findings.push_back(
      { "gateBelowBifurcation", contra,
        "aorta too short for the " + body.CodeText() + " main body: its contralateral gate ends " +
          Mm(c.gateClearanceMm) + " above the aortic bifurcation, needs ≥ " +
          (std::isnan(clearance) ? std::string("0 mm") : CompactNumber(clearance) + " mm") +
          " to be cannulated in the sac",
        "a main body with a shorter contralateral gate (another family or a short-body model), or an "
        "aorto-uni-iliac device with a femoro-femoral crossover" });
  if (std::isfinite(body.crotchWidthMm))
  {
    const double atCrotch = AortaNarrowestNear(anatomy, body.flowDividerMm);
    if (std::isfinite(atCrotch) && atCrotch < body.crotchWidthMm)
      c.findings.push_back({ "crotchTooNarrow", -1,
                             "distal aorta too narrow for the crotch: the lumen is " + Mm(atCrotch) + " within " +
                               FormatNumber(CrotchLevelMm, 0) + " mm of the flow divider (" + Mm(body.flowDividerMm) +
                               " below the proximal edge), the " + body.CodeText() + " crotch is " +
                               CompactNumber(body.crotchWidthMm) + " mm wide: the limbs will be compressed",
                             "a main body whose flow divider lies higher in the sac, or another family" });
  }
  else
    c.notes.push_back("The catalogue gives no crotch width for the " + body.CodeText() +
                      " main body: the crotch is not checked against the distal aorta.");
  if (std::isnan(clearance))
    c.notes.push_back("The catalogue gives no gate clearance for " + family.name +
                      ": the gate is only required to end above the aortic bifurcation.");
  const int failures = int(c.findings.size());
  const int outside = int(ipsiSide->landing) + int(contraSide->landing); // 0 in window, 1 short, 2 covers
  const double needed = std::isnan(clearance) ? 0.0 : clearance;
  const double gateDeficit = std::round(std::max(0.0, needed - c.gateClearanceMm) / SameEdgeMm);
  const double shortfall = (c.landingHighMm[0] - c.coveredLengthMm[0]) + (c.landingHighMm[1] - c.coveredLengthMm[1]);
  const double legMismatch =
    std::abs(body.distalDiameterMm - (ipsiSide->parts.empty() ? landingDiameter[ipsi]
                                                              : (std::isfinite(ipsiSide->parts[0].item.diameterMm)
                                                                   ? ipsiSide->parts[0].item.diameterMm
                                                                   : landingDiameter[ipsi])));
  const double margin = std::min(ipsiSide->margin, contraSide->margin);
  candidate.score = { failures,
                      outside,
                      gateDeficit,
                      -std::round(margin * 10.0) / 10.0,
                      c.components.size(),
                      std::round(shortfall / SameEdgeMm),
                      legMismatch };
  return candidate;
}

/// \throws InputError for a negative (or NaN) deployment tolerance.
void CheckTolerance(double deploymentToleranceMm)
{
  if (!(deploymentToleranceMm >= 0.0))
    throw InputError("deploymentToleranceMm is " + FormatNumber(deploymentToleranceMm) + "; expected ≥ 0 mm.");
}

/// `configuration` marked not configured, for `reason`.
DeviceConfiguration Unknown(DeviceConfiguration configuration, const std::string& reason)
{
  configuration.configured = false;
  configuration.unknownReason = reason;
  return configuration;
}

DeviceConfiguration ConfigureWithoutAlternatives(const DeviceFamily& family,
                                                 const ChosenDiameters& chosen,
                                                 const ConfigurationAnatomy& anatomy,
                                                 const SideChoice& ipsilateral,
                                                 double toleranceMm,
                                                 std::vector<const CatalogueComponent*>& bodies,
                                                 const ResolvedConfiguration* given)
{
  DeviceConfiguration base;
  base.deploymentToleranceMm = toleranceMm;
  base.family = family.name;
  base.ipsilateralSide = ipsilateral.side;
  base.ipsilateralReason = ipsilateral.reason;
  if (!std::isfinite(chosen.mainBodyMm))
    return Unknown(base, "no main body was sized for the neck");
  if (!std::isfinite(anatomy.targetToBifurcationMm))
    return Unknown(base, "the aortic bifurcation was not located");
  for (int side = 0; side < 2; ++side)
    if (!std::isfinite(anatomy.targetToInternalIliacMm[side]))
      return Unknown(base, std::string("the ") + SideName(side) +
                             " internal iliac origin was not found, so the landing zone's lower end is not known");
  for (const CatalogueComponent* body : family.ComponentsOf(ComponentRole::MainBody))
    if (given ? body == given->mainBody.item && body->GeometryKnown()
              : body->diameterMm == chosen.mainBodyMm && body->GeometryKnown())
      bodies.push_back(body);
  if (given && bodies.empty())
    return Unknown(base, "the catalogue gives no length, flow divider and contralateral gate position for the " +
                           given->mainBody.item->CodeText() + " " + family.name + " main body given");
  if (bodies.empty())
    return Unknown(base, "the catalogue gives no length, flow divider and contralateral gate position for the " +
                           CompactNumber(chosen.mainBodyMm) + " mm " + family.name +
                           " main body (not found in the public sources read; see the catalogue's evidence)");
  if (std::isnan(family.junctions.overlapMm.min))
    return Unknown(base, "the catalogue gives no minimum overlap between " + family.name +
                           " components (not found in the public sources read)");
  for (int side = 0; side < 2; ++side)
  {
    const double radius =
      std::isfinite(anatomy.internalIliacRadiusMm[side]) ? anatomy.internalIliacRadiusMm[side] : 0.0;
    const double ostium = anatomy.targetToInternalIliacOstiumMm[side];
    // At least the ostium's radius above the origin, and never past the located ostium's edge.
    base.landingHighMm[side] = anatomy.targetToInternalIliacMm[side] - radius;
    if (std::isfinite(ostium))
      base.landingHighMm[side] = std::min(base.landingHighMm[side], ostium);
    base.sealFromMm[side] = anatomy.SealFromMm(side);
    base.landingLowMm[side] = base.sealFromMm[side] + family.ifu.iliacSealLengthMm.min;
  }
  std::array<double, 2> landing{ NaN, NaN };
  std::vector<ConfigurationFinding> sizeFindings;
  for (int side = 0; side < 2; ++side)
  {
    if (given && given->limb[std::size_t(side)].Given())
    {
      const ResolvedComponent& last = given->extension[std::size_t(side)].Given() ? given->extension[std::size_t(side)]
                                                                                  : given->limb[std::size_t(side)];
      landing[side] = last.item->distalDiameterMm;
      continue;
    }
    landing[side] = LandingDiameter(family, chosen, anatomy, side, sizeFindings);
    if (!std::isfinite(landing[side]))
      return Unknown(base, std::string("no ") + SideName(side) + " limb was sized (the iliac diameter is not known)");
    const auto limbs = family.ComponentsOf(ComponentRole::Limb);
    if (std::none_of(limbs.begin(), limbs.end(),
                     [&](const CatalogueComponent* l)
                     { return l->distalDiameterMm == landing[side] && std::isfinite(l->lengthMm); }))
      return Unknown(base, "the catalogue gives no lengths for the " + CompactNumber(landing[side]) + " mm " +
                             family.name + " limb");
  }
  std::optional<Candidate> best;
  for (const CatalogueComponent* body : bodies)
  {
    std::optional<Candidate> candidate = ConfigureBody(family, *body, landing, anatomy, base, given);
    if (candidate && (!best || candidate->score < best->score))
      best = candidate;
  }
  if (!best)
    return Unknown(base, "no " + family.name + " limb can be inserted as deep as the family's minimum overlap of " +
                           CompactNumber(family.junctions.overlapMm.min) + " mm");
  DeviceConfiguration c = best->configuration;
  c.configured = true;
  c.findings.insert(c.findings.begin(), sizeFindings.begin(), sizeFindings.end());
  // The limbs side by side in the distal aorta (the NAB study's thresholds, compared with (d) on
  // the family's wall).
  const double aorta = anatomy.distalAorticDiameterMm;
  const double sum = landing[0] + landing[1];
  if (std::isfinite(aorta) && aorta < sum)
  {
    const std::string text = "the distal aorta is " + Mm(aorta) + " (d, " + anatomy.distalAorticWall +
                             "), narrower than the " + Mm(sum) + " the two limbs need side by side";
    // Within the measurement's uncertainty of the extremely narrow limit: it cannot be excluded.
    const double uncertainty =
      anatomy.distalAorticWall == "lumen" ? LumenDiameterUncertaintyMm : OuterDiameterUncertaintyMm;
    if (aorta <= ExtremelyNarrowAortaMm + uncertainty)
      c.findings.push_back({ "limbCompression", -1,
                             "limbs compressed in an extremely narrow distal aorta (≤ " +
                               FormatNumber(ExtremelyNarrowAortaMm, 0) + " mm, within the measurement's ±" +
                               FormatNumber(uncertainty) + " mm): " + text + " (limb stenosis and occlusion risk)",
                             "kissing-balloon moulding or relining of both limbs, limbs of a smaller diameter, or an "
                             "aorto-uni-iliac device" });
    else if (aorta <= NarrowAortaMm)
      c.notes.push_back("Narrow distal aorta (≤ " + FormatNumber(NarrowAortaMm, 0) + " mm): " + text +
                        "; the limbs will be compressed there.");
  }
  return c;
}

/// The limb lengths alternatives: a landing window W_hi ± IliacLengthUncertaintyMm that would
/// change a side's limb or extension.
void LengthAlternatives(const DeviceFamily& family,
                        const ChosenDiameters& chosen,
                        const ConfigurationAnatomy& anatomy,
                        const SideChoice& ipsilateral,
                        DeviceConfiguration& c)
{
  for (int side = 0; side < 2; ++side)
    for (double shift : { -IliacLengthUncertaintyMm, IliacLengthUncertaintyMm })
    {
      ConfigurationAnatomy moved = anatomy;
      moved.targetToInternalIliacMm[side] += shift;
      std::vector<const CatalogueComponent*> bodies;
      const DeviceConfiguration other =
        ConfigureWithoutAlternatives(family, chosen, moved, ipsilateral, c.deploymentToleranceMm, bodies, nullptr);
      if (!other.configured)
        continue;
      for (OrderRole role : { OrderRole::IpsilateralLimb, OrderRole::ContralateralLimb, OrderRole::IliacExtension })
      {
        const ConfiguredComponent* mine = c.Find(role, side);
        const ConfiguredComponent* theirs = other.Find(role, side);
        if (!mine || !theirs || mine->item.lengthMm == theirs->item.lengthMm)
          continue;
        const std::string what =
          std::string(SideName(side)) + " " + (role == OrderRole::IliacExtension ? "iliac extension" : "limb");
        const std::string alternative = CompactNumber(theirs->item.lengthMm) + " mm";
        const bool known =
          std::any_of(c.alternatives.begin(), c.alternatives.end(),
                      [&](const SizeAlternative& a) { return a.component == what && a.alternative == alternative; });
        if (!known)
          c.alternatives.push_back({ what, CompactNumber(mine->item.lengthMm) + " mm", alternative,
                                     "the " + what + " would be " + alternative + " long (" + theirs->item.CodeText() +
                                       ") if the " + SideName(side) + " internal iliac origin lay " +
                                       FormatNumber(std::abs(shift), 0) + " mm " + (shift > 0 ? "lower" : "higher") +
                                       " (the measured iliac length's uncertainty, ±" +
                                       FormatNumber(IliacLengthUncertaintyMm, 0) + " mm)" });
      }
    }
}

} // namespace

IpsilateralSide ParseIpsilateralSide(const std::string& text, const std::string& parameter)
{
  const std::string value = LowerCase(TrimBlanks(text));
  if (value == "auto")
    return IpsilateralSide::Auto;
  if (value == "right")
    return IpsilateralSide::Right;
  if (value == "left")
    return IpsilateralSide::Left;
  throw InputError(parameter + " is '" + text + "'; expected right, left or auto.");
}

double ConfigurationAnatomy::SealFromMm(int side) const
{
  const double divider = targetToFlowDividerMm[std::size_t(side)];
  return std::isfinite(divider) ? std::max(divider, targetToBifurcationMm) : targetToBifurcationMm;
}

SideChoice ChooseIpsilateralSide(IpsilateralSide wanted,
                                 const std::array<double, 2>& access,
                                 const std::array<double, 2>& tortuosity,
                                 double toleranceMm)
{
  if (wanted == IpsilateralSide::Right)
    return { 0, "right, as chosen in the plan's settings (main body side)" };
  if (wanted == IpsilateralSide::Left)
    return { 1, "left, as chosen in the plan's settings (main body side)" };
  const std::string accessText = "right " + Mm(access[0]) + ", left " + Mm(access[1]);
  const bool bothAccess = std::isfinite(access[0]) && std::isfinite(access[1]);
  if (bothAccess && std::abs(access[0] - access[1]) > toleranceMm)
  {
    const int side = access[0] > access[1] ? 0 : 1;
    return { side, std::string(SideName(side)) + ": the wider access vessel (" + accessText + ")" };
  }
  if (std::isfinite(tortuosity[0]) && std::isfinite(tortuosity[1]) &&
      std::abs(tortuosity[0] - tortuosity[1]) > TortuosityToleranceRatio)
  {
    const int side = tortuosity[0] < tortuosity[1] ? 0 : 1;
    return { side, std::string(SideName(side)) + ": the less tortuous iliac (tortuosity right " +
                     FormatNumber(tortuosity[0], 2) + ", left " + FormatNumber(tortuosity[1], 2) + "; access within " +
                     FormatNumber(toleranceMm) + " mm: " + accessText + ")" };
  }
  if (bothAccess && access[0] != access[1])
  {
    const int side = access[0] > access[1] ? 0 : 1;
    return { side, std::string(SideName(side)) + ": either side will do (access vessels alike within " +
                     FormatNumber(toleranceMm) + " mm: " + accessText +
                     "; iliacs alike in tortuosity); the marginally wider one" };
  }
  if (std::isfinite(access[0]) != std::isfinite(access[1]))
  {
    const int side = std::isfinite(access[0]) ? 0 : 1;
    return { side, std::string(SideName(side)) + ": the only side whose access vessel was measured" };
  }
  return { 0, "right: neither access nor tortuosity tells the sides apart" };
}

const char* ToString(OrderRole role)
{
  switch (role)
  {
    case OrderRole::MainBody:
      return "mainBody";
    case OrderRole::IpsilateralLimb:
      return "ipsilateralLimb";
    case OrderRole::ContralateralLimb:
      return "contralateralLimb";
    case OrderRole::IliacExtension:
      return "iliacExtension";
    case OrderRole::AorticCuff:
      return "aorticCuff";
  }
  return "";
}

std::string ConfiguredComponent::OrderText() const
{
  const auto diameter = [](double d) { return std::isfinite(d) ? CompactNumber(d) : std::string("?"); };
  // Proximal-distal where both are known and differ; the one known otherwise.
  std::string diameters = std::isfinite(item.diameterMm) ? diameter(item.diameterMm) : diameter(item.distalDiameterMm);
  if (std::isfinite(item.diameterMm) && std::isfinite(item.distalDiameterMm) &&
      item.distalDiameterMm != item.diameterMm)
    diameters += "-" + diameter(item.distalDiameterMm);
  return item.name + " " + diameters + " × " + diameter(item.lengthMm) + " mm" +
         (item.code.empty() ? "" : " (" + item.code + ")");
}

std::string ConfiguredComponent::RoleText() const
{
  switch (role)
  {
    case OrderRole::MainBody:
      return "main body";
    case OrderRole::IpsilateralLimb:
      return std::string(SideName(side)) + " ipsilateral limb";
    case OrderRole::ContralateralLimb:
      return std::string(SideName(side)) + " contralateral limb";
    case OrderRole::IliacExtension:
      return std::string(SideName(side)) + " iliac extension";
    case OrderRole::AorticCuff:
      return "aortic cuff";
  }
  return "";
}

std::string ConfiguredComponent::HoldsText() const
{
  if (!std::isfinite(holdsAboveMm + holdsBelowMm))
    return "";
  const std::string name = SideName(side);
  const auto limit = [&](const std::string& key, bool above)
  {
    if (key == "covers")
      return "it covers the " + name + " internal iliac ostium";
    if (key == "seal")
      return "the " + name + " iliac seal falls under the minimum";
    if (key == "overlap")
      return std::string("an overlap falls under the minimum");
    if (key == "stop")
      return std::string(above ? "it is as deep as it goes in what it is inserted into: it cannot land higher"
                               : "what is inserted into it is as deep as it goes: it cannot land lower");
    return key;
  };
  const auto range = [](double mm) { return mm >= 0.0 ? Mm(mm) : "none (" + Mm(-mm) + " short)"; };
  return "holds if it lands up to " + range(holdsAboveMm) + " higher (then " + limit(holdsAboveLimit, true) + ") or " +
         range(holdsBelowMm) + " lower (then " + limit(holdsBelowLimit, false) + ")";
}

std::string DeviceConfiguration::OrderList() const
{
  if (!configured)
    return "not configured: " + unknownReason;
  std::string list;
  for (const ConfiguredComponent& c : components)
    list += (list.empty() ? "" : "; ") + c.OrderText();
  return list;
}

const ConfiguredComponent* DeviceConfiguration::Find(OrderRole role, int side) const
{
  for (const ConfiguredComponent& c : components)
    if (c.role == role && (side < 0 || c.side == side))
      return &c;
  return nullptr;
}

DeviceConfiguration ConfigureDevice(const DeviceFamily& family,
                                    const ChosenDiameters& chosen,
                                    const ConfigurationAnatomy& anatomy,
                                    const SideChoice& ipsilateral,
                                    double deploymentToleranceMm)
{
  CheckTolerance(deploymentToleranceMm);
  std::vector<const CatalogueComponent*> bodies;
  DeviceConfiguration c =
    ConfigureWithoutAlternatives(family, chosen, anatomy, ipsilateral, deploymentToleranceMm, bodies, nullptr);
  if (c.configured)
    LengthAlternatives(family, chosen, anatomy, ipsilateral, c);
  for (int side = 0; side < 2 && c.configured; ++side)
    if (const std::optional<SizeAlternative> wider = MarginAlternative(family, c, side))
      c.alternatives.push_back(*wider);
  return c;
}

DeviceConfiguration ConfigureGivenDevice(const DeviceFamily& family,
                                         const ResolvedConfiguration& given,
                                         const ChosenDiameters& chosen,
                                         const ConfigurationAnatomy& anatomy,
                                         const SideChoice& ipsilateral,
                                         double deploymentToleranceMm)
{
  CheckTolerance(deploymentToleranceMm);
  std::vector<const CatalogueComponent*> bodies;
  DeviceConfiguration c =
    ConfigureWithoutAlternatives(family, chosen, anatomy, ipsilateral, deploymentToleranceMm, bodies, &given);
  c.given = true;
  return c;
}

} // namespace sgp
