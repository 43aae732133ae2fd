#include "IO/ReadLumenSegmentation.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <itkImageFileReader.h>
#include <itkImageIOFactory.h>
#include <itkMetaDataObject.h>
#include <itkVectorImage.h>

#include "Common/Errors.h"
#include "Common/HugePages.h"
#include "IO/InflateGzipNrrd.h"
#include "IO/RegisterImageIOFactories.h"

namespace sgp
{
namespace
{

/// One label: its layer (−1: any layer) and value.
using Label = std::pair<int, long>;

struct Segment
{
  std::string name;
  Label label;
};

std::string Lower(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return text;
}

std::string Trim(const std::string& text)
{
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos)
    return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

/// A Slicer segmentation's segments from its header (SegmentN_Name, _LabelValue, _Layer).
std::vector<Segment> SegmentsOf(const itk::MetaDataDictionary& header)
{
  std::vector<Segment> segments;
  for (int n = 0;; ++n)
  {
    const std::string prefix = "Segment" + std::to_string(n) + "_";
    std::string name, value, layer;
    if (!itk::ExposeMetaData<std::string>(header, prefix + "Name", name))
      break;
    itk::ExposeMetaData<std::string>(header, prefix + "LabelValue", value);
    itk::ExposeMetaData<std::string>(header, prefix + "Layer", layer);
    try
    {
      segments.push_back({ name, { layer.empty() ? 0 : std::stoi(layer), value.empty() ? 1L : std::stol(value) } });
    }
    catch (const std::exception&)
    {
      throw InputError("The segmentation's header gives segment '" + name + "' the label value '" + value +
                       "' and layer '" + layer + "'; expected whole numbers.");
    }
  }
  return segments;
}

/// The file's label values (and layers) with their voxel counts, and how to mark the chosen ones.
struct LabelVolume
{
  itk::ImageBase<3>::Pointer geometry;
  int layers = 1;
  std::map<Label, long> counts; ///< non-zero labels only
  /// The mask of the chosen labels (1, else 0) on the file's grid, and how many voxels it holds.
  /// A file of bytes is turned into it in place (the only full-size buffer held): call it once.
  std::function<LabelImage::Pointer(const std::set<Label>& chosen, std::size_t& count)> select;
};

/// A byte image is its own mask (LabelImage); any other gets a new one on its grid.
template<typename Image>
LabelImage::Pointer MaskLike(Image& image)
{
  if constexpr (std::is_same_v<Image, LabelImage>)
    return &image;
  auto mask = LabelImage::New();
  mask->CopyInformation(&image);
  mask->SetRegions(image.GetLargestPossibleRegion());
  AllocateAdvised(*mask);
  return mask;
}

bool Chosen(const std::set<Label>& chosen, int layer, long value)
{
  return value != 0 && (chosen.count({ layer, value }) > 0 || chosen.count({ -1, value }) > 0);
}

/// One layer of labels. Pixels of 8 and 16 bits are counted and chosen through a table of their
/// values (one pass each, no per-voxel look-up in a set: a 512 × 512 × 400 map in a few tenths of
/// a second); wider ones through the set, for their non-zero voxels.
template<typename Pixel>
LabelVolume ReadScalar(const std::string& path, const itk::ImageIOBase::Pointer& io)
{
  using Image = itk::Image<Pixel, 3>;
  auto reader = itk::ImageFileReader<Image>::New();
  reader->SetImageIO(io);
  reader->SetFileName(path);
  typename Image::Pointer image;
  if constexpr (std::is_same_v<Image, LabelImage>)
  {
    // A gzip NRRD of bytes (the plan's own label map): ITK's geometry, libdeflate's inflation.
    if (std::string(io->GetNameOfClass()) == "NrrdImageIO")
    {
      reader->UpdateOutputInformation();
      image = LabelImage::New();
      image->CopyInformation(reader->GetOutput());
      image->SetRegions(reader->GetOutput()->GetLargestPossibleRegion());
      image->Allocate(false);
      if (!InflateGzipNrrdInto(path, *image))
        image = nullptr;
    }
  }
  if (!image)
  {
    reader->Update();
    image = reader->GetOutput();
  }
  LabelVolume volume;
  volume.geometry = image;
  const std::size_t voxels = image->GetLargestPossibleRegion().GetNumberOfPixels();
  const Pixel* data = image->GetBufferPointer();
  if constexpr (sizeof(Pixel) <= 2)
  {
    std::vector<long> histogram(std::size_t(1) << (8 * sizeof(Pixel)), 0);
    for (std::size_t v = 0; v < voxels; ++v)
      ++histogram[data[v]];
    for (std::size_t value = 1; value < histogram.size(); ++value)
      if (histogram[value] > 0)
        volume.counts[{ 0, long(value) }] = histogram[value];
    volume.select = [image, voxels](const std::set<Label>& chosen, std::size_t& count)
    {
      std::vector<unsigned char> table(std::size_t(1) << (8 * sizeof(Pixel)), 0);
      for (std::size_t value = 1; value < table.size(); ++value)
        table[value] = Chosen(chosen, 0, long(value)) ? 1 : 0;
      LabelImage::Pointer mask = MaskLike(*image);
      const Pixel* in = image->GetBufferPointer();
      unsigned char* out = mask->GetBufferPointer(); // `in` itself for a byte image
      count = 0;
      for (std::size_t v = 0; v < voxels; ++v)
        count += out[v] = table[in[v]];
      return mask;
    };
  }
  else
  {
    for (std::size_t v = 0; v < voxels; ++v)
      if (data[v] != 0)
        ++volume.counts[{ 0, long(data[v]) }];
    volume.select = [image, data, voxels](const std::set<Label>& chosen, std::size_t& count)
    {
      LabelImage::Pointer mask = MaskLike(*image);
      unsigned char* out = mask->GetBufferPointer();
      count = 0;
      for (std::size_t v = 0; v < voxels; ++v)
        count += out[v] = Chosen(chosen, 0, long(data[v])) ? 1 : 0;
      return mask;
    };
  }
  return volume;
}

/// Slicer's layered segmentation: one component per layer.
LabelVolume ReadLayers(const std::string& path, const itk::ImageIOBase::Pointer& io)
{
  using Image = itk::VectorImage<std::uint16_t, 3>;
  auto reader = itk::ImageFileReader<Image>::New();
  reader->SetImageIO(io);
  reader->SetFileName(path);
  reader->Update();
  Image::Pointer image = reader->GetOutput();
  LabelVolume volume;
  volume.geometry = image;
  volume.layers = int(image->GetNumberOfComponentsPerPixel());
  const std::size_t voxels = image->GetLargestPossibleRegion().GetNumberOfPixels();
  const std::uint16_t* data = image->GetBufferPointer();
  const int layers = volume.layers;
  for (std::size_t v = 0; v < voxels; ++v)
    for (int l = 0; l < layers; ++l)
      if (data[v * std::size_t(layers) + std::size_t(l)] != 0)
        ++volume.counts[{ l, long(data[v * std::size_t(layers) + std::size_t(l)]) }];
  volume.select = [image, data, layers, voxels](const std::set<Label>& chosen, std::size_t& count)
  {
    LabelImage::Pointer mask = MaskLike(*image);
    unsigned char* out = mask->GetBufferPointer();
    count = 0;
    for (std::size_t v = 0; v < voxels; ++v)
    {
      out[v] = 0;
      for (int l = 0; l < layers && !out[v]; ++l)
        out[v] = Chosen(chosen, l, long(data[v * std::size_t(layers) + std::size_t(l)])) ? 1 : 0;
      count += out[v];
    }
    return mask;
  };
  return volume;
}

/// The labels present, for messages: "52 (aorta, 81234 voxels), 63 (…)".
std::string Present(const LabelVolume& volume, const std::vector<Segment>& segments)
{
  std::string text;
  for (const auto& [label, count] : volume.counts)
  {
    std::string name;
    for (const Segment& s : segments)
      if (s.label == label)
        name = "'" + s.name + "', ";
    text += (text.empty() ? "" : "; ") + std::to_string(label.second) +
            (volume.layers > 1 ? " in layer " + std::to_string(label.first) : "") + " (" + name +
            std::to_string(count) + " voxels)";
  }
  return text.empty() ? "none" : text;
}

std::string SegmentNames(const std::vector<Segment>& segments)
{
  std::string text;
  for (const Segment& s : segments)
    text += (text.empty() ? "'" : ", '") + s.name + "'";
  return text.empty() ? "none (the file names no segments)" : text;
}

} // namespace

GivenLumenFile ReadLumenSegmentation(const std::string& path, const std::string& lumenLabels)
{
  RegisterImageIOFactories();
  const std::string file = std::filesystem::path(path).filename().string();
  itk::ImageIOBase::Pointer io =
    itk::ImageIOFactory::CreateImageIO(path.c_str(), itk::ImageIOFactory::IOFileModeEnum::ReadMode);
  if (!io)
    throw InputError("Cannot read the lumen segmentation '" + path +
                     "': " + (std::filesystem::exists(path) ? "no reader recognises it" : "the file does not exist") +
                     "; expected a label map (NRRD, .seg.nrrd, NIfTI or MetaImage).");
  LabelVolume volume;
  std::vector<Segment> segments;
  try
  {
    io->SetFileName(path);
    io->ReadImageInformation();
    if (io->GetNumberOfDimensions() != 3)
      throw InputError("The lumen segmentation '" + path + "' is " + std::to_string(io->GetNumberOfDimensions()) +
                       "-D; expected a 3-D label map.");
    segments = SegmentsOf(io->GetMetaDataDictionary());
    const auto type = io->GetComponentType();
    if (io->GetNumberOfComponents() > 1)
      volume = ReadLayers(path, io);
    else if (type == itk::IOComponentEnum::UCHAR)
      volume = ReadScalar<std::uint8_t>(path, io);
    else if (type == itk::IOComponentEnum::CHAR || type == itk::IOComponentEnum::USHORT ||
             type == itk::IOComponentEnum::SHORT)
      volume = ReadScalar<std::uint16_t>(path, io);
    else
      volume = ReadScalar<std::int32_t>(path, io);
  }
  catch (const itk::ExceptionObject& e)
  {
    const std::string what = e.GetDescription();
    throw InputError("Cannot read the lumen segmentation '" + path + "': " + what.substr(0, what.find('\n')) +
                     "; expected a readable 3-D label map.");
  }

  // The chosen labels (file comment).
  std::set<Label> chosen;
  std::string description;
  std::string items = lumenLabels;
  std::replace(items.begin(), items.end(), ';', ',');
  std::size_t start = 0;
  while (start <= items.size() && !Trim(items).empty())
  {
    const std::size_t end = std::min(items.find(',', start), items.size());
    const std::string item = Trim(items.substr(start, end - start));
    start = end + 1;
    if (item.empty())
      continue;
    const auto named =
      std::find_if(segments.begin(), segments.end(), [&](const Segment& s) { return Lower(s.name) == Lower(item); });
    if (named != segments.end())
    {
      chosen.insert(named->label);
      description += (description.empty() ? "" : ", ") + ("'" + named->name + "'");
      continue;
    }
    std::size_t used = 0;
    long value = 0;
    try
    {
      value = std::stol(item, &used);
    }
    catch (const std::exception&)
    {
      used = 0;
    }
    if (used != item.size() || value < 1 || value > 65535)
      throw InputError("lumenLabels names '" + item + "', which is neither a segment of '" + file +
                       "' (segments: " + SegmentNames(segments) + ") nor a label value from 1 to 65535.");
    chosen.insert({ -1, value });
    description += (description.empty() ? "" : ", ") + std::to_string(value);
  }
  if (chosen.empty())
  {
    if (volume.counts.size() > 1)
      throw InputError("The lumen segmentation '" + file + "' holds " + std::to_string(volume.counts.size()) +
                       " labels (" + Present(volume, segments) +
                       "); name the lumen's with lumenLabels (label values or segment names, e.g. 52,65,66 for "
                       "TotalSegmentator's aorta and common iliac arteries), so that no vein or organ is planned "
                       "as the aorta.");
    if (!volume.counts.empty())
      chosen.insert(volume.counts.begin()->first);
    description = "every non-zero voxel";
  }
  else
    description =
      (lumenLabels.find_first_not_of("0123456789, ;\t") == std::string::npos ? "labels " : "") + description;
  description += " of '" + file + "'";

  std::size_t count = 0;
  LabelImage::Pointer mask = volume.select(chosen, count);
  if (count == 0)
    throw InputError("No voxel of the lumen segmentation '" + file + "' carries the labels chosen (" +
                     (lumenLabels.empty() ? std::string("any non-zero") : lumenLabels) +
                     "); the file holds: " + Present(volume, segments) + ".");
  return { mask, description };
}

} // namespace sgp
