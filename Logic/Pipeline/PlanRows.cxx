#include "Pipeline/PlanRows.h"

#include <cmath>
#include <limits>

#include "Common/Format.h"
#include "Common/Text.h"

namespace sgp
{

void AddDeviceRows(const DeviceCatalog& catalog, RepairPlan& plan)
{
  const FamilyEvaluation& family = plan.selection.families[plan.simulatedFamily];
  const bool outer =
    catalog.families[std::size_t(family.catalogIndex)].diameterReference == DiameterReference::OuterWall;
  const std::string wall = outer ? "outer" : "lumen";
  const std::string over = outer ? " % over the outer-wall " : " % over the lumen's ";
  const std::string name = family.family + (!plan.fitCheck.Complete() ? " (main body only: partial plan)"
                                            : plan.selection.recommended == plan.simulatedFamily ? ""
                                                                                                 : " (outside IFU)");
  const StentMesh& mesh = plan.graft.layout.mesh;
  const SizingAnatomy sizing =
    SizingFromMeasurements(plan.measurements).On(catalog.families[std::size_t(family.catalogIndex)].diameterReference);
  const double vessels[3] = { sizing.proximalNeckDiameterMm, sizing.rightIliacDiameterMm, sizing.leftIliacDiameterMm };
  const char* names[3] = { "mainBodyDiameter", "rightLimbDiameter", "leftLimbDiameter" };
  const char* parts[3] = { " main body, ", " right limb, ", " left limb, " };
  const char* levels[3] = { "(a)", "(e)", "(f)" };
  const char* vesselNames[3] = { "aorta", "rightIliac", "leftIliac" };
  for (int k = 0; k < 3; ++k)
  {
    const double d = plan.graftDiametersMm[std::size_t(k)];
    const double at = k == 0 ? plan.graft.layout.targetAbscissaMm : mesh.ringAbscissaMm[std::size_t(k)].back();
    plan.rows.push_back({ names[k], d, "mm",
                          name + parts[k] + FormatNumber(OversizingPercent(d, vessels[k])) + over + levels[k],
                          vesselNames[k], at });
    Measurement& row = plan.rows.back();
    row.wall = family.EstimatedOnLumen() ? "lumen" : wall;
    row.estimated = family.EstimatedOnLumen();
    if (family.EstimatedOnLumen())
      row.definition += "; estimated (lumen): sized on the lumen at " + JoinWithCommas(family.estimatedFromLumen) +
                        " where the outer wall was not traced";
  }
  for (const Measurement& m : FitCheckRows(plan.fitCheck, plan.graft))
    plan.rows.push_back(m);
}

void AddOrderRows(RepairPlan& plan)
{
  const DeviceConfiguration* c = plan.Configuration();
  const double target = plan.deploymentTargetAbscissaMm;
  const bool configured = c && c->configured;
  const ConfiguredComponent* body = configured ? c->Find(OrderRole::MainBody) : nullptr;
  const std::string estimated =
    plan.orderedFamily >= 0 && plan.selection.families[std::size_t(plan.orderedFamily)].EstimatedOnLumen()
      ? "; estimated (lumen)"
      : "";
  const std::string why = c ? c->unknownReason : "no main body was sized";
  plan.rows.push_back({ "mainBodyLength", body ? body->item.lengthMm : std::numeric_limits<double>::quiet_NaN(), "mm",
                        body
                          ? c->family + " " + body->item.name + " " + body->item.CodeText() +
                              ": covered length from the proximal fabric edge to the ipsilateral leg's end" + estimated
                          : "main body length: not configured (" + why + ")" + estimated,
                        "aorta", target });
  const char* names[2] = { "rightLimbLength", "leftLimbLength" };
  const char* vessels[2] = { "rightIliac", "leftIliac" };
  for (int side = 0; side < 2; ++side)
  {
    const ConfiguredComponent* limb = nullptr;
    if (configured)
      limb = c->Find(side == c->ipsilateralSide ? OrderRole::IpsilateralLimb : OrderRole::ContralateralLimb, side);
    const std::string sideName = side == 0 ? "right" : "left";
    std::string definition =
      !configured ? sideName + " limb length: not configured (" + why + ")" + estimated
      : limb      ? c->family + " " + sideName + (side == c->ipsilateralSide ? " ipsilateral" : " contralateral") +
                 " limb " + limb->item.CodeText() + ", its covered length; the " + sideName + " side covers " +
                 FormatNumber(c->coveredLengthMm[side]) + " mm from the proximal fabric edge" + estimated
             : "no " + sideName + " limb: the main body's ipsilateral leg lands there (" +
                 FormatNumber(c->coveredLengthMm[side]) + " mm from the proximal edge)";
    const double value = !configured ? std::numeric_limits<double>::quiet_NaN() : limb ? limb->item.lengthMm : 0.0;
    plan.rows.push_back({ names[side], value, "mm", definition, vessels[side],
                          configured ? c->coveredLengthMm[side] - plan.measurements.bifurcationAbscissaMm + target -
                                         plan.measurements.iliacStartBeyondBifurcationMm[side]
                                     : std::numeric_limits<double>::quiet_NaN() });
  }
}

double VoxelAlongAortaMm(const RepairPlan& plan)
{
  const Centerline& aorta = plan.centerlines.aorta;
  if (!plan.lumen.mask || aorta.Size() < 2)
    return std::numeric_limits<double>::quiet_NaN();
  const Eigen::Vector3d t = TangentAt(aorta, plan.measurements.site.Known() ? plan.measurements.site.abscissaMm : 0.0);
  const auto& direction = plan.lumen.mask->GetDirection();
  const auto& spacing = plan.lumen.mask->GetSpacing();
  double extent = 0.0;
  for (unsigned axis = 0; axis < 3; ++axis)
  {
    double along = 0.0;
    for (unsigned row = 0; row < 3; ++row)
      along += direction[row][axis] * t[Eigen::Index(row)];
    extent += along * along * spacing[axis] * spacing[axis];
  }
  return std::sqrt(extent);
}

} // namespace sgp
