#include "IO/ReportHtml.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <map>
#include <sstream>

#include "Common/Format.h"
#include "Common/Median.h"
#include "Common/Text.h"
#include "IO/EncodePng.h"
#include "IO/HtmlText.h"
#include "IO/ReportFigureSvg.h"
#include "Pipeline/OrderListText.h"
#include "Pipeline/PlanValues.h"
#include "Pipeline/ValueText.h"
#include "Views/SceneMeshes.h"

namespace sgp
{
namespace
{

using html::C;
using html::Escape;
using html::Num;
using html::Rgb;
using html::ValueCell;

const char* const Css = R"(
body{font-family:"DejaVu Sans",Arial,sans-serif;font-size:10pt;color:#111;margin:16px;max-width:190mm}
h1{font-size:16pt;margin:0 0 4px}h2{font-size:12pt;border-bottom:1px solid #888;margin:18px 0 6px}
table{border-collapse:collapse;width:100%;margin:4px 0}td,th{border:1px solid #bbb;padding:2px 4px;vertical-align:top}
th{background:#eee;text-align:left}.num{text-align:right;white-space:nowrap}.def{font-size:8pt;color:#444}
.summary{border:2px solid #333;padding:6px 10px;background:#f6f6f0}.summary li{margin:2px 0}
.pass{color:#060}.fail{color:#b00;font-weight:bold}.indeterminate{color:#a60}
.figures{display:flex;flex-wrap:wrap;gap:8px}.figure{break-inside:avoid;page-break-inside:avoid}
.caption{font-size:8pt;max-width:62mm}.caption.wide{max-width:none}svg text{font-family:"DejaVu Sans",Arial,sans-serif}
.recommended{background:#eef6ee}.meta td{border:none;padding:1px 6px 1px 0}
@page{size:A4;margin:12mm}
@media print{body{margin:0;max-width:none}h2{break-after:avoid;page-break-after:avoid}
.figure,table{break-inside:avoid;page-break-inside:avoid}}
)";

/// Whether each landmark the plan measures from was given or found, in words.
std::string LandmarkSources(const RepairPlan& plan)
{
  if (!plan.Reached(PlanStage::Measurements))
    return "not measured";
  const Measurements& m = plan.measurements;
  const auto source = [](bool given, bool found) {
    return std::string(given ? "<b>given by the user</b>" : found ? "found" : "not found");
  };
  return "lowest renal ostium " +
         source(m.site.source == ProximalSiteSource::Landmark, m.site.source == ProximalSiteSource::Renal) +
         "; aortic bifurcation " + source(m.bifurcationGiven, true) + "; right internal iliac origin " +
         source(m.internalIliacOriginGiven[0], m.internalIliacOriginLps[0].allFinite()) +
         "; left internal iliac origin " +
         source(m.internalIliacOriginGiven[1], m.internalIliacOriginLps[1].allFinite());
}

void Header(const RepairPlan& plan, const ReportRun& run, std::ostream& out)
{
  const LabelImage& grid = *plan.lumen.mask;
  const auto size = grid.GetLargestPossibleRegion().GetSize();
  const auto spacing = grid.GetSpacing();
  const ProximalSite& site = plan.measurements.site;
  out << "<h1>StentGraftPlanner: EVAR planning report</h1>\n<table class=\"meta\">"
      << "<tr><td>Input</td><td>" << Escape(run.inputVolume) << "</td></tr>"
      << "<tr><td>Grid</td><td>" << size[0] << " &#215; " << size[1] << " &#215; " << size[2] << " voxels of "
      << FormatNumber(spacing[0], 3) << " &#215; " << FormatNumber(spacing[1], 3) << " &#215; "
      << FormatNumber(spacing[2], 3) << " mm</td></tr>"
      << "<tr><td>Run</td><td>" << Escape(run.date) << ", StentGraftPlanner " << Escape(run.version) << "</td></tr>"
      << "<tr><td>Seed</td><td>"
      << (!plan.seedAutomatic && !plan.seedGiven
            ? std::string("none (the lumen was given)")
            : "RAS " + FormatNumber(-plan.seedLps.x()) + ", " + FormatNumber(-plan.seedLps.y()) + ", " +
                FormatNumber(plan.seedLps.z()) + " mm, " +
                (plan.seedAutomatic ? "found automatically: " + Escape(plan.seedDescription)
                                    : std::string("given by the user")))
      << "</td></tr>"
      << "<tr><td>Lumen</td><td>"
      << (plan.lumenGiven ? "given: " + Escape(plan.lumen.windowSource) +
                              (plan.ctGiven ? "" : "; no CT, so no outer wall: sized on the lumen (estimated)")
                          : std::string("grown from the seed (region growing)"))
      << "</td></tr>"
      << "<tr><td>Proximal site</td><td>"
      << (site.Known() ? Num(site.abscissaMm) + " mm along the aorta from its top in the scan, LPS " +
                           FormatPoint(site.lps) + " mm; source: " + ToString(site.source) +
                           (site.renal.empty() ? "" : " (lower edge of the " + Escape(site.renal) + " ostium)")
                       : std::string("<b>not known</b>: no renal artery in view and the aorta runs on past the "
                                     "renal level, so the neck values and the deployment target are not measured. "
                                     "Place the lowest-renal point (lowestRenalOstium) and run again."))
      << "</td></tr>"
      << "<tr><td>Landmarks</td><td>" << LandmarkSources(plan) << "</td></tr>"
      << "<tr><td>Catalogue</td><td>" << Escape(run.deviceCatalog)
      << " (public defaults: verify against the current instructions for use)</td></tr></table>\n";
}

std::string FitVerdict(const RepairPlan& plan)
{
  if (!plan.HasGraft())
    return plan.centerlines.Partial() && plan.simulatedFamily < 0
             ? "not available: the plan is partial (the scan cuts the iliacs short), so no limb was sized"
             : "not available: no family has a main body and both limbs within the oversizing ranges";
  const FitCheck& fit = plan.fitCheck;
  if (fit.Passed())
    return "passed";
  std::string text = fit.Complete() ? "failed" : "partial: the limbs were not checked";
  for (const std::string& f : fit.findings)
    text += "; " + f;
  return text;
}

void Summary(const RepairPlan& plan, const std::map<std::string, PlanValue>& values, std::ostream& out)
{
  const DeviceSelection& s = plan.selection;
  out << "<h2>Summary</h2>\n<div class=\"summary\"><ul>";
  // The device once, then its sizes and the IFU verdict the summary gives ("Excluder Conformable —
  // main body 26 mm …; within IFU"), the return value withinIfu riding along in data-value.
  const std::string device = values.at("recommendedDevice").text;
  std::string summary = s.summary;
  for (const std::string& prefix : { device + ": ", device + " (forced): " })
    if (summary.rfind(prefix, 0) == 0)
      summary = (prefix.find("forced") != std::string::npos ? "forced; " : "") + summary.substr(prefix.size());
  out << "<li><b>Recommendation:</b> <span data-name=\"recommendedDevice\">" << Escape(device) << "</span> — "
      << Escape(summary) << "<span data-name=\"withinIfu\" data-value=\"" << values.at("withinIfu").text
      << "\"></span>";
  if (!s.reasons.empty())
  {
    out << "<ul>";
    for (const std::string& r : s.reasons)
      out << "<li>" << Escape(r) << "</li>";
    out << "</ul>";
  }
  out << "</li>";
  out << "<li><b>Hostile neck:</b> "
      << (plan.neck.checks.empty() ? std::string("not assessed (no rules)") : Escape(plan.neck.summary)) << "</li>";
  out << "<li><b>Fit check:</b> " << Escape(FitVerdict(plan)) << "</li>";
  if (plan.centerlines.Partial())
    out << "<li><b>Partial plan:</b> the scan ends "
        << Num(std::isfinite(plan.centerlines.iliacCoverageMm[0]) ? plan.centerlines.iliacCoverageMm[0]
                                                                  : plan.centerlines.iliacCoverageMm[1])
        << " mm below the aortic bifurcation; the values that need more of the iliacs are not measured.</li>";
  out << "<li><b>Warnings (" << plan.warnings.size() << "):</b>";
  if (plan.warnings.empty())
    out << " none";
  else
  {
    out << "<ul>";
    for (const std::string& w : plan.warnings)
      out << "<li>" << Escape(w) << "</li>";
    out << "</ul>";
  }
  out << "</li></ul></div>\n";
}

void MeasurementTable(const RepairPlan& plan, const std::map<std::string, PlanValue>& values, std::ostream& out)
{
  out << "<h2>Measurements</h2>\n<table><tr><th>measurement</th><th>value</th><th>wall</th><th>definition</th></tr>";
  for (const Measurement& m : plan.measurements.values)
  {
    const auto v = values.find(m.name);
    const std::string text =
      v != values.end() ? v->second.text : (std::isfinite(m.value) ? FormatReturnValue(m.value) : "-1");
    const bool measured = v != values.end() ? v->second.measured : std::isfinite(m.value);
    out << "<tr><td>" << Escape(ValueLabel(m.name)) << "</td>" << ValueCell(m.name, m.value, m.unit, text) << "<td>"
        << (m.wall.empty() ? "" : Escape(m.wall)) << (m.estimated ? " (estimated)" : "") << "</td><td class=\"def\">"
        << Escape(m.definition) << (measured ? "" : " <b>Not measured.</b>") << "</td></tr>";
  }
  out << "</table>\n";
}

/// The aorta's side branches with the evidence for each name (LabelAortoIliacTree.h, step 4).
void BranchTable(const RepairPlan& plan, std::ostream& out)
{
  if (!plan.Reached(PlanStage::Centerlines))
    return;
  std::string rows;
  for (const Centerline& c : plan.centerlines.sideBranches)
    if (!c.evidence.empty())
      rows += "<tr><td>" + Escape(c.name) + "</td><td class=\"def\">" + Escape(c.evidence) + "</td></tr>";
  if (rows.empty())
    return;
  out << "<h2>Branches of the aorta</h2>\n<p class=\"def\">Each named by the side it leaves from, its course, "
         "calibre and height; a branch no rule names keeps a number.</p>\n<table><tr><th>branch</th><th>why "
         "this name</th></tr>"
      << rows << "</table>\n";
}

/// The order list (issue 29): the components to order, where each lies, the anatomy's lengths
/// they were chosen from, and what could not be met.
void OrderSection(const RepairPlan& plan, const std::map<std::string, PlanValue>& values, std::ostream& out)
{
  out << "<h2 id=\"order\">Order list</h2>\n";
  const DeviceConfiguration* c = plan.Configuration();
  out << "<p>Lengths along the centerlines: " << Escape(AnatomyLengthsText(plan)) << ".</p>";
  if (!c)
  {
    out << "<p>No main body was sized, so there is nothing to order.</p>\n";
    return;
  }
  const std::vector<std::string> lines = OrderLines(plan);
  out << "<p><b>" << Escape(lines.empty() ? c->family : lines.front()) << "</b></p>";
  out << "<p class=\"def\">One line: <span data-name=\"orderList\">" << Escape(values.at("orderList").text)
      << "</span></p>";
  if (!c->configured)
  {
    out << "<p class=\"indeterminate\">The components' lengths are not configured: " << Escape(c->unknownReason)
        << ".</p>\n";
    return;
  }
  out << "<table><tr><th>component</th><th>catalogue code</th><th>diameter (mm)</th><th>length</th>"
         "<th>lies (mm below the proximal edge)</th></tr>";
  for (const ConfiguredComponent& part : c->components)
  {
    const std::string role =
      part.role == OrderRole::MainBody         ? "main body"
      : part.role == OrderRole::IliacExtension ? std::string(part.side == 0 ? "right" : "left") + " iliac extension"
      : part.role == OrderRole::AorticCuff
        ? "aortic cuff"
        : std::string(part.side == 0 ? "right" : "left") +
            (part.role == OrderRole::IpsilateralLimb ? " ipsilateral limb" : " contralateral limb");
    const std::string name = part.role == OrderRole::MainBody ? "mainBodyLength"
                             : part.role == OrderRole::IliacExtension || part.role == OrderRole::AorticCuff
                               ? ""
                               : (part.side == 0 ? "rightLimbLength" : "leftLimbLength");
    out << "<tr><td><span style=\"color:" << Rgb(ComponentColour(part)) << "\">&#9632;</span> " << Escape(role) << ": "
        << Escape(part.item.name) << "</td><td>" << Escape(part.item.CodeText()) << "</td><td class=\"num\">"
        << Num(part.item.diameterMm)
        << (std::isfinite(part.item.distalDiameterMm) && part.item.distalDiameterMm != part.item.diameterMm
              ? " → " + Num(part.item.distalDiameterMm)
              : std::string())
        << "</td>"
        << (name.empty() ? "<td class=\"num\">" + Escape(ClinicalText(part.item.lengthMm, "mm")) + "</td>"
                         : ValueCell(name, part.item.lengthMm, "mm", values.at(name).text))
        << "<td class=\"num\">" << Num(part.proximalMm) << " – " << Num(part.distalMm) << "</td></tr>";
  }
  out << "</table><table><tr><th>junction</th><th>overlap</th><th>needs</th></tr>";
  for (const ComponentOverlap& o : c->overlaps)
    out << "<tr><td>" << Escape(o.junction) << "</td><td class=\"num\">" << Escape(ClinicalText(o.overlapMm, "mm"))
        << "</td><td class=\"num\">" << Escape(OverlapNeedsText(o)) << "</td></tr>";
  out << "</table><ul>";
  for (std::size_t i = 1; i < lines.size(); ++i)
    if (lines[i].find("side: covered") != std::string::npos || lines[i].find("FINDING") != std::string::npos ||
        lines[i].find("Note:") != std::string::npos || lines[i].find("Alternative:") != std::string::npos)
      out << "<li" << (lines[i].find("FINDING") != std::string::npos ? " class=\"fail\"" : "") << ">"
          << Escape(lines[i].substr(lines[i].find_first_not_of(' '))) << "</li>";
  out << "</ul>\n";
}

std::string StatusCell(CheckStatus status)
{
  const char* s = ToString(status);
  return std::string("<td class=\"") + s + "\">" + s + "</td>";
}

void SizeCell(const SizeChoice& c, std::ostream& out)
{
  if (c.Chosen())
    out << "<td class=\"num\">" << Num(c.diameterMm, 1) << " mm (" << Num(c.oversizingPercent) << " %)"
        << (c.forced ? " forced" : "") << "</td>";
  else
    out << "<td class=\"def\">none: " << Escape(c.reason) << "</td>";
}

void DeviceTable(const RepairPlan& plan, std::ostream& out)
{
  const DeviceSelection& s = plan.selection;
  out << "<h2>Devices</h2>\n<table><tr><th>family</th><th>main body</th><th>right limb</th><th>left limb</th>"
         "<th>checks</th></tr>";
  for (size_t i = 0; i < s.families.size(); ++i)
  {
    const FamilyEvaluation& f = s.families[i];
    out << "<tr" << (static_cast<int>(i) == s.recommended ? " class=\"recommended\"" : "") << "><td>"
        << Escape(f.family) << (static_cast<int>(i) == s.recommended ? " (recommended)" : "")
        << (static_cast<int>(i) == plan.simulatedFamily ? " (simulated)" : "") << "</td>";
    SizeCell(f.mainBody, out);
    SizeCell(f.rightLimb, out);
    SizeCell(f.leftLimb, out);
    out << "<td class=\"num\">" << f.Count(CheckStatus::Pass) << " pass, " << f.Count(CheckStatus::Fail) << " fail, "
        << f.Count(CheckStatus::Indeterminate) << " indeterminate</td></tr>";
    out << "<tr><td colspan=\"5\"><table><tr><th>IFU check</th><th>status</th><th>value</th><th>requirement</th>"
           "<th>margin</th></tr>";
    for (const CriterionCheck& c : f.checks)
      out << "<tr><td>" << Escape(c.name) << "</td>" << StatusCell(c.status) << "<td class=\"num\">"
          << Escape(QuantityText(c.value, c.unit)) << "</td><td>" << Escape(RequirementText(c.min, c.max, c.unit))
          << "</td><td class=\"num\">" << (std::isfinite(c.margin) ? Escape(SignedQuantityText(c.margin, c.unit)) : "")
          << "</td></tr>";
    out << "</table></td></tr>";
  }
  out << "</table>\n";
}

/// The simulated graft in the vessel from two directions, with the colours' legend.
void GraftViews(const RepairPlan& plan, const ReportFigures& figures, std::ostream& out)
{
  if (figures.graftViews.empty())
    return;
  out << "<div class=\"figures\">";
  for (std::size_t k = 0; k < figures.graftViews.size(); ++k)
    out << "<div class=\"figure\"><img class=\"graft-view\" data-view=\"" << Escape(figures.graftViewNames[k])
        << "\" width=\"" << figures.graftViews[k].width / 2 << "\" src=\"" << PngDataUri(figures.graftViews[k])
        << "\" alt=\"the simulated graft, " << Escape(figures.graftViewNames[k]) << " view\"><div class=\"caption\">"
        << Escape(figures.graftViewNames[k]) << " view</div></div>";
  out << "</div><p class=\"def\">The simulated graft in the vessel (lumen red and outer wall tan, both translucent), "
         "rendered by the planning run. ";
  for (const ConfiguredComponent& part : plan.graft.layout.components)
    out << "<span style=\"color:" << Rgb(ComponentColour(part)) << "\">&#9632;</span> " << Escape(part.item.name)
        << (part.role == OrderRole::MainBody ? ""
            : part.side == 0                 ? " (right)"
                                             : " (left)")
        << "; ";
  out << "</p>\n";
}

void FitCheckSection(const RepairPlan& plan,
                     const ReportFigures& figures,
                     const std::map<std::string, PlanValue>& values,
                     std::ostream& out)
{
  out << "<h2>Fit check of the simulated graft</h2>\n";
  if (!plan.HasGraft())
  {
    out << "<p>" << Escape(FitVerdict(plan)) << ".</p>\n";
    return;
  }
  const FitCheck& fit = plan.fitCheck;
  const GraftLayout& layout = plan.graft.layout;
  out << "<p>" << Escape(plan.selection.families[plan.simulatedFamily].family)
      << (layout.configured ? ", the ordered components deployed with the main body's proximal edge at the target"
                            : ", the chosen diameters over the measured landing zones (lengths not configured)")
      << ": the fit check <b class=\"" << (fit.Passed() ? "pass\">passed" : "fail\">failed") << "</b>.</p>";
  if (!fit.findings.empty())
  {
    out << "<ul>";
    for (const std::string& f : fit.findings)
      out << "<li class=\"fail\">" << Escape(f) << "</li>";
    out << "</ul>";
  }
  GraftViews(plan, figures, out);
  const auto row = [&](const std::string& label, const std::string& name, double value, const std::string& unit,
                       const std::string& needs)
  {
    const auto v = values.find(name);
    out << "<tr><td>" << Escape(label) << "</td>"
        << (name.empty() || v == values.end() ? "<td class=\"num\">" + Escape(ClinicalText(value, unit)) + "</td>"
                                              : ValueCell(name, value, unit, v->second.text))
        << "<td>" << Escape(needs) << "</td></tr>";
  };
  const std::string lumenOnly = " (estimated: the outer wall not traced under part of it)";
  out << "<table><tr><th>the simulated graft</th><th>value</th><th>needs</th></tr>";
  row("main body diameter", "mainBodyDiameter", plan.graftDiametersMm[0], "mm", "");
  row("right limb diameter where it lands", "rightLimbDiameter", plan.graftDiametersMm[1], "mm", "");
  row("left limb diameter where it lands", "leftLimbDiameter", plan.graftDiametersMm[2], "mm", "");
  for (int side = 0; side < 2 && layout.configured && std::isfinite(plan.graftAxisLengthMm[side]); ++side)
    row(std::string(side == 0 ? "right" : "left") + " side: the graft's own axis, proximal to distal edge", "",
        plan.graftAxisLengthMm[side], "mm", SimulatedLengthText(plan, side)); // issue 46 item 5
  const std::string proximalNeeds = "≥ " + FormatNumber(fit.minimumProximalSealMm, 0) + " mm";
  const std::string iliacNeeds = "≥ " + FormatNumber(fit.minimumIliacSealMm, 0) + " mm (the family's minimum)";
  row(std::string("proximal seal on healthy wall") + (fit.sealOnLumenOnly[0] ? lumenOnly : ""), "proximalSealLength",
      fit.proximalSealLengthMm, "mm",
      proximalNeeds + "; uncertainty " + ClinicalText(fit.proximalSealUncertaintyMm, "mm") + " (" +
        fit.proximalSealUncertaintyWhy + ")" +
        (fit.proximalSealEnd.empty() ? "" : "; ends where " + fit.proximalSealEnd));
  row("shortest apposition length (the patient's " + fit.shortestAppositionSide + " side)", "",
      fit.shortestAppositionLengthMm, "mm",
      "≥ " + FormatNumber(fit.minimumAppositionLengthMm, 0) + " mm" +
        (fit.shortestAppositionEnd.empty() ? "" : "; ends where " + fit.shortestAppositionEnd));
  row(std::string("right iliac seal on healthy wall") + (fit.sealOnLumenOnly[1] ? lumenOnly : ""),
      "rightIliacSealLength", fit.rightIliacSealLengthMm, "mm", iliacNeeds);
  row(std::string("left iliac seal on healthy wall") + (fit.sealOnLumenOnly[2] ? lumenOnly : ""), "leftIliacSealLength",
      fit.leftIliacSealLengthMm, "mm", iliacNeeds);
  row("main body oversizing at the proximal edge", "proximalOversizing", fit.proximalOversizingPercent, "%",
      "10–25 %; over 30 %: infolding");
  row("right limb oversizing in the landing zone", "rightLimbOversizing", fit.rightLimbOversizingPercent, "%",
      "10–25 %");
  row("left limb oversizing in the landing zone", "leftLimbOversizing", fit.leftLimbOversizingPercent, "%", "10–25 %");
  row("calcified share of the proximal seal zone (seals, flagged)", "", fit.proximalCalcifiedPercent, "%", "");
  out << "<tr><td>ostia covered</td><td data-name=\"coveredOstia\">" << Escape(values.at("coveredOstia").text)
      << "</td><td>none</td></tr></table>";
  out << "<table><tr><th>ostium</th><th>on</th><th>extent (mm)</th><th>overlap with the graft</th><th>covered</th>"
         "</tr>";
  for (const OstiumCoverage& o : fit.ostia)
    out << "<tr><td>" << Escape(ValueLabel(o.branch)) << "</td><td>" << Escape(o.parent) << "</td><td class=\"num\">"
        << Num(o.upperAbscissaMm) << " … " << Num(o.lowerAbscissaMm) << "</td><td class=\"num\">"
        << Escape(ClinicalText(o.overlapMm, "mm")) << "</td><td"
        << (o.covered        ? " class=\"fail\">yes"
            : o.mayBeCovered ? " class=\"fail\">cannot be excluded (its edge within " +
                                 Escape(ClinicalText(o.edgeUncertaintyMm, "mm")) + ")"
                             : ">no")
        << "</td></tr>";
  out << "</table><table><tr><th>segment</th><th>vertices</th><th>sealing</th><th>apposition gap median</th>"
         "<th>largest</th></tr>";
  const char* names[3] = { "trunk", "right leg", "left leg" };
  const StentMesh& mesh = layout.mesh;
  for (int seg = 0; seg < 3; ++seg)
  {
    std::vector<double> gaps;
    int sealed = 0;
    for (Eigen::Index i = 0; i < mesh.segment.size(); ++i)
      if (mesh.segment[i] == seg && i < fit.appositionMm.size())
      {
        gaps.push_back(fit.appositionMm[i]);
        sealed += i < fit.sealing.size() && fit.sealing[i] ? 1 : 0;
      }
    if (gaps.empty())
      continue;
    out << "<tr><td>" << names[seg] << "</td><td class=\"num\">" << gaps.size() << "</td><td class=\"num\">"
        << Escape(ClinicalText(100.0 * sealed / static_cast<double>(gaps.size()), "%")) << "</td><td class=\"num\">"
        << Escape(ClinicalText(Median(gaps), "mm")) << "</td><td class=\"num\">"
        << Escape(ClinicalText(*std::max_element(gaps.begin(), gaps.end()), "mm")) << "</td></tr>";
  }
  out << "</table>\n";
}

} // namespace

std::string ReportDateNow()
{
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char buffer[32];
  std::strftime(buffer, sizeof(buffer), "%Y-%m-%d %H:%M UTC", &utc);
  return buffer;
}

std::string ReportHtml(const RepairPlan& plan, const ReportFigures& figures, const ReportRun& run)
{
  std::map<std::string, PlanValue> values;
  for (const PlanValue& v : PlanReturnValues(plan))
    values[v.name] = v;
  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>EVAR plan: "
      << Escape(run.inputVolume) << "</title><style>" << Css << "</style></head><body>\n";
  Header(plan, run, out);
  Summary(plan, values, out);
  OrderSection(plan, values, out);
  MeasurementTable(plan, values, out);
  BranchTable(plan, out);
  const std::vector<SizingLevel> levels = SizingLevels(plan.measurements);
  out << "<h2>Diameter profiles</h2>\n";
  for (int v = 0; v < 3; ++v)
    WriteProfilePlot(plan, v, levels, out);
  out << "<h2 id=\"straightened\">Straightened views</h2>\n<p class=\"def\">The CT resampled along the centerline "
         "(stretched curved "
         "planar reformat, coronal orientation: the patient's right on the left), window "
      << FormatNumber(ReportWindowLowHu, 0) << " … " << FormatNumber(ReportWindowHighHu, 0)
      << " HU. Cyan: lumen edge; orange dashed: outer wall; red: levels (a)–(f); blue ticks: landmarks; coloured "
         "bars: each component of the simulated graft over its simulated extent (blue main body, green ipsilateral "
         "limb, orange contralateral limb, purple iliac extension).</p><div class=\"figures\">\n";
  WriteStraightenedView(figures.straightened[0], "right", out);
  WriteStraightenedView(figures.straightened[1], "left", out);
  out << "</div>\n";
  if (plan.deploymentTolerance.assessed)
  {
    out << "<h2 id=\"holds\">Where each component holds</h2>\n<p class=\"def\">The ordered graft deployed again "
           "with each component displaced along its vessel, the others where planned: around each component's edge "
           "on the straightened view, the range over which it may land and the fit check still passes.</p>"
           "<div class=\"figures\">\n";
    WriteHoldFigures(plan, figures, out);
    out << "</div>\n";
  }
  out << "<h2>Cross-sections at the sizing levels</h2>\n<p class=\"def\">Perpendicular to the centerline; the "
         "patient's left to the right, posterior down (as an axial view).</p><div class=\"figures\">\n";
  for (const CrossSectionFigure& f : figures.sections)
    WriteCrossSectionView(f, values, out);
  out << "</div>\n";
  FitCheckSection(plan, figures, values, out);
  DeviceTable(plan, out);
  out
    << "<p class=\"def\">Printing: open this file in a browser and print it (Ctrl+P) to PDF; the page is laid out for "
       "A4. Everything is in this one file.</p></body></html>\n";
  return out.str();
}

} // namespace sgp
