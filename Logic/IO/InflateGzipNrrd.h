/// \file InflateGzipNrrd.h
/// The fast path for the commonest CT file: a gzip NRRD with its data attached and 16-bit signed
/// voxels in the machine's byte order (what Slicer and most PACS exports write). Its data is
/// inflated in one call by libdeflate (Debian's libdeflate-dev: 0.28 s against zlib's 0.68 s for a
/// 512 × 512 × 400 CT, docs/development.md) straight into the image's buffer, while a second thread
/// maps that buffer's pages (the page faults were a fifth of the inflation's time); the file
/// itself is mapped, not copied.
///
/// The caller allocates `image` (uninitialised is fine) with the geometry ITK's reader gives the
/// file, so spacing, origin and direction are ITK's own; only the voxels come from here, and they
/// are the ones ITK would read (tested against ITK on the same files).
///
/// Returns false, leaving nothing written that the caller needs, for any other file, which the
/// caller then reads with ITK: another encoding, type or byte order, detached data, a header with a
/// line or byte skip or CRLF line ends, data that is not exactly one gzip member inflating to the
/// image's size (corrupt, truncated or concatenated: ITK then reports or reads it), and every file
/// in a build without libdeflate (SGP_HAVE_LIBDEFLATE undefined: the Slicer extension's build,
/// whose machines need not have it).
#pragma once

#include <string>

#include "Common/Types.h"

namespace sgp
{

bool InflateGzipNrrdInto(const std::string& path, CtImage& image);

/// The same for a label map of unsigned bytes (the plan's own lumen label map, given back as
/// `--inputLumenSegmentation`: ReadLumenSegmentation.h); the header must declare `unsigned char`.
bool InflateGzipNrrdInto(const std::string& path, LabelImage& image);

} // namespace sgp
