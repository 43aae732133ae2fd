/// \file ImageGeometry.h
/// Conversions between LPS millimetres and voxel indices that honour spacing, origin and
/// direction cosines, and the physical extent of an image for messages.
#pragma once

#include <array>
#include <string>

#include <itkImageBase.h>

#include "Common/Types.h"

namespace sgp
{

/// LPS mm of the centre of voxel `index`.
Point3 IndexToLps(const itk::ImageBase<3>& image, const itk::Index<3>& index);

/// Axis-aligned LPS bounds {xmin, xmax, ymin, ymax, zmin, zmax} of the image's voxels, edges
/// included (half a voxel beyond the outer centres).
std::array<double, 6> ImageBoundsLps(const itk::ImageBase<3>& image);

/// The voxel that contains `lps`.
/// \param what  names the point in the message, e.g. "Seed"
/// \throws InputError when the point lies outside the image, naming the point and the bounds.
itk::Index<3> LpsToIndexInside(const itk::ImageBase<3>& image, const Point3& lps, const std::string& what);

} // namespace sgp
