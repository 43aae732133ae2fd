#include "WriteReturnParameters.h"

#include <cstdio>
#include <fstream>

#include "../Errors.h"

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
  std::ofstream out(path);
  for (const auto& [name, value] : values)
  {
    out << name << " = " << value << "\n";
  }
  out.close();
  if (!out)
  {
    throw InputError("Cannot write the return-parameter file '" + path + "'; give a writable path.");
  }
}

} // namespace sgp
