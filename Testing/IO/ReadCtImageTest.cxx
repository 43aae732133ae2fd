// Tests of ReadCtImage: every supported format gives back the same physical volume.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include <gtest/gtest.h>
#include <itkGDCMImageIO.h>
#include <itkImageFileWriter.h>
#include <itkImageRegionConstIteratorWithIndex.h>
#include <itkImageSeriesWriter.h>
#include <itkMetaDataObject.h>
#include <itkRGBPixel.h>

#include "Common/Errors.h"
#include "Common/ImageGeometry.h"
#include "IO/ReadCtImage.h"
#include "TemporaryFolder.h"

namespace sgp
{
namespace
{

namespace fs = std::filesystem;

class ReadCtImageTest : public testing::TemporaryFolderTest
{
protected:
  /// 20 × 16 × 12 voxels of distinct values on an anisotropic grid; `oblique` rotates it.
  static CtImage::Pointer MakeRamp(bool oblique)
  {
    auto image = CtImage::New();
    CtImage::RegionType region;
    region.SetSize({ { 20, 16, 12 } });
    image->SetRegions(region);
    image->Allocate();
    const double spacing[3] = { 0.7, 0.8, 2.5 };
    const double origin[3] = { -30.5, 12.25, -400.0 };
    image->SetSpacing(spacing);
    image->SetOrigin(origin);
    if (oblique)
    {
      CtImage::DirectionType d;
      const double c = std::cos(0.3), s = std::sin(0.3);
      d(0, 0) = c, d(0, 1) = -s, d(0, 2) = 0;
      d(1, 0) = s, d(1, 1) = c, d(1, 2) = 0;
      d(2, 0) = 0, d(2, 1) = 0, d(2, 2) = 1;
      image->SetDirection(d);
    }
    for (long k = 0; k < 12; ++k)
      for (long j = 0; j < 16; ++j)
        for (long i = 0; i < 20; ++i)
          image->SetPixel({ { i, j, k } }, static_cast<short>(i + 20 * j + 320 * k - 1000));
    return image;
  }

  template<typename Image>
  static void Write(const Image* image, const fs::path& path, bool compress = true)
  {
    auto writer = itk::ImageFileWriter<Image>::New();
    writer->SetInput(image);
    writer->SetFileName(path.string());
    writer->SetUseCompression(compress);
    writer->Update();
  }

  /// Every voxel of `expected` has the same value at the same physical point in `actual`.
  static void ExpectSamePhysicalVolume(const CtImage& expected, const CtImage& actual, double geometryTolerance)
  {
    ASSERT_EQ(expected.GetLargestPossibleRegion().GetNumberOfPixels(),
              actual.GetLargestPossibleRegion().GetNumberOfPixels());
    long mismatches = 0;
    itk::ImageRegionConstIteratorWithIndex<CtImage> it(&expected, expected.GetLargestPossibleRegion());
    for (; !it.IsAtEnd(); ++it)
    {
      const Point3 p = IndexToLps(expected, it.GetIndex());
      itk::ContinuousIndex<double, 3> c;
      actual.TransformPhysicalPointToContinuousIndex(itk::Point<double, 3>(p.data()), c);
      itk::Index<3> index;
      for (unsigned a = 0; a < 3; ++a)
      {
        index[a] = std::lround(c[a]);
        EXPECT_NEAR(c[a], double(index[a]), geometryTolerance);
      }
      mismatches += actual.GetPixel(index) != it.Get();
    }
    EXPECT_EQ(mismatches, 0);
  }

  static std::string MessageOf(const std::string& path)
  {
    try
    {
      ReadCtImage(path);
    }
    catch (const InputError& e)
    {
      return e.what();
    }
    return "(no InputError)";
  }
};

// ITK stores NRRD and MetaImage geometry as decimal text: exact to 1e-6 of a voxel.
constexpr double textGeometryTolerance = 1e-6;
// NIfTI keeps the direction as a float quaternion: ~1e-7 relative, so 1e-4 of a voxel.
constexpr double niftiGeometryTolerance = 1e-4;

TEST_F(ReadCtImageTest, EveryFileFormat_SamePhysicalVolume)
{
  const auto ramp = MakeRamp(true);
  const std::vector<std::pair<std::string, bool>> files{ { "ramp.nrrd", true }, { "ramp-raw.nrrd", false },
                                                         { "ramp.nii", false }, { "ramp.nii.gz", true },
                                                         { "ramp.mha", true },  { "ramp.mhd", false } };
  for (const auto& [name, compress] : files)
  {
    SCOPED_TRACE(name);
    Write(ramp.GetPointer(), folder / name, compress);
    const CtVolume volume = ReadCtImage((folder / name).string());
    ExpectSamePhysicalVolume(*ramp, *volume.image,
                             name.find(".nii") != std::string::npos ? niftiGeometryTolerance : textGeometryTolerance);
    EXPECT_TRUE(volume.warnings.empty());
  }
}

TEST_F(ReadCtImageTest, NrrdStoredInRasSpace_SamePhysicalVolumeAsLps)
{
  const auto ramp = MakeRamp(false);
  // The same data with i and j reversed, described in right-anterior-superior space.
  const double s0 = 0.7, s1 = 0.8, s2 = 2.5;
  const double lastX = -30.5 + s0 * 19, lastY = 12.25 + s1 * 15;
  const fs::path path = folder / "ramp-ras.nrrd";
  {
    std::ofstream out(path, std::ios::binary);
    out << "NRRD0004\ntype: short\ndimension: 3\nspace: right-anterior-superior\nsizes: 20 16 12\n"
        << "space directions: (" << s0 << ",0,0) (0," << s1 << ",0) (0,0," << s2 << ")\n"
        << "kinds: domain domain domain\nendian: little\nencoding: raw\n"
        << "space origin: (" << -lastX << "," << -lastY << ",-400)\n\n";
    for (long k = 0; k < 12; ++k)
      for (long j = 15; j >= 0; --j)
        for (long i = 19; i >= 0; --i)
        {
          const short v = ramp->GetPixel({ { i, j, k } });
          out.write(reinterpret_cast<const char*>(&v), sizeof v); // little-endian machine
        }
  }
  const CtVolume volume = ReadCtImage(path.string());
  EXPECT_EQ(volume.image->GetDirection()(0, 0), -1.0); // index i grows toward patient right
  ExpectSamePhysicalVolume(*ramp, *volume.image, textGeometryTolerance);
}

/// Writes `image` as a DICOM CT series of one file per slice into `folder`.
void WriteDicomSeries(const CtImage::Pointer& image,
                      const fs::path& folder,
                      const std::string& seriesUid,
                      const std::string& prefix)
{
  using Slice = itk::Image<short, 2>;
  auto writer = itk::ImageSeriesWriter<CtImage, Slice>::New();
  auto io = itk::GDCMImageIO::New();
  io->KeepOriginalUIDOn();
  std::vector<std::unique_ptr<itk::MetaDataDictionary>> dictionaries;
  itk::ImageSeriesWriter<CtImage, Slice>::DictionaryArrayType pointers;
  std::vector<std::string> names;
  const auto slices = static_cast<int>(image->GetLargestPossibleRegion().GetSize()[2]);
  const auto spacing = image->GetSpacing();
  for (int k = 0; k < slices; ++k)
  {
    auto dictionary = std::make_unique<itk::MetaDataDictionary>();
    const Point3 position = IndexToLps(*image, { { 0, 0, k } });
    char text[256];
    std::snprintf(text, sizeof text, "%.4f\\%.4f\\%.4f", position.x(), position.y(), position.z());
    itk::EncapsulateMetaData<std::string>(*dictionary, "0020|0032", text);
    itk::EncapsulateMetaData<std::string>(*dictionary, "0020|0037", "1\\0\\0\\0\\1\\0");
    std::snprintf(text, sizeof text, "%.4f\\%.4f", spacing[1], spacing[0]); // row, column spacing
    itk::EncapsulateMetaData<std::string>(*dictionary, "0028|0030", text);
    itk::EncapsulateMetaData<std::string>(*dictionary, "0018|0050", std::to_string(spacing[2]));
    itk::EncapsulateMetaData<std::string>(*dictionary, "0020|0013", std::to_string(k + 1));
    itk::EncapsulateMetaData<std::string>(*dictionary, "0008|0060", "CT");
    itk::EncapsulateMetaData<std::string>(*dictionary, "0008|0016", "1.2.840.10008.5.1.4.1.1.2");
    itk::EncapsulateMetaData<std::string>(*dictionary, "0008|0018", seriesUid + ".7." + std::to_string(k + 1));
    itk::EncapsulateMetaData<std::string>(*dictionary, "0020|000d", "1.2.826.0.1.3680043.2.1125.5");
    itk::EncapsulateMetaData<std::string>(*dictionary, "0020|000e", seriesUid);
    itk::EncapsulateMetaData<std::string>(*dictionary, "0020|0052", "1.2.826.0.1.3680043.2.1125.8");
    itk::EncapsulateMetaData<std::string>(*dictionary, "0028|1052", "0"); // rescale intercept
    itk::EncapsulateMetaData<std::string>(*dictionary, "0028|1053", "1"); // rescale slope
    pointers.push_back(dictionary.get());
    dictionaries.push_back(std::move(dictionary));
    names.push_back((folder / (prefix + std::string(1, char('a' + k)) + ".dcm")).string());
  }
  writer->SetInput(image);
  writer->SetImageIO(io);
  writer->SetFileNames(names);
  writer->SetMetaDataDictionaryArray(&pointers);
  writer->Update();
}

TEST_F(ReadCtImageTest, DicomSeriesFolder_SamePhysicalVolume)
{
  const auto ramp = MakeRamp(false);
  WriteDicomSeries(ramp, folder, "1.2.826.0.1.3680043.2.1125.6", "slice");
  const CtVolume volume = ReadCtImage(folder.string());
  // DICOM stores positions as decimal strings with 4 decimals here: 1e-3 of a voxel.
  ExpectSamePhysicalVolume(*ramp, *volume.image, 1e-3);
  EXPECT_TRUE(volume.warnings.empty());
}

TEST_F(ReadCtImageTest, TwoDicomSeriesInFolder_ReadsLargestAndWarns)
{
  const auto ramp = MakeRamp(false);
  WriteDicomSeries(ramp, folder, "1.2.826.0.1.3680043.2.1125.6", "big");
  CtImage::RegionType few;
  few.SetSize({ { 20, 16, 3 } });
  auto small = CtImage::New();
  small->CopyInformation(ramp);
  small->SetRegions(few);
  small->Allocate(true);
  WriteDicomSeries(small, folder, "1.2.826.0.1.3680043.2.1125.9", "small");
  const CtVolume volume = ReadCtImage(folder.string());
  ExpectSamePhysicalVolume(*ramp, *volume.image, 1e-3);
  ASSERT_EQ(volume.warnings.size(), 1u);
  EXPECT_NE(volume.warnings[0].find("holds 2 DICOM series; read the largest (12 slices"), std::string::npos)
    << volume.warnings[0];
}

TEST_F(ReadCtImageTest, SingleDicomSlice_InputErrorSays2D)
{
  const auto ramp = MakeRamp(false);
  WriteDicomSeries(ramp, folder, "1.2.826.0.1.3680043.2.1125.6", "slice");
  for (char c = 'b'; c < 'a' + 12; ++c)
  {
    fs::remove(folder / (std::string("slice") + c + ".dcm"));
  }
  EXPECT_EQ(MessageOf(folder.string()),
            "The input volume '" + folder.string() + "' is 2-D (a DICOM series of 1 slice); expected a 3-D CT volume.");
}

TEST_F(ReadCtImageTest, FloatPixels_AcceptedAsHu)
{
  auto image = itk::Image<float, 3>::New();
  itk::Image<float, 3>::RegionType region;
  region.SetSize({ { 4, 4, 4 } });
  image->SetRegions(region);
  image->Allocate();
  image->FillBuffer(350.75f);
  Write(image.GetPointer(), folder / "float.nrrd");
  const CtVolume volume = ReadCtImage((folder / "float.nrrd").string());
  EXPECT_EQ(volume.image->GetPixel({ { 1, 2, 3 } }), 350); // truncated toward zero, as documented
}

TEST_F(ReadCtImageTest, TwoDimensionalImage_InputErrorSays2D)
{
  auto image = itk::Image<short, 2>::New();
  itk::Image<short, 2>::RegionType region;
  region.SetSize({ { 32, 24 } });
  image->SetRegions(region);
  image->Allocate(true);
  const fs::path path = folder / "slice.nrrd";
  Write(image.GetPointer(), path);
  EXPECT_EQ(MessageOf(path.string()),
            "The input volume '" + path.string() + "' is 2-D (32 × 24 voxels); expected a 3-D CT volume.");
}

TEST_F(ReadCtImageTest, SingleSliceVolume_InputErrorSays2D)
{
  auto image = CtImage::New();
  CtImage::RegionType region;
  region.SetSize({ { 32, 24, 1 } });
  image->SetRegions(region);
  image->Allocate(true);
  const fs::path path = folder / "one-slice.mha";
  Write(image.GetPointer(), path);
  EXPECT_NE(MessageOf(path.string()).find("is 2-D (32 × 24 × 1 voxels)"), std::string::npos);
}

TEST_F(ReadCtImageTest, RgbImage_InputErrorNamesComponents)
{
  using Rgb = itk::Image<itk::RGBPixel<unsigned char>, 3>;
  auto image = Rgb::New();
  Rgb::RegionType region;
  region.SetSize({ { 4, 4, 4 } });
  image->SetRegions(region);
  image->Allocate(true);
  const fs::path path = folder / "rgb.mha";
  Write(image.GetPointer(), path);
  EXPECT_NE(MessageOf(path.string()).find("has 3 components per voxel"), std::string::npos) << MessageOf(path.string());
}

TEST_F(ReadCtImageTest, MissingFile_InputErrorNamesPath)
{
  const std::string path = (folder / "absent.nrrd").string();
  EXPECT_EQ(MessageOf(path),
            "Cannot read the input volume '" + path + "': the file does not exist; give a readable 3-D CT volume.");
}

TEST_F(ReadCtImageTest, GarbageFile_InputErrorNamesPath)
{
  const fs::path path = folder / "garbage.nrrd";
  std::ofstream(path) << "this is not an image\n";
  EXPECT_EQ(MessageOf(path.string()), "Cannot read the input volume '" + path.string() +
                                        "': no reader recognises it (expected NRRD, NIfTI, MetaImage or a DICOM "
                                        "folder); give a readable 3-D CT volume.");
}

TEST_F(ReadCtImageTest, TruncatedNrrd_InputErrorNamesPath)
{
  const fs::path path = folder / "truncated.nrrd";
  std::ofstream(path) << "NRRD0004\ntype: short\ndimension: 3\nsizes: 10 10 10\nencoding: raw\nendian: little\n\nab";
  const std::string message = MessageOf(path.string());
  EXPECT_EQ(message.rfind("Cannot read the input volume '" + path.string() + "': ", 0), 0u) << message;
}

TEST_F(ReadCtImageTest, EmptyDicomFolder_InputErrorSaysNoSeries)
{
  EXPECT_NE(MessageOf(folder.string()).find("the folder holds no DICOM series"), std::string::npos);
}

} // namespace
} // namespace sgp
