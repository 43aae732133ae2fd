#include "Device/DeployGraft.h"

#include <algorithm>
#include <cmath>

#include "Common/Errors.h"
#include "Common/Format.h"

namespace sgp
{
namespace
{

constexpr double pi = 3.14159265358979323846;
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

/// The components on `side`'s path covering `pathMm`, outermost first (chain order), with the main
/// body's extent on that path: to its leg's end on the ipsilateral side, its gate's on the other.
std::vector<int> Covering(const GraftLayout& g, int ipsilateral, double gateEndMm, int side, double pathMm)
{
  constexpr double slack = 1e-6; // a ring placed exactly on an edge belongs to the component
  std::vector<int> found;
  for (int k = 0; k < int(g.components.size()); ++k)
  {
    const ConfiguredComponent& c = g.components[std::size_t(k)];
    double from = c.proximalMm, to = c.distalMm;
    if (c.role == OrderRole::MainBody)
    {
      if (side != ipsilateral && std::isfinite(gateEndMm))
        to = gateEndMm;
    }
    else if (c.side != side)
      continue;
    if (pathMm >= from - slack && pathMm <= to + slack)
      found.push_back(k);
  }
  return found;
}

/// The nearest component on `side`'s path when none covers `pathMm` (the connection element's
/// rings of an unconfigured graft may fall between the stand-ins' extents).
int Nearest(const GraftLayout& g, int side, double pathMm)
{
  int best = 0;
  double distance = 1e18;
  for (int k = 0; k < int(g.components.size()); ++k)
  {
    const ConfiguredComponent& c = g.components[std::size_t(k)];
    if (c.role != OrderRole::MainBody && c.side != side)
      continue;
    const double d = pathMm < c.proximalMm ? c.proximalMm - pathMm : std::max(0.0, pathMm - c.distalMm);
    if (d < distance)
    {
      distance = d;
      best = k;
    }
  }
  return best;
}

/// The diameter of component `c` at `pathMm` on `side` (see the file comment); the main body's flow
/// divider at path position `flowDividerMm` (NaN: the catalogue's, from its top).
double DiameterAt(const ConfiguredComponent& c,
                  const std::vector<ConfiguredComponent>& all,
                  int side,
                  int ipsilateral,
                  double pathMm,
                  double flowDividerMm)
{
  const CatalogueComponent& item = c.item;
  if (c.role != OrderRole::MainBody)
    return std::isfinite(item.distalDiameterMm) ? item.distalDiameterMm : item.diameterMm;
  const double divider = std::isfinite(flowDividerMm) ? flowDividerMm : item.flowDividerMm;
  if (!std::isfinite(divider) || pathMm < divider)
    return item.diameterMm;
  if (side == ipsilateral)
    return item.distalDiameterMm;
  if (std::isfinite(item.gateDiameterMm))
    return item.gateDiameterMm;
  // No gate diameter in the catalogue: the limb inserted into it, at its top where known.
  for (const ConfiguredComponent& other : all)
    if (other.role == OrderRole::ContralateralLimb)
      return std::isfinite(other.item.diameterMm) ? other.item.diameterMm : other.item.distalDiameterMm;
  return item.distalDiameterMm;
}

/// Tags every vertex of `g.mesh` (side, path, components, R).
void TagVertices(GraftLayout& g, int ipsilateral, double gateEndMm)
{
  const StentMesh& mesh = g.mesh;
  const Eigen::Index n = mesh.V.rows();
  g.side.resize(n);
  g.pathMm.resize(n);
  g.component.resize(n);
  g.innerComponent.resize(n);
  g.nominalRadiusMm.resize(n);
  const int perRing = mesh.verticesPerRing;
  for (Eigen::Index i = 0; i < n; ++i)
  {
    const int seg = mesh.segment[i], k = mesh.ring[i], j = mesh.column[i];
    const double s = mesh.ringAbscissaMm[std::size_t(seg)][std::size_t(k)];
    int side = seg - 1;
    double path = 0.0;
    if (seg == TrunkSegment)
    {
      side = (j >= perRing / 4 && j <= 3 * perRing / 4) ? 0 : 1;
      path = s - g.targetAbscissaMm;
    }
    else
      path = g.PathOfIliac(side, s);
    const std::vector<int> covering = Covering(g, ipsilateral, gateEndMm, side, path);
    const int outer = covering.empty() ? Nearest(g, side, path) : covering.front();
    g.side[i] = side;
    g.pathMm[i] = path;
    g.component[i] = outer;
    g.innerComponent[i] = covering.size() > 1 ? covering[1] : -1;
    const double d =
      DiameterAt(g.components[std::size_t(outer)], g.components, side, ipsilateral, path, g.flowDividerMm);
    const bool twoLegs = seg == TrunkSegment && std::isfinite(g.flowDividerMm) && path >= g.flowDividerMm;
    // Below the flow divider the trunk stands for two legs side by side (the file comment).
    const double theta = 2.0 * pi * j / perRing;
    g.nominalRadiusMm[i] = twoLegs ? 0.5 * d * (1.0 + std::abs(std::cos(theta))) : 0.5 * d;
  }
}

} // namespace

double GraftLayout::PathOfIliac(int side, double iliacAbscissaMm) const
{
  return toBifurcationMm + iliacStartBeyondBifurcationMm[std::size_t(side)] + iliacAbscissaMm;
}

double GraftLayout::IliacOfPath(int side, double pathMm) const
{
  return pathMm - toBifurcationMm - iliacStartBeyondBifurcationMm[std::size_t(side)];
}

GraftLayout LayOutGraft(const CenterlineTree& tree,
                        const Measurements& m,
                        const DeviceConfiguration& c,
                        double targetAbscissaMm,
                        StentMeshParams meshParams,
                        const DeviceConfiguration* ordered)
{
  if (!c.configured)
    throw InputError("The graft cannot be laid out from a configuration that was not made (" + c.unknownReason + ").");
  GraftLayout g;
  g.components = c.components;
  g.configured = true;
  g.targetAbscissaMm = targetAbscissaMm;
  g.toBifurcationMm = m.bifurcationAbscissaMm - targetAbscissaMm;
  g.iliacStartBeyondBifurcationMm = m.iliacStartBeyondBifurcationMm;
  g.flowDividerMm = c.flowDividerMm;
  g.gateEndMm = c.gateEndMm;
  g.ipsilateralSide = c.ipsilateralSide;
  const DeviceConfiguration& fabric = ordered ? *ordered : c;
  for (const ConfiguredComponent& part : fabric.components)
    g.fabricMm.push_back({ part.proximalMm, part.distalMm });
  g.fabricGateEndMm = fabric.gateEndMm;
  meshParams.proximalAbscissaMm = targetAbscissaMm;
  for (int side = 0; side < 2; ++side)
    meshParams.legEndAbscissaMm[std::size_t(side)] = g.IliacOfPath(side, c.coveredLengthMm[std::size_t(side)]);
  // A ring at every component's ends, the flow divider and the gate end: on the trunk where the
  // position lies above the aortic centerline's end, on its side's leg where below (the main body
  // on both paths, to its gate end on the contralateral one).
  std::vector<std::pair<int, double>> ends{ { c.ipsilateralSide, c.flowDividerMm },
                                            { 1 - c.ipsilateralSide, c.flowDividerMm },
                                            { 1 - c.ipsilateralSide, c.gateEndMm } };
  for (const ConfiguredComponent& part : c.components)
    for (int side = 0; side < 2; ++side)
      if (part.role != OrderRole::MainBody ? part.side == side : side == c.ipsilateralSide)
      {
        ends.emplace_back(side, part.proximalMm);
        ends.emplace_back(side, part.distalMm);
      }
  // An end in the connection element's gap (between the trunk's usual last ring, 3 stent radii
  // above the aortic centerline's end, and a leg's usual first one, as far down its iliac) moves
  // that last or first ring to it, so that every end has its ring.
  const double aortaEnd = tree.aorta.LengthMm() - targetAbscissaMm;
  const double gap = 3.0 * meshParams.startRadiusMm;
  // The legs start a stent radius down their iliacs (not three, as the measure-mode surface's do):
  // the common iliac's whole length carries rings, so that its seal can be judged (the crotch
  // plane keeps the two legs' first rings apart: ActiveContour.h).
  meshParams.legStartAbscissaMm = { meshParams.startRadiusMm, meshParams.startRadiusMm };
  for (const auto& [side, path] : ends)
    if (path < aortaEnd)
    {
      meshParams.requiredRingAbscissaMm[TrunkSegment].push_back(targetAbscissaMm + path);
      if (path > aortaEnd - gap)
        meshParams.trunkEndAbscissaMm = std::isnan(meshParams.trunkEndAbscissaMm)
                                          ? targetAbscissaMm + path
                                          : std::max(meshParams.trunkEndAbscissaMm, targetAbscissaMm + path);
    }
    else
    {
      const double s = g.IliacOfPath(side, path);
      meshParams.requiredRingAbscissaMm[std::size_t(1 + side)].push_back(s);
      double& start = meshParams.legStartAbscissaMm[std::size_t(side)];
      if (s < gap)
        start = std::isnan(start) ? s : std::min(start, s);
    }
  g.mesh = BuildStentMesh(tree, meshParams);
  TagVertices(g, c.ipsilateralSide, c.gateEndMm);
  return g;
}

GraftLayout LayOutOnMeasureMesh(const StentMesh& mesh,
                                const Measurements& m,
                                const std::string& family,
                                const std::array<double, 3>& diametersMm,
                                const std::array<double, 2>& fallbackLegDiameterMm)
{
  GraftLayout g;
  g.mesh = mesh;
  g.configured = false;
  g.targetAbscissaMm = mesh.ringAbscissaMm[TrunkSegment].front();
  g.toBifurcationMm = m.bifurcationAbscissaMm - g.targetAbscissaMm;
  g.iliacStartBeyondBifurcationMm = m.iliacStartBeyondBifurcationMm;
  ConfiguredComponent body;
  body.role = OrderRole::MainBody;
  body.item.role = ComponentRole::MainBody;
  body.item.name = family + " main body (length not configured)";
  body.item.diameterMm = diametersMm[0];
  body.side = 0;
  body.proximalMm = 0.0;
  body.distalMm = mesh.ringAbscissaMm[TrunkSegment].back() - g.targetAbscissaMm;
  body.item.lengthMm = body.distalMm;
  g.components.push_back(body);
  for (int side = 0; side < 2; ++side)
  {
    const std::vector<double>& rings = mesh.ringAbscissaMm[std::size_t(1 + side)];
    const bool sized = std::isfinite(diametersMm[std::size_t(1 + side)]);
    ConfiguredComponent limb;
    limb.role = side == 0 ? OrderRole::IpsilateralLimb : OrderRole::ContralateralLimb;
    limb.item.role = ComponentRole::Limb;
    limb.item.name = family + (side == 0 ? " right" : " left") +
                     (sized ? " limb (length not configured)" : " leg (not sized: it carries the connection only)");
    limb.item.distalDiameterMm = sized ? diametersMm[std::size_t(1 + side)] : fallbackLegDiameterMm[std::size_t(side)];
    limb.side = side;
    limb.proximalMm = g.PathOfIliac(side, rings.front());
    limb.distalMm = g.PathOfIliac(side, rings.back());
    limb.item.lengthMm = limb.distalMm - limb.proximalMm;
    g.components.push_back(limb);
  }
  TagVertices(g, 0, NaN);
  return g;
}

double GraftAxis::PathAt(double fabricMm) const
{
  if (lengthMm.empty())
    return fabricMm;
  if (fabricMm <= lengthMm.front())
    return pathMm.front() + (fabricMm - lengthMm.front());
  for (std::size_t i = 1; i < lengthMm.size(); ++i)
    if (fabricMm <= lengthMm[i])
    {
      const double span = lengthMm[i] - lengthMm[i - 1];
      const double t = span > 0.0 ? (fabricMm - lengthMm[i - 1]) / span : 1.0;
      return pathMm[i - 1] + t * (pathMm[i] - pathMm[i - 1]);
    }
  return pathMm.back() + (fabricMm - lengthMm.back());
}

GraftAxis GraftAxisOf(const GraftLayout& g, const Points& V, int side)
{
  GraftAxis axis;
  Point3 previous = Point3::Zero();
  const auto add = [&](int segment, int k, double path)
  {
    const Point3 centre = RingCentroid(g.mesh, V, segment, k);
    axis.lengthMm.push_back(axis.lengthMm.empty() ? 0.0 : axis.lengthMm.back() + (centre - previous).norm());
    axis.pathMm.push_back(path);
    previous = centre;
  };
  const std::vector<double>& trunk = g.mesh.ringAbscissaMm[TrunkSegment];
  for (int k = 0; k < g.mesh.RingsIn(TrunkSegment); ++k)
    add(TrunkSegment, k, trunk[std::size_t(k)] - g.targetAbscissaMm);
  const std::vector<double>& leg = g.mesh.ringAbscissaMm[std::size_t(1 + side)];
  for (int k = 0; k < g.mesh.RingsIn(1 + side); ++k)
    add(1 + side, k, g.PathOfIliac(side, leg[std::size_t(k)]));
  return axis;
}

DeviceConfiguration PlacedAlongTheGraft(const DeviceConfiguration& c, const std::array<GraftAxis, 2>& axes)
{
  DeviceConfiguration placed = c;
  const int ipsilateral = c.ipsilateralSide;
  const auto place = [&](int side, double fabricMm)
  { return std::isfinite(fabricMm) ? axes[std::size_t(side)].PathAt(fabricMm) : fabricMm; };
  for (ConfiguredComponent& part : placed.components)
  {
    const int side = part.role == OrderRole::MainBody ? ipsilateral : part.side;
    part.proximalMm = place(side, part.proximalMm);
    part.distalMm = place(side, part.distalMm);
  }
  placed.flowDividerMm = place(ipsilateral, c.flowDividerMm);
  placed.gateEndMm = place(1 - ipsilateral, c.gateEndMm);
  for (int side = 0; side < 2; ++side)
    placed.coveredLengthMm[std::size_t(side)] = place(side, c.coveredLengthMm[std::size_t(side)]);
  return placed;
}

DeviceConfiguration PlacedAlongShiftedGraft(const DeviceConfiguration& configuration,
                                            double targetShiftMm,
                                            const std::array<GraftAxis, 2>& axes)
{
  const auto shift = [](DeviceConfiguration c, double mm)
  {
    for (ConfiguredComponent& part : c.components)
    {
      part.proximalMm += mm;
      part.distalMm += mm;
    }
    c.flowDividerMm += mm;
    c.gateEndMm += mm;
    for (double& covered : c.coveredLengthMm)
      covered += mm;
    return c;
  };
  DeviceConfiguration placed = shift(PlacedAlongTheGraft(shift(configuration, targetShiftMm), axes), -targetShiftMm);
  for (ConfiguredComponent& part : placed.components)
    if (part.role == OrderRole::MainBody)
      part.proximalMm = 0.0;
  return placed;
}

FabricDeployment DeployTheFabric(const CenterlineTree& tree,
                                 const Measurements& measurements,
                                 const DeviceConfiguration& configuration,
                                 double targetAbscissaMm,
                                 const StentMeshParams& meshParams,
                                 const std::function<DeployedGraft(GraftLayout)>& fit)
{
  FabricDeployment out;
  DeviceConfiguration placed = configuration;
  for (int pass = 1;; ++pass)
  {
    out.graft = fit(LayOutGraft(tree, measurements, placed, targetAbscissaMm, meshParams, &configuration));
    double worst = 0.0;
    for (int side = 0; side < 2; ++side)
    {
      const std::size_t s = std::size_t(side);
      out.axes[s] = GraftAxisOf(out.graft.layout, out.graft.fit.V, side);
      worst = std::max(worst, std::abs(configuration.coveredLengthMm[s] - out.axes[s].LengthMm()));
    }
    if (worst <= FabricLengthToleranceMm || pass == FabricLengthPasses)
      return out;
    DeviceConfiguration next = PlacedAlongTheGraft(configuration, out.axes);
    for (int side = 0; side < 2; ++side)
    {
      const Centerline& iliac = side == 0 ? tree.rightIliac : tree.leftIliac;
      if (out.graft.layout.IliacOfPath(side, next.coveredLengthMm[std::size_t(side)]) > iliac.LengthMm())
      {
        out.carried = false;
        return out;
      }
    }
    placed = std::move(next);
  }
}

DeployedGraft DeployGraft(GraftLayout layout,
                          const WallDistanceField& wall,
                          ActiveContourParams params,
                          const ProgressCallback& progress)
{
  params.vertexBalloonRadiusMm.assign(layout.nominalRadiusMm.data(),
                                      layout.nominalRadiusMm.data() + layout.nominalRadiusMm.size());
  DeployedGraft graft;
  graft.fit = FitActiveContour(layout.mesh, wall, params, progress);
  graft.layout = std::move(layout);
  return graft;
}

} // namespace sgp
