#include "Views/ReportFigures.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "Measurement/MeasureDiameters.h"
#include "Views/SceneMeshes.h"

namespace sgp
{
namespace
{

constexpr double pi = 3.14159265358979323846;

/// The ray directions of a wall plane (SegmentOuterWall.cxx: ray k at 2πk/K from u towards v).
Eigen::Vector3d RayDirection(const OuterWallPlane& plane, Eigen::Index k, Eigen::Index rays)
{
  const double angle = 2 * pi * double(k) / double(rays);
  return std::cos(angle) * plane.uLps + std::sin(angle) * plane.vLps;
}

int VesselIndex(const std::string& vessel)
{
  return vessel == "aorta" ? 0 : vessel == "rightIliac" ? 1 : vessel == "leftIliac" ? 2 : -1;
}

/// The lumen and outer edges of each plane of `vessel` where the path's row crosses it.
void AddEdges(const OuterWall& wall, const std::string& vessel, StraightenedFigure& f)
{
  const VesselPath& path = f.path;
  for (const OuterWallPlane& plane : wall.planes)
  {
    const Eigen::Index rays = plane.lumenRadiusMm.size();
    const double s = path.PathAbscissa(vessel, plane.abscissaMm);
    if (rays == 0 || !std::isfinite(s))
      continue;
    const auto row = static_cast<Eigen::Index>(std::lround(s / path.stepMm));
    if (row < 0 || row >= path.points.rows())
      continue;
    // On the aorta's last planes the path already runs into the iliac: they belong to the other view.
    if (vessel == "aorta" && s > path.iliacStartMm)
      continue;
    const Eigen::Vector3d u = path.u.row(row).transpose();
    const Point3 p = path.points.row(row).transpose();
    Eigen::Index left = 0, right = 0;
    for (Eigen::Index k = 1; k < rays; ++k)
    {
      const double c = RayDirection(plane, k, rays).dot(u);
      if (c > RayDirection(plane, right, rays).dot(u))
        right = k;
      if (c < RayDirection(plane, left, rays).dot(u))
        left = k;
    }
    const auto offset = [&](Eigen::Index k, double radius)
    { return (plane.centreLps + radius * RayDirection(plane, k, rays) - p).dot(u); };
    f.lumenLeft.push_back({ "", s, offset(left, plane.lumenRadiusMm[left]) });
    f.lumenRight.push_back({ "", s, offset(right, plane.lumenRadiusMm[right]) });
    if (plane.Usable() && plane.outerRadiusMm.size() == rays)
    {
      f.outerLeft.push_back({ "", s, offset(left, plane.outerRadiusMm[left]) });
      f.outerRight.push_back({ "", s, offset(right, plane.outerRadiusMm[right]) });
    }
  }
}

/// Each component's simulated extent on `side`'s path (ReportFigures.h), and the whole graft's.
void AddSimulatedComponents(const DeployedGraft& graft, int side, StraightenedFigure& f)
{
  const GraftLayout& g = graft.layout;
  const StentMesh& mesh = g.mesh;
  const int ipsilateral = g.configured ? g.ipsilateralSide : side;
  for (int index = 0; index < int(g.components.size()); ++index)
  {
    const ConfiguredComponent& part = g.components[std::size_t(index)];
    if (part.role != OrderRole::MainBody && part.side != side)
      continue;
    double from = std::numeric_limits<double>::infinity(), to = -from;
    for (int seg : { int(TrunkSegment), 1 + side })
      for (int k = 0; k < mesh.RingsIn(seg); ++k)
      {
        Point3 centroid = Point3::Zero();
        bool carries = false;
        for (int j = 0; j < mesh.verticesPerRing; ++j)
        {
          const int i = mesh.Id(seg, k, j);
          centroid += graft.fit.V.row(i).transpose();
          carries = carries || (g.side[i] == side && (g.component[i] == index || g.innerComponent[i] == index));
        }
        if (!carries)
          continue;
        const double s = f.path.Project(centroid / mesh.verticesPerRing);
        from = std::min(from, s);
        to = std::max(to, s);
      }
    if (!std::isfinite(from))
      continue;
    std::string label = part.role == OrderRole::MainBody ? "main body" : part.item.name;
    if (part.role == OrderRole::IpsilateralLimb || part.role == OrderRole::ContralateralLimb)
      label = std::string(part.role == OrderRole::IpsilateralLimb ? "ipsilateral" : "contralateral") + " limb";
    else if (part.role == OrderRole::IliacExtension)
      label = "iliac extension";
    (void)ipsilateral;
    f.components.push_back({ label, ComponentColour(part), from, to, std::size_t(index) });
    f.graftStartMm = std::isnan(f.graftStartMm) ? from : std::min(f.graftStartMm, from);
    f.graftEndMm = std::isnan(f.graftEndMm) ? to : std::max(f.graftEndMm, to);
  }
}

StraightenedFigure Straighten(const RepairPlan& plan,
                              const CtImage& ct,
                              const std::vector<SizingLevel>& levels,
                              int side,
                              const ReportFigureParams& params)
{
  const CenterlineTree& tree = plan.centerlines;
  const Centerline& iliac = side == 0 ? tree.rightIliac : tree.leftIliac;
  StraightenedFigure f;
  f.path = SampleVesselPath(tree.aorta, iliac, params.pixelMm);
  f.image = StraightenAlongPath(ct, f.path, params.halfWidthMm);
  AddEdges(plan.vesselWall.vessels[0], "aorta", f);
  AddEdges(plan.vesselWall.vessels[1 + side], iliac.name, f);
  for (const SizingLevel& level : levels)
  {
    const double s = f.path.PathAbscissa(level.vessel, level.abscissaMm);
    if (std::isfinite(s))
      f.levels.push_back({ level.label, s, 0.0 });
  }
  const std::string otherOrigin = side == 0 ? "leftIliacBifurcation" : "rightIliacBifurcation";
  for (const Landmark& l : tree.landmarks)
  {
    if (l.name == otherOrigin)
      continue;
    f.landmarks.push_back({ l.name, f.path.Project(l.lps), 0.0 });
  }
  if (plan.HasGraft())
    AddSimulatedComponents(plan.graft, side, f);
  return f;
}

/// The ring of `segment` nearest abscissa s, or −1.
int NearestRing(const StentMesh& mesh, int segment, double s)
{
  const std::vector<double>& a = mesh.ringAbscissaMm[segment];
  int best = -1;
  for (int r = 0; r < static_cast<int>(a.size()); ++r)
    if (best < 0 || std::abs(a[r] - s) < std::abs(a[best] - s))
      best = r;
  return best;
}

CrossSectionFigure Section(const RepairPlan& plan,
                           const CtImage& ct,
                           const SizingLevel& level,
                           const ReportFigureParams& params)
{
  const Centerline& vessel = *plan.centerlines.FindVessel(level.vessel);
  const int v = VesselIndex(level.vessel);
  CrossSectionFigure f;
  f.level = level;
  const Point3 centre = PositionAt(vessel, level.abscissaMm);
  const Eigen::Vector3d t = TangentAt(vessel, level.abscissaMm);
  const Eigen::Vector3d u = CoronalAxis(t), w = u.cross(t);
  const auto project = [&](const Point3& p) { return Eigen::Vector2d((p - centre).dot(u), (p - centre).dot(w)); };

  const OuterWallPlane* plane = v >= 0 ? plan.vesselWall.vessels[v].Nearest(level.abscissaMm) : nullptr;
  if (plane && std::abs(plane->abscissaMm - level.abscissaMm) <= plan.vesselWall.stepMm && plane->Usable())
    for (Eigen::Index k = 0; k < plane->contourLps.rows(); ++k)
      f.outer.push_back(project(plane->contourLps.row(k).transpose()));

  // The measured ring: the measure-mode fit (plan.fit unless the stent was fitted in simulate mode).
  if (plan.fitInMeasureMode && v >= 0 && plan.fit.V.rows() == plan.mesh.V.rows())
  {
    const int ring = NearestRing(plan.mesh, v, level.abscissaMm);
    const std::vector<double>& a = plan.mesh.ringAbscissaMm[v];
    const double spacing = a.size() >= 2 ? std::abs(a[1] - a[0]) : 0.0;
    if (ring >= 0 && std::abs(a[ring] - level.abscissaMm) <= 0.5 * spacing + 1e-6)
    {
      const int n = plan.mesh.verticesPerRing;
      std::vector<Point3> vertices;
      for (int j = 0; j < n; ++j)
        vertices.push_back(plan.fit.V.row(plan.mesh.Id(v, ring, j)).transpose());
      for (const Point3& p : vertices)
        f.ring.push_back(project(p));
      // The diameters MeasureDiameters averages: vertex j to vertex j + n/2, leaving out a
      // branch mouth's vertices (BranchMouthRadiusFactor × the median radius).
      std::vector<double> radii;
      for (const Eigen::Vector2d& q : f.ring)
        radii.push_back(q.norm());
      std::vector<double> sorted = radii;
      std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.end());
      const double mouth = BranchMouthRadiusFactor * sorted[n / 2];
      double shortest = 1e300, longest = -1.0;
      for (int j = 0; j < n / 2; ++j)
      {
        if (radii[j] > mouth || radii[j + n / 2] > mouth)
          continue;
        const double d = (f.ring[j] - f.ring[j + n / 2]).norm();
        if (d < shortest)
        {
          shortest = d;
          f.minCaliper = { f.ring[j], f.ring[j + n / 2] };
        }
        if (d > longest)
        {
          longest = d;
          f.maxCaliper = { f.ring[j], f.ring[j + n / 2] };
        }
      }
      f.hasCalipers = longest > 0.0;
    }
  }
  double radius = 0.0;
  for (const Eigen::Vector2d& q : f.outer)
    radius = std::max(radius, q.norm());
  for (const Eigen::Vector2d& q : f.ring)
    radius = std::max(radius, q.norm());
  if (radius == 0.0) // neither a ring nor a contour: the vessel's inscribed radius
    radius = std::max(1.0, vessel.radiusMm.maxCoeff());
  const double half = params.sectionHalfMm > 0.0 ? params.sectionHalfMm : std::min(1.4 * radius + 10.0, 100.0);
  f.image = CrossSection(ct, centre, u, w, half, params.pixelMm);
  return f;
}

} // namespace

std::vector<SizingLevel> SizingLevels(const Measurements& measurements)
{
  const char* names[6][3] = { { "(a)", "proximalNeckDiameter", "proximalNeckLumenDiameter" },
                              { "(b)", "neckDiameter15mm", "neckLumenDiameter15mm" },
                              { "(c)", "maxAneurysmDiameter", "maxAneurysmLumenDiameter" },
                              { "(d)", "distalNeckMinDiameter", "distalNeckMinLumenDiameter" },
                              { "(e)", "rightIliacDiameter", "rightIliacLumenDiameter" },
                              { "(f)", "leftIliacDiameter", "leftIliacLumenDiameter" } };
  std::vector<SizingLevel> levels;
  for (const auto& n : names)
  {
    SizingLevel level{ n[0], n[1], n[2], "", std::numeric_limits<double>::quiet_NaN() };
    // The lumen value's ring is the level (the outer wall is read at the plane nearest it).
    const Measurement* lumen = measurements.Find(n[2]);
    const Measurement* outer = measurements.Find(n[1]);
    const Measurement* at = lumen && std::isfinite(lumen->value) ? lumen : outer;
    if (at && std::isfinite(at->value))
    {
      level.vessel = at->vessel;
      level.abscissaMm = at->abscissaMm;
    }
    levels.push_back(level);
  }
  return levels;
}

ReportFigures BuildReportFigures(const RepairPlan& plan, const CtImage& ct, const ReportFigureParams& params)
{
  ReportFigures figures;
  const std::vector<SizingLevel> levels = SizingLevels(plan.measurements);
  for (int side = 0; side < 2; ++side)
    figures.straightened[side] = Straighten(plan, ct, levels, side, params);
  for (const SizingLevel& level : levels)
    if (std::isfinite(level.abscissaMm) && plan.centerlines.FindVessel(level.vessel))
      figures.sections.push_back(Section(plan, ct, level, params));
  if (plan.HasGraft())
  {
    const std::array<Point3, 2> box = GraftBox(plan.graft, 25.0);
    const std::vector<SceneMesh> scene = { LumenSurface(*plan.lumen.mask, box[0], box[1]),
                                           OuterWallSurface(plan.vesselWall), GraftSurface(plan.graft) };
    for (const SceneView& view : { AnteriorView(), LeftLateralView() })
    {
      figures.graftViews.push_back(RenderScene(scene, view, 420));
      figures.graftViewNames.push_back(view.name);
    }
  }
  return figures;
}

} // namespace sgp
