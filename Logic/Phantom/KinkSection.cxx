// The truth of a diameter near the phantom's neck bend (KinkSection.h).
#include "Phantom/KinkSection.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "Common/PlaneDiameters.h"

namespace sgp::phantom
{
namespace
{

constexpr double pi = 3.14159265358979323846;
constexpr double degToRad = pi / 180.0;
constexpr double marchMm = 0.25, farthestMm = 200.0, precisionMm = 1e-4;

/// Distance from `centre` along unit `e` to the first point outside.
double ExitDistance(const std::function<bool(const Point3&)>& inside, const Point3& centre, const Eigen::Vector3d& e)
{
  double in = 0.0, out = marchMm;
  while (out < farthestMm && inside(centre + out * e))
  {
    in = out;
    out += marchMm;
  }
  while (out - in > precisionMm)
  {
    const double mid = 0.5 * (in + out);
    (inside(centre + mid * e) ? in : out) = mid;
  }
  return 0.5 * (in + out);
}

/// `n` turned by `angle` about the unit `axis` (Rodrigues).
Eigen::Vector3d Turned(const Eigen::Vector3d& n, const Eigen::Vector3d& axis, double angleRad)
{
  return Eigen::AngleAxisd(angleRad, axis) * n;
}

} // namespace

double KinkReachMm(const std::function<double(double)>& otherRadius, double betaRad)
{
  if (!(betaRad > 0.0))
    return 0.0;
  double reach = 0.0;
  for (double u = 0.0; u <= farthestMm; u += 0.1)
    reach = std::max(reach, otherRadius(u) * std::sin(betaRad) - u * std::cos(betaRad));
  return reach;
}

double SectionMeanDiameterMm(const std::function<bool(const Point3&)>& inside,
                             const Point3& centre,
                             const Eigen::Vector3d& normal,
                             int directions)
{
  return MeanDiameterInPlane(normal, directions,
                             [&](const Eigen::Vector3d& e) { return ExitDistance(inside, centre, e); });
}

double SmallestSectionMeanDiameterMm(const std::function<bool(const Point3&)>& inside,
                                     const Point3& centre,
                                     const Eigen::Vector3d& from,
                                     const Eigen::Vector3d& to)
{
  const Eigen::Vector3d a = from.normalized(), b = to.normalized();
  Eigen::Vector3d bendAxis = a.cross(b); // ⊥ the plane of the bend
  const double arc = std::atan2(bendAxis.norm(), a.dot(b));
  if (bendAxis.norm() < 1e-12)
  {
    const Eigen::Vector3d other = std::abs(a.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    bendAxis = a.cross(other);
  }
  bendAxis.normalize();
  // φ along the arc from `from`, ψ out of the bend's plane (about the in-plane ⊥ of the normal).
  const auto normalAt = [&](double phiDeg, double psiDeg)
  {
    const Eigen::Vector3d inPlane = Turned(a, bendAxis, phiDeg * degToRad);
    return Turned(inPlane, inPlane.cross(bendAxis).normalized(), psiDeg * degToRad);
  };
  const double margin = 10.0, arcDeg = arc / degToRad;
  double best = SectionMeanDiameterMm(inside, centre, a), bestPhi = 0.0, bestPsi = 0.0;
  const auto consider = [&](double phi, double psi)
  {
    const double d = SectionMeanDiameterMm(inside, centre, normalAt(phi, psi));
    if (d < best)
    {
      best = d;
      bestPhi = phi;
      bestPsi = psi;
    }
  };
  for (double phi = -margin; phi <= arcDeg + margin + 1e-9; phi += 1.0)
    consider(phi, 0.0);
  for (double psi = -margin; psi <= margin + 1e-9; psi += 1.0)
    consider(bestPhi, psi);
  const double phi0 = bestPhi, psi0 = bestPsi;
  for (double dphi = -1.0; dphi <= 1.0 + 1e-9; dphi += 0.2)
    for (double dpsi = -1.0; dpsi <= 1.0 + 1e-9; dpsi += 0.2)
      consider(phi0 + dphi, psi0 + dpsi);
  return best;
}

} // namespace sgp::phantom
