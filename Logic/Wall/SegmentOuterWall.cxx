#include "Wall/SegmentOuterWall.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "Common/CheckRange.h"
#include "Common/Errors.h"
#include "Common/Median.h"

namespace sgp
{
namespace
{

constexpr double pi = 3.14159265358979323846;

/// Trilinear HU at an LPS point (the nearest edge voxel's value outside the grid's centres).
class HuSampler
{
public:
  explicit HuSampler(const CtImage& ct)
    : m_Ct(ct)
    , m_Size(ct.GetLargestPossibleRegion().GetSize())
  {
  }
  double operator()(const Point3& lps) const
  {
    itk::Point<double, 3> p;
    for (int a = 0; a < 3; ++a)
      p[a] = lps[a];
    itk::ContinuousIndex<double, 3> c;
    m_Ct.TransformPhysicalPointToContinuousIndex(p, c);
    long base[3];
    double t[3];
    for (int a = 0; a < 3; ++a)
    {
      const double x = std::clamp(c[a], 0.0, double(m_Size[a] - 1));
      base[a] = std::min(static_cast<long>(std::floor(x)), long(m_Size[a]) - 2);
      t[a] = x - base[a];
    }
    const short* data = m_Ct.GetBufferPointer();
    const long sj = long(m_Size[0]), sk = long(m_Size[0] * m_Size[1]);
    double value = 0.0;
    for (int corner = 0; corner < 8; ++corner)
    {
      const int di = corner & 1, dj = (corner >> 1) & 1, dk = (corner >> 2) & 1;
      const double w = (di ? t[0] : 1 - t[0]) * (dj ? t[1] : 1 - t[1]) * (dk ? t[2] : 1 - t[2]);
      value += w * data[(base[0] + di) + (base[1] + dj) * sj + (base[2] + dk) * sk];
    }
    return value;
  }

private:
  const CtImage& m_Ct;
  const itk::Size<3> m_Size;
};

bool InLumen(const LabelImage& lumen, const Point3& lps)
{
  itk::Point<double, 3> p;
  for (int a = 0; a < 3; ++a)
    p[a] = lps[a];
  itk::Index<3> index;
  return lumen.TransformPhysicalPointToIndex(p, index) && lumen.GetPixel(index) != 0;
}

/// Kåsa's algebraic circle fit: centre (x, y) and radius from points (n × 2), n ≥ 3.
Eigen::Vector3d FitCircle(const std::vector<Eigen::Vector2d>& points)
{
  Eigen::MatrixXd A(points.size(), 3);
  Eigen::VectorXd b(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    A.row(i) << 2 * points[i].x(), 2 * points[i].y(), 1.0;
    b[i] = points[i].squaredNorm();
  }
  const Eigen::Vector3d x = A.colPivHouseholderQr().solve(b);
  return { x[0], x[1], std::sqrt(std::max(0.0, x[2] + x[0] * x[0] + x[1] * x[1])) };
}

/// Where the ray from the circle's centre frame origin along u meets the circle (x, y, R).
double RayCircle(const Eigen::Vector3d& circle, const Eigen::Vector2d& u)
{
  const Eigen::Vector2d c = circle.head<2>();
  const double b = u.dot(c);
  return b + std::sqrt(std::max(0.0, b * b - c.squaredNorm() + circle[2] * circle[2]));
}

} // namespace

const OuterWallPlane* OuterWall::Nearest(double s) const
{
  const OuterWallPlane* best = nullptr;
  for (const OuterWallPlane& p : planes)
    if (!best || std::abs(p.abscissaMm - s) < std::abs(best->abscissaMm - s))
      best = &p;
  return best;
}

void ValidateOuterWallParams(const OuterWallParams& p)
{
  CheckRange("stepMm", p.stepMm, 1e-3, 20, "mm");
  CheckRange("rays", p.rays, 16, 360, "");
  CheckRange("sampleMm", p.sampleMm, 1e-3, 2, "mm");
  CheckRange("maxRadiusMm", p.maxRadiusMm, 5, 100, "mm");
  CheckRange("outlierMm", p.outlierMm, 0.1, 20, "mm");
  CheckRange("minimumSupport", p.minimumSupport, 0, 1, "");
}

OuterWall SegmentOuterWall(const CtImage& ct,
                           const LabelImage& lumen,
                           const Centerline& vessel,
                           double fromMm,
                           double toMm,
                           const OuterWallParams& params)
{
  ValidateOuterWallParams(params);
  if (vessel.Size() < 2)
    throw InputError("The centerline " + vessel.name + " has fewer than two points; no outer wall can be traced.");
  if (ct.GetLargestPossibleRegion() != lumen.GetLargestPossibleRegion())
    throw InputError("The CT and the lumen mask are on different grids; the outer wall needs both on one.");
  const HuSampler hu(ct);
  const int K = params.rays;
  const int samples = static_cast<int>(params.maxRadiusMm / params.sampleMm);
  OuterWall wall;
  for (double s = std::max(0.0, fromMm); s <= std::min(toMm, vessel.LengthMm()) + 1e-9; s += params.stepMm)
  {
    OuterWallPlane plane;
    plane.abscissaMm = s;
    plane.centreLps = PositionAt(vessel, s);
    const Eigen::Vector3d t = TangentAt(vessel, s);
    Eigen::Vector3d u = t.cross(Eigen::Vector3d::UnitX());
    if (u.norm() < 0.3)
      u = t.cross(Eigen::Vector3d::UnitY());
    u.normalize();
    const Eigen::Vector3d v = t.cross(u);
    // 1. Profiles from the lumen's edge outward.
    std::vector<std::vector<double>> profile(K);
    std::vector<int> edge(K, samples);
    std::vector<Eigen::Vector2d> direction(K);
    std::vector<double> insideLevels, fatLevels;
    for (int k = 0; k < K; ++k)
    {
      const double angle = 2 * pi * k / K;
      direction[k] = Eigen::Vector2d(std::cos(angle), std::sin(angle));
      const Eigen::Vector3d d = direction[k].x() * u + direction[k].y() * v;
      profile[k].resize(samples);
      for (int j = 0; j < samples; ++j)
      {
        const Point3 x = plane.centreLps + (j * params.sampleMm) * d;
        profile[k][j] = hu(x);
        if (edge[k] == samples && j > 0 && !InLumen(lumen, x))
          edge[k] = j;
      }
      const int inside = edge[k] + static_cast<int>(params.insideMm / params.sampleMm);
      if (inside < samples)
        insideLevels.push_back(profile[k][inside]);
      for (int j = edge[k]; j < samples; ++j)
        if (profile[k][j] < params.fatBelowHu)
          fatLevels.push_back(profile[k][j]);
    }
    plane.lumenRadiusMm.resize(K);
    for (int k = 0; k < K; ++k)
      plane.lumenRadiusMm[k] = edge[k] * params.sampleMm;
    // 2. The boundary level: halfway from the vessel's layer to the fat.
    const bool hasFat = !fatLevels.empty() && !insideLevels.empty();
    const double threshold = hasFat ? 0.5 * (Median(insideLevels) + Median(fatLevels)) : 0.0;
    // 3. Candidates.
    std::vector<double> candidate(K, -1.0);
    const int minimumWall = static_cast<int>(std::ceil(params.minimumWallMm / params.sampleMm));
    const int support = static_cast<int>(std::ceil(params.fatSupportMm / params.sampleMm));
    for (int k = 0; hasFat && k < K; ++k)
      for (int j = edge[k] + minimumWall; j + 1 < samples; ++j)
        if (profile[k][j] >= threshold && profile[k][j + 1] < threshold)
        {
          bool fat = false;
          for (int q = j + 1; q < std::min(samples, j + 1 + support) && !fat; ++q)
            fat = profile[k][q] < params.fatBelowHu;
          if (fat)
          {
            const double f = (profile[k][j] - threshold) / (profile[k][j] - profile[k][j + 1]);
            candidate[k] = (j + f) * params.sampleMm;
          }
          break; // the first crossing decides: beyond it lies what is not this vessel
        }
    // 4. Robust circle: drop candidates beyond it, refit.
    std::vector<bool> kept(K);
    for (int k = 0; k < K; ++k)
      kept[k] = candidate[k] > 0.0;
    Eigen::Vector3d circle(0.0, 0.0, 0.0);
    for (int iteration = 0; iteration < 20; ++iteration)
    {
      std::vector<Eigen::Vector2d> points;
      for (int k = 0; k < K; ++k)
        if (kept[k])
          points.push_back(candidate[k] * direction[k]);
      if (points.size() < 3)
        break;
      circle = FitCircle(points);
      bool changed = false;
      for (int k = 0; k < K; ++k)
        if (kept[k] && candidate[k] > RayCircle(circle, direction[k]) + params.outlierMm)
        {
          kept[k] = false;
          changed = true;
        }
      if (!changed)
        break;
    }
    // The rays beside a sector without a boundary still see the neighbour's blurred edge (its
    // first fat crossing lies up to a millimetre out): they are not supported either.
    const std::vector<bool> before = kept;
    for (int k = 0; k < K; ++k)
      if (before[k] && (!before[(k + 1) % K] || !before[(k + K - 1) % K]))
        kept[k] = false;
    std::vector<Eigen::Vector2d> keptPoints;
    for (int k = 0; k < K; ++k)
      if (kept[k])
        keptPoints.push_back(candidate[k] * direction[k]);
    if (keptPoints.size() >= 3)
      circle = FitCircle(keptPoints);
    int supported = 0;
    for (int k = 0; k < K; ++k)
      supported += kept[k] ? 1 : 0;
    plane.supportedFraction = double(supported) / K;
    plane.flagged = plane.supportedFraction < params.minimumSupport || circle[2] <= 0.0;
    if (supported < 3)
      continue; // no outer wall can be drawn in this plane
    plane.supported = kept;
    plane.outerRadiusMm.resize(K);
    plane.contourLps.resize(K, 3);
    for (int k = 0; k < K; ++k)
    {
      const double r = kept[k] && !plane.flagged ? candidate[k] : RayCircle(circle, direction[k]);
      plane.outerRadiusMm[k] = std::max(r, plane.lumenRadiusMm[k]);
      const Eigen::Vector3d d = direction[k].x() * u + direction[k].y() * v;
      plane.contourLps.row(k) = (plane.centreLps + plane.outerRadiusMm[k] * d).transpose();
    }
    double area = 0.0;
    for (int k = 0; k < K; ++k)
      area += 0.5 * plane.outerRadiusMm[k] * plane.outerRadiusMm[(k + 1) % K] * std::sin(2 * pi / K);
    plane.areaDiameterMm = 2.0 * std::sqrt(area / pi);
    for (int a = 0; a < K; ++a)
      for (int b = a + 1; b < K; ++b)
        plane.maxCaliperMm = std::max(plane.maxCaliperMm, (plane.contourLps.row(a) - plane.contourLps.row(b)).norm());
    wall.planes.push_back(std::move(plane));
  }
  return wall;
}

} // namespace sgp
