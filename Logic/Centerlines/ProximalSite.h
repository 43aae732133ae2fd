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
///     lies ρ↓ / sin φ further down (φ: the angle between the renal's axis and the aorta, clamped
///     to ≥ 30°) — the point where the renal's downstream wall line meets the aortic wall. ρ↓ is
///     the distance from the renal's axis to its downstream wall measured on the CT
///     (MeasureRenalMouthWalls) where the plan has one, else the renal's median inscribed radius
///     there. The lowest of the renals is the site;
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
  /// Source Renal: how far the true lower edge may lie from `abscissaMm` (OstiumEdgeUncertainty),
  /// mm, and why in words; 0 and "" for the other sources (a person's point is taken as given).
  double edgeUncertaintyMm = 0.0;
  std::string edgeUncertaintyWhy;
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
// The edges lie the branch's walls (Centerline::mouthWallMm, else radiusMm) / sin φ from the centre.

/// See BranchOstium. `parent` and `branch` as labelled (the branch starts at the junction).
BranchOstium FindBranchOstium(const Centerline& parent, const Centerline& branch);

/// The renal arteries' walls at their mouths, on the CT (issue 46 item 1): on thick slices the
/// inscribed radius of a renal that runs across them is cut to the slices it spans (4 mm read
/// 3.0 mm on 2.5 mm slices) and its skeleton lies on a slice, up to half a slice off its axis, so
/// the lower edge was read up to 2.2 mm high. Here, across the renal's fitted axis (the chord
/// of FindBranchOstium) at each centerline point 3–16 mm outside the aortic wall, a profile of the
/// CT (trilinear) along the aorta's direction (made perpendicular to the renal): the distance
/// from the axis to where it first falls below the edge level, upstream and downstream, is that
/// point's wall, and the medians over the points are Centerline::mouthWallMm. The edge level is
/// the lumen's own rule (GrowLumenRegion.h step 5): half-way between the profile's lumen (the
/// median within half the inscribed radius of the axis) and its tissue (2.5–4.5 mm beyond the
/// inscribed radius, both sides) raised to 40 HU (lumen_growth::LumenBorderHu: a wall's soft
/// tissue, not the fat beyond it, which put the walls 0.2–0.3 mm wide), so the renal's walls lie
/// where a lumen boundary is placed; an edge level read between slices lies on the edge however
/// the slices sample it, which the skeleton and the mask do not. Not set (NaN: the inscribed
/// radius is used): fewer than 3 profiles whose lumen lies 100 HU above its tissue, a renal
/// running within 30° of the aorta, or walls whose sum is under
/// the inscribed radius or over twice the inscribed diameter + 2 mm; and where the walls put the
/// ostium's edges within half the CT's coarsest spacing of where the inscribed radius puts them,
/// the inscribed radius stands (Centerline::mouthEdgeAgreementMm says by how much they differ):
/// every neck value hangs from the site, and below a short angled neck (b) moved by up to 4 mm
/// for a 0.2 mm shift of it. Input: the labelled tree and
/// the CT (HU, any grid or a crop of it holding the renals' mouths), LPS mm. Cost: 10^3–10^4
/// samples.
void MeasureRenalMouthWalls(CenterlineTree& tree, const CtImage& ct);

/// How far the edges of `branch`'s ostium (FindBranchOstium) may lie from where they are read,
/// mm, and why in words: with walls measured on the CT (Centerline::mouthWallMm) max(1 mm, half
/// the scan's coarsest spacing) — an edge level read between slices; with the
/// inscribed radius standing within half a voxel of the walls on the CT (mouthEdgeAgreementMm), the
/// same (every such reading on the series below lay within it: at most 0.66 mm against 1.0); with
/// the inscribed radius alone, max(1 mm, the coarsest spacing) — that radius cut to the slices the
/// branch spans and its skeleton on one slice. Measured on renals of 2.5–4 mm radius on 0.8–3 mm slices
/// (LandmarksPlanTest, Issue46/RenalEdgeSeries): walls on the CT within 0.75 mm, inscribed radii
/// up to 2.2 mm high. `largestSpacingMm` NaN (not known): 1 mm is taken.
struct OstiumEdgeUncertainty
{
  double mm = 0.0;
  std::string why;
};
OstiumEdgeUncertainty EdgeUncertainty(const Centerline& branch, double largestSpacingMm);

/// See the file comment. `lowestRenalOstiumLps`, when given, wins over detection.
ProximalSite FindProximalSite(const CenterlineTree& tree, const std::optional<Point3>& lowestRenalOstiumLps = {});

} // namespace sgp
