// Step 4 of LabelAortoIliacTree: the aorta's side branches named (AortoIliacSteps.h).
#include "Centerlines/AortoIliacSteps.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <set>

#include "Centerlines/LimbDivergence.h"
#include "Centerlines/ProximalSite.h"
#include "Centerlines/SmoothCenterline.h"
#include "Centerlines/VesselOrigins.h"
#include "Common/Errors.h"
#include "Common/Format.h"
#include "Common/Median.h"

namespace sgp::aorto_iliac
{

namespace
{

/// The side of the aorta a branch leaves from, by its offset's angle in the horizontal plane from
/// anterior (−y): anterior within anteriorSectorDeg, right or left lateral up to lateralSectorDeg
/// (renals leave anterolaterally or posterolaterally: 50° in front of lateral to 60° behind it),
/// else posterior or none (an offset without a horizontal part: unnamed).
enum class Clock
{
  Anterior,
  Right,
  Left,
  Other
};
constexpr double anteriorSectorDeg = 40.0, lateralSectorDeg = 150.0;

/// The offset's angle from the front (−y) toward either side in the horizontal plane, degrees in
/// [0, 180]; NaN when it leaves mostly up or down along the aorta (horizontal part under 0.5).
double DegreesFromFront(const Eigen::Vector3d& offset)
{
  if (std::hypot(offset.x(), offset.y()) < 0.5)
    return std::numeric_limits<double>::quiet_NaN();
  return std::atan2(std::abs(offset.x()), -offset.y()) * 57.29577951308232;
}

Clock ClockOf(const Eigen::Vector3d& offset)
{
  const double fromAnterior = DegreesFromFront(offset);
  if (std::isnan(fromAnterior)) // no side
    return Clock::Other;
  if (fromAnterior <= anteriorSectorDeg)
    return Clock::Anterior;
  if (fromAnterior < lateralSectorDeg)
    return offset.x() < 0 ? Clock::Right : Clock::Left; // patient right is −x in LPS
  return Clock::Other;
}

/// Renal arteries run from horizontal (and up to 0.6 of a unit upward) to 65° downward.
constexpr double renalSteepestDescentZ = -0.91;
/// The narrowest renal (median inscribed radius, mm): main renals are 4–7 mm across, accessory
/// ones 2–4 mm; the lumbar arteries, which also leave laterally and posterolaterally, are
/// 1.5–2.5 mm across (inscribed radius ≤ 1 mm on the lumen) and are never named renals.
constexpr double minimumRenalRadiusMm = 1.5, minimumAccessoryRenalRadiusMm = 1.0;

/// The visceral trunks (coeliac, SMA) are the anterior branches at least this share of the widest
/// anterior branch's radius; the thinner ones (the inferior mesenteric's 3–4 mm against the SMA's
/// 6–8 mm) are not.
constexpr double visceralShareOfWidest = 0.7;

} // namespace

std::vector<std::string> NameAorticBranches(const SkeletonGraph& graph,
                                            const std::vector<SideBranch>& sides,
                                            const Point3& bifurcation,
                                            double visceralRadiusMm,
                                            std::vector<Landmark>& landmarks)
{
  std::vector<std::string> names(sides.size());
  const auto height = [&](const SideBranch& s) { return graph.nodes[s.node].position.z() - bifurcation.z(); };
  const auto name = [&](int i, const std::string& vessel)
  {
    names[i] = vessel;
    landmarks.push_back({ vessel + "Ostium", graph.nodes[sides[i].node].position });
  };
  // Anterior: the visceral trunks (the SMA, the coeliac above it) by calibre; the thinner ones
  // are the inferior mesenteric's candidates.
  std::vector<int> anterior;
  double widestAnterior = 0.0;
  for (int i = 0; i < int(sides.size()); ++i)
    if (ClockOf(sides[i].offset) == Clock::Anterior && height(sides[i]) > 20.0 && height(sides[i]) < 250.0)
    {
      anterior.push_back(i); // from the top down
      widestAnterior = std::max(widestAnterior, sides[i].radius);
    }
  const double trunkRadius = std::max(visceralRadiusMm, visceralShareOfWidest * widestAnterior);
  std::vector<int> trunks;
  for (const int i : anterior)
    if (sides[i].radius >= trunkRadius && height(sides[i]) > 30.0)
      trunks.push_back(i);
  double renalCeiling = MaximumRenalHeightMm;
  int sma = -1;
  if (!trunks.empty())
  {
    sma = trunks.back();
    name(sma, "superiorMesenteric");
    renalCeiling = std::min(renalCeiling, height(sides[sma]) + 15.0); // renals leave below it
  }
  if (trunks.size() >= 2)
    name(trunks[trunks.size() - 2], "coeliac");
  // Lateral, between 20 mm above the bifurcation and the superior mesenteric, running out level
  // to 65° down: the widest on each side is the renal artery, the others accessory renals.
  double lowestRenal = std::numeric_limits<double>::infinity();
  for (const Clock side : { Clock::Right, Clock::Left })
  {
    const std::string sideName = side == Clock::Right ? "right" : "left";
    int widest = -1;
    for (int i = 0; i < int(sides.size()); ++i)
    {
      const double z = sides[i].direction.z();
      if (names[i].empty() && ClockOf(sides[i].offset) == side && z >= renalSteepestDescentZ && z <= 0.6 &&
          height(sides[i]) > 20.0 && height(sides[i]) < renalCeiling &&
          sides[i].radius >= minimumAccessoryRenalRadiusMm)
      {
        names[i] = sideName + "AccessoryRenal";
        if (widest < 0 || sides[i].radius > sides[widest].radius)
          widest = i;
      }
    }
    if (widest >= 0 && sides[widest].radius >= minimumRenalRadiusMm)
    {
      name(widest, sideName + "Renal");
      lowestRenal = std::min(lowestRenal, height(sides[widest]));
    }
  }
  // The inferior mesenteric: the widest thinner anterior branch below the SMA and the renals (it
  // leaves the aorta's front 30–50 mm above the bifurcation, from the sac in an AAA).
  const double imaCeiling = std::min(sma >= 0 ? height(sides[sma]) - 20.0 : renalCeiling, lowestRenal - 20.0);
  int ima = -1;
  for (const int i : anterior)
    if (names[i].empty() && sides[i].radius < trunkRadius && height(sides[i]) < imaCeiling &&
        (ima < 0 || sides[i].radius > sides[ima].radius))
      ima = i;
  if (ima >= 0)
    name(ima, "inferiorMesenteric");
  return names;
}

std::string DescribeBranch(const SideBranch& b, double heightMm)
{
  constexpr double degrees = 57.29577951308232;
  std::string side = "no side (it leaves along the aorta)";
  const double fromFront = DegreesFromFront(b.offset);
  if (!std::isnan(fromFront))
  {
    side = "its " + std::string(fromFront < 1.0 ? "front" : (b.offset.x() < 0 ? "right" : "left")) + " side (" +
           FormatNumber(fromFront, 0) + "° from the front)";
  }
  const double slope = std::asin(std::clamp(b.direction.z(), -1.0, 1.0)) * degrees;
  return "leaves the aorta from " + side + ", runs " + FormatNumber(std::abs(slope), 0) + "° " +
         (slope <= 0 ? "below" : "above") + " horizontal, " + FormatNumber(2 * b.radius, 1) + " mm across, " +
         FormatNumber(heightMm, 0) + " mm above the bifurcation";
}

std::string NamingRule(const std::string& name)
{
  const auto ends = [&](const std::string& tail)
  { return name.size() >= tail.size() && name.compare(name.size() - tail.size(), tail.size(), tail) == 0; };
  if (name == "superiorMesenteric")
    return "the lowest anterior visceral trunk (at least " + FormatNumber(visceralShareOfWidest, 1) +
           " x the widest anterior branch's calibre)";
  if (name == "coeliac")
    return "the anterior visceral trunk above the superior mesenteric";
  if (name == "inferiorMesenteric")
    return "the widest thinner anterior branch more than 20 mm below the superior mesenteric and the renals";
  if (ends("AccessoryRenal"))
    return "a narrower lateral branch of the renal range on that side";
  if (ends("Renal"))
    return "the widest lateral branch on that side running level to 65° down, between 20 mm above the "
           "bifurcation and 15 mm above the superior mesenteric";
  return "no rule names it (not anterior or lateral, outside the heights or calibres the rules read, or a second "
         "candidate), so it is not forced";
}

} // namespace sgp::aorto_iliac
