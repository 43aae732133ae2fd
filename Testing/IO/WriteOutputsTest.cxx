// Tests of the writers of the I/O room: models marked LPS, return-parameter files, and the
// all-or-nothing output transaction.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>

#include "Common/Errors.h"
#include "IO/OutputTransaction.h"
#include "IO/WriteImage.h"
#include "IO/WriteModel.h"
#include "IO/WriteReturnParameters.h"
#include "TemporaryFolder.h"

namespace sgp
{
namespace
{

namespace fs = std::filesystem;

class WriteOutputsTest : public testing::TemporaryFolderTest
{
protected:
  std::vector<std::string> Listing() const
  {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder))
      names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  static std::string Read(const fs::path& path)
  {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  static vtkNew<vtkPolyData> Triangle()
  {
    vtkNew<vtkPolyData> polyData;
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(-12.5, 40.0, 103.25); // LPS mm
    points->InsertNextPoint(1.0, 2.0, 3.0);
    points->InsertNextPoint(0.0, -7.5, 0.5);
    polyData->SetPoints(points);
    return polyData;
  }
};

TEST_F(WriteOutputsTest, VtpModel_CarriesSpaceLpsAndPointsUnchanged)
{
  auto model = Triangle();
  const fs::path path = folder / "model.vtp";
  WriteModelLps(model, path.string());
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(path.string().c_str());
  reader->Update();
  auto* space = vtkStringArray::SafeDownCast(reader->GetOutput()->GetFieldData()->GetAbstractArray("SPACE"));
  ASSERT_NE(space, nullptr);
  EXPECT_EQ(space->GetValue(0), "LPS");
  ASSERT_EQ(reader->GetOutput()->GetNumberOfPoints(), 3);
  double p[3];
  reader->GetOutput()->GetPoint(0, p);
  EXPECT_DOUBLE_EQ(p[0], -12.5); // written as given: no RAS flip
  EXPECT_DOUBLE_EQ(p[1], 40.0);
  EXPECT_DOUBLE_EQ(p[2], 103.25);
}

TEST_F(WriteOutputsTest, LegacyVtkModel_HeaderSaysSpaceLps)
{
  auto model = Triangle();
  const fs::path path = folder / "model.vtk";
  WriteModelLps(model, path.string());
  const std::string text = Read(path);
  EXPECT_EQ(text.rfind("# vtk DataFile Version 4.2\n3D Slicer output. SPACE=LPS\n", 0), 0u) << text.substr(0, 80);
  vtkNew<vtkPolyDataReader> reader;
  reader->SetFileName(path.string().c_str());
  reader->Update();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 3);
}

TEST_F(WriteOutputsTest, ModelWithUnknownExtension_InputError)
{
  auto model = Triangle();
  const std::string path = (folder / "model.stl").string();
  try
  {
    WriteModelLps(model, path);
    ADD_FAILURE();
  }
  catch (const InputError& e)
  {
    EXPECT_EQ(std::string(e.what()),
              "Cannot write the model '" + path + "': unknown extension; expected .vtp or .vtk.");
  }
  EXPECT_TRUE(Listing().empty());
}

TEST_F(WriteOutputsTest, ModelInMissingFolder_InputError)
{
  auto model = Triangle();
  const std::string path = (folder / "no" / "model.vtp").string();
  EXPECT_THROW(WriteModelLps(model, path), InputError);
}

TEST_F(WriteOutputsTest, ReturnParameters_NameEqualsValueLines)
{
  const fs::path path = folder / "123_abc.params";
  WriteReturnParameters({ { "lumenVolumeMl", FormatReturnValue(165.25) },
                          { "seedRas", FormatReturnValue(-0.0) + "," + FormatReturnValue(1e-5) + ",60" } },
                        path.string());
  EXPECT_EQ(Read(path), "lumenVolumeMl = 165.25\nseedRas = 0,1e-05,60\n");
  EXPECT_THROW(WriteReturnParameters({}, (folder / "no" / "x.params").string()), InputError);
}

TEST_F(WriteOutputsTest, LabelMapInMissingFolder_InputErrorNamesPath)
{
  auto image = LabelImage::New();
  LabelImage::RegionType region;
  region.SetSize({ { 3, 3, 3 } });
  image->SetRegions(region);
  image->Allocate(true);
  const std::string path = (folder / "no" / "lumen.nrrd").string();
  try
  {
    WriteLabelMap(*image, path);
    ADD_FAILURE();
  }
  catch (const InputError& e)
  {
    EXPECT_EQ(std::string(e.what()).rfind("Cannot write '" + path + "': ", 0), 0u) << e.what();
  }
}

TEST_F(WriteOutputsTest, TransactionCommitted_OnlyFinalFilesRemain)
{
  {
    OutputTransaction outputs;
    const std::string staged = outputs.Stage((folder / "lumen.nii.gz").string());
    EXPECT_NE(staged.find("lumen.sgp-partial-"), std::string::npos);
    EXPECT_EQ(staged.substr(staged.size() - 7), ".nii.gz"); // same extension: ITK picks the same writer
    std::ofstream(staged) << "a";
    std::ofstream(outputs.Stage((folder / "ret.params").string())) << "b";
    outputs.Commit();
  }
  EXPECT_EQ(Listing(), (std::vector<std::string>{ "lumen.nii.gz", "ret.params" }));
}

TEST_F(WriteOutputsTest, TransactionAbandoned_NothingRemains)
{
  try
  {
    OutputTransaction outputs;
    std::ofstream(outputs.Stage((folder / "lumen.nrrd").string())) << "a";
    throw std::runtime_error("a later stage failed");
  }
  catch (const std::runtime_error&)
  {
  }
  EXPECT_TRUE(Listing().empty());
}

TEST_F(WriteOutputsTest, TransactionRenameFails_EarlierOutputsRemovedAndPathNamed)
{
  OutputTransaction outputs;
  std::ofstream(outputs.Stage((folder / "first.nrrd").string())) << "a";
  const std::string blocked = (folder / "blocked").string();
  fs::create_directories(fs::path(blocked) / "occupied"); // a non-empty folder cannot be replaced by a file
  std::ofstream(outputs.Stage(blocked)) << "b";
  try
  {
    outputs.Commit();
    ADD_FAILURE();
  }
  catch (const InputError& e)
  {
    EXPECT_EQ(std::string(e.what()).rfind("Cannot move the output into place at '" + blocked + "': ", 0), 0u)
      << e.what();
  }
  EXPECT_FALSE(fs::exists(folder / "first.nrrd"));
}

} // namespace
} // namespace sgp
