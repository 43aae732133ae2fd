/// \file SyntheticAorticPhantomParameters.h
/// Copies SyntheticAorticPhantom's parsed XML parameters into PhantomParams (the CLI edge).
#pragma once

#include <vector>

#include "Phantom/AorticPhantom.h"

namespace sgp
{

/// \throws InputError when a vector parameter has the wrong number of components (spacing 3,
///         direction 9, size 3), naming it; ranges are checked by ValidatePhantomParams.
PhantomParams MakePhantomParams(const std::vector<double>& spacingMm,
                                const std::vector<double>& directionLps,
                                const std::vector<int>& sizeVoxels);

} // namespace sgp
