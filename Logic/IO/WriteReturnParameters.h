/// \file WriteReturnParameters.h
/// Writes SEM return parameters: one `name = value` line each, the format Slicer reads from the
/// `--returnparameterfile` path after a successful run (slicer-conventions.md §2.5).
///
/// \param values  (name, value) pairs; names are the XML `<name>`s, values already formatted
///                (vectors comma-separated, booleans `true`/`false`)
/// \throws InputError naming the path when it cannot be written.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "Common/Format.h" // FormatReturnValue, for the callers that format the values

namespace sgp
{

using ReturnValues = std::vector<std::pair<std::string, std::string>>;

void WriteReturnParameters(const ReturnValues& values, const std::string& path);

} // namespace sgp
