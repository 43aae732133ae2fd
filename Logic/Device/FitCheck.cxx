#include "Device/FitCheck.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

#include "Centerlines/ProximalSite.h"
#include "Common/Errors.h"
#include "Common/Format.h"
#include "Common/Text.h"
#include "Common/Median.h"
#include "Device/SelectDevice.h"

namespace sgp
{
namespace
{

constexpr double pi = 3.14159265358979323846;
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
constexpr double landingZoneMm = 15.0; ///< as MeasureAnatomy's (e)/(f)

std::string Mm(double value)
{
  return FormatNumber(value) + " mm";
}

std::string Percent(double value)
{
  return FormatNumber(value, 0) + " %";
}

/// The wall under one vertex, read off the traced plane at its level (VesselWall).
struct WallUnder
{
  int healthy = -1; ///< 1, 0, −1 not traced
  double thrombusMm = NaN;
  int calcified = -1;
  bool aneurysmal = false;
  double vesselDiameterMm = NaN; ///< the outer wall's area-equivalent diameter there, NaN: not traced
};

WallUnder ReadWallUnder(const VesselWall* wall,
                        int segment,
                        double abscissaMm,
                        const Point3& vertex,
                        double neckLimitMm,
                        const FitCheckParams& p)
{
  WallUnder under;
  if (!wall)
    return under;
  const OuterWallPlane* plane = wall->vessels[std::size_t(segment)].Nearest(abscissaMm);
  if (!plane || !plane->Usable() || std::abs(plane->abscissaMm - abscissaMm) > 0.5 * wall->stepMm + 1e-9 ||
      plane->thrombusMm.size() == 0)
    return under;
  const Eigen::Vector3d d = vertex - plane->centreLps;
  double angle = std::atan2(d.dot(plane->vLps), d.dot(plane->uLps));
  if (angle < 0.0)
    angle += 2.0 * pi;
  const Eigen::Index rays = plane->thrombusMm.size();
  const double x = angle / (2.0 * pi) * double(rays);
  const Eigen::Index k0 = Eigen::Index(std::floor(x)) % rays, k1 = (k0 + 1) % rays;
  const double f = x - std::floor(x);
  under.thrombusMm = (1.0 - f) * plane->thrombusMm[k0] + f * plane->thrombusMm[k1];
  under.calcified = plane->calcified[std::size_t(f < 0.5 ? k0 : k1)] ? 1 : 0;
  under.aneurysmal = segment == TrunkSegment && std::isfinite(neckLimitMm) && plane->minCaliperMm > neckLimitMm;
  under.vesselDiameterMm = plane->areaDiameterMm;
  const bool healthy =
    under.thrombusMm <= p.maxThrombusMm && !under.aneurysmal && (p.calciumSeals || under.calcified == 0);
  under.healthy = healthy ? 1 : 0;
  return under;
}

/// The share of a wall plane's rays under which a graft would not seal: thrombus thicker than the
/// limit, or (an aortic plane) the whole plane when its smallest width exceeds the neck's limit.
double UnhealthyShare(const OuterWallPlane& plane, double neckLimitMm, const FitCheckParams& p)
{
  if (std::isfinite(neckLimitMm) && plane.minCaliperMm > neckLimitMm)
    return 1.0;
  int unhealthy = 0;
  for (Eigen::Index k = 0; k < plane.thrombusMm.size(); ++k)
    unhealthy += plane.thrombusMm[k] > p.maxThrombusMm || (!p.calciumSeals && plane.calcified[std::size_t(k)]) ? 1 : 0;
  return double(unhealthy) / double(plane.thrombusMm.size());
}

/// The lumen's diameter at `s` on `segment`: the measured ring profile where it reaches, else
/// (an extension beyond the measured landing zone) twice the centerline's inscribed radius.
double LumenDiameterAt(const Measurements& m, const CenterlineTree& tree, int segment, double s)
{
  const DiameterProfile& profile = m.profiles[std::size_t(segment)];
  if (!profile.rings.empty() && s <= profile.rings.back().abscissaMm + 2.0 &&
      s >= profile.rings.front().abscissaMm - 2.0)
    return profile.At(s).meanMm;
  const Centerline* vessel[3] = { &tree.aorta, &tree.rightIliac, &tree.leftIliac };
  return 2.0 * RadiusAt(*vessel[segment], s);
}

/// The share of ring k's vertices that seal.
double SealingShare(const StentMesh& mesh, int seg, int k, const Eigen::VectorXi& sealing)
{
  int touching = 0;
  for (int j = 0; j < mesh.verticesPerRing; ++j)
    touching += sealing[mesh.Id(seg, k, j)];
  return double(touching) / mesh.verticesPerRing;
}

/// The sealed length from ring `from` toward ring `to` (one step `dir`), given each ring's share of
/// sealing vertices: to where that share, interpolated linearly between the last ring at or above
/// `fraction` and the first below it, crosses `fraction`; the whole stretch when every ring seals;
/// 0 when the first does not.
double SealedLength(const std::vector<double>& s,
                    int from,
                    int to,
                    int dir,
                    const std::function<double(int)>& share,
                    double fraction,
                    int* firstFailing = nullptr)
{
  int k = from;
  while (k != to + dir && share(k) >= fraction)
    k += dir;
  if (firstFailing)
    *firstFailing = k == to + dir ? -1 : k;
  if (k == from)
    return 0.0;
  if (k == to + dir)
    return std::abs(s[std::size_t(to)] - s[std::size_t(from)]);
  const double a = share(k - dir), b = share(k);
  const double t = a > b ? std::clamp((a - fraction) / (a - b), 0.0, 1.0) : 0.5;
  const double end = s[std::size_t(k - dir)] + t * (s[std::size_t(k)] - s[std::size_t(k - dir)]);
  return std::abs(end - s[std::size_t(from)]);
}

/// Why ring k of the trunk does not seal, in words.
std::string WhyRingDoesNotSeal(const StentMesh& mesh,
                               int k,
                               const FitCheck& c,
                               const std::vector<bool>& aneurysmal,
                               const FitCheckParams& p)
{
  int gap = 0, thrombus = 0, wide = 0;
  double largestGap = 0.0;
  for (int j = 0; j < mesh.verticesPerRing; ++j)
  {
    const int i = mesh.Id(TrunkSegment, k, j);
    if (c.appositionMm[i] > p.contactToleranceMm)
    {
      ++gap;
      largestGap = std::max(largestGap, c.appositionMm[i]);
    }
    else if (aneurysmal[std::size_t(i)])
      ++wide;
    else if (c.healthyWall[i] == 0)
      ++thrombus;
  }
  const double n = mesh.verticesPerRing;
  std::string why;
  const auto add = [&](const std::string& part) { why += (why.empty() ? "" : "; ") + part; };
  if (wide > 0)
    add("the aorta widens beyond " + FormatNumber(100.0 + p.neckDilationPercent, 0) + " % of (a) under " +
        Percent(100.0 * wide / n) + " of the ring (the aneurysm)");
  if (thrombus > 0)
    add("thrombus over " + FormatNumber(p.maxThrombusMm, 0) + " mm thick under " + Percent(100.0 * thrombus / n) +
        " of the ring");
  if (gap > 0)
    add(Percent(100.0 * gap / n) + " of the ring is not apposed (gap up to " + Mm(largestGap) + ")");
  return why;
}

/// Why vertex i does not seal, in words (the shortest apposition length's column).
std::string WhyVertexDoesNotSeal(int i, const FitCheck& c, bool aneurysmal, const FitCheckParams& p)
{
  const std::string overCalcium = c.calcified[i] == 1 ? " over calcium" : "";
  if (c.appositionMm[i] > p.contactToleranceMm)
    return "it is not in contact with the wall" + overCalcium + " (gap " + Mm(c.appositionMm[i]) + ")";
  if (aneurysmal)
    return "the aorta under it is wider than " + FormatNumber(100.0 + p.neckDilationPercent, 0) +
           " % of (a) (the aneurysm)";
  if (c.healthyWall[i] == 0 && c.thrombusUnderMm[i] > p.maxThrombusMm)
    return "it lies on thrombus " + Mm(c.thrombusUnderMm[i]) + " thick (over " + FormatNumber(p.maxThrombusMm, 0) +
           " mm)";
  if (c.healthyWall[i] == 0 && c.calcified[i] == 1)
    return "it lies on calcium";
  return "it does not seal";
}

/// The direction from `centre` to `vertex` across the unit `axis`, in the patient's words (LPS: +x
/// left, +y posterior, +z superior): each axis whose share of the unit direction is at least
/// sin 22.5° (eight sectors around an axial graft), the larger first — "left posterior", "anterior".
std::string PatientSide(const Point3& centre, const Point3& vertex, const Eigen::Vector3d& axis)
{
  Eigen::Vector3d d = vertex - centre;
  d -= d.dot(axis) * axis;
  if (d.norm() < 1e-9)
    return "centre";
  d.normalize();
  const char* positive[3] = { "left", "posterior", "superior" };
  const char* negative[3] = { "right", "anterior", "inferior" };
  std::vector<std::pair<double, std::string>> parts;
  for (int a = 0; a < 3; ++a)
    if (std::abs(d[a]) >= std::sin(pi / 8.0))
      parts.emplace_back(std::abs(d[a]), d[a] > 0.0 ? positive[a] : negative[a]);
  std::sort(parts.begin(), parts.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  std::string words;
  for (const auto& part : parts)
    words += (words.empty() ? "" : " ") + part.second;
  return words;
}

std::string ComponentWords(const ConfiguredComponent& c)
{
  return c.item.name + (c.item.code.empty() ? "" : " " + c.item.code);
}

} // namespace

std::string FitCheck::CoveredOstia() const
{
  std::string names;
  for (const OstiumCoverage& o : ostia)
    if (o.covered)
      names += (names.empty() ? "" : ", ") + o.branch;
  return names.empty() ? "none" : names;
}

FitCheck CheckGraftFit(const DeployedGraft& graft,
                       const Measurements& measured,
                       const CenterlineTree& tree,
                       const VesselWall* wall,
                       const FitCheckContext& context,
                       const FitCheckParams& p)
{
  const GraftLayout& layout = graft.layout;
  const StentMesh& mesh = layout.mesh;
  const Eigen::Index n = mesh.V.rows();
  const Points& V = graft.fit.V;
  if (V.rows() != n || graft.fit.wallDistanceMm.size() != n || layout.component.size() != n)
    throw InputError("The simulated graft has " + std::to_string(V.rows()) + " vertices and " +
                     std::to_string(graft.fit.wallDistanceMm.size()) + " wall distances; expected the layout's " +
                     std::to_string(n) + ".");
  const double aOuter = measured.Value("proximalNeckDiameter");
  const double neckLimit = std::isfinite(aOuter) ? (1.0 + p.neckDilationPercent / 100.0) * aOuter : NaN;
  FitCheck c;
  c.oversizingPercent.resize(n);
  c.appositionMm.resize(n);
  c.healthyWall.resize(n);
  c.thrombusUnderMm.resize(n);
  c.calcified.resize(n);
  c.sealing.resize(n);
  std::vector<bool> aneurysmal(std::size_t(n), false);
  std::vector<bool> outerAt(std::size_t(n), false);
  for (Eigen::Index i = 0; i < n; ++i)
  {
    const int seg = mesh.segment[i], k = mesh.ring[i];
    const double s = mesh.ringAbscissaMm[std::size_t(seg)][std::size_t(k)];
    const WallUnder under = ReadWallUnder(wall, seg, s, V.row(i).transpose(), neckLimit, p);
    c.healthyWall[i] = under.healthy;
    c.thrombusUnderMm[i] = under.thrombusMm;
    c.calcified[i] = under.calcified;
    aneurysmal[std::size_t(i)] = under.aneurysmal;
    outerAt[std::size_t(i)] = std::isfinite(under.vesselDiameterMm);
    const double vessel =
      std::isfinite(under.vesselDiameterMm) ? under.vesselDiameterMm : LumenDiameterAt(measured, tree, seg, s);
    c.oversizingPercent[i] = OversizingPercent(2.0 * layout.nominalRadiusMm[i], vessel);
    c.appositionMm[i] = std::max(0.0, -graft.fit.wallDistanceMm[i]);
    c.sealing[i] = c.appositionMm[i] <= p.contactToleranceMm && under.healthy != 0 ? 1 : 0;
  }

  // The proximal seal, from the trunk's first ring down, and the shortest apposition length.
  const std::vector<double>& trunkS = mesh.ringAbscissaMm[TrunkSegment];
  const int trunkRings = mesh.RingsIn(TrunkSegment);
  int failing = -1;
  c.proximalSealLengthMm = SealedLength(
    trunkS, 0, trunkRings - 1, 1, [&](int k) { return SealingShare(mesh, TrunkSegment, k, c.sealing); },
    p.sealedRingFraction, &failing);
  if (failing >= 0)
  {
    c.proximalSealEnd = WhyRingDoesNotSeal(mesh, failing, c, aneurysmal, p);
    // Where the wall turns unhealthy between the last sealing ring and the first that does not,
    // read on the wall's own planes (1 mm apart) rather than half-way between rings (4 mm): where
    // the unhealthy share crosses its limit, linear between the last plane under it and the first
    // over it (the first plane over it alone read the onset 0–1 mm late, +0.6 on average, and on
    // 1 mm slices a neck-thrombus onset up to 1.6 mm late).
    if (failing > 0 && wall)
    {
      const double from = trunkS[std::size_t(failing - 1)], to = trunkS[std::size_t(failing)];
      const double limit = 1.0 - p.sealedRingFraction;
      const OuterWallPlane* previous = nullptr;
      double previousShare = 0.0;
      for (const OuterWallPlane& plane : wall->vessels[TrunkSegment].planes)
      {
        if (plane.abscissaMm > to || !plane.Usable() || plane.thrombusMm.size() == 0)
          continue;
        const double share = UnhealthyShare(plane, neckLimit, p);
        if (plane.abscissaMm > from && share > limit)
        {
          double end = plane.abscissaMm;
          if (previous && previousShare <= limit && plane.abscissaMm - previous->abscissaMm <= 2.0 * wall->stepMm)
            end = previous->abscissaMm +
                  (limit - previousShare) / (share - previousShare) * (plane.abscissaMm - previous->abscissaMm);
          c.proximalSealLengthMm = std::max(from, end) - trunkS.front();
          break;
        }
        previous = &plane;
        previousShare = share;
      }
    }
  }
  // The seal's uncertainty: its top (the site) and its end (where the wall turns unhealthy) are
  // each placed no better than the wall planes' 1 mm step or, on coarser scans, the sampling
  // interval along the aorta (a thrombus onset blurred over a 2.5 mm slice).
  const double voxel = std::isfinite(context.voxelAlongAortaMm) ? context.voxelAlongAortaMm : 0.0;
  c.proximalSealUncertaintyMm = std::max(p.sealUncertaintyMm, 2.0 * voxel);
  c.proximalSealUncertaintyWhy =
    2.0 * voxel > p.sealUncertaintyMm
      ? "the site's and the seal end's " + Mm(voxel) + " each, the scan's sampling interval along the aorta"
      : "the site's 1 mm and the wall planes' 1 mm";

  // The shortest apposition length: the shortest column's continuous sealed length from the edge,
  // where that column lies and why it stops.
  c.shortestAppositionLengthMm = std::numeric_limits<double>::infinity();
  int shortestColumn = 0, shortestEnd = -1;
  for (int j = 0; j < mesh.verticesPerRing; ++j)
  {
    int columnEnd = -1;
    const double length = SealedLength(
      trunkS, 0, trunkRings - 1, 1, [&](int k) { return double(c.sealing[mesh.Id(TrunkSegment, k, j)]); }, 1.0,
      &columnEnd);
    if (length < c.shortestAppositionLengthMm)
    {
      c.shortestAppositionLengthMm = length;
      shortestColumn = j;
      shortestEnd = columnEnd;
    }
  }
  {
    const Point3 top = RingCentroid(mesh, V, TrunkSegment, 0);
    const Eigen::Vector3d down =
      trunkRings > 1 ? Eigen::Vector3d(RingCentroid(mesh, V, TrunkSegment, 1) - top) : Eigen::Vector3d::Zero();
    const Eigen::Vector3d axis = down.norm() > 1e-9 ? down.normalized() : Eigen::Vector3d::UnitZ();
    c.shortestAppositionSide = PatientSide(top, V.row(mesh.Id(TrunkSegment, 0, shortestColumn)).transpose(), axis);
    if (shortestEnd >= 0)
    {
      const int i = mesh.Id(TrunkSegment, shortestEnd, shortestColumn);
      c.shortestAppositionEnd = WhyVertexDoesNotSeal(i, c, aneurysmal[std::size_t(i)], p);
    }
  }
  const int sealedRings = failing < 0 ? trunkRings : failing;
  int calcified = 0, zone = 0;
  for (int k = 0; k < sealedRings; ++k)
    for (int j = 0; j < mesh.verticesPerRing; ++j)
    {
      const int i = mesh.Id(TrunkSegment, k, j);
      ++zone;
      calcified += c.calcified[i] == 1 ? 1 : 0;
      c.sealOnLumenOnly[0] = c.sealOnLumenOnly[0] || c.healthyWall[i] < 0;
    }
  c.proximalCalcifiedPercent = zone > 0 ? 100.0 * calcified / zone : 0.0;

  // Oversizing summaries, the vessel on the outer wall where traced.
  int outerSummaries = 0, summaries = 1;
  const auto ringOversizing = [&](int seg, int k, bool& outer)
  {
    std::vector<double> values;
    outer = true;
    for (int j = 0; j < mesh.verticesPerRing; ++j)
    {
      const int i = mesh.Id(seg, k, j);
      values.push_back(c.oversizingPercent[i]);
      outer = outer && outerAt[std::size_t(i)];
    }
    return Median(values);
  };
  bool outerTop = false;
  c.proximalOversizingPercent = ringOversizing(TrunkSegment, 0, outerTop);
  outerSummaries += outerTop ? 1 : 0;
  double* iliacSeal[2] = { &c.rightIliacSealLengthMm, &c.leftIliacSealLengthMm };
  double* limbOversizing[2] = { &c.rightLimbOversizingPercent, &c.leftLimbOversizingPercent };
  for (int side = 0; side < 2; ++side)
  {
    c.limbChecked[side] = context.limbSized[side];
    if (!c.limbChecked[side])
    {
      *iliacSeal[side] = *limbOversizing[side] = NaN;
      continue;
    }
    ++summaries;
    const int seg = 1 + side, last = mesh.RingsIn(seg) - 1;
    const std::vector<double>& s = mesh.ringAbscissaMm[std::size_t(seg)];
    int legFailing = -1;
    *iliacSeal[side] = SealedLength(
      s, last, 0, -1, [&](int k) { return SealingShare(mesh, seg, k, c.sealing); }, p.sealedRingFraction, &legFailing);
    for (int k = last; k >= 0 && k != legFailing; --k)
      for (int j = 0; j < mesh.verticesPerRing; ++j)
        c.sealOnLumenOnly[std::size_t(1 + side)] =
          c.sealOnLumenOnly[std::size_t(1 + side)] || c.healthyWall[mesh.Id(seg, k, j)] < 0;
    std::vector<double> zoneValues;
    bool allOuter = true;
    for (int k = 0; k <= last; ++k)
      if (s[std::size_t(k)] >= s[std::size_t(last)] - landingZoneMm - 1e-9)
      {
        bool outer = false;
        zoneValues.push_back(ringOversizing(seg, k, outer));
        allOuter = allOuter && outer;
      }
    *limbOversizing[side] = Median(zoneValues);
    outerSummaries += allOuter ? 1 : 0;
  }
  c.oversizingWall = outerSummaries == summaries ? "outer" : outerSummaries == 0 ? "lumen" : "mixed";

  // Ostia under the deployed graft.
  const struct
  {
    const char* branch;
    const Centerline* parent;
    int segment;
  } branches[] = { { "rightRenal", &tree.aorta, TrunkSegment },
                   { "leftRenal", &tree.aorta, TrunkSegment },
                   { "superiorMesenteric", &tree.aorta, TrunkSegment },
                   { "coeliac", &tree.aorta, TrunkSegment },
                   { "rightInternalIliac", &tree.rightIliac, RightLegSegment },
                   { "leftInternalIliac", &tree.leftIliac, LeftLegSegment } };
  for (const auto& b : branches)
  {
    const Centerline* branch = tree.FindVessel(b.branch);
    if (!branch || branch->Size() < 2 || (b.segment != TrunkSegment && !c.limbChecked[std::size_t(b.segment - 1)]))
      continue; // an unsized leg is not the device's: where its limb would end is not known
    const BranchOstium ostium = FindBranchOstium(*b.parent, *branch);
    if (!ostium.found)
      continue;
    const std::vector<double>& s = mesh.ringAbscissaMm[std::size_t(b.segment)];
    OstiumCoverage o;
    o.branch = b.branch;
    o.parent = b.parent->name;
    o.upperAbscissaMm = ostium.upperAbscissaMm;
    o.lowerAbscissaMm = ostium.lowerAbscissaMm;
    o.overlapMm = std::min(s.back(), ostium.lowerAbscissaMm) - std::max(s.front(), ostium.upperAbscissaMm);
    o.covered = o.overlapMm > p.ostiumOverlapToleranceMm;
    const bool renal = std::string(b.branch).find("Renal") != std::string::npos;
    // A configured graft is deployed at the plan's target, which carries the site's margin; an
    // unconfigured one lies on the measure-mode mesh from the site as read (its coverage as read).
    if (layout.configured && b.segment == TrunkSegment && (!renal || measured.site.source == ProximalSiteSource::Renal))
    {
      const OstiumEdgeUncertainty u = EdgeUncertainty(*branch, tree.largestSpacingMm);
      o.edgeUncertaintyMm = u.mm;
      o.edgeUncertaintyWhy = u.why;
      // 1 µm: a graft placed at SiteMarginMm lies exactly at the bound, and its abscissa is read back
      // through the mesh.
      o.mayBeCovered = !o.covered && o.overlapMm + u.mm > p.ostiumOverlapToleranceMm + 1e-3;
    }
    c.ostia.push_back(o);
  }

  // Findings.
  const ConfiguredComponent& body = layout.components.front();
  const auto atEnd = [&](int side) -> const ConfiguredComponent&
  {
    const ConfiguredComponent* last = &body;
    for (const ConfiguredComponent& part : layout.components)
      if (part.role != OrderRole::MainBody && part.side == side && part.distalMm >= last->distalMm - 1e-9)
        last = &part;
    return *last;
  };
  const std::string range =
    FormatNumber(p.oversizingMinPercent, 0) + "–" + FormatNumber(p.oversizingMaxPercent, 0) + " %";
  const auto oversizingFindings = [&](double percent, const std::string& where)
  {
    if (percent > p.infoldingPercent)
      c.findings.push_back("infolding risk: " + where + " oversized " + Percent(percent) + " (over " +
                           Percent(p.infoldingPercent) + ")");
    else if (percent < p.oversizingMinPercent || percent > p.oversizingMaxPercent)
      c.findings.push_back(where + " oversizing " + Percent(percent) + " outside " + range);
  };
  oversizingFindings(c.proximalOversizingPercent, "the " + ComponentWords(body) + " at the proximal edge");
  const char* sides[2] = { "right", "left" };
  for (int side = 0; side < 2; ++side)
    if (c.limbChecked[side])
      oversizingFindings(*limbOversizing[side],
                         "the " + ComponentWords(atEnd(side)) + " in the " + sides[side] + " landing zone");
  if (c.proximalSealLengthMm < p.minimumProximalSealMm)
  {
    c.migrationRisk = true;
    c.findings.push_back("type Ia endoleak and migration risk: proximal seal " + Mm(c.proximalSealLengthMm) +
                         ", needs ≥ " + FormatNumber(p.minimumProximalSealMm, 0) + " mm — the " + ComponentWords(body) +
                         " seals from its proximal edge down to " + Mm(c.proximalSealLengthMm) + " below it" +
                         (c.proximalSealEnd.empty() ? "" : ", where " + c.proximalSealEnd));
  }
  else if (c.proximalSealLengthMm < p.minimumProximalSealMm + c.proximalSealUncertaintyMm)
  {
    c.migrationRisk = true;
    c.findings.push_back("type Ia endoleak and migration risk cannot be excluded: proximal seal " +
                         Mm(c.proximalSealLengthMm) + ", within its uncertainty (" + Mm(c.proximalSealUncertaintyMm) +
                         ": " + c.proximalSealUncertaintyWhy + ") of the " + FormatNumber(p.minimumProximalSealMm, 0) +
                         " mm needed — the " + ComponentWords(body) + " seals from its proximal edge down to " +
                         Mm(c.proximalSealLengthMm) + " below it" +
                         (c.proximalSealEnd.empty() ? "" : ", where " + c.proximalSealEnd));
  }
  if (c.shortestAppositionLengthMm < p.minimumAppositionLengthMm)
  {
    c.migrationRisk = true;
    c.findings.push_back("type Ia endoleak and migration risk: shortest apposition length " +
                         Mm(c.shortestAppositionLengthMm) + ", needs ≥ " +
                         FormatNumber(p.minimumAppositionLengthMm, 0) + " mm — the " + ComponentWords(body) +
                         " on the patient's " + c.shortestAppositionSide +
                         " side is apposed from its proximal edge down to " + Mm(c.shortestAppositionLengthMm) +
                         " below it" + (c.shortestAppositionEnd.empty() ? "" : ", where " + c.shortestAppositionEnd));
  }
  const double iliacMinimum =
    std::isfinite(context.minimumIliacSealMm) ? context.minimumIliacSealMm : p.minimumIliacSealMm;
  c.minimumProximalSealMm = p.minimumProximalSealMm;
  c.minimumIliacSealMm = iliacMinimum;
  c.minimumAppositionLengthMm = p.minimumAppositionLengthMm;
  for (int side = 0; side < 2; ++side)
    if (c.limbChecked[side] && *iliacSeal[side] < iliacMinimum)
      c.findings.push_back("type Ib endoleak risk: " + std::string(sides[side]) + " iliac seal " +
                           Mm(*iliacSeal[side]) + ", needs ≥ " + FormatNumber(iliacMinimum, 0) + " mm — the " +
                           ComponentWords(atEnd(side)) + " seals over its distal " + Mm(*iliacSeal[side]));
  // Overlaps on the deployed fabric: each component in the one before it on its side's chain, along
  // the graft (the fabric positions it was deployed at, which LayOutGraft keeps: DeployGraft.h).
  const std::vector<std::array<double, 2>>& fabric = layout.fabricMm;
  if (layout.configured && fabric.size() == layout.components.size() && std::isfinite(context.minimumOverlapMm))
    for (int side = 0; side < 2; ++side)
    {
      const ConfiguredComponent* outer = &body;
      double outerEnd = side == layout.ipsilateralSide ? fabric.front()[1] : layout.fabricGateEndMm;
      for (std::size_t index = 0; index < layout.components.size(); ++index)
      {
        const ConfiguredComponent& part = layout.components[index];
        if (part.role == OrderRole::MainBody || part.side != side)
          continue;
        const double overlap = outerEnd - fabric[index][0];
        if (overlap < context.minimumOverlapMm - 1e-6)
          c.findings.push_back("type III endoleak risk: the " + ComponentWords(part) + " overlaps " + Mm(overlap) +
                               " in the " + ComponentWords(*outer) + ", needs ≥ " +
                               FormatNumber(context.minimumOverlapMm, 0) + " mm");
        outer = &part;
        outerEnd = fabric[index][1];
      }
    }
  for (const OstiumCoverage& o : c.ostia)
    if (o.covered)
      c.findings.push_back("the " + IdentifierWords(o.branch) + " ostium is covered by the deployed graft (" +
                           Mm(o.overlapMm) + " of it, on the " + IdentifierWords(o.parent) + ")");
    else if (o.mayBeCovered)
      c.findings.push_back(
        "the " + IdentifierWords(o.branch) + " ostium may be covered by the deployed graft: the graft's edge lies " +
        Mm(std::max(0.0, -o.overlapMm)) + " from the ostium's edge, within that edge's uncertainty of " +
        Mm(o.edgeUncertaintyMm) + " (" + o.edgeUncertaintyWhy + ")");
  for (const ConfigurationFinding& f : context.configurationFindings)
    c.findings.push_back(f.text + " — option: " + f.option);
  return c;
}

double SiteMarginMm(const ProximalSite& site, const FitCheckParams& params)
{
  return site.source == ProximalSiteSource::Renal
           ? std::max(0.0, site.edgeUncertaintyMm - params.ostiumOverlapToleranceMm)
           : 0.0;
}

std::vector<Measurement> FitCheckRows(const FitCheck& c, const DeployedGraft& graft)
{
  const StentMesh& mesh = graft.layout.mesh;
  const double top = mesh.ringAbscissaMm[TrunkSegment].front();
  const double rightEnd = mesh.ringAbscissaMm[RightLegSegment].back(),
               leftEnd = mesh.ringAbscissaMm[LeftLegSegment].back();
  const std::string over = c.oversizingWall == "outer"   ? "outer wall"
                           : c.oversizingWall == "lumen" ? "lumen"
                                                         : "outer wall where traced, else lumen";
  const auto estimated = [&](int zone)
  {
    return c.sealOnLumenOnly[std::size_t(zone)] ? "; estimated (lumen): the outer wall not traced under part of it"
                                                : "";
  };
  std::vector<Measurement> rows = {
    { "proximalSealLength", c.proximalSealLengthMm, "mm",
      std::string("simulated graft: sealed length from its proximal edge down, on healthy wall (apposed, thrombus ") +
        "under 2 mm, outer diameter within 10 % of (a)); uncertainty " + Mm(c.proximalSealUncertaintyMm) + " (" +
        c.proximalSealUncertaintyWhy + ")" + estimated(0),
      "aorta", top },
    { "rightIliacSealLength", c.rightIliacSealLengthMm, "mm",
      std::string("simulated graft: sealed length from the right distal edge up, on healthy wall") + estimated(1),
      "rightIliac", rightEnd },
    { "leftIliacSealLength", c.leftIliacSealLengthMm, "mm",
      std::string("simulated graft: sealed length from the left distal edge up, on healthy wall") + estimated(2),
      "leftIliac", leftEnd },
    { "proximalOversizing", c.proximalOversizingPercent, "%",
      "main body diameter over the vessel at the graft's proximal edge, minus 1, " + over, "aorta", top },
    { "rightLimbOversizing", c.rightLimbOversizingPercent, "%",
      "right limb diameter over the common iliac's landing zone diameter, minus 1, " + over, "rightIliac", rightEnd },
    { "leftLimbOversizing", c.leftLimbOversizingPercent, "%",
      "left limb diameter over the common iliac's landing zone diameter, minus 1, " + over, "leftIliac", leftEnd },
  };
  for (std::size_t i = 0; i < rows.size(); ++i)
  {
    rows[i].wall = i < 3 ? "lumen" : c.oversizingWall == "mixed" ? "outer" : c.oversizingWall;
    rows[i].estimated = i < 3 && c.sealOnLumenOnly[i];
  }
  return rows;
}

} // namespace sgp
