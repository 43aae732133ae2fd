#include "Measurement/MeasureAnatomy.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "Centerlines/FlowDivider.h"
#include "Centerlines/VesselOrigins.h"
#include "Common/Format.h"
#include "Common/Median.h"
#include "Measurement/DistalAorta.h"
#include "Measurement/MeasureOuterWall.h"
#include "Measurement/SectionTilt.h"
#include "Stent/StentMesh.h"

namespace sgp
{
namespace
{

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double radiansToDegrees = 57.29577951308232;
constexpr double neckDilationFactor = 1.10;    ///< the neck ends where the diameter exceeds (a) by 10 %
constexpr double secondDiameterDepthMm = 15.0; ///< (b), paper section 2.2
constexpr double landingZoneMm = 15.0;         ///< distal iliac landing zone for (e)/(f)

double AngleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return std::atan2(a.cross(b).norm(), a.dot(b)) * radiansToDegrees;
}

Measurement Diameter(const std::string& name,
                     const RingDiameters& ring,
                     const std::string& vessel,
                     const std::string& definition)
{
  Measurement m{ name, ring.meanMm, "mm", definition, vessel, ring.abscissaMm };
  m.wall = "lumen";
  m.minMm = ring.minMm;
  m.maxMm = ring.maxMm;
  m.areaMm = ring.areaMm;
  return m;
}

const char* Side(int side)
{
  return side == 0 ? "right" : "left";
}

/// A ring whose smallest diameter is under half its mean has folded or cut the wall obliquely:
/// its mean is not a diameter of the vessel.
bool Distorted(const RingDiameters& r)
{
  return r.minMm < 0.5 * r.meanMm;
}

/// What every step of MeasureAnatomy reads: the inputs, the profiles and the landmarks found so far.
struct MeasureContext
{
  const CenterlineTree& tree;
  const ProximalSite& site;
  const Centerline* iliac[2];
  const DiameterProfile& trunk;
  const VesselWall* wall;          ///< the traced outer wall, or nullptr
  Point3 B;                        ///< the aortic bifurcation, LPS mm
  double sSite = nan, sBif = nan;  ///< along the aorta, mm
  double internalIliacAbscissa[2]; ///< along each iliac, mm (NaN: none found)
};

/// (a) at the site and (b) 15 mm below it; returns both rings.
std::pair<RingDiameters, RingDiameters> MeasureNeckDiameters(const MeasureContext& c, Measurements& out)
{
  const DiameterProfile& trunk = c.trunk;
  if (!trunk.rings.empty() && trunk.rings.front().abscissaMm > c.sSite + 1.0)
    out.warnings.push_back(
      "The fitted trunk starts " + FormatNumber(trunk.rings.front().abscissaMm - c.sSite) +
      " mm below the proximal implantation site (proximalStartMm); (a) is read at its first ring.");
  const RingDiameters a = trunk.At(c.sSite);
  out.values.push_back(Diameter("proximalNeckLumenDiameter", a, "aorta",
                                "(a) mean ring diameter of the fitted surface at the proximal implantation site (" +
                                  std::string(ToString(c.site.source)) + "), lumen"));
  const RingDiameters b = trunk.At(c.sSite + secondDiameterDepthMm);
  out.values.push_back(
    Diameter("neckLumenDiameter15mm", b, "aorta",
             "(b) mean ring diameter 15 mm below the proximal site along the aortic centerline, lumen"));
  const std::pair<const char*, const RingDiameters*> levels[2] = { { "(a)", &a }, { "(b)", &b } };
  for (const auto& [level, ring] : levels)
    if (ring->mouthVertices > 0)
      out.warnings.push_back(std::string(level) + "'s ring crosses a branch mouth (" +
                             std::to_string(ring->mouthVertices) + " of its vertices lie more than " +
                             FormatNumber(BranchMouthRadiusFactor) +
                             " x its median radius from the centerline); the diameters through them are left out.");
  return { a, b };
}

/// The distal aorta's direction below the trunk's last ring (unit, LPS): from the centerline 20 mm
/// above that ring to B — the axis the sections are read ⊥ to. Not the centerline's tangent near its
/// end, which bends toward an iliac: tilted 13° there, its planes read a steep funnel 1 mm wide.
Eigen::Vector3d DistalDirection(const MeasureContext& c)
{
  const double s = std::max(0.0, c.trunk.rings.back().abscissaMm - 20.0);
  return Eigen::Vector3d(c.B - PositionAt(c.tree.aorta, s)).normalized();
}

/// (c) the widest ring between the site and B, (d) the narrowest below it — on down to B on the
/// lumen's sections ⊥ `down` (DistalDirection) where the trunk still narrows at its last ring
/// (DistalAorta.h); returns (c)'s ring index.
std::size_t MeasureSacDiameters(const MeasureContext& c,
                                const LabelImage* lumen,
                                const Eigen::Vector3d& down,
                                Measurements& out)
{
  const DiameterProfile& trunk = c.trunk;
  std::size_t widest = 0;
  for (std::size_t k = 0; k < trunk.rings.size(); ++k)
    if (trunk.rings[k].abscissaMm >= c.sSite - 1e-9 && trunk.rings[k].abscissaMm <= c.sBif &&
        trunk.rings[k].meanMm > trunk.rings[widest].meanMm)
      widest = k;
  out.values.push_back(
    Diameter("maxAneurysmLumenDiameter", trunk.rings[widest], "aorta",
             "(c) largest mean ring diameter between the proximal site and the aortic bifurcation, lumen"));
  std::size_t narrowest = widest;
  std::vector<AbscissaDiameter> below;
  for (std::size_t k = widest; k < trunk.rings.size(); ++k)
  {
    below.push_back({ trunk.rings[k].abscissaMm, trunk.rings[k].meanMm });
    if (trunk.rings[k].meanMm < trunk.rings[narrowest].meanMm)
      narrowest = k;
  }
  const RingDiameters& last = trunk.rings.back();
  DistalSection section;
  if (lumen && StillNarrowingAtItsEnd(below))
  {
    const FlowDivider& divider = out.flowDivider;
    // Down to B's level along the distal aorta's direction (the centerline's abscissa runs ahead
    // of the height where it bends at its end).
    const double reach = std::max(0.0, (c.B - last.centre).dot(down));
    section = NarrowestLumenSectionBelow(*lumen, last.centre, last.abscissaMm, down, reach,
                                         divider.found ? &divider.lps : nullptr);
  }
  if (section.found && section.section.meanMm < trunk.rings[narrowest].meanMm)
    out.values.push_back(
      Diameter("distalNeckMinLumenDiameter", section.section, "aorta",
               "(d) smallest mean diameter between (c) and the aortic bifurcation: the aorta still narrows at the "
               "trunk's last ring, so read below it on the lumen's cross-sections down to the bifurcation, lumen"));
  else
    out.values.push_back(Diameter("distalNeckMinLumenDiameter", trunk.rings[narrowest], "aorta",
                                  "(d) smallest mean ring diameter between (c) and the trunk's last ring (3 stent "
                                  "radii above the flow divider), lumen"));
  return widest;
}

/// (e) or (f): the distal landing zone of one leg, from the rings that kept their shape; where the
/// fit collapsed there (a tortuous iliac can fold the rings), the centerline's inscribed diameter
/// instead, with a warning.
void MeasureIliacLandingZone(const MeasureContext& c, int side, Measurements& out)
{
  const DiameterProfile& leg = out.profiles[1 + side];
  const Centerline& vessel = *c.iliac[side];
  const double end = leg.rings.back().abscissaMm, start = end - landingZoneMm;
  std::vector<double> means;
  int distorted = 0;
  for (const RingDiameters& r : leg.rings)
    if (r.abscissaMm >= start - 1e-9)
    {
      if (Distorted(r))
        ++distorted;
      else
        means.push_back(r.meanMm);
    }
  RingDiameters zone = leg.At(0.5 * (start + end));
  const std::string name = std::string(Side(side)) + "IliacLumenDiameter";
  std::string definition = std::string(side == 0 ? "(e)" : "(f)") +
                           " median mean ring diameter of the common iliac over the leg's distal 15 mm (landing "
                           "zone ending 5 mm above the internal iliac origin), lumen";
  if (means.size() >= 2)
    zone.meanMm = Median(means);
  else
  {
    std::vector<double> inscribed;
    for (Eigen::Index i = 0; i < vessel.Size(); ++i)
      if (vessel.abscissaMm[i] >= start - 1e-9 && vessel.abscissaMm[i] <= end + 1e-9)
        inscribed.push_back(2.0 * vessel.radiusMm[i]);
    zone.meanMm = inscribed.empty() ? nan : Median(inscribed);
    zone.minMm = zone.maxMm = zone.areaMm = zone.meanMm;
    definition += "; the fitted rings there are distorted, so: median inscribed-sphere diameter of the centerline";
    out.warnings.push_back(std::to_string(distorted) + " of the " + Side(side) +
                           " leg's rings in its landing zone are distorted (smallest diameter under half the mean: "
                           "a tortuous iliac?); " +
                           name + " is the centerline's inscribed diameter there, " + FormatNumber(zone.meanMm) +
                           " mm.");
  }
  out.values.push_back(Diameter(name, zone, leg.vessel, definition));
}

/// (a)–(d) read one ring each: a warning for each such ring that is distorted.
void WarnDistortedAorticRings(Measurements& out)
{
  for (const Measurement& m : out.values)
    if (m.vessel == "aorta" && m.minMm < 0.5 * m.value)
      out.warnings.push_back(m.name + ": the ring at " + FormatNumber(m.abscissaMm) +
                             " mm along the aorta is distorted (smallest diameter " + FormatNumber(m.minMm) +
                             " mm, mean " + FormatNumber(m.value) + " mm); check the fit there.");
}

/// Where the neck ends: the first ring above (c) whose smallest diameter (the minor axis where a
/// ring cuts a bend obliquely) exceeds (a) by 10 %, linear between rings; NaN with a warning when
/// none does. Near an angulated neck's bend the mean of a tilted ring grows before the aorta does.
double FindNeckEnd(const MeasureContext& c, const RingDiameters& a, std::size_t widest, Measurements& out)
{
  const DiameterProfile& trunk = c.trunk;
  for (std::size_t k = 1; k <= widest && k < trunk.rings.size(); ++k)
  {
    const RingDiameters &p = trunk.rings[k - 1], &q = trunk.rings[k];
    const double threshold = neckDilationFactor * a.meanMm;
    if (q.abscissaMm > c.sSite && q.minMm > threshold)
    {
      const double t = q.minMm > p.minMm ? std::clamp((threshold - p.minMm) / (q.minMm - p.minMm), 0.0, 1.0) : 1.0;
      return std::max(c.sSite, p.abscissaMm + t * (q.abscissaMm - p.abscissaMm));
    }
  }
  out.warnings.push_back("The aorta never widens 10 % beyond (a) below the proximal site; proximalNeckLength is "
                         "not measured (no aneurysm between the site and the bifurcation?).");
  return nan;
}

/// Neck length, site to B, and B to each internal iliac origin; fills `iliacOffset` (B to the
/// start of each iliac centerline along its first tangent, mm).
void MeasureLengths(const MeasureContext& c, double sNeckEnd, double iliacOffset[2], Measurements& out)
{
  std::vector<Measurement>& v = out.values;
  const bool outer = std::isfinite(out.outerNeckEndMm);
  Measurement neck{ "proximalNeckLength",
                    sNeckEnd - c.sSite,
                    "mm",
                    outer ? "proximal site to where the outer wall's smallest width first exceeds (a) by 10 %, along "
                            "the aortic centerline"
                          : "proximal site to where the ring's smallest diameter first exceeds the lumen's (a) by "
                            "10 %, along the aortic centerline",
                    "aorta",
                    c.sSite };
  neck.wall = outer ? "outer" : "lumen";
  v.push_back(neck);
  v.push_back({ "proximalSiteToBifurcationLength", c.sBif - c.sSite, "mm",
                "proximal site to the aortic bifurcation (where the aortic and common iliac axes meet), along the "
                "aortic centerline",
                "aorta", c.sSite });
  for (int side = 0; side < 2; ++side)
  {
    const Point3 start = c.iliac[side]->points.row(0).transpose();
    iliacOffset[side] = (start - c.B).dot(TangentAt(*c.iliac[side], 0.0));
    const double length = c.internalIliacAbscissa[side] + iliacOffset[side];
    if (!std::isfinite(length))
      out.warnings.push_back(std::string("No ") + Side(side) +
                             " internal iliac artery was found; the iliac length is not measured.");
    v.push_back({ std::string(Side(side)) + "IliacLength", length, "mm",
                  "aortic bifurcation to the internal iliac origin, along the iliac centerline", c.iliac[side]->name,
                  0.0 });
  }
}

/// Site to the flow divider along the aorta (B's abscissa plus the divider's depth below it: the
/// aortic centerline extended along the distal aorta's axis) and from the divider to each internal
/// iliac origin along the iliac centerline (FlowDivider.h); NaN with a warning where it was not
/// found or no lumen mask was given.
void MeasureFlowDividerLengths(const MeasureContext& c, Measurements& out)
{
  const FlowDivider& f = out.flowDivider; // found before (d), which stops at it
  if (!f.found)
    out.warnings.push_back(
      "The flow divider (where the aortic lumen divides into the iliacs) was not found: " + f.reason +
      "; the lengths from it are not measured and the limbs' seal is judged from "
      "the aortic bifurcation.");
  const double depth = f.DepthBelowMm(c.B);
  out.values.push_back(
    { "proximalSiteToFlowDividerLength", c.sBif + depth - c.sSite, "mm",
      "proximal site to the flow divider (where the aortic lumen divides" +
        (f.found ? ", " + FormatNumber(depth, 1) + " mm below the aortic bifurcation" : std::string()) +
        "), along the aortic centerline and the distal aorta's axis",
      "aorta", c.sSite });
  for (int side = 0; side < 2; ++side)
    out.values.push_back({ std::string(Side(side)) + "IliacLengthFromFlowDivider",
                           c.internalIliacAbscissa[side] - f.iliacAbscissaMm[side], "mm",
                           "flow divider to the internal iliac origin, along the iliac centerline (the length a "
                           "limb can seal in)",
                           c.iliac[side]->name, f.iliacAbscissaMm[side] });
}

/// β (neck against aneurysm axis), α (suprarenal against neck axis) and the neck's conicity.
void MeasureNeckAngles(const MeasureContext& c, double sNeckEnd, const RingDiameters& a, Measurements& out)
{
  const Centerline& aorta = c.tree.aorta;
  const double sSite = c.sSite;
  const double neckAxisLength =
    std::max(5.0, std::min(secondDiameterDepthMm, std::isfinite(sNeckEnd) ? sNeckEnd - sSite : secondDiameterDepthMm));
  // On the outer wall's centroids where it was traced (an eccentric thrombus moves the lumen's
  // centerline off the vessel's axis), else on the centerline.
  const auto axis = [&](double s) { return OuterAxisPoint(c.wall, aorta, s); };
  const Eigen::Vector3d neckAxis = axis(sSite + neckAxisLength) - axis(sSite);
  double beta = nan;
  if (std::isfinite(sNeckEnd) && (c.B - axis(sNeckEnd)).norm() > 10.0)
    beta = AngleDeg(neckAxis, c.B - axis(sNeckEnd));
  out.values.push_back({ "neckAngleBeta", beta, "deg",
                         "infrarenal angulation: neck axis (chord over the first " + FormatNumber(neckAxisLength) +
                           " mm below the site) against the aneurysm axis (chord from the neck's end to the "
                           "bifurcation)",
                         "aorta", sSite });
  const double suprarenalLength = std::min(30.0, sSite);
  double alpha = nan;
  if (suprarenalLength >= 10.0)
    alpha = AngleDeg(axis(sSite) - axis(sSite - suprarenalLength), neckAxis);
  else
    out.warnings.push_back("The scan covers " + FormatNumber(sSite) +
                           " mm of aorta above the proximal site (at least 10 mm needed); neckAngleAlpha is not "
                           "measured.");
  out.values.push_back({ "neckAngleAlpha", alpha, "deg",
                         "suprarenal angulation: suprarenal axis (chord over " + FormatNumber(suprarenalLength) +
                           " mm above the site) against the neck axis",
                         "aorta", sSite - suprarenalLength });
  const double aOuter = out.Value("proximalNeckDiameter"), bOuter = out.Value("neckDiameter15mm");
  const bool outer = std::isfinite(aOuter) && std::isfinite(bOuter);
  Measurement conicity{ "neckConicity",
                        outer ? 100.0 * (bOuter - aOuter) / aOuter
                              : 100.0 * (out.Value("neckLumenDiameter15mm") - a.meanMm) / a.meanMm,
                        "%",
                        "(b − a) / a over the first 15 mm of the neck; positive: the neck widens downward (reverse "
                        "taper)",
                        "aorta",
                        sSite };
  conicity.wall = outer ? "outer" : "lumen";
  out.values.push_back(conicity);
}

/// Each iliac's tortuosity, then each external iliac's smallest inscribed diameter (access).
void MeasureIliacAccess(const MeasureContext& c, const double iliacOffset[2], Measurements& out)
{
  for (int side = 0; side < 2; ++side)
  {
    const Centerline& iliac = *c.iliac[side];
    const double chord = (iliac.points.row(iliac.Size() - 1).transpose() - c.B).norm();
    const double length = iliac.LengthMm() + iliacOffset[side];
    out.values.push_back({ std::string(Side(side)) + "IliacTortuosity", chord > 1.0 ? length / chord : nan, "ratio",
                           "iliac centerline length / straight distance, from the aortic bifurcation to the "
                           "centerline's distal end in the scan (1 = straight)",
                           iliac.name, 0.0 });
  }
  for (int side = 0; side < 2; ++side)
  {
    const Centerline& iliac = *c.iliac[side];
    const double from = c.internalIliacAbscissa[side] + 10.0, to = iliac.LengthMm() - 10.0;
    double smallest = nan, where = nan;
    if (std::isfinite(from) && to - from >= 10.0)
      for (Eigen::Index i = 0; i < iliac.Size(); ++i)
        if (iliac.abscissaMm[i] >= from && iliac.abscissaMm[i] <= to && !(2 * iliac.radiusMm[i] >= smallest))
        {
          smallest = 2 * iliac.radiusMm[i];
          where = iliac.abscissaMm[i];
        }
    out.values.push_back({ std::string(Side(side)) + "AccessMinDiameter", smallest, "mm",
                           "smallest inscribed-sphere diameter of the external iliac, 10 mm below the internal iliac "
                           "origin to 10 mm before the centerline's end in the scan (the delivery system's path), "
                           "lumen",
                           iliac.name, where });
    out.values.back().wall = "lumen";
  }
}

/// Sets the values called one of `names` to NaN (not measured); returns their names, comma-separated.
std::string LeaveOut(const std::vector<std::string>& names, Measurements& out)
{
  std::string list;
  for (Measurement& m : out.values)
    if (std::find(names.begin(), names.end(), m.name) != names.end())
    {
      m.value = m.minMm = m.maxMm = m.areaMm = nan;
      list += (list.empty() ? "" : ", ") + m.name;
    }
  return list;
}

/// A partial plan (CenterlineTree::iliacCoverageMm): on an iliac the scan cuts short, the values
/// that need more of it than the scan holds are NaN, with one warning naming the coverage. The
/// landing zone's diameters need its internal iliac origin in view; the iliac's length needs
/// that origin where the axes meet, hence the internal iliac's own axis, which the scan cuts (on
/// AVT D4 cut 40 mm below the bifurcation it read 57.8 mm for the whole scan's 53.1 mm); the
/// tortuosity and the access diameter need the external iliac down to the groin;
/// B — hence the site-to-bifurcation length and β, whose aneurysm axis ends at B — needs
/// BifurcationIliacReachMm of each iliac (VesselOrigins.h).
void LeaveOutWhatTheScanDoesNotHold(const MeasureContext& c, Measurements& out)
{
  for (int side = 0; side < 2; ++side)
  {
    const double coverage = c.tree.iliacCoverageMm[side];
    if (!std::isfinite(coverage))
      continue;
    const std::string s = Side(side);
    std::vector<std::string> names{ s + "IliacLength", s + "IliacLengthFromFlowDivider", s + "IliacTortuosity",
                                    s + "AccessMinDiameter" };
    if (!std::isfinite(c.internalIliacAbscissa[side]))
      names.insert(names.begin(), { s + "IliacLumenDiameter", s + "IliacDiameter" });
    if (coverage < BifurcationIliacReachMm)
      names.insert(names.begin(), { "proximalSiteToBifurcationLength", "neckAngleBeta" });
    const std::string list = LeaveOut(names, out);
    out.warnings.push_back("Partial plan: the scan ends " + FormatNumber(coverage, 1) + " mm below the aortic " +
                           "bifurcation along the " + s + " common iliac" +
                           (std::isfinite(c.internalIliacAbscissa[side]) ? "" : ", above its internal iliac origin") +
                           "; " + list + " need more of the " + s + " iliac than the scan holds and are not measured.");
  }
}

/// (e) and (f) where no internal iliac origin anchors the landing zone (in a scan that holds the
/// iliac: a partial plan's are left out above): the leg ran its default length (StentMesh.h), so
/// the zone was read at a level chosen by no anatomy — on the widened stretch past a cut-off
/// internal iliac, or on the external iliac. Both diameters are estimates; their definitions and
/// one warning per side say at which level they were read.
void MarkLandingZonesReadAtTheDefault(const MeasureContext& c, Measurements& out)
{
  for (int side = 0; side < 2; ++side)
  {
    const DiameterProfile& leg = out.profiles[std::size_t(1 + side)];
    if (std::isfinite(c.internalIliacAbscissa[side]) || leg.rings.empty())
      continue;
    const std::string s = Side(side);
    const double end = leg.rings.back().abscissaMm;
    // The leg ends 5 mm above where the common iliac narrows into its external iliac where it
    // does (StentMesh.cxx), else at its default length.
    const double narrowing = IliacNarrowingAbscissa(*c.iliac[side]);
    const std::string zone =
      FormatNumber(end - landingZoneMm) + " to " + FormatNumber(end) + " mm down the " + s + " iliac's centerline";
    const std::string level =
      std::isfinite(narrowing)
        ? "a landing zone above where the " + s + " iliac narrows into its external iliac (" + FormatNumber(narrowing) +
            " mm down it, taken for its division), " + zone + ", as no " + s + " internal iliac origin was found"
        : "the leg's default landing zone, " + zone + " (a " + FormatNumber(DefaultLegLengthMm, 0) +
            " mm leg), as no " + s + " internal iliac origin was found";
    std::string marked;
    int count = 0;
    for (Measurement& m : out.values)
      if ((m.name == s + "IliacLumenDiameter" || m.name == s + "IliacDiameter") && std::isfinite(m.value))
      {
        m.estimated = true;
        m.definition += "; estimated: read at " + level;
        marked += (marked.empty() ? "" : " and ") + m.name + " " + FormatNumber(m.value) + " mm";
        ++count;
      }
    if (!marked.empty())
      out.warnings.push_back(marked + (count > 1 ? " are" : " is") + " estimated: read at " + level +
                             (std::isfinite(narrowing)
                                ? " (a narrowing that is a stenosis would put it higher than the division)."
                                : " (not 5 mm above it); the common iliac may end above that level."));
  }
}

/// How much a tilt of (b)'s plane by SectionTiltDeg changes the lumen's diameter there, mm.
double BTiltChangeMm(const MeasureContext& c, const LabelImage& lumen)
{
  const double s = c.sSite + secondDiameterDepthMm;
  return TiltSensitivityMm(lumen, PositionAt(c.tree.aorta, s), TangentAt(c.tree.aorta, s), SectionTiltDeg);
}

/// (b) where no plane is the vessel's cross-section (SectionTilt.h): the lumen's mean diameter in
/// the plane ⊥ the aorta at (b)'s level changes by more than SectionTiltMaxMm when the plane is
/// tilted by SectionTiltDeg — a bend that is also the sac's shoulder, below a short angled neck.
/// The lumen and outer (b) and the conicity built on them are NaN, with one warning giving the
/// numbers. `change` is BTiltChangeMm, NaN (nothing checked) without the lumen mask or the site.
void LeaveOutBOnABend(double change, Measurements& out)
{
  if (!(out.Value("neckLumenDiameter15mm") > 0.0) || !(change > SectionTiltMaxMm))
    return;
  const std::string list = LeaveOut({ "neckLumenDiameter15mm", "neckDiameter15mm", "neckConicity" }, out);
  out.reverseTaperMm[1] = nan; // the outer (b) less (a): not measured with it
  out.warnings.push_back("(b) is not measured: 15 mm below the proximal site the lumen's diameter changes by " +
                         FormatNumber(change, 1) + " mm when the plane is tilted by " +
                         FormatNumber(SectionTiltDeg, 0) +
                         " degrees (a bend on the sac's shoulder below a short "
                         "angled neck), so no plane there is the vessel's cross-section; " +
                         list + " are left out.");
}

/// (b) in the lumen's narrowest plane (SectionTilt.h FindNarrowestSection): below a short
/// angled neck the smoothed centerline's direction at (b) runs up to 16° off the vessel's axis
/// (issue 32's sweep), and the ring's plane ⊥ it cuts the lumen obliquely, wide. Where the
/// narrowest plane through the ring's centre, within ObliqueSearchDeg, is narrower than the ring's
/// own plane by more than ObliqueExcessMm, the lumen and outer (b) (mean, area-equivalent) and the
/// reverse taper over 15 mm are scaled by the ratio of the two planes' mean diameters — an oblique
/// cut of a tube widens every concentric contour by the same factor — and their smallest and
/// largest diameters each by the ratio of the two planes' own (an oblique cut widens the long axis
/// only), with a warning. The diameter profile keeps the ring's own reading. Not where (b) is left
/// out on a bend (LeaveOutBOnABend, later; `bTiltChange` is its BTiltChangeMm).
void ReadBInTheNarrowestPlane(const MeasureContext& c, const LabelImage* lumen, double bTiltChange, Measurements& out)
{
  Measurement* lumenB = nullptr;
  for (Measurement& m : out.values)
    if (m.name == "neckLumenDiameter15mm")
      lumenB = &m;
  if (!lumen || !c.site.Known() || !lumenB || !(lumenB->value > 0.0) || bTiltChange > SectionTiltMaxMm)
    return;
  const double s = c.sSite + secondDiameterDepthMm;
  const NarrowestSection section =
    FindNarrowestSection(*lumen, c.trunk.At(s).centre, TangentAt(c.tree.aorta, s), ObliqueSearchDeg);
  if (!(section.givenPlaneMeanMm - section.meanMm > ObliqueExcessMm))
    return;
  const double ratio = section.meanMm / section.givenPlaneMeanMm;
  const double minRatio = section.minMm / section.givenPlaneMinMm, maxRatio = section.maxMm / section.givenPlaneMaxMm;
  const double aOuter = out.Value("proximalNeckDiameter");
  for (Measurement& m : out.values)
    if (m.name == "neckLumenDiameter15mm" || m.name == "neckDiameter15mm")
    {
      m.value *= ratio;
      m.minMm *= minRatio;
      m.maxMm *= maxRatio;
      m.areaMm *= ratio;
      m.definition += ", scaled to the lumen's narrowest plane through the ring's centre";
    }
  if (std::isfinite(out.reverseTaperMm[1]) && std::isfinite(aOuter))
    out.reverseTaperMm[1] = (out.reverseTaperMm[1] + aOuter) * ratio - aOuter;
  out.warnings.push_back("(b) is read in the lumen's narrowest plane: 15 mm below the proximal site the plane "
                         "perpendicular to the centerline cuts the lumen " +
                         FormatNumber(section.givenPlaneMeanMm - section.meanMm, 1) + " mm wider than a plane tilted " +
                         FormatNumber(section.tiltDeg, 1) +
                         " degrees from it (the centerline's direction on the bend below an angled neck), so (b)'s "
                         "diameters are scaled by " +
                         FormatNumber(ratio, 3) + " (the diameter profile keeps the ring's own reading).");
}

/// The site not known (ProximalSiteSource::None): every value measured from it is NaN — the neck's
/// diameters, length, angles and conicity, the site-to-bifurcation length, and the thrombus and
/// sac volumes and neck arcs that run from it — with one warning naming them. (c), (d) and the
/// iliac values stay: the stent surface they are read on starts on the abdominal aorta.
void LeaveOutWhatNeedsTheSite(const MeasureContext& c, Measurements& out)
{
  if (c.site.Known())
    return;
  const std::string list = LeaveOut(
    { "proximalNeckLumenDiameter", "neckLumenDiameter15mm", "proximalNeckDiameter", "neckDiameter15mm",
      "proximalNeckLength", "proximalSiteToBifurcationLength", "proximalSiteToFlowDividerLength", "neckAngleBeta",
      "neckAngleAlpha", "neckConicity", "thrombusVolume", "sacVolume", "neckThrombusArc", "neckCalcificationArc" },
    out);
  out.outerNeckEndMm = nan;
  out.reverseTaperMm = { nan, nan };
  out.warnings.push_back("The proximal implantation site is not known (no renal artery in view, no lowestRenalOstium "
                         "point): " +
                         list + " are not measured; (c), (d) and the iliac values are read below " +
                         FormatNumber(c.sBif - c.sSite, 0) + " mm above the aortic bifurcation along the aorta.");
}

} // namespace

const Measurement* Measurements::Find(const std::string& name) const
{
  for (const Measurement& m : values)
    if (m.name == name)
      return &m;
  return nullptr;
}

double Measurements::Value(const std::string& name) const
{
  const Measurement* m = Find(name);
  return m ? m->value : nan;
}

Measurements MeasureAnatomy(const CenterlineTree& tree,
                            const StentMesh& mesh,
                            const Points& V,
                            const ProximalSite& site,
                            const VesselWall* wall,
                            const LabelImage* lumen)
{
  Measurements out;
  out.site = site;
  out.profiles = MeasureRingDiameters(mesh, V);
  if (!site.warning.empty())
    out.warnings.push_back(site.warning);
  const AorticBifurcation bifurcation = FindAorticBifurcation(tree);
  out.bifurcationLps = bifurcation.lps;
  out.bifurcationAbscissaMm = bifurcation.abscissaMm;
  out.bifurcationGiven = bifurcation.given;
  for (int side = 0; side < 2; ++side)
    out.internalIliacOriginGiven[std::size_t(side)] =
      std::isfinite(tree.givenInternalIliacAbscissaMm[std::size_t(side)]);
  MeasureContext c{ tree,
                    site,
                    { &tree.rightIliac, &tree.leftIliac },
                    out.profiles[TrunkSegment],
                    wall,
                    bifurcation.lps,
                    site.abscissaMm,
                    bifurcation.abscissaMm,
                    { InternalIliacOriginAbscissa(tree, 0), InternalIliacOriginAbscissa(tree, 1) } };

  for (int side = 0; side < 2; ++side)
    if (std::isfinite(c.internalIliacAbscissa[side]))
      out.internalIliacOriginLps[side] = PositionAt(*c.iliac[side], c.internalIliacAbscissa[side]);

  if (lumen)
    out.flowDivider = FindFlowDivider(*lumen, tree);
  else
    out.flowDivider.reason = "no lumen mask was given";
  const RingDiameters a = MeasureNeckDiameters(c, out).first;
  const Eigen::Vector3d distalDirection = DistalDirection(c);
  const std::size_t widest = MeasureSacDiameters(c, lumen, distalDirection, out);
  for (int side = 0; side < 2; ++side)
    MeasureIliacLandingZone(c, side, out);
  WarnDistortedAorticRings(out);
  if (wall)
  {
    OuterWallLevels levels{ c.sSite, c.sBif, c.trunk.rings.back().abscissaMm, {}, {}, c.B, distalDirection };
    for (int side = 0; side < 2; ++side)
    {
      levels.landingToMm[side] = out.profiles[1 + side].rings.back().abscissaMm;
      levels.landingFromMm[side] = levels.landingToMm[side] - landingZoneMm;
    }
    MeasureOuterWall(*wall, levels, out);
  }
  else
    out.warnings.push_back("The outer wall was not traced: the outer-wall diameters (a)-(f) and the thrombus values "
                           "are not measured.");
  // How much a tilt of (b)'s plane changes the lumen's diameter: both (b) rules read it.
  const double bTiltChange = lumen && c.site.Known() ? BTiltChangeMm(c, *lumen) : nan;
  ReadBInTheNarrowestPlane(c, lumen, bTiltChange, out);
  // The neck's end on the outer wall where it was found (the IFU's and the truth's definition),
  // else on the lumen's rings.
  const double sLumenNeckEnd = FindNeckEnd(c, a, widest, out);
  const double sNeckEnd = std::isfinite(out.outerNeckEndMm) ? out.outerNeckEndMm : sLumenNeckEnd;
  double iliacOffset[2];
  MeasureLengths(c, sNeckEnd, iliacOffset, out);
  for (int side = 0; side < 2; ++side)
  {
    out.iliacStartBeyondBifurcationMm[side] = iliacOffset[side];
    out.internalIliacAbscissaMm[side] = c.internalIliacAbscissa[side];
  }
  MeasureFlowDividerLengths(c, out);
  MeasureNeckAngles(c, sNeckEnd, a, out);
  MeasureIliacAccess(c, iliacOffset, out);
  LeaveOutWhatTheScanDoesNotHold(c, out);
  MarkLandingZonesReadAtTheDefault(c, out);
  LeaveOutWhatNeedsTheSite(c, out);
  LeaveOutBOnABend(bTiltChange, out);
  return out;
}

} // namespace sgp
