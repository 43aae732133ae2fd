#include "Measurement/DistalAorta.h"

#include <algorithm>
#include <cmath>

#include "Common/PlaneDiameters.h"
#include "Measurement/SectionTilt.h"

namespace sgp
{
namespace
{

constexpr double pi = 3.14159265358979323846;
constexpr double sectionStepMm = 1.0;

/// One section ⊥ `normal` through `centre`: mean, smallest and largest of `count` diameters, and
/// the area-equivalent diameter of the polygon through their 2·count edge points.
RingDiameters ReadSection(const SmoothMask& mask, const Point3& centre, const Eigen::Vector3d& normal, int count)
{
  const Eigen::Vector3d n = normal.normalized(), u = PerpendicularTo(n), v = n.cross(u);
  const int edges = 2 * count;
  std::vector<double> r(static_cast<std::size_t>(edges));
  for (int k = 0; k < edges; ++k)
  {
    const double angle = pi * k / count;
    r[std::size_t(k)] = SmoothBoundaryDistance(mask, centre, std::cos(angle) * u + std::sin(angle) * v);
  }
  RingDiameters ring;
  ring.centre = centre;
  ring.minMm = std::numeric_limits<double>::infinity();
  double sum = 0.0, area = 0.0;
  for (int k = 0; k < count; ++k)
  {
    const double d = r[std::size_t(k)] + r[std::size_t(k + count)];
    sum += d;
    ring.minMm = std::min(ring.minMm, d);
    ring.maxMm = std::max(ring.maxMm, d);
  }
  for (int k = 0; k < edges; ++k)
    area += 0.5 * std::sin(pi / count) * r[std::size_t(k)] * r[std::size_t((k + 1) % edges)];
  ring.meanMm = sum / count;
  ring.areaMm = 2.0 * std::sqrt(area / pi);
  return ring;
}

} // namespace

bool StillNarrowingAtItsEnd(const std::vector<AbscissaDiameter>& profile)
{
  if (profile.size() < 2)
    return false;
  const AbscissaDiameter& last = profile.back();
  for (const AbscissaDiameter& p : profile)
    if (p.diameterMm < last.diameterMm)
      return false;
  // The reading nearest NarrowingWindowMm above the last, at least that far.
  const AbscissaDiameter* above = nullptr;
  for (const AbscissaDiameter& p : profile)
    if (p.abscissaMm <= last.abscissaMm - NarrowingWindowMm + 1e-9)
      above = &p;
  return above && above->diameterMm - last.diameterMm > NarrowingPerMm * (last.abscissaMm - above->abscissaMm);
}

DistalSection NarrowestLumenSectionBelow(const LabelImage& lumen,
                                         const Point3& from,
                                         double fromMm,
                                         const Eigen::Vector3d& down,
                                         double reachMm,
                                         const Point3* divider,
                                         int diameterCount)
{
  DistalSection out;
  const Eigen::Vector3d axis = down.normalized();
  if (!axis.allFinite())
    return out;
  const SmoothMask mask(lumen);
  // Every 1 mm, and B's own level (the last ring may lie less than a step above it).
  std::vector<double> depths;
  for (double depth = sectionStepMm; depth < reachMm - 0.05; depth += sectionStepMm)
    depths.push_back(depth);
  if (reachMm > 0.05)
    depths.push_back(reachMm);
  for (const double depth : depths)
  {
    const Point3 centre = from + depth * axis;
    // Off the lumen (the crotch), or level with the flow divider: the iliacs' sections from here.
    if (mask(centre) < 0.5 || (divider && (centre - *divider).dot(axis) >= 0.0))
      break;
    RingDiameters section = ReadSection(mask, centre, axis, diameterCount);
    section.abscissaMm = fromMm + depth;
    if (!out.found || section.meanMm < out.section.meanMm)
      out.section = section;
    out.found = true;
  }
  return out;
}

} // namespace sgp
