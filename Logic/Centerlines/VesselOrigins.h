/// \file VesselOrigins.h
/// Where the vessels of the labelled Y branch: the aortic bifurcation and the internal iliac
/// origins, each **where the vessel axes meet**, not where the skeleton's junction lies. The
/// junction sits distal to the true branching point, inside the merged cross-section of the two
/// daughters (2–4 mm on our phantoms), so lengths to it read long.
///
///  - **Internal iliac origin** (per side): the point nearest (least squares) to the axes of the
///    common iliac above the skeleton's junction, the external iliac below it and the internal
///    iliac, projected onto the iliac's centerline. Each axis is a 15 mm chord that starts `d`
///    from the junction, d = max(5 mm, r_common + r_internal) (the common iliac's inscribed radius
///    15 mm above the junction, the internal iliac's 20 mm from it): within about the two radii
///    the skeleton bends into the merged cross-section (with a fixed 5 mm, a 14 mm iliac's origin
///    read 2 mm off). The junction itself when a chord does not fit (iliac < d + 5 mm either side
///    of it, internal iliac < d + 15 mm) or the axes meet farther than 10 mm from it; NaN when no
///    internal iliac was labelled.
///  - **Aortic bifurcation** B: the point nearest to the axes of the distal aorta (chord 25…5 mm
///    above the skeleton's junction) and of both common iliacs (chords from min(10 mm, half the
///    stretch) to min(30 mm, internal iliac origin − 5 mm) below it; where that chord is 20 mm or
///    longer, its start moves down until the iliac's inscribed radius is within 1.2 × its own (the
///    median over the chord's last 10 mm): below a wide distal aorta the first centimetre or two of
///    the iliac's centerline runs on the skeleton of the lumen both iliacs share, lateral of the
///    iliac's axis, and on a 30 mm distal aorta on 2.5 mm slices B read 2.7 mm high from there
///    (0.5 mm with the moved start, FlowDividerPlanTest; chords started at the flow divider instead
///    had raised B on two real AVT aortas); the junction when an
///    iliac chord is shorter than 1 mm, the axes meet farther than 10 mm from it, or — on scans with voxels of 1.25 mm
///    or finer, where the junction lies distal to B — they meet more than 1 mm below it along the aorta: such iliac
///    axes do not run straight up to B, a common iliac that kinks near its start (on the phantoms with 30–45° kinks 10
///    mm below B they met 6–7 mm below B; the junction lies 2.7–3.0 mm below it). On 3 mm slices the junction
///    lay 2.5–5.7 mm above B, so the rule is not applied there, and a kinked start is not recognised. Its abscissa is
///    along the aortic centerline, extended straight past the centerline's end where B lies beyond.
///    **A sac that narrows right into the bifurcation** (no distal neck; recognised where the
///    aorta's inscribed radius falls by more than 2 mm over the 20 mm ending 5 mm above the
///    junction — a distal neck's by ±0.2 mm): the skeleton's junction lies up the funnel, above B
///    (2.3 mm on 1.25 mm slices, 9.8 mm on 3 mm slices in issue 46's sweep), so (1) axes meeting
///    below the junction are B on any slices (the kinked-start rule above fell back to the
///    junction: B 2.3 mm high), and (2) where that first B lies more than 3 mm below the junction,
///    B is found again on each iliac's straight stretch — grown up from the last 10 mm of the
///    iliac's first min(45 mm, internal iliac origin − 5 mm) while the next two points lie within
///    0.5 mm of the line fitted so far, and that least-squares line as its axis: the centerline runs
///    down the funnel's middle before it joins the iliac's axis, and chords from 10 mm below a
///    junction 9.8 mm above B leaned 6° and met 3.8 mm above it on 3 mm slices (the stretch ending
///    30 mm down, as the chords: 1.6–2.2 mm above B on 3 mm funnels, within 0.5 mm ending 45 mm
///    down). Not otherwise: the fitted lines move B by up to 0.7 mm on stretches a millimetre apart,
///    and real common iliacs curve enough (the four AVT cases) that their straight stretches stop
///    16–20 mm down — taken on every scan with slices over 1.25 mm, the stretches moved AVT D2's B
///    by 7.9 mm between the whole scan and the scan cut 40 mm below B. Left: on thick slices the
///    iliacs' centerlines join their axes 15–20 mm below the junction, and where the sac narrows
///    gently, or the junction lies less than 3 mm above the chords' meeting point, B reads 2.2–4.6 mm
///    high (two draws of issue 46's sweep, docs/accuracy.md). (test_funnel_bifurcation.py and
///    FlowDividerPlanTest hold these rules.)
///
/// A landmark a person gave (CenterlineTree::givenBifurcationLps, givenInternalIliacAbscissaMm;
/// GivenLandmarks.h) is returned as it is, in place of the rules above.
///
/// Input: a labelled CenterlineTree (LPS mm) whose aorta has at least two points. Output in LPS mm
/// and mm of arc length. No errors: the fallbacks above are the answer where the axes say nothing.
#pragma once

#include "Centerlines/Centerlines.h"

namespace sgp
{

/// How far down each common iliac B's iliac axis reaches (the chord's end; file comment), mm. A
/// scan that holds less of an iliac below the flow divider (a partial plan) locates B on
/// shorter chords: on the AVT cases cropped 10–20 mm below it, 1.3–7.9 mm from the whole
/// scan's B along the aorta.
constexpr double BifurcationIliacReachMm = 30.0;

/// The internal iliac origin of the right (`side` 0) or left (1) iliac, as an abscissa along
/// that iliac's centerline (mm); NaN when the tree has no internal iliac junction on that side.
double InternalIliacOriginAbscissa(const CenterlineTree& tree, int side);

/// The same found by the rule above, whatever was given (B's iliac chords end at it, so a given
/// origin does not move B).
double FoundInternalIliacOriginAbscissa(const CenterlineTree& tree, int side);

/// Where a common iliac with no internal iliac junction in view narrows into its external iliac
/// (issue 46 item 9: an internal iliac cut off, occluded or lost to the blur): the first abscissa s
/// ≥ `IliacNarrowingSearchFromMm` along `iliac` at which the median inscribed radius over [s, s + 5]
/// is under `IliacNarrowingRatio` of the median over [s − 15, s − 5] (the common iliac just above),
/// mm; NaN when it never narrows so, or the centerline is shorter than 35 mm. The external iliac
/// is about three quarters of the common iliac across (0.6–0.7 of its lumen with a wall); a
/// common iliac tapers by a few per cent over 15 mm. The search starts 30 mm down, its first
/// reference 15 mm down: past the shared lumen above the flow divider (10–14 mm below B on our
/// anatomies), where the inscribed spheres are the aorta's.
double IliacNarrowingAbscissa(const Centerline& iliac);
constexpr double IliacNarrowingSearchFromMm = 30.0;
constexpr double IliacNarrowingRatio = 0.8;

struct AorticBifurcation
{
  Point3 lps = Point3::Zero(); ///< B, LPS mm
  double abscissaMm = 0.0;     ///< along the aorta from its top, mm
  bool axesMeet = false;       ///< false: B is the skeleton's junction (the fallback) or given
  bool given = false;          ///< B is the point a person gave (GivenLandmarks.h)
};

/// B as described in the file comment.
AorticBifurcation FindAorticBifurcation(const CenterlineTree& tree);

} // namespace sgp
