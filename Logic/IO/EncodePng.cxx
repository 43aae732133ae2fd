#include "IO/EncodePng.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkUnsignedCharArray.h>

#include "Common/Errors.h"
#include "Common/Format.h"

namespace sgp
{

namespace
{

/// The PNG file of `data` (unsigned char, 1 or 3 components), in memory, by VTK's PNG writer.
std::string WritePng(vtkImageData* data, const char* kind)
{
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(data);
  writer->WriteToMemoryOn();
  writer->Write();
  vtkUnsignedCharArray* bytes = writer->GetResult();
  const int* size = data->GetDimensions();
  if (!bytes || bytes->GetNumberOfValues() == 0)
    throw std::runtime_error("VTK's PNG writer produced no bytes for a " + std::to_string(size[0]) + " x " +
                             std::to_string(size[1]) + kind + " image.");
  return std::string(reinterpret_cast<const char*>(bytes->GetPointer(0)),
                     static_cast<size_t>(bytes->GetNumberOfValues()));
}

} // namespace

std::string EncodeGreyPng(const PlaneImage& image, double lowHu, double highHu)
{
  if (image.width <= 0 || image.height <= 0 ||
      image.hu.size() != static_cast<size_t>(image.width) * static_cast<size_t>(image.height))
    throw InputError("A PNG needs a non-empty image; got " + std::to_string(image.width) + " x " +
                     std::to_string(image.height) + " pixels with " + std::to_string(image.hu.size()) + " values.");
  if (!(lowHu < highHu))
    throw InputError("The PNG's HU window is " + FormatNumber(lowHu) + " … " + FormatNumber(highHu) +
                     "; expected low < high.");
  vtkNew<vtkImageData> data;
  data->SetDimensions(image.width, image.height, 1);
  data->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* out = static_cast<unsigned char*>(data->GetScalarPointer());
  const double scale = 255.0 / (highHu - lowHu);
  for (int row = 0; row < image.height; ++row)
  {
    // VTK's rows run upward: the plane's row 0 (the top) is VTK's last row.
    unsigned char* line = out + static_cast<size_t>(image.height - 1 - row) * image.width;
    for (int col = 0; col < image.width; ++col)
      line[col] = static_cast<unsigned char>(std::lround(std::clamp((image.At(col, row) - lowHu) * scale, 0.0, 255.0)));
  }
  return WritePng(data.GetPointer(), "");
}

std::string Base64(std::string_view bytes)
{
  static const char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3)
  {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                       static_cast<unsigned char>(bytes[i + 2]);
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += alphabet[(v >> 6) & 63];
    out += alphabet[v & 63];
  }
  if (i < bytes.size())
  {
    const bool two = i + 1 < bytes.size();
    const unsigned v =
      (static_cast<unsigned char>(bytes[i]) << 16) | (two ? static_cast<unsigned char>(bytes[i + 1]) << 8 : 0u);
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += two ? alphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

std::string PngDataUri(const PlaneImage& image, double lowHu, double highHu)
{
  return "data:image/png;base64," + Base64(EncodeGreyPng(image, lowHu, highHu));
}

std::string EncodeRgbPng(const RenderedImage& image)
{
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() != static_cast<size_t>(image.width) * static_cast<size_t>(image.height) * 3)
    throw InputError("An RGB PNG needs a non-empty image; got " + std::to_string(image.width) + " x " +
                     std::to_string(image.height) + " pixels with " + std::to_string(image.rgb.size()) + " bytes.");
  vtkNew<vtkImageData> data;
  data->SetDimensions(image.width, image.height, 1);
  data->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(data->GetScalarPointer());
  const size_t rowBytes = static_cast<size_t>(image.width) * 3;
  for (int row = 0; row < image.height; ++row) // VTK's rows run upward
    std::copy_n(image.rgb.data() + static_cast<size_t>(row) * rowBytes, rowBytes,
                out + static_cast<size_t>(image.height - 1 - row) * rowBytes);
  return WritePng(data.GetPointer(), " RGB");
}

std::string PngDataUri(const RenderedImage& image)
{
  return "data:image/png;base64," + Base64(EncodeRgbPng(image));
}

} // namespace sgp
