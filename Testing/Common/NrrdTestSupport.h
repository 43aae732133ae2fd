/// \file NrrdTestSupport.h
/// Writes a CT volume as an NRRD whose geometry is stated in `right-anterior-superior` space, the
/// way some scanners and tools store it, to check that readers honour the storage space.
#pragma once

#include <fstream>
#include <string>

#include "Common/Types.h"

namespace sgp::testing
{

/// The same voxels in the same order; the axis directions and origin given in RAS
/// (x and y negated), so a correct reader gives back the image's own LPS geometry.
inline void WriteNrrdInRasSpace(const CtImage& image, const std::string& path)
{
  const auto size = image.GetLargestPossibleRegion().GetSize();
  const auto& d = image.GetDirection();
  const auto& s = image.GetSpacing();
  const auto& o = image.GetOrigin();
  std::ofstream out(path, std::ios::binary);
  out.precision(17);
  out << "NRRD0004\ntype: short\ndimension: 3\nspace: right-anterior-superior\nsizes: " << size[0] << " " << size[1]
      << " " << size[2] << "\nspace directions:";
  for (int axis = 0; axis < 3; ++axis)
    out << " (" << -d(0, axis) * s[axis] << "," << -d(1, axis) * s[axis] << "," << d(2, axis) * s[axis] << ")";
  out << "\nkinds: domain domain domain\nendian: little\nencoding: raw\nspace origin: (" << -o[0] << "," << -o[1] << ","
      << o[2] << ")\n\n";
  out.write(reinterpret_cast<const char*>(image.GetBufferPointer()),
            static_cast<std::streamsize>(image.GetLargestPossibleRegion().GetNumberOfPixels() * sizeof(short)));
}

} // namespace sgp::testing
