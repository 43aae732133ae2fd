/// \file WriteOuterWallModel.h
/// The traced outer wall (VesselWall.h) as a model for 3D Slicer: per vessel (aorta, right and left
/// common iliac) a tube of triangles joining each plane's contour to the next one's, in LPS mm
/// with SPACE=LPS (WriteModel.h), and point data
///   - `ThrombusThicknessMm` (double): the ray's thrombus thickness, mm;
///   - `Supported` (int): 1 where the ray found a visible outer boundary, 0 where the contour was
///     interpolated from the supported sectors;
///   - `Vessel` (int): 0 aorta, 1 right iliac, 2 left iliac.
/// Consecutive planes are joined only when they lie within 2.5 steps of each other (a plane that
/// could not be traced leaves a gap rather than a wrong bridge).
/// \throws InputError naming the path when the file cannot be written.
#pragma once

#include <string>

#include "Wall/VesselWall.h"

namespace sgp
{

void WriteOuterWallModel(const VesselWall& wall, const std::string& path);

} // namespace sgp
