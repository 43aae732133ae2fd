/// \file DeviceCatalog.h
/// The stent-graft device catalogue as plain data, and its semantic validation.
///
/// A catalogue lists bifurcated EVAR device families (Endurant II, Excluder, …): every component
/// that can be ordered — main bodies, limbs, iliac extensions, aortic cuffs — with its catalogue
/// code (where public), diameters, covered length and delivery profile, and for main bodies the
/// flow divider's and the contralateral gate's distance from the proximal fabric edge, the gate's
/// diameter and the crotch width; the overlap the family needs between components and the gate's
/// clearance above the aortic bifurcation; and the anatomical criteria of the family's
/// instructions for use (IFU). The shipped catalogue, `Resources/devices.json`, holds public
/// figures from `shared/reference/evar-sizing.md` §2.1–2.2 and `device-configuration.md` §1; it is
/// user-editable, every family says `verified: false` until someone reads the manufacturer's
/// current sizing table, and a figure no public source gave is NaN here (null in the file): the
/// configuration then reports what depends on it as unknown. Reading the file is the I/O room's
/// job (IO/ReadDeviceCatalog.h); this file holds no I/O.
///
/// Component geometry (mm, along the graft from its proximal fabric edge): a main body's
/// `lengthMm` is its covered length to the ipsilateral leg's distal end, `flowDividerMm` where its
/// two lumens part, `gateEndMm` where the contralateral gate (the short leg a contralateral limb is
/// inserted into) ends; so the gate stub is gateEnd − flowDivider long and a limb can overlap in
/// it by at most that. A limb's or extension's `diameterMm` is its proximal end (the part inside
/// the gate or leg it is inserted into), `distalDiameterMm` its landing end.
///
/// Units: diameters and lengths in mm (IFU diameters are outer wall to outer wall), angles in
/// degrees, delivery profiles in French (outer diameter in mm = Fr / 3). A NaN limit means "no
/// such criterion" for this family.
///
/// Angles: β is the angle between the infrarenal neck and the aneurysm's long axis (the one most
/// IFUs limit), α the angle between the suprarenal aorta and the neck (Zenith limits it too).
///
/// The neck-length criterion may depend on β: a list of tiers (minimum length, largest β it
/// admits), e.g. Endurant II ≥ 10 mm when β ≤ 60° and ≥ 15 mm when β ≤ 75°. The family's
/// largest admissible β is the largest tier angle. Limits are inclusive (≥, ≤) even where an IFU
/// writes "<" or ">": measurement repeatability (≈ 6° for angles) is far coarser than the
/// difference.
#pragma once

#include <limits>
#include <string>
#include <vector>

namespace sgp
{

/// One orderable size of a main body (proximal diameter) or of a limb (distal diameter).
struct DeviceSize
{
  double diameterMm = 0.0; ///< nominal diameter, mm (> 0)
  double profileFr = 0.0;  ///< delivery system outer diameter, French (> 0; mm = Fr / 3)
};

/// What a catalogue component is for.
enum class ComponentRole
{
  MainBody,       ///< bifurcated trunk with its ipsilateral leg and contralateral gate
  Limb,           ///< iliac limb (contralateral or ipsilateral leg)
  IliacExtension, ///< extends a limb distally
  AorticCuff      ///< extends the main body proximally
};

/// "mainBody", "limb", "iliacExtension", "aorticCuff" (the report's role names).
const char* ToString(ComponentRole role);
/// "mainBodies", "limbs", "iliacExtensions", "aorticCuffs" (the catalogue's group keys).
const char* GroupKey(ComponentRole role);

/// A figure the sources disagree on: every value they give (the component's own is the chosen
/// one, and must be among them) and a note naming the sources.
struct FigureConflict
{
  std::string field; ///< the component field, e.g. "lengthMm"
  std::vector<double> values;
  std::string note;
};

/// One orderable component. NaN: not found in any public source (null in the file).
struct CatalogueComponent
{
  static constexpr double Unknown = std::numeric_limits<double>::quiet_NaN();
  ComponentRole role = ComponentRole::Limb;
  int index = 0;                     ///< position within its role's group in the catalogue ("items[index]")
  std::string name;                  ///< the product line, e.g. "Endurant II bifurcated main body"
  std::string code;                  ///< catalogue code; empty when it is not public
  double diameterMm = Unknown;       ///< proximal end, mm (> 0; required for a main body)
  double distalDiameterMm = Unknown; ///< distal end (a main body's ipsilateral leg), mm (> 0; required for a limb)
  double lengthMm = Unknown;         ///< covered length, mm (> 0)
  double profileFr = Unknown;        ///< delivery system, French (> 0, required)
  double flowDividerMm = Unknown;    ///< main bodies: proximal edge to the flow divider, mm
  double gateEndMm = Unknown;        ///< main bodies: proximal edge to the contralateral gate's end, mm
  double gateDiameterMm = Unknown;   ///< main bodies: the contralateral gate, mm
  double crotchWidthMm = Unknown;    ///< main bodies: both lumens side by side at the flow divider, mm
  std::string evidence;              ///< its own, else its group's
  std::string note;
  std::vector<FigureConflict> conflicts;

  /// A main body whose covered length, flow divider and gate end are all known.
  bool GeometryKnown() const;
  /// "mainBodies.items[3] ETBF2313C124E" (or without the code when it is not public).
  std::string Label() const;
  /// The code, or "(code not public)".
  std::string CodeText() const;
};

/// The main bodies or the limbs of one family, as the selection sizes them.
struct DeviceComponent
{
  std::vector<DeviceSize> sizes; ///< at least one, diameters strictly ascending
  /// Shortest and longest available length, mm; NaN when the catalogue does not list lengths.
  double lengthMinMm = std::numeric_limits<double>::quiet_NaN();
  double lengthMaxMm = std::numeric_limits<double>::quiet_NaN();
  /// Main bodies only (empty for limbs and when unknown): the lengths from the proximal edge to
  /// the flow divider, mm, ascending.
  std::vector<double> lengthToFlowDividerMm;
  std::string evidence; ///< source / evidence mark of these figures
};

/// Minimum neck length admitted up to a neck angle β.
struct NeckLengthTier
{
  double minLengthMm = 0.0; ///< > 0
  double maxBetaDeg = 0.0;  ///< in (0, 180]
};

/// A numeric IFU limit: [min, max], either side NaN when unbounded.
struct IfuLimit
{
  double min = std::numeric_limits<double>::quiet_NaN();
  double max = std::numeric_limits<double>::quiet_NaN();
  std::string evidence;
};

/// The overlap a family needs where one component is inserted into another (limb in the gate or
/// the ipsilateral leg, extension in a limb), mm, and how far above the aortic bifurcation the
/// contralateral gate must open to be cannulated, mm. NaN: not found.
struct ComponentJunctions
{
  IfuLimit overlapMm;       ///< min and max (each NaN when not found)
  IfuLimit gateClearanceMm; ///< min (NaN when not found)
};

/// A family's IFU anatomical criteria.
struct DeviceIfu
{
  /// At least one tier, β strictly ascending and lengths non-decreasing (a steeper neck never
  /// needs a shorter seal).
  std::vector<NeckLengthTier> neckLengthTiers;
  std::string neckLengthEvidence;
  IfuLimit neckDiameterMm;    ///< both bounds, mm
  IfuLimit neckAngleAlphaDeg; ///< max only, degrees; both NaN when the IFU does not limit α
  IfuLimit iliacSealLengthMm; ///< min only, mm
  IfuLimit iliacDiameterMm;   ///< both bounds, mm
};

/// Which diameter a family's IFU ranges (neck, iliac) and oversizing are stated on.
enum class DiameterReference
{
  OuterWall, ///< outer wall to outer wall (every IFU of the shipped catalogue)
  Lumen      ///< lumen to lumen
};

/// "outerWall" / "lumen", the catalogue's spelling.
const char* ToString(DiameterReference reference);

struct DeviceFamily
{
  std::string name;         ///< unique in the catalogue, non-empty, without ':'
  std::string manufacturer; ///< may be empty
  std::string source;       ///< where the figures come from; non-empty
  std::string note;         ///< "verify against the current IFU"
  /// The diameter its ranges use (catalogue field "diameterReference", required): sizing, the IFU
  /// diameter checks and the limb choice use the anatomy's diameters on that wall.
  DiameterReference diameterReference = DiameterReference::OuterWall;
  /// false until someone has read the manufacturer's current sizing table (catalogue field
  /// "verified", required); reports say so beside every figure of an unverified family.
  bool verified = false;
  /// The selection's view: main-body proximal diameters and limb distal diameters with their
  /// largest delivery profile, lengths and flow-divider positions, derived from `components` by
  /// the reader (a catalogue built in memory may give them alone, without components).
  DeviceComponent mainBodies;
  DeviceComponent limbs;
  /// Every orderable component, grouped by role in the order mainBody, limb, iliacExtension,
  /// aorticCuff (empty: the catalogue gives diameters only, so nothing can be configured).
  std::vector<CatalogueComponent> components;
  ComponentJunctions junctions;
  DeviceIfu ifu;
  /// The components of `role`, in catalogue order.
  std::vector<const CatalogueComponent*> ComponentsOf(ComponentRole role) const;
};

struct DeviceCatalog
{
  /// Where the catalogue came from (a path, or a description); error messages name it.
  std::string origin;
  int formatVersion = 2;
  std::vector<DeviceFamily> families; ///< in catalogue order (ties in selection follow it)
};

/// The catalogue format version this code reads (2: every component listed; 1 listed diameters
/// only).
constexpr int DeviceCatalogFormatVersion = 2;

/// "Device catalogue '<origin>', families[<index>] \"<name>\", field '<field>'" — the opening
/// of every message about one field of one entry (also used by the reader). An empty name is
/// left out; index < 0 names the top level.
std::string DescribeCatalogField(const std::string& origin,
                                 int familyIndex,
                                 const std::string& familyName,
                                 const std::string& field);

/// "Device catalogue '<origin>', families[<index>] \"<name>\", component <Label()>, field
/// '<field>'" — the opening of every message about one field of one component.
std::string DescribeCatalogComponentField(const std::string& origin,
                                          int familyIndex,
                                          const std::string& familyName,
                                          const CatalogueComponent& component,
                                          const std::string& field);

/// The selection's sizes from the components: the main bodies' proximal diameters and the limbs'
/// distal diameters, ascending, each with the largest profile of its components, the length range
/// and the known flow-divider positions; evidence from the first component of each role. Leaves a
/// family without components as it is.
void DeriveSizesFromComponents(DeviceFamily& family);

/// Checks the semantic rules listed on the structs above: at least one family; names non-empty,
/// unique (case-insensitively, as --device matches them) and without ':'; source non-empty;
/// sizes, lengths and profiles positive; diameters strictly ascending; every range min < max;
/// neck-length tiers as documented; angles in (0, 180]; the largest main body wider than the
/// largest IFU neck diameter and the largest limb wider than the largest IFU iliac diameter
/// (otherwise those necks or iliacs could not be sealed); flow-divider lengths only on main
/// bodies. Components (when given; the reader rejects a missing or empty code — null is "not
/// public", an empty code here): diameters, lengths and profile positive where known, a main body's diameter, a limb's
/// distal diameter and every profile known; a main body's flow divider before its gate end and both within its covered
/// length (a gate beyond the body's length), its gate narrower than the body; each conflict naming a component field
/// and listing the value chosen; the junctions' overlap min ≥ 0, max ≥ min, and the minimum overlap no longer than any
/// main body's gate stub (gateEnd − flowDivider: a limb could not be inserted that far); the gate clearance ≥ 0; and
/// the sizes consistent with the components (DeriveSizesFromComponents). \throws InputError "<DescribeCatalogField(…)>:
/// <value seen>; expected <rule>; correct the
///         entry." for the first broken rule.
void ValidateDeviceCatalog(const DeviceCatalog& catalog);

/// The family named `name` (case-insensitive, surrounding spaces ignored), or nullptr.
const DeviceFamily* FindDeviceFamily(const DeviceCatalog& catalog, const std::string& name);

/// The diameters of `sizes` for messages and reports: "23, 25, 28.5 mm".
std::string DiametersText(const std::vector<DeviceSize>& sizes);

/// A device forced by the user (the CLI's --device).
struct ForcedDevice
{
  int familyIndex = -1; ///< into DeviceCatalog::families
  /// One of the family's main-body diameters, mm (the catalogue's value); NaN: family only.
  double mainBodyDiameterMm = std::numeric_limits<double>::quiet_NaN();
};

/// A forced diameter matches a catalogue size within this, mm (sizes step by ≥ 0.5 mm).
constexpr double ForcedDiameterToleranceMm = 0.05;

/// Parses "Family" or "Family:diameter" (family as FindDeviceFamily matches it; the text after
/// the last ':' a diameter in mm).
/// 	hrows InputError "Forced device '<text>': no family '<name>' in the device catalogue
///         '<origin>'; expected one of: <families> …" or "…: '<diameter>' is not a main-body
///         diameter of <family> in the device catalogue '<origin>'; expected one of <sizes>."
ForcedDevice ParseForcedDevice(const std::string& text, const DeviceCatalog& catalog);

} // namespace sgp
