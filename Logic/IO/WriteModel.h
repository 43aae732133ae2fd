/// \file WriteModel.h
/// Writes a surface or polyline model for 3D Slicer, in LPS millimetres, marked as LPS.
///
/// Slicer's model storage node reads the coordinate system from the file: a string field-data
/// array `SPACE` = `LPS` in XML files (.vtp), or `SPACE=LPS` in the header of legacy .vtk files
/// (written as file version 4.2, as Slicer writes them). Without the marker Slicer warns and
/// assumes LPS; with it, models land where the image does. `.vtp` is written binary, appended and
/// zlib-compressed.
///
/// \param polyData  points in LPS mm; its field data gets the SPACE array (modified in place)
/// \throws InputError naming the path when the extension is not .vtp/.vtk or the writer fails.
#pragma once

#include <string>

class vtkPolyData;

namespace sgp
{

void WriteModelLps(vtkPolyData* polyData, const std::string& path);

} // namespace sgp
