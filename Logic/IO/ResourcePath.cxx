#include "IO/ResourcePath.h"

#include <filesystem>
#include <system_error>

namespace sgp
{

std::string BesideExecutable(const std::string& argv0, const std::string& fileName)
{
  std::error_code error;
  std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error)
    exe = std::filesystem::absolute(argv0, error);
  return (exe.parent_path() / fileName).string();
}

} // namespace sgp
