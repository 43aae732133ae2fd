#include "IO/WriteTextFile.h"

#include <fstream>

#include "Common/Errors.h"

namespace sgp
{

void WriteTextFile(const std::string& text, const std::string& path, const std::string& what, const std::string& hint)
{
  std::ofstream out(path);
  out << text;
  out.close();
  if (!out)
    throw InputError("Cannot write " + what + " '" + path + "'; " + hint);
}

} // namespace sgp
