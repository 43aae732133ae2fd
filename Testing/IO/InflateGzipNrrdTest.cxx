// Tests of the reader's fast path for gzip NRRD (InflateGzipNrrd.h): the voxels it inflates are the
// ones ITK reads from the same file, and it declines every file it does not read (ITK then does).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>
#include <itkImageFileReader.h>
#include <itkImageFileWriter.h>

#include "IO/InflateGzipNrrd.h"
#include "IO/ReadCtImage.h"
#include "TemporaryFolder.h"

namespace sgp
{
namespace
{

namespace fs = std::filesystem;

class InflateGzipNrrdTest : public testing::TemporaryFolderTest
{
protected:
  /// 64 × 48 × 40 voxels (240 KiB: more than the 64 pages from which the pages are mapped on the
  /// second thread) of distinct values over the whole short range, on an oblique anisotropic grid.
  template<typename Image = CtImage>
  static typename Image::Pointer MakeVolume()
  {
    auto image = Image::New();
    typename Image::RegionType region;
    region.SetSize({ { 64, 48, 40 } });
    image->SetRegions(region);
    image->Allocate();
    const double spacing[3] = { 0.7, 0.8, 2.5 }, origin[3] = { -30.5, 12.25, -400.0 };
    image->SetSpacing(spacing);
    image->SetOrigin(origin);
    typename Image::DirectionType d;
    const double c = std::cos(0.3), s = std::sin(0.3);
    d(0, 0) = c, d(0, 1) = -s, d(0, 2) = 0;
    d(1, 0) = s, d(1, 1) = c, d(1, 2) = 0;
    d(2, 0) = 0, d(2, 1) = 0, d(2, 2) = 1;
    image->SetDirection(d);
    auto* voxel = image->GetBufferPointer();
    for (long n = 0; n < 64 * 48 * 40; ++n)
      voxel[n] = static_cast<typename Image::PixelType>((n * 7919) % 65536 - 32768);
    return image;
  }

  template<typename Image>
  static void Write(const Image* image, const fs::path& path, bool compress)
  {
    auto writer = itk::ImageFileWriter<Image>::New();
    writer->SetInput(image);
    writer->SetFileName(path.string());
    writer->SetUseCompression(compress);
    writer->Update();
  }

  static std::string Bytes(const fs::path& path)
  {
    std::ifstream in(path, std::ios::binary);
    return { std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>() };
  }

  static void WriteBytes(const fs::path& path, const std::string& bytes)
  {
    std::ofstream(path, std::ios::binary) << bytes;
  }

  /// ITK's own reading of the file.
  static CtImage::Pointer ReadWithItk(const fs::path& path)
  {
    auto reader = itk::ImageFileReader<CtImage>::New();
    reader->SetFileName(path.string());
    reader->Update();
    return reader->GetOutput();
  }

  /// The fast path on `path`, into an image of ITK's geometry for it; `read` says whether it read.
  static CtImage::Pointer Inflate(const fs::path& path, bool& read)
  {
    auto reader = itk::ImageFileReader<CtImage>::New();
    reader->SetFileName(path.string());
    reader->UpdateOutputInformation();
    auto image = CtImage::New();
    image->CopyInformation(reader->GetOutput());
    image->SetRegions(reader->GetOutput()->GetLargestPossibleRegion());
    image->Allocate(true);
    read = InflateGzipNrrdInto(path.string(), *image);
    return image;
  }

  static bool SameVoxels(const CtImage& a, const CtImage& b)
  {
    const auto n = a.GetPixelContainer()->Size();
    return n == b.GetPixelContainer()->Size() &&
           std::equal(a.GetBufferPointer(), a.GetBufferPointer() + n, b.GetBufferPointer());
  }

  /// The gzip NRRD of MakeVolume() with its header line `from` replaced by `to` (or `to` added
  /// before the blank line when `from` is empty).
  fs::path EditedHeader(const std::string& name, const std::string& from, const std::string& to)
  {
    const fs::path path = folder / name;
    Write(MakeVolume().GetPointer(), path, true);
    std::string bytes = Bytes(path);
    const std::size_t at = from.empty() ? bytes.find("\n\n") + 1 : bytes.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    bytes.replace(at, from.size(), to);
    WriteBytes(path, bytes);
    return path;
  }
};

TEST_F(InflateGzipNrrdTest, ShortGzipNrrd_ReadsItksVoxels)
{
  const fs::path path = folder / "volume.nrrd";
  Write(MakeVolume().GetPointer(), path, true);
  bool read = false;
  const CtImage::Pointer fast = Inflate(path, read);
  ASSERT_TRUE(read);
  EXPECT_TRUE(SameVoxels(*ReadWithItk(path), *fast));
  EXPECT_TRUE(SameVoxels(*MakeVolume(), *fast));
  // And ReadCtImage (which takes this path for it) gives ITK's geometry with them.
  const CtImage::Pointer viaReader = ReadCtImage(path.string()).image;
  const CtImage::Pointer itk = ReadWithItk(path);
  EXPECT_TRUE(SameVoxels(*itk, *viaReader));
  EXPECT_EQ(itk->GetSpacing(), viaReader->GetSpacing());
  EXPECT_EQ(itk->GetOrigin(), viaReader->GetOrigin());
  EXPECT_EQ(itk->GetDirection(), viaReader->GetDirection());
  EXPECT_EQ(itk->GetLargestPossibleRegion(), viaReader->GetLargestPossibleRegion());
}

/// A byte label map (the plan's own, given back: ReadLumenSegmentation): inflated as ITK reads it;
/// a short volume is not taken for one, nor a byte map for a CT.
TEST_F(InflateGzipNrrdTest, ByteLabelMap_ReadsItksVoxels)
{
  auto labels = LabelImage::New();
  labels->CopyInformation(MakeVolume());
  labels->SetRegions(MakeVolume()->GetLargestPossibleRegion());
  labels->Allocate();
  for (std::size_t v = 0; v < labels->GetLargestPossibleRegion().GetNumberOfPixels(); ++v)
    labels->GetBufferPointer()[v] = static_cast<unsigned char>((v * 7919) % 253);
  const fs::path path = folder / "labels.nrrd";
  Write(labels.GetPointer(), path, true);
  auto fast = LabelImage::New();
  fast->CopyInformation(labels);
  fast->SetRegions(labels->GetLargestPossibleRegion());
  fast->Allocate(true);
  ASSERT_TRUE(InflateGzipNrrdInto(path.string(), *fast));
  EXPECT_TRUE(std::equal(labels->GetBufferPointer(),
                         labels->GetBufferPointer() + labels->GetLargestPossibleRegion().GetNumberOfPixels(),
                         fast->GetBufferPointer()));
  CtImage::Pointer wrongType = ReadWithItk(path);
  EXPECT_FALSE(InflateGzipNrrdInto(path.string(), *wrongType)); // bytes are not HU
  const fs::path volume = folder / "volume.nrrd";
  Write(MakeVolume().GetPointer(), volume, true);
  EXPECT_FALSE(InflateGzipNrrdInto(volume.string(), *fast)); // HU are not bytes
}

TEST_F(InflateGzipNrrdTest, CommentsAndKeyValuePairs_StillRead)
{
  const fs::path path = EditedHeader("comments.nrrd", "", "# a comment: with a colon\nmodality:=CT\n");
  bool read = false;
  const CtImage::Pointer fast = Inflate(path, read);
  ASSERT_TRUE(read);
  EXPECT_TRUE(SameVoxels(*MakeVolume(), *fast));
}

TEST_F(InflateGzipNrrdTest, OtherFiles_DeclinedAndReadByItk)
{
  // Another encoding, another type, detached data: written by ITK.
  Write(MakeVolume().GetPointer(), folder / "raw.nrrd", false);
  using FloatImage = itk::Image<float, 3>;
  Write(MakeVolume<FloatImage>().GetPointer(), folder / "float.nrrd", true);
  Write(MakeVolume().GetPointer(), folder / "detached.nhdr", true);
  // Header fields the fast path does not honour, in any case (NrrdIO matches field names without
  // regard to case), and a field whose value holds ":=" (a field still, for NrrdIO).
  const fs::path skip = EditedHeader("skip.nrrd", "", "byte skip: 2\n");
  const fs::path lines = EditedHeader("lines.nrrd", "", "line skip: 1\n");
  const fs::path upperSkip = EditedHeader("upper-skip.nrrd", "", "Byte Skip: 2\n");
  fs::copy_file(folder / "detached.raw.gz", folder / "detached:=copy.raw.gz");
  const fs::path upperDataFile = EditedHeader("upper-data-file.nrrd", "", "DATA FILE: detached.raw.gz\n");
  const fs::path keyValueLike = EditedHeader("key-value-like.nrrd", "", "data file: detached:=copy.raw.gz\n");
  const fs::path big = EditedHeader("big.nrrd", "endian: little", "endian: big");
  const fs::path crlf = folder / "crlf.nrrd";
  {
    std::string bytes = Bytes(folder / "raw.nrrd");
    const std::size_t end = bytes.find("\n\n");
    std::string header = bytes.substr(0, end + 2), converted;
    for (char c : header)
      converted += c == '\n' ? std::string("\r\n") : std::string(1, c);
    WriteBytes(crlf, converted + bytes.substr(end + 2));
  }
  for (const fs::path& path : { folder / "raw.nrrd", folder / "float.nrrd", folder / "detached.nhdr", skip, lines,
                                upperSkip, upperDataFile, keyValueLike, big, crlf })
  {
    SCOPED_TRACE(path.filename().string());
    bool read = true;
    Inflate(path, read);
    EXPECT_FALSE(read);
  }
  // The volumes ITK reads as it always has (the big-endian one aside: its header lies).
  for (const fs::path& path : { folder / "raw.nrrd", folder / "detached.nhdr", crlf })
  {
    SCOPED_TRACE(path.filename().string());
    EXPECT_TRUE(SameVoxels(*MakeVolume(), *ReadCtImage(path.string()).image));
  }
}

TEST_F(InflateGzipNrrdTest, DataNotExactlyOneMemberOfTheSize_Declined)
{
  const fs::path path = folder / "volume.nrrd";
  Write(MakeVolume().GetPointer(), path, true);
  const std::string bytes = Bytes(path);
  const fs::path truncated = folder / "truncated.nrrd", trailing = folder / "trailing.nrrd",
                 corrupt = folder / "corrupt.nrrd";
  WriteBytes(truncated, bytes.substr(0, bytes.size() - 100));
  WriteBytes(trailing, bytes + "trailing bytes");
  std::string flipped = bytes;
  flipped[bytes.size() / 2] = static_cast<char>(flipped[bytes.size() / 2] ^ 0x5a);
  WriteBytes(corrupt, flipped);
  for (const fs::path& p : { truncated, trailing, corrupt })
  {
    SCOPED_TRACE(p.filename().string());
    bool read = true;
    Inflate(p, read);
    EXPECT_FALSE(read);
  }
  // ITK then reports the truncated file as unreadable, with the path named.
  try
  {
    ReadCtImage(truncated.string());
    ADD_FAILURE() << "a truncated file was read";
  }
  catch (const std::exception& e)
  {
    EXPECT_EQ(std::string(e.what()).rfind("Cannot read the input volume '" + truncated.string() + "': ", 0), 0u)
      << e.what();
  }
}

} // namespace
} // namespace sgp
