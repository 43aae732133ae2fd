#include "Measurement/MeasureOuterWall.h"

#include <algorithm>
#include <cmath>

#include "Common/Format.h"
#include "Common/Median.h"
#include "Measurement/DistalAorta.h"

namespace sgp
{
namespace
{

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double pi = 3.14159265358979323846;
constexpr double secondDiameterDepthMm = 15.0; ///< (b), as MeasureAnatomy
constexpr double neckStretchMm = 15.0;         ///< the neck's seal zone for the arcs
constexpr double thrombusArcMm = 2.0;          ///< vessel-wall.md §3.1: "significant" neck thrombus is > 2 mm thick
constexpr double neckDilationFactor = 1.10;

/// The plane within half a step of s, or nullptr.
const OuterWallPlane* PlaneAt(const OuterWall& vessel, double s, double stepMm)
{
  const OuterWallPlane* p = vessel.Nearest(s);
  return p && std::abs(p->abscissaMm - s) <= 0.5 * stepMm + 1e-9 ? p : nullptr;
}

std::string Percent(double fraction)
{
  return FormatNumber(100.0 * fraction, 0) + " %";
}

/// An outer diameter Measurement from one plane (value: area-equivalent diameter), with its
/// support judged; NaN with a warning when there is no usable plane.
Measurement OuterDiameter(const std::string& name,
                          const OuterWallPlane* plane,
                          double value,
                          double supportedFraction,
                          const std::string& vessel,
                          double s,
                          const std::string& definition,
                          Measurements& out)
{
  Measurement m{ name, nan, "mm", definition + ", outer wall", vessel, s };
  m.wall = "outer";
  if (!plane)
  {
    out.warnings.push_back(name + ": no outer wall was traced at " + FormatNumber(s) + " mm along the " + vessel +
                           " (no fat outside the vessel there?); not measured.");
    return m;
  }
  if (!plane->Usable())
  {
    out.warnings.push_back(
      name + ": only " + Percent(supportedFraction) + " of the circumference at " + FormatNumber(s) + " mm along the " +
      vessel +
      " shows an outer wall (at least 25 % needed) and the traced planes above and below lie more than "
      "20 mm apart (or one is missing); not "
      "measured.");
    return m;
  }
  m.value = value;
  m.abscissaMm = plane->abscissaMm;
  m.minMm = plane->minCaliperMm;
  m.maxMm = plane->maxCaliperMm;
  m.areaMm = plane->areaDiameterMm;
  if (plane->interpolated)
  {
    m.estimated = true;
    out.warnings.push_back(name + " is estimated: only " + Percent(supportedFraction) + " of the circumference at " +
                           FormatNumber(plane->abscissaMm) + " mm along the " + vessel +
                           " shows an outer wall; the contour there is interpolated from the traced planes above and "
                           "below (" +
                           FormatNumber(value) + " mm).");
  }
  else if (supportedFraction < EstimatedBelowSupport)
  {
    m.estimated = true;
    out.warnings.push_back(name + " is estimated: only " + Percent(supportedFraction) + " of the circumference at " +
                           FormatNumber(plane->abscissaMm) + " mm along the " + vessel +
                           " shows an outer wall (60 % wanted); the rest is interpolated from the supported sectors (" +
                           FormatNumber(value) + " mm).");
  }
  return m;
}

Measurement Plain(const std::string& name,
                  double value,
                  const std::string& unit,
                  const std::string& definition,
                  double s)
{
  Measurement m{ name, value, unit, definition, "aorta", s };
  m.wall = "outer";
  return m;
}

/// (e) or (f): the median over the iliac planes of the landing zone.
Measurement OuterIliac(const VesselWall& wall, int side, const OuterWallLevels& levels, Measurements& out)
{
  const OuterWall& vessel = wall.vessels[1 + side];
  std::vector<const OuterWallPlane*> zone;
  for (const OuterWallPlane& p : vessel.planes)
    if (p.abscissaMm >= levels.landingFromMm[side] - 1e-9 && p.abscissaMm <= levels.landingToMm[side] + 1e-9 &&
        p.Usable())
      zone.push_back(&p);
  const std::string name = side == 0 ? "rightIliacDiameter" : "leftIliacDiameter";
  const std::string definition =
    std::string(side == 0 ? "(e)" : "(f)") +
    " median area-equivalent diameter of the common iliac over the leg's distal 15 mm (landing zone)";
  const double s = 0.5 * (levels.landingFromMm[side] + levels.landingToMm[side]);
  if (zone.size() < 2)
    return OuterDiameter(name, nullptr, nan, 0.0, wall.names[1 + side], s, definition, out);
  std::vector<double> diameters, support;
  for (const OuterWallPlane* p : zone)
  {
    diameters.push_back(p->areaDiameterMm);
    support.push_back(p->supportedFraction);
  }
  const OuterWallPlane* middle = zone[zone.size() / 2];
  Measurement m = OuterDiameter(name, middle, Median(diameters), Median(support), wall.names[1 + side],
                                middle->abscissaMm, definition, out);
  return m;
}

/// The longest stretch of [fromMm, toMm] with no plane that has a contour, mm.
double LongestGap(const OuterWall& vessel, double fromMm, double toMm)
{
  double last = fromMm, gap = 0.0;
  for (const OuterWallPlane& p : vessel.planes)
    if (p.Usable() && p.abscissaMm >= fromMm - 1e-9 && p.abscissaMm <= toMm + 1e-9)
    {
      gap = std::max(gap, p.abscissaMm - last);
      last = p.abscissaMm;
    }
  return std::max(gap, toMm - last);
}

/// A largest or smallest over a stretch, or a volume over it, is only known when the stretch was
/// traced: a gap of more than this may hide the extreme.
constexpr double largestGapMm = 10.0;

/// NaN and a warning when `m` is an extreme over a stretch with a gap.
void RequireCovered(Measurement& m, const OuterWall& vessel, double fromMm, double toMm, Measurements& out)
{
  const double gap = LongestGap(vessel, fromMm, toMm);
  if (std::isfinite(m.value) && gap > largestGapMm)
  {
    out.warnings.push_back(m.name + ": the outer wall is not traced over " + FormatNumber(gap) + " mm between " +
                           FormatNumber(fromMm) + " and " + FormatNumber(toMm) +
                           " mm along the aorta (neighbours hide it); not measured.");
    m.value = nan;
  }
}

/// (d) on a sac that narrows right into the bifurcation: its narrowest level is B itself, and the
/// wall's last plane lies up to a step above it, where the funnel widens by up to 2.2 mm of
/// diameter per mm (a 75 mm sac over 80 mm into an 18 mm bifurcation: 20.4 mm read for 18, 0.7 mm
/// above B). When `narrowest` is the lowest plane that counts, lies above B's level and the plane
/// before it (within 1.5 steps) is wider, `value` becomes the line through the two extrapolated
/// down to B's level (never more than 1.5 steps: the planes lie a step apart along the centerline,
/// which leans off the distal direction and ends short of B — 1.05 mm above it on a 1.25 mm funnel
/// in FlowDividerPlanTest); returns whether it did.
template<typename Counts>
bool ExtrapolateToB(const OuterWall& aorta,
                    double stepMm,
                    const OuterWallPlane& narrowest,
                    const OuterWallLevels& levels,
                    const Counts& counts,
                    double& value)
{
  const auto height = [&](const OuterWallPlane& p)
  { return -(p.centreLps - levels.bifurcationLps).dot(levels.distalDirection); };
  const OuterWallPlane* above = nullptr;
  for (const OuterWallPlane& p : aorta.planes)
  {
    if (!p.Usable() || !counts(p))
      continue;
    if (p.abscissaMm > narrowest.abscissaMm + 1e-9)
      return false; // not the lowest
    if (p.abscissaMm < narrowest.abscissaMm - 1e-9 && p.abscissaMm >= narrowest.abscissaMm - 1.5 * stepMm)
      above = &p;
  }
  const double h = height(narrowest);
  if (!above || h <= 0.0 || h > 1.5 * stepMm)
    return false;
  const double rise = height(*above) - h, widening = above->areaDiameterMm - narrowest.areaDiameterMm;
  if (rise <= 0.0 || widening <= 0.0)
    return false;
  value = narrowest.areaDiameterMm - h * widening / rise;
  return true;
}

} // namespace

Point3 OuterAxisPoint(const VesselWall* wall, const Centerline& aorta, double s)
{
  const OuterWallPlane* p = wall ? PlaneAt(wall->vessels[0], s, wall->stepMm) : nullptr;
  if (!p || p->flagged)
    return PositionAt(aorta, s);
  return p->centroidLps;
}

void MeasureOuterWall(const VesselWall& wall, const OuterWallLevels& levels, Measurements& out)
{
  const OuterWall& aorta = wall.vessels[0];
  const double step = wall.stepMm;
  const OuterWallPlane* a = PlaneAt(aorta, levels.siteMm, step);
  out.values.push_back(OuterDiameter("proximalNeckDiameter", a, a ? a->areaDiameterMm : nan,
                                     a ? a->supportedFraction : 0.0, "aorta", levels.siteMm,
                                     "(a) area-equivalent diameter at the proximal implantation site", out));
  const double aOuter = out.values.back().value;
  const double sB = levels.siteMm + secondDiameterDepthMm;
  const OuterWallPlane* b = PlaneAt(aorta, sB, step);
  out.values.push_back(OuterDiameter("neckDiameter15mm", b, b ? b->areaDiameterMm : nan, b ? b->supportedFraction : 0.0,
                                     "aorta", sB, "(b) area-equivalent diameter 15 mm below the proximal site", out));
  // (c): the largest maximum caliper over [site, B]; (d): the smallest area diameter below it.
  const OuterWallPlane* widest = nullptr;
  for (const OuterWallPlane& p : aorta.planes)
    if (p.abscissaMm >= levels.siteMm - 1e-9 && p.abscissaMm <= levels.bifurcationMm && p.Usable() &&
        (!widest || p.maxCaliperMm > widest->maxCaliperMm))
      widest = &p;
  out.values.push_back(
    OuterDiameter("maxAneurysmDiameter", widest, widest ? widest->maxCaliperMm : nan,
                  widest ? widest->supportedFraction : 0.0, "aorta", widest ? widest->abscissaMm : levels.siteMm,
                  "(c) largest maximum caliper between the proximal site and the aortic bifurcation (Dmax)", out));
  // The caliper's ends on the arc no boundary showed on (a neighbour without a fat plane): the
  // width there is the fitted model's, estimated even where most of the circumference is traced.
  if (widest && !out.values.back().estimated && !widest->supported.empty())
  {
    const bool first = widest->supported[std::size_t(widest->maxCaliperRays[0])],
               second = widest->supported[std::size_t(widest->maxCaliperRays[1])];
    if (!first || !second)
    {
      const bool both = !first && !second;
      out.values.back().estimated = true;
      out.warnings.push_back("maxAneurysmDiameter is estimated: " + std::string(both ? "both ends" : "one end") +
                             " of its caliper at " + FormatNumber(widest->abscissaMm) + " mm along the aorta " +
                             (both ? "lie" : "lies") +
                             " where no outer boundary shows (a neighbour against the wall); the wall there is the " +
                             (widest->elliptical ? "ellipse" : "circle") + " fitted to the traced arc (" +
                             FormatNumber(widest->maxCaliperMm) + " mm).");
    }
  }
  RequireCovered(out.values.back(), aorta, levels.siteMm, std::min(levels.bifurcationMm, levels.trunkEndMm), out);
  // (d) down to the trunk's last ring, or on down to B where the wall still narrows there
  // (DistalAorta.h: a sac that narrows into the bifurcation).
  std::vector<AbscissaDiameter> toTrunkEnd;
  for (const OuterWallPlane& p : aorta.planes)
    if (widest && p.abscissaMm >= widest->abscissaMm && p.abscissaMm <= levels.trunkEndMm + 1e-9 && p.Usable())
      toTrunkEnd.push_back({ p.abscissaMm, p.areaDiameterMm });
  const bool toBifurcation = StillNarrowingAtItsEnd(toTrunkEnd) && levels.bifurcationMm > levels.trunkEndMm;
  const double dEndMm = toBifurcation ? levels.bifurcationMm : levels.trunkEndMm;
  // Below the trunk's last ring a plane counts only when its centre lies above B's level (half a
  // millimetre's grace): the lumen's centerline bends into an iliac at its end, and a plane there
  // cuts the iliac's origin obliquely (14.7 mm for 19.1, 0.9 mm below B, on issue 46's sweep).
  const auto counts = [&](const OuterWallPlane& p)
  {
    return p.abscissaMm <= levels.trunkEndMm + 1e-9 ||
           (p.centreLps - levels.bifurcationLps).dot(levels.distalDirection) <= 0.5;
  };
  const OuterWallPlane* narrowest = nullptr;
  for (const OuterWallPlane& p : aorta.planes)
    if (widest && p.abscissaMm >= widest->abscissaMm && p.abscissaMm <= dEndMm + 1e-9 && p.Usable() && counts(p) &&
        (!narrowest || p.areaDiameterMm < narrowest->areaDiameterMm))
      narrowest = &p;
  double dOuter = narrowest ? narrowest->areaDiameterMm : nan;
  bool extrapolated = false;
  if (toBifurcation && narrowest)
    extrapolated = ExtrapolateToB(aorta, step, *narrowest, levels, counts, dOuter);
  out.values.push_back(OuterDiameter(
    "distalNeckMinDiameter", narrowest, dOuter, narrowest ? narrowest->supportedFraction : 0.0, "aorta",
    narrowest ? narrowest->abscissaMm : dEndMm,
    toBifurcation ? std::string("(d) smallest area-equivalent diameter between (c) and the aortic bifurcation (the "
                                "wall still narrows at the trunk's last ring") +
                      (extrapolated ? "; extrapolated to B's level from the last two planes above it)" : ")")
                  : std::string("(d) smallest area-equivalent diameter between (c) and the trunk's last ring"),
    out));
  if (widest)
    RequireCovered(out.values.back(), aorta, widest->abscissaMm, dEndMm, out);
  for (int side = 0; side < 2; ++side)
    out.values.push_back(OuterIliac(wall, side, levels, out));

  // The neck's end and the reverse taper, on the outer wall.
  out.outerNeckEndMm = nan;
  if (std::isfinite(aOuter))
  {
    const double threshold = neckDilationFactor * aOuter;
    const OuterWallPlane* previous = nullptr;
    for (const OuterWallPlane& p : aorta.planes)
    {
      if (p.abscissaMm < levels.siteMm - 1e-9 || !p.Usable())
        continue;
      if (widest && p.abscissaMm > widest->abscissaMm)
        break;
      if (p.minCaliperMm > threshold)
      {
        double t = 1.0;
        if (previous && p.minCaliperMm > previous->minCaliperMm)
          t = std::clamp((threshold - previous->minCaliperMm) / (p.minCaliperMm - previous->minCaliperMm), 0.0, 1.0);
        out.outerNeckEndMm =
          previous ? std::max(levels.siteMm, previous->abscissaMm + t * (p.abscissaMm - previous->abscissaMm))
                   : p.abscissaMm;
        break;
      }
      previous = &p;
    }
    for (int i = 0; i < 2; ++i)
    {
      const OuterWallPlane* q = PlaneAt(aorta, levels.siteMm + (i == 0 ? 10.0 : 15.0), step);
      out.reverseTaperMm[i] = q && q->Usable() ? q->areaDiameterMm - aOuter : nan;
    }
  }

  // Thrombus, sac and calcium.
  double thrombusMm3 = 0.0, sacMm3 = 0.0, thickest = nan, thrombusArc = nan, calciumArc = nan;
  int sacPlanes = 0;
  const double w = wall.wallThicknessMm;
  for (std::size_t i = 0; i < aorta.planes.size(); ++i)
  {
    const OuterWallPlane& p = aorta.planes[i];
    if (p.abscissaMm < levels.siteMm - 1e-9 || p.abscissaMm > levels.bifurcationMm + 1e-9 || !p.Usable())
      continue;
    ++sacPlanes;
    // The slab's thickness along the axis the planes are ⊥ to (half the gap to each neighbour).
    const double before = i > 0 ? p.axisAbscissaMm - aorta.planes[i - 1].axisAbscissaMm : step;
    const double after = i + 1 < aorta.planes.size() ? aorta.planes[i + 1].axisAbscissaMm - p.axisAbscissaMm : step;
    const double slab = std::clamp(0.5 * (before + after), 0.0, 2.0 * step);
    const double R = 0.5 * p.areaDiameterMm;
    thrombusMm3 += std::max(0.0, pi * std::max(0.0, R - w) * std::max(0.0, R - w) - p.lumenAreaMm2) * slab;
    sacMm3 += p.areaMm2 * slab;
    if (p.thrombusMm.size() > 0 && !(p.thrombusMm.maxCoeff() <= thickest))
      thickest = p.thrombusMm.maxCoeff();
    if (p.abscissaMm <= levels.siteMm + neckStretchMm + 1e-9)
    {
      const double K = double(p.thrombusMm.size());
      const double thick = (p.thrombusMm.array() > thrombusArcMm).count() / K;
      const double calcified = std::count(p.calcified.begin(), p.calcified.end(), true) / K;
      thrombusArc = std::isfinite(thrombusArc) ? std::max(thrombusArc, 100.0 * thick) : 100.0 * thick;
      calciumArc = std::isfinite(calciumArc) ? std::max(calciumArc, 100.0 * calcified) : 100.0 * calcified;
    }
  }
  const double gap = LongestGap(aorta, levels.siteMm, std::min(levels.bifurcationMm, levels.trunkEndMm));
  const bool traced = sacPlanes >= 2 && gap <= largestGapMm;
  if (!traced)
    out.warnings.push_back("The outer wall is not traced over " + FormatNumber(gap) +
                           " mm between the proximal site and the bifurcation; thrombusVolume, sacVolume and "
                           "maxThrombusThickness are not measured.");
  const std::string stretch = "between the proximal site and the aortic bifurcation";
  out.values.push_back(Plain("thrombusVolume", traced ? thrombusMm3 / 1000.0 : nan, "mL",
                             "thrombus inside the outer wall less the lumen and a wall of " + FormatNumber(w) +
                               " mm (" + (wall.wallThicknessEstimated ? "measured above the neck" : "assumed") + "), " +
                               stretch,
                             levels.siteMm));
  out.values.push_back(Plain("sacVolume", traced ? sacMm3 / 1000.0 : nan, "mL",
                             "volume inside the outer wall, " + stretch, levels.siteMm));
  out.values.push_back(Plain("maxThrombusThickness", traced ? thickest : nan, "mm",
                             "largest thrombus thickness along a ray from the centerline (outer wall less lumen less "
                             "wall), " +
                               stretch,
                             levels.siteMm));
  out.values.push_back(Plain("neckThrombusArc", thrombusArc, "%",
                             "largest share of the circumference with thrombus thicker than 2 mm, proximal site to "
                             "15 mm below",
                             levels.siteMm));
  out.values.push_back(Plain("neckCalcificationArc", calciumArc, "%",
                             "largest share of the circumference with calcium (at least " +
                               FormatNumber(wall.calciumHu, 0) + " HU) in the wall, proximal site to 15 mm below",
                             levels.siteMm));
}

} // namespace sgp
