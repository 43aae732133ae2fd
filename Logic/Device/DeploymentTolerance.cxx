#include "Device/DeploymentTolerance.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <future>
#include <system_error>

#include "Common/Errors.h"
#include "Common/Format.h"

namespace sgp
{
namespace
{

constexpr double Infinity = std::numeric_limits<double>::infinity();
constexpr double Eps = 1e-9;
/// The search reaches at least this far each way, mm (a tolerance of 0 still shows the ranges).
constexpr double MinimumSearchMm = 5.0;

std::string Mm(double value)
{
  return FormatNumber(value) + " mm";
}

/// How far component `k` may move up before it goes deeper into what it is inserted into than the
/// overlap window's upper end (mm; ∞: no such limit, and always for the main body).
double InsertionCap(const DeviceConfiguration& c, std::size_t k)
{
  double cap = Infinity;
  for (const ComponentOverlap& o : c.overlaps)
    if (std::isfinite(o.maxMm) && std::size_t(o.inner) == k)
      cap = std::min(cap, std::max(0.0, o.maxMm - o.overlapMm));
  return cap;
}

struct DirectionResult
{
  int simulations = 0;
  double holdsMm = 0.0;
  std::string fails;
  bool stops = false;
  bool aorticOstium = false;
};

} // namespace

Displacement Displaced(const DeviceConfiguration& c, std::size_t index, double mm)
{
  if (!c.configured || index >= c.components.size())
    throw InputError("Displaced: component " + std::to_string(index) + " of a configuration with " +
                     std::to_string(c.components.size()) + " components" +
                     (c.configured ? std::string() : " (not configured)") + "; expected one of them.");
  Displacement out{ c, 0.0 };
  DeviceConfiguration& d = out.configuration;
  if (d.components[index].role == OrderRole::MainBody)
  {
    out.targetShiftMm = mm;
    for (std::size_t k = 0; k < d.components.size(); ++k)
      if (d.components[k].role != OrderRole::MainBody)
      {
        d.components[k].proximalMm -= mm;
        d.components[k].distalMm -= mm;
      }
    for (std::size_t s = 0; s < 2; ++s)
    {
      d.landingLowMm[s] -= mm;
      d.landingHighMm[s] -= mm;
      d.sealFromMm[s] -= mm;
    }
  }
  else
  {
    d.components[index].proximalMm += mm;
    d.components[index].distalMm += mm;
  }
  // In chain order (inward to outward): what is inserted into a moved component stays where it was
  // planned as far as its overlap window lets it — moved no more than keeps its overlap within
  // [min, max] (a limb is deployed to its gate's markers: pushed down by a gate that landed low,
  // drawn up by one that landed high).
  const ConfiguredComponent& body = d.components.front();
  for (ComponentOverlap& o : d.overlaps)
  {
    const double outerEnd = o.outer == 0 ? (o.side == d.ipsilateralSide ? body.distalMm : d.gateEndMm)
                                         : d.components[std::size_t(o.outer)].distalMm;
    ConfiguredComponent& inner = d.components[std::size_t(o.inner)];
    o.overlapMm = outerEnd - inner.proximalMm;
    if (std::size_t(o.inner) == index)
      continue; // the component moved: its own overlap is what the move does
    double shift = 0.0;
    if (std::isfinite(o.maxMm) && o.overlapMm > o.maxMm)
      shift = o.overlapMm - o.maxMm;
    else if (std::isfinite(o.minMm) && o.overlapMm < o.minMm)
      shift = o.overlapMm - o.minMm;
    inner.proximalMm += shift;
    inner.distalMm += shift;
    o.overlapMm -= shift;
  }
  for (int side = 0; side < 2; ++side)
  {
    const std::size_t s = std::size_t(side);
    // The side's last component in chain order (inward to outward) ends it.
    double covered = side == d.ipsilateralSide ? body.distalMm : d.gateEndMm;
    for (const ConfiguredComponent& part : d.components)
      if (part.role != OrderRole::MainBody && part.side == side)
        covered = part.distalMm;
    d.coveredLengthMm[s] = covered;
    d.sealLengthMm[s] = covered - d.sealFromMm[s];
    d.marginToInternalIliacMm[s] = d.landingHighMm[s] - covered;
  }
  return out;
}

std::string ComponentHold::Text(double searchMm) const
{
  const auto range = [&](double mm, const std::string& fails, bool stops)
  {
    if (stops)
      return Mm(mm) + " (as far as it goes)";
    return (fails.empty() && mm >= searchMm - Eps ? "at least " : "") + Mm(mm);
  };
  std::string why;
  if (!aboveFails.empty())
    why += "higher: " + aboveFails;
  if (!belowFails.empty())
    why += (why.empty() ? "" : "; ") + std::string("lower: ") + belowFails;
  return "holds from " + range(aboveMm, aboveFails, aboveStops) + " above to " +
         range(belowMm, belowFails, belowStops) + " below its planned position" +
         (why.empty() ? std::string() : " (" + why + ")");
}

DeploymentTolerance AssessDeploymentTolerance(const DeviceConfiguration& configuration,
                                              double toleranceMm,
                                              const CheckDisplacement& check,
                                              const DisplacedCheck* planned,
                                              double resolutionMm)
{
  if (!(toleranceMm >= 0.0))
    throw InputError("deploymentToleranceMm is " + FormatNumber(toleranceMm) + "; expected ≥ 0 mm.");
  if (!(resolutionMm > 0.0))
    throw InputError("the tolerance search's resolution is " + FormatNumber(resolutionMm) + " mm; expected > 0 mm.");
  DeploymentTolerance out;
  out.toleranceMm = toleranceMm;
  out.resolutionMm = resolutionMm;
  out.searchMm = std::max(MinimumSearchMm, 2.0 * toleranceMm);
  if (!configuration.configured || configuration.components.empty())
  {
    out.notAssessedReason = "the configuration is not known";
    return out;
  }
  const DisplacedCheck atPlan = planned ? *planned : check(configuration, 0.0);
  out.simulations += planned ? 0 : 1;
  if (!atPlan.passed)
  {
    out.notAssessedReason = "the graft does not pass at its planned position (" + atPlan.why + ")";
    return out;
  }
  out.assessed = true;
  const auto search = [&](std::size_t k, int direction, double predictedMm) -> DirectionResult
  {
    DirectionResult r;
    const double cap = direction < 0 ? InsertionCap(configuration, k) : Infinity;
    const double end = std::min(out.searchMm, cap);
    if (end < resolutionMm) // stopped within a step of its plan
    {
      r.stops = true;
      r.holdsMm = std::max(0.0, end);
      return r;
    }
    double lo = 0.0, hi = Infinity;
    double x =
      std::clamp(std::isfinite(predictedMm) ? predictedMm : std::max(toleranceMm, resolutionMm), resolutionMm, end);
    for (int step = 1;; ++step)
    {
      const DisplacedCheck at = [&]
      {
        const Displacement moved = Displaced(configuration, k, direction * x);
        return check(moved.configuration, moved.targetShiftMm);
      }();
      ++r.simulations;
      if (at.passed)
        lo = x;
      else
      {
        hi = x;
        r.fails = at.why;
        r.aorticOstium = at.aorticOstium;
      }
      if (lo >= end - Eps || (std::isfinite(hi) && hi - lo <= resolutionMm + Eps))
        break;
      if (!std::isfinite(hi))
        x = step == 1 ? std::min(end, lo + resolutionMm) : end; // one step beyond, then the end
      else if (step == 1)
        x = hi - resolutionMm; // just inside where it failed
      else
        x = 0.5 * (lo + hi);
    }
    r.holdsMm = lo;
    if (!std::isfinite(hi))
    {
      r.fails.clear();
      r.stops = cap <= end + Eps;
      r.aorticOstium = false;
    }
    return r;
  };
  // Every component's two directions are independent searches, taken in turn by two threads (their
  // costs differ too much for a fixed split).
  const std::size_t n = configuration.components.size();
  std::vector<DirectionResult> results(2 * n);
  std::atomic<std::size_t> next{ 0 };
  const auto worker = [&]
  {
    for (std::size_t task; (task = next++) < 2 * n;)
    {
      const ConfiguredComponent& part = configuration.components[task / 2];
      results[task] = task % 2 == 0 ? search(task / 2, -1, part.holdsAboveMm) : search(task / 2, +1, part.holdsBelowMm);
    }
  };
  std::future<void> second;
  try
  {
    second = std::async(std::launch::async, worker);
  }
  catch (const std::system_error&)
  {
    // no thread to spare: this one takes every task
  }
  worker(); // should it throw, `second` is waited for as it goes out of scope
  if (second.valid())
    second.get();
  for (std::size_t k = 0; k < n; ++k)
  {
    const ConfiguredComponent& part = configuration.components[k];
    ComponentHold hold;
    hold.component = k;
    hold.name = part.RoleText();
    const DirectionResult& up = results[2 * k];
    const DirectionResult& down = results[2 * k + 1];
    out.simulations += up.simulations + down.simulations;
    hold.aboveMm = up.holdsMm;
    hold.aboveFails = up.fails;
    hold.aboveStops = up.stops;
    hold.aboveAtAorticOstium = part.role == OrderRole::MainBody && up.aorticOstium;
    hold.belowMm = down.holdsMm;
    hold.belowFails = down.fails;
    hold.belowStops = down.stops;
    const bool narrowBelow = !down.stops && hold.belowMm < toleranceMm - Eps;
    const bool narrowAbove = !up.stops && hold.aboveMm < toleranceMm - Eps;
    std::string narrow;
    if (narrowAbove && !hold.aboveAtAorticOstium)
      narrow = Mm(hold.aboveMm) + " above (higher: " + hold.aboveFails + ")";
    if (narrowBelow)
      narrow += (narrow.empty() ? "" : " and ") + Mm(hold.belowMm) + " below (lower: " + hold.belowFails + ")";
    if (!narrow.empty())
    {
      hold.finding = "the " + hold.name + " holds only " + narrow + " its planned position: less than the " +
                     Mm(toleranceMm) + " deployment tolerance";
      out.findings.push_back(hold.finding);
    }
    if (narrowAbove && hold.aboveAtAorticOstium)
      out.notes.push_back("The main body's proximal edge is placed at the lowest renal ostium on purpose, so it holds "
                          "only " +
                          Mm(hold.aboveMm) + " above its planned position (higher: " + hold.aboveFails + ").");
    out.components.push_back(hold);
  }
  return out;
}

} // namespace sgp
