#include "Centerlines/VesselOrigins.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "Common/Median.h"
#include "Common/PrincipalLine.h"

namespace sgp
{
namespace
{

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double snapMm = 10.0;       ///< axes meeting farther from the junction are not trusted
constexpr double minimumSkipMm = 5.0; ///< the least length of a branch's centerline left out at a junction
constexpr double chordMm = 15.0;      ///< each internal iliac chord's length
/// B's iliac chords start where the inscribed radius is within this of the iliac's own.
constexpr double SharedLumenRadiusRatio = 1.2;
/// How far below the skeleton's junction (along the aorta) the axes may meet and still be B, mm:
/// straight iliacs met 0.3–2.5 mm above it on the phantoms (LandmarksPlanTest, IliacVariants).
constexpr double belowJunctionToleranceMm = 1.0;
/// The iliac chord's straight stretch: the distal length it grows from, and how far (mm) a point
/// may lie off the line fitted to it: the skeleton's points scatter ±0.2 mm about a straight
/// phantom iliac's axis on 0.6–0.9 mm voxels (3 mm slices included); where the funnel's
/// centerline leaves the axis it is 1.2 mm off within 3 mm.
constexpr double StraightSeedMm = 10.0;
/// …and how far down the iliac the straight stretch may reach, mm (BifurcationIliacReachMm for
/// the first chords). A line fitted to 10–15 mm of centerline scattering ±0.3 mm points 2–3° off
/// the axis; extrapolated 20–30 mm up to B that is a millimetre across, and B's height error is
/// the lateral one over the tangent of the iliac's angle off the aorta (25–45°). Lines fitted to
/// the centerlines of three 2.5–3 mm sacs narrowing into B (issue 46's sweep, seed 246) met
/// 1.3–3.7 mm above B over 10–30 mm below the junction, within 0.8 mm over 20–45 mm.
constexpr double StraightIliacReachMm = 45.0;
constexpr double StraightToleranceMm = 0.5;
/// A funnel, where the belowJunctionToleranceMm rule is not applied: the aorta narrows into the
/// junction (a sac with no distal neck) — its inscribed radius falls by more than
/// funnelNarrowingPerMm per mm over the funnelSpanMm that end funnelEndMm above the junction (a
/// distal neck's by ±0.2 mm over it, a half-sine sac's floor by 0.25–1 mm per mm). There the
/// junction lies up the funnel: 2.3 mm above B on 1.25 mm slices in issue 46's sweep, where the
/// axes met 0.3 mm from B.
constexpr double funnelSpanMm = 20.0;
constexpr double funnelEndMm = 5.0;
constexpr double funnelNarrowingPerMm = 0.1;
/// Down a funnel, the junction this far above the axes' first meeting point (along the aorta), mm,
/// calls for the straight stretches: 2.3 mm on 1.25 mm slices (where the chords met right: 0.3 mm
/// from B), 6 mm on 3 mm slices (3.8 mm above B) in issue 46's sweep.
constexpr double junctionAboveBMm = 3.0;
/// …on scans this fine or finer, mm: on 3 mm slices the junction itself lay 2.5–5.7 mm above B
/// (15–55 mm common iliacs), and the axes met within 0.3–1.0 mm of B for 20–55 mm ones.
constexpr double junctionDistalMaxSpacingMm = 1.25;

using Line = std::pair<Point3, Eigen::Vector3d>; ///< a point on the line and its unit direction

/// The point nearest to the lines in the least-squares sense.
Point3 NearestToLines(const std::vector<Line>& lines)
{
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (const auto& [p, d] : lines)
  {
    const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - d * d.transpose();
    A += P;
    b += P * p;
  }
  return A.ldlt().solve(b);
}

/// The chord of `c` from arc length `from` to `to` (clamped to the centerline) as a line.
Line Chord(const Centerline& c, double from, double to)
{
  const Point3 a = PositionAt(c, from), b = PositionAt(c, to);
  return { b, (b - a).normalized() };
}

const char* Side(int side)
{
  return side == 0 ? "right" : "left";
}

} // namespace

double FoundInternalIliacOriginAbscissa(const CenterlineTree& tree, int side)
{
  const Centerline& iliac = side == 0 ? tree.rightIliac : tree.leftIliac;
  const Landmark* junctionLandmark = tree.FindLandmark(std::string(Side(side)) + "IliacBifurcation");
  if (!junctionLandmark || iliac.Size() < 2)
    return nan;
  const double junction = ProjectOntoCenterline(iliac, junctionLandmark->lps);
  const Centerline* internal = tree.FindVessel(std::string(Side(side)) + "InternalIliac");
  if (!internal || internal->Size() < 2)
    return junction;
  // Within about the two vessels' radii of the junction the skeleton bends into the merged
  // cross-section: the chords start beyond that.
  const double skip =
    std::max(minimumSkipMm, RadiusAt(iliac, junction - chordMm) + RadiusAt(*internal, minimumSkipMm + chordMm));
  if (internal->LengthMm() < skip + chordMm || junction < skip + 5.0 || iliac.LengthMm() - junction < skip + 5.0)
    return junction;
  const std::vector<Line> axes = { Chord(iliac, std::max(0.0, junction - skip - chordMm), junction - skip),
                                   Chord(iliac, junction + skip, std::min(iliac.LengthMm(), junction + skip + chordMm)),
                                   Chord(*internal, skip, skip + chordMm) };
  const Point3 origin = NearestToLines(axes);
  if (!origin.allFinite() || (origin - PositionAt(iliac, junction)).norm() > snapMm)
    return junction;
  return ProjectOntoCenterline(iliac, origin);
}

double IliacNarrowingAbscissa(const Centerline& iliac)
{
  const Eigen::Index n = iliac.Size();
  const auto medianOver = [&](double from, double to)
  {
    std::vector<double> radii;
    for (Eigen::Index i = 0; i < n; ++i)
      if (iliac.abscissaMm[i] >= from - 1e-9 && iliac.abscissaMm[i] <= to + 1e-9)
        radii.push_back(iliac.radiusMm[i]);
    return radii.empty() ? std::numeric_limits<double>::quiet_NaN() : Median(radii);
  };
  const double length = iliac.LengthMm();
  for (double s = IliacNarrowingSearchFromMm; s + 5.0 <= length + 1e-9; s += 0.5)
  {
    const double above = medianOver(s - 15.0, s - 5.0), here = medianOver(s, s + 5.0);
    if (std::isfinite(above) && std::isfinite(here) && here < IliacNarrowingRatio * above)
      return s;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

double InternalIliacOriginAbscissa(const CenterlineTree& tree, int side)
{
  if (std::isfinite(tree.givenInternalIliacAbscissaMm[std::size_t(side)]))
    return tree.givenInternalIliacAbscissaMm[std::size_t(side)];
  return FoundInternalIliacOriginAbscissa(tree, side);
}

namespace
{

/// A sac that narrows right into the bifurcation (the constants' comment): the skeleton's junction
/// lies up its funnel, above B.
bool NarrowsIntoTheJunction(const Centerline& aorta)
{
  const double L = aorta.LengthMm();
  return L > funnelSpanMm + funnelEndMm &&
         RadiusAt(aorta, L - funnelSpanMm - funnelEndMm) - RadiusAt(aorta, L - funnelEndMm) >
           funnelNarrowingPerMm * funnelSpanMm;
}

/// The least-squares line through `c`'s points every 1 mm over [from, to] (its centroid and
/// principal direction).
Line FitLine(const Centerline& c, double from, double to)
{
  std::vector<Point3> points;
  for (double s = from; s <= to + 1e-9; s += 1.0)
    points.push_back(PositionAt(c, s));
  return PrincipalLine(points);
}

double DistanceToLine(const Point3& p, const Line& line)
{
  const Eigen::Vector3d offset = p - line.first;
  return (offset - offset.dot(line.second) * line.second).norm();
}

/// Where the straight stretch of `iliac` that ends at `end` begins (arc length, mm): grown up from
/// its last StraightSeedMm, 1 mm at a time, while the next two points up lie within
/// StraightToleranceMm of the line fitted to the stretch so far. Where the sac narrows right into
/// the bifurcation (no distal neck), the skeleton's junction lies up the funnel, 2–10 mm above B, and
/// the iliac's first 10–15 mm of centerline runs down the funnel's middle before it joins the
/// iliac's axis: a chord from 10 mm below the junction tilted 6° toward the midline and met 3.8 mm
/// above B on 3 mm slices (issue 46's sweep).
double StraightFrom(const Centerline& iliac, double end)
{
  double start = std::max(0.0, end - StraightSeedMm);
  while (start >= 2.0)
  {
    const Line line = FitLine(iliac, start, end);
    if (DistanceToLine(PositionAt(iliac, start - 1.0), line) > StraightToleranceMm &&
        DistanceToLine(PositionAt(iliac, start - 2.0), line) > StraightToleranceMm)
      break;
    start -= 1.0;
  }
  return start;
}

/// The aortic axis and each common iliac's chord (the file comment); the lines found (fewer than
/// three when an iliac is missing or its chord degenerate). `straight`: each iliac's chord starts
/// no higher than its straight stretch (StraightFrom) and is the line fitted to it.
std::vector<Line> BifurcationAxes(const CenterlineTree& tree, bool straight)
{
  const Centerline& aorta = tree.aorta;
  const double L = aorta.LengthMm();
  std::vector<Line> axes = { Chord(aorta, L - 25.0, L - 5.0) };
  for (int side = 0; side < 2; ++side)
  {
    const Centerline& iliac = side == 0 ? tree.rightIliac : tree.leftIliac;
    if (iliac.Size() < 2)
      continue;
    // The found origin, not a given one: B does not move with an internal iliac origin given.
    const double origin = FoundInternalIliacOriginAbscissa(tree, side);
    const double reach = straight ? StraightIliacReachMm : BifurcationIliacReachMm;
    const double end = std::isfinite(origin) ? std::min(reach, origin - 5.0) : std::min(reach, iliac.LengthMm());
    double from = std::min(10.0, 0.5 * end);
    // Below a wide distal aorta the iliac's first centimetre or two still runs in the lumen both
    // iliacs share, on the skeleton of that lumen (lateral of the iliac's axis: B read 2.7 mm high
    // on a 30 mm distal aorta on 2.5 mm slices): the chord starts where the inscribed radius has
    // come down to within SharedLumenRadiusRatio of the iliac's own (the median over the chord's
    // last 10 mm), keeping at least 10 mm of chord.
    if (end - from >= 20.0)
    {
      std::vector<double> own;
      for (double s = end - 10.0; s <= end + 1e-9; s += 1.0)
        own.push_back(RadiusAt(iliac, s));
      const double ownRadius = Median(own);
      while (from < end - 10.0 && RadiusAt(iliac, from) > SharedLumenRadiusRatio * ownRadius)
        from += 0.5;
    }
    if (straight)
      from = std::max(from, StraightFrom(iliac, end));
    if ((PositionAt(iliac, end) - PositionAt(iliac, from)).norm() > 1.0)
      axes.push_back(straight ? FitLine(iliac, from, end) : Chord(iliac, from, end));
  }
  return axes;
}

} // namespace

AorticBifurcation FindAorticBifurcation(const CenterlineTree& tree)
{
  const Centerline& aorta = tree.aorta;
  const double L = aorta.LengthMm();
  const Point3 junction = aorta.points.row(aorta.Size() - 1).transpose();
  const Eigen::Vector3d down = TangentAt(aorta, L);
  const bool funnel = NarrowsIntoTheJunction(aorta);
  // Where the axes meet, if they meet near the junction and not below it: the junction lies in the
  // merged cross-section, distal to B, so axes meeting more than belowJunctionToleranceMm below it
  // do not run straight up to B (a common iliac that kinks near its start).
  const auto meet = [&](const std::vector<Line>& axes, Point3& at)
  {
    if (axes.size() != 3)
      return false;
    at = NearestToLines(axes);
    const bool thin = tree.largestSpacingMm <= junctionDistalMaxSpacingMm; // false when not known (NaN)
    return at.allFinite() && (at - junction).norm() <= snapMm &&
           (!thin || funnel || (at - junction).dot(down) <= belowJunctionToleranceMm);
  };
  AorticBifurcation result;
  if (tree.givenBifurcationLps)
  {
    result.lps = *tree.givenBifurcationLps;
    result.given = true;
    result.abscissaMm = L + (result.lps - junction).dot(down);
    return result;
  }
  result.axesMeet = meet(BifurcationAxes(tree, false), result.lps);
  // Down a funnel whose junction lies well above the axes' meeting point, the iliac chords 10 mm
  // below the junction can start on the funnel's centerline (it runs down the funnel's middle
  // before it joins the iliac's axis: 1.2 mm off it 11 mm down on 3 mm slices, the chords leaning
  // 6° and meeting 3.8 mm above B): once more on each iliac's straight stretch. Not where the
  // junction lies near or below B (a 0.625 mm funnel whose junction lay 8 mm below B: the fitted
  // lines, on stretches that differ by a millimetre, moved B 0.7 mm up its 1.5 mm-per-mm floor).
  Point3 again;
  if (funnel && result.axesMeet && (junction - result.lps).dot(down) < -junctionAboveBMm &&
      meet(BifurcationAxes(tree, true), again))
    result.lps = again;
  // (Chords over the iliacs' first 7 mm from the junction, before a kink 10 mm below B, met at
  // the junction too: the skeleton runs down the middle of the merged cross-section there. The
  // junction it is: 2.7–3.0 mm below B on those phantoms.)
  if (!result.axesMeet)
    result.lps = junction;
  result.abscissaMm = L + (result.lps - junction).dot(down);
  return result;
}

} // namespace sgp
