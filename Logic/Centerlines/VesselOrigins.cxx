#include "Centerlines/VesselOrigins.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "Common/Median.h"

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

/// The aortic axis and each common iliac's chord (the file comment); the lines found (fewer than
/// three when an iliac is missing or its chord degenerate).
std::vector<Line> BifurcationAxes(const CenterlineTree& tree)
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
    const double end = std::isfinite(origin) ? std::min(BifurcationIliacReachMm, origin - 5.0)
                                             : std::min(BifurcationIliacReachMm, iliac.LengthMm());
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
    if ((PositionAt(iliac, end) - PositionAt(iliac, from)).norm() > 1.0)
      axes.push_back(Chord(iliac, from, end));
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
           (!thin || (at - junction).dot(down) <= belowJunctionToleranceMm);
  };
  AorticBifurcation result;
  if (tree.givenBifurcationLps)
  {
    result.lps = *tree.givenBifurcationLps;
    result.given = true;
    result.abscissaMm = L + (result.lps - junction).dot(down);
    return result;
  }
  result.axesMeet = meet(BifurcationAxes(tree), result.lps);
  // (Chords over the iliacs' first 7 mm from the junction, before a kink 10 mm below B, met at
  // the junction too: the skeleton runs down the middle of the merged cross-section there. The
  // junction it is: 2.7–3.0 mm below B on those phantoms.)
  if (!result.axesMeet)
    result.lps = junction;
  result.abscissaMm = L + (result.lps - junction).dot(down);
  return result;
}

} // namespace sgp
