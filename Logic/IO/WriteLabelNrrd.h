/// \file WriteLabelNrrd.h
/// The fast path for writing a label map as .nrrd (WriteImage.h's WriteLabelMap takes it in the
/// standalone build): the header ITK 5.2's NRRD writer gives the same image, character for
/// character — its geometry as ITK computes it (the origin is the physical point of the region's
/// first index, spacing × direction per axis, each number printed with 17 significant digits, a −0
/// as −0) — then the voxels as one gzip member coded as runs (GzipRuns.h). ITK reads back the
/// same voxels and geometry as from ITK's own file.
///
/// Input: a 3-D label map (unsigned char, any spacing, origin, direction and region index), `path`.
/// Returns false, with nothing written, for what it leaves to ITK's writer: a path not ending in
/// ".nrrd" (.nhdr, .nii.gz, .mha, ...), an image with metadata to carry, one not wholly buffered,
/// or an empty one.
///
/// \throws InputError "Cannot write '<path>': <reason>; ..." when the file cannot be created or
///         written (no such folder, no permission, disk full); no partial file is left.
#pragma once

#include <string>

#include "Common/Types.h"

namespace sgp
{

bool WriteLabelNrrd(const LabelImage& image, const std::string& path);

} // namespace sgp
