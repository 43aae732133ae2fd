/// \file DeviceCatalogSupport.h
/// A small in-memory device catalogue with round numbers, so that the selection tests do not
/// depend on edits to the shipped Resources/devices.json:
///  - "TenMm": Endurant-like sizes (bodies 23, 25, 28, 32, 36 mm; 18 Fr up to 28, 20 Fr above;
///    limbs 10, 13, 16, 20, 24, 28 mm at 16 Fr), neck ≥ 10 mm with β ≤ 60°, ≥ 15 mm with
///    β ≤ 75°, neck 19–32 mm, iliac seal ≥ 15 mm, iliac 8–25 mm.
///  - "FifteenMm": Excluder-like sizes (bodies 23, 26, 28.5, 31, 35 mm at 18 Fr; limbs 12, 14.5,
///    16, 18, 20, 23, 27 mm at 16 Fr), neck ≥ 15 mm with β ≤ 60°, α ≤ 45°, neck 18–32 mm,
///    iliac seal ≥ 10 mm, iliac 7.5–25 mm, body 55 or 65 mm to the flow divider.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "Common/Errors.h"
#include "Device/DeviceCatalog.h"
#include "Device/SelectDevice.h"

namespace sgp::testing
{

inline DeviceCatalog MakeTestCatalog()
{
  DeviceCatalog catalog;
  catalog.origin = "test catalogue";
  DeviceFamily ten;
  ten.name = "TenMm";
  ten.source = "test";
  ten.mainBodies.sizes = { { 23, 18 }, { 25, 18 }, { 28, 18 }, { 32, 20 }, { 36, 20 } };
  ten.limbs.sizes = { { 10, 16 }, { 13, 16 }, { 16, 16 }, { 20, 16 }, { 24, 16 }, { 28, 16 } };
  ten.ifu.neckLengthTiers = { { 10, 60 }, { 15, 75 } };
  ten.ifu.neckDiameterMm = { 19, 32, "" };
  ten.ifu.iliacSealLengthMm.min = 15;
  ten.ifu.iliacDiameterMm = { 8, 25, "" };
  DeviceFamily fifteen;
  fifteen.name = "FifteenMm";
  fifteen.source = "test";
  fifteen.mainBodies.sizes = { { 23, 18 }, { 26, 18 }, { 28.5, 18 }, { 31, 18 }, { 35, 18 } };
  fifteen.mainBodies.lengthToFlowDividerMm = { 55, 65 };
  fifteen.limbs.sizes = { { 12, 16 }, { 14.5, 16 }, { 16, 16 }, { 18, 16 }, { 20, 16 }, { 23, 16 }, { 27, 16 } };
  fifteen.ifu.neckLengthTiers = { { 15, 60 } };
  fifteen.ifu.neckDiameterMm = { 18, 32, "" };
  fifteen.ifu.neckAngleAlphaDeg.max = 45;
  fifteen.ifu.iliacSealLengthMm.min = 10;
  fifteen.ifu.iliacDiameterMm = { 7.5, 25, "" };
  catalog.families = { ten, fifteen };
  return catalog;
}

/// An anatomy inside both test families' IFU with margin everywhere: neck 22 mm (TenMm 25 mm
/// body at 13.6 %, FifteenMm 26 mm at 18.2 %), iliacs 14 mm, ample lengths, 8/7 mm access.
inline SizingAnatomy MakeGoodAnatomy()
{
  SizingAnatomy a;
  a.proximalNeckDiameterMm = 22.0;
  a.neckDiameter15mmMm = 23.0;
  a.proximalNeckLengthMm = 25.0;
  a.neckAngleBetaDeg = 30.0;
  a.neckAngleAlphaDeg = 20.0;
  a.rightIliacDiameterMm = 14.0;
  a.leftIliacDiameterMm = 14.0;
  a.rightIliacSealLengthMm = 30.0;
  a.leftIliacSealLengthMm = 30.0;
  a.rightAccessMinDiameterMm = 8.0;
  a.leftAccessMinDiameterMm = 7.0;
  a.proximalSiteToBifurcationLengthMm = 110.0;
  return a;
}

/// Runs `f`, which must throw InputError with every one of `parts` in its one-line message.
inline void ExpectInputError(const std::function<void()>& f, const std::vector<std::string>& parts)
{
  try
  {
    f();
    ADD_FAILURE() << "no InputError; expected one naming " << parts.front();
  }
  catch (const InputError& e)
  {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    for (const std::string& part : parts)
      EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
  }
}

} // namespace sgp::testing
