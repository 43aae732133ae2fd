#include "Centerlines/VesselOrigins.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

namespace sgp
{
namespace
{

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double snapMm = 10.0;       ///< axes meeting farther from the junction are not trusted
constexpr double minimumSkipMm = 5.0; ///< the least length of a branch's centerline left out at a junction
constexpr double chordMm = 15.0;      ///< each internal iliac chord's length

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

double InternalIliacOriginAbscissa(const CenterlineTree& tree, int side)
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

AorticBifurcation FindAorticBifurcation(const CenterlineTree& tree)
{
  const Centerline& aorta = tree.aorta;
  const double L = aorta.LengthMm();
  const Point3 junction = aorta.points.row(aorta.Size() - 1).transpose();
  std::vector<Line> axes = { Chord(aorta, L - 25.0, L - 5.0) };
  for (int side = 0; side < 2; ++side)
  {
    const Centerline& iliac = side == 0 ? tree.rightIliac : tree.leftIliac;
    if (iliac.Size() < 2)
      continue;
    const double origin = InternalIliacOriginAbscissa(tree, side);
    const double end = std::isfinite(origin) ? std::min(BifurcationIliacReachMm, origin - 5.0)
                                             : std::min(BifurcationIliacReachMm, iliac.LengthMm());
    const double from = std::min(10.0, 0.5 * end);
    if ((PositionAt(iliac, end) - PositionAt(iliac, from)).norm() > 1.0)
      axes.push_back(Chord(iliac, from, end));
  }
  AorticBifurcation result;
  result.lps = axes.size() == 3 ? NearestToLines(axes) : junction;
  result.axesMeet = axes.size() == 3 && result.lps.allFinite() && (result.lps - junction).norm() <= snapMm;
  if (!result.axesMeet)
    result.lps = junction;
  result.abscissaMm = L + (result.lps - junction).dot(TangentAt(aorta, L));
  return result;
}

} // namespace sgp
