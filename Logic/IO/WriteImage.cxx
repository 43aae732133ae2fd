#include "IO/WriteImage.h"

#include <itkImageFileWriter.h>

#include "Common/Errors.h"

namespace sgp
{

namespace
{

template<typename Image>
void Write(const Image& image, const std::string& path)
{
  try
  {
    auto writer = itk::ImageFileWriter<Image>::New();
    writer->SetInput(&image);
    writer->SetFileName(path);
    writer->SetUseCompression(true);
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
  Write(image, path);
}

void WriteCtImage(const CtImage& image, const std::string& path)
{
  Write(image, path);
}

} // namespace sgp
