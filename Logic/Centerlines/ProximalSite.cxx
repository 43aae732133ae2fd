#include "Centerlines/ProximalSite.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <vector>

#include <Eigen/Geometry>

#include "Common/Errors.h"
#include "Common/Format.h"
#include "Common/Median.h"
#include "Common/PrincipalLine.h"
#include "Common/SampleCt.h"
#include "Segmentation/LumenGrowthSteps.h"

namespace sgp
{
namespace
{

/// How far from the aortic centerline a user's ostium point may lie: an aortic radius plus a
/// margin (the widest suprarenal aorta is ~15 mm in radius), mm.
constexpr double maximumLandmarkDistanceMm = 30.0;
/// The renal's axis is fitted to its centerline from this far outside the aortic wall…
constexpr double renalFitStartMm = 1.0;
/// …to this far (the first, straight part of a renal artery), mm.
constexpr double renalFitEndMm = 16.0;
/// Renal arteries leave the aorta at 30–90°; a smaller fitted angle is noise, clamped here.
constexpr double minimumRenalSinAngle = 0.5;
/// The parent's axis at a branch is the line fitted to its centerline within this many of its
/// radii of the junction, clamped to [8, 20] mm: the skeleton bends toward the branch over about
/// the branch's diameter there, and its local tangent tilted by it (up to ~9° measured on a
/// 21 mm neck) moves an ostium a parent radius away by 1.5 mm along the aorta.
constexpr double parentAxisWindowRadii = 1.5;
constexpr double parentAxisWindowMinMm = 8.0, parentAxisWindowMaxMm = 20.0;
/// The renal's walls are profiled from this far outside the aortic wall (nearer, the mouth's
/// blurred edge into the aorta's lumen lies on the profile), mm.
constexpr double mouthProfileStartMm = 3.0;
/// The tissue level around the renal: this far beyond its inscribed radius, on both sides, mm
/// (beyond the edge's blur, short of the next structure).
constexpr double mouthTissueFromMm = 2.5, mouthTissueToMm = 4.5;
/// A profile whose lumen is not this much brighter than its tissue is not read, HU.
constexpr double minimumMouthContrastHu = 100.0;

/// The least-squares line through the parent's centerline points within `halfWidthMm` of abscissa
/// `s`: its centroid, the centroid's abscissa, its unit direction (downstream) and the median radius.
struct AxisLine
{
  Point3 centroid = Point3::Zero();
  double abscissaMm = 0.0;
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
  double radiusMm = 0.0; ///< the median inscribed radius there (the junction's is widened by the branch's mouth)
};

AxisLine FitAxisLine(const Centerline& parent, double s, double halfWidthMm)
{
  std::vector<Eigen::Index> near;
  for (Eigen::Index i = 0; i < parent.Size(); ++i)
    if (std::abs(parent.abscissaMm[i] - s) <= halfWidthMm)
      near.push_back(i);
  AxisLine line;
  if (near.size() < 3) // a centerline too short (or too coarse) for a fit: its local tangent
  {
    line.centroid = PositionAt(parent, s);
    line.abscissaMm = s;
    line.direction = TangentAt(parent, s);
    line.radiusMm = RadiusAt(parent, s);
    return line;
  }
  std::vector<double> radii;
  for (const Eigen::Index i : near)
    radii.push_back(parent.radiusMm[i]);
  line.radiusMm = Median(radii);
  std::vector<Point3> points;
  for (const Eigen::Index i : near)
  {
    points.push_back(parent.points.row(i).transpose());
    line.abscissaMm += parent.abscissaMm[i];
  }
  line.abscissaMm /= double(near.size());
  std::tie(line.centroid, line.direction) = PrincipalLine(points);
  const Eigen::Vector3d downstream = parent.points.row(near.back()) - parent.points.row(near.front());
  if (line.direction.dot(downstream) < 0.0)
    line.direction = -line.direction;
  return line;
}

/// No renal artery and no point (the file comment, sources 3 and 4): the top of the aorta where
/// the aorta in view reaches no higher than MaximumRenalHeightMm above its bifurcation (its last
/// point) and passes over no arch; else the site is not known.
void PlaceWithoutRenals(const CenterlineTree& tree, ProximalSite& site)
{
  const Centerline& aorta = tree.aorta;
  const Point3 top = aorta.points.row(0).transpose();
  const Point3 bifurcation = aorta.points.row(aorta.Size() - 1).transpose();
  const double topHeight = top.z() - bifurcation.z();
  const bool arch = tree.FindVessel("ascendingAorta") != nullptr;
  std::string extent;
  bool cut = false;
  if (std::isfinite(tree.scanHighestZMm))
  {
    // The aorta's top within its radius (and a voxel or two) of the scan's superior border:
    // the scan is cut there, and the renal arteries may lie above it.
    cut = tree.scanHighestZMm - top.z() <= aorta.radiusMm[0] + 3.0;
    extent = " The scan spans z " + FormatNumber(tree.scanLowestZMm, 1) + " to " +
             FormatNumber(tree.scanHighestZMm, 1) + " mm (LPS, inferior to superior); the aorta " +
             (cut ? "runs out of its superior border" : "ends inside it") + " at z " + FormatNumber(top.z(), 1) +
             " mm, " + FormatNumber(aorta.LengthMm(), 0) + " mm of centerline above the bifurcation.";
  }
  if (!arch && topHeight <= MaximumRenalHeightMm)
  {
    site.source = ProximalSiteSource::Top;
    site.abscissaMm = 0.0;
    site.warning =
      "No renal artery was found on the aortic centerline and --lowestRenalOstium was not given; the "
      "aorta in view reaches " +
      FormatNumber(topHeight, 1) + " mm above its bifurcation (at most " + FormatNumber(MaximumRenalHeightMm, 0) +
      " mm, as high as renal arteries are looked for), so the scan is taken to start near the renal "
      "level: the proximal implantation site is the top of the aortic centerline (" +
      FormatPoint(top) + " mm LPS), and the neck values are measured from there." + extent +
      (cut ? " A scan that begins below the renal arteries shows none." : "") + " Place the lowestRenalOstium point.";
    return;
  }
  // The aorta goes on past the renal level (into the chest): its top is not the site. The stent
  // surface starts MaximumRenalHeightMm above the bifurcation, on the abdominal aorta.
  site.source = ProximalSiteSource::None;
  site.abscissaMm = 0.0;
  for (Eigen::Index i = 0; i < aorta.Size(); ++i)
    if (aorta.points(i, 2) - bifurcation.z() <= MaximumRenalHeightMm)
    {
      site.abscissaMm = aorta.abscissaMm[i];
      break;
    }
  site.warning = "No renal artery was found on the aortic centerline and --lowestRenalOstium was not given, and the "
                 "aorta in view " +
                 std::string(arch ? "runs over the arch into the chest"
                                  : "reaches " + FormatNumber(topHeight, 1) + " mm above its bifurcation") +
                 ", past where renal arteries leave (at most " + FormatNumber(MaximumRenalHeightMm, 0) +
                 " mm above it): the proximal implantation site is not known, so the neck values (a), (b), the neck "
                 "length and angles, the site-to-bifurcation length and the deployment target are not measured, and "
                 "no graft is simulated." +
                 extent + " Place the lowestRenalOstium point at the lower edge of the lowest renal artery's ostium.";
}

/// A branch's axis at its mouth (FindBranchOstium's first steps): the parent's axis line there and
/// the branch's chord fitted to its centerline renalFitStartMm…renalFitEndMm outside the wall.
struct BranchAxis
{
  bool found = false;
  AxisLine parent;                              ///< the parent's axis at the junction
  Point3 centroid = Point3::Zero();             ///< of the branch's fitted points
  Eigen::Vector3d d = Eigen::Vector3d::UnitX(); ///< the branch's direction, away from the parent
  double radiusMm = 0.0;                        ///< the branch's median inscribed radius there
  std::vector<Point3> fit;                      ///< the fitted points
  std::vector<double> outsideMm;                ///< each one's distance outside the parent's wall
};

BranchAxis FitBranchAxis(const Centerline& parent, const Centerline& branch)
{
  BranchAxis b;
  const Point3 junction = branch.points.row(0).transpose();
  const double sJunction = ProjectOntoCenterline(parent, junction);
  b.parent = FitAxisLine(
    parent, sJunction,
    std::clamp(parentAxisWindowRadii * RadiusAt(parent, sJunction), parentAxisWindowMinMm, parentAxisWindowMaxMm));
  const Point3 a = b.parent.centroid;
  const Eigen::Vector3d T = b.parent.direction;
  std::vector<double> radii;
  for (Eigen::Index i = 0; i < branch.Size(); ++i)
  {
    const Point3 p = branch.points.row(i).transpose();
    const Eigen::Vector3d w = p - a;
    const double outside = (w - w.dot(T) * T).norm() - b.parent.radiusMm;
    if (outside >= renalFitStartMm && outside <= renalFitEndMm)
    {
      b.fit.push_back(p);
      b.outsideMm.push_back(outside);
      radii.push_back(branch.radiusMm[i]);
    }
    if (outside > renalFitEndMm)
      break;
  }
  if (b.fit.size() < 3)
    return b;
  b.found = true;
  b.radiusMm = Median(radii);
  b.d = (b.fit.back() - b.fit.front()).normalized();
  for (const Point3& p : b.fit)
    b.centroid += p;
  b.centroid /= static_cast<double>(b.fit.size());
  return b;
}

/// Where, from `q` along `n`, the CT first falls below `threshold` HU (linear between samples),
/// mm; NaN when it does not within `reachMm`.
double CrossingMm(const CtSampler& ct, const Point3& q, const Eigen::Vector3d& n, double threshold, double reachMm)
{
  constexpr double stepMm = 0.05;
  double previous = ct(q);
  for (double t = stepMm; t <= reachMm; t += stepMm)
  {
    const double hu = ct(q + t * n);
    if (hu < threshold)
      return previous > hu ? t - stepMm * (threshold - hu) / (previous - hu) : t;
    previous = hu;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

} // namespace

BranchOstium FindBranchOstium(const Centerline& parent, const Centerline& branch)
{
  BranchOstium ostium;
  const BranchAxis b = FitBranchAxis(parent, branch);
  if (!b.found)
    return ostium;
  const Point3 a = b.parent.centroid;
  const Eigen::Vector3d T = b.parent.direction;
  const double parentRadius = b.parent.radiusMm;
  const Eigen::Vector3d d = b.d;
  // Walk the fitted axis inward from the centroid to the aortic wall (radial distance = radius):
  // |w⊥ + t d⊥|² = r² with w = centroid − a, ⊥ = perpendicular to T.
  const Eigen::Vector3d w = b.centroid - a;
  const Eigen::Vector3d wPerp = w - w.dot(T) * T, dPerp = d - d.dot(T) * T;
  const double qa = dPerp.squaredNorm(), qb = 2 * wPerp.dot(dPerp),
               qc = wPerp.squaredNorm() - parentRadius * parentRadius;
  const double discriminant = qb * qb - 4 * qa * qc;
  double t = 0.0;
  if (qa > 1e-12 && discriminant >= 0.0)
    t = (-qb + std::sqrt(discriminant)) / (2 * qa); // the near wall (both roots lie inward, t < 0)
  const Point3 ostiumCentre = b.centroid + t * d;
  const double sinAngle = std::max(d.cross(T).norm(), minimumRenalSinAngle);
  const double up = std::isfinite(branch.mouthWallMm[0]) ? branch.mouthWallMm[0] : b.radiusMm;
  const double down = std::isfinite(branch.mouthWallMm[1]) ? branch.mouthWallMm[1] : b.radiusMm;
  ostium.found = true;
  ostium.radiusMm = b.radiusMm;
  ostium.centreAbscissaMm = b.parent.abscissaMm + (ostiumCentre - a).dot(T);
  ostium.upperAbscissaMm = ostium.centreAbscissaMm - up / sinAngle;
  ostium.lowerAbscissaMm = ostium.centreAbscissaMm + down / sinAngle;
  return ostium;
}

void MeasureRenalMouthWalls(CenterlineTree& tree, const CtImage& ct)
{
  const CtSampler sample(ct, -1000.0f);
  const double coarsest = std::max({ ct.GetSpacing()[0], ct.GetSpacing()[1], ct.GetSpacing()[2] });
  for (Centerline& renal : tree.sideBranches)
  {
    if (renal.name != "rightRenal" && renal.name != "leftRenal")
      continue;
    renal.mouthWallMm = { std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN() };
    renal.mouthEdgeAgreementMm = std::numeric_limits<double>::quiet_NaN();
    const BranchAxis b = FitBranchAxis(tree.aorta, renal);
    if (!b.found)
      continue;
    const Eigen::Vector3d T = b.parent.direction;
    const Eigen::Vector3d alongParent = T - T.dot(b.d) * b.d;
    if (alongParent.norm() < minimumRenalSinAngle)
      continue; // a branch running along its parent: no upstream and downstream wall to profile
    const Eigen::Vector3d n = alongParent.normalized(); // downstream along the parent, across the branch
    const double rho = b.radiusMm;
    std::array<std::vector<double>, 2> walls;
    for (std::size_t i = 0; i < b.fit.size(); ++i)
    {
      if (b.outsideMm[i] < mouthProfileStartMm)
        continue;                                                           // the mouth's blur into the aorta's lumen
      const Point3 q = b.centroid + (b.fit[i] - b.centroid).dot(b.d) * b.d; // on the fitted axis
      std::vector<double> core, tissue;
      for (double t = -0.5 * rho; t <= 0.5 * rho; t += 0.25)
        core.push_back(sample(q + t * n));
      for (double t = rho + mouthTissueFromMm; t <= rho + mouthTissueToMm; t += 0.25)
      {
        tissue.push_back(sample(q + t * n));
        tissue.push_back(sample(q - t * n));
      }
      const double lumenHu = Median(core), tissueHu = Median(tissue);
      if (lumenHu - tissueHu < minimumMouthContrastHu)
        continue;
      // The lumen's own edge rule (GrowLumenRegion.h step 5): half-way to the tissue, raised to the
      // soft tissue of a wall (lumen_growth::LumenBorderHu) — half-way to the fat beyond a wall
      // put the walls 0.2–0.3 mm wide on the wall phantoms.
      const double edgeHu = 0.5 * (lumenHu + lumen_growth::LumenBorderHu(tissueHu));
      const double reach = 2.0 * rho + mouthTissueFromMm;
      const auto wall = [&](const Eigen::Vector3d& along) { return CrossingMm(sample, q, along, edgeHu, reach); };
      const double up = wall(-n);
      const double down = wall(n);
      if (std::isfinite(up) && std::isfinite(down))
      {
        walls[0].push_back(up);
        walls[1].push_back(down);
      }
    }
    if (walls[0].size() < 3)
      continue;
    const double up = Median(walls[0]), down = Median(walls[1]);
    // A plausible mouth: its width within half and twice the inscribed diameter (and a voxel).
    const double width = up + down;
    if (width < rho || width > 4.0 * rho + 2.0)
      continue;
    // The lumen's reading stands where the CT's lies within half a voxel of it (both edges): every
    // neck value hangs from the site, and below a short angled neck (b) moved by up to 4 mm for a
    // 0.2 mm shift of the site (Issue32.BJustBelowAKinkedNeck…).
    const BranchOstium asRead = FindBranchOstium(tree.aorta, renal);
    renal.mouthWallMm = { up, down };
    const BranchOstium onCt = FindBranchOstium(tree.aorta, renal);
    const double difference = std::max(std::abs(onCt.lowerAbscissaMm - asRead.lowerAbscissaMm),
                                       std::abs(onCt.upperAbscissaMm - asRead.upperAbscissaMm));
    if (difference <= 0.5 * coarsest)
    {
      renal.mouthWallMm = { std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN() };
      renal.mouthEdgeAgreementMm = difference;
    }
  }
}

OstiumEdgeUncertainty EdgeUncertainty(const Centerline& branch, double largestSpacingMm)
{
  const double spacing = std::isfinite(largestSpacingMm) ? largestSpacingMm : 1.0;
  OstiumEdgeUncertainty u;
  if (std::isfinite(branch.mouthWallMm[0]) && std::isfinite(branch.mouthWallMm[1]))
  {
    u.mm = std::max(1.0, 0.5 * spacing);
    u.why = "its walls read on the CT at the lumen's edge level, on " + FormatNumber(spacing, 1) + " mm voxels";
  }
  else if (std::isfinite(branch.mouthEdgeAgreementMm))
  {
    u.mm = std::max(1.0, 0.5 * spacing);
    u.why = "its radius read from the lumen's inscribed spheres, within " +
            FormatNumber(branch.mouthEdgeAgreementMm, 1) + " mm of its walls read on the CT, on " +
            FormatNumber(spacing, 1) + " mm voxels";
  }
  else
  {
    u.mm = std::max(1.0, spacing);
    u.why = "its radius read from the lumen's inscribed spheres, on " + FormatNumber(spacing, 1) + " mm voxels";
  }
  return u;
}

const char* ToString(ProximalSiteSource source)
{
  switch (source)
  {
    case ProximalSiteSource::Landmark:
      return "landmark";
    case ProximalSiteSource::Renal:
      return "renal";
    case ProximalSiteSource::None:
      return "notFound";
    case ProximalSiteSource::Top:
      break;
  }
  return "top";
}

ProximalSite FindProximalSite(const CenterlineTree& tree, const std::optional<Point3>& lowestRenalOstiumLps)
{
  const Centerline& aorta = tree.aorta;
  if (aorta.Size() < 2)
    throw InputError("The aortic centerline has " + std::to_string(aorta.Size()) +
                     " points; expected at least two to place the proximal implantation site.");
  ProximalSite site;
  if (lowestRenalOstiumLps)
  {
    double distance = 0.0;
    site.abscissaMm = ProjectOntoCenterline(aorta, *lowestRenalOstiumLps, &distance);
    if (distance > maximumLandmarkDistanceMm)
    {
      throw InputError(
        "lowestRenalOstium " +
        FormatPoint(Point3(-lowestRenalOstiumLps->x(), -lowestRenalOstiumLps->y(), lowestRenalOstiumLps->z())) +
        " mm RAS lies " + FormatNumber(distance) +
        " mm from the aortic centerline; expected a point on the aortic wall "
        "(within " +
        FormatNumber(maximumLandmarkDistanceMm, 0) + " mm) at the lower edge of the lowest renal artery's ostium.");
    }
    site.source = ProximalSiteSource::Landmark;
  }
  else
  {
    double lowest = -1.0;
    for (const char* name : { "rightRenal", "leftRenal" })
    {
      const Centerline* renal = tree.FindVessel(name);
      if (!renal || renal->Size() < 2)
        continue;
      const BranchOstium ostium = FindBranchOstium(aorta, *renal);
      if (ostium.found && ostium.lowerAbscissaMm > lowest)
      {
        lowest = ostium.lowerAbscissaMm;
        site.renal = name;
        site.renalRadiusMm = ostium.radiusMm;
        const OstiumEdgeUncertainty u = EdgeUncertainty(*renal, tree.largestSpacingMm);
        site.edgeUncertaintyMm = u.mm;
        site.edgeUncertaintyWhy = u.why;
      }
    }
    if (lowest >= 0.0)
    {
      site.source = ProximalSiteSource::Renal;
      site.abscissaMm = std::min(lowest, aorta.LengthMm());
    }
    else
      PlaceWithoutRenals(tree, site);
  }
  site.lps = PositionAt(aorta, site.abscissaMm);
  return site;
}

} // namespace sgp
