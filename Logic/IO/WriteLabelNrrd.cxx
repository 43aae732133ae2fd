#include "IO/WriteLabelNrrd.h"

#include <cerrno>
#include <cstdio>
#include <system_error>

#include "Common/Errors.h"
#include "IO/GzipRuns.h"

namespace sgp
{
namespace
{

/// A number as ITK's NRRD writer prints it (NrrdIO: "%.17g", so −0 stays −0).
std::string NrrdNumber(double value)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

std::string LabelNrrdHeader(const LabelImage& image)
{
  const auto region = image.GetLargestPossibleRegion();
  const auto size = region.GetSize();
  const auto& spacing = image.GetSpacing();
  const auto& direction = image.GetDirection();
  // As ITK's ImageFileWriter gives it to the NRRD writer: the physical point of the first index
  // (origin + D·diag(spacing)·index, which for index 0 turns an origin of −0 into 0).
  LabelImage::PointType origin;
  image.TransformIndexToPhysicalPoint(region.GetIndex(), origin);
  std::string header = "NRRD0004\n# Complete NRRD file format specification at:\n"
                       "# http://teem.sourceforge.net/nrrd/format.html\ntype: unsigned char\ndimension: 3\n"
                       "space: left-posterior-superior\nsizes: " +
                       std::to_string(size[0]) + " " + std::to_string(size[1]) + " " + std::to_string(size[2]) +
                       "\nspace directions:";
  for (unsigned axis = 0; axis < 3; ++axis)
    header += " (" + NrrdNumber(spacing[axis] * direction(0, axis)) + "," +
              NrrdNumber(spacing[axis] * direction(1, axis)) + "," + NrrdNumber(spacing[axis] * direction(2, axis)) +
              ")";
  header += "\nkinds: domain domain domain\nencoding: gzip\nspace origin: (" + NrrdNumber(origin[0]) + "," +
            NrrdNumber(origin[1]) + "," + NrrdNumber(origin[2]) + ")\n\n";
  return header;
}

} // namespace

bool WriteLabelNrrd(const LabelImage& image, const std::string& path)
{
  const std::string extension = ".nrrd";
  const auto region = image.GetLargestPossibleRegion();
  if (path.size() <= extension.size() ||
      path.compare(path.size() - extension.size(), extension.size(), extension) != 0 ||
      !image.GetMetaDataDictionary().GetKeys().empty() || region != image.GetBufferedRegion() ||
      region.GetNumberOfPixels() == 0)
    return false;
  const std::string header = LabelNrrdHeader(image);
  const std::string data = GzipRuns(image.GetBufferPointer(), region.GetNumberOfPixels());
  const auto cannot = [&](int error)
  {
    // The message from the category, not strerror: label maps are written on other threads.
    return InputError("Cannot write '" + path + "': " + std::generic_category().message(error) +
                      "; give a writable path ending in .nrrd, .nii.gz or .mha.");
  };
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file)
    throw cannot(errno);
  bool written = std::fwrite(header.data(), 1, header.size(), file) == header.size() &&
                 std::fwrite(data.data(), 1, data.size(), file) == data.size();
  int error = written ? 0 : errno;
  if (std::fclose(file) != 0 && written)
  {
    written = false;
    error = errno;
  }
  if (!written)
  {
    std::remove(path.c_str()); // no partial file
    throw cannot(error);
  }
  return true;
}

} // namespace sgp
