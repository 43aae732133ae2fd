#include "IO/ReportFigureSvg.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "Common/Format.h"
#include "Common/Text.h"
#include "IO/EncodePng.h"
#include "IO/HtmlText.h"
#include "IO/ReportHtml.h"
#include "Pipeline/ValueText.h"

namespace sgp
{
namespace
{

using html::C;
using html::Escape;
using html::Num;
using html::Polyline;
using html::Rgb;

/// The device's nominal diameters drawn over the profiles: main body, right limb, left limb.
std::array<double, 3> NominalDiameters(const RepairPlan& plan)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const DeviceSelection& s = plan.selection;
  if (plan.HasGraft())
    return plan.graftDiametersMm;
  const int f = s.recommended;
  if (f < 0 || f >= static_cast<int>(s.families.size()))
    return { nan, nan, nan };
  const FamilyEvaluation& e = s.families[f];
  return { e.mainBody.diameterMm, e.rightLimb.diameterMm, e.leftLimb.diameterMm };
}

/// The rows [first, last] of `image`, as an image of its own.
PlaneImage Rows(const PlaneImage& image, int first, int last)
{
  PlaneImage crop;
  crop.width = image.width;
  crop.height = last - first + 1;
  crop.pixelMm = image.pixelMm;
  crop.hu.assign(image.hu.begin() + std::ptrdiff_t(first) * image.width,
                 image.hu.begin() + std::ptrdiff_t(last + 1) * image.width);
  return crop;
}

/// Display pixels per mm of a hold figure.
constexpr double HoldScale = 4.0;

} // namespace

void WriteHoldFigures(const RepairPlan& plan, const ReportFigures& figures, std::ostream& out)
{
  const DeploymentTolerance& t = plan.deploymentTolerance;
  const DeviceConfiguration* c = plan.Configuration();
  if (!t.assessed || !c)
    return;
  for (const ComponentHold& h : t.components)
  {
    if (h.component >= c->components.size())
      continue;
    const ConfiguredComponent& part = c->components[h.component];
    const bool body = part.role == OrderRole::MainBody;
    const int side = body ? c->ipsilateralSide : part.side;
    const StraightenedFigure& f = figures.straightened[std::size_t(side)];
    const auto extent = std::find_if(f.components.begin(), f.components.end(),
                                     [&](const ComponentExtent& e) { return e.component == h.component; });
    if (extent == f.components.end() || f.image.height < 2)
      continue;
    const double edge = body ? extent->fromMm : extent->toMm;
    const double px = f.image.pixelMm, half = (f.image.width - 1) / 2.0 * px;
    const double reach = std::max(t.searchMm, t.toleranceMm) + 8.0;
    const int first = std::clamp(int(std::floor((edge - reach) / px)), 0, f.image.height - 1);
    const int last = std::clamp(int(std::ceil((edge + reach) / px)), first, f.image.height - 1);
    const double top = edge - reach, height = 2.0 * reach;
    const double left = -half - 2.0, width = 2.0 * half + 42.0;
    const double from = edge - h.aboveMm, to = edge + h.belowMm;
    out << "<div class=\"figure\"><svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << C(left) << " " << C(top)
        << " " << C(width) << " " << C(height) << "\" width=\"" << int(std::lround(width * HoldScale)) << "\" height=\""
        << int(std::lround(height * HoldScale)) << "\" data-hold=\"" << h.component << "\" data-view-top-mm=\""
        << FormatNumber(top, 3) << "\" data-view-height-mm=\"" << FormatNumber(height, 3) << "\"><rect x=\"" << C(left)
        << "\" y=\"" << C(top) << "\" width=\"" << C(width) << "\" height=\"" << C(height) << "\" fill=\"#fff\"/>";
    out << "<image x=\"" << C(-half - px / 2) << "\" y=\"" << C(first * px - px / 2) << "\" width=\""
        << C(f.image.width * px) << "\" height=\"" << C((last - first + 1) * px)
        << "\" preserveAspectRatio=\"none\" href=\""
        << PngDataUri(Rows(f.image, first, last), ReportWindowLowHu, ReportWindowHighHu) << "\"/>";
    // The band over the CT, the tolerance dashed, the edge; the band again as a bar beside the CT.
    out << "<rect x=\"" << C(-half) << "\" y=\"" << C(from) << "\" width=\"" << C(2 * half) << "\" height=\""
        << C(to - from) << "\" fill=\"#2c2\" fill-opacity=\"0.25\"/>";
    for (const double y : { edge - t.toleranceMm, edge + t.toleranceMm })
      out << "<line x1=\"" << C(-half) << "\" x2=\"" << C(half + 8) << "\" y1=\"" << C(y) << "\" y2=\"" << C(y)
          << "\" stroke=\"#333\" stroke-width=\"0.3\" stroke-dasharray=\"1.5,1\"/>";
    out << "<rect class=\"hold-band\" data-hold=\"" << h.component << "\" data-edge-mm=\"" << FormatNumber(edge, 3)
        << "\" data-band-from-mm=\"" << FormatNumber(from, 3) << "\" data-band-to-mm=\"" << FormatNumber(to, 3)
        << "\" x=\"" << C(half + 2) << "\" y=\"" << C(from) << "\" width=\"4\" height=\"" << C(to - from)
        << "\" fill=\"#0a0\"/>";
    out << "<line class=\"hold-edge\" x1=\"" << C(-half) << "\" x2=\"" << C(half + 8) << "\" y1=\"" << C(edge)
        << "\" y2=\"" << C(edge) << "\" stroke=\"#e00\" stroke-width=\"0.5\"/>";
    // "≥" where the range held to the search's end; "as far as it goes" where it ends at a stop.
    const auto label = [&](double mm, bool stops, const std::string& fails, const char* way)
    {
      return (stops           ? ""
              : fails.empty() ? "≥ "
                              : "") +
             FormatNumber(mm) + " mm " + way + (stops ? " (as far as it goes)" : "");
    };
    out << "<text x=\"" << C(half + 9) << "\" y=\"" << C(from - 0.8) << "\" font-size=\"3\">"
        << Escape(label(h.aboveMm, h.aboveStops, h.aboveFails, "up")) << "</text><text x=\"" << C(half + 9) << "\" y=\""
        << C(to + 3.2) << "\" font-size=\"3\">" << Escape(label(h.belowMm, h.belowStops, h.belowFails, "down"))
        << "</text></svg>";
    out << "<div class=\"caption\"><b>" << Escape(h.name) << "</b> (" << (body ? "proximal" : "distal") << " edge, "
        << (side == 0 ? "right" : "left") << " view): " << Escape(h.Text(t.searchMm))
        << ". Red: its edge as simulated; green: where it may land and the plan still holds; dashed: ±"
        << Num(t.toleranceMm) << " mm.</div></div>\n";
  }
}

void WriteProfilePlot(const RepairPlan& plan, int v, const std::vector<SizingLevel>& levels, std::ostream& out)
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

void WriteStraightenedView(const StraightenedFigure& f, const char* side, std::ostream& out)
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
        << Escape(IdentifierWords(l.label)) << "</text>";
  // The simulated components side by side, each in its colour, over its simulated extent.
  for (std::size_t k = 0; k < f.components.size(); ++k)
  {
    const ComponentExtent& e = f.components[k];
    const double x = half + 7.0 + 2.0 * double(k);
    out << "<line class=\"component\" data-component=\"" << Escape(e.label) << "\" data-from-mm=\""
        << FormatNumber(e.fromMm, 2) << "\" data-to-mm=\"" << FormatNumber(e.toMm, 2) << "\" x1=\"" << C(x)
        << "\" x2=\"" << C(x) << "\" y1=\"" << C(e.fromMm) << "\" y2=\"" << C(e.toMm) << "\" stroke=\"" << Rgb(e.rgb)
        << "\" stroke-width=\"1.4\"/>";
  }
  if (std::isfinite(f.graftStartMm))
    out << "<text x=\"" << C(half + 6) << "\" y=\"" << C(f.graftStartMm - 1.5)
        << "\" font-size=\"2.8\" fill=\"#036\">graft</text>";
  out << "<line x1=\"" << C(-half) << "\" x2=\"" << C(-half + 10) << "\" y1=\"" << C(length + 5) << "\" y2=\""
      << C(length + 5) << "\" stroke=\"#000\" stroke-width=\"0.8\"/><text x=\"" << C(-half) << "\" y=\""
      << C(length + 10) << "\" font-size=\"3\">10 mm</text>";
  out << "<text x=\"" << C(-half) << "\" y=\"-2\" font-size=\"3.2\">" << Escape(f.path.name) << "</text></svg></div>\n";
}

void WriteCrossSectionView(const CrossSectionFigure& f,
                           const std::map<std::string, PlanValue>& values,
                           std::ostream& out)
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
    const std::string text = v == values.end() ? std::string("-1") : v->second.text;
    const double number = v != values.end() && v->second.measured ? std::stod(text) : std::nan("");
    return "<span data-name=\"" + Escape(name) + "\" data-value=\"" + Escape(text) + "\">" +
           Escape(ClinicalText(number, "mm")) + "</span>";
  };
  out << "<div class=\"caption\"><b>" << f.level.label << "</b> " << Escape(f.level.vessel) << " at "
      << Num(f.level.abscissaMm) << " mm: outer " << value(f.level.outerName) << ", lumen " << value(f.level.lumenName)
      << ". Cyan: the measured ring; green/magenta: its shortest and "
      << "longest diameter; orange dashed: the outer wall; white bar 10 mm.</div></div>\n";
}

} // namespace sgp
