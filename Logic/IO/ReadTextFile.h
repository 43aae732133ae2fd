/// \file ReadTextFile.h
/// Reads a whole text file (the JSON inputs: device catalogue, hostile-neck rules, configuration).
/// \throws InputError "Cannot read the <what> '<path>': the file does not exist or is not readable;
///         give the path of <hint>." when it cannot be read.
#pragma once

#include <string>

namespace sgp
{

std::string ReadTextFile(const std::string& path, const std::string& what, const std::string& hint);

} // namespace sgp
