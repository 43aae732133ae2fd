// Tests of the label maps' NRRD fast path (WriteLabelNrrd.h): its header is the one ITK's writer
// gives the same image, character for character, ITK's reader (zlib, through NrrdIO) inflates its
// runs to the same voxels, it leaves to ITK what it does not write, and it fails as the house does.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

#include <gtest/gtest.h>
#include <itkImageFileReader.h>
#include <itkImageFileWriter.h>
#include <itkMetaDataObject.h>

#include "Common/Errors.h"
#include "IO/WriteImage.h"
#include "IO/WriteLabelNrrd.h"
#include "TemporaryFolder.h"

namespace sgp
{
namespace
{

namespace fs = std::filesystem;

class WriteLabelNrrdTest : public testing::TemporaryFolderTest
{
protected:
  struct Geometry
  {
    double spacing[3] = { 1, 1, 1 };
    double origin[3] = { 0, 0, 0 };
    double direction[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
    long index[3] = { 0, 0, 0 };
  };

  /// A label map of odd sizes whose labels 0–4 come in runs of every length up to 40, on `g`.
  static LabelImage::Pointer MakeLabels(const Geometry& g)
  {
    auto image = LabelImage::New();
    LabelImage::RegionType region;
    region.SetIndex({ { g.index[0], g.index[1], g.index[2] } });
    region.SetSize({ { 37, 29, 23 } });
    image->SetRegions(region);
    image->Allocate();
    image->SetSpacing(g.spacing);
    image->SetOrigin(g.origin);
    LabelImage::DirectionType d;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        d(r, c) = g.direction[3 * r + c];
    image->SetDirection(d);
    unsigned char* voxel = image->GetBufferPointer();
    const long n = 37 * 29 * 23;
    for (long v = 0, run = 1, value = 0; v < n; ++run, value = (value + 3) % 5)
      for (long r = 0; r < run % 41 && v < n; ++r)
        voxel[v++] = static_cast<unsigned char>(value);
    return image;
  }

  static std::string Bytes(const fs::path& path)
  {
    std::ifstream in(path, std::ios::binary);
    return { std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>() };
  }

  static std::string Header(const fs::path& path)
  {
    const std::string bytes = Bytes(path);
    return bytes.substr(0, bytes.find("\n\n") + 2);
  }

  static LabelImage::Pointer ReadWithItk(const fs::path& path)
  {
    auto reader = itk::ImageFileReader<LabelImage>::New();
    reader->SetFileName(path.string());
    reader->Update();
    return reader->GetOutput();
  }

  static void WriteWithItk(const LabelImage& image, const fs::path& path)
  {
    auto writer = itk::ImageFileWriter<LabelImage>::New();
    writer->SetInput(&image);
    writer->SetFileName(path.string());
    writer->SetUseCompression(true);
    writer->Update();
  }

  static bool SameVoxels(const LabelImage& a, const LabelImage& b)
  {
    const auto n = a.GetPixelContainer()->Size();
    return n == b.GetPixelContainer()->Size() &&
           std::equal(a.GetBufferPointer(), a.GetBufferPointer() + n, b.GetBufferPointer());
  }

  /// The fast path's file against ITK's writer's for the same image: the same header text, and
  /// ITK reads back the image's voxels and geometry.
  void ExpectAsItkWrites(const LabelImage& image, const std::string& name)
  {
    const fs::path fast = folder / (name + ".nrrd"), itk = folder / (name + "-itk.nrrd");
    WriteLabelMap(image, fast.string());
    WriteWithItk(image, itk);
    EXPECT_EQ(Header(fast), Header(itk)) << name;
    EXPECT_NE(Bytes(fast), Bytes(itk)) << name << ": the fast path was not taken (ITK's own file)";
    const LabelImage::Pointer read = ReadWithItk(fast);
    ASSERT_EQ(read->GetLargestPossibleRegion().GetSize(), image.GetLargestPossibleRegion().GetSize()) << name;
    EXPECT_TRUE(SameVoxels(*read, image)) << name;
    // The geometry read back is the image's to the last digits of 17: ITK's reader takes spacing
    // and direction apart again from their products, and the origin of a region not starting at
    // index 0 is its first voxel's (1e-12: far above that rounding, far below any real error).
    LabelImage::PointType first;
    image.TransformIndexToPhysicalPoint(image.GetLargestPossibleRegion().GetIndex(), first);
    for (unsigned a = 0; a < 3; ++a)
    {
      EXPECT_NEAR(read->GetSpacing()[a], image.GetSpacing()[a], 1e-12) << name;
      EXPECT_NEAR(read->GetOrigin()[a], first[a], 1e-12 * std::max(1.0, std::abs(first[a]))) << name;
      for (unsigned b = 0; b < 3; ++b)
        EXPECT_NEAR(read->GetDirection()(a, b), image.GetDirection()(a, b), 1e-12) << name;
    }
  }
};

TEST_F(WriteLabelNrrdTest, Geometries_HeaderAsItksAndSameImageRead)
{
  Geometry identity;
  ExpectAsItkWrites(*MakeLabels(identity), "identity");

  Geometry ct; // a CT's: anisotropic, an origin of 17 digits
  ct = { { 0.7, 0.8, 2.5 }, { -178.85, -168.34420965866127, -144.1241446364339 } };
  ExpectAsItkWrites(*MakeLabels(ct), "ct-like");

  Geometry oblique = ct;
  const double c = std::cos(0.3), s = std::sin(0.3);
  const double rotation[9] = { c, -s, 0, s * 0.6, c * 0.6, -0.8, s * 0.8, c * 0.8, 0.6 };
  std::copy(rotation, rotation + 9, oblique.direction);
  ExpectAsItkWrites(*MakeLabels(oblique), "oblique");

  // A scan read from right-anterior-superior: two axes flipped (its zeros, −0 after the flip, stay
  // +0 in an ITK image: SetDirection keeps an entry that compares equal).
  Geometry ras = ct;
  const double flipped[9] = { -1, -0.0, 0, -0.0, -1, 0, 0, 0, 1 };
  std::copy(flipped, flipped + 9, ras.direction);
  ExpectAsItkWrites(*MakeLabels(ras), "from-ras");

  // An origin of −0: 0 where a direction row has a +0 product, −0 where all three are −0.
  Geometry odd = { { 0.1, 1.0 / 3.0, 1e-3 }, { -0.0, 1e-20, -0.0 } };
  const double r2 = 1.0 / std::sqrt(2.0), r3 = 1.0 / std::sqrt(3.0), r6 = 1.0 / std::sqrt(6.0);
  const double negativeRow[9] = { r2, -r2, 0, -r6, -r6, 2 * r6, -r3, -r3, -r3 }; // orthonormal, last row < 0
  std::copy(negativeRow, negativeRow + 9, odd.direction);
  ExpectAsItkWrites(*MakeLabels(odd), "minus-zero-origin");

  Geometry shifted = oblique; // a region not starting at index 0: the origin is its first voxel's
  shifted.index[0] = 3, shifted.index[1] = -4, shifted.index[2] = 5;
  ExpectAsItkWrites(*MakeLabels(shifted), "shifted-region");
}

TEST_F(WriteLabelNrrdTest, LongRunsEveryByteAndNoRuns_ItkReadsTheVoxels)
{
  // One row of runs from 800 bytes down to 1 (length symbol 285 and every other, with the one- and
  // two-byte remainders), every byte value, then bytes without runs: inflated by zlib this time.
  std::vector<unsigned char> row;
  for (int length = 800; length >= 1; --length)
    row.insert(row.end(), std::size_t(length), static_cast<unsigned char>(255 - (length * 11) % 256));
  for (int value = 255; value >= 0; --value)
    row.push_back(static_cast<unsigned char>(value));
  std::mt19937 random(11);
  for (int n = 0; n < 20000; ++n)
    row.push_back(static_cast<unsigned char>(random() & 0xFF));
  auto image = LabelImage::New();
  LabelImage::RegionType region;
  region.SetSize({ { row.size(), 1, 1 } });
  image->SetRegions(region);
  image->Allocate();
  std::copy(row.begin(), row.end(), image->GetBufferPointer());
  ExpectAsItkWrites(*image, "long-runs");
}

TEST_F(WriteLabelNrrdTest, OtherFormatsMetadataAndEmpty_LeftToItk)
{
  const LabelImage::Pointer image = MakeLabels(Geometry{});
  for (const std::string name : { "labels.nhdr", "labels.nii.gz", "labels.mha" })
  {
    EXPECT_FALSE(WriteLabelNrrd(*image, (folder / name).string())) << name;
    EXPECT_FALSE(fs::exists(folder / name)) << name;
    WriteLabelMap(*image, (folder / name).string()); // ITK's writer
    EXPECT_TRUE(SameVoxels(*ReadWithItk(folder / name), *image)) << name;
  }
  // Metadata to carry: ITK's writer, which writes it.
  itk::EncapsulateMetaData<std::string>(image->GetMetaDataDictionary(), "Segment0_Name", "lumen");
  EXPECT_FALSE(WriteLabelNrrd(*image, (folder / "named.nrrd").string()));
  WriteLabelMap(*image, (folder / "named.nrrd").string());
  EXPECT_NE(Header(folder / "named.nrrd").find("Segment0_Name:=lumen"), std::string::npos);
  // Nothing to write, or not all of it in memory.
  auto empty = LabelImage::New();
  LabelImage::RegionType none;
  none.SetSize({ { 0, 4, 4 } });
  empty->SetRegions(none);
  empty->Allocate();
  EXPECT_FALSE(WriteLabelNrrd(*empty, (folder / "empty.nrrd").string()));
  auto part = LabelImage::New();
  LabelImage::RegionType whole, buffered;
  whole.SetSize({ { 8, 8, 8 } });
  buffered.SetSize({ { 8, 8, 4 } });
  part->SetLargestPossibleRegion(whole);
  part->SetBufferedRegion(buffered);
  part->Allocate();
  EXPECT_FALSE(WriteLabelNrrd(*part, (folder / "part.nrrd").string()));
  EXPECT_FALSE(fs::exists(folder / "empty.nrrd") || fs::exists(folder / "part.nrrd"));
}

TEST_F(WriteLabelNrrdTest, NoFolderOrDiskFull_InputErrorAndNoFile)
{
  const LabelImage::Pointer image = MakeLabels(Geometry{});
  const auto expectError = [&](const fs::path& path, const std::string& reason)
  {
    try
    {
      WriteLabelMap(*image, path.string());
      ADD_FAILURE() << path;
    }
    catch (const InputError& e)
    {
      EXPECT_EQ(std::string(e.what()).rfind("Cannot write '" + path.string() + "': " + reason, 0), 0u) << e.what();
    }
  };
  expectError(folder / "no" / "labels.nrrd", "No such file or directory");
  // A full disk: the writes fail when the file is closed, and what was written goes.
  if (!fs::exists("/dev/full"))
    GTEST_SKIP() << "no /dev/full on this machine to fill";
  const fs::path full = folder / "full.nrrd";
  fs::create_symlink("/dev/full", full);
  expectError(full, "No space left on device");
  EXPECT_FALSE(fs::exists(fs::symlink_status(full))) << "the partial file was left";
}

} // namespace
} // namespace sgp
