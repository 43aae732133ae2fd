/// \file ReadCtImage.h
/// Reads a CT volume for the pipeline: NRRD (raw or gzip), NIfTI, MetaImage, or a DICOM series
/// folder.
///
/// Any integer or floating-point scalar pixel type is accepted and its values are taken as HU
/// (floating-point values are truncated toward zero when cast to `short`; DICOM rescale slope and
/// intercept are applied by the reader). Spacing, origin and direction cosines come from the file
/// in LPS: ITK converts an NRRD stored in `right-anterior-superior` space, so its physical points
/// equal those of the same data stored in LPS.
///
/// A path that names a folder is read as a DICOM series; if the folder holds several series, the
/// one with the most slices is read and a warning names the others. Paths are not checked with
/// the file system beforehand (under Slicer they may be memory references): the reader's failure
/// is turned into a message that names the file.
///
/// \throws InputError naming the path when the file cannot be read, is not 3-D (or has fewer than
///         two voxels along an axis), or has more than one component per voxel.
#pragma once

#include <string>
#include <vector>

#include "Common/Types.h"

namespace sgp
{

struct CtVolume
{
  CtImage::Pointer image;
  std::vector<std::string> warnings; ///< one line each, without the "WARNING: " prefix
};

CtVolume ReadCtImage(const std::string& path);

/// Reads a label map (any integer pixel type, NRRD / NIfTI / MetaImage, e.g. a Slicer `.seg.nrrd`
/// with one layer) as LabelImage; values are cast to unsigned char.
/// \throws InputError as ReadCtImage does (not 3-D, several components, unreadable).
LabelImage::Pointer ReadLabelMap(const std::string& path);

} // namespace sgp
