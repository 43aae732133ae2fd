/// \file ConfigurationLengths.h
/// The lengths a configuration is chosen from (ConfigurationAnatomy, ConfigureDevice.h), read off
/// the measurements and the labelled centerlines: every position along one side's path from the
/// deployment target — down the aortic centerline to the aortic bifurcation B, then along that
/// side's iliac centerline from B (the measured iliac lengths' convention: MeasureAnatomy.h).
///
///  - L_AB = B's abscissa − the target's (both along the aorta from its top);
///  - L_IIA per side = L_AB + the measured iliac length (B to the internal iliac origin), NaN where
///    no internal iliac was found;
///  - r_IIA per side: the internal iliac's inscribed radius, the median over 5–20 mm from its
///    start (nearer, the skeleton still runs in the merged cross-section and reads the common
///    iliac's radius); NaN without a labelled internal iliac;
///  - the internal iliac ostium per side: L_AB + the iliac's start beyond B + the upstream edge of
///    the internal iliac's ostium on the iliac's centerline (FindBranchOstium), NaN when not located;
///  - the flow divider per side: L_AB + the iliac's start beyond B + the divider's projection on
///    that iliac's centerline + its uncertainty (FlowDivider.h: its lowest position, so that no
///    seal is overstated), NaN when not found;
///  - the iliac end per side: L_AB + the iliac centerline's length beyond B;
///  - the aortic profile: each trunk ring's abscissa − the target's and its smallest lumen diameter;
///  - (d) on the outer wall where it was traced, else on the lumen.
///
/// Input: CenterlineTree and Measurements (LPS mm), the target's abscissa along the aorta (mm).
/// Output: ConfigurationAnatomy, mm; the iliac diameters are left NaN (the family's wall decides).
/// No errors: what was not measured stays NaN.
#pragma once

#include "Centerlines/Centerlines.h"
#include "Device/ConfigureDevice.h"
#include "Measurement/MeasureAnatomy.h"

namespace sgp
{

ConfigurationAnatomy ConfigurationLengths(const CenterlineTree& tree,
                                          const Measurements& measurements,
                                          double targetAbscissaMm);

/// The internal iliac's radius near its origin as described above (`side` 0 right, 1 left), mm;
/// NaN without one.
double InternalIliacRadiusMm(const CenterlineTree& tree, int side);

} // namespace sgp
