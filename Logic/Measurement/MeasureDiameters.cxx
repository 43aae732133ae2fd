#include "Measurement/MeasureDiameters.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

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
  r.mouthVertices = std::max(a.mouthVertices, b.mouthVertices);
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
      std::vector<double> radius(static_cast<std::size_t>(n));
      for (int j = 0; j < n; ++j)
        radius[std::size_t(j)] = (V.row(mesh.Id(seg, k, j)).transpose() - r.centre).norm();
      std::vector<double> sorted = radius;
      std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.end());
      const double medianRadius = sorted[std::size_t(n / 2)];
      const auto inMouth = [&](int j) { return radius[std::size_t(j % n)] > BranchMouthRadiusFactor * medianRadius; };
      const auto vertex = [&](int j) -> Eigen::Vector3d
      {
        const Eigen::Vector3d d = V.row(mesh.Id(seg, k, j)).transpose() - r.centre;
        return inMouth(j) ? Eigen::Vector3d(d * (medianRadius / d.norm())) : d;
      };
      double sum = 0.0, lo = std::numeric_limits<double>::infinity(), hi = 0.0;
      int kept = 0;
      for (int j = 0; j < n / 2; ++j)
      {
        if (inMouth(j) || inMouth(j + n / 2))
          continue;
        const double d = (V.row(mesh.Id(seg, k, j)) - V.row(mesh.Id(seg, k, j + n / 2))).norm();
        sum += d;
        lo = std::min(lo, d);
        hi = std::max(hi, d);
        ++kept;
      }
      for (int j = 0; j < n; ++j)
        r.mouthVertices += inMouth(j) ? 1 : 0;
      double area = 0.0; // shoelace on the ring plane: ½ Σ ((v_j − c) × (v_{j+1} − c))·axis
      for (int j = 0; j < n; ++j)
        area += 0.5 * vertex(j).cross(vertex(j + 1)).dot(axis);
      // Fewer than half the vertices exceed the median, so at least one diameter is kept.
      r.meanMm = sum / kept;
      r.minMm = lo;
      r.maxMm = hi;
      r.areaMm = 2.0 * std::sqrt(std::abs(area) / pi);
      profiles[seg].rings.push_back(r);
    }
  }
  return profiles;
}

} // namespace sgp
