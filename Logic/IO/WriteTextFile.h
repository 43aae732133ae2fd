/// \file WriteTextFile.h
/// Writes a text file in one go (JSON reports, markups, return parameters).
/// \throws InputError "Cannot write <what> '<path>'; <hint>" when it cannot be written.
#pragma once

#include <string>

namespace sgp
{

void WriteTextFile(const std::string& text,
                   const std::string& path,
                   const std::string& what,
                   const std::string& hint = "give a writable path.");

} // namespace sgp
