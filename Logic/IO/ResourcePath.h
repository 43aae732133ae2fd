/// \file ResourcePath.h
/// Where the CLIs find the resources installed beside them (devices.json,
/// hostile-neck-rules.json): CMake copies Resources/<file> beside the executables in the build
/// tree and on install.
#pragma once

#include <string>

namespace sgp
{

/// <directory of /proc/self/exe, or of `argv0` made absolute when that cannot be read>/`fileName`.
/// Not checked for existence (the reader reports a missing file).
std::string BesideExecutable(const std::string& argv0, const std::string& fileName);

} // namespace sgp
