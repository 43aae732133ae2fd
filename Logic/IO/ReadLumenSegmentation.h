/// \file ReadLumenSegmentation.h
/// Reads the lumen segmentation a person gives (`--inputLumenSegmentation`): a label map as NRRD,
/// NIfTI (TotalSegmentator's `.nii.gz`) or MetaImage, or Slicer's segmentation NRRD (`.seg.nrrd`,
/// whose segments are named in its header: `SegmentN_Name`, `SegmentN_LabelValue`,
/// `SegmentN_Layer`; a file with overlapping segments stores one layer per component).
///
/// Which voxels are lumen (`lumenLabels`, comma-separated, white space ignored):
///  - each item is a segment name of a `.seg.nrrd` (case-insensitive), or a label value (1–65535;
///    in a layered `.seg.nrrd`, that value in any layer);
///  - empty (the default): every non-zero voxel **when the file holds one label** (one segment).
///    A file with several labels is refused and its labels listed: a map that holds the aorta
///    beside the inferior vena cava, the kidneys or the spine (TotalSegmentator's `total` task:
///    aorta 52, left and right common iliac arteries 65 and 66, inferior vena cava 63) must never
///    have a vein planned as the aorta, so the person names the lumen's labels.
///
/// Output: a mask on the file's own grid (LPS; 1 = a chosen label) and a description of what was
/// taken ("labels 52, 65, 66 of 'total.nii.gz'"), for messages and the report.
/// Errors (InputError, one line): the file cannot be read or is not 3-D; a floating-point map
/// with non-integer values; an item that is neither a segment name nor a label value (the
/// segments listed); no voxel carries a chosen label (the labels present listed, with segment
/// names); several labels and no `lumenLabels`.
#pragma once

#include <string>

#include "Common/Types.h"

namespace sgp
{

struct GivenLumenFile
{
  LabelImage::Pointer mask; ///< on the file's grid, 1 = lumen
  std::string description;  ///< what was taken, e.g. "labels 52, 65, 66 of 'total.nii.gz'"
};

GivenLumenFile ReadLumenSegmentation(const std::string& path, const std::string& lumenLabels);

} // namespace sgp
