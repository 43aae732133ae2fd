#include "SyntheticAorticPhantomParameters.h"

#include "Common/Errors.h"

namespace sgp
{

PhantomParams MakePhantomParams(const std::vector<double>& spacingMm,
                                const std::vector<double>& directionLps,
                                const std::vector<int>& sizeVoxels)
{
  const auto count = [](const char* name, std::size_t got, std::size_t expected)
  {
    if (got != expected)
    {
      throw InputError(std::string(name) + " has " + std::to_string(got) + " values; expected " +
                       std::to_string(expected) + ".");
    }
  };
  count("spacingMm", spacingMm.size(), 3);
  count("directionLps", directionLps.size(), 9);
  count("sizeVoxels", sizeVoxels.size(), 3);
  PhantomParams p;
  for (int a = 0; a < 3; ++a)
  {
    p.spacingMm[a] = spacingMm[a];
    p.sizeVoxels[a] = sizeVoxels[a];
    for (int r = 0; r < 3; ++r)
    {
      p.directionLps(r, a) = directionLps[3 * a + r];
    }
  }
  return p;
}

} // namespace sgp
