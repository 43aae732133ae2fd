/// \file WriteImage.h
/// Writes CT volumes and label maps with ITK (format from the extension: .nrrd, .nhdr, .nii,
/// .nii.gz, .mha, .mhd), gzip-compressed where the format allows, on the image's own grid (LPS
/// geometry as ITK stores it). A label map written as .nrrd takes a fast path in the standalone
/// build (WriteLabelNrrd.h: ITK's header, the voxels coded as runs); ITK reads back the same image.
///
/// \throws InputError naming the path when the image cannot be written (unknown extension, no such
///         folder, no permission, disk full).
#pragma once

#include <string>

#include "Common/Types.h"

namespace sgp
{

void WriteLabelMap(const LabelImage& image, const std::string& path);
void WriteCtImage(const CtImage& image, const std::string& path);

} // namespace sgp
