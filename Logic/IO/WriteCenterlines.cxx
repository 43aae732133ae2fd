#include "IO/WriteCenterlines.h"

#include <cstdio>
#include <sstream>
#include <utility>
#include <vector>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <nlohmann/json.hpp>

#include "Common/Text.h"
#include "IO/WriteModel.h"
#include "IO/WriteTextFile.h"

namespace sgp
{

void WriteCenterlines(const CenterlineTree& tree, const std::string& path)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkStringArray> names;
  names->SetName("Name");
  vtkNew<vtkDoubleArray> radius;
  radius->SetName("Radius");
  vtkNew<vtkDoubleArray> abscissa;
  abscissa->SetName("Abscissa");
  std::vector<const Centerline*> vessels{ &tree.aorta, &tree.rightIliac, &tree.leftIliac };
  for (const Centerline& c : tree.sideBranches)
    vessels.push_back(&c);
  for (const Centerline* c : vessels)
  {
    lines->InsertNextCell(static_cast<vtkIdType>(c->Size()));
    for (Eigen::Index i = 0; i < c->Size(); ++i)
    {
      lines->InsertCellPoint(points->InsertNextPoint(c->points(i, 0), c->points(i, 1), c->points(i, 2)));
      radius->InsertNextValue(c->radiusMm[i]);
      abscissa->InsertNextValue(c->abscissaMm[i]);
    }
    names->InsertNextValue(c->name);
  }
  vtkNew<vtkPolyData> polyData;
  polyData->SetPoints(points);
  polyData->SetLines(lines);
  polyData->GetCellData()->AddArray(names);
  polyData->GetPointData()->AddArray(radius);
  polyData->GetPointData()->AddArray(abscissa);
  WriteModelLps(polyData, path);
}

namespace
{

/// The landmarks to write (WriteCenterlines.h): the tree's, with the measured ones in place.
std::vector<std::pair<Landmark, std::string>> LandmarksToWrite(const CenterlineTree& tree, const Measurements* m)
{
  std::vector<std::pair<Landmark, std::string>> out;
  const auto described = [](bool given, const std::string& how)
  { return given ? std::string("Given by the user.") : "Found: " + how + "."; };
  if (m && m->site.Known())
    out.push_back({ { "lowestRenalOstium", m->site.lps },
                    m->site.source == ProximalSiteSource::Landmark
                      ? described(true, "")
                      : described(false, m->site.source == ProximalSiteSource::Renal
                                           ? "the lower edge of the " + IdentifierWords(m->site.renal) +
                                               " artery's ostium, on the aortic centerline"
                                           : "the top of the aorta in view (no renal artery found)") });
  for (const Landmark& l : tree.landmarks)
  {
    if (m && l.name == "aorticBifurcation")
    {
      out.push_back({ { l.name, m->bifurcationLps },
                      described(m->bifurcationGiven, "where the aortic and common iliac axes meet") });
      continue;
    }
    const int side = l.name == "rightIliacBifurcation" ? 0 : l.name == "leftIliacBifurcation" ? 1 : -1;
    if (m && side >= 0)
    {
      if (m->internalIliacOriginLps[std::size_t(side)].allFinite())
        out.push_back({ { side == 0 ? "rightInternalIliacOrigin" : "leftInternalIliacOrigin",
                          m->internalIliacOriginLps[std::size_t(side)] },
                        described(m->internalIliacOriginGiven[std::size_t(side)],
                                  "where the common, external and internal iliac axes meet") });
      continue;
    }
    // An ostium's description: the evidence for its branch's name.
    std::string description;
    if (l.name.size() > 6 && l.name.compare(l.name.size() - 6, 6, "Ostium") == 0)
      if (const Centerline* branch = tree.FindVessel(l.name.substr(0, l.name.size() - 6)))
        description = branch->evidence;
    out.push_back({ l, description });
  }
  return out;
}

} // namespace

void WriteLandmarks(const CenterlineTree& tree, const std::string& path, const Measurements* measurements)
{
  std::ostringstream json;
  json << "{\n  \"@schema\": \"https://raw.githubusercontent.com/slicer/slicer/master/Modules/Loadable/Markups/"
          "Resources/Schema/markups-schema-v1.0.3.json#\",\n"
       << "  \"markups\": [\n    {\n      \"type\": \"Fiducial\",\n      \"coordinateSystem\": \"LPS\",\n"
       << "      \"coordinateUnits\": \"mm\",\n      \"locked\": true,\n      \"labelFormat\": \"%N-%d\",\n"
       << "      \"controlPoints\": [\n";
  const std::vector<std::pair<Landmark, std::string>> landmarks = LandmarksToWrite(tree, measurements);
  for (std::size_t i = 0; i < landmarks.size(); ++i)
  {
    const Landmark& l = landmarks[i].first;
    char position[128];
    std::snprintf(position, sizeof position, "[%.4f, %.4f, %.4f]", l.lps.x() + 0.0, l.lps.y() + 0.0, l.lps.z() + 0.0);
    json << "        {\"id\": \"" << i + 1 << "\", \"label\": \"" << l.name
         << "\", \"description\": " << nlohmann::json(landmarks[i].second).dump() << ", "
         << "\"associatedNodeID\": \"\", \"position\": " << position
         << ", \"orientation\": [-1.0, -0.0, -0.0, -0.0, -1.0, -0.0, 0.0, 0.0, 1.0], \"selected\": true, "
         << "\"locked\": true, \"visibility\": true, \"positionStatus\": \"defined\"}"
         << (i + 1 < landmarks.size() ? "," : "") << "\n";
  }
  json << "      ]\n    }\n  ]\n}\n";
  WriteTextFile(json.str(), path, "the landmarks", "give a writable path ending in .mrk.json.");
}

} // namespace sgp
