/// \file DeploymentTolerance.h
/// How far each component of a configuration may land from its planned position before the
/// simulated graft fails its fit check (issue 47): a graft lands a few millimetres from its plan —
/// limbs migrate (≥ 5 mm counts as migration), the achieved seal of one family fell a median 8 mm
/// short of the planned one (device-configuration.md §2) — and a plan that holds only where it was
/// planned is fragile.
///
/// **Displacement.** One component at a time is moved along its vessel by d mm (positive: down,
/// distally; negative: up, toward the proximal edge) while every other component stays where the
/// plan put it, so the overlaps it has follow (Displaced): the main body moves the deployment
/// target (its proximal edge, its flow divider and gate with it, the limbs stay in the iliacs); a
/// limb or extension moves its own ends. What is inserted into a moved component stays where it
/// was planned as far as its overlap window lets it: it moves only as much as keeps its overlap
/// within [min, max] (a limb is deployed to its gate's markers — pushed down by a gate that landed
/// low, drawn up by one that landed high, so its distal edge moves too). A component is not moved further up
/// than its own window's upper end allows (it is stopped there): a range that ends at such a stop
/// ends because the component cannot go further, not because the graft fails, and is never a
/// finding.
///
/// **Search.** For each component and direction, the largest displacement in [0, S] (S = twice
/// the tolerance, at least 5 mm) at which the simulated graft still passes, to `resolutionMm`,
/// found from the configuration's own prediction where it has one (ConfiguredComponent::holds…:
/// tried first, then one step beyond), else from the tolerance, by bisection. The fit check is
/// assumed to fail monotonically outward from the plan (a seal only shortens, an ostium only comes
/// nearer, as a component moves one way); the first finding beyond the range says why it fails.
///
/// **Findings**: a component whose range either way is narrower than the tolerance — except the
/// main body's upward range where an aortic ostium ends it: its proximal edge is placed at the
/// lowest renal ostium on purpose (the deployment's landmark on the angiogram), so that range is
/// stated as a note, not a failure.
///
/// Input: a configured DeviceConfiguration, the tolerance (mm, ≥ 0), and the simulation (a
/// callback that deploys a displaced configuration with the deployment target shifted by a given
/// mm and checks its fit on its own findings, not the configuration's). Output: per component, its
/// range, in mm at `resolutionMm`. Errors: InputError for a configuration that is not configured
/// or a negative tolerance; what the callback throws passes through.
/// Complexity: ≤ 2 + log2(S / resolution) simulations per component and direction (two where the
/// prediction is right within the resolution), on two cores.
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "Device/ConfigureDevice.h"

namespace sgp
{

/// A configuration with one component displaced, and how far the deployment target moves with it.
struct Displacement
{
  DeviceConfiguration configuration;
  double targetShiftMm = 0.0; ///< along the aorta, down positive (the main body's displacement)
};

/// `c` with component `index` moved `mm` along its vessel (down positive), what is inserted into it
/// kept within its overlap window (see the file comment), the overlaps, covered
/// lengths, seals and margins recomputed; for the main body every other path position moves by
/// −mm (paths are measured from the deployment target, which moves +mm).
/// \throws InputError for an index out of range or a configuration that is not configured.
Displacement Displaced(const DeviceConfiguration& c, std::size_t index, double mm);

/// What one displaced simulation found.
struct DisplacedCheck
{
  bool passed = false;
  std::string why;           ///< the fit check's first finding ("" when it passed)
  bool aorticOstium = false; ///< it covers (or may cover) an ostium on the aorta
};

using CheckDisplacement = std::function<DisplacedCheck(const DeviceConfiguration&, double targetShiftMm)>;

/// One component's range.
struct ComponentHold
{
  std::size_t component = 0; ///< index into the configuration's components
  std::string name;          ///< "main body", "left contralateral limb", "right iliac extension"
  /// The largest displacement searched at which the graft still passes, above (up) and below
  /// (down) its planned position, mm (≥ 0).
  double aboveMm = 0.0, belowMm = 0.0;
  /// Beyond the range: why it fails ("" when it held to the search's end, `searchMm`, or to a stop).
  std::string aboveFails, belowFails;
  /// The range ends where the component is stopped (its overlap window's end), not at a failure.
  bool aboveStops = false, belowStops = false;
  bool aboveAtAorticOstium = false; ///< the main body's upward range ends at an aortic ostium
  std::string finding;              ///< its line in DeploymentTolerance::findings, or ""
  /// "holds from 3.0 mm above to 7.5 mm below its planned position (higher: …; lower: …)"; a range
  /// that held to the search's end "at least …", one that ends at a stop "… (as far as it goes)".
  std::string Text(double searchMm) const;
};

struct DeploymentTolerance
{
  bool assessed = false;
  std::string notAssessedReason; ///< when not: the planned graft does not pass, or nothing to move
  double toleranceMm = 0.0;
  double searchMm = 0.0;     ///< how far each direction was searched
  double resolutionMm = 0.5; ///< how finely
  std::vector<ComponentHold> components;
  std::vector<std::string> findings; ///< ranges narrower than the tolerance, one line each
  std::vector<std::string> notes;    ///< the main body's upward range at the renal ostium
  int simulations = 0;
};

/// See the file comment. `planned`: the check at the planned position where the caller has it
/// (nullptr: simulated first). The searches run on two threads at once: `check` must be safe to
/// call concurrently. `resolutionMm` > 0.
DeploymentTolerance AssessDeploymentTolerance(const DeviceConfiguration& configuration,
                                              double toleranceMm,
                                              const CheckDisplacement& check,
                                              const DisplacedCheck* planned = nullptr,
                                              double resolutionMm = 0.5);

} // namespace sgp
