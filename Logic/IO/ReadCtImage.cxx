#include "IO/ReadCtImage.h"

#include <filesystem>
#include <new>
#include <type_traits>

#include <itkGDCMImageIO.h>
#include <itkGDCMSeriesFileNames.h>
#include <itkImageFileReader.h>
#include <itkImageIOFactory.h>
#include <itkImageSeriesReader.h>

#include "Common/Errors.h"
#include "Common/Format.h"
#include "Common/HugePages.h"
#include "IO/InflateGzipNrrd.h"
#include "IO/RegisterImageIOFactories.h"

namespace sgp
{

namespace
{

std::string FirstLine(const std::string& text)
{
  const auto end = text.find_first_of("\r\n");
  return end == std::string::npos ? text : text.substr(0, end);
}

std::string SizeText(const std::vector<std::size_t>& sizes)
{
  std::string text;
  for (std::size_t a = 0; a < sizes.size(); ++a)
  {
    text += (a ? " × " : "") + std::to_string(sizes[a]);
  }
  return text + " voxels";
}

CtImage::Pointer ReadDicomSeries(const std::string& folder, std::vector<std::string>& warnings)
{
  auto names = itk::GDCMSeriesFileNames::New();
  names->SetUseSeriesDetails(true);
  names->SetDirectory(folder);
  const std::vector<std::string> series = names->GetSeriesUIDs();
  if (series.empty())
  {
    throw InputError("Cannot read the input volume '" + folder +
                     "': the folder holds no DICOM series; give a folder of DICOM slices or a volume file.");
  }
  std::string chosen = series.front();
  for (const std::string& uid : series)
  {
    if (names->GetFileNames(uid).size() > names->GetFileNames(chosen).size())
    {
      chosen = uid;
    }
  }
  const std::vector<std::string> files = names->GetFileNames(chosen);
  if (series.size() > 1)
  {
    warnings.push_back("The folder '" + folder + "' holds " + std::to_string(series.size()) +
                       " DICOM series; read the largest (" + std::to_string(files.size()) + " slices, " + chosen +
                       ").");
  }
  if (files.size() < 2)
  {
    throw InputError("The input volume '" + folder + "' is 2-D (a DICOM series of " + std::to_string(files.size()) +
                     " slice); expected a 3-D CT volume.");
  }
  auto reader = itk::ImageSeriesReader<CtImage>::New();
  reader->SetImageIO(itk::GDCMImageIO::New());
  reader->SetFileNames(files);
  reader->Update();
  return reader->GetOutput();
}

/// Checks the file's header (3-D, one component) and returns its ImageIO.
itk::ImageIOBase::Pointer OpenVolumeFile(const std::string& path)
{
  itk::ImageIOBase::Pointer io =
    itk::ImageIOFactory::CreateImageIO(path.c_str(), itk::ImageIOFactory::IOFileModeEnum::ReadMode);
  if (!io)
  {
    const bool exists = std::filesystem::exists(path);
    throw InputError("Cannot read the input volume '" + path + "': " +
                     (exists ? "no reader recognises it (expected NRRD, NIfTI, MetaImage or a DICOM folder)"
                             : std::string("the file does not exist")) +
                     "; give a readable 3-D CT volume.");
  }
  io->SetFileName(path);
  io->ReadImageInformation();
  std::vector<std::size_t> sizes;
  for (unsigned a = 0; a < io->GetNumberOfDimensions(); ++a)
  {
    sizes.push_back(io->GetDimensions(a));
  }
  const bool thin = sizes.size() == 3 && (sizes[0] < 2 || sizes[1] < 2 || sizes[2] < 2);
  if (sizes.size() < 3 || thin)
  {
    throw InputError("The input volume '" + path + "' is 2-D (" + SizeText(sizes) + "); expected a 3-D CT volume.");
  }
  if (sizes.size() > 3)
  {
    throw InputError("The input volume '" + path + "' is " + std::to_string(sizes.size()) + "-D (" + SizeText(sizes) +
                     "); expected a 3-D CT volume.");
  }
  // A header that declares more voxels than any CT this tool plans on (2^32: 8.6 GB of HU) is
  // corrupt or not a CT; refused before the reader allocates for it.
  const double voxels = double(sizes[0]) * double(sizes[1]) * double(sizes[2]);
  if (voxels > 4294967296.0)
  {
    throw InputError("The input volume '" + path + "' declares " + SizeText(sizes) + " (" +
                     FormatNumber(voxels / 1e9, 1) + " billion); expected at most 4.3 billion (a corrupt header?).");
  }
  if (io->GetNumberOfComponents() != 1)
  {
    throw InputError("The input volume '" + path + "' has " + std::to_string(io->GetNumberOfComponents()) +
                     " components per voxel (" + io->GetPixelTypeAsString(io->GetPixelType()) +
                     "); expected a scalar CT volume in HU.");
  }
  return io;
}

template<typename Image>
typename Image::Pointer ReadVolumeFile(const std::string& path)
{
  auto reader = itk::ImageFileReader<Image>::New();
  const itk::ImageIOBase::Pointer io = OpenVolumeFile(path);
  reader->SetImageIO(io);
  reader->SetFileName(path);
  if constexpr (std::is_same_v<Image, CtImage>)
  {
    // A gzip NRRD of 16-bit HU: ITK's geometry, libdeflate's inflation (InflateGzipNrrd.h).
    if (std::string(io->GetNameOfClass()) == "NrrdImageIO" && io->GetComponentType() == itk::IOComponentEnum::SHORT)
    {
      reader->UpdateOutputInformation();
      auto image = CtImage::New();
      image->CopyInformation(reader->GetOutput());
      image->SetRegions(reader->GetOutput()->GetLargestPossibleRegion());
      AllocateAdvised(*image);
      if (InflateGzipNrrdInto(path, *image))
        return image;
    }
  }
  reader->Update();
  return reader->GetOutput();
}

} // namespace

CtVolume ReadCtImage(const std::string& path)
{
  RegisterImageIOFactories(); // done at start-up already; inside Slicer UseITK registers none
  CtVolume volume;
  try
  {
    volume.image =
      std::filesystem::is_directory(path) ? ReadDicomSeries(path, volume.warnings) : ReadVolumeFile<CtImage>(path);
  }
  catch (const itk::ExceptionObject& e)
  {
    throw InputError("Cannot read the input volume '" + path + "': " + FirstLine(e.GetDescription()) +
                     "; give a readable 3-D CT volume.");
  }
  catch (const std::bad_alloc&)
  {
    throw InputError("Cannot read the input volume '" + path +
                     "': its voxels do not fit in this machine's memory; give a smaller or cropped volume.");
  }
  return volume;
}

LabelImage::Pointer ReadLabelMap(const std::string& path)
{
  RegisterImageIOFactories();
  try
  {
    return ReadVolumeFile<LabelImage>(path);
  }
  catch (const itk::ExceptionObject& e)
  {
    throw InputError("Cannot read the label map '" + path + "': " + FirstLine(e.GetDescription()) +
                     "; give a readable 3-D label map.");
  }
  catch (const std::bad_alloc&)
  {
    throw InputError("Cannot read the label map '" + path + "': its voxels do not fit in this machine's memory.");
  }
}

} // namespace sgp
