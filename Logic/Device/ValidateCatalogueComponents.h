/// \file ValidateCatalogueComponents.h
/// The component rules of ValidateDeviceCatalog (DeviceCatalog.h lists them) for one family:
/// codes, diameters, lengths, profiles, a main body's flow divider and gate within its length,
/// conflicts, the junctions' overlap and gate clearance, and the selection's sizes consistent
/// with the components.
///
/// Input: a catalogue and the index of one of its families (LPS-free plain data, mm and Fr).
/// \throws InputError "<DescribeCatalogComponentField(…) or DescribeCatalogField(…)>: <value
///         seen>; expected <rule>; correct the entry." for the first broken rule.
#pragma once

#include "Device/DeviceCatalog.h"

namespace sgp
{

void ValidateCatalogueComponents(const DeviceCatalog& catalog, int familyIndex);

} // namespace sgp
