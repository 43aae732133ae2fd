#include "IO/WriteImage.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <mutex>

#include <itkImageFileWriter.h>

#include "Common/Errors.h"
#include "IO/GzipRuns.h"

namespace sgp
{

namespace
{

/// One image written at a time, whatever its type: a front end writes label maps on another thread
/// while the rest is written, and ITK's NRRD library keeps its error messages in one unguarded store.
std::mutex oneImageAtATime;

template<typename Image>
void Write(const Image& image, const std::string& path)
{
  try
  {
    auto writer = itk::ImageFileWriter<Image>::New();
    writer->SetInput(&image);
    writer->SetFileName(path);
    writer->SetUseCompression(true);
    const std::lock_guard<std::mutex> lock(oneImageAtATime);
    writer->Update();
  }
  catch (const itk::ExceptionObject& e)
  {
    std::string reason = e.GetDescription();
    reason = reason.substr(0, reason.find_first_of("\r\n"));
    throw InputError("Cannot write '" + path + "': " + reason +
                     "; give a writable path ending in .nrrd, .nii.gz or .mha.");
  }
}

#if defined(SGP_HAVE_LIBDEFLATE)

/// A number as ITK's NRRD writer prints it: 17 significant digits, the shortest form, and −0 as 0.
std::string NrrdNumber(double value)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value == 0.0 ? 0.0 : value);
  return text;
}

/// The header ITK's NRRD writer gives a 3-D label map with gzip data and no metadata, line for line
/// (tested against it): the geometry's numbers are the same text, so the same doubles read back.
std::string LabelNrrdHeader(const LabelImage& image)
{
  const auto size = image.GetLargestPossibleRegion().GetSize();
  const auto& spacing = image.GetSpacing();
  const auto& direction = image.GetDirection();
  const auto& origin = image.GetOrigin();
  std::string header = "NRRD0004\n# Complete NRRD file format specification at:\n"
                       "# http://teem.sourceforge.net/nrrd/format.html\ntype: unsigned char\ndimension: 3\n"
                       "space: left-posterior-superior\nsizes: " +
                       std::to_string(size[0]) + " " + std::to_string(size[1]) + " " + std::to_string(size[2]) +
                       "\nspace directions:";
  for (unsigned axis = 0; axis < 3; ++axis)
    header += " (" + NrrdNumber(direction(0, axis) * spacing[axis]) + "," +
              NrrdNumber(direction(1, axis) * spacing[axis]) + "," + NrrdNumber(direction(2, axis) * spacing[axis]) +
              ")";
  header += "\nkinds: domain domain domain\nencoding: gzip\nspace origin: (" + NrrdNumber(origin[0]) + "," +
            NrrdNumber(origin[1]) + "," + NrrdNumber(origin[2]) + ")\n\n";
  return header;
}

/// The fast path for a label map written as .nrrd (GzipRuns.h): false, leaving nothing written,
/// for what it does not write (another extension, metadata to carry, a region not at the origin),
/// which ITK's writer then writes.
bool WriteLabelNrrd(const LabelImage& image, const std::string& path)
{
  const std::string extension = ".nrrd";
  if (path.size() <= extension.size() ||
      path.compare(path.size() - extension.size(), extension.size(), extension) != 0 ||
      !image.GetMetaDataDictionary().GetKeys().empty() || image.GetLargestPossibleRegion() != image.GetBufferedRegion())
    return false;
  const auto region = image.GetLargestPossibleRegion();
  for (unsigned a = 0; a < 3; ++a)
    if (region.GetIndex()[a] != 0)
      return false;
  const std::string header = LabelNrrdHeader(image);
  const std::string data = GzipRuns(image.GetBufferPointer(), region.GetNumberOfPixels());
  const auto cannot = [&](int error)
  {
    return InputError("Cannot write '" + path + "': " + std::strerror(error) +
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

#endif

} // namespace

void WriteLabelMap(const LabelImage& image, const std::string& path)
{
#if defined(SGP_HAVE_LIBDEFLATE)
  if (WriteLabelNrrd(image, path))
    return;
#endif
  Write(image, path);
}

void WriteCtImage(const CtImage& image, const std::string& path)
{
  Write(image, path);
}

} // namespace sgp
