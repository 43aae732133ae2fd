#include "IO/ReadTextFile.h"

#include <fstream>
#include <sstream>

#include "Common/Errors.h"

namespace sgp
{

std::string ReadTextFile(const std::string& path, const std::string& what, const std::string& hint)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in)
    throw InputError("Cannot read the " + what + " '" + path +
                     "': the file does not exist or is not readable; give the path of " + hint + ".");
  return text.str();
}

} // namespace sgp
