#include "Device/FitCheck.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "Common/Errors.h"
#include "Common/Format.h"
#include "Common/Median.h"
#include "Device/SelectDevice.h"

namespace sgp
{
namespace
{

constexpr double landingZoneMm = 15.0; ///< as MeasureAnatomy's (e)/(f)

/// Whether ring k of a segment seals.
bool RingSeals(const StentMesh& mesh, int seg, int k, const Eigen::VectorXi& sealing, double fraction)
{
  int touching = 0;
  for (int j = 0; j < mesh.verticesPerRing; ++j)
    touching += sealing[mesh.Id(seg, k, j)];
  return touching >= fraction * mesh.verticesPerRing;
}

std::string Percent(double value)
{
  return FormatNumber(value) + " %";
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

FitCheck CheckGraftFit(const StentMesh& mesh,
                       const Points& V,
                       const Eigen::VectorXd& wallDistanceMm,
                       const Measurements& measured,
                       const CenterlineTree& tree,
                       const std::array<double, 3>& graft,
                       const FitCheckParams& p,
                       const VesselWall* wall)
{
  const Eigen::Index n = mesh.V.rows();
  if (V.rows() != n || wallDistanceMm.size() != n)
    throw InputError("The simulated graft has " + std::to_string(V.rows()) + " vertices and " +
                     std::to_string(wallDistanceMm.size()) + " wall distances; expected the mesh's " +
                     std::to_string(n) + ".");
  for (int seg = 0; seg < 3; ++seg)
    if (measured.profiles[seg].rings.size() != static_cast<std::size_t>(mesh.RingsIn(seg)))
      throw InputError("The measurements have " + std::to_string(measured.profiles[seg].rings.size()) +
                       " rings on segment " + std::to_string(seg) + "; expected the mesh's " +
                       std::to_string(mesh.RingsIn(seg)) + " (measure and simulate the same mesh).");
  // The vessel diameter under ring k of segment seg, and whether it is the outer wall's.
  const auto vesselAt = [&](int seg, int k, bool& outer)
  {
    const double s = mesh.ringAbscissaMm[seg][std::size_t(k)];
    const OuterWallPlane* plane = wall ? wall->vessels[seg].Nearest(s) : nullptr;
    outer = plane && plane->Usable() && std::abs(plane->abscissaMm - s) <= 0.5 * wall->stepMm + 1e-9;
    return outer ? plane->areaDiameterMm : measured.profiles[seg].rings[std::size_t(k)].meanMm;
  };
  int outerSummaries = 0;
  FitCheck c;
  c.oversizingPercent.resize(n);
  c.appositionMm.resize(n);
  c.sealing.resize(n);
  for (Eigen::Index v = 0; v < n; ++v)
  {
    const int seg = mesh.segment[v], k = mesh.ring[v];
    bool outer = false;
    c.oversizingPercent[v] = OversizingPercent(graft[seg], vesselAt(seg, k, outer));
    c.appositionMm[v] = std::max(0.0, -wallDistanceMm[v]);
    c.sealing[v] = c.appositionMm[v] <= p.contactToleranceMm ? 1 : 0;
  }

  // Seal zones.
  const auto& trunkS = mesh.ringAbscissaMm[TrunkSegment];
  int k = 0;
  while (k < mesh.RingsIn(TrunkSegment) && RingSeals(mesh, TrunkSegment, k, c.sealing, p.sealedRingFraction))
    ++k;
  c.proximalSealLengthMm = k == 0 ? 0.0 : trunkS[std::min(k, mesh.RingsIn(TrunkSegment) - 1)] - trunkS[0];
  double* iliacSeal[2] = { &c.rightIliacSealLengthMm, &c.leftIliacSealLengthMm };
  double* limbOversizing[2] = { &c.rightLimbOversizingPercent, &c.leftLimbOversizingPercent };
  int summaries = 1; // the proximal one, then each sized limb's
  for (int side = 0; side < 2; ++side)
  {
    c.limbChecked[side] = std::isfinite(graft[1 + side]);
    if (!c.limbChecked[side])
    {
      *iliacSeal[side] = *limbOversizing[side] = std::numeric_limits<double>::quiet_NaN();
      continue;
    }
    ++summaries;
    const int seg = 1 + side, last = mesh.RingsIn(seg) - 1;
    const auto& s = mesh.ringAbscissaMm[seg];
    int m = last;
    while (m >= 0 && RingSeals(mesh, seg, m, c.sealing, p.sealedRingFraction))
      --m;
    *iliacSeal[side] = m == last ? 0.0 : s[last] - s[std::max(m, 0)];
    std::vector<double> zone;
    bool allOuter = true;
    for (int r = 0; r <= last; ++r)
      if (s[r] >= s[last] - landingZoneMm - 1e-9)
      {
        bool outer = false;
        zone.push_back(OversizingPercent(graft[seg], vesselAt(seg, r, outer)));
        allOuter = allOuter && outer;
      }
    *limbOversizing[side] = Median(zone);
    outerSummaries += allOuter ? 1 : 0;
  }
  bool outerTop = false;
  c.proximalOversizingPercent = OversizingPercent(graft[TrunkSegment], vesselAt(TrunkSegment, 0, outerTop));
  outerSummaries += outerTop ? 1 : 0;
  c.oversizingWall = outerSummaries == summaries ? "outer" : outerSummaries == 0 ? "lumen" : "mixed";

  // Ostia under the graft.
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
    if (!branch || branch->Size() < 2 || (b.segment != TrunkSegment && !c.limbChecked[b.segment - 1]))
      continue; // an unsized leg is not the device's: where its limb would end is not known
    const BranchOstium ostium = FindBranchOstium(*b.parent, *branch);
    if (!ostium.found)
      continue;
    const auto& s = mesh.ringAbscissaMm[b.segment];
    OstiumCoverage o{ b.branch, b.parent->name, ostium.upperAbscissaMm, ostium.lowerAbscissaMm };
    o.overlapMm = std::min(s.back(), ostium.lowerAbscissaMm) - std::max(s.front(), ostium.upperAbscissaMm);
    o.covered = o.overlapMm > p.ostiumOverlapToleranceMm;
    c.ostia.push_back(o);
  }

  // Findings.
  const auto outside = [&](double percent)
  { return percent < p.oversizingMinPercent || percent > p.oversizingMaxPercent; };
  const std::string range =
    FormatNumber(p.oversizingMinPercent, 0) + "–" + FormatNumber(p.oversizingMaxPercent, 0) + " %";
  if (outside(c.proximalOversizingPercent))
    c.findings.push_back("proximal oversizing " + Percent(c.proximalOversizingPercent) + " outside " + range);
  const char* sides[2] = { "right", "left" };
  for (int side = 0; side < 2; ++side)
    if (c.limbChecked[side] && outside(*limbOversizing[side]))
      c.findings.push_back(std::string(sides[side]) + " limb oversizing " + Percent(*limbOversizing[side]) +
                           " outside " + range);
  if (c.proximalSealLengthMm < p.minimumProximalSealMm)
  {
    c.migrationRisk = true;
    c.findings.push_back("proximal seal zone " + FormatNumber(c.proximalSealLengthMm) + " mm, needs ≥ " +
                         FormatNumber(p.minimumProximalSealMm, 0) + " mm: risk of migration and type Ia endoleak");
  }
  for (int side = 0; side < 2; ++side)
    if (c.limbChecked[side] && *iliacSeal[side] < p.minimumIliacSealMm)
      c.findings.push_back(std::string(sides[side]) + " iliac seal zone " + FormatNumber(*iliacSeal[side]) +
                           " mm, needs ≥ " + FormatNumber(p.minimumIliacSealMm, 0) + " mm: risk of type Ib endoleak");
  for (const OstiumCoverage& o : c.ostia)
    if (o.covered)
      c.findings.push_back(o.branch + " ostium covered by the graft (" + FormatNumber(o.overlapMm) + " mm)");
  return c;
}

std::vector<Measurement> FitCheckRows(const FitCheck& c, const StentMesh& mesh)
{
  const double top = mesh.ringAbscissaMm[TrunkSegment].front();
  const double rightEnd = mesh.ringAbscissaMm[RightLegSegment].back(),
               leftEnd = mesh.ringAbscissaMm[LeftLegSegment].back();
  const std::string over = c.oversizingWall == "outer"   ? "outer wall"
                           : c.oversizingWall == "lumen" ? "lumen"
                                                         : "outer wall where traced, else lumen";
  std::vector<Measurement> rows = {
    { "proximalSealLength", c.proximalSealLengthMm, "mm",
      "simulated graft: length from its top down to the first ring not in contact with the lumen wall", "aorta", top },
    { "rightIliacSealLength", c.rightIliacSealLengthMm, "mm",
      "simulated graft: length from the right leg's distal end up to the first ring not in contact with the lumen wall",
      "rightIliac", rightEnd },
    { "leftIliacSealLength", c.leftIliacSealLengthMm, "mm",
      "simulated graft: length from the left leg's distal end up to the first ring not in contact with the lumen wall",
      "leftIliac", leftEnd },
    { "proximalOversizing", c.proximalOversizingPercent, "%",
      "main body diameter over (a) at the graft's top, minus 1, " + over, "aorta", top },
    { "rightLimbOversizing", c.rightLimbOversizingPercent, "%",
      "right limb diameter over the common iliac's landing zone diameter, minus 1, " + over, "rightIliac", rightEnd },
    { "leftLimbOversizing", c.leftLimbOversizingPercent, "%",
      "left limb diameter over the common iliac's landing zone diameter, minus 1, " + over, "leftIliac", leftEnd },
  };
  for (std::size_t i = 0; i < rows.size(); ++i)
    rows[i].wall = i < 3 ? "lumen" : c.oversizingWall == "mixed" ? "outer" : c.oversizingWall;
  return rows;
}

} // namespace sgp
