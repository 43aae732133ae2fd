/// \file ConfigureDevice.h
/// The modular configuration a surgeon orders: for the family and the diameters the selection
/// chose, the main body (its length, so that its contralateral gate opens above the aortic
/// bifurcation and its crotch fits the distal aorta), each limb and, where needed, an iliac
/// extension (their lengths, so that each overlaps in its gate or leg within the family's range
/// and lands in the common iliac as low as the catalogue's lengths allow), and the order list
/// (device-configuration.md §1.4 and §2.1; Zenith Flex IFU p. 31: "from the lowest renal artery
/// to just above the internal iliac artery bifurcation").
///
/// **Paths.** Every position is a length in mm along one side's path from the deployment target
/// (the main body's proximal fabric edge): down the aortic centerline to the aortic bifurcation B,
/// then along that side's iliac centerline (the same convention as the measured iliac lengths).
/// So the main body runs on both paths from 0 — to its ipsilateral leg's end T on the ipsilateral
/// path, to its gate end g on the contralateral one —, a contralateral limb inserted `ov` into the
/// gate runs from g − ov to g − ov + L, and a side's covered length is its last component's
/// distal edge: exactly the components' lengths minus the overlaps.
///
/// **Rules**, per side (0 right, 1 left):
///  - the landing window: the distal edge at most W_hi = L_IIA − r_IIA (the internal iliac origin
///    less its ostium's radius), and never past the ostium's upper edge where it was located on the
///    common iliac's wall (targetToInternalIliacOstiumMm: the edge the fit check judges coverage
///    by), so the ostium stays uncovered; and at least W_lo = L_AB + the family's
///    minimum iliac seal; within the window the distal edge is placed with a margin for the
///    deployment tolerance (LimbOptions.h: where the narrowest of the part's hold ranges, capped at
///    the tolerance, is widest, then the lowest — the longest seal; with no tolerance the highest
///    reachable position ≤ W_hi); if none reaches W_lo the seal is short (a finding), and only if
///    every option passes W_hi is the internal iliac covered (a finding);
///  - overlaps: a limb in the gate overlaps in [ov_min, min(ov_max, g − f)], a limb in the
///    ipsilateral leg in [ov_min, min(ov_max, T − f)], an extension in a limb in [ov_min,
///    min(ov_max, L_limb)] (f: the flow divider; ov_min/ov_max the family's junction figures);
///    within that window the limb sits where its distal edge's placement needs;
///  - the gate: g ≤ L_AB − the family's gate clearance (the gate opens in the sac where it can be
///    cannulated); the crotch: the narrowest aortic lumen within ±10 mm of the flow divider at
///    least the body's crotch width; the limbs: where the distal aorta (d) is narrower than the
///    two limbs side by side (the sum of their diameters), limb compression — a finding when (d)
///    is extremely narrow (≤ 16 mm, the NAB study [S]; within the measurement's uncertainty of it,
///    as it cannot be excluded), a note when narrow (≤ 20 mm);
///  - the ipsilateral side: `ipsilateralSide` (the selection's main-body access side: the side with
///    the wider access vessel, then the less tortuous iliac; ChooseIpsilateralSide);
///  - the main body: every catalogue body of the chosen diameter (any ipsilateral-leg variant) is
///    tried with every way of completing both sides (the body's own leg, one limb, or a limb and one
///    extension); the configuration kept has the fewest failed constraints, then the fewest sides
///    outside their window, then the widest margin, then the lowest distal edges, then the fewest
///    components, then the body whose ipsilateral leg is nearest the landing (or the limb's)
///    diameter. (Precisely: failed constraints; then the sides' landings, in the window before
///    short before covering; then the gate's shortfall below its clearance; then the narrower
///    side's margin (its narrowest hold range capped at the tolerance) to 0.1 mm, wider first;
///    then components; then the distal edges' distance from W_hi to the mm; then the leg's
///    mismatch.)
///
/// **Sizes not chosen.** A side whose limb the selection could not size because the iliac is wider
/// than the widest limb allows is planned with the widest limb (a bell-bottom limb) and a finding
/// that names the option of an extension into the external iliac covering the internal iliac; one
/// narrower than the smallest limb allows, with the smallest limb and a finding.
///
/// **Unknown.** The configuration is not made — `configured` false, the reason in
/// `unknownReason`, never guessed — when the catalogue gives no main body of the chosen diameter
/// with its length, flow divider and gate end, no limb lengths of a needed diameter, or no
/// minimum overlap; or when a landmark is missing (B, an internal iliac origin).
///
/// **Alternatives**: where a measurement's stated uncertainty (DiameterUncertaintyMm for the
/// diameters, IliacLengthUncertaintyMm for the landing window) straddles a size boundary, the
/// size the other side of it (main body, each limb diameter; each limb or extension length).
/// And where a side's narrowest hold range is under the deployment tolerance while another way of
/// completing it would hold wider (a limb with an extension where a single limb lands within a
/// length step of the ostium: LimbOptions.h MarginAlternative), that way.
///
/// Input: the DeviceFamily (validated), the chosen diameters (mm; NaN where the selection chose
/// none), the ConfigurationAnatomy (mm). Output: DeviceConfiguration. Pure, deterministic.
/// Errors: none beyond InputError for a negative (or NaN) deployment tolerance: what cannot be configured is
/// a result (`configured` false), and what breaks a constraint is a finding.
/// Complexity: bodies × (limbs × extensions)² per side — a few thousand combinations.
#pragma once

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "Device/DeviceCatalog.h"

namespace sgp
{

/// How far a measured diameter may lie from the truth, mm: the accuracy the random-anatomy sweep
/// and the phantom tests hold (README "Accuracy": lumen within 1.0 mm, outer wall within 1.5 mm
/// on slices up to 1.25 mm). A size choice that would change within ± this is listed as an
/// alternative.
constexpr double LumenDiameterUncertaintyMm = 1.0;
constexpr double OuterDiameterUncertaintyMm = 1.5;
/// How far a measured length to an internal iliac origin may lie from the truth, mm (the bar the
/// landmark work holds the internal iliac origins to: within 3 mm).
constexpr double IliacLengthUncertaintyMm = 3.0;

/// Which side the main body goes up (its ipsilateral leg's side).
enum class IpsilateralSide
{
  Auto,  ///< the wider access vessel, then the less tortuous iliac
  Right, ///< the patient's right
  Left
};

/// "auto", "right", "left"; \throws InputError for any other text, naming `parameter`.
IpsilateralSide ParseIpsilateralSide(const std::string& text, const std::string& parameter);

/// The side (0 right, 1 left) and why: the given one, else the side whose access (minimum external
/// iliac diameter, mm) is wider by more than `toleranceMm`, else the less tortuous iliac (ratio,
/// by more than 0.05: paths differing by under 5 % of their length are alike), else the wider
/// access, else the right. NaN values are unknown and never win a comparison.
struct SideChoice
{
  int side = 0;
  std::string reason; ///< e.g. "wider access: right 8.2 mm, left 6.9 mm"
};
SideChoice ChooseIpsilateralSide(IpsilateralSide wanted,
                                 const std::array<double, 2>& accessDiameterMm,
                                 const std::array<double, 2>& tortuosity,
                                 double toleranceMm = LumenDiameterUncertaintyMm);

/// The anatomy the lengths are chosen from (path lengths from the deployment target, see the
/// file comment; NaN: not measured).
struct ConfigurationAnatomy
{
  static constexpr double NotMeasured = std::numeric_limits<double>::quiet_NaN();
  double targetToBifurcationMm = NotMeasured; ///< L_AB, > 0
  /// L_IIA per side: to the internal iliac origin along the path.
  std::array<double, 2> targetToInternalIliacMm{ NotMeasured, NotMeasured };
  /// r_IIA per side: the internal iliac's radius near its origin (its ostium's half width), mm.
  std::array<double, 2> internalIliacRadiusMm{ NotMeasured, NotMeasured };
  /// Per side, to the internal iliac ostium's upper edge on the common iliac's wall
  /// (FindBranchOstium: the edge the fit check judges coverage by), mm; NaN: not located.
  std::array<double, 2> targetToInternalIliacOstiumMm{ NotMeasured, NotMeasured };
  /// Per side, to the flow divider on that side's path (where the lumen divides and a limb starts
  /// to seal in the common iliac: FlowDivider.h), mm; NaN: not found.
  std::array<double, 2> targetToFlowDividerMm{ NotMeasured, NotMeasured };
  /// Where a side's iliac seal is measured from: the flow divider, or B where it was not found
  /// (never above B).
  double SealFromMm(int side) const;
  /// Per side, to the end of the iliac centerline in view (the external iliac), mm.
  std::array<double, 2> targetToIliacEndMm{ NotMeasured, NotMeasured };
  /// (e)/(f) on the family's wall (as sized), mm.
  std::array<double, 2> iliacDiameterMm{ NotMeasured, NotMeasured };
  /// The aortic lumen's profile from the target down: each ring's distance from the target (mm,
  /// ascending) and its smallest diameter (mm) — the crotch is compared with it.
  std::vector<double> aortaProfileMm;
  std::vector<double> aortaMinDiameterMm;
  /// (d): the narrowest distal aorta the two limbs pass side by side, mm, on `distalAorticWall`
  /// ("outer wall" where it was traced, else "lumen").
  double distalAorticDiameterMm = NotMeasured;
  std::string distalAorticWall = "lumen";
};

/// The roles the order list names (the report's `role`).
enum class OrderRole
{
  MainBody,
  IpsilateralLimb,
  ContralateralLimb,
  IliacExtension,
  AorticCuff
};

/// "mainBody", "ipsilateralLimb", "contralateralLimb", "iliacExtension", "aorticCuff".
const char* ToString(OrderRole role);

/// One ordered component where it is deployed.
struct ConfiguredComponent
{
  OrderRole role = OrderRole::MainBody;
  CatalogueComponent item; ///< the catalogue's entry (code, diameters, length, geometry)
  /// The path it runs along (0 right, 1 left); a main body runs on both, and is given on its
  /// ipsilateral side (its gate end on the other path is DeviceConfiguration::gateEndMm).
  int side = 0;
  double proximalMm = 0.0; ///< along the side's path from the deployment target
  double distalMm = 0.0;
  /// How far it may land above (toward the target) and below its planned position, displaced
  /// alone, before a constraint of the configuration breaks (LimbOptions.h: the iliac seal, the
  /// internal iliac ostium, its overlap), mm, and that constraint ("seal", "covers", "overlap"; or
  /// "stop": it cannot go further that way); NaN for the main body (its range needs the deployed
  /// graft: DeploymentTolerance.h).
  double holdsAboveMm = std::numeric_limits<double>::quiet_NaN();
  double holdsBelowMm = std::numeric_limits<double>::quiet_NaN();
  std::string holdsAboveLimit, holdsBelowLimit;
  /// "Endurant II bifurcated main body 28-16 × 145 mm" — diameters proximal-distal × length.
  std::string OrderText() const;
  /// Its role in words, with its side: "main body", "left contralateral limb", "right iliac extension".
  std::string RoleText() const;
  /// "holds if it lands up to 5.0 mm higher (then the left iliac seal falls under the minimum) or
  /// 5.0 mm lower (then it covers the left internal iliac ostium)"; a negative range as "none (…
  /// short)"; "" for the main body.
  std::string HoldsText() const;
};

/// One junction of two components.
struct ComponentOverlap
{
  std::string junction; ///< e.g. "left contralateral limb in the gate"
  int side = 0;
  int outer = 0; ///< index into DeviceConfiguration::components: the component inserted into
  int inner = 0; ///< the one inserted
  double overlapMm = 0.0;
  double minMm = std::numeric_limits<double>::quiet_NaN();
  double maxMm = std::numeric_limits<double>::quiet_NaN(); ///< the window's upper end used (≤ the stub or leg)
};

/// A constraint the configuration could not meet: the constraint, its numbers, and the option a
/// surgeon would weigh.
struct ConfigurationFinding
{
  std::string constraint; ///< stable key: "commonIliacTooShort", "iliacTooWide", "iliacTooNarrow", "iliacBetweenSizes",
                          ///< "gateBelowBifurcation", "crotchTooNarrow", "limbCompression",
                          ///< "internalIliacCovered", "iliacSealShort"
  int side = -1;          ///< 0 right, 1 left, −1 both / the aorta
  std::string text;       ///< the sentence, with its numbers (0.1 mm)
  std::string option;     ///< what a surgeon would weigh
};

/// A size the other side of a boundary a measurement's uncertainty straddles.
struct SizeAlternative
{
  std::string component; ///< "main body", "right limb", …
  std::string chosen;    ///< "28 mm", "124 mm"
  std::string alternative;
  std::string text; ///< the sentence: why
};

struct DeviceConfiguration
{
  std::string family;
  bool configured = false;
  std::string unknownReason; ///< why not, when not configured
  int ipsilateralSide = 0;
  std::string ipsilateralReason;
  std::vector<ConfiguredComponent> components; ///< main body first, then per side inward to outward
  std::vector<ComponentOverlap> overlaps;
  std::array<double, 2> coveredLengthMm{ 0.0, 0.0 };         ///< from the proximal edge to each side's distal edge
  std::array<double, 2> landingLowMm{ 0.0, 0.0 };            ///< W_lo per side
  std::array<double, 2> landingHighMm{ 0.0, 0.0 };           ///< W_hi per side
  std::array<double, 2> sealFromMm{ 0.0, 0.0 };              ///< per side: ConfigurationAnatomy::SealFromMm, mm
  std::array<double, 2> sealLengthMm{ 0.0, 0.0 };            ///< planned: distal edge − sealFromMm
  std::array<double, 2> marginToInternalIliacMm{ 0.0, 0.0 }; ///< W_hi − distal edge (≥ 0: ostium clear)
  double gateEndMm = 0.0;                                    ///< g along the contralateral path
  double gateClearanceMm = 0.0;                              ///< L_AB − g
  double flowDividerMm = 0.0;                                ///< f
  /// The deployment tolerance the limbs were placed for (LimbOptions.h), mm.
  double deploymentToleranceMm = 0.0;
  /// Given by the surgeon (ConfigureGivenDevice), not chosen by the plan.
  bool given = false;
  std::vector<ConfigurationFinding> findings;
  /// Remarks that do not fail the plan (a narrow but not extremely narrow distal aorta, a crotch
  /// or gate clearance the catalogue does not give).
  std::vector<std::string> notes;
  std::vector<SizeAlternative> alternatives;
  /// Configured and no constraint failed.
  bool Feasible() const { return configured && findings.empty(); }
  /// Each component as "name diameter × length" joined by "; " ("not configured: <reason>" when
  /// not configured).
  std::string OrderList() const;
  /// The component of `role` on `side` (−1: any), or nullptr.
  const ConfiguredComponent* Find(OrderRole role, int side = -1) const;
};

/// The chosen diameters, mm (NaN: not chosen), and the least limb oversizing the selection
/// accepted (%; a side with no limb chosen is "too wide" when even the widest limb is under it).
struct ChosenDiameters
{
  double mainBodyMm = std::numeric_limits<double>::quiet_NaN();
  std::array<double, 2> limbMm{ std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN() };
  double limbOversizingMinPercent = 10.0;
  double limbOversizingMaxPercent = 25.0;
};

/// How far a component may land from its planned position and the plan still hold, by default,
/// mm: the displacement that counts as a limb's migration (≥ 5 mm, device-configuration.md §2,
/// PMC11880382). The achieved seal of one family fell a median 8 mm short of the planned seal
/// (IQR −20.5 to +1), but that shortfall is mostly apposition, not position; 5 mm is what a
/// deployment that lands "where planned" can still miss by.
constexpr double DeploymentToleranceMm = 5.0;

/// See the file comment. `ipsilateralSide` is 0 (right) or 1 (left), with its `reason`; the limbs
/// are placed with a margin for `deploymentToleranceMm` (≥ 0; LimbOptions.h).
DeviceConfiguration ConfigureDevice(const DeviceFamily& family,
                                    const ChosenDiameters& chosen,
                                    const ConfigurationAnatomy& anatomy,
                                    const SideChoice& ipsilateral,
                                    double deploymentToleranceMm = DeploymentToleranceMm);

struct ResolvedConfiguration;

/// The surgeon's configuration (GivenConfiguration.h) on this anatomy: exactly its main body on
/// its side (`ipsilateral`: the given side, or the plan's choice), each side it gives with exactly
/// its limb and extension at the positions it gives (the others placed by the rule, LimbOptions.h),
/// each side it leaves out completed by the rule; judged by the same constraints, with the given
/// sides' findings phrased for what was given and an overlap outside the family's window a finding
/// ("overlapShort", "overlapLong"). `given` was resolved against the catalogue holding `family`;
/// `chosen` gives the diameters the sides left out land with. `given` true, no alternatives.
/// \throws InputError for a negative tolerance, or a given position a part cannot take
/// (GivenSideOption).
DeviceConfiguration ConfigureGivenDevice(const DeviceFamily& family,
                                         const ResolvedConfiguration& given,
                                         const ChosenDiameters& chosen,
                                         const ConfigurationAnatomy& anatomy,
                                         const SideChoice& ipsilateral,
                                         double deploymentToleranceMm = DeploymentToleranceMm);

} // namespace sgp
