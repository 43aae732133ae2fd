#include "Measurement/MeasureDiameters.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "Common/Errors.h"

namespace
{
constexpr double pi = 3.14159265358979323846;
} // namespace

namespace sgp
{

RingDiameters DiameterProfile::At(double s) const
{
  if (rings.empty())
    return {};
  if (s <= rings.front().abscissaMm)
    return rings.front();
  if (s >= rings.back().abscissaMm)
    return rings.back();
  std::size_t k = 0;
  while (k + 2 < rings.size() && rings[k + 1].abscissaMm < s)
    ++k;
  const RingDiameters &a = rings[k], &b = rings[k + 1];
  const double t = (s - a.abscissaMm) / (b.abscissaMm - a.abscissaMm);
  const auto mix = [t](double x, double y) { return (1 - t) * x + t * y; };
  RingDiameters r;
  r.abscissaMm = s;
  r.meanMm = mix(a.meanMm, b.meanMm);
  r.minMm = mix(a.minMm, b.minMm);
  r.maxMm = mix(a.maxMm, b.maxMm);
  r.areaMm = mix(a.areaMm, b.areaMm);
  r.centre = (1 - t) * a.centre + t * b.centre;
  return r;
}

std::array<DiameterProfile, 3> MeasureRingDiameters(const StentMesh& mesh, const Points& V)
{
  if (V.rows() != mesh.V.rows())
    throw InputError("The surface has " + std::to_string(V.rows()) + " vertices; expected the mesh's " +
                     std::to_string(mesh.V.rows()) + ".");
  const int n = mesh.verticesPerRing;
  std::array<DiameterProfile, 3> profiles;
  const char* names[3] = { "aorta", "rightIliac", "leftIliac" };
  for (int seg = 0; seg < 3; ++seg)
  {
    profiles[seg].vessel = names[seg];
    for (int k = 0; k < mesh.RingsIn(seg); ++k)
    {
      RingDiameters r;
      r.abscissaMm = mesh.ringAbscissaMm[seg][k];
      const int first = mesh.Id(seg, k, 0);
      r.centre = mesh.centre.row(first).transpose();
      const Eigen::Vector3d axis = mesh.axis.row(first).transpose();
      double sum = 0.0, lo = std::numeric_limits<double>::infinity(), hi = 0.0;
      for (int j = 0; j < n / 2; ++j)
      {
        const double d = (V.row(mesh.Id(seg, k, j)) - V.row(mesh.Id(seg, k, j + n / 2))).norm();
        sum += d;
        lo = std::min(lo, d);
        hi = std::max(hi, d);
      }
      double area = 0.0; // shoelace on the ring plane: ½ Σ ((v_j − c) × (v_{j+1} − c))·axis
      for (int j = 0; j < n; ++j)
      {
        const Eigen::Vector3d a = V.row(mesh.Id(seg, k, j)).transpose() - r.centre;
        const Eigen::Vector3d b = V.row(mesh.Id(seg, k, j + 1)).transpose() - r.centre;
        area += 0.5 * a.cross(b).dot(axis);
      }
      r.meanMm = sum / (n / 2);
      r.minMm = lo;
      r.maxMm = hi;
      r.areaMm = 2.0 * std::sqrt(std::abs(area) / pi);
      profiles[seg].rings.push_back(r);
    }
  }
  return profiles;
}

} // namespace sgp
