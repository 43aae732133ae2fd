#include "WriteReturnParameters.h"

#include <cstdio>

#include "WriteTextFile.h"

namespace sgp
{

std::string FormatReturnValue(double value)
{
  char buffer[64];
  // + 0.0 turns a negative zero (a negated coordinate of 0) into "0" rather than "-0".
  std::snprintf(buffer, sizeof(buffer), "%.10g", value + 0.0);
  return buffer;
}

void WriteReturnParameters(const ReturnValues& values, const std::string& path)
{
  std::string text;
  for (const auto& [name, value] : values)
    text += name + " = " + value + "\n";
  WriteTextFile(text, path, "the return-parameter file");
}

} // namespace sgp
