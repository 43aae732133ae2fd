#include "IO/OutputTransaction.h"

#include <cstdio>
#include <random>
#include <system_error>

#include <filesystem>

#include "Common/Errors.h"

namespace sgp
{

namespace
{

/// Six random lower-case letters: no digits, which ITK's archetype readers could take for a
/// slice number.
std::string RandomTag()
{
  static std::mt19937 generator(std::random_device{}());
  std::uniform_int_distribution<int> letter(0, 25);
  std::string tag;
  for (int i = 0; i < 6; ++i)
  {
    tag += static_cast<char>('a' + letter(generator));
  }
  return tag;
}

} // namespace

OutputTransaction::~OutputTransaction()
{
  for (const auto& [staged, final] : m_Staged)
  {
    std::error_code ignored;
    std::filesystem::remove(staged, ignored);
  }
}

std::string OutputTransaction::Stage(const std::string& finalPath)
{
  const std::filesystem::path path(finalPath);
  const std::string name = path.filename().string();
  const auto dot = name.find('.', 1);
  const std::string stem = name.substr(0, dot);
  const std::string extensions = dot == std::string::npos ? std::string() : name.substr(dot);
  const std::string staged = (path.parent_path() / (stem + ".sgp-partial-" + RandomTag() + extensions)).string();
  m_Staged.emplace_back(staged, finalPath);
  return staged;
}

void OutputTransaction::Commit()
{
  std::vector<std::string> done;
  for (const auto& [staged, final] : m_Staged)
  {
    std::error_code error;
    std::filesystem::rename(staged, final, error);
    if (error)
    {
      for (const std::string& path : done)
      {
        std::error_code ignored;
        std::filesystem::remove(path, ignored);
      }
      throw InputError("Cannot move the output into place at '" + final + "': " + error.message() +
                       "; give a writable output path.");
    }
    done.push_back(final);
  }
  m_Staged.clear();
}

} // namespace sgp
