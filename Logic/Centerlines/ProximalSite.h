/// \file ProximalSite.h
/// The proximal implantation site: the lower edge of the lowest renal artery's ostium, as an arc
/// length along the aortic centerline (Egger et al. 2007, measurement (a); evar-sizing.md §2.4).
///
/// Three sources, in this order:
///  1. **landmark** — a point the user placed at the lower edge of the lowest renal ostium
///     (`--lowestRenalOstium`), projected onto the aortic centerline;
///  2. **renal** — detected from the labelled renal side branches (rightRenal, leftRenal): each
///     renal's axis is the chord of its centerline from 1 to 16 mm outside the aortic wall (the
///     skeleton's junction lies on the aortic axis, up to a renal radius away from the true
///     branching level), its ostium centre is where that axis crosses the aortic wall (the
///     cylinder of the aorta's inscribed radius around the aortic axis there — the line fitted to
///     the aortic centerline within 1.5 aortic radii, 8–20 mm, of the junction: the centerline's
///     local tangent is tilted toward the branch, and a parent radius away that tilt moved the
///     ostium along the aorta by up to 2 mm), and its lower edge
///     lies ρ / sin φ further down (ρ: the renal's median inscribed radius there; φ: the angle
///     between the renal's axis and the aorta, clamped to ≥ 30°) — the point where the renal's
///     downstream wall line meets the aortic wall. The lowest of the renals is the site;
///  3. **top** — neither available, and the aorta in view reaches no higher than
///     MaximumRenalHeightMm above its bifurcation (the scan starts near the renal level, so the
///     renals may lie just above it): the top of the aortic centerline, with a warning that says so;
///  4. **notFound** (ProximalSiteSource::None) — neither available, and the aorta in view
///     reaches past where renal arteries leave
///     (its top more than MaximumRenalHeightMm above the bifurcation, or over an arch into the
///     chest): the site is **not known**. The neck values measured from it are not measured
///     (MeasureAnatomy.h), no deployment target is set, and the warning asks for the
///     `lowestRenalOstium` point. `abscissaMm` is then only where the measure-mode stent surface
///     starts: the aorta MaximumRenalHeightMm above the bifurcation (its top where lower), so
///     that (c), (d) and the iliac values are read on the abdominal aorta, never in the chest.
///
/// Input: the labelled CenterlineTree (LPS mm) and optionally the user's point (LPS mm).
/// Output: ProximalSite (below), abscissa along `tree.aorta` from its top, mm.
/// Errors: InputError when the user's point lies more than 30 mm from the aortic centerline
/// (it cannot be on the aortic wall) or the aortic centerline has fewer than two points.
#pragma once

#include <optional>
#include <string>

#include "Centerlines/Centerlines.h"

namespace sgp
{

enum class ProximalSiteSource
{
  Landmark,
  Renal,
  Top,
  None
};

/// How high above the aortic bifurcation a renal artery is looked for (LabelAortoIliacTree.h,
/// step 4) and so the highest a scan's top may lie for its top to stand in for the renal level,
/// mm (along z). One bound for both: a scan whose aorta reaches higher than renals are looked for
/// has passed the renal level, so its top is not a stand-in for it.
constexpr double MaximumRenalHeightMm = 180.0;

/// "landmark", "renal", "top" or "notFound" (not "none": a text return value not measured is
/// "none", PlanValues.h).
const char* ToString(ProximalSiteSource source);

struct ProximalSite
{
  ProximalSiteSource source = ProximalSiteSource::Top;
  double abscissaMm = 0.0;     ///< along the aortic centerline from its top, mm
  Point3 lps = Point3::Zero(); ///< the aortic centerline point there, LPS mm
  std::string renal;           ///< the renal that defines it (source Renal), else empty
  double renalRadiusMm = 0.0;  ///< that renal's radius at its ostium (source Renal), mm
  std::string warning;         ///< non-empty for sources Top and None (what was used and why)
  /// False for source None: the site is not known, and nothing is measured from it.
  bool Known() const { return source != ProximalSiteSource::None; }
};

/// Where a side branch opens from its parent vessel, as arc lengths along the parent's
/// centerline: the branch's axis (chord of its centerline 1…16 mm outside the parent's wall)
/// crosses the parent's wall at `centreAbscissaMm`; the ostium reaches ρ / sin φ up and down from
/// there (the file comment). `found` is false when the branch's centerline does not reach 1 mm
/// beyond the parent's wall.
struct BranchOstium
{
  bool found = false;
  double centreAbscissaMm = 0.0;
  double upperAbscissaMm = 0.0; ///< the ostium's upstream edge (smaller abscissa)
  double lowerAbscissaMm = 0.0; ///< its downstream edge
  double radiusMm = 0.0;        ///< the branch's median inscribed radius there
};

/// See BranchOstium. `parent` and `branch` as labelled (the branch starts at the junction).
BranchOstium FindBranchOstium(const Centerline& parent, const Centerline& branch);

/// See the file comment. `lowestRenalOstiumLps`, when given, wins over detection.
ProximalSite FindProximalSite(const CenterlineTree& tree, const std::optional<Point3>& lowestRenalOstiumLps = {});

} // namespace sgp
