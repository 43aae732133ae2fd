#include "Device/ConfigurationLengths.h"

#include <cmath>
#include <limits>
#include <vector>

#include "Centerlines/ProximalSite.h"
#include "Common/Median.h"

namespace sgp
{

double InternalIliacRadiusMm(const CenterlineTree& tree, int side)
{
  const Centerline* branch = tree.FindVessel(side == 0 ? "rightInternalIliac" : "leftInternalIliac");
  if (!branch || branch->Size() < 2)
    return std::numeric_limits<double>::quiet_NaN();
  // Beyond the merged cross-section of the origin, before the branch divides.
  constexpr double fromMm = 5.0, toMm = 20.0;
  std::vector<double> radii;
  for (Eigen::Index i = 0; i < branch->Size(); ++i)
    if (branch->abscissaMm[i] >= fromMm && branch->abscissaMm[i] <= toMm)
      radii.push_back(branch->radiusMm[i]);
  if (radii.empty())
    return RadiusAt(*branch, 0.5 * branch->LengthMm());
  return Median(radii);
}

ConfigurationAnatomy ConfigurationLengths(const CenterlineTree& tree, const Measurements& m, double targetAbscissaMm)
{
  ConfigurationAnatomy a;
  a.targetToBifurcationMm = m.bifurcationAbscissaMm - targetAbscissaMm;
  const Centerline* iliac[2] = { &tree.rightIliac, &tree.leftIliac };
  const char* lengths[2] = { "rightIliacLength", "leftIliacLength" };
  for (int side = 0; side < 2; ++side)
  {
    a.targetToInternalIliacMm[side] = a.targetToBifurcationMm + m.Value(lengths[side]);
    a.internalIliacRadiusMm[side] = InternalIliacRadiusMm(tree, side);
    if (m.flowDivider.found) // its lowest position within its uncertainty: the seal is not overstated
      a.targetToFlowDividerMm[side] = a.targetToBifurcationMm + m.iliacStartBeyondBifurcationMm[side] +
                                      m.flowDivider.iliacAbscissaMm[side] + m.flowDivider.uncertaintyMm;
    a.targetToIliacEndMm[side] =
      a.targetToBifurcationMm + m.iliacStartBeyondBifurcationMm[side] + iliac[side]->LengthMm();
    const Centerline* branch = tree.FindVessel(side == 0 ? "rightInternalIliac" : "leftInternalIliac");
    if (branch && branch->Size() >= 2 && iliac[side]->Size() >= 2)
    {
      const BranchOstium ostium = FindBranchOstium(*iliac[side], *branch);
      if (ostium.found)
        a.targetToInternalIliacOstiumMm[side] =
          a.targetToBifurcationMm + m.iliacStartBeyondBifurcationMm[side] + ostium.upperAbscissaMm;
    }
  }
  for (const RingDiameters& ring : m.profiles[0].rings)
  {
    a.aortaProfileMm.push_back(ring.abscissaMm - targetAbscissaMm);
    a.aortaMinDiameterMm.push_back(ring.minMm);
  }
  const double outer = m.Value("distalNeckMinDiameter");
  a.distalAorticDiameterMm = std::isfinite(outer) ? outer : m.Value("distalNeckMinLumenDiameter");
  a.distalAorticWall = std::isfinite(outer) ? "outer wall" : "lumen";
  return a;
}

} // namespace sgp
