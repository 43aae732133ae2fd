/// \file AvtSupport.h
/// The AVT dataset's manual aortic-tree masks (../shared/data/avt, read at test time) as the
/// anatomy tests use them: each mask painted into a CT-like volume — lumen enhancement falling
/// from 400 HU at the top of the scan to 300 HU at its bottom (the bolus), soft tissue 40 HU,
/// noise σ 15 HU from std::mt19937(seed) — and the case's seed voxel.
#pragma once

#include <fstream>
#include <random>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>

#include "Common/ImageGeometry.h"
#include "Common/Types.h"

namespace sgp::testing
{

/// The mask file of case `caseName` (D1 … D4).
inline std::string AvtMaskPath(const std::string& caseName)
{
  return std::string(SGP_SHARED_DIR) + "/data/avt/avt_dongyang_" + caseName + ".seg.nrrd";
}

/// The case's seed voxel (seeds.json).
inline itk::Index<3> AvtSeed(const std::string& caseName)
{
  std::ifstream in(std::string(SGP_SHARED_DIR) + "/data/avt/seeds.json");
  std::stringstream text;
  text << in.rdbuf();
  const std::string json = text.str();
  const auto at = json.find("\"" + caseName + "\"");
  std::smatch match;
  const std::string rest = json.substr(at == std::string::npos ? json.size() : at);
  if (!std::regex_search(rest, match, std::regex(R"("seed_ijk"\s*:\s*\[\s*(\d+)\s*,\s*(\d+)\s*,\s*(\d+))")))
    throw std::runtime_error("no seed for " + caseName + " in " + std::string(SGP_SHARED_DIR) + "/data/avt/seeds.json");
  return { { std::stol(match[1]), std::stol(match[2]), std::stol(match[3]) } };
}

/// The mask painted into a CT-like volume (the file comment).
inline CtImage::Pointer PaintAvtCt(const LabelImage& mask, unsigned seed)
{
  auto ct = CtImage::New();
  ct->CopyInformation(&mask);
  ct->SetRegions(mask.GetLargestPossibleRegion());
  ct->Allocate();
  const auto size = mask.GetLargestPossibleRegion().GetSize();
  const auto bounds = ImageBoundsLps(mask);
  std::mt19937 generator(seed);
  std::normal_distribution<double> noise(0.0, 15.0);
  long flat = 0;
  for (long k = 0; k < long(size[2]); ++k)
  {
    const double z = IndexToLps(mask, { { 0, 0, k } }).z();
    const double lumenHu = 300.0 + 100.0 * (z - bounds[4]) / (bounds[5] - bounds[4]);
    for (long j = 0; j < long(size[1]); ++j)
      for (long i = 0; i < long(size[0]); ++i, ++flat)
        ct->GetBufferPointer()[flat] =
          static_cast<short>(std::lround((mask.GetBufferPointer()[flat] ? lumenHu : 40.0) + noise(generator)));
  }
  return ct;
}

} // namespace sgp::testing
