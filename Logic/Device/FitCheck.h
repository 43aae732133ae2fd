/// \file FitCheck.h
/// Whether the simulated stent graft fits: where it seals, how much it is oversized, whether it
/// covers an ostium (Egger et al. 2007, section 2: "It hereby becomes apparent if the dimensions
/// of the bifurcated stent graft are exact … and no ostium was covered"; evar-sizing.md §2.3).
///
/// Input: the StentMesh both fits used; the graft's surface after the simulate-mode fit with the
/// device's nominal radii (V and the signed wall distance φ per vertex, LPS mm); the measurements
/// read off the measure-mode fit of the same mesh (their ring profiles give the vessel diameter
/// under every ring); the labelled centerlines (for the ostia); the device's nominal diameters.
///
/// Per vertex: **Oversizing** = (device diameter / vessel diameter at its ring − 1) × 100 %, the
/// vessel diameter on the outer wall (the traced plane within a step of the ring, area-equivalent,
/// as the IFU's oversizing is stated) where a `wall` is given and traced there, else the lumen's
/// ring mean; `oversizingWall` says which the summary values used ("outer", "lumen", "mixed").
/// Apposition and sealing are against the lumen: the graft presses on the thrombus, not through
/// it;
/// **Apposition** = the gap between the graft and the wall, max(0, −φ) mm (0: on the wall);
/// **Sealing** = 1 where the vertex is within `contactToleranceMm` of the wall. A ring seals when
/// at least `sealedRingFraction` of its vertices do.
/// Seal zones: proximal, from the graft's top ring down to the first ring that does not seal;
/// each iliac, from the leg's distal ring up to the first that does not — lengths along the
/// centerline between those rings (so quantized by the ring spacing).
/// Ostia: each labelled side branch (rightRenal, leftRenal, superiorMesenteric, coeliac on the
/// aorta; rightInternalIliac, leftInternalIliac on the iliacs) whose ostium (FindBranchOstium)
/// overlaps the graft's extent on its parent by more than `ostiumOverlapToleranceMm` is covered.
/// Limbs not sized (a partial plan: the scan ends above the iliac landing zones): a NaN limb
/// diameter; that leg was simulated only to carry the connection element, so its seal length and
/// limb oversizing are NaN, its internal iliac ostium is not checked, and it has no findings
/// (limbChecked says which sides were checked; Complete() whether both were).
/// Findings (one line each; none = the fit check passed): oversizing outside
/// [oversizingMinPercent, oversizingMaxPercent] at the proximal site or a limb's landing zone; a
/// seal zone shorter than its minimum (proximal: migration and type Ia endoleak risk; iliac:
/// type Ib); a covered ostium.
/// Errors: InputError when the surface or the measurements do not belong to the mesh.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "Measurement/MeasureAnatomy.h"
#include "Wall/VesselWall.h"

namespace sgp
{

struct FitCheckParams
{
  double contactToleranceMm = 1.0;    ///< a vertex this close to the wall touches it (one voxel)
  double sealedRingFraction = 0.9;    ///< a ring seals when this share of its vertices touch
  double oversizingMinPercent = 10.0; ///< evar-sizing.md §2.3: 10–25 %
  double oversizingMaxPercent = 25.0;
  double minimumProximalSealMm = 10.0; ///< shorter: migration risk
  double minimumIliacSealMm = 10.0;
  double ostiumOverlapToleranceMm = 0.5; ///< a graft edge at the ostium's edge does not cover it
};

struct OstiumCoverage
{
  std::string branch;           ///< e.g. rightRenal
  std::string parent;           ///< aorta, rightIliac, leftIliac
  double upperAbscissaMm = 0.0; ///< the ostium's extent on the parent, mm
  double lowerAbscissaMm = 0.0;
  double overlapMm = 0.0; ///< of the graft's extent with it (≤ 0: apart)
  bool covered = false;
};

struct FitCheck
{
  Eigen::VectorXd oversizingPercent; ///< #V
  Eigen::VectorXd appositionMm;      ///< #V
  Eigen::VectorXi sealing;           ///< #V, 0 or 1
  double proximalSealLengthMm = 0.0;
  double rightIliacSealLengthMm = 0.0;
  double leftIliacSealLengthMm = 0.0;
  double proximalOversizingPercent = 0.0;  ///< at the graft's top ring
  double rightLimbOversizingPercent = 0.0; ///< over the leg's distal 15 mm (median)
  double leftLimbOversizingPercent = 0.0;
  std::vector<OstiumCoverage> ostia;
  bool migrationRisk = false;                    ///< proximal seal shorter than its minimum
  std::string oversizingWall = "lumen";          ///< the wall the three summary oversizings are over
  std::vector<std::string> findings;             ///< the problems, one line each
  std::array<bool, 2> limbChecked{ true, true }; ///< right, left: the limb was sized and checked
  bool Complete() const { return limbChecked[0] && limbChecked[1]; }
  /// No finding on a complete check (a partial one cannot pass: its limbs are not known).
  bool Passed() const { return findings.empty() && Complete(); }
  /// The covered ostia's branch names joined by ", ", or "none".
  std::string CoveredOstia() const;
};

/// See the file comment. `graftDiametersMm`: trunk, right leg, left leg (StentSegment order);
/// NaN for a limb not sized.
FitCheck CheckGraftFit(const StentMesh& mesh,
                       const Points& V,
                       const Eigen::VectorXd& wallDistanceMm,
                       const Measurements& measured,
                       const CenterlineTree& tree,
                       const std::array<double, 3>& graftDiametersMm,
                       const FitCheckParams& params = {},
                       const VesselWall* wall = nullptr);

/// The fit check's numbers as table rows (Measurement: name, value, unit, definition, vessel,
/// abscissa) — the CLI's return parameters of the same names.
std::vector<Measurement> FitCheckRows(const FitCheck& check, const StentMesh& mesh);

} // namespace sgp
