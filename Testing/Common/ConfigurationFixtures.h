// Shared by the configuration tests: the shipped catalogue, and anatomies given as path lengths.
#pragma once

#include <stdexcept>
#include <string>

#include "Device/ConfigureDevice.h"
#include "IO/ReadDeviceCatalog.h"

namespace sgp
{
namespace
{

/// Sums of catalogue figures are exact in double to far better than this, mm.
constexpr double ExactMm = 1e-9;

const DeviceCatalog& Shipped()
{
  static const DeviceCatalog catalog = ReadDeviceCatalog(SGP_DEVICES_JSON);
  return catalog;
}

const DeviceFamily& Family(const std::string& name)
{
  const DeviceFamily* family = FindDeviceFamily(Shipped(), name);
  if (!family)
    throw std::runtime_error("no family " + name);
  return *family;
}

/// A neck of 22 mm for 25 mm below the target, a 50 mm sac, a distal aorta of `distalAortaMm`
/// over its last 20 mm; common iliacs of the given lengths and diameter, internal iliacs of
/// radius 3 mm, 80 mm of external iliac beyond them.
ConfigurationAnatomy Anatomy(double toBifurcationMm,
                             double rightCommonIliacMm,
                             double leftCommonIliacMm,
                             double iliacDiameterMm = 14.0,
                             double distalAortaMm = 22.0)
{
  ConfigurationAnatomy a;
  a.targetToBifurcationMm = toBifurcationMm;
  a.targetToInternalIliacMm = { toBifurcationMm + rightCommonIliacMm, toBifurcationMm + leftCommonIliacMm };
  a.internalIliacRadiusMm = { 3.0, 3.0 };
  a.targetToIliacEndMm = { a.targetToInternalIliacMm[0] + 80.0, a.targetToInternalIliacMm[1] + 80.0 };
  a.iliacDiameterMm = { iliacDiameterMm, iliacDiameterMm };
  for (double s = 0.0; s <= toBifurcationMm; s += 4.0)
  {
    a.aortaProfileMm.push_back(s);
    a.aortaMinDiameterMm.push_back(s < 25.0 ? 22.0 : s > toBifurcationMm - 20.0 ? distalAortaMm : 50.0);
  }
  a.distalAorticDiameterMm = distalAortaMm;
  a.distalAorticWall = "outer wall";
  return a;
}

ChosenDiameters Chosen(double bodyMm, double limbMm)
{
  ChosenDiameters chosen;
  chosen.mainBodyMm = bodyMm;
  chosen.limbMm = { limbMm, limbMm };
  return chosen;
}

const SideChoice Right{ 0, "right, as asked" };

} // namespace
} // namespace sgp
