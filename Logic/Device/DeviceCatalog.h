/// \file DeviceCatalog.h
/// The stent-graft device catalogue as plain data, and its semantic validation.
///
/// A catalogue lists bifurcated EVAR device families (Endurant II, Excluder, …): the proximal
/// diameters of the main bodies and the diameters of the iliac limbs that can be ordered, each
/// with its delivery profile, and the anatomical criteria of the family's instructions for use
/// (IFU). The shipped catalogue, `Resources/devices.json`, holds public figures from
/// `shared/reference/evar-sizing.md` §2.1–2.2; it is user-editable and every figure must be
/// verified against the current IFU. Reading the file is the I/O room's job
/// (IO/ReadDeviceCatalog.h); this file holds no I/O.
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

/// The main bodies or the limbs of one family.
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
  DeviceComponent mainBodies;
  DeviceComponent limbs;
  DeviceIfu ifu;
};

struct DeviceCatalog
{
  /// Where the catalogue came from (a path, or a description); error messages name it.
  std::string origin;
  int formatVersion = 1;
  std::vector<DeviceFamily> families; ///< in catalogue order (ties in selection follow it)
};

/// The catalogue format version this code reads.
constexpr int DeviceCatalogFormatVersion = 1;

/// "Device catalogue '<origin>', families[<index>] \"<name>\", field '<field>'" — the opening
/// of every message about one field of one entry (also used by the reader). An empty name is
/// left out; index < 0 names the top level.
std::string DescribeCatalogField(const std::string& origin,
                                 int familyIndex,
                                 const std::string& familyName,
                                 const std::string& field);

/// Checks the semantic rules listed on the structs above: at least one family; names non-empty,
/// unique (case-insensitively, as --device matches them) and without ':'; source non-empty;
/// sizes, lengths and profiles positive; diameters strictly ascending; every range min < max;
/// neck-length tiers as documented; angles in (0, 180]; the largest main body wider than the
/// largest IFU neck diameter and the largest limb wider than the largest IFU iliac diameter
/// (otherwise those necks or iliacs could not be sealed); flow-divider lengths only on main
/// bodies.
/// \throws InputError "<DescribeCatalogField(…)>: <value seen>; expected <rule>; correct the
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
