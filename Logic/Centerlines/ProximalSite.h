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
///  3. **top** — neither available: the top of the aortic centerline, with a warning.
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
  Top
};

/// "landmark", "renal" or "top".
const char* ToString(ProximalSiteSource source);

struct ProximalSite
{
  ProximalSiteSource source = ProximalSiteSource::Top;
  double abscissaMm = 0.0;     ///< along the aortic centerline from its top, mm
  Point3 lps = Point3::Zero(); ///< the aortic centerline point there, LPS mm
  std::string renal;           ///< the renal that defines it (source Renal), else empty
  double renalRadiusMm = 0.0;  ///< that renal's radius at its ostium (source Renal), mm
  std::string warning;         ///< non-empty for source Top (what was used and why)
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
