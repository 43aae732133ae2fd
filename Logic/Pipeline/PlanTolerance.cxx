#include "Pipeline/PlanTolerance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "Common/Errors.h"

namespace sgp
{
namespace
{

constexpr double Infinity = std::numeric_limits<double>::infinity();

} // namespace

DeploymentTolerance AssessPlanTolerance(const RepairPlan& plan,
                                        const PlanParams& params,
                                        const WallDistanceField& measureWall,
                                        FitCheckContext context)
{
  const std::array<GraftAxis, 2>& axes = plan.graftAxes;
  DeviceConfiguration configuration = *plan.Configuration();
  // Where the searches start (DeploymentTolerance.h): each side's distal edge may move down to the
  // internal iliac ostium as the fit check reads it, up until its iliac seal reaches the minimum.
  std::array<double, 2> edgeRoomBelow{ Infinity, Infinity }, edgeRoomAbove{ Infinity, Infinity };
  for (int side = 0; side < 2; ++side)
  {
    const std::string ostium = side == 0 ? "rightInternalIliac" : "leftInternalIliac";
    for (const OstiumCoverage& o : plan.fitCheck.ostia)
      if (o.branch == ostium)
        edgeRoomBelow[std::size_t(side)] = FitCheckParams{}.ostiumOverlapToleranceMm - o.overlapMm;
    const double seal = side == 0 ? plan.fitCheck.rightIliacSealLengthMm : plan.fitCheck.leftIliacSealLengthMm;
    if (std::isfinite(seal))
      edgeRoomAbove[std::size_t(side)] = seal - plan.fitCheck.minimumIliacSealMm;
  }
  // The limb that lands: its own edge's room, unless its overlap ends its range sooner.
  for (ConfiguredComponent& part : configuration.components)
    if (part.role != OrderRole::MainBody &&
        part.distalMm >= configuration.coveredLengthMm[std::size_t(part.side)] - 1e-9)
    {
      if (part.holdsBelowLimit == "covers")
        part.holdsBelowMm = edgeRoomBelow[std::size_t(part.side)];
      if (part.holdsAboveLimit == "seal")
        part.holdsAboveMm = edgeRoomAbove[std::size_t(part.side)];
    }
  // The main body: down, the proximal seal beyond its minimum and uncertainty; up, the deployment
  // margin, offset and the ostium tolerance (then a renal ostium) — or sooner where it carries a
  // side's limbs along once their overlaps reach their window's end (Displaced) and that side's
  // edge runs out of room.
  ConfiguredComponent& body = configuration.components.front();
  body.holdsBelowMm =
    plan.fitCheck.proximalSealLengthMm - plan.fitCheck.minimumProximalSealMm - plan.fitCheck.proximalSealUncertaintyMm;
  body.holdsAboveMm = plan.deploymentMarginMm + params.deploymentOffsetMm + FitCheckParams{}.ostiumOverlapToleranceMm;
  for (int side = 0; side < 2; ++side)
  {
    double slackDown = 0.0, slackUp = 0.0;
    for (const ComponentOverlap& o : configuration.overlaps)
      if (o.side == side)
      {
        slackDown += std::isfinite(o.maxMm) ? std::max(0.0, o.maxMm - o.overlapMm) : Infinity;
        slackUp += std::isfinite(o.minMm) ? std::max(0.0, o.overlapMm - o.minMm) : Infinity;
      }
    body.holdsBelowMm = std::min(body.holdsBelowMm, slackDown + edgeRoomBelow[std::size_t(side)]);
    body.holdsAboveMm = std::min(body.holdsAboveMm, slackUp + edgeRoomAbove[std::size_t(side)]);
  }
  // The planned graft judged on the fit check's own findings (the configuration's are the plan's,
  // not a displacement's): no deployment, only the check.
  context.configurationFindings.clear();
  const FitCheck own = CheckGraftFit(plan.graft, plan.measurements, plan.centerlines, &plan.vesselWall, context);
  const DisplacedCheck planned{ own.Passed(), own.findings.empty() ? std::string() : own.findings.front(), false };
  const auto check = [&](const DeviceConfiguration& moved, double shiftMm) -> DisplacedCheck
  {
    try
    {
      GraftLayout layout =
        LayOutGraft(plan.centerlines, plan.measurements, PlacedAlongShiftedGraft(moved, shiftMm, axes),
                    plan.deploymentTargetAbscissaMm + shiftMm, params.mesh, &moved);
      std::optional<WallDistanceField> ownWall;
      const WallDistanceField& wall = WallDistanceField::SharedOrOwn(
        measureWall, *plan.lumen.mask, SharedWallBandMm, StentReach(layout.mesh, plan.centerlines), ownWall);
      const DeployedGraft graft = DeployGraft(std::move(layout), wall, params.graft);
      const FitCheck fit = CheckGraftFit(graft, plan.measurements, plan.centerlines, &plan.vesselWall, context);
      const bool aortic =
        std::any_of(fit.ostia.begin(), fit.ostia.end(),
                    [](const OstiumCoverage& o) { return o.parent == "aorta" && (o.covered || o.mayBeCovered); });
      // Why it fails: the aortic ostium where one is covered (what ends the main body's rise).
      const auto why =
        std::find_if(fit.findings.begin(), fit.findings.end(),
                     [&](const std::string& f) { return !aortic || f.find(" ostium ") != std::string::npos; });
      return { fit.Passed(), why == fit.findings.end() ? std::string() : *why, aortic };
    }
    catch (const InputError& e) // a distal edge beyond the iliac in view, a vessel too short
    {
      return { false, e.what(), false };
    }
  };
  return AssessDeploymentTolerance(configuration, params.selection.deploymentToleranceMm, check, &planned);
}

} // namespace sgp
