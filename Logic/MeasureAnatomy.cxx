#include "MeasureAnatomy.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "Format.h"
#include "Median.h"

namespace sgp
{
namespace
{

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double radiansToDegrees = 57.29577951308232;
constexpr double neckDilationFactor = 1.10;    ///< the neck ends where the diameter exceeds (a) by 10 %
constexpr double secondDiameterDepthMm = 15.0; ///< (b), paper section 2.2
constexpr double landingZoneMm = 15.0;         ///< distal iliac landing zone for (e)/(f)
constexpr double bifurcationSnapMm = 10.0;     ///< axes meeting farther from the junction are not trusted

double AngleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return std::atan2(a.cross(b).norm(), a.dot(b)) * radiansToDegrees;
}

/// The point nearest to the lines (p_i, unit d_i) in the least-squares sense.
Point3 NearestToLines(const std::vector<std::pair<Point3, Eigen::Vector3d>>& lines)
{
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (const auto& [p, d] : lines)
  {
    const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - d * d.transpose();
    A += P;
    b += P * p;
  }
  return A.ldlt().solve(b);
}

/// The chord of `c` from arc length `from` to `to` (clamped to the centerline) as a line.
std::pair<Point3, Eigen::Vector3d> Chord(const Centerline& c, double from, double to)
{
  const Point3 a = PositionAt(c, from), b = PositionAt(c, to);
  return { b, (b - a).normalized() };
}

/// Where the internal iliac leaves the iliac, as an abscissa along the iliac: like the aortic
/// bifurcation, the point nearest the axes of the common iliac above the skeleton's junction
/// (chord 25…5 mm before it), the external iliac below it (5…25 mm after) and the internal iliac
/// (its centerline 5…20 mm from the junction), projected onto the iliac's centerline — the
/// junction itself lies distal to it, inside the merged cross-section. Falls back to the junction
/// when a chord is too short or the axes meet farther than 10 mm from it.
double InternalIliacOrigin(const Centerline& iliac, const Centerline* internal, double junction)
{
  if (!internal || internal->LengthMm() < 20.0 || junction < 10.0 || iliac.LengthMm() - junction < 10.0)
    return junction;
  const std::vector<std::pair<Point3, Eigen::Vector3d>> axes = {
    Chord(iliac, std::max(0.0, junction - 25.0), junction - 5.0),
    Chord(iliac, junction + 5.0, std::min(iliac.LengthMm(), junction + 25.0)), Chord(*internal, 5.0, 20.0)
  };
  const Point3 origin = NearestToLines(axes);
  const Point3 atJunction = PositionAt(iliac, junction);
  if (!origin.allFinite() || (origin - atJunction).norm() > bifurcationSnapMm)
    return junction;
  return ProjectOntoCenterline(iliac, origin);
}

Measurement Diameter(const std::string& name,
                     const RingDiameters& ring,
                     const std::string& vessel,
                     const std::string& definition)
{
  Measurement m{ name, ring.meanMm, "mm", definition, vessel, ring.abscissaMm };
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
                            const ProximalSite& site)
{
  Measurements out;
  out.site = site;
  out.profiles = MeasureRingDiameters(mesh, V);
  if (!site.warning.empty())
    out.warnings.push_back(site.warning);
  const Centerline& aorta = tree.aorta;
  const Centerline* iliac[2] = { &tree.rightIliac, &tree.leftIliac };
  const DiameterProfile& trunk = out.profiles[TrunkSegment];
  const double L = aorta.LengthMm();
  const Point3 junction = aorta.points.row(aorta.Size() - 1).transpose();

  // The aortic bifurcation B where the axes meet.
  std::vector<std::pair<Point3, Eigen::Vector3d>> axes = { Chord(aorta, L - 25.0, L - 5.0) };
  double internalIliacAbscissa[2] = { nan, nan };
  for (int side = 0; side < 2; ++side)
  {
    if (const Landmark* origin = tree.FindLandmark(std::string(Side(side)) + "IliacBifurcation"))
      internalIliacAbscissa[side] =
        InternalIliacOrigin(*iliac[side], tree.FindVessel(std::string(Side(side)) + "InternalIliac"),
                            ProjectOntoCenterline(*iliac[side], origin->lps));
    const double end = std::isfinite(internalIliacAbscissa[side]) ? std::min(30.0, internalIliacAbscissa[side] - 5.0)
                                                                  : std::min(30.0, iliac[side]->LengthMm());
    const double from = std::min(10.0, 0.5 * end);
    if ((PositionAt(*iliac[side], end) - PositionAt(*iliac[side], from)).norm() > 1.0)
      axes.push_back(Chord(*iliac[side], from, end));
  }
  Point3 B = axes.size() == 3 ? NearestToLines(axes) : junction;
  if (!B.allFinite() || (B - junction).norm() > bifurcationSnapMm)
    B = junction;
  out.bifurcationLps = B;
  const Eigen::Vector3d endTangent = TangentAt(aorta, L);
  out.bifurcationAbscissaMm = L + (B - junction).dot(endTangent);
  const double sSite = site.abscissaMm, sBif = out.bifurcationAbscissaMm;

  // (a), (b).
  std::vector<Measurement>& v = out.values;
  if (!trunk.rings.empty() && trunk.rings.front().abscissaMm > sSite + 1.0)
    out.warnings.push_back(
      "The fitted trunk starts " + FormatNumber(trunk.rings.front().abscissaMm - sSite) +
      " mm below the proximal implantation site (proximalStartMm); (a) is read at its first ring.");
  const RingDiameters a = trunk.At(sSite);
  v.push_back(Diameter("proximalNeckDiameter", a, "aorta",
                       "(a) mean ring diameter of the fitted surface at the proximal implantation site (" +
                         std::string(ToString(site.source)) + "), lumen"));
  const RingDiameters b = trunk.At(sSite + secondDiameterDepthMm);
  v.push_back(Diameter("neckDiameter15mm", b, "aorta",
                       "(b) mean ring diameter 15 mm below the proximal site along the aortic centerline, lumen"));

  // (c): the widest ring between the site and B; (d): the narrowest below it.
  std::size_t widest = 0;
  for (std::size_t k = 0; k < trunk.rings.size(); ++k)
    if (trunk.rings[k].abscissaMm >= sSite - 1e-9 && trunk.rings[k].abscissaMm <= sBif &&
        trunk.rings[k].meanMm > trunk.rings[widest].meanMm)
      widest = k;
  v.push_back(Diameter("maxAneurysmDiameter", trunk.rings[widest], "aorta",
                       "(c) largest mean ring diameter between the proximal site and the aortic bifurcation, lumen"));
  std::size_t narrowest = widest;
  for (std::size_t k = widest; k < trunk.rings.size(); ++k)
    if (trunk.rings[k].meanMm < trunk.rings[narrowest].meanMm)
      narrowest = k;
  v.push_back(Diameter("distalNeckMinDiameter", trunk.rings[narrowest], "aorta",
                       "(d) smallest mean ring diameter between (c) and the trunk's last ring (3 stent radii above the "
                       "flow divider), lumen"));

  // (e), (f): the distal landing zone of each leg, from the rings that kept their shape; where
  // the fit collapsed there (a tortuous iliac can fold the rings), the centerline's inscribed
  // diameter instead, with a warning.
  for (int side = 0; side < 2; ++side)
  {
    const DiameterProfile& leg = out.profiles[1 + side];
    const Centerline& vessel = *iliac[side];
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
    const std::string name = std::string(Side(side)) + "IliacDiameter";
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
    v.push_back(Diameter(name, zone, leg.vessel, definition));
  }
  // (a)–(d) read one ring each: say so when it is distorted.
  for (const Measurement& m : v)
    if (m.vessel == "aorta" && m.minMm < 0.5 * m.value)
      out.warnings.push_back(m.name + ": the ring at " + FormatNumber(m.abscissaMm) +
                             " mm along the aorta is distorted (smallest diameter " + FormatNumber(m.minMm) +
                             " mm, mean " + FormatNumber(m.value) + " mm); check the fit there.");

  // Lengths.
  const double aValue = a.meanMm;
  double sNeckEnd = nan;
  for (std::size_t k = 1; k <= widest && k < trunk.rings.size(); ++k)
  {
    // The ring's smallest diameter (the minor axis where a ring cuts a bend obliquely) must
    // exceed the threshold: near an angulated neck's bend the mean of a tilted ring grows before
    // the aorta does.
    const RingDiameters &p = trunk.rings[k - 1], &q = trunk.rings[k];
    const double threshold = neckDilationFactor * aValue;
    if (q.abscissaMm > sSite && q.minMm > threshold)
    {
      const double t = q.minMm > p.minMm ? std::clamp((threshold - p.minMm) / (q.minMm - p.minMm), 0.0, 1.0) : 1.0;
      sNeckEnd = std::max(sSite, p.abscissaMm + t * (q.abscissaMm - p.abscissaMm));
      break;
    }
  }
  if (!std::isfinite(sNeckEnd))
    out.warnings.push_back("The aorta never widens 10 % beyond (a) below the proximal site; proximalNeckLength is "
                           "not measured (no aneurysm between the site and the bifurcation?).");
  v.push_back(
    { "proximalNeckLength", sNeckEnd - sSite, "mm",
      "proximal site to where the ring's smallest diameter first exceeds (a) by 10 %, along the aortic centerline",
      "aorta", sSite });
  v.push_back({ "proximalSiteToBifurcationLength", sBif - sSite, "mm",
                "proximal site to the aortic bifurcation (where the aortic and common iliac axes meet), along the "
                "aortic centerline",
                "aorta", sSite });
  double iliacOffset[2];
  for (int side = 0; side < 2; ++side)
  {
    const Point3 start = iliac[side]->points.row(0).transpose();
    iliacOffset[side] = (start - B).dot(TangentAt(*iliac[side], 0.0)); // B to the iliac centerline's start
    const double length = internalIliacAbscissa[side] + iliacOffset[side];
    if (!std::isfinite(length))
      out.warnings.push_back(std::string("No ") + Side(side) +
                             " internal iliac artery was found; the iliac length is not measured.");
    v.push_back({ std::string(Side(side)) + "IliacLength", length, "mm",
                  "aortic bifurcation to the internal iliac origin, along the iliac centerline", iliac[side]->name,
                  0.0 });
  }

  // Angles and shape.
  const double neckAxisLength =
    std::max(5.0, std::min(secondDiameterDepthMm, std::isfinite(sNeckEnd) ? sNeckEnd - sSite : secondDiameterDepthMm));
  const Eigen::Vector3d neckAxis = PositionAt(aorta, sSite + neckAxisLength) - PositionAt(aorta, sSite);
  double beta = nan;
  if (std::isfinite(sNeckEnd) && (B - PositionAt(aorta, sNeckEnd)).norm() > 10.0)
    beta = AngleDeg(neckAxis, B - PositionAt(aorta, sNeckEnd));
  v.push_back({ "neckAngleBeta", beta, "deg",
                "infrarenal angulation: neck axis (chord over the first " + FormatNumber(neckAxisLength) +
                  " mm below the site) against the aneurysm axis (chord from the neck's end to the bifurcation)",
                "aorta", sSite });
  const double suprarenalLength = std::min(30.0, sSite);
  double alpha = nan;
  if (suprarenalLength >= 10.0)
    alpha = AngleDeg(PositionAt(aorta, sSite) - PositionAt(aorta, sSite - suprarenalLength), neckAxis);
  else
    out.warnings.push_back("The scan covers " + FormatNumber(sSite) +
                           " mm of aorta above the proximal site (at least 10 mm needed); neckAngleAlpha is not "
                           "measured.");
  v.push_back({ "neckAngleAlpha", alpha, "deg",
                "suprarenal angulation: suprarenal axis (chord over " + FormatNumber(suprarenalLength) +
                  " mm above the site) against the neck axis",
                "aorta", sSite - suprarenalLength });
  v.push_back({ "neckConicity", 100.0 * (b.meanMm - aValue) / aValue, "%",
                "(b − a) / a over the first 15 mm of the neck; positive: the neck widens downward (reverse taper)",
                "aorta", sSite });
  for (int side = 0; side < 2; ++side)
  {
    const Centerline& c = *iliac[side];
    const double chord = (c.points.row(c.Size() - 1).transpose() - B).norm();
    const double length = c.LengthMm() + iliacOffset[side];
    v.push_back({ std::string(Side(side)) + "IliacTortuosity", chord > 1.0 ? length / chord : nan, "ratio",
                  "iliac centerline length / straight distance, from the aortic bifurcation to the centerline's distal "
                  "end in the scan (1 = straight)",
                  c.name, 0.0 });
  }
  for (int side = 0; side < 2; ++side)
  {
    const Centerline& c = *iliac[side];
    const double from = internalIliacAbscissa[side] + 10.0, to = c.LengthMm() - 10.0;
    double smallest = nan, where = nan;
    if (std::isfinite(from) && to - from >= 10.0)
      for (Eigen::Index i = 0; i < c.Size(); ++i)
        if (c.abscissaMm[i] >= from && c.abscissaMm[i] <= to && !(2 * c.radiusMm[i] >= smallest))
        {
          smallest = 2 * c.radiusMm[i];
          where = c.abscissaMm[i];
        }
    v.push_back({ std::string(Side(side)) + "AccessMinDiameter", smallest, "mm",
                  "smallest inscribed-sphere diameter of the external iliac, 10 mm below the internal iliac origin to "
                  "10 mm before the centerline's end in the scan (the delivery system's path), lumen",
                  c.name, where });
  }
  return out;
}

} // namespace sgp
