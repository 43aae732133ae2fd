/// \file SelectDevice.h
/// Device selection for EVAR: per catalogue family, the main body and limbs that give the
/// wanted oversizing, the IFU check of the measured anatomy, and the recommended device.
///
/// **Sizing.** Every diameter below is on the wall the family's catalogue entry names
/// (`diameterReference`: outer wall for every shipped family; SizingAnatomy::On). Where the outer
/// wall was not traced at a sizing level (no fat around the vessel there) but the lumen was
/// measured, that level is sized on the lumen and the family's sizes are an estimate
/// (`estimatedFromLumen`): every check that reads such a value is indeterminate rather than pass
/// or fail — the IFU states the outer wall, which was not measured.
/// Oversizing = (device diameter / vessel diameter − 1) × 100 %. For each family the
/// main body is the catalogue size whose oversizing of the proximal neck diameter is nearest the
/// target — the middle of [proximalOversizingMinPercent, proximalOversizingMaxPercent] (15 % by
/// default) — among the sizes inside that range (limits inclusive, to 1e-9 %); a tie goes to the
/// smaller size. Each limb is chosen likewise for its common iliac diameter within the limb
/// range (target 17.5 % by default). No size inside the range: none is chosen, and the sizing
/// check fails naming the nearest size.
///
/// **IFU check** (evar-sizing.md §2.5), each a CriterionCheck (pass / fail / indeterminate when
/// a measurement it needs is NaN, with signed margin), in this order and with these names:
///   "main body oversizing", "neck diameter", "neck diameter 15 mm below" (the IFU range holds
///   along the seal zone), "neck length" (the tier admitting β; with β unmeasured it passes
///   above every tier, fails below every tier, else is indeterminate; and indeterminate when its
///   margin lies within ±proximalNeckLengthUncertaintyMm of the limit), "neck angle β" (≤ the
///   largest tier angle), "neck angle α" (only for families that limit it), then per side
///   ("right …", "left …"): "iliac diameter", "limb oversizing", "iliac seal length"; then
///   "main-body access" (the main body goes up the side with the wider access vessel: its
///   minimum diameter ≥ profile / 3 mm, with the chosen body's profile or, with none chosen,
///   the family's largest), "contralateral access" (the other side, the contralateral limb's
///   profile or the largest limb profile), and "proximal site to bifurcation" (≥ the shortest
///   main body length to the flow divider; only for families whose catalogue gives it).
///
/// **Recommendation.** Among families with no failing check and a chosen main body (a family
/// whose main body could not be sized — its diameter not measured — has nothing to implant and is
/// never recommended; `reasons` says so), those whose configuration meets every constraint come
/// first (when configured: see SelectDevice below), then those with no indeterminate check; within
/// that group the family whose main-body oversizing is nearest the target (ties in catalogue
/// order). None: "no device within IFU" when a family failed a check, "no device sized" when none
/// could be judged, and `reasons` lists every failing check of every family. A forced device (--device
/// "Family" or "Family:diameter") is the only family evaluated and is the recommendation, its
/// main body that diameter (its oversizing check fails if outside the range), flagged when it
/// is outside IFU.
///
/// Inputs: SizingAnatomy (mm, degrees; NaN = not measured), DeviceCatalog (validated),
/// DeviceSelectionParams. Output: DeviceSelection. Pure: no I/O, deterministic.
/// \throws InputError for parameters out of range (ValidateDeviceSelectionParams), a negative,
///         zero or infinite measurement (ValidateSizingAnatomy), an invalid catalogue
///         (ValidateDeviceCatalog), or a forced device that the catalogue does not hold (the
///         message names the catalogue and lists the families or sizes it does hold), or a
///         configuration the catalogue cannot resolve (ResolveGivenConfiguration) or place
///         (ConfigureGivenDevice).
#pragma once

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "Device/ConfigureDevice.h"
#include "Device/CriterionCheck.h"
#include "Device/GivenConfiguration.h"
#include "Device/DeviceCatalog.h"
#include "Measurement/MeasureAnatomy.h"

namespace sgp
{

/// The measurements that sizing needs. The four sizing diameters come on both walls: outer wall
/// to outer wall (the fields without "Lumen") and lumen to lumen; each family is sized on the
/// one its catalogue entry names (DeviceFamily::diameterReference, through On()). Each NaN when
/// not measured.
struct SizingAnatomy
{
  static constexpr double NotMeasured = std::numeric_limits<double>::quiet_NaN();
  double proximalNeckDiameterMm = NotMeasured;            ///< (a) outer wall at the proximal implantation site, > 0
  double neckDiameter15mmMm = NotMeasured;                ///< (b) outer wall 15 mm below it, > 0
  double proximalNeckLumenDiameterMm = NotMeasured;       ///< (a) lumen, > 0
  double neckLumenDiameter15mmMm = NotMeasured;           ///< (b) lumen, > 0
  double rightIliacLumenDiameterMm = NotMeasured;         ///< (e) lumen, > 0
  double leftIliacLumenDiameterMm = NotMeasured;          ///< (f) lumen, > 0
  double proximalNeckLengthMm = NotMeasured;              ///< from the lowest renal to the aneurysm onset, ≥ 0
  double neckAngleBetaDeg = NotMeasured;                  ///< infrarenal neck vs aneurysm long axis, [0, 180]
  double neckAngleAlphaDeg = NotMeasured;                 ///< suprarenal aorta vs neck axis, [0, 180]
  double rightIliacDiameterMm = NotMeasured;              ///< (e) outer wall, common iliac at the limb's seal, > 0
  double leftIliacDiameterMm = NotMeasured;               ///< (f) outer wall, > 0
  double rightIliacSealLengthMm = NotMeasured;            ///< common iliac length available for the seal, ≥ 0
  double leftIliacSealLengthMm = NotMeasured;             ///< ≥ 0
  double rightAccessMinDiameterMm = NotMeasured;          ///< minimum external iliac lumen diameter, > 0
  double leftAccessMinDiameterMm = NotMeasured;           ///< > 0
  double rightIliacTortuosity = NotMeasured;              ///< centerline / chord length, > 0 (1 = straight)
  double leftIliacTortuosity = NotMeasured;               ///< > 0
  double proximalSiteToBifurcationLengthMm = NotMeasured; ///< along the centerline, ≥ 0
  /// How far the measured neck length may lie from the true one, mm (≥ 0; 0 for an exact
  /// input): a neck-length margin within it is indeterminate — neither pass nor fail.
  double proximalNeckLengthUncertaintyMm = 0.0;
  /// A copy whose four sizing diameters (the fields without "Lumen") are those on `reference`.
  /// On the outer wall, a diameter whose outer value was not measured (no outer wall traced at
  /// that level) but whose lumen value was takes the lumen's, and `estimatedFromLumen` names it
  /// ("(a)", "(b)", "(e)", "(f)"): sized on the lumen, estimated.
  SizingAnatomy On(DiameterReference reference) const;
  /// The levels whose sizing diameter On() took from the lumen because the outer wall was not
  /// traced there (empty on the wall the family names, or when every outer value was measured).
  std::vector<std::string> estimatedFromLumen;
};

struct DeviceSelectionParams
{
  double proximalOversizingMinPercent = 10.0; ///< in [0, 100], ≤ max
  double proximalOversizingMaxPercent = 20.0; ///< in [0, 100]
  double limbOversizingMinPercent = 10.0;     ///< in [0, 100], ≤ max
  double limbOversizingMaxPercent = 25.0;     ///< in [0, 100]
  /// Empty: evaluate every family. "Family" (case-insensitive) or "Family:diameter" (mm, one of
  /// the family's main-body diameters to within 0.05 mm).
  std::string forcedDevice;
  /// The side the main body goes up (ChooseIpsilateralSide): its access check and configuration.
  IpsilateralSide ipsilateralSide = IpsilateralSide::Auto;
  /// How far a component may land from its plan, mm (≥ 0): the limbs are placed with this margin
  /// where their landing window allows (ConfigureDevice, LimbOptions.h).
  double deploymentToleranceMm = DeploymentToleranceMm;
  /// The surgeon's configuration (GivenConfiguration.h): when set, its family is the only one
  /// evaluated and is the recommendation (as forced), its main body and given limbs the sizes the
  /// IFU checks judge, its main-body side (when given) the ipsilateral side, and its configuration
  /// exactly what it gives (ConfigureGivenDevice). Resolved against the catalogue by SelectDevice.
  std::optional<GivenConfiguration> configuration;
};

/// One chosen catalogue size, or none.
struct SizeChoice
{
  double diameterMm = std::numeric_limits<double>::quiet_NaN(); ///< NaN: none chosen
  double oversizingPercent = std::numeric_limits<double>::quiet_NaN();
  double profileFr = std::numeric_limits<double>::quiet_NaN();
  bool forced = false;
  std::string reason; ///< why none was chosen; empty when one was
  bool Chosen() const { return !std::isnan(diameterMm); }
};

struct FamilyEvaluation
{
  std::string family;   ///< the catalogue's name
  int catalogIndex = 0; ///< index into DeviceCatalog::families
  SizeChoice mainBody;
  SizeChoice rightLimb;
  SizeChoice leftLimb;
  std::string mainBodyAccessSide; ///< "right" or "left" (ChooseIpsilateralSide)
  SideChoice ipsilateral;         ///< the same as a side index, with the reason
  std::vector<CriterionCheck> checks;
  /// The levels sized on the lumen because the outer wall was not traced there (SizingAnatomy::On);
  /// non-empty: every size of this family is an estimate, "estimated (lumen)".
  std::vector<std::string> estimatedFromLumen;
  /// The components with their lengths (ConfigureDevice), when SelectDevice was given the lengths
  /// and a main body was chosen; else not configured, with the reason.
  DeviceConfiguration configuration;
  int Count(CheckStatus status) const;
  bool WithinIfu() const { return Count(CheckStatus::Fail) == 0; }
  /// A check failed on a measured value: "fail"; else an indeterminate check (a value not
  /// measured, within its uncertainty, or sized on the lumen): "indeterminate"; else "pass".
  CheckStatus IfuStatus() const;
  bool EstimatedOnLumen() const { return !estimatedFromLumen.empty(); }
};

struct DeviceSelection
{
  std::vector<FamilyEvaluation> families; ///< catalogue order; only the forced one when forced
  int recommended = -1;                   ///< index into `families`; −1: no device within IFU
  bool forced = false;
  bool given = false; ///< forced by a configuration the surgeon gave (DeviceSelectionParams::configuration)
  bool recommendedWithinIfu = false;    ///< no failing check
  bool recommendedFullyChecked = false; ///< and no indeterminate check
  /// The IFU result: the recommended family's IfuStatus(); with no recommendation, "fail" when every
  /// family failed a check on measured values, else "indeterminate" (no family could be judged).
  CheckStatus ifuStatus = CheckStatus::Indeterminate;
  double proximalTargetPercent = 0.0;
  double limbTargetPercent = 0.0;
  /// One line, e.g. "Endurant II: main body 25 mm (13.6 %), right limb 16 mm (14.3 %), left
  /// limb 16 mm (14.3 %); within IFU", or "no device within IFU".
  std::string summary;
  /// No recommendation: every failing check of every family ("<family>: <check text>"). A
  /// recommendation outside IFU or not fully checked: its failing and indeterminate checks.
  std::vector<std::string> reasons;
};

/// The sizing inputs from the measurement stage (MeasureAnatomy.h; outer and lumen diameters): (a), (b),
/// neck length with its uncertainty (NeckLengthUncertaintyMm), β, α, (e), (f), access minimum
/// diameters, site to bifurcation; each iliac's seal length is its common iliac length,
/// bifurcation to internal iliac origin — the most a limb can seal in. A value the stage could
/// not measure stays NaN.
SizingAnatomy SizingFromMeasurements(const Measurements& measurements);

/// (deviceDiameterMm / vesselDiameterMm − 1) × 100.
double OversizingPercent(double deviceDiameterMm, double vesselDiameterMm);

/// The size of `sizes` (ascending) nearest the middle of [minPercent, maxPercent] among those
/// inside it, as described above; `vesselDiameterMm` NaN or no size inside: none, with reason.
SizeChoice ChooseDeviceSize(const std::vector<DeviceSize>& sizes,
                            double vesselDiameterMm,
                            double minPercent,
                            double maxPercent);

/// \throws InputError "<name> is <value> %; expected 0.0 to 100.0 %." or min > max.
void ValidateDeviceSelectionParams(const DeviceSelectionParams& params);

/// \throws InputError "<field> is <value> <unit>; expected …" for a measurement that is not NaN
///         and not in its documented range.
void ValidateSizingAnatomy(const SizingAnatomy& anatomy);

/// See the file comment. With `lengths`, every family whose main body was chosen is also
/// configured (ConfigureDevice: the lengths from `lengths`, the ipsilateral side from
/// `params.ipsilateralSide`), and the recommendation prefers, before the rest of its ranking, a
/// family whose configuration has every constraint met, then one with failed constraints (it can
/// be ordered; its findings name the options), then one that could not be configured (lengths
/// unknown: nothing to order).
DeviceSelection SelectDevice(const SizingAnatomy& anatomy,
                             const DeviceCatalog& catalog,
                             const DeviceSelectionParams& params = {},
                             const ConfigurationAnatomy* lengths = nullptr);

/// Where the uncertainty of a measured diameter ((a) for the main body, (e)/(f) for the limbs;
/// LumenDiameterUncertaintyMm or OuterDiameterUncertaintyMm by the wall the family sizes on)
/// straddles a size boundary of `family`: the size chosen at the value ± the uncertainty when it
/// differs from `evaluation`'s.
std::vector<SizeAlternative> DiameterAlternatives(const SizingAnatomy& anatomy,
                                                  const DeviceFamily& family,
                                                  const FamilyEvaluation& evaluation,
                                                  const DeviceSelectionParams& params);

} // namespace sgp
