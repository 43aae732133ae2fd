// Tests of the label maps' run-length gzip (GzipRuns.h) and of the NRRD fast path that writes it
// (WriteImage.h): two independent inflaters — libdeflate's and ITK's reader (zlib, through NrrdIO)
// — give back every byte, and the header is the one ITK's writer gives the same image.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <itkImageFileReader.h>
#include <itkImageFileWriter.h>
#include <itkMetaDataObject.h>
#include <libdeflate.h>

#include "Common/Errors.h"
#include "IO/GzipRuns.h"
#include "IO/WriteImage.h"
#include "TemporaryFolder.h"

namespace sgp
{
namespace
{

namespace fs = std::filesystem;

/// The bytes libdeflate inflates from `member`, which must be one whole gzip member whose CRC-32
/// and size match what it inflates to (libdeflate checks both).
std::vector<unsigned char> Inflate(const std::string& member, std::size_t size)
{
  std::vector<unsigned char> out(size + 1);
  libdeflate_decompressor* inflater = libdeflate_alloc_decompressor();
  std::size_t used = 0, written = 0;
  const libdeflate_result result =
    libdeflate_gzip_decompress_ex(inflater, member.data(), member.size(), out.data(), out.size(), &used, &written);
  libdeflate_free_decompressor(inflater);
  EXPECT_EQ(result, LIBDEFLATE_SUCCESS);
  EXPECT_EQ(used, member.size()); // nothing after the member
  out.resize(result == LIBDEFLATE_SUCCESS ? written : 0);
  return out;
}

void ExpectRoundTrip(const std::vector<unsigned char>& data, const std::string& what)
{
  const std::string member = GzipRuns(data.data(), data.size());
  EXPECT_EQ(Inflate(member, data.size()), data) << what;
}

TEST(GzipRunsTest, EmptyAndSingleByte_Inflate)
{
  ExpectRoundTrip({}, "empty");
  ExpectRoundTrip({ 0 }, "one zero");
  ExpectRoundTrip({ 255 }, "one 255");
}

TEST(GzipRunsTest, RunsOfEveryLength_Inflate)
{
  // Every run length from 1 to 800 (every length symbol and extra-bit value, 258 exactly, and
  // the remainders of one and two bytes after whole 258-byte copies), each of a byte other than its
  // neighbours', over all 256 byte values (the 8- and the 9-bit literal codes).
  std::vector<unsigned char> data;
  for (int length = 1; length <= 800; ++length)
    data.insert(data.end(), std::size_t(length), static_cast<unsigned char>((length * 37) % 256));
  ExpectRoundTrip(data, "runs 1..800");
  for (int value = 0; value < 256; ++value)
    data.insert(data.end(), std::size_t(value % 5 + 1), static_cast<unsigned char>(value));
  ExpectRoundTrip(data, "every byte value");
}

TEST(GzipRunsTest, BytesWithoutRuns_InflateWithinNineBitsEach)
{
  std::mt19937 random(7);
  std::vector<unsigned char> data(65536);
  for (unsigned char& b : data)
    b = static_cast<unsigned char>(random() & 0xFF);
  const std::string member = GzipRuns(data.data(), data.size());
  EXPECT_EQ(Inflate(member, data.size()), data);
  // At most 9 bits a literal; header, block header, end of block and trailer 21 bytes.
  EXPECT_LE(member.size(), data.size() * 9 / 8 + 21);
}

TEST(GzipRunsTest, LabelMapOfRuns_SmallAndRoundTrips)
{
  // A 200 × 150 × 60 label map: empty but for a box of label 1 with a shell of 2 and a few 3s, the
  // shape of a lumen map. Copies of 258 zeros cost 13 bits, so 1.8 MB of mostly zeros must fit
  // in a few kilobytes; coded a literal a byte it would take 2 MB.
  const long nx = 200, ny = 150, nz = 60;
  std::vector<unsigned char> data(std::size_t(nx * ny * nz), 0);
  for (long k = 10; k < 50; ++k)
    for (long j = 40; j < 110; ++j)
      for (long i = 60; i < 140; ++i)
      {
        const bool shell = i < 63 || i >= 137 || j < 43 || j >= 107;
        data[std::size_t(i + nx * (j + ny * k))] = shell ? ((i + j + k) % 17 == 0 ? 3 : 2) : 1;
      }
  const std::string member = GzipRuns(data.data(), data.size());
  EXPECT_EQ(Inflate(member, data.size()), data);
  // The most a run may cost: its first byte a literal (≤ 9 bits), 13 bits for each whole 258-byte
  // copy, then a shorter copy (≤ 8 + 5 + 5 bits) or one or two literals; plus 21 bytes of frame.
  double bits = 0.0;
  for (std::size_t n = 0; n < data.size();)
  {
    std::size_t run = 1;
    while (n + run < data.size() && data[n + run] == data[n])
      ++run;
    const std::size_t rest = (run - 1) % 258;
    bits += 9.0 + 13.0 * double((run - 1) / 258) + (rest >= 3 ? 18.0 : 9.0 * double(rest));
    n += run;
  }
  EXPECT_LE(double(member.size()), std::ceil(bits / 8.0) + 21.0);
  EXPECT_LT(member.size(), data.size() / 20); // so under 5 % of the 1.8 MB: a literal a byte would be 100 %
}

class WriteLabelNrrdTest : public testing::TemporaryFolderTest
{
protected:
  /// A label map of odd sizes whose labels 0–4 come in runs of every length up to 40, on the
  /// geometry given.
  static LabelImage::Pointer MakeLabels(const double spacing[3], const double origin[3], const double direction[9])
  {
    auto image = LabelImage::New();
    LabelImage::RegionType region;
    region.SetSize({ { 37, 29, 23 } });
    image->SetRegions(region);
    image->Allocate();
    image->SetSpacing(spacing);
    image->SetOrigin(origin);
    LabelImage::DirectionType d;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        d(r, c) = direction[3 * r + c];
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

  /// The fast path's file against ITK's writer's for the same image: the same header text, and
  /// ITK reads back the image's voxels and, bit for bit, the geometry it reads from its own file
  /// (the image's own, but for the last bit of an oblique direction's products, which 17 digits
  /// carry as ITK's writer rounds them).
  void ExpectAsItkWrites(const LabelImage& image, const std::string& name)
  {
    const fs::path fast = folder / (name + ".nrrd"), itk = folder / (name + "-itk.nrrd");
    WriteLabelMap(image, fast.string());
    WriteWithItk(image, itk);
    EXPECT_EQ(Header(fast), Header(itk)) << name;
    EXPECT_NE(Bytes(fast), Bytes(itk)) << name << ": the fast path was not taken (ITK's own file)";
    const LabelImage::Pointer read = ReadWithItk(fast), reference = ReadWithItk(itk);
    EXPECT_EQ(read->GetLargestPossibleRegion(), image.GetLargestPossibleRegion());
    EXPECT_EQ(read->GetSpacing(), reference->GetSpacing()) << name;
    EXPECT_EQ(read->GetOrigin(), reference->GetOrigin()) << name;
    EXPECT_EQ(read->GetDirection(), reference->GetDirection()) << name;
    const auto n = image.GetPixelContainer()->Size();
    EXPECT_TRUE(std::equal(image.GetBufferPointer(), image.GetBufferPointer() + n, read->GetBufferPointer())) << name;
  }
};

TEST_F(WriteLabelNrrdTest, Geometries_HeaderAsItksAndSameImageRead)
{
  const double identity[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  const double c = std::cos(0.3), s = std::sin(0.3);
  const double oblique[9] = { c, -s, 0, s * 0.6, c * 0.6, -0.8, s * 0.8, c * 0.8, 0.6 };
  const double flipped[9] = { -1, 0, 0, 0, 1, 0, 0, 0, -1 };
  const double spacing[3] = { 0.7, 0.8, 2.5 }, unit[3] = { 1, 1, 1 }, fine[3] = { 0.1, 1.0 / 3.0, 1e-3 };
  const double origin[3] = { -178.85, -168.34420965866127, -144.1241446364339 };
  const double odd[3] = { -0.0, 1e-20, 123456.789 }, zero[3] = { 0, 0, 0 };
  ExpectAsItkWrites(*MakeLabels(unit, zero, identity), "identity");
  ExpectAsItkWrites(*MakeLabels(spacing, origin, identity), "ct-like");
  ExpectAsItkWrites(*MakeLabels(spacing, origin, oblique), "oblique");
  ExpectAsItkWrites(*MakeLabels(fine, odd, flipped), "flipped-odd-numbers");
}

TEST_F(WriteLabelNrrdTest, OtherFormatsAndMetadata_WrittenByItk)
{
  const double identity[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 }, spacing[3] = { 0.7, 0.8, 2.5 }, origin[3] = { 1, 2, 3 };
  const LabelImage::Pointer image = MakeLabels(spacing, origin, identity);
  for (const std::string name : { "labels.nhdr", "labels.nii.gz", "labels.mha" })
  {
    WriteLabelMap(*image, (folder / name).string());
    const LabelImage::Pointer read = ReadWithItk(folder / name);
    const auto n = image->GetPixelContainer()->Size();
    EXPECT_TRUE(std::equal(image->GetBufferPointer(), image->GetBufferPointer() + n, read->GetBufferPointer())) << name;
  }
  // Metadata to carry: ITK's writer, which writes it.
  itk::EncapsulateMetaData<std::string>(image->GetMetaDataDictionary(), "Segment0_Name", "lumen");
  WriteLabelMap(*image, (folder / "named.nrrd").string());
  EXPECT_NE(Header(folder / "named.nrrd").find("Segment0_Name:=lumen"), std::string::npos);
}

TEST_F(WriteLabelNrrdTest, UnwritablePath_InputErrorAndNoFile)
{
  const double identity[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 }, unit[3] = { 1, 1, 1 }, zero[3] = { 0, 0, 0 };
  const fs::path path = folder / "labels.nrrd";
  fs::create_directory(path); // a folder where the file should go
  try
  {
    WriteLabelMap(*MakeLabels(unit, zero, identity), path.string());
    ADD_FAILURE();
  }
  catch (const InputError& e)
  {
    EXPECT_EQ(std::string(e.what()).rfind("Cannot write '" + path.string() + "': ", 0), 0u) << e.what();
  }
  EXPECT_TRUE(fs::is_directory(path));
}

} // namespace
} // namespace sgp
