#include "IO/ReportHtml.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <map>
#include <sstream>

#include "Common/Format.h"
#include "Common/Median.h"
#include "IO/EncodePng.h"
#include "Pipeline/PlanValues.h"

namespace sgp
{
namespace
{

std::string Escape(const std::string& text)
{
  std::string out;
  out.reserve(text.size());
  for (const char c : text)
    switch (c)
    {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  return out;
}

std::string Num(double value, int decimals = 1)
{
  return std::isfinite(value) ? FormatNumber(value, decimals) : "n/a";
}

/// An SVG coordinate (mm in the viewBox), two decimals.
std::string C(double value)
{
  return FormatNumber(value, 2);
}

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
      << "<tr><td>Seed</td><td>RAS " << FormatNumber(-plan.seedLps.x()) << ", " << FormatNumber(-plan.seedLps.y())
      << ", " << FormatNumber(plan.seedLps.z()) << " mm, "
      << (plan.seedAutomatic ? "found automatically: " + Escape(plan.seedDescription)
                             : std::string("given by the user"))
      << "</td></tr>"
      << "<tr><td>Proximal site</td><td>" << Num(site.abscissaMm) << " mm along the aorta from its top in the scan, "
      << "LPS " << FormatPoint(site.lps) << " mm; source: " << ToString(site.source)
      << (site.renal.empty() ? "" : " (lower edge of the " + Escape(site.renal) + " ostium)") << "</td></tr>"
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
  out << "<li><b>Recommendation:</b> <span data-name=\"recommendedDevice\">"
      << Escape(values.at("recommendedDevice").text) << "</span>; " << Escape(s.summary)
      << "; within IFU: <span data-name=\"withinIfu\">" << values.at("withinIfu").text << "</span>";
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

const char* LevelOf(const std::string& name)
{
  static const std::map<std::string, const char*> levels = {
    { "proximalNeckDiameter", "(a)" },  { "proximalNeckLumenDiameter", "(a)" },
    { "neckDiameter15mm", "(b)" },      { "neckLumenDiameter15mm", "(b)" },
    { "maxAneurysmDiameter", "(c)" },   { "maxAneurysmLumenDiameter", "(c)" },
    { "distalNeckMinDiameter", "(d)" }, { "distalNeckMinLumenDiameter", "(d)" },
    { "rightIliacDiameter", "(e)" },    { "rightIliacLumenDiameter", "(e)" },
    { "leftIliacDiameter", "(f)" },     { "leftIliacLumenDiameter", "(f)" }
  };
  const auto found = levels.find(name);
  return found == levels.end() ? "" : found->second;
}

void MeasurementTable(const RepairPlan& plan, const std::map<std::string, PlanValue>& values, std::ostream& out)
{
  out << "<h2>Measurements</h2>\n<table><tr><th></th><th>value</th><th>unit</th><th>wall</th><th>definition</th></tr>";
  for (const Measurement& m : plan.measurements.values)
  {
    const auto v = values.find(m.name);
    const std::string text =
      v != values.end() ? v->second.text : (std::isfinite(m.value) ? FormatReturnValue(m.value) : "-1");
    const bool measured = v != values.end() ? v->second.measured : std::isfinite(m.value);
    out << "<tr><td>" << LevelOf(m.name) << " " << Escape(m.name) << "</td><td class=\"num\" data-name=\""
        << Escape(m.name) << "\">" << Escape(text) << "</td><td>" << Escape(m.unit) << "</td><td>"
        << (m.wall.empty() ? "" : Escape(m.wall)) << (m.estimated ? " (estimated)" : "") << "</td><td class=\"def\">"
        << Escape(m.definition) << (measured ? "" : " <b>Not measured (−1).</b>") << "</td></tr>";
  }
  out << "</table>\n";
}

/// The device's nominal diameters drawn over the profiles: main body, right limb, left limb.
std::array<double, 3> NominalDiameters(const RepairPlan& plan)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const DeviceSelection& s = plan.selection;
  const int f = plan.HasGraft() ? plan.simulatedFamily : s.recommended;
  if (f < 0 || f >= static_cast<int>(s.families.size()))
    return { nan, nan, nan };
  const FamilyEvaluation& e = s.families[f];
  return { e.mainBody.diameterMm, e.rightLimb.diameterMm, e.leftLimb.diameterMm };
}

std::string Polyline(const std::vector<std::pair<double, double>>& points)
{
  std::string s;
  for (const auto& [x, y] : points)
    s += C(x) + "," + C(y) + " ";
  return s;
}

void ProfilePlot(const RepairPlan& plan, int v, const std::vector<SizingLevel>& levels, std::ostream& out)
{
  const DiameterProfile& profile = plan.measurements.profiles[v];
  const std::string& vessel = plan.vesselWall.names[v];
  if (profile.rings.empty())
    return;
  double s0 = profile.rings.front().abscissaMm, s1 = profile.rings.back().abscissaMm, dMax = 0.0;
  for (const RingDiameters& r : profile.rings)
    dMax = std::max(dMax, r.maxMm);
  std::vector<std::pair<double, double>> outer;
  for (const OuterWallPlane& p : plan.vesselWall.vessels[v].planes)
    if (p.Usable() && p.abscissaMm >= s0 - 1e-9 && p.abscissaMm <= s1 + 1e-9)
    {
      outer.emplace_back(p.abscissaMm, p.areaDiameterMm);
      dMax = std::max(dMax, p.areaDiameterMm);
    }
  const std::array<double, 3> nominal = NominalDiameters(plan);
  if (std::isfinite(nominal[v]))
    dMax = std::max(dMax, nominal[v]);
  dMax = 10.0 * std::ceil(dMax / 10.0 + 0.01);
  const double W = 160.0, H = 50.0, left = 12.0, top = 4.0; // plot area in viewBox units
  const double span = std::max(s1 - s0, 1.0);
  const auto X = [&](double s) { return left + (s - s0) / span * W; };
  const auto Y = [&](double d) { return top + H - d / dMax * H; };
  out << "<div class=\"figure\"><svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " << C(left + W + 6) << " "
      << C(top + H + 6) << "\" width=\"680\" data-profile=\"" << vessel << "\">";
  for (double d = 0; d <= dMax + 1e-9; d += 10)
    out << "<line x1=\"" << C(left) << "\" x2=\"" << C(left + W) << "\" y1=\"" << C(Y(d)) << "\" y2=\"" << C(Y(d))
        << "\" stroke=\"#ddd\" stroke-width=\"0.2\"/><text x=\"" << C(left - 1) << "\" y=\"" << C(Y(d) + 1)
        << "\" font-size=\"3\" text-anchor=\"end\">" << d << "</text>";
  std::vector<std::pair<double, double>> band, mean;
  for (const RingDiameters& r : profile.rings)
  {
    band.emplace_back(X(r.abscissaMm), Y(r.maxMm));
    mean.emplace_back(X(r.abscissaMm), Y(r.meanMm));
  }
  for (auto r = profile.rings.rbegin(); r != profile.rings.rend(); ++r)
    band.emplace_back(X(r->abscissaMm), Y(r->minMm));
  out << "<polygon points=\"" << Polyline(band) << "\" fill=\"#9bd\" fill-opacity=\"0.5\" stroke=\"none\"/>";
  out << "<polyline points=\"" << Polyline(mean) << "\" fill=\"none\" stroke=\"#036\" stroke-width=\"0.5\"/>";
  for (auto& p : outer)
    p = { X(p.first), Y(p.second) };
  if (!outer.empty())
    out << "<polyline points=\"" << Polyline(outer)
        << "\" fill=\"none\" stroke=\"#d60\" stroke-width=\"0.4\" stroke-dasharray=\"1.5,0.8\"/>";
  if (std::isfinite(nominal[v]))
    out << "<line x1=\"" << C(left) << "\" x2=\"" << C(left + W) << "\" y1=\"" << C(Y(nominal[v])) << "\" y2=\""
        << C(Y(nominal[v])) << "\" stroke=\"#080\" stroke-width=\"0.4\" stroke-dasharray=\"3,1\"/><text x=\""
        << C(left + W - 1) << "\" y=\"" << C(Y(nominal[v]) - 1)
        << "\" font-size=\"3\" text-anchor=\"end\" fill=\"#080\">" << (v == 0 ? "main body " : "limb ")
        << Num(nominal[v], 0) << " mm</text>";
  for (const SizingLevel& l : levels)
    if (l.vessel == vessel && std::isfinite(l.abscissaMm))
      out << "<line x1=\"" << C(X(l.abscissaMm)) << "\" x2=\"" << C(X(l.abscissaMm)) << "\" y1=\"" << C(top)
          << "\" y2=\"" << C(top + H) << "\" stroke=\"#a00\" stroke-width=\"0.3\"/><text x=\""
          << C(X(l.abscissaMm) + 0.5) << "\" y=\"" << C(top + 3) << "\" font-size=\"3\" fill=\"#a00\">" << l.label
          << "</text>";
  out << "<line x1=\"" << C(left) << "\" x2=\"" << C(left + W) << "\" y1=\"" << C(top + H) << "\" y2=\"" << C(top + H)
      << "\" stroke=\"#000\" stroke-width=\"0.3\"/>";
  for (double s = 10.0 * std::ceil(s0 / 10.0); s <= s1 + 1e-9; s += (span > 120 ? 20.0 : 10.0))
    out << "<text x=\"" << C(X(s)) << "\" y=\"" << C(top + H + 4) << "\" font-size=\"3\" text-anchor=\"middle\">" << s
        << "</text>";
  out << "</svg><div class=\"caption wide\">" << vessel
      << ": diameter (mm) along the centerline (mm). Blue: mean ring diameter of the fitted lumen surface, band: its "
         "min–max; orange dashed: outer wall (area-equivalent); green dashed: the device's nominal diameter; red: "
         "the sizing levels.</div></div>\n";
}

void StraightenedView(const StraightenedFigure& f, const char* side, std::ostream& out)
{
  const double half = (f.image.width - 1) / 2.0 * f.image.pixelMm;
  const double length = f.path.LengthMm();
  const double px = f.image.pixelMm;
  const double left = -half - 4.0, right = half + 46.0, top = -6.0, bottom = length + 12.0;
  const double scale = 2.0; // display px per mm
  out << "<div class=\"figure\"><svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << C(left) << " " << C(top) << " "
      << C(right - left) << " " << C(bottom - top) << "\" width=\"" << static_cast<int>((right - left) * scale)
      << "\" height=\"" << static_cast<int>((bottom - top) * scale) << "\" data-straightened=\"" << side << "\">";
  out << "<image x=\"" << C(-half - px / 2) << "\" y=\"" << C(-px / 2) << "\" width=\"" << C(f.image.width * px)
      << "\" height=\"" << C(f.image.height * px) << "\" preserveAspectRatio=\"none\" href=\""
      << PngDataUri(f.image, ReportWindowLowHu, ReportWindowHighHu) << "\"/>";
  const auto edge = [&](const std::vector<PathMark>& marks, const char* colour, const char* dash)
  {
    std::vector<std::pair<double, double>> pts;
    for (const PathMark& m : marks)
      pts.emplace_back(m.offsetMm, m.pathMm);
    if (!pts.empty())
      out << "<polyline points=\"" << Polyline(pts) << "\" fill=\"none\" stroke=\"" << colour
          << "\" stroke-width=\"0.35\"" << dash << "/>";
  };
  edge(f.lumenLeft, "#0cf", "");
  edge(f.lumenRight, "#0cf", "");
  edge(f.outerLeft, "#f90", " stroke-dasharray=\"1.2,0.8\"");
  edge(f.outerRight, "#f90", " stroke-dasharray=\"1.2,0.8\"");
  for (const PathMark& l : f.levels)
    out << "<line class=\"level\" data-level=\"" << l.label << "\" data-path-mm=\"" << FormatNumber(l.pathMm, 2)
        << "\" x1=\"" << C(-half) << "\" x2=\"" << C(half + 2) << "\" y1=\"" << C(l.pathMm) << "\" y2=\"" << C(l.pathMm)
        << "\" stroke=\"#f33\" stroke-width=\"0.4\"/><text x=\"" << C(half + 3) << "\" y=\"" << C(l.pathMm + 1.2)
        << "\" font-size=\"3.5\" fill=\"#b00\">" << l.label << "</text>";
  for (const PathMark& l : f.landmarks)
    out << "<line x1=\"" << C(-half - 3) << "\" x2=\"" << C(-half) << "\" y1=\"" << C(l.pathMm) << "\" y2=\""
        << C(l.pathMm) << "\" stroke=\"#06c\" stroke-width=\"0.5\"/><text x=\"" << C(half + 12) << "\" y=\""
        << C(l.pathMm + 1.0) << "\" font-size=\"3\" fill=\"#06c\" data-landmark=\"" << Escape(l.label) << "\">"
        << Escape(l.label) << "</text>";
  if (std::isfinite(f.graftStartMm) && std::isfinite(f.graftEndMm))
    out << "<line x1=\"" << C(half + 9) << "\" x2=\"" << C(half + 9) << "\" y1=\"" << C(f.graftStartMm) << "\" y2=\""
        << C(f.graftEndMm) << "\" stroke=\"#080\" stroke-width=\"1.2\"/><text x=\"" << C(half + 8) << "\" y=\""
        << C(f.graftStartMm - 1.5) << "\" font-size=\"2.8\" fill=\"#080\">graft</text>";
  out << "<line x1=\"" << C(-half) << "\" x2=\"" << C(-half + 10) << "\" y1=\"" << C(length + 5) << "\" y2=\""
      << C(length + 5) << "\" stroke=\"#000\" stroke-width=\"0.8\"/><text x=\"" << C(-half) << "\" y=\""
      << C(length + 10) << "\" font-size=\"3\">10 mm</text>";
  out << "<text x=\"" << C(-half) << "\" y=\"-2\" font-size=\"3.2\">" << Escape(f.path.name) << "</text></svg></div>\n";
}

void CrossSectionView(const CrossSectionFigure& f, const std::map<std::string, PlanValue>& values, std::ostream& out)
{
  const double half = (f.image.width - 1) / 2.0 * f.image.pixelMm, px = f.image.pixelMm;
  out << "<div class=\"figure\"><svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << C(-half - px / 2) << " "
      << C(-half - px / 2) << " " << C(2 * half + px) << " " << C(2 * half + px)
      << "\" width=\"220\" height=\"220\" data-section=\"" << f.level.label << "\"><image x=\"" << C(-half - px / 2)
      << "\" y=\"" << C(-half - px / 2) << "\" width=\"" << C(f.image.width * px) << "\" height=\""
      << C(f.image.height * px) << "\" preserveAspectRatio=\"none\" href=\""
      << PngDataUri(f.image, ReportWindowLowHu, ReportWindowHighHu) << "\"/>";
  const double stroke = std::max(0.25, half / 120.0);
  const auto polygon = [&](const std::vector<Eigen::Vector2d>& pts, const char* colour, const char* dash)
  {
    if (pts.empty())
      return;
    std::vector<std::pair<double, double>> p;
    for (const Eigen::Vector2d& q : pts)
      p.emplace_back(q.x(), q.y());
    out << "<polygon points=\"" << Polyline(p) << "\" fill=\"none\" stroke=\"" << colour << "\" stroke-width=\""
        << C(stroke) << "\"" << dash << "/>";
  };
  polygon(f.outer, "#f90", " stroke-dasharray=\"1.2,0.8\"");
  polygon(f.ring, "#0cf", "");
  const auto segment = [&](const std::array<Eigen::Vector2d, 2>& s, const char* colour)
  {
    out << "<line x1=\"" << C(s[0].x()) << "\" y1=\"" << C(s[0].y()) << "\" x2=\"" << C(s[1].x()) << "\" y2=\""
        << C(s[1].y()) << "\" stroke=\"" << colour << "\" stroke-width=\"" << C(stroke) << "\"/>";
  };
  if (f.hasCalipers)
  {
    segment(f.minCaliper, "#3f3");
    segment(f.maxCaliper, "#f3f");
  }
  out << "<line x1=\"" << C(-half + 2) << "\" x2=\"" << C(-half + 12) << "\" y1=\"" << C(half - 3) << "\" y2=\""
      << C(half - 3) << "\" stroke=\"#fff\" stroke-width=\"" << C(2 * stroke) << "\"/></svg>";
  const auto value = [&](const std::string& name)
  {
    const auto v = values.find(name);
    return v == values.end() ? std::string("-1") : v->second.text;
  };
  out << "<div class=\"caption\"><b>" << f.level.label << "</b> " << Escape(f.level.vessel) << " at "
      << Num(f.level.abscissaMm) << " mm: outer <span data-name=\"" << f.level.outerName << "\">"
      << Escape(value(f.level.outerName)) << "</span> mm, lumen <span data-name=\"" << f.level.lumenName << "\">"
      << Escape(value(f.level.lumenName)) << "</span> mm. Cyan: the measured ring; green/magenta: its shortest and "
      << "longest diameter; orange dashed: the outer wall; white bar 10 mm.</div></div>\n";
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

void FitCheckSection(const RepairPlan& plan, const std::map<std::string, PlanValue>& values, std::ostream& out)
{
  out << "<h2>Fit check of the simulated graft</h2>\n";
  if (!plan.HasGraft())
  {
    out << "<p>" << Escape(FitVerdict(plan)) << ".</p>\n";
    return;
  }
  const FitCheck& fit = plan.fitCheck;
  out << "<p>" << Escape(plan.selection.families[plan.simulatedFamily].family) << ", main body "
      << Num(plan.graftDiametersMm[0], 1) << " mm, limbs " << Num(plan.graftDiametersMm[1], 1) << " / "
      << Num(plan.graftDiametersMm[2], 1) << " mm: " << Escape(FitVerdict(plan)) << ".</p><table>";
  for (const char* name : { "mainBodyDiameter", "rightLimbDiameter", "leftLimbDiameter", "proximalSealLength",
                            "rightIliacSealLength", "leftIliacSealLength", "proximalOversizing", "rightLimbOversizing",
                            "leftLimbOversizing", "coveredOstia", "migrationRisk" })
  {
    const auto v = values.find(name);
    out << "<tr><td>" << name << "</td><td class=\"num\" data-name=\"" << name << "\">"
        << Escape(v != values.end() ? v->second.text : "") << "</td></tr>";
  }
  out << "</table><table><tr><th>ostium</th><th>on</th><th>extent (mm)</th><th>overlap (mm)</th><th>covered</th></tr>";
  for (const OstiumCoverage& o : fit.ostia)
    out << "<tr><td>" << Escape(o.branch) << "</td><td>" << Escape(o.parent) << "</td><td class=\"num\">"
        << Num(o.upperAbscissaMm) << " … " << Num(o.lowerAbscissaMm) << "</td><td class=\"num\">" << Num(o.overlapMm)
        << "</td><td" << (o.covered ? " class=\"fail\">yes" : ">no") << "</td></tr>";
  out << "</table><table><tr><th>segment</th><th>vertices</th><th>sealing</th><th>apposition gap median (mm)</th>"
         "<th>max (mm)</th></tr>";
  const char* names[3] = { "trunk", "right leg", "left leg" };
  for (int seg = 0; seg < 3; ++seg)
  {
    std::vector<double> gaps;
    int sealed = 0;
    for (Eigen::Index i = 0; i < plan.mesh.segment.size(); ++i)
      if (plan.mesh.segment[i] == seg && i < fit.appositionMm.size())
      {
        gaps.push_back(fit.appositionMm[i]);
        sealed += i < fit.sealing.size() && fit.sealing[i] ? 1 : 0;
      }
    if (gaps.empty())
      continue;
    out << "<tr><td>" << names[seg] << "</td><td class=\"num\">" << gaps.size() << "</td><td class=\"num\">"
        << Num(100.0 * sealed / static_cast<double>(gaps.size())) << " %</td><td class=\"num\">" << Num(Median(gaps), 2)
        << "</td><td class=\"num\">" << Num(*std::max_element(gaps.begin(), gaps.end()), 2) << "</td></tr>";
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
  MeasurementTable(plan, values, out);
  const std::vector<SizingLevel> levels = SizingLevels(plan.measurements);
  out << "<h2>Diameter profiles</h2>\n";
  for (int v = 0; v < 3; ++v)
    ProfilePlot(plan, v, levels, out);
  out << "<h2 id=\"straightened\">Straightened views</h2>\n<p class=\"def\">The CT resampled along the centerline "
         "(stretched curved "
         "planar reformat, coronal orientation: the patient's right on the left), window "
      << FormatNumber(ReportWindowLowHu, 0) << " … " << FormatNumber(ReportWindowHighHu, 0)
      << " HU. Cyan: lumen edge; orange dashed: outer wall; red: levels (a)–(f); blue ticks: landmarks; green bar: "
         "the simulated graft.</p><div class=\"figures\">\n";
  StraightenedView(figures.straightened[0], "right", out);
  StraightenedView(figures.straightened[1], "left", out);
  out << "</div>\n<h2>Cross-sections at the sizing levels</h2>\n<p class=\"def\">Perpendicular to the centerline; the "
         "patient's left to the right, posterior down (as an axial view).</p><div class=\"figures\">\n";
  for (const CrossSectionFigure& f : figures.sections)
    CrossSectionView(f, values, out);
  out << "</div>\n";
  DeviceTable(plan, out);
  FitCheckSection(plan, values, out);
  out
    << "<p class=\"def\">Printing: open this file in a browser and print it (Ctrl+P) to PDF; the page is laid out for "
       "A4. Everything is in this one file.</p></body></html>\n";
  return out.str();
}

} // namespace sgp
