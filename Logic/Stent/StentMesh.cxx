#include "Stent/StentMesh.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "Centerlines/ProximalSite.h"
#include "Centerlines/VesselOrigins.h"
#include "Common/CheckRange.h"
#include "Common/Errors.h"
#include "Common/Format.h"

namespace sgp
{

namespace
{

constexpr double pi = 3.14159265358979323846;

/// Position and unit tangent of a centerline at arc length s (clamped to its ends); the tangent
/// over ±2 mm, smooth enough for ring planes on a 1 mm polyline.
std::pair<Point3, Eigen::Vector3d> PointAt(const Centerline& c, double s)
{
  return { PositionAt(c, s), (PositionAt(c, s + 2.0) - PositionAt(c, s - 2.0)).normalized() };
}

/// One segment's rings: centres, tangents (downstream) and frame axes u, v.
struct RingFrames
{
  std::vector<Point3> centre;
  std::vector<Eigen::Vector3d> tangent, u, v;
};

/// Rotation-minimizing frames by double reflection, from ring `from` (whose u is set) outward.
void PropagateFrames(RingFrames& f, int from, double handedness)
{
  const int n = static_cast<int>(f.centre.size());
  const auto step = [&](int i, int next)
  {
    const Eigen::Vector3d v1 = f.centre[next] - f.centre[i];
    const double c1 = v1.squaredNorm();
    Eigen::Vector3d rL = f.u[i], tL = f.tangent[i];
    if (c1 > 1e-12)
    {
      rL -= (2.0 / c1) * v1.dot(f.u[i]) * v1;
      tL -= (2.0 / c1) * v1.dot(f.tangent[i]) * v1;
    }
    const Eigen::Vector3d v2 = f.tangent[next] - tL;
    const double c2 = v2.squaredNorm();
    f.u[next] = c2 > 1e-12 ? Eigen::Vector3d(rL - (2.0 / c2) * v2.dot(rL) * v2) : rL;
    f.u[next] = (f.u[next] - f.u[next].dot(f.tangent[next]) * f.tangent[next]).normalized();
  };
  for (int i = from; i + 1 < n; ++i)
    step(i, i + 1);
  for (int i = from; i > 0; --i)
    step(i, i - 1);
  for (int i = 0; i < n; ++i)
    f.v[i] = handedness * f.tangent[i].cross(f.u[i]);
}

/// Ring positions from `from` to `to` (inclusive), through every `required` position strictly
/// between them (StentMeshParams::requiredRingAbscissaMm), each stretch evenly spaced at most
/// `spacing` apart.
std::vector<double> RingsThrough(double from, double to, double spacing, std::vector<double> required)
{
  std::sort(required.begin(), required.end());
  std::vector<double> stops{ from };
  for (double r : required)
    if (r > from + RequiredRingSnapMm && r < to - RequiredRingSnapMm && r > stops.back() + RequiredRingSnapMm)
      stops.push_back(r);
  stops.push_back(to);
  std::vector<double> rings{ from };
  for (std::size_t k = 1; k < stops.size(); ++k)
  {
    const double a = stops[k - 1], b = stops[k];
    const int intervals = std::max(1, static_cast<int>(std::ceil((b - a) / spacing - 1e-9)));
    for (int i = 1; i <= intervals; ++i)
      rings.push_back(a + (b - a) * i / intervals);
  }
  return rings;
}

RingFrames Rings(const Centerline& c, const std::vector<double>& positions)
{
  RingFrames f;
  for (double s : positions)
  {
    const auto [p, t] = PointAt(c, s);
    f.centre.push_back(p);
    f.tangent.push_back(t);
  }
  f.u.resize(positions.size());
  f.v.resize(positions.size());
  return f;
}

/// The unit vector `d` made perpendicular to the unit `axis`.
Eigen::Vector3d Perpendicular(const Eigen::Vector3d& d, const Eigen::Vector3d& axis)
{
  return (d - d.dot(axis) * axis).normalized();
}

} // namespace

int StentMesh::Id(int segmentId, int ringId, int columnId) const
{
  const int n = verticesPerRing;
  return firstVertex[segmentId] + ringId * n + ((columnId % n) + n) % n;
}

void ValidateStentMeshParams(const StentMeshParams& p)
{
  CheckRange("verticesPerRing", p.verticesPerRing, 8, 256, "");
  if (p.verticesPerRing % 4 != 0)
    throw InputError("verticesPerRing is " + std::to_string(p.verticesPerRing) +
                     "; expected a multiple of 4 (the junction joins quarter rings).");
  CheckRange("ringSpacingMm", p.ringSpacingMm, 0.5, 20, "mm");
  CheckRange("startRadiusMm", p.startRadiusMm, 0.5, 30, "mm");
  CheckRange("proximalAbscissaMm", p.proximalAbscissaMm, -1, 1e4, "mm");
  CheckRange("legLengthMm", p.legLengthMm, 0, 1e3, "mm");
  for (double end : p.legEndAbscissaMm)
    if (!std::isnan(end))
      CheckRange("legEndAbscissaMm", end, p.startRadiusMm, 1e3, "mm");
}

Point3 RingCentroid(const StentMesh& mesh, const Points& V, int segment, int k)
{
  Point3 centre = Point3::Zero();
  for (int j = 0; j < mesh.verticesPerRing; ++j)
    centre += V.row(mesh.Id(segment, k, j)).transpose();
  return centre / double(mesh.verticesPerRing);
}

StentMesh BuildStentMesh(const CenterlineTree& tree, const StentMeshParams& p)
{
  ValidateStentMeshParams(p);
  const int n = p.verticesPerRing;
  const double gap = 3.0 * p.startRadiusMm;
  // Ring positions: the trunk measured up from its junction end, the legs down from theirs.
  std::vector<double> trunk;
  const double trunkEnd = std::isfinite(p.trunkEndAbscissaMm)
                            ? std::min(p.trunkEndAbscissaMm, tree.aorta.LengthMm() - 1.0)
                            : tree.aorta.LengthMm() - gap;
  const double proximal = p.proximalAbscissaMm >= 0.0 ? p.proximalAbscissaMm : FindProximalSite(tree).abscissaMm;
  if (trunkEnd > proximal) // evenly spaced, at most ringSpacingMm apart, the first ring at the proximal site
    trunk = RingsThrough(proximal, trunkEnd, p.ringSpacingMm, p.requiredRingAbscissaMm[TrunkSegment]);
  std::array<std::vector<double>, 2> legs;
  const Centerline* iliac[2] = { &tree.rightIliac, &tree.leftIliac };
  for (int side = 0; side < 2; ++side)
  {
    double length = p.legLengthMm;
    if (length <= 0.0)
    {
      // To 5 mm above the internal iliac origin where the axes meet (the one the iliac lengths use);
      // with none in view, 5 mm above where the common iliac narrows into the external iliac
      // (IliacNarrowingAbscissa), else the default length.
      const double origin = InternalIliacOriginAbscissa(tree, side);
      const double narrowing = std::isfinite(origin) ? origin : IliacNarrowingAbscissa(*iliac[side]);
      length = std::isfinite(narrowing) ? narrowing - gap - 5.0 : DefaultLegLengthMm;
    }
    const double iliacLength = iliac[side]->LengthMm();
    const double end = p.legEndAbscissaMm[std::size_t(side)];
    if (std::isfinite(end))
    {
      if (end > iliacLength + 1e-6)
        throw InputError(std::string(side == 0 ? "The right" : "The left") + " leg is to end " + FormatNumber(end) +
                         " mm down its iliac, beyond the " + FormatNumber(iliacLength) +
                         " mm of it in the scan; give a scan that covers the iliac arteries there.");
      const double start = p.legStartAbscissaMm[std::size_t(side)];
      const double first = std::isfinite(start)           ? std::max(LegStartMinimumMm, std::min(start, gap))
                           : end - gap >= p.ringSpacingMm ? gap
                                                          : std::max(p.startRadiusMm, end - p.ringSpacingMm);
      if (end > first)
        legs[side] = RingsThrough(first, end, p.ringSpacingMm, p.requiredRingAbscissaMm[std::size_t(1 + side)]);
      continue;
    }
    if (std::isfinite(tree.iliacCoverageMm[side]) && iliacLength < gap + p.ringSpacingMm)
    {
      // The scan cuts this iliac short (a partial plan): the leg's rings are evenly spaced over the
      // stretch in view, at most ringSpacingMm apart, the first at most `gap` down — the leg holds
      // the trunk's connection element; nothing is measured on it.
      const double first = std::min(gap, iliacLength / 3.0), last = iliacLength - std::min(1.0, iliacLength / 3.0);
      const int intervals = std::max(1, static_cast<int>(std::ceil((last - first) / p.ringSpacingMm - 1e-9)));
      if (last > first)
        for (int k = 0; k <= intervals; ++k)
          legs[side].push_back(first + (last - first) * k / intervals);
      continue;
    }
    length = std::min(length, iliacLength - gap);
    double first = gap;
    if (length < p.ringSpacingMm && p.legLengthMm <= 0.0)
    {
      // A short common iliac: two rings ending where the leg should end, the first moved up
      // toward the junction (but at least a stent radius down it, where the two legs part).
      first = std::max(p.startRadiusMm, gap + length - p.ringSpacingMm);
      length = p.ringSpacingMm;
    }
    for (double s = first; s <= first + length + 1e-9; s += p.ringSpacingMm)
      legs[side].push_back(s);
  }
  if (trunk.size() < 2 || legs[0].size() < 2 || legs[1].size() < 2)
  {
    throw InputError("The vessels are too short for a stent of at least two rings per segment (aorta " +
                     FormatNumber(tree.aorta.LengthMm()) + " mm, iliacs " + FormatNumber(iliac[0]->LengthMm()) +
                     " and " + FormatNumber(iliac[1]->LengthMm()) + " mm, ring spacing " +
                     FormatNumber(p.ringSpacingMm) + " mm); lower ringSpacingMm or startRadiusMm.");
  }

  RingFrames frames[3] = { Rings(tree.aorta, trunk), Rings(tree.rightIliac, legs[0]), Rings(tree.leftIliac, legs[1]) };
  const Point3 rightStart = frames[1].centre.front(), leftStart = frames[2].centre.front();
  const Eigen::Vector3d towardLeft = (leftStart - rightStart).normalized();
  const int last = static_cast<int>(trunk.size()) - 1;
  frames[0].u[last] = Perpendicular(towardLeft, frames[0].tangent[last]);
  Eigen::Vector3d anterior = frames[0].tangent[last].cross(frames[0].u[last]);
  const double trunkHand = anterior.y() <= 0.0 ? 1.0 : -1.0; // anterior is −y in LPS
  PropagateFrames(frames[0], last, trunkHand);
  anterior = frames[0].v[last];
  for (int side = 0; side < 2; ++side)
  {
    RingFrames& f = frames[1 + side];
    f.u[0] = Perpendicular(side == 0 ? towardLeft : Eigen::Vector3d(-towardLeft), f.tangent[0]);
    const double hand = f.tangent[0].cross(f.u[0]).dot(anterior) >= 0.0 ? 1.0 : -1.0;
    PropagateFrames(f, 0, hand);
  }

  StentMesh mesh;
  mesh.verticesPerRing = n;
  mesh.crotchPoint = 0.5 * (rightStart + leftStart);
  mesh.crotchNormal = towardLeft;
  int total = 0;
  for (int seg = 0; seg < 3; ++seg)
  {
    mesh.firstVertex[seg] = total;
    mesh.ringCount[seg] = static_cast<int>(frames[seg].centre.size());
    mesh.ringAbscissaMm[seg] = seg == TrunkSegment ? trunk : legs[seg - 1];
    total += mesh.ringCount[seg] * n;
  }
  mesh.V.resize(total, 3);
  mesh.centre.resize(total, 3);
  mesh.axis.resize(total, 3);
  mesh.segment.resize(total);
  mesh.ring.resize(total);
  mesh.column.resize(total);
  for (int seg = 0; seg < 3; ++seg)
    for (int k = 0; k < mesh.ringCount[seg]; ++k)
    {
      std::vector<int> ringIds;
      for (int j = 0; j < n; ++j)
      {
        const int id = mesh.Id(seg, k, j);
        const double theta = 2.0 * pi * j / n;
        const RingFrames& f = frames[seg];
        mesh.V.row(id) =
          (f.centre[k] + p.startRadiusMm * (std::cos(theta) * f.u[k] + std::sin(theta) * f.v[k])).transpose();
        mesh.centre.row(id) = f.centre[k].transpose();
        mesh.axis.row(id) = f.tangent[k].transpose();
        mesh.segment[id] = seg;
        mesh.ring[id] = k;
        mesh.column[id] = j;
        ringIds.push_back(id);
      }
      mesh.rings.push_back(ringIds);
    }

  // s-chains through the connection element (see the header).
  const int kt = mesh.ringCount[0];
  const auto column = [&](int seg, int j, bool downward)
  {
    std::vector<int> ids;
    const int rings = mesh.ringCount[seg];
    for (int k = 0; k < rings; ++k)
      ids.push_back(mesh.Id(seg, downward ? k : rings - 1 - k, j));
    return ids;
  };
  const auto join = [](std::vector<int> a, const std::vector<int>& b)
  {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  const int quarter = n / 4, half = n / 2;
  for (int j = quarter; j <= 3 * quarter; ++j) // trunk right half → right leg lateral half
    mesh.chains.push_back(join(column(0, j, true), column(1, j, true)));
  for (int j = 3 * quarter + 1; j < n + quarter; ++j) // trunk left half → left leg lateral half
    mesh.chains.push_back(join(column(0, j % n, true), column(2, ((half - j) % n + n) % n, true)));
  for (int j : { quarter, 3 * quarter }) // left leg's anterior and posterior columns
  {
    // From the trunk's last two rings only: the trunk's column j is already on the right leg's
    // chain, and a trunk edge on two chains would carry its s-stiffness twice (a dent along the
    // whole trunk at these two columns).
    const std::vector<int> trunk = column(0, j, true);
    mesh.chains.push_back(join({ trunk.end() - 2, trunk.end() }, column(2, j, true)));
  }
  for (int j = 3 * quarter + 1; j < n + quarter; ++j) // crotch: right leg up, left leg down
    mesh.chains.push_back(join(column(1, j % n, false), column(2, j % n, true)));

  // Triangles: each segment's quads, then the connection element.
  std::vector<Eigen::Vector3i> triangles;
  const auto quad = [&](int a, int b, int c, int d)
  {
    triangles.emplace_back(a, b, c);
    triangles.emplace_back(a, c, d);
  };
  for (int seg = 0; seg < 3; ++seg)
    for (int k = 0; k + 1 < mesh.ringCount[seg]; ++k)
      for (int j = 0; j < n; ++j)
        quad(mesh.Id(seg, k, j), mesh.Id(seg, k, j + 1), mesh.Id(seg, k + 1, j + 1), mesh.Id(seg, k + 1, j));
  for (int j = quarter; j < 3 * quarter; ++j)
    quad(mesh.Id(0, kt - 1, j), mesh.Id(0, kt - 1, j + 1), mesh.Id(1, 0, j + 1), mesh.Id(1, 0, j));
  const auto toLeft = [&](int j) { return ((half - j) % n + n) % n; };
  for (int j = 3 * quarter; j < n + quarter; ++j)
    quad(mesh.Id(0, kt - 1, j), mesh.Id(0, kt - 1, j + 1), mesh.Id(2, 0, toLeft(j + 1)), mesh.Id(2, 0, toLeft(j)));
  for (int j = 3 * quarter; j < n + quarter; ++j)
    quad(mesh.Id(1, 0, j), mesh.Id(1, 0, j + 1), mesh.Id(2, 0, j + 1), mesh.Id(2, 0, j));
  for (int j : { quarter, 3 * quarter })
    triangles.emplace_back(mesh.Id(0, kt - 1, j), mesh.Id(1, 0, j), mesh.Id(2, 0, j));
  mesh.F.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  for (std::size_t i = 0; i < triangles.size(); ++i)
    mesh.F.row(static_cast<Eigen::Index>(i)) = triangles[i].transpose();
  return mesh;
}

std::vector<Ball> StentReach(const StentMesh& mesh, const CenterlineTree& tree)
{
  const Centerline* vessel[3] = { &tree.aorta, &tree.rightIliac, &tree.leftIliac };
  std::vector<Ball> balls;
  for (int seg = 0; seg < 3; ++seg)
    for (int k = 0; k < mesh.RingsIn(seg); ++k)
    {
      const double radius = RadiusAt(*vessel[seg], mesh.ringAbscissaMm[seg][k]);
      balls.push_back({ mesh.centre.row(mesh.Id(seg, k, 0)).transpose(), 1.5 * radius + 10.0 });
    }
  return balls;
}

std::vector<Ball> SharedFieldReach(const StentMesh& mesh, const CenterlineTree& tree, double deploymentOffsetMm)
{
  std::vector<Ball> balls = StentReach(mesh, tree);
  constexpr double StepMm = 4.0, LegBeyondMm = 16.0;
  const auto add = [&](const Centerline& c, double s) {
    balls.push_back({ PositionAt(c, s), 1.5 * RadiusAt(c, s) + 10.0 });
  };
  const Centerline* iliac[2] = { &tree.rightIliac, &tree.leftIliac };
  for (int side = 0; side < 2; ++side)
  {
    const std::vector<double>& rings = mesh.ringAbscissaMm[std::size_t(1 + side)];
    if (rings.empty())
      continue;
    for (double s = rings.back() + StepMm; s <= std::min(rings.back() + LegBeyondMm, iliac[side]->LengthMm());
         s += StepMm)
      add(*iliac[side], s);
  }
  const std::vector<double>& trunk = mesh.ringAbscissaMm[0];
  if (!trunk.empty())
    for (double s = trunk.front() - StepMm; s >= std::max(0.0, trunk.front() + deploymentOffsetMm - StepMm);
         s -= StepMm)
      add(tree.aorta, s);
  return balls;
}

} // namespace sgp
