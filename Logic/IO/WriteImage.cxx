#include "IO/WriteImage.h"

#include <mutex>

#include <itkImageFileWriter.h>

#include "Common/Errors.h"
#if defined(SGP_HAVE_LIBDEFLATE)
#include "IO/WriteLabelNrrd.h"
#endif

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
