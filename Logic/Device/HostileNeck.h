/// \file HostileNeck.h
/// The hostile-neck rule engine: a configurable rule set tested against the neck's outer-wall
/// quantities, one pass / fail / indeterminate verdict per rule with its signed margin.
///
/// There is no consensus definition of a hostile neck (vessel-wall.md §3.2): length < 10–15 mm,
/// diameter > 28 mm, angulation > 60°, thrombus or calcium over ≥ 50 % of the circumference,
/// reverse taper > 2 mm within 10 mm or ≥ 2 mm over 15 mm. So the engine hard-codes none of them:
/// each rule names one quantity, a threshold, which side of it is hostile, and its source. The
/// bundled set is Resources/hostile-neck-rules.json (read by IO/ReadNeckRules.h); this file holds
/// no I/O.
///
/// **Quantities** (NeckQuantities(); all measured on the outer wall by the caller, in planes
/// perpendicular to the centerline, NaN = not measured):
///   neckLength           mm   ≥ 0       proximal site to the aneurysm onset
///   neckDiameter         mm   > 0       (a), outer wall to outer wall at the proximal site
///   neckAngleBeta        deg  0–180     infrarenal neck vs aneurysm long axis
///   neckAngleAlpha       deg  0–180     suprarenal aorta vs neck axis
///   neckThrombusArc      %    0–100     circumference share with thrombus > 2 mm thick (largest, site to 15 mm)
///   neckCalcificationArc %    0–100     circumference share calcified (largest, site to 15 mm)
///   reverseTaper10mm     mm   any       D_out 10 mm below the site − (a); positive = widening downward
///   reverseTaper15mm     mm   any       the same 15 mm below the site
/// A rule's threshold must be finite and lie in its quantity's range (a negative threshold is
/// meaningful for the tapers only), and its unit must be the quantity's.
///
/// **Comparisons** (HostileWhen): Below (value < threshold is hostile), AtOrBelow (≤), Above (>),
/// AtOrAbove (≥). Whether the threshold itself is hostile follows the cited definition's "<"/"≤"
/// or ">"/"≥": the "At…" forms make it hostile, the others do not.
///
/// **Conventions.** Pass = not hostile by that rule, Fail = hostile, Indeterminate = not
/// decidable. Each rule gives one CriterionCheck (CriterionCheck.h) in rule order: `name` is the
/// rule's id, `requirement` the not-hostile side ("≥ 15 mm", "< 50 %"), `min`/`max` the threshold
/// on that side (unlike the catalogue's limits these are exclusive for the "At…" forms),
/// `evidence` the rule's source, and the signed `margin` is in the rule's unit, positive on the
/// not-hostile side: value − threshold for Below/AtOrBelow, threshold − value for
/// Above/AtOrAbove. A margin of exactly 0 passes Below/Above and fails AtOrBelow/AtOrAbove. A
/// NaN quantity is indeterminate with a NaN margin. A neck-length rule whose margin lies within
/// ±neckLengthUncertaintyMm is indeterminate and keeps its margin (as SelectDevice's neck-length
/// check; MeasureAnatomy.h NeckLengthUncertaintyMm). Texts read like
///   "neck length 12.0 mm, needs ≥ 15 mm: −3.0 mm"
///   "neck thrombus arc 50.0 %, needs < 50 %: +0.0 % (the threshold itself is hostile)"
///
/// **Aggregate.** `hostile`: at least one rule fails. `determinate`: no rule is indeterminate.
/// A neck with no failing rule but some indeterminate ones is not hostile and not determinate
/// ("undetermined"), and the summary names the undecided rules.
///
/// \throws InputError (one line, naming the rule file, the rule as "rules[i] \"id\"" and the
///         field, the value seen and what was expected) from ValidateNeckRuleSet: no rules; an
///         empty or repeated id (case-insensitive); a quantity the engine does not know; a unit
///         other than the quantity's; a non-finite threshold or one outside the quantity's
///         range; an empty source. AssessNeck validates the rule set (with its `origin`) and the
///         anatomy (ValidateNeckAnatomy: a quantity that is not NaN and outside its range, or a
///         negative or non-finite uncertainty).
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "Device/CriterionCheck.h"

namespace sgp
{

/// Which side of the threshold is hostile.
enum class HostileWhen
{
  Below,     ///< value < threshold
  AtOrBelow, ///< value ≤ threshold
  Above,     ///< value > threshold
  AtOrAbove  ///< value ≥ threshold
};

/// "below", "atOrBelow", "above", "atOrAbove" (the rule file's spelling).
const char* ToString(HostileWhen when);

/// The comparison spelled `text` (exactly, case-sensitive), or none.
std::optional<HostileWhen> HostileWhenFromString(const std::string& text);

/// The neck quantities, NaN when not measured (see the table above for units and ranges).
struct NeckAnatomy
{
  static constexpr double NotMeasured = std::numeric_limits<double>::quiet_NaN();
  double neckLengthMm = NotMeasured;
  double neckDiameterMm = NotMeasured; ///< (a), outer wall
  double neckAngleBetaDeg = NotMeasured;
  double neckAngleAlphaDeg = NotMeasured;
  double neckThrombusArcPercent = NotMeasured;
  double neckCalcificationArcPercent = NotMeasured;
  double reverseTaper10mmMm = NotMeasured; ///< D_out(site + 10 mm) − (a), mm
  double reverseTaper15mmMm = NotMeasured; ///< D_out(site + 15 mm) − (a), mm
  /// How far the measured neck length may lie from the true one, mm (≥ 0, finite; 0 for an exact
  /// input): a neck-length margin within it is indeterminate.
  double neckLengthUncertaintyMm = 0.0;
};

/// One quantity the engine knows, with its unit and range (inclusive unless stated).
struct NeckQuantity
{
  const char* name;           ///< the rule file's spelling, e.g. "neckLength"
  const char* unit;           ///< "mm", "deg" or "%"
  const char* label;          ///< opens a check's text, e.g. "neck length"
  double min;                 ///< smallest admissible value (−inf: none)
  double max;                 ///< largest admissible value (+inf: none)
  bool minExclusive;          ///< true: the value must exceed `min` (a diameter > 0)
  double NeckAnatomy::*field; ///< where NeckAnatomy holds it
};

/// The eight quantities, in the order of the table above.
const std::vector<NeckQuantity>& NeckQuantities();

/// The quantity named `name` (exactly), or nullptr.
const NeckQuantity* FindNeckQuantity(const std::string& name);

struct NeckRule
{
  std::string id;       ///< unique in its set (case-insensitive), e.g. "short-neck"
  std::string quantity; ///< one of NeckQuantities()
  HostileWhen hostileWhen = HostileWhen::Above;
  double threshold = std::numeric_limits<double>::quiet_NaN(); ///< in `unit`; finite, in the quantity's range
  std::string unit;                                            ///< the quantity's unit
  std::string description;                                     ///< one sentence, may be empty
  std::string source; ///< the publication (and evidence mark) the threshold comes from; not empty
};

struct NeckRuleSet
{
  std::string name;            ///< the set's own label, e.g. "StentGraftPlanner default hostile-neck rules"
  std::string origin;          ///< where it came from (a file path), named in messages
  std::vector<NeckRule> rules; ///< at least one
};

struct NeckAssessment
{
  std::vector<CriterionCheck> checks; ///< one per rule, in rule order
  bool hostile = false;               ///< some rule fails
  bool determinate = true;            ///< no rule is indeterminate
  /// One line: "hostile neck: fails short-neck, neck-thrombus (2 of 8 rules of '<name>')", "not
  /// hostile: passes all 8 rules of '<name>'" or "undetermined: no rule fails, 7 of 8 rules of
  /// '<name>' pass"; then, when some rule is indeterminate, "; indeterminate: <ids>". <name> is
  /// the set's name, or its origin when the name is empty.
  std::string summary;
  int Count(CheckStatus status) const;
};

/// "Hostile-neck rules '<origin>'[, rules[<index>][ \"<id>\"]], field '<field>'": the opening of
/// every rule-file message (index < 0: the file's top level; id empty: the index alone).
std::string DescribeNeckRuleField(const std::string& origin,
                                  int index,
                                  const std::string& id,
                                  const std::string& field);

/// Checks the semantic rules above; `file` names the set in messages.
/// \throws InputError as described in the file comment.
void ValidateNeckRuleSet(const NeckRuleSet& rules, const std::string& file);

/// \throws InputError "Neck anatomy: <field> is <value> <unit>; expected …" for a quantity that is
///         not NaN and outside its range, or an uncertainty that is negative or not finite.
void ValidateNeckAnatomy(const NeckAnatomy& anatomy);

/// One check per rule, the aggregate and the summary, as described above. Pure, deterministic.
NeckAssessment AssessNeck(const NeckAnatomy& anatomy, const NeckRuleSet& rules);

} // namespace sgp
