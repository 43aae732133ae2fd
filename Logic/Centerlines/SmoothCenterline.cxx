#include "Centerlines/SmoothCenterline.h"

#include <algorithm>
#include <cmath>

#include "Common/CheckRange.h"

namespace sgp
{

namespace
{

/// Points (with radii) every `step` of arc length along the polyline, plus its end.
void Resample(const Centerline& c, double step, std::vector<Point3>& points, std::vector<double>& radii)
{
  points.clear();
  radii.clear();
  const Eigen::Index n = c.Size();
  if (n == 1)
  {
    points.push_back(c.points.row(0).transpose());
    radii.push_back(c.radiusMm[0]);
    return;
  }
  const double length = c.LengthMm();
  Eigen::Index segment = 0;
  for (double s = 0.0; s < length - 1e-9; s += step)
  {
    while (segment + 2 < n && c.abscissaMm[segment + 1] < s)
      ++segment;
    const double s0 = c.abscissaMm[segment], s1 = c.abscissaMm[segment + 1];
    const double t = s1 > s0 ? std::clamp((s - s0) / (s1 - s0), 0.0, 1.0) : 0.0;
    points.push_back(((1 - t) * c.points.row(segment) + t * c.points.row(segment + 1)).transpose());
    radii.push_back((1 - t) * c.radiusMm[segment] + t * c.radiusMm[segment + 1]);
  }
  points.push_back(c.points.row(n - 1).transpose());
  radii.push_back(c.radiusMm[n - 1]);
}

} // namespace

Centerline SmoothCenterline(const Centerline& raw, double stepMm, double smoothingMm)
{
  CheckRange("centerlineStepMm", stepMm, 0.1, 10.0, "mm");
  CheckRange("centerlineSmoothingMm", smoothingMm, 0.0, 20.0, "mm");
  std::vector<Point3> fine;
  std::vector<double> fineRadii;
  const double fineStep = stepMm / 10.0;
  Resample(raw, fineStep, fine, fineRadii);
  const long n = static_cast<long>(fine.size());
  // One Gaussian pass of width σ_i about each point i (a symmetric window: the ends stay put).
  const auto smoothAt = [&](long i, double sigma, const auto& value)
  {
    const long reach = sigma > 0 ? static_cast<long>(std::ceil(3.0 * sigma / fineStep)) : 0;
    const long half = std::min({ reach, i, n - 1 - i });
    decltype(value(i)) sum = value(i) * 0.0;
    double weights = 0.0;
    for (long j = i - half; j <= i + half; ++j)
    {
      const double x = (j - i) * fineStep / std::max(sigma, 1e-9);
      const double w = std::exp(-0.5 * x * x);
      sum += w * value(j);
      weights += w;
    }
    return decltype(value(i))(sum / weights);
  };
  std::vector<double> smoothRadii(fine.size());
  for (long i = 0; i < n; ++i)
    smoothRadii[i] = smoothAt(i, smoothingMm, [&](long j) { return fineRadii[j]; });
  std::vector<Point3> smooth(fine.size());
  for (long i = 0; i < n; ++i)
  {
    const double sigma = smoothingMm > 0 ? std::max(smoothingMm, WideVesselSmoothingPerRadius * smoothRadii[i]) : 0.0;
    smooth[i] = smoothAt(i, sigma, [&](long j) -> Point3 { return fine[j]; });
  }
  std::vector<Point3> points;
  std::vector<double> radii;
  Resample(MakeCenterline(raw.name, smooth, smoothRadii), stepMm, points, radii);
  if (points.size() == 1)
  {
    points.push_back(points.front());
    radii.push_back(radii.front());
  }
  return MakeCenterline(raw.name, points, radii);
}

} // namespace sgp
