#include "PrintPlanSummary.h"

#include "Common/Text.h"

#include <cmath>

#include "Common/Format.h"
#include "Pipeline/OrderListText.h"
#include "Pipeline/ValueText.h"

namespace sgp
{

void PrintWarnings(const std::vector<std::string>& warnings, std::ostream& err)
{
  for (const std::string& warning : warnings)
    err << "WARNING: " << warning << std::endl;
}

void PrintUnmeasuredValues(const std::vector<PlanValue>& values, std::ostream& err)
{
  std::string names;
  for (const PlanValue& v : values)
    if (!v.measured)
      names += (names.empty() ? "" : ", ") + v.name;
  if (!names.empty())
    err << "WARNING: Not measured, so written to the return-parameter file as -1 (numbers), none or false: " << names
        << "." << std::endl;
}

void PrintPlanSummary(const RepairPlan& plan, const std::string& acmMode, std::ostream& out)
{
  const LumenSegmentation& lumen = plan.lumen;
  if (plan.seedAutomatic)
    out << "Seed: automatic, RAS " << FormatNumber(-plan.seedLps.x()) << "," << FormatNumber(-plan.seedLps.y()) << ","
        << FormatNumber(plan.seedLps.z()) << " mm: " << plan.seedDescription << std::endl;
  if (plan.lumenGiven)
    out << "Lumen: " << FormatNumber(lumen.volumeMl) << " mL, given: " << lumen.windowSource
        << (plan.ctGiven ? "" : "; no CT, so no outer wall: sized on the lumen (estimated)") << std::endl;
  else
    out << "Lumen: " << FormatNumber(lumen.volumeMl) << " mL; window " << FormatNumber(lumen.lowerHu, 0) << " to "
        << FormatNumber(lumen.upperHu, 0) << " HU (seed median " << FormatNumber(lumen.seedMedianHu, 0) << " HU, sigma "
        << FormatNumber(lumen.seedSigmaHu, 0) << " HU, from " << lumen.windowSource << "); boundary at "
        << FormatNumber(lumen.edgeHu, 0) << " HU" << std::endl;
  if (plan.Reached(PlanStage::Centerlines))
  {
    const CenterlineTree& tree = plan.centerlines;
    out << "Centerlines: aorta " << FormatNumber(tree.aorta.LengthMm()) << " mm, right iliac "
        << FormatNumber(tree.rightIliac.LengthMm()) << " mm, left iliac " << FormatNumber(tree.leftIliac.LengthMm())
        << " mm; side branches:";
    for (const Centerline& c : tree.sideBranches)
      out << " " << c.name;
    out << std::endl;
    if (tree.Partial())
    {
      const auto coverage = [&](int side)
      {
        return std::isnan(tree.iliacCoverageMm[side]) ? std::string("whole")
                                                      : FormatNumber(tree.iliacCoverageMm[side]) + " mm";
      };
      out << "Partial plan: the scan ends below the bifurcation after " << coverage(0) << " of the right iliac and "
          << coverage(1) << " of the left; the values that need more of them are -1." << std::endl;
    }
  }
  if (plan.Reached(PlanStage::StentSurface))
    out << "Stent surface: " << plan.mesh.V.rows() << " vertices, " << acmMode << " mode, "
        << (plan.fit.converged ? "converged" : "not converged") << " after " << plan.fit.iterations << " iterations"
        << std::endl;
  if (plan.Reached(PlanStage::Device))
  {
    out << "Device: " << plan.selection.summary << std::endl;
    for (const std::string& reason : plan.selection.reasons)
      out << "  " << reason << std::endl;
    out << "Lengths along the centerlines: " << AnatomyLengthsText(plan) << std::endl;
    const std::vector<std::string> order = OrderLines(plan);
    if (!order.empty())
      out << "Order list: " << order.front() << std::endl;
    for (std::size_t i = 1; i < order.size(); ++i)
      out << order[i] << std::endl;
    if (plan.HasGraft())
    {
      const FitCheck& check = plan.fitCheck;
      const auto seal = [](double mm)
      { return std::isfinite(mm) ? FormatNumber(mm) + " mm" : std::string("not known"); };
      out << "Simulated graft (" << plan.selection.families[plan.simulatedFamily].family
          << (check.Complete() ? "" : ", its main body only: partial plan") << "): proximal seal "
          << seal(check.proximalSealLengthMm) << ", iliac seal right " << seal(check.rightIliacSealLengthMm)
          << " / left " << seal(check.leftIliacSealLengthMm)
          << ", covered ostia: " << IdentifierWords(check.CoveredOstia()) << "; fit check "
          << (!check.Complete()
                ? (check.findings.empty() ? "of the proximal part passed" : "of the proximal part FAILED")
              : check.Passed() ? "passed"
                               : "FAILED")
          << std::endl;
      for (const std::string& finding : check.findings)
        out << "  " << finding << std::endl;
    }
  }
  if (plan.Reached(PlanStage::Measurements))
  {
    const Measurements& m = plan.measurements;
    const char* siteFrom = m.site.source == ProximalSiteSource::Landmark ? "at the landmark given"
                           : m.site.source == ProximalSiteSource::Renal  ? "below the lowest renal artery"
                                                                         : "at the top of the scan";
    if (m.site.Known())
      out << "Measurements (proximal site " << siteFrom << ", " << FormatNumber(m.site.abscissaMm)
          << " mm along the aorta):" << std::endl;
    else
      out << "Measurements (proximal site not known: no renal artery in view; give --lowestRenalOstium):" << std::endl;
    const auto source = [](bool given, bool found) { return given ? "given" : found ? "found" : "not found"; };
    out << "Landmarks: lowest renal ostium "
        << source(m.site.source == ProximalSiteSource::Landmark, m.site.source == ProximalSiteSource::Renal)
        << ", aortic bifurcation " << source(m.bifurcationGiven, true) << ", right internal iliac origin "
        << source(m.internalIliacOriginGiven[0], m.internalIliacOriginLps[0].allFinite())
        << ", left internal iliac origin "
        << source(m.internalIliacOriginGiven[1], m.internalIliacOriginLps[1].allFinite()) << std::endl;
    for (const Measurement& v : m.values)
      out << "  " << ValueLabel(v.name) << ": " << ClinicalText(v.value, v.unit) << std::endl;
  }
}

} // namespace sgp
