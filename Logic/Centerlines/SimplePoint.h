/// \file SimplePoint.h
/// The local topology tests of 3-D thinning, on a voxel's 3×3×3 neighbourhood.
///
/// A neighbourhood is a 27-bit mask: bit (dk+1)·9 + (dj+1)·3 + (di+1) is set when the voxel at
/// offset (di, dj, dk) is foreground; bit 13 is the centre and is ignored.
///
/// A foreground voxel p is *simple* for (26, 6) connectivity — removing it changes neither the
/// number of 26-connected foreground components, nor of 6-connected background components, nor
/// of tunnels — exactly when both topological numbers are 1 (G. Bertrand and G. Malandain,
/// "A new characterization of three-dimensional simple points", Pattern Recognition Letters 15,
/// 1994):
///   T26(p, X): 26-connected components of foreground in the 26-neighbourhood without p;
///   T6(p, X̄): 6-connected components of background in the 18-neighbourhood without p that
///              are 6-adjacent to p.
/// Deleting only simple points therefore keeps the skeleton homotopic to the mask, the guarantee
/// Lee, Kashyap and Chu (1994) obtain with their Euler-table and octree tests.
#pragma once

#include <cstdint>

namespace sgp
{

/// Bit of the neighbour at offset (di, dj, dk), each in {−1, 0, 1}.
constexpr int NeighbourBit(int di, int dj, int dk)
{
  return (dk + 1) * 9 + (dj + 1) * 3 + (di + 1);
}

/// Number of foreground voxels among the 26 neighbours.
int CountNeighbours(std::uint32_t neighbourhood);

/// T26(p, X) for the neighbourhood (see the file comment).
int ForegroundComponents26(std::uint32_t neighbourhood);

/// T6(p, X̄) for the neighbourhood (see the file comment).
int BackgroundComponents6(std::uint32_t neighbourhood);

/// True when removing the centre preserves topology: T26 = 1 and T6 = 1.
bool IsSimplePoint(std::uint32_t neighbourhood);

} // namespace sgp
