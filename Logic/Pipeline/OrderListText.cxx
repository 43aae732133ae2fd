#include "Pipeline/OrderListText.h"

#include <cmath>

#include "Common/Format.h"
#include "Common/Text.h"

namespace sgp
{
namespace
{

const char* SideName(int side)
{
  return side == 0 ? "right" : "left";
}

std::string Mm(double value)
{
  return std::isfinite(value) ? FormatNumber(value) + " mm" : std::string("not measured");
}

} // namespace

std::string AnatomyLengthsText(const RepairPlan& plan)
{
  const Measurements& m = plan.measurements;
  const double toBifurcation = m.Value("proximalSiteToBifurcationLength");
  const double right = m.Value("rightIliacLength"), left = m.Value("leftIliacLength");
  const auto total = [&](double iliac)
  { return std::isfinite(toBifurcation + iliac) ? " (" + Mm(toBifurcation + iliac) + " from the lowest renal)" : ""; };
  return "lowest renal → aortic bifurcation " + Mm(toBifurcation) + " → right internal iliac origin " + Mm(right) +
         total(right) + ", left " + Mm(left) + total(left);
}

std::vector<std::string> OrderLines(const RepairPlan& plan)
{
  std::vector<std::string> lines;
  const DeviceConfiguration* c = plan.Configuration();
  if (!c)
    return lines;
  const FamilyEvaluation& family = plan.selection.families[std::size_t(plan.orderedFamily)];
  const std::string estimated = family.EstimatedOnLumen()
                                  ? " — estimated (lumen): sized on the lumen at " +
                                      JoinWithCommas(family.estimatedFromLumen) + " where the outer wall was not traced"
                                  : "";
  if (!c->configured)
  {
    lines.push_back(c->family + ": the components' lengths are not configured — " + c->unknownReason + estimated + ".");
    return lines;
  }
  lines.push_back((c->given ? "Given by the surgeon: " : "") + c->family + ", main body from the " +
                  c->ipsilateralReason + estimated);
  const double offset = plan.deploymentTargetAbscissaMm - plan.measurements.site.abscissaMm;
  for (const ConfiguredComponent& part : c->components)
  {
    std::string where;
    if (part.role == OrderRole::MainBody)
      where =
        "proximal edge " +
        (std::abs(offset) < 0.05
           ? std::string("at the lower edge of the lowest renal ostium")
           : Mm(std::abs(offset)) + (offset > 0 ? " below" : " above") + " the lower edge of the lowest renal ostium") +
        (plan.deploymentMarginMm > 0.0 ? " (" + Mm(plan.deploymentMarginMm) + " of it a margin: that edge may lie " +
                                           Mm(plan.measurements.site.edgeUncertaintyMm) + " lower, " +
                                           plan.measurements.site.edgeUncertaintyWhy + ")"
                                       : std::string()) +
        ", flow divider " + Mm(c->flowDividerMm) + " and contralateral gate end " + Mm(c->gateEndMm) + " below it (" +
        Mm(c->gateClearanceMm) + " above the aortic bifurcation), ipsilateral leg to " + Mm(part.distalMm);
    else
      where = "from " + Mm(part.proximalMm) + " to " + Mm(part.distalMm) + " below the proximal edge" +
              (std::isfinite(part.holdsAboveMm + part.holdsBelowMm) ? "; " + part.HoldsText() : std::string());
    lines.push_back("  " + part.RoleText() + ": " + part.OrderText() + ", " + where);
  }
  if (plan.recommendation)
  {
    const int f = FamilyForMainBody(*plan.recommendation);
    const std::string recommended =
      f >= 0 ? plan.recommendation->families[std::size_t(f)].configuration.OrderList() : std::string("none");
    if (plan.configurationDifferences.empty())
      lines.push_back("  the same as the plan's recommendation (" + recommended + ")");
    else
      lines.push_back("  differs from the plan's recommendation (" + recommended + "):");
    for (const ConfigurationDifference& d : plan.configurationDifferences)
      lines.push_back("    " + d.Text());
  }
  for (const ComponentOverlap& o : c->overlaps)
    lines.push_back("  overlap, " + o.junction + ": " + Mm(o.overlapMm) + " (needs " + OverlapNeedsText(o) + ")");
  for (int side = 0; side < 2; ++side)
  {
    const double margin = c->marginToInternalIliacMm[side];
    lines.push_back("  " + std::string(SideName(side)) + " side: covered " + Mm(c->coveredLengthMm[side]) +
                    " from the proximal edge; planned seal in the common iliac " + Mm(c->sealLengthMm[side]) +
                    ", distal edge " +
                    (margin >= 0.0 ? Mm(margin) + " above the internal iliac ostium"
                                   : Mm(-margin) + " past the internal iliac ostium (covers it)") +
                    (std::isfinite(plan.distalEdgeShiftMm[side])
                       ? "; simulated, the graft's own axis runs " + Mm(plan.graftAxisLengthMm[side]) + ": " +
                           SimulatedLengthText(plan, side)
                       : std::string()));
  }
  const DeploymentTolerance& t = plan.deploymentTolerance;
  if (t.assessed)
  {
    lines.push_back("  deployment tolerance (each component moved up to " + Mm(t.searchMm) +
                    " up and down its vessel, the others where planned; it should hold " + Mm(t.toleranceMm) +
                    " either way):");
    for (const ComponentHold& h : t.components)
      lines.push_back("    " + h.name + ": " + h.Text(t.searchMm));
    for (const std::string& f : t.findings)
      lines.push_back("  FINDING (deployment tolerance): " + f + ".");
    for (const std::string& note : t.notes)
      lines.push_back("  Note: " + note);
  }
  else if (!t.notAssessedReason.empty())
    lines.push_back("  deployment tolerance: not assessed — " + t.notAssessedReason + ".");
  for (const ConfigurationFinding& f : c->findings)
    lines.push_back("  FINDING: " + f.text + ". Option: " + f.option + ".");
  for (const std::string& note : c->notes)
    lines.push_back("  Note: " + note);
  for (const SizeAlternative& a : c->alternatives)
    lines.push_back("  Alternative: " + a.text + ".");
  return lines;
}

std::string SimulatedLengthText(const RepairPlan& plan, int side)
{
  const std::size_t s = std::size_t(side);
  const double shift = plan.distalEdgeShiftMm[s];
  if (!std::isfinite(shift))
    return "";
  const std::string fabric = "the fabric ordered, " + Mm(plan.graftFabricLengthMm[s]) + ", over " +
                             Mm(plan.graftPathLengthMm[s]) + " of centerline";
  if (std::abs(shift) < 0.05) // equal at 0.1 mm
    return fabric + ": its distal edge where the covered length puts it";
  return fabric + ": its distal edge " + Mm(std::abs(shift)) + (shift > 0.0 ? " further down" : " higher") +
         " than the covered length read along the centerline";
}

std::string OverlapNeedsText(const ComponentOverlap& overlap)
{
  if (!std::isfinite(overlap.maxMm))
    return "≥ " + Mm(overlap.minMm);
  if (overlap.maxMm - overlap.minMm < 0.05) // equal at 0.1 mm
    return Mm(overlap.minMm);
  return FormatNumber(overlap.minMm) + "–" + Mm(overlap.maxMm);
}

} // namespace sgp
