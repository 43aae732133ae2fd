/// \file CropSupport.h
/// Scans whose field of view ends earlier: the slices of an axis-aligned CT (identity direction, z
/// superior) above or below an LPS height, with the geometry of the original.
#pragma once

#include <algorithm>
#include <cmath>

#include "Common/Types.h"

namespace sgp::testing
{

/// Slices `first` … `first + count − 1` of `ct` (the phantom's grid is axis-aligned, z up): a scan
/// whose field of view ends there.
inline CtImage::Pointer CropSlices(const CtImage& ct, itk::SizeValueType first, itk::SizeValueType count)
{
  const auto size = ct.GetLargestPossibleRegion().GetSize();
  count = std::min(count, size[2] - first);
  auto crop = CtImage::New();
  crop->CopyInformation(&ct);
  auto origin = ct.GetOrigin();
  origin[2] += double(first) * ct.GetSpacing()[2];
  crop->SetOrigin(origin);
  crop->SetRegions(CtImage::SizeType{ { size[0], size[1], count } });
  crop->Allocate();
  std::copy_n(ct.GetBufferPointer() + first * size[0] * size[1], crop->GetLargestPossibleRegion().GetNumberOfPixels(),
              crop->GetBufferPointer());
  return crop;
}

/// The slices at or below LPS z = `topZ`.
inline CtImage::Pointer CropAbove(const CtImage& ct, double topZ)
{
  const double slices = std::floor((topZ - ct.GetOrigin()[2]) / ct.GetSpacing()[2] + 1e-9) + 1;
  return CropSlices(ct, 0, static_cast<itk::SizeValueType>(slices));
}

/// The slices at or above LPS z = `bottomZ`.
inline CtImage::Pointer CropBelow(const CtImage& ct, double bottomZ)
{
  const double first = std::max(0.0, std::ceil((bottomZ - ct.GetOrigin()[2]) / ct.GetSpacing()[2] - 1e-9));
  return CropSlices(ct, static_cast<itk::SizeValueType>(first), ct.GetLargestPossibleRegion().GetSize()[2]);
}

} // namespace sgp::testing
