#include "IO/WriteStentModel.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkFieldData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include "IO/WriteModel.h"

namespace sgp
{

void WriteStentModel(const StentMesh& mesh,
                     const Points& V,
                     const Eigen::VectorXd& radiusMm,
                     const Eigen::VectorXd& wallDistanceMm,
                     const std::string& path)
{
  WriteStentModel(mesh, V, radiusMm, wallDistanceMm, {}, path);
}

void WriteStentModel(const StentMesh& mesh,
                     const Points& V,
                     const Eigen::VectorXd& radiusMm,
                     const Eigen::VectorXd& wallDistanceMm,
                     const std::vector<std::pair<std::string, Eigen::VectorXd>>& extra,
                     const std::string& path)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkIntArray> segment, ring;
  vtkNew<vtkDoubleArray> radius, wall;
  segment->SetName("Segment");
  ring->SetName("Ring");
  radius->SetName("Radius");
  wall->SetName("WallDistance");
  for (Eigen::Index i = 0; i < V.rows(); ++i)
  {
    points->InsertNextPoint(V(i, 0), V(i, 1), V(i, 2));
    segment->InsertNextValue(mesh.segment[i]);
    ring->InsertNextValue(mesh.ring[i]);
    radius->InsertNextValue(radiusMm[i]);
    wall->InsertNextValue(wallDistanceMm[i]);
  }
  vtkNew<vtkCellArray> triangles;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
  {
    const vtkIdType ids[3] = { mesh.F(f, 0), mesh.F(f, 1), mesh.F(f, 2) };
    triangles->InsertNextCell(3, ids);
  }
  vtkNew<vtkPolyData> polyData;
  polyData->SetPoints(points);
  polyData->SetPolys(triangles);
  for (vtkDataArray* array : { static_cast<vtkDataArray*>(segment), static_cast<vtkDataArray*>(ring),
                               static_cast<vtkDataArray*>(radius), static_cast<vtkDataArray*>(wall) })
    polyData->GetPointData()->AddArray(array);
  for (const auto& [name, values] : extra)
  {
    vtkNew<vtkDoubleArray> array;
    array->SetName(name.c_str());
    for (Eigen::Index i = 0; i < values.size(); ++i)
      array->InsertNextValue(values[i]);
    polyData->GetPointData()->AddArray(array);
  }
  WriteModelLps(polyData, path);
}

void WriteNotSimulatedModel(const std::string& reason, const std::string& path)
{
  vtkNew<vtkPolyData> polyData;
  vtkNew<vtkPoints> points;
  polyData->SetPoints(points);
  vtkNew<vtkStringArray> why;
  why->SetName("NotSimulated");
  why->InsertNextValue(reason);
  polyData->GetFieldData()->AddArray(why);
  WriteModelLps(polyData, path);
}

} // namespace sgp
