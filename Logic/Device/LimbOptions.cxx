#include "Device/LimbOptions.h"

#include <algorithm>
#include <cmath>

#include "Common/Errors.h"
#include "Common/Format.h"
#include "Device/CriterionCheck.h"

namespace sgp
{
namespace
{

constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
/// The grid the limb's overlap is searched on when an extension is placed below it, mm (the
/// extension's overlap is then solved exactly).
constexpr double OverlapGridMm = 0.25;
/// Two margins this close are alike (the ranges are reported to 0.1 mm).
constexpr double SameMarginMm = 0.05;

const char* SideName(int side)
{
  return side == 0 ? "right" : "left";
}

/// a + b·x.
struct Line
{
  double a = 0.0, b = 0.0;
};

/// The smallest x in [lo, hi] where `value` is largest, among the ends and the points where two of
/// `lines` cross: `value` is piecewise linear with its pieces bounded by those lines, so its
/// maximum lies at one of those points.
template<typename Value>
double ArgMax(const Value& value, const std::vector<Line>& lines, double lo, double hi)
{
  std::vector<double> xs{ lo, hi };
  for (std::size_t i = 0; i < lines.size(); ++i)
    for (std::size_t j = i + 1; j < lines.size(); ++j)
      if (lines[i].b != lines[j].b)
      {
        const double x = (lines[j].a - lines[i].a) / (lines[i].b - lines[j].b);
        if (x > lo && x < hi)
          xs.push_back(x);
      }
  std::sort(xs.begin(), xs.end());
  double best = -std::numeric_limits<double>::infinity(), bestX = lo;
  for (double x : xs)
  {
    const double v = value(x);
    if (v > best + 1e-9)
    {
      best = v;
      bestX = x;
    }
  }
  return bestX;
}

/// A direction limited by a failure at `failMm` unless a stop comes first (at `stopMm` ≤ it):
/// then the part cannot move that far, and the direction is safe.
void Limit(double failMm, const char* fail, double stopMm, double& mm, std::string& limit)
{
  if (stopMm <= failMm)
  {
    mm = stopMm;
    limit = "stop";
  }
  else
  {
    mm = failMm;
    limit = fail;
  }
}

/// The hold range of the side's last part: its distal edge in [lo, hi], its overlap `ov` in
/// [ovLo, ovHi] (down: it covers the ostium or its overlap falls under the minimum, whichever
/// first; up: its seal falls under the minimum, unless it reaches the window's top first).
HoldRange LandingHold(double distal, double lo, double hi, double ov, double ovLo, double ovHi)
{
  HoldRange h;
  h.belowMm = hi - distal;
  h.belowLimit = "covers";
  if (ov - ovLo < h.belowMm)
  {
    h.belowMm = ov - ovLo;
    h.belowLimit = "overlap";
  }
  Limit(distal - lo, "seal", ovHi - ov, h.aboveMm, h.aboveLimit);
  return h;
}

/// The hold range of a limb with an extension below it (overlaps ov1 of the limb, ov2 of the
/// extension in the limb): down, its overlap falls under the minimum unless the extension reaches
/// its window's top in it first; up, the extension's overlap falls under the minimum unless the
/// limb reaches its own window's top first.
HoldRange LimbAboveExtensionHold(double ov1, double ovLo, double ovHi, double ov2, double exLo, double exHi)
{
  HoldRange h;
  Limit(ov1 - ovLo, "overlap", exHi - ov2, h.belowMm, h.belowLimit);
  Limit(ov2 - exLo, "overlap", ovHi - ov1, h.aboveMm, h.aboveLimit);
  return h;
}

/// The narrowest of the option's ranges capped at the tolerance (a stop does not narrow it); 0
/// outside its window.
double MarginOf(const std::vector<HoldRange>& holds, Landing landing, double toleranceMm)
{
  if (landing != Landing::InWindow)
    return 0.0;
  double m = toleranceMm;
  for (const HoldRange& h : holds)
    m = std::min(m, h.Narrowest());
  return std::max(0.0, m);
}

/// What a placement is worth: its margin in the window, else how far outside it (negative).
double PlacementValue(const std::vector<HoldRange>& holds, double distal, double lo, double hi, double tol)
{
  const Landing landing = Classify(distal, lo, hi);
  if (landing != Landing::InWindow)
    return std::min(hi - distal, distal - lo);
  return MarginOf(holds, landing, tol);
}

/// The overlap window [lo, hi] of a component inserted into one whose insertable stretch is
/// `stretchMm` long; hi < lo when it cannot be inserted as deep as the family needs.
std::pair<double, double> OverlapWindow(const IfuLimit& overlap, double stretchMm)
{
  const double hi = std::isnan(overlap.max) ? stretchMm : std::min(overlap.max, stretchMm);
  return { overlap.min, hi };
}

/// A single limb of length L inserted `ov` ∈ [ovLo, ovHi] into a stub ending at `stubEnd`.
double SingleLimbOverlap(double stubEnd, double L, double ovLo, double ovHi, double lo, double hi, double tol)
{
  // The rule without a margin: the highest edge not past W_hi (also where the side cannot land
  // in its window).
  const double highest = std::clamp(stubEnd + L - hi, ovLo, ovHi);
  const auto value = [&](double ov)
  {
    const double distal = stubEnd - ov + L;
    return PlacementValue({ LandingHold(distal, lo, hi, ov, ovLo, ovHi) }, distal, lo, hi, tol);
  };
  const std::vector<Line> lines{
    { tol, 0.0 }, { hi - stubEnd - L, 1.0 }, { -ovLo, 1.0 }, { stubEnd + L - lo, -1.0 }, { ovHi, -1.0 }
  };
  const double ov = ArgMax(value, lines, ovLo, ovHi);
  return value(ov) >= -1e-9 ? ov : highest;
}

/// A limb of length L1 in a stub ending at `stubEnd` (overlap window [ovLo, ovHi]) and an extension
/// of length L2 in the limb ([exLo, exHi]), landing in [lo, hi], placed for the tolerance `tol`.
struct LimbStack
{
  double stubEnd = 0.0, L1 = 0.0, L2 = 0.0;
  double ovLo = 0.0, ovHi = 0.0, exLo = 0.0, exHi = 0.0;
  double lo = 0.0, hi = 0.0, tol = 0.0;
  double Distal(double ov1, double ov2) const { return stubEnd - ov1 + L1 - ov2 + L2; }
  std::vector<HoldRange> Holds(double ov1, double ov2) const
  {
    return { LimbAboveExtensionHold(ov1, ovLo, ovHi, ov2, exLo, exHi),
             LandingHold(Distal(ov1, ov2), lo, hi, ov2, exLo, exHi) };
  }
  /// What the placement (ov1, ov2) is worth (PlacementValue).
  double Value(double ov1, double ov2) const { return PlacementValue(Holds(ov1, ov2), Distal(ov1, ov2), lo, hi, tol); }
};

/// The extension's best overlap for the limb's `ov1`, and what it is worth.
std::pair<double, double> ExtensionOverlap(const LimbStack& s, double ov1)
{
  const auto value = [&](double ov2) { return s.Value(ov1, ov2); };
  const std::vector<Line> lines{ { s.tol, 0.0 },
                                 { ov1 - s.ovLo, 0.0 },
                                 { s.ovHi - ov1, 0.0 },
                                 { s.exHi, -1.0 },
                                 { -s.exLo, 1.0 },
                                 { s.hi - s.stubEnd + ov1 - s.L1 - s.L2, 1.0 },
                                 { s.stubEnd - ov1 + s.L1 + s.L2 - s.lo, -1.0 } };
  const double ov2 = ArgMax(value, lines, s.exLo, s.exHi);
  return { ov2, value(ov2) };
}

/// The option of a single limb inserted `ov` into a stub ending at `stubEndMm`.
SideOption SingleLimb(OrderRole role,
                      const CatalogueComponent& limb,
                      int side,
                      double stubEndMm,
                      double ov,
                      double ovLo,
                      double ovHi,
                      double lo,
                      double hi,
                      double toleranceMm)
{
  SideOption o;
  o.parts.push_back(Place(role, limb, side, stubEndMm - ov));
  o.overlapMm.push_back(ov);
  o.overlapMaxMm.push_back(ovHi);
  o.distalMm = o.parts.back().distalMm;
  o.landing = Classify(o.distalMm, lo, hi);
  o.holds.push_back(LandingHold(o.distalMm, lo, hi, ov, ovLo, ovHi));
  o.margin = MarginOf(o.holds, o.landing, toleranceMm);
  return o;
}

/// Positions the surgeon fixed (NaN: free), mm.
struct FixedPositions
{
  double limbOverlapMm = NaN;
  double extensionOverlapMm = NaN;
  double distalMm = NaN; ///< the extension's distal edge along the path
};

/// The overlaps (ov1, ov2) of the limb and the extension of `s`, placed as the file comment says,
/// keeping what `fixed` gives.
std::pair<double, double> LimbAndExtensionOverlaps(const LimbStack& s, const FixedPositions& fixed)
{
  // The extension's overlap for the limb's v1 and what the placement is worth: fixed, from the
  // fixed distal edge, or solved.
  const auto extensionFor = [&](double v1) -> std::pair<double, double>
  {
    double v2 = fixed.extensionOverlapMm;
    if (std::isnan(v2) && std::isfinite(fixed.distalMm))
      v2 = s.Distal(v1, 0.0) - fixed.distalMm;
    if (std::isnan(v2))
      return ExtensionOverlap(s, v1);
    return { v2, s.Value(v1, v2) };
  };
  // Without a margin (or where the side cannot land in its window): both overlaps as shallow as
  // possible gives the lowest edge; deepen the limb's first, then the extension's, until the edge
  // is not past W_hi.
  const double deepest = s.Distal(s.ovLo, s.exLo);
  double excess = std::max(0.0, deepest - s.hi);
  double ov1 = s.ovLo + std::min(excess, s.ovHi - s.ovLo);
  excess -= ov1 - s.ovLo;
  double ov2 = s.exLo + std::min(excess, s.exHi - s.exLo);
  if (std::isfinite(fixed.limbOverlapMm))
    ov1 = fixed.limbOverlapMm;
  if (std::isfinite(fixed.extensionOverlapMm) || std::isfinite(fixed.distalMm))
    ov2 = extensionFor(ov1).first;
  // With one: the limb's overlap on a grid (and the rule's), the extension's solved for each.
  std::vector<double> grid{ ov1 };
  if (std::isnan(fixed.limbOverlapMm))
  {
    for (double v = s.ovLo; v < s.ovHi; v += OverlapGridMm)
      grid.push_back(v);
    grid.push_back(s.ovHi);
  }
  double bestMargin = -std::numeric_limits<double>::infinity(), bestEdge = NaN, best1 = ov1, best2 = ov2;
  for (double v1 : grid)
  {
    const auto [v2, margin] = extensionFor(v1);
    const double edge = s.Distal(v1, v2);
    const bool better =
      margin > bestMargin + 1e-9 ||
      (margin > bestMargin - 1e-9 && (edge > bestEdge + 1e-9 || (edge > bestEdge - 1e-9 && v1 > best1)));
    if (better)
    {
      bestMargin = margin;
      bestEdge = edge;
      best1 = v1;
      best2 = v2;
    }
  }
  if (bestMargin >= -1e-9)
  {
    ov1 = best1;
    ov2 = best2;
  }
  return { ov1, ov2 };
}

/// The option of the limb and the extension of `s` inserted ov1 and ov2.
SideOption LimbAndExtension(OrderRole role,
                            const CatalogueComponent& limb,
                            const CatalogueComponent& extension,
                            int side,
                            const LimbStack& s,
                            double ov1,
                            double ov2)
{
  SideOption o;
  o.parts.push_back(Place(role, limb, side, s.stubEnd - ov1));
  o.parts.push_back(Place(OrderRole::IliacExtension, extension, side, o.parts[0].distalMm - ov2));
  o.overlapMm = { ov1, ov2 };
  o.overlapMaxMm = { s.ovHi, s.exHi };
  o.distalMm = o.parts.back().distalMm;
  o.landing = Classify(o.distalMm, s.lo, s.hi);
  o.holds = s.Holds(ov1, ov2);
  o.margin = MarginOf(o.holds, o.landing, s.tol);
  return o;
}

} // namespace

Landing Classify(double distal, double lo, double hi)
{
  if (distal > hi + 1e-9)
    return Landing::Covers;
  return distal < lo - 1e-9 ? Landing::Short : Landing::InWindow;
}

ConfiguredComponent Place(OrderRole role, const CatalogueComponent& item, int side, double proximalMm)
{
  ConfiguredComponent c;
  c.role = role;
  c.item = item;
  c.side = side;
  c.proximalMm = proximalMm;
  c.distalMm = proximalMm + item.lengthMm;
  return c;
}

std::vector<SideOption> LimbOptions(const DeviceFamily& family,
                                    OrderRole role,
                                    int side,
                                    double stubStartMm,
                                    double stubEndMm,
                                    double landingDiameterMm,
                                    double lo,
                                    double hi,
                                    double toleranceMm,
                                    bool everyCombination)
{
  const IfuLimit& overlap = family.junctions.overlapMm;
  std::vector<SideOption> options;
  std::vector<double> lengths;
  for (const CatalogueComponent* limb : family.ComponentsOf(ComponentRole::Limb))
  {
    if (limb->distalDiameterMm != landingDiameterMm || !std::isfinite(limb->lengthMm))
      continue;
    lengths.push_back(limb->lengthMm);
    // Inserted at most the stub's length, and never so deep that it ends inside the stub.
    const auto [ovLo, ovHi] = OverlapWindow(overlap, std::min(stubEndMm - stubStartMm, limb->lengthMm - SameEdgeMm));
    if (ovHi < ovLo)
      continue;
    // Distal edge = stubEnd − ov + L, ov ∈ [ovLo, ovHi].
    const double ov = SingleLimbOverlap(stubEndMm, limb->lengthMm, ovLo, ovHi, lo, hi, toleranceMm);
    options.push_back(SingleLimb(role, *limb, side, stubEndMm, ov, ovLo, ovHi, lo, hi, toleranceMm));
  }
  std::sort(lengths.begin(), lengths.end());
  double lengthStep = 0.0;
  for (std::size_t i = 1; i < lengths.size(); ++i)
    lengthStep = std::max(lengthStep, lengths[i] - lengths[i - 1]);
  // A single limb that lands within the length step of W_hi is as low as the catalogue's lengths
  // allow; otherwise a limb and an extension may come lower.
  const bool closeEnough =
    std::any_of(options.begin(), options.end(),
                [&](const SideOption& o) { return o.landing == Landing::InWindow && hi - o.distalMm <= lengthStep; });
  if (closeEnough && !everyCombination)
    return options;
  const std::size_t singles = options.size();
  for (std::size_t i = 0; i < singles; ++i)
    for (const CatalogueComponent* extension : family.ComponentsOf(ComponentRole::IliacExtension))
    {
      if (extension->distalDiameterMm != landingDiameterMm || !std::isfinite(extension->lengthMm))
        continue;
      const SideOption& single = options[i];
      const double L1 = single.parts[0].item.lengthMm, L2 = extension->lengthMm;
      const double ovLo = overlap.min, ovHi = single.overlapMaxMm[0];
      // Inserted at most the limb's length, and never so deep that it ends inside the limb.
      const auto [exLo, exHi] = OverlapWindow(overlap, std::min(L1, L2 - SameEdgeMm));
      if (exHi < exLo)
        continue;
      const LimbStack stack{ stubEndMm, L1, L2, ovLo, ovHi, exLo, exHi, lo, hi, toleranceMm };
      const auto [ov1, ov2] = LimbAndExtensionOverlaps(stack, {});
      options.push_back(LimbAndExtension(role, single.parts[0].item, *extension, side, stack, ov1, ov2));
    }
  return options;
}

SideOption BodyLegOption(double legEndMm, double lo, double hi, double toleranceMm)
{
  SideOption alone;
  alone.distalMm = legEndMm;
  alone.landing = Classify(legEndMm, lo, hi);
  HoldRange h;
  h.belowMm = hi - legEndMm;
  h.belowLimit = "covers";
  h.aboveMm = legEndMm - lo;
  h.aboveLimit = "seal";
  alone.holds.push_back(h);
  alone.margin = MarginOf(alone.holds, alone.landing, toleranceMm);
  return alone;
}

std::optional<SideOption> BestSide(std::vector<SideOption> options, const std::optional<SideOption>& bodyAlone)
{
  if (bodyAlone)
    options.push_back(*bodyAlone);
  if (options.empty())
    return std::nullopt;
  const auto better = [](const SideOption& a, const SideOption& b)
  {
    if (a.landing != b.landing)
      return a.landing < b.landing;
    if (a.landing == Landing::Covers)
      return a.distalMm < b.distalMm - 1e-9;
    if (std::abs(a.margin - b.margin) > SameMarginMm)
      return a.margin > b.margin;
    if (std::abs(a.distalMm - b.distalMm) > SameEdgeMm)
      return a.distalMm > b.distalMm;
    if (a.parts.size() != b.parts.size())
      return a.parts.size() < b.parts.size();
    return a.distalMm > b.distalMm + 1e-9;
  };
  return *std::min_element(options.begin(), options.end(), better);
}

SideOption GivenSideOption(const DeviceFamily& family,
                           OrderRole role,
                           int side,
                           double stubStartMm,
                           double stubEndMm,
                           const ResolvedComponent& limb,
                           const ResolvedComponent& extension,
                           double lo,
                           double hi,
                           double toleranceMm)
{
  const IfuLimit& overlap = family.junctions.overlapMm;
  const CatalogueComponent& L = *limb.item;
  const double stub = stubEndMm - stubStartMm;
  const std::string into = role == OrderRole::ContralateralLimb ? "the contralateral gate" : "the ipsilateral leg";
  auto [ovLo, ovHi] = OverlapWindow(overlap, std::min(stub, L.lengthMm - SameEdgeMm));
  ovHi = std::max(ovHi, ovLo); // a window the catalogue cannot meet: its holds say so
  // Where the limb cannot go: not into what it joins, or deeper than it is long.
  const auto check = [&](double ov, const ResolvedComponent& part, double room, const std::string& what)
  {
    if (ov <= 0.0)
      throw InputError(part.where + ": the " + std::string(SideName(side)) + " " + part.item->CodeText() + " (" +
                       CompactNumber(part.item->lengthMm) + " mm) placed there overlaps " + what + " by " +
                       FormatNumber(ov) + " mm: it cannot reach it; expected an overlap of " +
                       FormatNumber(overlap.min) + " to " + FormatNumber(room) +
                       " mm, or no position, to let the plan place it.");
    if (ov > room + 1e-6)
      throw InputError(part.where + ": the " + std::string(SideName(side)) + " " + part.item->CodeText() +
                       " placed there goes " + FormatNumber(ov) + " mm into " + what + ", deeper than its " +
                       FormatNumber(room) + " mm; expected an overlap of " + FormatNumber(overlap.min) + " to " +
                       FormatNumber(room) + " mm, or no position, to let the plan place it.");
  };
  const double limbRoom = std::min(stub, L.lengthMm - SameEdgeMm);
  if (!extension.Given())
  {
    double ov = limb.overlapMm;
    if (std::isfinite(limb.distalEdgeAboveInternalIliacMm))
      ov = stubEndMm + L.lengthMm - (hi - limb.distalEdgeAboveInternalIliacMm);
    if (std::isnan(ov))
      ov = SingleLimbOverlap(stubEndMm, L.lengthMm, ovLo, ovHi, lo, hi, toleranceMm);
    check(ov, limb, limbRoom, into);
    return SingleLimb(role, L, side, stubEndMm, ov, ovLo, ovHi, lo, hi, toleranceMm);
  }
  const CatalogueComponent& E = *extension.item;
  auto [exLo, exHi] = OverlapWindow(overlap, std::min(L.lengthMm, E.lengthMm - SameEdgeMm));
  exHi = std::max(exHi, exLo);
  FixedPositions fixed;
  fixed.limbOverlapMm = limb.overlapMm;
  fixed.extensionOverlapMm = extension.overlapMm;
  if (std::isfinite(extension.distalEdgeAboveInternalIliacMm))
    fixed.distalMm = hi - extension.distalEdgeAboveInternalIliacMm;
  const LimbStack stack{ stubEndMm, L.lengthMm, E.lengthMm, ovLo, ovHi, exLo, exHi, lo, hi, toleranceMm };
  const auto [ov1, ov2] = LimbAndExtensionOverlaps(stack, fixed);
  check(ov1, limb, limbRoom, into);
  check(ov2, extension, std::min(L.lengthMm, E.lengthMm - SameEdgeMm), "the limb");
  return LimbAndExtension(role, L, E, side, stack, ov1, ov2);
}

std::optional<SizeAlternative> MarginAlternative(const DeviceFamily& family, const DeviceConfiguration& c, int side)
{
  std::vector<const ConfiguredComponent*> parts;
  for (const ConfiguredComponent& part : c.components)
    if (part.role != OrderRole::MainBody && part.side == side)
      parts.push_back(&part);
  if (!c.configured || parts.empty() || c.components.empty())
    return std::nullopt;
  const double tol = c.deploymentToleranceMm;
  double chosen = tol;
  for (const ConfiguredComponent* part : parts)
  {
    HoldRange h;
    h.aboveMm = part->holdsAboveMm;
    h.belowMm = part->holdsBelowMm;
    h.aboveLimit = part->holdsAboveLimit;
    h.belowLimit = part->holdsBelowLimit;
    chosen = std::min(chosen, h.Narrowest());
  }
  chosen = std::max(0.0, chosen);
  if (chosen >= tol - SameMarginMm)
    return std::nullopt;
  const CatalogueComponent& body = c.components.front().item;
  const bool ipsilateral = side == c.ipsilateralSide;
  const std::vector<SideOption> options =
    LimbOptions(family, ipsilateral ? OrderRole::IpsilateralLimb : OrderRole::ContralateralLimb, side,
                body.flowDividerMm, ipsilateral ? body.lengthMm : body.gateEndMm, parts.back()->item.distalDiameterMm,
                c.landingLowMm[std::size_t(side)], c.landingHighMm[std::size_t(side)], tol, true);
  const SideOption* best = nullptr;
  for (const SideOption& o : options)
    if (o.landing == Landing::InWindow && o.margin > chosen + SameMarginMm &&
        (!best || o.margin > best->margin + SameMarginMm ||
         (o.margin > best->margin - SameMarginMm && o.parts.size() < best->parts.size())))
      best = &o;
  if (!best)
    return std::nullopt;
  const auto names = [](const auto& list, const auto& order)
  {
    std::string text;
    for (const auto& part : list)
      text += (text.empty() ? "" : " and ") + order(part);
    return text;
  };
  const std::string mine = names(parts, [](const ConfiguredComponent* p) { return p->OrderText(); });
  const std::string theirs = names(best->parts, [](const ConfiguredComponent& p) { return p.OrderText(); });
  const std::string name = std::string(SideName(side)) + " side";
  return SizeAlternative{ name, mine, theirs,
                          "the " + name + " would hold at least " + FormatNumber(best->margin) +
                            " mm up and down with " + theirs + ", where the " + mine + " holds " +
                            FormatNumber(chosen) + " mm (the narrowest range, up to the " + FormatNumber(tol) +
                            " mm deployment tolerance); the plan orders a single limb where one lands within a "
                            "length step of the ostium" };
}

} // namespace sgp
