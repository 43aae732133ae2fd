#include "IO/WriteReturnParameters.h"

#include "IO/WriteTextFile.h"

namespace sgp
{

void WriteReturnParameters(const ReturnValues& values, const std::string& path)
{
  std::string text;
  for (const auto& [name, value] : values)
    text += name + " = " + value + "\n";
  WriteTextFile(text, path, "the return-parameter file");
}

} // namespace sgp
