/// \file GrowLumenRegion.h
/// Segments the contrast-filled aortic lumen and its arterial branches from a seed point.
///
/// Step 1 of Egger et al. (2007), section 2: "the affected artery is segmented with a region
/// growing method that starts at a user-defined seed point", made safe for real CT angiography:
///
///  1. **Window.** The median m and robust standard deviation σ (1.4826 × MAD) of the voxels within
///     `seedNeighbourhoodRadiusMm` of the seed give the window [m − h, m + 2h], h = max(k·σ,
///     `minimumHalfWindowHu`), k = `windowSigmas` (thresholdMode Auto); or [lowerHu, upperHu] as
///     given (Manual). A seed beside the wall, a calcified plaque or a dissection flap has such
///     voxels in its ball, which widen the window into tissue: when more than 2 % of the ball lies
///     outside ±4 σ of the most homogeneous fifth of the lumen neighbourhoods within `seedSearchRadiusMm` (joined
///     to the seed by a straight line through lumen, so never across a wall or flap), the window
///     is taken from the nearest clean neighbourhood instead, with a warning naming it (Auto only).
///     **1b.** (Auto, `windowFromLumen`, the default) The region grown with that window gives
///     the window again, slab by slab (20 mm along k): the median and robust σ of the lumen's core
///     — its voxels at least 5 mm inside its edge, found on 2 mm blocks, in the piece nearest the
///     seed, so a kidney joined through a renal artery does not count — with a half-width of
///     max(k σ, `minimumHalfWindowHu`, 0.2 × the slab's median), and the region is grown again until
///     the windows no longer change (at most six growths; windows met again — a cycle, since whole
///     HU move the core's σ in steps of 1.48 HU — end it on the cycle's narrowest, the same from any
///     start). The seed ball's estimate moves with its
///     noise sample and its place (a bolus gradient, a thick slice, a ball of 30–100 voxels); the
///     lumen's own is the same from any seed inside it: the plan from FindAorticSeed's seed then
///     equals the plan from any other seed in the aorta. The blocks lie on a grid fixed in space
///     and the slabs at fixed heights, so a scan cut lower keeps the others' levels; step 5's edge
///     is then each slice's own: half-way between its slab's lumen level and the tissue median of
///     its slab (the whole region's where the slab has fewer than 200 samples).
///     The window reaches further up than down: above the lumen lie only
///     brighter contrast, then calcium and cortical bone (> 700 HU); below it lie enhancing
///     kidney parenchyma (150–200 HU) and cancellous bone (200–300 HU).
///  2. **Region growing** from the seed: the face-connected (6-neighbour) region of voxels in the
///     window that have no face neighbour above `calciumHu` (upper + half the window's width:
///     calcium or bone; the blurred rim of a plaque against the lumen passes through the window
///     and would otherwise carry the region around the plaque, which hole filling then swallows —
///     a shell the thinning turns into false branches) — what ITK's ConnectedThresholdImageFilter grows with face
///     connectivity, written here with one bit per voxel for its marks (ITK's filter holds a full-size output and a
///     full-size scratch image beside the CT).
///  3. **Leak cutting.** A morphological opening with a ball of `leakOpeningRadiusMm`, keeping the
///     seed's component, cuts what is joined to the lumen only through thin bridges (partial-volume
///     shells along bone, noise paths); the opened region is dilated back inside the grown one,
///     so the vessel's own shape is kept. Cut-off pieces smaller than `leakMinimumPieceMl` are put
///     back — on real scans they are vessels narrower than the ball (small branches, distal
///     vessels on 3 mm slices, the run-off beyond a stenosis) — and larger ones, the size of a
///     leak into a vertebral body, kidney or bowel, stay cut and are reported.
///  4. **Leak detection.** Deep inside the region (after the opening's erosion) the lumen is
///     homogeneous. More than `darkLeakLimitMl` of voxels there darker than
///     tissue + 0.7·(m − tissue) means the region flooded a tissue of another class (kidney,
///     bowel, marrow): AlgorithmError. So does a lumen over `maximumLumenVolumeMl`.
///  5. **Boundary refinement.** The boundary is moved to the half-maximum between lumen (m; with
///     step 1b the slice's slab level) and the
///     surrounding tissue (median HU `tissueDepthMm` outside the region, beyond the blur of the edge): neighbours
///     within `refineDistanceMm` (millimetres on every axis, an ellipsoid of voxels on the grid) with HU in
///     [edge, upper], not beside calcium, are added; this undoes the conservative lower threshold without reaching
///     into darker tissue. The reach is what the blur needs and no more: on the 1 mm-blur phantom the lumen is
///     complete at 1.6 mm (volume −0.5 %, −0.4 % at 2 mm, −17 % without refinement), while every further
///     tenth of a millimetre takes more of an enhancing vein behind a thin wall (2.1–3.5 % of it at 2 mm).
///  6. **Pits and holes:** single background voxels with five or six lumen faces (noise pits in the
///     boundary) and background cavities not connected to the outside become lumen.
///  7. **Narrow branches** the window lost (blurred below its lower end: a narrow internal iliac
///     on thick slices) are followed on at the edge level, piece by piece, where a piece is thin
///     (no ball of `thinBranchRadiusMm`), bright (its core above half-way between the edge and the
///     lumen level), reaches `thinBranchReachMm` away from the lumen, meets no calcium rim and is
///     smaller than `leakMinimumPieceMl` (ContinueThinBranches.h).
///
/// Inputs: `ct` in HU on any grid (spacing, origin and direction are honoured); `seedLps` in LPS mm.
/// Output: a LabelImage on the exact grid of `ct`, 1 = lumen, 0 = background; the window used;
/// warnings as text (the caller prints them; Logic never prints).
///
/// Preconditions, each an InputError naming the value: parameters in range (see
/// ValidateRegionGrowingParams); the seed inside the image; the median HU around the seed at
/// least `seedMinimumHu` (contrast-filled lumen); in Manual mode the seed's median inside
/// [lowerHu, upperHu]; the seed in a vessel wider than the opening ball.
/// Errors (AlgorithmError): a flood into darker tissue, or a lumen larger than the limit.
///
/// Complexity: work linear in the grown region (region growing, which also finds its bounding
/// box), then work linear in that bounding box times the ball size, then one fill of the output
/// mask. Memory beside the CT: 1 bit per voxel while growing, then buffers the size of the padded
/// bounding box, then the output mask (1 byte per voxel).
///
/// Reference: J. Egger, S. Großkopf, B. Freisleben, "Simulation of bifurcated stent grafts to treat
/// abdominal aortic aneurysms (AAA)", Proc. SPIE 6509, Medical Imaging 2007, section 2.
#pragma once

#include <string>
#include <vector>

#include "Common/IndexBox.h"
#include "Common/Types.h"

namespace sgp
{

enum class ThresholdMode
{
  Auto,  ///< window estimated from the seed's neighbourhood
  Manual ///< lowerHu and upperHu as given
};

/// Parameters of GrowLumenRegion. Defaults equal the XML defaults of StentGraftSimulation
/// (a test compares them); the fields after the first block are not exposed in the XML.
struct RegionGrowingParams
{
  ThresholdMode thresholdMode = ThresholdMode::Auto;
  double lowerHu = 200.0;               ///< Manual window, HU; must be < upperHu; in [-1024, 3071]
  double upperHu = 600.0;               ///< Manual window, HU; in [-1024, 3071]
  double windowSigmas = 3.0;            ///< Auto half-width below the median, in σ; in [1, 10]
  double seedMinimumHu = 150.0;         ///< lumen test at the seed, HU; in [-1024, 3071]
  double leakOpeningRadiusMm = 1.0;     ///< opening ball radius, mm; 0 disables; in [0, 5]
  double maximumLumenVolumeMl = 1500.0; ///< larger lumen = leak, mL; in [1, 20000]

  double seedNeighbourhoodRadiusMm = 2.5; ///< ball for the seed statistics, mm
  double seedSearchRadiusMm = 5.0;        ///< Auto: how far a cleaner neighbourhood is looked for, mm; 0 = never
  /// Auto: after growing, the window again from the lumen's core, slab by slab, until it no longer
  /// changes (step 1b of the file comment); false keeps the seed neighbourhood's window (and one
  /// edge level for every slice).
  bool windowFromLumen = true;
  double minimumHalfWindowHu = 30.0; ///< floor of h for noise-free images, HU
  double refineDistanceMm = 1.6;     ///< reach of the boundary refinement, mm
  double tissueDepthMm = 5.0;        ///< where tissue is sampled outside the region, mm
  double leakMinimumPieceMl = 10.0;  ///< smaller cut-off pieces are vessels and stay, mL
  double darkLeakLimitMl = 5.0;      ///< dark interior volume that means a flood, mL
  /// Step 7: a piece beyond the lumen at the edge level holding a ball this large is not a lost
  /// narrow branch, mm; 0 disables the step (ContinueThinBranches.h).
  double thinBranchRadiusMm = 3.0;
  double thinBranchReachMm = 5.0; ///< step 7: a lost branch reaches this far from the lumen, mm
};

/// Checks every range and cross-parameter rule of `params`.
/// \throws InputError naming the parameter, its value and the expected range.
void ValidateRegionGrowingParams(const RegionGrowingParams& params);

struct LumenSegmentation
{
  LabelImage::Pointer mask; ///< on the grid of the input, 1 = lumen
  IndexBox box;             ///< image-index box holding every lumen voxel (padded; inside the image)
  double volumeMl = 0.0;    ///< lumen volume, mL
  double lowerHu = 0.0;     ///< window used, HU
  double upperHu = 0.0;     ///< window used, HU
  double edgeHu = 0.0;      ///< half-maximum boundary level used, HU
  /// Above it: calcium or bone, whose blurred rim is not lumen (upper + half the window's width).
  double calciumHu = 0.0;
  double seedMedianHu = 0.0;         ///< median HU around the seed
  double seedSigmaHu = 0.0;          ///< robust standard deviation around the seed, HU
  Point3 windowCentreLps{ 0, 0, 0 }; ///< centre of the neighbourhood the window came from, LPS mm
  std::string windowSource;          ///< where the window came from and why, for the report
  double tissueHu = 0.0;             ///< median HU just outside the region
  double cutVolumeMl = 0.0;          ///< volume removed by the leak-cutting opening, mL
  int thinBranchPieces = 0;          ///< step 7: narrow branches followed on at the edge level
  double thinBranchMl = 0.0;         ///< their volume, mL (in volumeMl)
  std::vector<std::string> warnings; ///< one line each, without the "WARNING: " prefix
};

/// Segments the lumen connected to `seedLps`; see the file comment for the method.
/// \throws InputError, AlgorithmError as listed in the file comment.
LumenSegmentation GrowLumenRegion(const CtImage& ct,
                                  const Point3& seedLps,
                                  const RegionGrowingParams& params,
                                  const ProgressCallback& progress = {});

} // namespace sgp
