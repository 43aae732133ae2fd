#include "Phantom/AorticWall.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "Phantom/AorticPhantom.h"

namespace sgp
{
namespace
{

constexpr double pi = 3.14159265358979323846;
constexpr double degToRad = pi / 180.0;
constexpr double taperMm = 3.0;          ///< the neck thrombus's ends
constexpr double neckStretchMm = 15.0;   ///< the neck's seal zone below the site, for the arcs
constexpr double significantIltMm = 2.0; ///< neck thrombus counts where thicker (vessel-wall.md §3.1)

double WrapDeg(double deg)
{
  deg = std::fmod(deg, 360.0);
  return deg < 0.0 ? deg + 360.0 : deg;
}

/// |a − b| on the circle, degrees in [0, 180].
double AngleBetweenDeg(double a, double b)
{
  const double d = std::fabs(WrapDeg(a - b));
  return d > 180.0 ? 360.0 - d : d;
}

} // namespace

AorticWall::AorticWall(const PhantomParams& p,
                       std::function<double(double)> outerRadius,
                       double sacBottomH,
                       double sacTopH,
                       double siteH,
                       double topH,
                       double betaRad)
  : m_Outer(std::move(outerRadius))
  , m_WallMm(p.wallThicknessMm)
  , m_SacBottom(sacBottomH)
  , m_SacTop(sacTopH)
  , m_Site(siteH)
  , m_TopH(topH)
  , m_Beta(betaRad)
  , m_MaxOuter(0.0)
  , m_SacThrombusMm(p.thrombusMaxThicknessMm)
  , m_NeckThrombusMm(p.neckThrombusThicknessMm)
  , m_NeckThrombusLengthMm(p.neckThrombusLengthMm)
  , m_NeckLumenPerLevel(p.neckLumenPerLevel)
  , m_SacThrombusSideDeg(SideDegrees(p.thrombusSide))
  , m_NeckThrombusSideDeg(SideDegrees(p.neckThrombusSide))
  , m_Concentric(p.thrombusConcentric)
  , m_SacAxisRatio(p.sacAxisRatio)
  , m_SacMajorDeg(SideDegrees(p.sacMajorAxis))
{
  for (double h = 0.0; h <= topH; h += 0.05)
    m_MaxOuter = std::max(m_MaxOuter, m_Outer(h) * Stretch(h));
  if (p.sacCalcificationArcDeg > 0.0)
  {
    const double third = (sacTopH - sacBottomH) / 3.0;
    m_Calcifications.push_back(
      { sacBottomH + third, sacTopH - third, SideDegrees(p.sacCalcificationSide), p.sacCalcificationArcDeg });
  }
  if (p.neckCalcificationArcDeg > 0.0)
    m_Calcifications.push_back(
      { siteH - neckStretchMm, siteH, SideDegrees(p.neckCalcificationSide), p.neckCalcificationArcDeg });
  // Neighbours: each touches over ≥ 72° (a fifth of the circumference) where it lies against the
  // vessel, so the outer wall there has no fat plane to show it.
  if (p.includePsoas)
  {
    m_Neighbours.push_back({ "leftPsoas", PsoasLabel, p.psoasHu, 0.0, siteH, 135.0, 80.0, 25.0 });
    m_Neighbours.push_back({ "rightPsoas", PsoasLabel, p.psoasHu, 0.0, siteH, 225.0, 80.0, 25.0 });
  }
  if (p.includeIvc)
    m_Neighbours.push_back({ "ivc", IvcLabel, p.ivcHu, 0.0, topH, 270.0, p.ivcArcDeg, 20.0 });
  if (p.includeDuodenum) // crossing in front of the neck, 24 mm high
    m_Neighbours.push_back(
      { "duodenum", DuodenumLabel, p.duodenumHu, sacTopH - 6.0, sacTopH + 18.0, 0.0, 100.0, 18.0 });
  if (p.includeLeftRenalVein) // 9 mm calibre, between the left renal artery and the SMA
    m_Neighbours.push_back(
      { "leftRenalVein", RenalVeinLabel, p.leftRenalVeinHu, siteH + 9.5, siteH + 18.5, 30.0, 90.0, 9.0 });
}

Point3 AorticWall::AxisPoint(double h) const
{
  if (h <= m_SacTop)
    return Point3(0, 0, h);
  return Point3(0, 0, m_SacTop) + (h - m_SacTop) * Point3(0.0, -std::sin(m_Beta), std::cos(m_Beta));
}

double AorticWall::ReachMm() const
{
  double reach = m_MaxOuter;
  for (const WallNeighbour& n : m_Neighbours)
    reach = std::max(reach, m_MaxOuter + n.thicknessMm);
  return reach;
}

std::array<Point3, 2> AorticWall::BoundsLps(double marginMm) const
{
  const Point3 r = Point3::Constant(ReachMm() + marginMm);
  const Point3 a = AxisPoint(0.0), b = AxisPoint(m_TopH);
  return { a.cwiseMin(b) - r, a.cwiseMax(b) + r };
}

std::array<Eigen::Vector3d, 2> AorticWall::Frame(double h) const
{
  const double lean = h <= m_SacTop ? 0.0 : m_Beta;
  // Anterior (−y) tilted with the neck; left (+x) is ⊥ the plane in which the neck leans.
  return { Eigen::Vector3d(0.0, -std::cos(lean), -std::sin(lean)), Eigen::Vector3d(1.0, 0.0, 0.0) };
}

AorticWall::Coordinates AorticWall::At(const Point3& x) const
{
  // The nearer of the two straight pieces of the axis.
  const double rawLow = x.z();
  const Point3 neckDirection(0.0, -std::sin(m_Beta), std::cos(m_Beta));
  const double rawHigh = m_SacTop + (x - Point3(0, 0, m_SacTop)).dot(neckDirection);
  const double hLow = std::clamp(rawLow, 0.0, m_SacTop);
  const double hHigh = std::clamp(rawHigh, m_SacTop, std::max(m_SacTop, m_TopH));
  const double dLow = (x - AxisPoint(hLow)).squaredNorm(), dHigh = (x - AxisPoint(hHigh)).squaredNorm();
  Coordinates c;
  c.h = dLow <= dHigh ? hLow : hHigh;
  const double raw = dLow <= dHigh ? rawLow : rawHigh;
  c.beyondMm = std::max(-raw, raw - m_TopH);
  const Eigen::Vector3d d = x - AxisPoint(c.h);
  const auto frame = Frame(c.h);
  c.q = Eigen::Vector2d(d.dot(frame[0]), d.dot(frame[1]));
  c.rho = c.q.norm();
  c.thetaDeg = WrapDeg(std::atan2(c.q.y(), c.q.x()) / degToRad);
  return c;
}

Eigen::Vector2d AorticWall::SideVector(double deg) const
{
  return Eigen::Vector2d(std::cos(deg * degToRad), std::sin(deg * degToRad));
}

double AorticWall::Taper(double h) const
{
  const double from = m_SacTop, to = m_SacTop + m_NeckThrombusLengthMm;
  if (h <= from || h >= to)
    return 0.0;
  const double edge = std::min({ h - from, to - h, taperMm }) / taperMm; // 0…1 within a taper
  return 0.5 - 0.5 * std::cos(pi * edge);
}

double AorticWall::Stretch(double h) const
{
  if (m_SacAxisRatio <= 1.0 || h <= m_SacBottom || h >= m_SacTop)
    return 1.0;
  return 1.0 + (m_SacAxisRatio - 1.0) * std::sin(pi * (m_SacTop - h) / (m_SacTop - m_SacBottom));
}

double AorticWall::OuterRadius(double h, double thetaDeg) const
{
  const double b = m_Outer(h), stretch = Stretch(h);
  if (stretch == 1.0)
    return b;
  const double a = stretch * b, phi = (thetaDeg - m_SacMajorDeg) * degToRad;
  return a * b / std::hypot(b * std::cos(phi), a * std::sin(phi));
}

double AorticWall::MaxCaliperMm(double fromH, double toH) const
{
  double largest = 0.0;
  for (double h = fromH; h <= toH; h += 0.01)
    largest = std::max(largest, 2.0 * m_Outer(h) * Stretch(h));
  return largest;
}

double AorticWall::ThrombusThickness(double h) const
{
  if (h >= m_SacBottom && h <= m_SacTop && m_SacThrombusMm > 0.0)
    return m_SacThrombusMm * std::sin(pi * (m_SacTop - h) / (m_SacTop - m_SacBottom));
  return m_NeckThrombusMm * Taper(h);
}

bool AorticWall::ConcentricAt(double h) const
{
  // The neck's thrombus is a crescent whatever the sac's shape: drawn concentric, a 6 mm neck
  // thrombus was a ring closing a 19 mm neck to 8 mm, a stenosis no neck has.
  return m_Concentric && h >= m_SacBottom && h <= m_SacTop && m_SacThrombusMm > 0.0;
}

Eigen::Vector2d AorticWall::LumenCentre(double h) const
{
  if (ConcentricAt(h))
    return Eigen::Vector2d::Zero();
  const double side = h <= m_SacTop ? m_SacThrombusSideDeg : m_NeckThrombusSideDeg;
  return -0.5 * ThrombusThickness(h) * SideVector(side);
}

double AorticWall::LumenRadius(double h) const
{
  return InnerRadius(h) - (ConcentricAt(h) ? 1.0 : 0.5) * ThrombusThickness(h);
}

double AorticWall::ThrombusThicknessAt(double h, double thetaDeg) const
{
  // The lumen's edge along direction u from the axis: |t·u − c| = rl, t ≥ 0.
  const Eigen::Vector2d u = SideVector(thetaDeg), c = LumenCentre(h);
  const double rl = LumenRadius(h), b = u.dot(c);
  const double t = b + std::sqrt(std::max(0.0, b * b - c.squaredNorm() + rl * rl));
  return std::max(0.0, InnerRadius(h, thetaDeg) - t);
}

Point3 AorticWall::LumenCentreLps(double h) const
{
  const auto frame = Frame(h);
  const Eigen::Vector2d c = LumenCentre(h);
  return AxisPoint(h) + c.x() * frame[0] + c.y() * frame[1];
}

void AorticWall::SampleLumen(double stepMm, std::vector<Point3>& points, std::vector<double>& radii) const
{
  points.clear();
  radii.clear();
  for (double h = m_TopH;; h -= stepMm)
  {
    h = std::max(h, 0.0);
    points.push_back(LumenCentreLps(h));
    radii.push_back(LumenRadius(h));
    if (h <= 0.0)
      break;
  }
}

double AorticWall::NeckLumenSignedDistance(const Coordinates& c) const
{
  // Beyond the stretch too, by three of the tube's 2 mm samples: its chords and nearest-point
  // radii reach that far from each taper (bands of "thrombus" 1–3 mm beyond them).
  const double from = std::max(m_SacTop - 6.0, 0.0), to = std::min(m_SacTop + m_NeckThrombusLengthMm + 6.0, m_TopH);
  if (!DrawsNeckLumenPerLevel() || c.beyondMm > 0.0 || c.h <= from || c.h >= to)
    return std::numeric_limits<double>::quiet_NaN();
  const Eigen::Vector2d d = c.q - LumenCentre(c.h);
  const double r = d.norm();
  constexpr double dh = 0.05; // central differences along the axis (the tapers are 3 mm long)
  const Eigen::Vector2d centreSlope = (LumenCentre(c.h + dh) - LumenCentre(c.h - dh)) / (2.0 * dh);
  const double radiusSlope = (LumenRadius(c.h + dh) - LumenRadius(c.h - dh)) / (2.0 * dh);
  const double along = (r > 1e-9 ? -d.dot(centreSlope) / r : 0.0) - radiusSlope;
  return (r - LumenRadius(c.h)) / std::sqrt(1.0 + along * along);
}

double AorticWall::WallSignedDistance(const Coordinates& c) const
{
  return std::max(c.rho - OuterRadius(c.h, c.thetaDeg), InnerRadius(c.h, c.thetaDeg) - c.rho);
}

double AorticWall::CalcificationSignedDistance(const Coordinates& c, const WallCalcification& w) const
{
  const double radial = std::max(c.rho - OuterRadius(c.h, c.thetaDeg), InnerRadius(c.h, c.thetaDeg) - 1.0 - c.rho);
  const double around = c.rho * (AngleBetweenDeg(c.thetaDeg, w.sideDeg) - 0.5 * w.arcDeg) * degToRad;
  const double along = std::max(w.fromH - c.h, c.h - w.toH);
  return std::max({ radial, around, along });
}

double AorticWall::NeighbourSignedDistance(const Coordinates& c, const WallNeighbour& n) const
{
  const double ro = OuterRadius(c.h, c.thetaDeg);
  const double radial = std::max(ro - c.rho, c.rho - ro - n.thicknessMm);
  const double around = c.rho * (AngleBetweenDeg(c.thetaDeg, n.sideDeg) - 0.5 * n.arcDeg) * degToRad;
  const double along = std::max(n.fromH - c.h, c.h - n.toH);
  return std::max({ radial, around, along });
}

double AorticWall::ThrombusVolumeMl() const
{
  // The inner wall's disc less the lumen's, in planes ⊥ the axis, h from 0 to the site (0.05 mm
  // steps, midpoint rule; the lumen's tilt off the axis changes its area by < 1 %).
  double mm3 = 0.0;
  constexpr double dh = 0.05;
  for (double h = 0.5 * dh; h < m_Site; h += dh)
  {
    const double rl = LumenRadius(h);
    const double ri = InnerRadius(h);
    double area = pi * (ri * ri - rl * rl);
    if (Stretch(h) > 1.0) // ½ ∮ Ri(h, θ)² dθ, 1° steps, less the lumen
    {
      area = -pi * rl * rl;
      for (int k = 0; k < 360; ++k)
        area += 0.5 * std::pow(InnerRadius(h, k + 0.5), 2) * degToRad;
    }
    mm3 += area * dh;
  }
  return mm3 / 1000.0;
}

double AorticWall::MaxThrombusThicknessMm() const
{
  double largest = 0.0;
  for (double h = 0.0; h <= m_Site; h += 0.05)
  {
    largest = std::max(largest, ThrombusThickness(h));
    if (Stretch(h) > 1.0) // thickest at the ellipse's ends or on the crescent's side
      for (int k = 0; k < 360; ++k)
        largest = std::max(largest, ThrombusThicknessAt(h, k));
  }
  return largest;
}

double AorticWall::NeckThrombusArcPercent() const
{
  double largest = 0.0;
  for (double h = m_Site - neckStretchMm; h <= m_Site + 1e-9; h += 0.25)
  {
    int thick = 0;
    for (int k = 0; k < 720; ++k) // 0.5° steps
      thick += ThrombusThicknessAt(h, 0.5 * k) > significantIltMm ? 1 : 0;
    largest = std::max(largest, 100.0 * thick / 720.0);
  }
  return largest;
}

double AorticWall::NeckCalcificationArcPercent() const
{
  double largest = 0.0;
  for (const WallCalcification& w : m_Calcifications)
    if (w.toH > m_Site - neckStretchMm && w.fromH < m_Site)
      largest = std::max(largest, 100.0 * std::min(w.arcDeg, 360.0) / 360.0);
  return largest;
}

} // namespace sgp
