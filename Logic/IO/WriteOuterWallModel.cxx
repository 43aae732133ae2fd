#include "IO/WriteOuterWallModel.h"

#include <cmath>

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include "IO/WriteModel.h"

namespace sgp
{

void WriteOuterWallModel(const VesselWall& wall, const std::string& path)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> thrombus;
  vtkNew<vtkIntArray> supported, vessel;
  thrombus->SetName("ThrombusThicknessMm");
  supported->SetName("Supported");
  vessel->SetName("Vessel");
  vtkNew<vtkCellArray> triangles;
  for (int v = 0; v < 3; ++v)
  {
    vtkIdType previousStart = -1;
    double previousAbscissa = 0.0;
    for (const OuterWallPlane& plane : wall.vessels[v].planes)
    {
      if (!plane.Usable())
        continue;
      const vtkIdType K = plane.contourLps.rows();
      const vtkIdType start = points->GetNumberOfPoints();
      for (vtkIdType k = 0; k < K; ++k)
      {
        points->InsertNextPoint(plane.contourLps(k, 0), plane.contourLps(k, 1), plane.contourLps(k, 2));
        thrombus->InsertNextValue(plane.thrombusMm.size() == K ? plane.thrombusMm[k] : 0.0);
        supported->InsertNextValue(plane.supported[std::size_t(k)] ? 1 : 0);
        vessel->InsertNextValue(v);
      }
      if (previousStart >= 0 && std::abs(plane.abscissaMm - previousAbscissa) <= 2.5 * wall.stepMm)
        for (vtkIdType k = 0; k < K; ++k)
        {
          const vtkIdType a = previousStart + k, b = previousStart + (k + 1) % K, c = start + k,
                          d = start + (k + 1) % K;
          const vtkIdType first[3] = { a, b, d }, second[3] = { a, d, c };
          triangles->InsertNextCell(3, first);
          triangles->InsertNextCell(3, second);
        }
      previousStart = start;
      previousAbscissa = plane.abscissaMm;
    }
  }
  vtkNew<vtkPolyData> polyData;
  polyData->SetPoints(points);
  polyData->SetPolys(triangles);
  polyData->GetPointData()->AddArray(thrombus);
  polyData->GetPointData()->AddArray(supported);
  polyData->GetPointData()->AddArray(vessel);
  WriteModelLps(polyData, path);
}

} // namespace sgp
