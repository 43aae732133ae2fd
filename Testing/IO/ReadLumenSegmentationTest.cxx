// Issue 45 item 1: the lumen segmentation a person gives — TotalSegmentator's NIfTI map, a plain
// NRRD label map, Slicer's .seg.nrrd with named segments (one layer, and overlapping segments in
// layers as Slicer writes them) — and the labels chosen from it.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <itkImageFileWriter.h>

#include "Common/Errors.h"
#include "IO/ReadLumenSegmentation.h"
#include "TemporaryFolder.h"

namespace sgp
{
namespace
{

namespace fs = std::filesystem;
using LabelMap16 = itk::Image<std::uint16_t, 3>;

constexpr long nx = 12, ny = 10, nz = 8;

/// The map's labels by voxel: 52 (aorta) in i < 4, 63 (vein) in 4 ≤ i < 6, 65 and 66 (iliacs)
/// in 6 ≤ i < 9 by the half of j, 0 beyond; `k` ≥ 1 only (the first slice empty).
std::uint16_t LabelAt(long i, long j, long k)
{
  if (k == 0 || i >= 9)
    return 0;
  return i < 4 ? 52 : i < 6 ? 63 : j < ny / 2 ? 65 : 66;
}

LabelMap16::Pointer MakeMap()
{
  auto image = LabelMap16::New();
  LabelMap16::RegionType region;
  region.SetSize({ { nx, ny, nz } });
  image->SetRegions(region);
  image->Allocate();
  const double spacing[3] = { 0.8, 0.8, 2.5 }, origin[3] = { -10.0, 20.0, -300.0 };
  image->SetSpacing(spacing);
  image->SetOrigin(origin);
  for (long k = 0; k < nz; ++k)
    for (long j = 0; j < ny; ++j)
      for (long i = 0; i < nx; ++i)
        image->SetPixel({ { i, j, k } }, LabelAt(i, j, k));
  return image;
}

/// The mask's voxels that are 1, as flat indices.
long CountWhere(const LabelImage& mask, const std::vector<std::uint16_t>& labels)
{
  long mismatches = 0;
  for (long k = 0; k < nz; ++k)
    for (long j = 0; j < ny; ++j)
      for (long i = 0; i < nx; ++i)
      {
        const bool expected = std::find(labels.begin(), labels.end(), LabelAt(i, j, k)) != labels.end();
        mismatches += (mask.GetPixel({ { i, j, k } }) != 0) != expected;
      }
  return mismatches;
}

std::string ErrorOf(const std::string& path, const std::string& labels)
{
  try
  {
    ReadLumenSegmentation(path, labels);
  }
  catch (const InputError& e)
  {
    return e.what();
  }
  return "";
}

/// A Slicer segmentation NRRD written as Slicer writes it (raw data here): one layer of labels, or
/// (layered) two layers in a leading `list` axis; `segments` lines are `SegmentN_…:=…` fields.
void WriteSegNrrd(const fs::path& path, bool layered, const std::vector<std::string>& segments)
{
  std::ofstream out(path, std::ios::binary);
  out << "NRRD0004\ntype: unsigned char\n";
  out << (layered ? "dimension: 4\nspace: left-posterior-superior\nsizes: 2 "
                  : "dimension: 3\nspace: "
                    "left-posterior-superior\nsizes: ")
      << nx << " " << ny << " " << nz << "\n";
  out << "space directions: " << (layered ? "none " : "") << "(0.8,0,0) (0,0.8,0) (0,0,2.5)\n";
  out << "kinds: " << (layered ? "list " : "") << "domain domain domain\nencoding: raw\n";
  out << "space origin: (-10,20,-300)\n";
  for (const std::string& s : segments)
    out << s << "\n";
  out << "\n";
  for (long k = 0; k < nz; ++k)
    for (long j = 0; j < ny; ++j)
      for (long i = 0; i < nx; ++i)
      {
        const std::uint16_t label = LabelAt(i, j, k);
        if (!layered)
          out.put(static_cast<char>(label == 52 ? 1 : label == 63 ? 2 : label == 65 || label == 66 ? 3 : 0));
        else
        {
          out.put(static_cast<char>(label == 52 || label == 65 || label == 66 ? 1 : 0)); // layer 0: arteries
          out.put(static_cast<char>(label == 63 || label == 52 ? 1 : 0));                // layer 1: overlaps the aorta
        }
      }
}

class ReadLumenSegmentationTest : public testing::TemporaryFolderTest
{
};

/// TotalSegmentator's map (.nii.gz): the chosen labels and no other voxel; the grid kept.
TEST_F(ReadLumenSegmentationTest, NiftiLabelsChosen)
{
  const fs::path path = folder / "total.nii.gz";
  auto writer = itk::ImageFileWriter<LabelMap16>::New();
  writer->SetInput(MakeMap());
  writer->SetFileName(path.string());
  writer->Update();
  const GivenLumenFile file = ReadLumenSegmentation(path.string(), "52, 65,66");
  EXPECT_EQ(CountWhere(*file.mask, { 52, 65, 66 }), 0);
  EXPECT_EQ(file.description, "labels 52, 65, 66 of 'total.nii.gz'");
  EXPECT_NEAR(file.mask->GetSpacing()[2], 2.5, 1e-6);
  EXPECT_NEAR(file.mask->GetOrigin()[1], 20.0, 1e-6);
  EXPECT_EQ(CountWhere(*ReadLumenSegmentation(path.string(), "63").mask, { 63 }), 0);
}

/// The default with several labels is refused, listing them: a vein is never taken for the aorta.
TEST_F(ReadLumenSegmentationTest, SeveralLabelsNeedChoosing)
{
  const fs::path path = folder / "total.nrrd";
  auto writer = itk::ImageFileWriter<LabelMap16>::New();
  writer->SetInput(MakeMap());
  writer->SetFileName(path.string());
  writer->Update();
  const std::string what = ErrorOf(path.string(), "");
  EXPECT_NE(what.find("holds 4 labels"), std::string::npos) << what;
  for (const char* label : { "52 (", "63 (", "65 (", "66 (", "lumenLabels" })
    EXPECT_NE(what.find(label), std::string::npos) << label << ": " << what;
  const std::string none = ErrorOf(path.string(), "99");
  EXPECT_NE(none.find("No voxel"), std::string::npos) << none;
  EXPECT_NE(none.find("(99)"), std::string::npos) << none;
  EXPECT_NE(none.find("63 ("), std::string::npos) << none; // what it holds
  const std::string word = ErrorOf(path.string(), "aorta");
  EXPECT_NE(word.find("'aorta', which is neither a segment"), std::string::npos) << word;
}

/// One label: the default takes every non-zero voxel.
TEST_F(ReadLumenSegmentationTest, OneLabelTakenByDefault)
{
  auto map = MakeMap();
  for (std::size_t v = 0; v < map->GetLargestPossibleRegion().GetNumberOfPixels(); ++v)
    if (map->GetBufferPointer()[v] != 52)
      map->GetBufferPointer()[v] = 0;
  const fs::path path = folder / "aorta.mha";
  auto writer = itk::ImageFileWriter<LabelMap16>::New();
  writer->SetInput(map);
  writer->SetFileName(path.string());
  writer->Update();
  const GivenLumenFile file = ReadLumenSegmentation(path.string(), "");
  EXPECT_EQ(CountWhere(*file.mask, { 52 }), 0);
  EXPECT_EQ(file.description, "every non-zero voxel of 'aorta.mha'");
}

/// A .seg.nrrd: segments chosen by name, without regard to case; an unknown name lists them.
TEST_F(ReadLumenSegmentationTest, SegNrrdByName)
{
  const fs::path path = folder / "case.seg.nrrd";
  WriteSegNrrd(path, false,
               { "Segment0_ID:=Segment_1", "Segment0_Name:=Aorta", "Segment0_LabelValue:=1", "Segment0_Layer:=0",
                 "Segment1_ID:=Segment_2", "Segment1_Name:=Inferior vena cava", "Segment1_LabelValue:=2",
                 "Segment1_Layer:=0", "Segment2_ID:=Segment_3", "Segment2_Name:=Iliac arteries",
                 "Segment2_LabelValue:=3", "Segment2_Layer:=0" });
  const GivenLumenFile file = ReadLumenSegmentation(path.string(), "aorta,ILIAC ARTERIES");
  EXPECT_EQ(CountWhere(*file.mask, { 52, 65, 66 }), 0);
  EXPECT_EQ(file.description, "'Aorta', 'Iliac arteries' of 'case.seg.nrrd'");
  const std::string what = ErrorOf(path.string(), "kidney");
  EXPECT_NE(what.find("'Aorta', 'Inferior vena cava', 'Iliac arteries'"), std::string::npos) << what;
  const std::string all = ErrorOf(path.string(), "");
  EXPECT_NE(all.find("'Inferior vena cava'"), std::string::npos) << all;
}

/// Overlapping segments in layers (Slicer's 4-D .seg.nrrd): each segment from its own layer.
TEST_F(ReadLumenSegmentationTest, SegNrrdLayers)
{
  const fs::path path = folder / "layers.seg.nrrd";
  WriteSegNrrd(path, true,
               { "Segment0_ID:=a", "Segment0_Name:=Arteries", "Segment0_LabelValue:=1", "Segment0_Layer:=0",
                 "Segment1_ID:=v", "Segment1_Name:=Vein and aorta", "Segment1_LabelValue:=1", "Segment1_Layer:=1" });
  EXPECT_EQ(CountWhere(*ReadLumenSegmentation(path.string(), "arteries").mask, { 52, 65, 66 }), 0);
  EXPECT_EQ(CountWhere(*ReadLumenSegmentation(path.string(), "vein and aorta").mask, { 52, 63 }), 0);
  // The value 1 without a name: in any layer.
  EXPECT_EQ(CountWhere(*ReadLumenSegmentation(path.string(), "1").mask, { 52, 63, 65, 66 }), 0);
}

/// Unreadable: one message naming the path.
TEST_F(ReadLumenSegmentationTest, MissingFile)
{
  const std::string what = ErrorOf((folder / "none.nii.gz").string(), "");
  EXPECT_NE(what.find("none.nii.gz"), std::string::npos) << what;
  EXPECT_NE(what.find("does not exist"), std::string::npos) << what;
}

} // namespace
} // namespace sgp
