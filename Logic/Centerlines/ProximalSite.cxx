#include "Centerlines/ProximalSite.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "Common/Errors.h"
#include "Common/Format.h"
#include "Common/Median.h"

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
  for (const Eigen::Index i : near)
  {
    line.centroid += parent.points.row(i).transpose();
    line.abscissaMm += parent.abscissaMm[i];
  }
  line.centroid /= double(near.size());
  line.abscissaMm /= double(near.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Eigen::Index i : near)
  {
    const Eigen::Vector3d d = parent.points.row(i).transpose() - line.centroid;
    scatter += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);
  line.direction = eigen.eigenvectors().col(2).normalized(); // the largest eigenvalue's
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

} // namespace

BranchOstium FindBranchOstium(const Centerline& parent, const Centerline& branch)
{
  BranchOstium ostium;
  const Point3 junction = branch.points.row(0).transpose();
  const double sJunction = ProjectOntoCenterline(parent, junction);
  const AxisLine axis = FitAxisLine(
    parent, sJunction,
    std::clamp(parentAxisWindowRadii * RadiusAt(parent, sJunction), parentAxisWindowMinMm, parentAxisWindowMaxMm));
  const double parentRadius = axis.radiusMm;
  const Point3 a = axis.centroid;
  const Eigen::Vector3d T = axis.direction;
  const auto radial = [&](const Point3& p)
  {
    const Eigen::Vector3d w = p - a;
    return (w - w.dot(T) * T).norm();
  };
  std::vector<Point3> fit;
  std::vector<double> radii;
  for (Eigen::Index i = 0; i < branch.Size(); ++i)
  {
    const Point3 p = branch.points.row(i).transpose();
    const double outside = radial(p) - parentRadius;
    if (outside >= renalFitStartMm && outside <= renalFitEndMm)
    {
      fit.push_back(p);
      radii.push_back(branch.radiusMm[i]);
    }
    if (outside > renalFitEndMm)
      break;
  }
  if (fit.size() < 3)
    return ostium;
  const double radiusMm = Median(radii);
  const Eigen::Vector3d d = (fit.back() - fit.front()).normalized();
  Point3 centroid = Point3::Zero();
  for (const Point3& p : fit)
    centroid += p;
  centroid /= static_cast<double>(fit.size());
  // Walk the fitted axis inward from the centroid to the aortic wall (radial distance = radius):
  // |w⊥ + t d⊥|² = r² with w = centroid − a, ⊥ = perpendicular to T.
  const Eigen::Vector3d w = centroid - a;
  const Eigen::Vector3d wPerp = w - w.dot(T) * T, dPerp = d - d.dot(T) * T;
  const double qa = dPerp.squaredNorm(), qb = 2 * wPerp.dot(dPerp),
               qc = wPerp.squaredNorm() - parentRadius * parentRadius;
  const double discriminant = qb * qb - 4 * qa * qc;
  double t = 0.0;
  if (qa > 1e-12 && discriminant >= 0.0)
    t = (-qb + std::sqrt(discriminant)) / (2 * qa); // the near wall (both roots lie inward, t < 0)
  const Point3 ostiumCentre = centroid + t * d;
  const double sinAngle = std::max(d.cross(T).norm(), minimumRenalSinAngle);
  ostium.found = true;
  ostium.radiusMm = radiusMm;
  ostium.centreAbscissaMm = axis.abscissaMm + (ostiumCentre - a).dot(T);
  ostium.upperAbscissaMm = ostium.centreAbscissaMm - radiusMm / sinAngle;
  ostium.lowerAbscissaMm = ostium.centreAbscissaMm + radiusMm / sinAngle;
  return ostium;
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
