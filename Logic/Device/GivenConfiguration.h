/// \file GivenConfiguration.h
/// A configuration given by the surgeon (the CLI's --configuration, issue 47): the family, the side
/// the main body goes up, each component by catalogue code or by diameters and length, and where
/// wanted its position — and its resolution against the device catalogue into the components the
/// plan then simulates exactly (ConfigureGivenDevice, ConfigureDevice.h). The file format is the
/// I/O room's (IO/ReadConfiguration.h); this file holds no I/O.
///
/// **Components** are named by their catalogue role ("mainBody", "limb", "iliacExtension") and,
/// for a limb or an extension, the patient's side it goes down. A limb on the main body's side is
/// its ipsilateral limb, the other its contralateral limb: changing the main body's side alone
/// swaps the limbs' roles. Exactly one main body; per side at most one limb and one extension
/// (an extension only below a limb). A side given no component is completed by the plan's own
/// rule (LimbOptions.h) — or by the main body's own leg where that is what the rule picks.
///
/// **Positions**, each optional (not given: the plan places the component with its margin rule):
///  - the main body's proximal fabric edge, mm below the lower edge of the lowest renal ostium
///    along the aorta (the proximal site; negative: above it), in [−30, 60] as --deploymentOffsetMm;
///  - a limb's or extension's overlap in what it is inserted into (gate, ipsilateral leg, limb), mm,
///    > 0 (a limb that does not overlap cannot reach its gate);
///  - or, for the last component on its side, its distal edge above the internal iliac ostium's
///    upper edge (the landing window's lower end, ConfigureDevice.h), mm (negative: it covers the
///    ostium by that much).
///
/// Units mm; sides 0 right, 1 left. Errors: InputError, one line naming the entry ("components[2]"),
/// the value seen and what the catalogue offers.
#pragma once

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "Device/DeviceCatalog.h"

namespace sgp
{

/// One component as the surgeon gave it (before resolution). NaN: not given.
struct GivenComponent
{
  static constexpr double NotGiven = std::numeric_limits<double>::quiet_NaN();
  std::string where; ///< for messages: "components[2]"
  ComponentRole role = ComponentRole::Limb;
  int side = -1; ///< limbs and extensions: 0 right, 1 left; −1 for the main body
  std::string code;
  double diameterMm = NotGiven;       ///< proximal, mm
  double distalDiameterMm = NotGiven; ///< distal, mm
  double lengthMm = NotGiven;         ///< covered length, mm
  /// Positions (see the file comment), mm.
  double proximalEdgeBelowLowestRenalMm = NotGiven; ///< main body only
  double overlapMm = NotGiven;                      ///< limbs and extensions
  double distalEdgeAboveInternalIliacMm = NotGiven; ///< the last component on its side
};

/// The surgeon's configuration as read.
struct GivenConfiguration
{
  std::string origin; ///< where it came from (a path), for messages
  std::string family;
  int mainBodySide = -1; ///< 0 right, 1 left; −1: the plan's choice (ChooseIpsilateralSide)
  /// No ipsilateral limb: the main body's own leg lands on its side (a family whose leg is long
  /// enough); no limb may then be given on the main body's side.
  bool bodyLegLandsAlone = false;
  std::vector<GivenComponent> components;
};

/// One resolved component: its catalogue entry and the position given (NaN: the plan's rule).
struct ResolvedComponent
{
  const CatalogueComponent* item = nullptr; ///< nullptr: not given
  std::string where;
  double overlapMm = GivenComponent::NotGiven;
  double distalEdgeAboveInternalIliacMm = GivenComponent::NotGiven;
  bool Given() const { return item != nullptr; }
};

/// The configuration resolved against the catalogue; pointers into the catalogue it was resolved
/// with (which must outlive it).
struct ResolvedConfiguration
{
  std::string origin;
  int familyIndex = -1; ///< into DeviceCatalog::families
  int mainBodySide = -1;
  bool bodyLegLandsAlone = false;
  ResolvedComponent mainBody;
  double proximalEdgeBelowLowestRenalMm = GivenComponent::NotGiven;
  std::array<ResolvedComponent, 2> limb;      ///< per side
  std::array<ResolvedComponent, 2> extension; ///< per side
};

/// The role names a configuration file uses: ToString(ComponentRole) ("mainBody", "limb",
/// "iliacExtension"); \throws InputError for "aorticCuff" (not simulated yet) and any other text.
ComponentRole ParseGivenRole(const std::string& text, const std::string& where);

/// Resolves `given` against `catalog` (validated): the family by name (FindDeviceFamily), each
/// component by its code (exactly, case-insensitive) or by the diameters and length given (each
/// within ForcedDiameterToleranceMm; exactly one match). \throws InputError naming the entry and
/// what the catalogue offers for an unknown family; a code not in the family, or one of another
/// role ("ETTF2828C049E is an aortic cuff, not a limb"); a size that matches none (the lengths or
/// diameters the family makes) or several (their codes); no main body or two; two limbs or two
/// extensions on one side; an extension on a side with no limb; a position on the wrong role,
/// both positions on one component, an overlap ≤ 0, a distal edge on a component that is not its
/// side's last, or a main-body position outside [−30, 60] mm.
ResolvedConfiguration ResolveGivenConfiguration(const GivenConfiguration& given, const DeviceCatalog& catalog);

struct DeviceConfiguration;

/// A configuration as the surgeon would give it (what --outputConfiguration writes): its family,
/// main-body side, every component by code (by diameters and length where the code is not
/// public), the main body at `proximalEdgeBelowLowestRenalMm`, each limb and extension at its
/// overlap; `bodyLegLandsAlone` when no ipsilateral limb is ordered. Given back
/// (ResolveGivenConfiguration, ConfigureGivenDevice) on the same anatomy it is the same
/// configuration. `origin` left empty. Requires `configuration.configured`.
GivenConfiguration GivenFromConfiguration(const DeviceConfiguration& configuration,
                                          double proximalEdgeBelowLowestRenalMm);

} // namespace sgp
