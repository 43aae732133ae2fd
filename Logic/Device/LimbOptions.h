/// \file LimbOptions.h
/// The ways one side of a modular configuration can be completed from the main body's gate or
/// ipsilateral leg (ConfigureDevice.h): one limb, or a limb and an iliac extension, each inserted
/// within the family's overlap window — and where, within that window, each part is placed so that
/// the configuration still holds when it is deployed a few millimetres from its plan (issue 47).
///
/// **Positions** are mm along the side's path from the deployment target (ConfigureDevice.h).
/// A side's landing window is [W_lo, W_hi]: the distal edge at least the family's minimum iliac
/// seal below where the seal starts, at most the internal iliac ostium's upper edge.
///
/// **How far a part may land from its plan** (its hold range, predicted from the configuration's
/// own figures), displaced alone along its vessel while every other component stays:
///  - the part that lands (the side's last): below by W_hi − its distal edge (then it covers the
///    internal iliac ostium) or by its overlap − the family's minimum (its junction comes apart),
///    whichever is less; above by its distal edge − W_lo (the iliac seal falls under the minimum) —
///    unless its overlap reaches the window's upper end first (the top of the gate or leg it goes
///    into: it is stopped there, it cannot land higher, and that direction is safe);
///  - a limb with an extension below it: below by its overlap − the minimum, unless the extension
///    is stopped at its own window's top in it first; above by the extension's overlap − the
///    minimum, unless the limb is stopped at its window's top first.
/// **Placement with a margin**: within the overlap windows each part sits where the narrowest of
/// these ranges that end in a failure (a stop does not count), capped at the deployment tolerance
/// T, is widest; among such placements the lowest distal edge (the longest seal). With T = 0 this
/// is the highest edge not past W_hi, as before the margin (a limb then ends exactly at the ostium:
/// 0 mm below holds). A side that cannot land in its window keeps the rule without margin: the
/// highest edge not past W_hi.
///
/// Input: the family (validated), mm throughout. Output: SideOption values. Pure, deterministic.
/// Errors: none.
#pragma once

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "Device/ConfigureDevice.h"
#include "Device/GivenConfiguration.h"

namespace sgp
{

/// Two distal edges this close land at the same place (the seal is measured to 0.1 mm).
constexpr double SameEdgeMm = 1.0;

/// Where a side's limbs land, and how it went.
enum class Landing
{
  InWindow = 0, ///< W_lo ≤ distal edge ≤ W_hi
  Short = 1,    ///< below W_lo: the seal is shorter than the family's minimum
  Covers = 2    ///< beyond W_hi: the internal iliac's ostium is covered
};

/// How far a part may land above and below its plan, mm (negative: it already breaks a constraint
/// there), and what limits each: "covers", "seal", "overlap" (failures) or "stop" (it cannot go
/// further that way).
struct HoldRange
{
  double aboveMm = std::numeric_limits<double>::infinity();
  double belowMm = std::numeric_limits<double>::infinity();
  std::string aboveLimit, belowLimit;
  /// The narrower range that ends in a failure (∞ when both end at a stop).
  double Narrowest() const
  {
    const double inf = std::numeric_limits<double>::infinity();
    const double above = aboveLimit == "stop" ? inf : aboveMm, below = belowLimit == "stop" ? inf : belowMm;
    return above < below ? above : below;
  }
};

/// One way of completing a side from the gate or leg the main body ends it with.
struct SideOption
{
  std::vector<ConfiguredComponent> parts; ///< limb, extension (none: the body's own leg lands)
  std::vector<double> overlapMm;          ///< per part, its overlap in what it is inserted into
  std::vector<double> overlapMaxMm;       ///< per part, the window's upper end
  std::vector<HoldRange> holds;           ///< per part (the body's own leg: one, for the leg's end)
  double distalMm = std::numeric_limits<double>::quiet_NaN();
  Landing landing = Landing::Short;
  /// The narrowest hold range of its parts, capped at the tolerance it was placed for (0 when not
  /// in its window), mm.
  double margin = 0.0;
};

/// Landing of a distal edge in [lo, hi].
Landing Classify(double distal, double lo, double hi);

/// `item` placed from `proximalMm` on `side`'s path.
ConfiguredComponent Place(OrderRole role, const CatalogueComponent& item, int side, double proximalMm);

/// The ways to complete a side whose main body ends at `stubEndMm` (gate end or ipsilateral leg
/// end) with an insertable stretch from `stubStartMm` (the flow divider): one limb, or — only when
/// no single limb lands in the window within the length step of W_hi (the largest gap between this
/// diameter's limb lengths) — also a limb and an extension, each placed as the file comment says
/// for the deployment tolerance `toleranceMm` (≥ 0); with `everyCombination`, the limbs with an
/// extension too, whatever the single limbs reach.
std::vector<SideOption> LimbOptions(const DeviceFamily& family,
                                    OrderRole role,
                                    int side,
                                    double stubStartMm,
                                    double stubEndMm,
                                    double landingDiameterMm,
                                    double lo,
                                    double hi,
                                    double toleranceMm,
                                    bool everyCombination = false);

/// The side completed with the surgeon's `limb` (given) and `extension` (given or not), each at its
/// given position (GivenConfiguration.h: an overlap, or the last part's distal edge above the
/// internal iliac ostium, i.e. `hi` − that) or, where none is given, placed for the tolerance as
/// the file comment says — whatever the landing diameter; its holds measured against the family's
/// overlap windows (an overlap given outside them: a negative range). \throws InputError naming the
/// component's entry when a position leaves a part not inserted at all (overlap ≤ 0: it cannot
/// reach its gate, leg or limb) or deeper than what it goes into allows.
SideOption GivenSideOption(const DeviceFamily& family,
                           OrderRole role,
                           int side,
                           double stubStartMm,
                           double stubEndMm,
                           const ResolvedComponent& limb,
                           const ResolvedComponent& extension,
                           double lo,
                           double hi,
                           double toleranceMm);

/// The body's own leg landing on its side (its end at `legEndMm`), with its hold range.
SideOption BodyLegOption(double legEndMm, double lo, double hi, double toleranceMm);

/// Another way to complete `side` of `c` (configured by the plan) whose narrowest hold range,
/// capped at the tolerance, is wider by more than SameMarginMm than the side's own when that is
/// under the tolerance: among every single limb of the side's landing diameter and every limb with
/// an extension (LimbOptions with everyCombination) that lands in the window, the widest, then the
/// one with fewer parts; with the sentence that names it. nullopt when none is wider.
std::optional<SizeAlternative> MarginAlternative(const DeviceFamily& family, const DeviceConfiguration& c, int side);

/// One side's best option (`bodyAlone`, when given, is the body's own leg landing there): in its
/// window first, then the widest margin (to 0.1 mm), then the lowest edge not past W_hi (within
/// SameEdgeMm the fewer components), or the least covering.
std::optional<SideOption> BestSide(std::vector<SideOption> options, const std::optional<SideOption>& bodyAlone);

} // namespace sgp
