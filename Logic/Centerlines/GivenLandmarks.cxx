#include "Centerlines/GivenLandmarks.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

#include "Common/Errors.h"
#include "Common/Format.h"

namespace sgp
{
namespace
{

const char* SideName(int side)
{
  return side == 0 ? "right" : "left";
}

/// The given origin's abscissa along its iliac, after the checks of the file comment.
double CheckedOriginAbscissa(const CenterlineTree& tree, int side, const Point3& origin)
{
  const Centerline& own = side == 0 ? tree.rightIliac : tree.leftIliac;
  const Centerline& other = side == 0 ? tree.leftIliac : tree.rightIliac;
  const std::string name = std::string(SideName(side)) + "InternalIliacOrigin";
  if (own.Size() < 2)
    throw InputError(name + " was given at " + FormatPoint(origin) + " mm LPS, but the plan holds no " +
                     SideName(side) + " iliac centerline to put it on; expected a scan that shows the " +
                     SideName(side) + " common iliac artery.");
  double distance = 0.0, otherDistance = std::numeric_limits<double>::infinity();
  const double s = ProjectOntoCenterline(own, origin, &distance);
  if (other.Size() >= 2)
    ProjectOntoCenterline(other, origin, &otherDistance);
  if (otherDistance < distance)
    throw InputError(name + " was given at " + FormatPoint(origin) + " mm LPS, on the patient's " + SideName(1 - side) +
                     ": " + FormatNumber(otherDistance) + " mm from the " + SideName(1 - side) +
                     " iliac centerline and " + FormatNumber(distance) + " mm from the " + SideName(side) +
                     " one; expected a point on the " + SideName(side) + " iliac (right is -x in LPS, +x in RAS).");
  if (distance > MaxOriginDistanceMm)
    throw InputError(name + " was given " + FormatNumber(distance) + " mm from the " + SideName(side) +
                     " iliac centerline (nearest point " + FormatPoint(PositionAt(own, s)) +
                     " mm LPS); expected a point within " + FormatNumber(MaxOriginDistanceMm, 0) +
                     " mm of it, where the internal iliac branches.");
  return s;
}

/// Makes the side branch of `side`'s iliac nearest to the origin (within SnapBranchMm along the
/// iliac) its internal iliac, numbering the one the labelling took if it is another.
void NameInternalIliac(CenterlineTree& tree, int side, double originMm)
{
  const std::string prefix = SideName(side);
  const Centerline& iliac = side == 0 ? tree.rightIliac : tree.leftIliac;
  Centerline* nearest = nullptr;
  double best = SnapBranchMm;
  int numbered = 0;
  for (Centerline& branch : tree.sideBranches)
  {
    const bool onIliac = branch.name == prefix + "InternalIliac" || branch.name.rfind(prefix + "IliacBranch", 0) == 0;
    if (!onIliac || branch.Size() < 2)
      continue;
    if (branch.name != prefix + "InternalIliac")
      numbered = std::max(numbered, std::atoi(branch.name.c_str() + (prefix + "IliacBranch").size()));
    const double along = std::abs(ProjectOntoCenterline(iliac, branch.points.row(0).transpose()) - originMm);
    if (along <= best)
    {
      best = along;
      nearest = &branch;
    }
  }
  for (Centerline& branch : tree.sideBranches)
    if (branch.name == prefix + "InternalIliac" && &branch != nearest)
      branch.name = prefix + "IliacBranch" + std::to_string(++numbered);
  const Point3 at = PositionAt(iliac, originMm);
  bool marked = false;
  for (Landmark& l : tree.landmarks)
    if (l.name == prefix + "IliacBifurcation")
    {
      l.lps = nearest ? Point3(nearest->points.row(0).transpose()) : at;
      marked = true;
    }
  if (!marked)
    tree.landmarks.push_back(
      { prefix + "IliacBifurcation", nearest ? Point3(nearest->points.row(0).transpose()) : at });
  if (nearest)
    nearest->name = prefix + "InternalIliac";
}

} // namespace

void ApplyGivenLandmarks(CenterlineTree& tree, const GivenLandmarks& given)
{
  if (given.aorticBifurcationLps)
  {
    if (tree.aorta.Size() < 2)
      throw InputError("aorticBifurcation was given, but the plan holds no aortic centerline to put it on.");
    const Point3 end = tree.aorta.points.row(tree.aorta.Size() - 1).transpose();
    const double distance = (*given.aorticBifurcationLps - end).norm();
    if (distance > MaxBifurcationDistanceMm)
      throw InputError("aorticBifurcation was given at " + FormatPoint(*given.aorticBifurcationLps) + " mm LPS, " +
                       FormatNumber(distance) + " mm from the aortic centerline's lower end " + FormatPoint(end) +
                       " mm LPS; expected a point within " + FormatNumber(MaxBifurcationDistanceMm, 0) +
                       " mm of it, where the aorta divides into the common iliacs.");
  }
  // Both origins are checked before either is applied (a renamed branch changes no distance).
  std::array<double, 2> origin{ std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN() };
  for (int side = 0; side < 2; ++side)
    if (given.internalIliacOriginLps[std::size_t(side)])
      origin[std::size_t(side)] = CheckedOriginAbscissa(tree, side, *given.internalIliacOriginLps[std::size_t(side)]);
  for (int side = 0; side < 2; ++side)
    if (std::isfinite(origin[std::size_t(side)]))
    {
      NameInternalIliac(tree, side, origin[std::size_t(side)]);
      tree.givenInternalIliacAbscissaMm[std::size_t(side)] = origin[std::size_t(side)];
    }
  if (given.aorticBifurcationLps)
    tree.givenBifurcationLps = given.aorticBifurcationLps;
}

} // namespace sgp
