/// \file FindAorticSeed.h
/// The automatic seed: a point in the abdominal aorta's lumen found without the user, for runs
/// with no --seed (cohorts).
///
/// Method: on axial levels (planes of constant LPS z, every `levelStepMm` from 5 mm inside the
/// scan's top and bottom) the CT is resampled at `pixelMm`; the pixels at or above `minimumHu`
/// (contrast-filled: unenhanced blood is 30–60 HU) form connected pieces. A piece is a candidate
/// when it is
///  - **large**: area-equivalent diameter in [minimumDiameterMm, maximumDiameterMm] (the aorta,
///    normal to aneurysmal; a common iliac of 8–13 mm and the renal arteries are smaller);
///  - **round**: area / (π · its largest centre distance²) ≥ minimumRoundness (a kidney's
///    section is an ellipse of aspect 1.2–1.6, a vein crossing in front of the aorta a band);
///  - **not bone**: its rim (the pixels on its border) no brighter than its median, and its shell
///    (1–4 mm inside the border) at most 30 HU brighter than its core — a vessel's
///    edge is darker than its middle (partial volume with the tissue around it), a vertebral
///    body's brighter (the cortex around the cancellous core) — and under maximumBrightFraction of
///    its pixels at or above max(700 HU, median + 300 HU) (an aortic plaque is a few %);
///  - **near the midline**: its centre within maximumMidlineOffsetMm of the body's left–right
///    centre on that level (pixels above −500 HU; the aorta lies just left of it, the kidneys
///    50–100 mm lateral);
///  - **a vessel along the body**: followed level by level (`trackStepMm`, the piece overlapping
///    the previous centre's neighbourhood) for at least `minimumRunMm` (or 80 % of the scan's
///    extent when it is shorter): a vertebral body ends at its disc, a kidney is not round.
/// The candidates are scored by roundness × min(diameter, 25 mm)/25 mm (HU plays no part past the
/// threshold: the bolus makes the chest's aorta brighter than the abdomen's), and the seed is taken
/// from the most inferior candidate scoring within 75 % of the best on a level where it is the only
/// candidate at least 0.7 × as wide (below the bifurcation the common iliacs come in pairs; in the
/// chest the ascending aorta lies beside the descending one): the abdominal aorta in an
/// abdominal or chest-to-pelvis scan, the descending aorta in a scan that ends above it. The seed
/// is the piece's deepest pixel (farthest from its border: a crescent lumen's middle).
///
/// Output: the seed (LPS mm) and one sentence saying what was found and where.
/// Errors: AlgorithmError when no candidate passes, naming what was looked for, the levels
/// searched and the nearest miss (or that no pixel reached minimumHu: a non-contrast scan).
/// Cost: (levels + tracked levels) × the slice's pixels trilinear samples; about 0.1–0.3 s on a
/// 512 × 512 × 400 CTA.
#pragma once

#include <string>

#include "Common/Types.h"

namespace sgp
{

struct AorticSeedParams
{
  double minimumHu = 150.0; ///< contrast-filled; the CLI uses seedMinimumHu
  double pixelMm = 1.0;
  double levelStepMm = 10.0;
  double minimumDiameterMm = 14.0;
  double maximumDiameterMm = 100.0;
  double minimumRoundness = 0.5;
  double maximumBrightFraction = 0.1;
  double maximumMidlineOffsetMm = 60.0;
  double trackStepMm = 5.0;
  double minimumRunMm = 50.0;
};

struct AorticSeed
{
  Point3 lps = Point3::Zero();
  std::string description; ///< "the lowest round contrast-filled cross-section … at LPS z … mm"
};

/// See the file comment.
AorticSeed FindAorticSeed(const CtImage& ct, const AorticSeedParams& params = {});

} // namespace sgp
