#include "IO/WriteModel.h"

#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataWriter.h>

#include "Common/Errors.h"

namespace sgp
{

namespace
{

bool EndsWith(const std::string& text, const std::string& suffix)
{
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

} // namespace

void WriteModelLps(vtkPolyData* polyData, const std::string& path)
{
  vtkNew<vtkStringArray> space;
  space->SetName("SPACE");
  space->InsertNextValue("LPS");
  polyData->GetFieldData()->RemoveArray("SPACE");
  polyData->GetFieldData()->AddArray(space);
  int written = 0;
  if (EndsWith(path, ".vtp"))
  {
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(polyData);
    writer->SetFileName(path.c_str());
    writer->SetDataModeToAppended();
    writer->SetCompressorTypeToZLib();
    written = writer->Write() == 1 && writer->GetErrorCode() == 0 ? 1 : 0;
  }
  else if (EndsWith(path, ".vtk"))
  {
    vtkNew<vtkPolyDataWriter> writer;
    writer->SetInputData(polyData);
    writer->SetFileName(path.c_str());
    writer->SetHeader("3D Slicer output. SPACE=LPS");
    writer->SetFileVersion(vtkPolyDataWriter::VTK_LEGACY_READER_VERSION_4_2);
    writer->SetFileTypeToBinary();
    written = writer->Write() == 1 && writer->GetErrorCode() == 0 ? 1 : 0;
  }
  else
  {
    throw InputError("Cannot write the model '" + path + "': unknown extension; expected .vtp or .vtk.");
  }
  if (written != 1)
  {
    throw InputError("Cannot write the model '" + path + "': the VTK writer failed; give a writable path.");
  }
}

} // namespace sgp
