/// \file FitCheck.h
/// Whether the simulated stent graft fits: where it seals on healthy wall, how much it is
/// oversized, whether its components overlap enough, whether it covers an ostium (Egger et al.
/// 2007, section 2: "It hereby becomes apparent if the dimensions of the bifurcated stent graft are
/// exact … and no ostium was covered"; evar-sizing.md §2.3; device-configuration.md §1.7, §2.4).
///
/// Input: the deployed graft (DeployGraft.h: its layout — each vertex's component, side, path
/// position and nominal radius — and its fitted surface with the signed wall distance φ per
/// vertex, LPS mm); the measurements (their ring profiles give the lumen's diameter at every
/// level, (a) the neck's); the labelled centerlines (the ostia); the traced vessel wall (thrombus,
/// calcium and the outer diameter under every vertex), when there is one; the family's figures
/// and the configuration's findings (FitCheckContext).
///
/// Per vertex:
///  - **Apposition** = the gap between the graft and the lumen wall, max(0, −φ) mm (0: on the
///    wall); the graft presses on the thrombus, not through it;
///  - **HealthyWall** = 1 where the wall under the vertex is healthy: the thrombus between lumen
///    and outer wall along the vertex's ray (VesselWall) at most `maxThrombusMm` (2 mm,
///    vessel-wall.md), and on the aorta the outer wall's smallest width at that level at most
///    (1 + neckDilationPercent) × (a) (aneurysmal wall does not seal: the neck-length rule); 0
///    where it is not; −1 where the outer wall was not traced under it (no fat around it there):
///    then the seal is judged on apposition alone and every seal length through such a vertex is
///    marked estimated (lumen);
///  - **Calcified** = 1 where the vertex's ray crosses calcium (0 none, −1 not traced); with
///    `calciumSeals` (the default) it still seals, and the seal zone's calcified share is reported;
///  - **Sealing** = 1 where the vertex is apposed (within `contactToleranceMm`) and the wall under
///    it is healthy (or not traced);
///  - **Oversizing** = (the component's nominal diameter there / the vessel's − 1) × 100 %, the
///    vessel's on the outer wall (the traced plane within a step, area-equivalent, as the IFU's
///    oversizing is stated) where traced, else the lumen's.
/// A ring seals when at least `sealedRingFraction` of its vertices do.
///
/// Seal zones (lengths along the centerline, mm; a zone ends between its last sealing ring and the
/// first that does not, where their shares of sealing vertices, interpolated linearly, cross
/// sealedRingFraction — except the proximal zone where the wall turns unhealthy between those two
/// rings: it ends at the first of the wall's planes (1 mm apart) there where more than
/// 1 − sealedRingFraction of its rays are unhealthy):
///  - **proximal**: from the graft's proximal edge (the trunk's first ring) down; with it the
///    **shortest apposition length** (SAL, the post-EVAR literature's measure): the shortest, over
///    the trunk's columns, of the continuous sealed length from the edge;
///  - **iliac**: from each leg's distal edge up.
/// Oversizing summaries: the main body's at the proximal edge; each limb's, the median over the
/// leg's last 15 mm.
///
/// Findings (one line each, naming the component and the level; none = the fit check passed):
///  - type Ia risk: proximal seal shorter than `minimumProximalSealMm` (10 mm), and why it ends;
///    within its uncertainty above it (`sealUncertaintyMm`, 2 mm, or on coarser scans twice the
///    voxel's extent along the aorta: FitCheckContext::voxelAlongAortaMm) the risk "cannot be
///    excluded" (flagged all the same);
///  - type Ia risk from apposition: the shortest apposition length under
///    `minimumAppositionLengthMm` (10 mm), even where the rings seal (a column over a narrow arc of
///    thrombus or out of contact leaves the rest of its ring sealing): naming the column's side in
///    the patient's words and why it stops apposing (not in contact, on thrombus, on calcium, on the
///    aneurysm's wall);
///  - type Ib risk: an iliac seal shorter than the family's minimum iliac seal;
///  - type III risk: an overlap (limb in the gate or leg, extension in a limb) below the family's
///    minimum — measured on the deployed fabric (GraftLayout::fabricMm: the positions along the
///    graft it was deployed at);
///  - infolding risk: oversizing over `infoldingPercent` (30 %) at the proximal edge or a landing
///    zone; oversizing outside [oversizingMinPercent, oversizingMaxPercent] there;
///  - an ostium the deployed graft covers: renal, superior mesenteric and coeliac on the aorta by
///    the trunk's extent, each internal iliac by its leg's (FindBranchOstium, overlap beyond
///    `ostiumOverlapToleranceMm`); an aortic ostium the graft may cover: one it would cover were
///    its edge where its uncertainty lets it lie (EdgeUncertainty, ProximalSite.h; issue 46 item 1;
///    the renals' when the site was found from them, not from a person's point; a configured graft
///    only, deployed at the plan's target with its margin — an unconfigured one, on the measure-mode
///    mesh from the site as read, is judged as read) — the internal iliacs' edges are taken as read
///    (their tolerance is issue 47's);
///  - the configuration's findings (limb compression, the gate below the aortic bifurcation, a
///    common iliac too short, an iliac too wide, …), each as it stands.
/// Limbs not sized (a partial plan: the scan ends above the iliac landing zones): that leg was
/// simulated only to carry the connection element, so its seal length and limb oversizing are
/// NaN, its internal iliac ostium is not checked, and it has no findings (limbChecked says which
/// sides were checked; Complete() whether both were).
/// Errors: InputError when the fitted surface does not belong to the layout's mesh.
#pragma once

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "Device/ConfigureDevice.h"
#include "Device/DeployGraft.h"
#include "Measurement/MeasureAnatomy.h"
#include "Wall/VesselWall.h"

namespace sgp
{

struct FitCheckParams
{
  double contactToleranceMm = 1.0;    ///< a vertex this close to the wall touches it (one voxel)
  double sealedRingFraction = 0.9;    ///< a ring seals when this share of its vertices seal
  double maxThrombusMm = 2.0;         ///< thicker thrombus under a vertex: it does not seal (vessel-wall.md)
  double neckDilationPercent = 10.0;  ///< the aorta wider than (a) by more than this does not seal
  bool calciumSeals = true;           ///< calcium under a vertex: it seals (flagged) when true
  double oversizingMinPercent = 10.0; ///< evar-sizing.md §2.3: 10–25 %
  double oversizingMaxPercent = 25.0;
  double infoldingPercent = 30.0;      ///< over this: infolding (device-configuration.md §2.3, SBC 2010)
  double minimumProximalSealMm = 10.0; ///< shorter: migration and type Ia endoleak risk
  /// The measured proximal seal's uncertainty, mm — the neck length's (NeckLengthUncertaintyMm):
  /// the proximal site's 1 mm and the wall planes' 1 mm step the seal's end is refined on. A seal
  /// within it above the minimum cannot exclude the risk: it is flagged too, as "cannot be
  /// excluded" (issue 32: a 9 mm healthy neck read 10.8 mm, its site 0.8 mm high).
  double sealUncertaintyMm = 2.0;
  /// A shortest apposition length (SAL) under this is associated with late type Ia endoleak and
  /// migration (Schuurmann's SAL on the first post-operative CTA; device-configuration.md §2).
  double minimumAppositionLengthMm = 10.0;
  double minimumIliacSealMm = 10.0;      ///< used where the family gives none
  double ostiumOverlapToleranceMm = 0.5; ///< a graft edge at the ostium's edge does not cover it
};

/// What the fit check needs from the device and its configuration.
struct FitCheckContext
{
  std::string family;
  double minimumIliacSealMm = std::numeric_limits<double>::quiet_NaN(); ///< the family's (NaN: params')
  double minimumOverlapMm = std::numeric_limits<double>::quiet_NaN();   ///< the family's (NaN: not checked)
  std::vector<ConfigurationFinding> configurationFindings;
  std::array<bool, 2> limbSized{ true, true }; ///< false: a partial plan's unsized leg
  /// The scan's sampling interval along the aorta at the proximal site (√Σ_i (axis_i · t
  /// spacing_i)², t the aorta's direction: the slice spacing along an axial aorta), mm: the site
  /// and a thrombus onset are placed no better than it. NaN: not known (sealUncertaintyMm alone).
  double voxelAlongAortaMm = std::numeric_limits<double>::quiet_NaN();
};

struct OstiumCoverage
{
  std::string branch;           ///< e.g. rightRenal
  std::string parent;           ///< aorta, rightIliac, leftIliac
  double upperAbscissaMm = 0.0; ///< the ostium's extent on the parent, mm
  double lowerAbscissaMm = 0.0;
  double overlapMm = 0.0; ///< of the graft's extent with it (≤ 0: apart)
  bool covered = false;
  double edgeUncertaintyMm = 0.0; ///< how far its edges may lie from where they are read, mm
  std::string edgeUncertaintyWhy;
  /// Not covered as read, but covered (beyond the tolerance) were its edges edgeUncertaintyMm
  /// further toward the graft: a finding too.
  bool mayBeCovered = false;
};

/// How far below the lowest renal ostium's lower edge as read the main body's fabric is deployed
/// (before PlanParams::deploymentOffsetMm) so that it covers no part of the ostium wherever its
/// edge lies within its uncertainty: max(0, site.edgeUncertaintyMm − ostiumOverlapToleranceMm), mm
/// (0.5 mm on slices up to 2 mm, 1 mm on 3 mm: EdgeUncertainty; 0 for a person's point).
double SiteMarginMm(const ProximalSite& site, const FitCheckParams& params = {});

struct FitCheck
{
  Eigen::VectorXd oversizingPercent; ///< #V
  Eigen::VectorXd appositionMm;      ///< #V
  Eigen::VectorXi healthyWall;       ///< #V, 1 healthy, 0 not (thrombus, aneurysmal), −1 not traced
  Eigen::VectorXd thrombusUnderMm;   ///< #V, NaN where not traced
  Eigen::VectorXi calcified;         ///< #V, 1, 0, −1 not traced
  Eigen::VectorXi sealing;           ///< #V, 0 or 1
  double proximalSealLengthMm = 0.0;
  double minimumProximalSealMm = 0.0;     ///< the minimum the proximal seal was judged against
  double minimumIliacSealMm = 0.0;        ///< and each iliac seal (the family's, else FitCheckParams')
  double minimumAppositionLengthMm = 0.0; ///< and the shortest apposition length
  /// The proximal seal's uncertainty, mm: max(FitCheckParams::sealUncertaintyMm, 2 × the voxel
  /// along the aorta) — its top and its end each placed no better than one voxel — and why, in words.
  double proximalSealUncertaintyMm = 0.0;
  std::string proximalSealUncertaintyWhy;
  double shortestAppositionLengthMm = 0.0; ///< SAL over the trunk's columns
  /// The column with the SAL: where it lies around the graft's proximal edge in the patient's words
  /// ("left posterior": the direction from the edge's centre, across the graft's axis, LPS), and why
  /// it stops apposing ("" when it apposes to the trunk's end).
  std::string shortestAppositionSide;
  std::string shortestAppositionEnd;
  double rightIliacSealLengthMm = 0.0;
  double leftIliacSealLengthMm = 0.0;
  /// Each zone judged on apposition alone somewhere (the outer wall not traced there): estimated.
  std::array<bool, 3> sealOnLumenOnly{ false, false, false }; ///< proximal, right, left
  std::string proximalSealEnd;             ///< why the proximal seal ends, in words ("" when it runs to the end)
  double proximalCalcifiedPercent = 0.0;   ///< share of the proximal seal zone's vertices over calcium
  double proximalOversizingPercent = 0.0;  ///< at the graft's top ring
  double rightLimbOversizingPercent = 0.0; ///< over the leg's distal 15 mm (median)
  double leftLimbOversizingPercent = 0.0;
  std::vector<OstiumCoverage> ostia;
  bool migrationRisk = false;           ///< proximal seal or shortest apposition length shorter than its minimum
  std::string oversizingWall = "lumen"; ///< the wall the three summary oversizings are over
  std::vector<std::string> findings;    ///< the problems, one line each
  std::array<bool, 2> limbChecked{ true, true }; ///< right, left: the limb was sized and checked
  bool Complete() const { return limbChecked[0] && limbChecked[1]; }
  /// No finding on a complete check (a partial one cannot pass: its limbs are not known).
  bool Passed() const { return findings.empty() && Complete(); }
  /// The covered ostia's branch names joined by ", ", or "none".
  std::string CoveredOstia() const;
};

/// See the file comment.
FitCheck CheckGraftFit(const DeployedGraft& graft,
                       const Measurements& measured,
                       const CenterlineTree& tree,
                       const VesselWall* wall,
                       const FitCheckContext& context,
                       const FitCheckParams& params = {});

/// The fit check's numbers as table rows (Measurement: name, value, unit, definition, vessel,
/// abscissa) — the CLI's return parameters of the same names.
std::vector<Measurement> FitCheckRows(const FitCheck& check, const DeployedGraft& graft);

} // namespace sgp
