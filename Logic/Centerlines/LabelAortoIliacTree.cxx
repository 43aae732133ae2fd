#include "Centerlines/LabelAortoIliacTree.h"

#include "Centerlines/ProximalSite.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <set>

#include "Centerlines/LimbDivergence.h"
#include "Centerlines/SmoothCenterline.h"
#include "Centerlines/VesselOrigins.h"
#include "Common/CheckRange.h"
#include "Common/Errors.h"
#include "Common/Format.h"
#include "Common/Median.h"

namespace sgp
{

namespace
{

/// Median radius of `edge` leaving `node`, beyond the junction's own radius (where the
/// inscribed sphere still touches the parent vessel) and within `reach` mm after it.
double BranchRadius(const SkeletonGraph& graph, int edge, int node, double reach)
{
  const auto points = PointsFrom(graph, edge, node);
  const auto radii = RadiiFrom(graph, edge, node);
  const double from = graph.Degree(node) >= 3 ? graph.nodes[node].radiusMm : 0.0;
  std::vector<double> inside, all;
  double s = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i)
  {
    s += (points[i] - points[i - 1]).norm();
    all.push_back(radii[i]);
    if (s >= from && s <= from + reach)
      inside.push_back(radii[i]);
  }
  return Median(inside.empty() ? all : inside);
}

/// The widest way on from `node` other than `incoming`, or −1 at an end.
int WidestContinuation(const SkeletonGraph& graph, int node, int incoming, double reach)
{
  int best = -1;
  double bestRadius = -1.0;
  for (int e : graph.nodes[node].edges)
    if (e != incoming && graph.edges[e].a != graph.edges[e].b)
    {
      const double r = BranchRadius(graph, e, node, reach);
      if (r > bestRadius)
        best = e, bestRadius = r;
    }
  return best;
}

/// Unit direction from `node` to the point `reach` mm along `edge`, continuing through the
/// widest branch at junctions when the edge is shorter.
Eigen::Vector3d BranchDirection(const SkeletonGraph& graph, int edge, int node, double reach)
{
  const Point3 origin = graph.nodes[node].position;
  Point3 last = origin;
  double s = 0.0;
  std::set<int> seen{ node };
  for (int e = edge, from = node; e >= 0;)
  {
    const auto points = PointsFrom(graph, e, from);
    for (std::size_t i = 1; i < points.size(); ++i)
    {
      s += (points[i] - points[i - 1]).norm();
      last = points[i];
      if (s >= reach)
        return (last - origin).normalized();
    }
    from = graph.Other(e, from);
    if (!seen.insert(from).second)
      break;
    e = WidestContinuation(graph, from, e, reach);
  }
  return (last - origin).norm() > 0 ? Eigen::Vector3d((last - origin).normalized()) : Eigen::Vector3d::Zero();
}

/// How far a side branch must run outside its parent's wall before its direction is read, mm (as
/// the renal axis of ProximalSite.h, which starts 1 mm outside the wall).
constexpr double outsideParentStartMm = 1.0;

/// The direction in which a side branch leaves its parent, for naming it (step 4): the chord of
/// the branch's path (`branch`, from the junction outward) from its first point at least
/// `outsideParentStartMm` outside the parent's wall — the distance to the parent's centerline past
/// the parent's radius there — to `reach` mm further along it. The
/// skeleton's junction lies on the parent's axis, and inside the parent the branch's skeleton
/// follows the medial surface, which can run along the axis for a parent radius or more before
/// it turns out (a 6 mm renal from an 18 mm neck: 11 mm up the axis, then level); the chord from
/// the junction then points along the parent, not where the branch goes. `fromJunction` (the
/// chord from the junction) when the path runs less than `reach`/4 outside the parent.
Eigen::Vector3d DirectionOutsideParent(const std::vector<Point3>& branch,
                                       const Centerline& parent,
                                       double reach,
                                       const Eigen::Vector3d& fromJunction)
{
  const auto outside = [&](const Point3& p)
  {
    double distance = 0.0;
    const double s = ProjectOntoCenterline(parent, p, &distance);
    return distance - RadiusAt(parent, s);
  };
  std::size_t start = 0;
  while (start < branch.size() && outside(branch[start]) < outsideParentStartMm)
    ++start;
  if (start >= branch.size())
    return fromJunction;
  double s = 0.0;
  Point3 last = branch[start];
  for (std::size_t i = start + 1; i < branch.size() && s < reach; ++i)
  {
    s += (branch[i] - branch[i - 1]).norm();
    last = branch[i];
  }
  if (s < reach / 4)
    return fromJunction;
  return (last - branch[start]).normalized();
}

/// Where around its parent a side branch leaves (step 4): the unit vector from the parent's axis,
/// perpendicular to it, to the branch's first point at least `outsideParentStartMm` outside the
/// parent's wall — the side of the aorta the branch lies on as it leaves, whatever its course
/// then (an SMA that turns down at once runs in front of the aorta: anterior). Zero when the path
/// never leaves the parent.
Eigen::Vector3d OffsetOutsideParent(const std::vector<Point3>& branch, const Centerline& parent)
{
  for (const Point3& p : branch)
  {
    double distance = 0.0;
    const double s = ProjectOntoCenterline(parent, p, &distance);
    if (distance - RadiusAt(parent, s) < outsideParentStartMm)
      continue;
    const Eigen::Vector3d t = TangentAt(parent, s);
    const Eigen::Vector3d w = p - PositionAt(parent, s);
    const Eigen::Vector3d radial = w - w.dot(t) * t;
    return radial.norm() > 1e-9 ? Eigen::Vector3d(radial.normalized()) : Eigen::Vector3d::Zero();
  }
  return Eigen::Vector3d::Zero();
}

/// Total length of vessel reachable through `edge` from `node` without passing `node` again.
double ReachableLength(const SkeletonGraph& graph, int edge, int node)
{
  std::set<int> seenEdges{ edge }, seenNodes{ node };
  std::vector<int> stack{ graph.Other(edge, node) };
  double length = graph.edges[edge].lengthMm;
  while (!stack.empty())
  {
    const int n = stack.back();
    stack.pop_back();
    if (!seenNodes.insert(n).second)
      continue;
    for (int e : graph.nodes[n].edges)
      if (seenEdges.insert(e).second)
      {
        length += graph.edges[e].lengthMm;
        stack.push_back(graph.Other(e, n));
      }
  }
  return length;
}

/// True when an end point (degree 1) can be reached through `edge` from `node` without passing
/// `node` or a node of `blocked`.
bool LeadsToANewEnd(const SkeletonGraph& graph, int node, int edge, const std::set<int>& blocked)
{
  std::set<int> seen{ node };
  std::vector<int> stack{ graph.Other(edge, node) };
  while (!stack.empty())
  {
    const int n = stack.back();
    stack.pop_back();
    if (blocked.count(n) || !seen.insert(n).second)
      continue;
    if (graph.Degree(n) == 1)
      return true;
    for (int e : graph.nodes[n].edges)
      stack.push_back(graph.Other(e, n));
  }
  return false;
}

/// A vessel followed through the graph from a node along an edge.
struct VesselPath
{
  std::vector<Point3> points;
  std::vector<double> radii;
  struct Junction
  {
    int node;
    double abscissa;            ///< along the path, mm
    std::vector<int> sideEdges; ///< the branches not taken
  };
  std::vector<Junction> junctions;
  std::vector<int> nodes; ///< every node passed, the start included
};

double PathLength(const std::vector<Point3>& points)
{
  double s = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i)
    s += (points[i] - points[i - 1]).norm();
  return s;
}

/// Follows the vessel: at each junction the branch scoring best on radius × (1 + cos turn)/2.
VesselPath FollowVessel(const SkeletonGraph& graph, int start, int firstEdge, std::set<int> blocked, double reach)
{
  VesselPath path;
  path.points = PointsFrom(graph, firstEdge, start);
  path.radii = RadiiFrom(graph, firstEdge, start);
  path.nodes.push_back(start);
  blocked.insert(start);
  int node = graph.Other(firstEdge, start), incoming = firstEdge;
  while (blocked.insert(node).second)
  {
    path.nodes.push_back(node);
    // Ways on that reach an end the path has not passed: a loop in the skeleton (a tunnel through
    // a sac) leads only back into the path, and taken, it ended the aorta in the sac.
    std::vector<int> options;
    for (int e : graph.nodes[node].edges)
      if (e != incoming && graph.edges[e].a != graph.edges[e].b && LeadsToANewEnd(graph, node, e, blocked))
        options.push_back(e);
    if (options.empty())
      break;
    // Incoming direction over the last `reach` mm.
    std::size_t back = path.points.size() - 1;
    double s = 0.0;
    while (back > 0 && s < reach)
    {
      s += (path.points[back] - path.points[back - 1]).norm();
      --back;
    }
    const Eigen::Vector3d in = (path.points.back() - path.points[back]).normalized();
    int best = -1;
    double bestScore = -1.0;
    for (int e : options)
    {
      const double turn = in.dot(BranchDirection(graph, e, node, reach));
      const double score = BranchRadius(graph, e, node, reach) * (1.0 + turn) / 2.0;
      if (score > bestScore)
        best = e, bestScore = score;
    }
    VesselPath::Junction junction{ node, PathLength(path.points), {} };
    for (int e : options)
      if (e != best)
        junction.sideEdges.push_back(e);
    path.junctions.push_back(junction);
    const auto more = PointsFrom(graph, best, node);
    const auto moreRadii = RadiiFrom(graph, best, node);
    path.points.insert(path.points.end(), more.begin() + 1, more.end());
    path.radii.insert(path.radii.end(), moreRadii.begin() + 1, moreRadii.end());
    incoming = best;
    node = graph.Other(best, node);
  }
  return path;
}

/// Longest shortest-path distance in the graph, by two Dijkstra sweeps (exact on a tree).
double LongestPathMm(const SkeletonGraph& graph)
{
  const auto farthest = [&](int source)
  {
    std::vector<double> d(graph.nodes.size(), std::numeric_limits<double>::max());
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    d[source] = 0.0;
    queue.push({ 0.0, source });
    while (!queue.empty())
    {
      const auto [dist, n] = queue.top();
      queue.pop();
      if (dist > d[n])
        continue;
      for (int e : graph.nodes[n].edges)
      {
        const int m = graph.Other(e, n);
        if (dist + graph.edges[e].lengthMm < d[m])
          queue.push({ d[m] = dist + graph.edges[e].lengthMm, m });
      }
    }
    int best = source;
    for (int n = 0; n < int(d.size()); ++n)
      if (d[n] < std::numeric_limits<double>::max() && d[n] > d[best])
        best = n;
    return std::make_pair(best, d[best]);
  };
  return graph.nodes.empty() ? 0.0 : farthest(farthest(0).first).second;
}

struct Bifurcation
{
  int node = -1;
  int up = -1, right = -1, left = -1;
  double score = 0.0;
  std::array<bool, 2> cut{ false, false }; ///< right, left: cut by the scan's inferior border first
  bool Partial() const { return cut[0] || cut[1]; }
};

/// Of two readings of one junction: a whole Y before a partial one, then the wider.
bool Better(const Bifurcation& a, const Bifurcation& b)
{
  return a.Partial() != b.Partial() ? !a.Partial() : a.score > b.score;
}

/// An end where the image's inferior border cuts a vessel: its inscribed ball reaches the border,
/// within its radius + 3 mm of the lowest slice.
bool AtInferiorBorder(const SkeletonGraph& graph, int node)
{
  const SkeletonGraph::Node& end = graph.nodes[node];
  return end.atBorder && end.position.z() - graph.scanLowestZMm <= end.radiusMm + 3.0;
}

/// A junction with the shape of a Y that is refused as the bifurcation, and why.
struct RefusedY
{
  int node = -1;
  double score = 0.0; ///< as Bifurcation::score
  std::string reason;
};

std::vector<Bifurcation> FindBifurcations(const SkeletonGraph& graph,
                                          const CenterlineParams& params,
                                          std::vector<RefusedY>& refused)
{
  std::vector<Bifurcation> found;
  for (int n = 0; n < int(graph.nodes.size()); ++n)
  {
    if (graph.Degree(n) < 3)
      continue;
    struct Branch
    {
      int edge;
      Eigen::Vector3d direction;
      double radius, length;
    };
    std::vector<Branch> branches;
    for (int e : graph.nodes[n].edges)
      if (graph.edges[e].a != graph.edges[e].b)
        branches.push_back({ e, BranchDirection(graph, e, n, params.directionReachMm),
                             BranchRadius(graph, e, n, params.directionReachMm), ReachableLength(graph, e, n) });
    for (const Branch& up : branches)
    {
      if (up.direction.z() <= 0.5 || up.length < params.minimumBranchLengthMm)
        continue;
      double aortaRadius = -1.0; // median along the vessel followed up, computed when needed
      for (const Branch& right : branches)
        for (const Branch& left : branches)
        {
          const bool lower = right.direction.z() < -0.2 && left.direction.z() < -0.2;
          // Toward opposite sides of each other: the aorta may run obliquely, so the two
          // directions are compared with each other rather than with the x axis.
          const bool sides = left.direction.x() - right.direction.x() > 0.3;
          // The iliacs are narrower than the aorta, but not much: this also rejects the arch in
          // a chest scan, whose two limbs go down under a narrow supra-aortic branch.
          const double minimum = params.minimumIliacRadiusRatio * up.radius;
          const bool wide =
            right.radius >= minimum && left.radius >= minimum && up.radius >= 0.8 * std::max(right.radius, left.radius);
          if (!(lower && sides && wide))
            continue;
          const VesselPath rightPath = FollowVessel(graph, n, right.edge, {}, params.directionReachMm);
          const VesselPath leftPath = FollowVessel(graph, n, left.edge, {}, params.directionReachMm);
          // Each lower limb leads on to a whole iliac (long, and down), or the scan's inferior
          // border cuts it first (a partial Y, taken only when no whole one is found).
          const double bottom = graph.nodes[n].position.z() - params.minimumIliacDescentMm;
          const auto whole = [&](const Branch& b, const VesselPath& path)
          { return b.length >= params.minimumIliacLengthMm && path.points.back().z() <= bottom; };
          const std::array<bool, 2> cut{ !whole(right, rightPath), !whole(left, leftPath) };
          if ((cut[0] && !AtInferiorBorder(graph, rightPath.nodes.back())) ||
              (cut[1] && !AtInferiorBorder(graph, leftPath.nodes.back())))
            continue;
          const double score = std::min(right.radius, left.radius);
          const std::string where =
            "the junction at " + FormatPoint(graph.nodes[n].position) + " mm LPS has the shape of a Y, but ";
          // The iliacs part; a dissection's two channels run on side by side (LimbDivergence.h).
          // Limbs too short to tell (under 4 mm: the skeleton's fork at a cut face) make no Y.
          const LimbDivergence parting = MeasureLimbDivergence(rightPath.points, rightPath.radii, leftPath.points,
                                                               leftPath.radii, LimbDivergenceReachMm);
          if (std::isnan(parting.angleDeg))
            continue;
          // Judged where a partial Y could be taken (its coverage rule wants as much of each limb).
          if (parting.reachMm >= params.minimumIliacCoverageMm && parting.angleDeg < MinimumLimbDivergenceDeg &&
              parting.septumMm < MaximumDissectionSeptumMm)
          {
            refused.push_back({ n, score,
                                where + "its two lower limbs run on side by side (diverging by " +
                                  FormatNumber(parting.angleDeg, 1) + " degrees over their first " +
                                  FormatNumber(parting.reachMm, 0) + " mm, their lumens " +
                                  FormatNumber(std::max(0.0, parting.septumMm), 1) +
                                  " mm apart there): two channels split by a septum, as the true and false lumens "
                                  "of an aortic dissection, not the iliac arteries" });
            continue;
          }
          // The aorta is wider than each iliac over its length: a junction whose upper vessel is
          // narrower than a lower one is large vessels meeting (the venae cavae at the heart), not
          // the aorta above its bifurcation. Whole vessels are compared, not their first
          // centimetres: a common iliac aneurysm may be wider than the aorta just above it, never
          // the iliac over its length (the external iliac is most of it). Only "narrower": a
          // small aorta (18 mm) over ectatic iliacs (16–17 mm) is a real Y.
          if (aortaRadius < 0.0)
            aortaRadius = Median(FollowVessel(graph, n, up.edge, {}, params.directionReachMm).radii);
          const double iliacRadius = std::max(Median(rightPath.radii), Median(leftPath.radii));
          if (aortaRadius < params.minimumAortaToIliacRatio * iliacRadius)
          {
            refused.push_back({ n, score,
                                where + "the vessel above it (median " + FormatNumber(2.0 * aortaRadius, 1) +
                                  " mm across) is narrower than one below (" + FormatNumber(2.0 * iliacRadius, 1) +
                                  " mm): large vessels meeting, not the aorta and its iliacs" });
            continue;
          }
          // The renal and visceral arteries leave the aorta above its bifurcation: a lower limb
          // giving off a branch forward (anterior, direction y < −0.6) as wide as the coeliac or
          // the superior mesenteric (radius ≥ visceralRadiusMm; an iliac's anterior branches, the
          // inferior epigastric and the superficial circumflex, are under 1.5 mm) is the aorta
          // below a junction of the aorta with other large vessels (the heart), and the scan may
          // end above the real bifurcation.
          std::string visceral;
          for (const auto* path : { &rightPath, &leftPath })
            for (const auto& junction : path->junctions)
              for (int e : junction.sideEdges)
                if (visceral.empty() && BranchDirection(graph, e, junction.node, params.directionReachMm).y() < -0.6 &&
                    BranchRadius(graph, e, junction.node, params.directionReachMm) >= params.visceralRadiusMm &&
                    ReachableLength(graph, e, junction.node) >= params.minimumBranchLengthMm / 2)
                  visceral = FormatPoint(graph.nodes[junction.node].position);
          if (!visceral.empty())
          {
            refused.push_back({ n, score,
                                where + "a vessel below it gives off a branch forward at " + visceral +
                                  " mm LPS as wide as a visceral artery: that vessel is the aorta, and the " +
                                  "junction above it is not its bifurcation" });
            continue;
          }
          const Bifurcation candidate{ n, up.edge, right.edge, left.edge, score, cut };
          if (found.empty() || found.back().node != n || Better(candidate, found.back()))
          {
            if (!found.empty() && found.back().node == n)
              found.pop_back();
            found.push_back(candidate);
          }
        }
    }
  }
  // A partial Y only where the scan holds no whole one.
  if (std::any_of(found.begin(), found.end(), [](const Bifurcation& b) { return !b.Partial(); }))
    found.erase(std::remove_if(found.begin(), found.end(), [](const Bifurcation& b) { return b.Partial(); }),
                found.end());
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.score > b.score; });
  return found;
}

Centerline Finish(const std::string& name,
                  const std::vector<Point3>& points,
                  const std::vector<double>& radii,
                  const CenterlineParams& params)
{
  return SmoothCenterline(MakeCenterline(name, points, radii), params.stepMm, params.smoothingMm);
}

/// A side branch before naming: the path and how it leaves its parent.
struct SideBranch
{
  VesselPath path;
  int node;
  Eigen::Vector3d direction; ///< its course as it leaves (DirectionOutsideParent)
  double radius;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero(); ///< the side it leaves from (OffsetOutsideParent)
};

/// The side of the aorta a branch leaves from, by its offset's angle in the horizontal plane from
/// anterior (−y): anterior within anteriorSectorDeg, right or left lateral up to lateralSectorDeg
/// (renals leave anterolaterally or posterolaterally: 50° in front of lateral to 60° behind it),
/// else posterior or none (an offset without a horizontal part: unnamed).
enum class Clock
{
  Anterior,
  Right,
  Left,
  Other
};
constexpr double anteriorSectorDeg = 40.0, lateralSectorDeg = 150.0;

/// The offset's angle from the front (−y) toward either side in the horizontal plane, degrees in
/// [0, 180]; NaN when it leaves mostly up or down along the aorta (horizontal part under 0.5).
double DegreesFromFront(const Eigen::Vector3d& offset)
{
  if (std::hypot(offset.x(), offset.y()) < 0.5)
    return std::numeric_limits<double>::quiet_NaN();
  return std::atan2(std::abs(offset.x()), -offset.y()) * 57.29577951308232;
}

Clock ClockOf(const Eigen::Vector3d& offset)
{
  const double fromAnterior = DegreesFromFront(offset);
  if (std::isnan(fromAnterior)) // no side
    return Clock::Other;
  if (fromAnterior <= anteriorSectorDeg)
    return Clock::Anterior;
  if (fromAnterior < lateralSectorDeg)
    return offset.x() < 0 ? Clock::Right : Clock::Left; // patient right is −x in LPS
  return Clock::Other;
}

/// Renal arteries run from horizontal (and up to 0.6 of a unit upward) to 65° downward.
constexpr double renalSteepestDescentZ = -0.91;
/// The narrowest renal (median inscribed radius, mm): main renals are 4–7 mm across, accessory
/// ones 2–4 mm; the lumbar arteries, which also leave laterally and posterolaterally, are
/// 1.5–2.5 mm across (inscribed radius ≤ 1 mm on the lumen) and are never named renals.
constexpr double minimumRenalRadiusMm = 1.5, minimumAccessoryRenalRadiusMm = 1.0;

/// The visceral trunks (coeliac, SMA) are the anterior branches at least this share of the widest
/// anterior branch's radius; the thinner ones (the inferior mesenteric's 3–4 mm against the SMA's
/// 6–8 mm) are not.
constexpr double visceralShareOfWidest = 0.7;

/// Names the aorta's side branches by how they leave it (see the header, step 4); unnamed ones
/// stay empty. `sides` are sorted from the top down; landmarks are appended.
std::vector<std::string> NameAorticBranches(const SkeletonGraph& graph,
                                            const std::vector<SideBranch>& sides,
                                            const Point3& bifurcation,
                                            double visceralRadiusMm,
                                            std::vector<Landmark>& landmarks)
{
  std::vector<std::string> names(sides.size());
  const auto height = [&](const SideBranch& s) { return graph.nodes[s.node].position.z() - bifurcation.z(); };
  const auto name = [&](int i, const std::string& vessel)
  {
    names[i] = vessel;
    landmarks.push_back({ vessel + "Ostium", graph.nodes[sides[i].node].position });
  };
  // Anterior: the visceral trunks (the SMA, the coeliac above it) by calibre; the thinner ones
  // are the inferior mesenteric's candidates.
  std::vector<int> anterior;
  double widestAnterior = 0.0;
  for (int i = 0; i < int(sides.size()); ++i)
    if (ClockOf(sides[i].offset) == Clock::Anterior && height(sides[i]) > 20.0 && height(sides[i]) < 250.0)
    {
      anterior.push_back(i); // from the top down
      widestAnterior = std::max(widestAnterior, sides[i].radius);
    }
  const double trunkRadius = std::max(visceralRadiusMm, visceralShareOfWidest * widestAnterior);
  std::vector<int> trunks;
  for (const int i : anterior)
    if (sides[i].radius >= trunkRadius && height(sides[i]) > 30.0)
      trunks.push_back(i);
  double renalCeiling = MaximumRenalHeightMm;
  int sma = -1;
  if (!trunks.empty())
  {
    sma = trunks.back();
    name(sma, "superiorMesenteric");
    renalCeiling = std::min(renalCeiling, height(sides[sma]) + 15.0); // renals leave below it
  }
  if (trunks.size() >= 2)
    name(trunks[trunks.size() - 2], "coeliac");
  // Lateral, between 20 mm above the bifurcation and the superior mesenteric, running out level
  // to 65° down: the widest on each side is the renal artery, the others accessory renals.
  double lowestRenal = std::numeric_limits<double>::infinity();
  for (const Clock side : { Clock::Right, Clock::Left })
  {
    const std::string sideName = side == Clock::Right ? "right" : "left";
    int widest = -1;
    for (int i = 0; i < int(sides.size()); ++i)
    {
      const double z = sides[i].direction.z();
      if (names[i].empty() && ClockOf(sides[i].offset) == side && z >= renalSteepestDescentZ && z <= 0.6 &&
          height(sides[i]) > 20.0 && height(sides[i]) < renalCeiling &&
          sides[i].radius >= minimumAccessoryRenalRadiusMm)
      {
        names[i] = sideName + "AccessoryRenal";
        if (widest < 0 || sides[i].radius > sides[widest].radius)
          widest = i;
      }
    }
    if (widest >= 0 && sides[widest].radius >= minimumRenalRadiusMm)
    {
      name(widest, sideName + "Renal");
      lowestRenal = std::min(lowestRenal, height(sides[widest]));
    }
  }
  // The inferior mesenteric: the widest thinner anterior branch below the SMA and the renals (it
  // leaves the aorta's front 30–50 mm above the bifurcation, from the sac in an AAA).
  const double imaCeiling = std::min(sma >= 0 ? height(sides[sma]) - 20.0 : renalCeiling, lowestRenal - 20.0);
  int ima = -1;
  for (const int i : anterior)
    if (names[i].empty() && sides[i].radius < trunkRadius && height(sides[i]) < imaCeiling &&
        (ima < 0 || sides[i].radius > sides[ima].radius))
      ima = i;
  if (ima >= 0)
    name(ima, "inferiorMesenteric");
  return names;
}

/// How a side branch leaves the aorta, in words: its side (degrees from the front toward the
/// patient's left or right), its course (degrees below or above horizontal), its calibre
/// (twice its median inscribed radius) and its height above the bifurcation.
std::string DescribeBranch(const SideBranch& b, double heightMm)
{
  constexpr double degrees = 57.29577951308232;
  std::string side = "no side (it leaves along the aorta)";
  const double fromFront = DegreesFromFront(b.offset);
  if (!std::isnan(fromFront))
  {
    side = "its " + std::string(fromFront < 1.0 ? "front" : (b.offset.x() < 0 ? "right" : "left")) + " side (" +
           FormatNumber(fromFront, 0) + "° from the front)";
  }
  const double slope = std::asin(std::clamp(b.direction.z(), -1.0, 1.0)) * degrees;
  return "leaves the aorta from " + side + ", runs " + FormatNumber(std::abs(slope), 0) + "° " +
         (slope <= 0 ? "below" : "above") + " horizontal, " + FormatNumber(2 * b.radius, 1) + " mm across, " +
         FormatNumber(heightMm, 0) + " mm above the bifurcation";
}

/// The rule that gave `name` (NameAorticBranches), or why none did (empty name).
std::string NamingRule(const std::string& name)
{
  const auto ends = [&](const std::string& tail)
  { return name.size() >= tail.size() && name.compare(name.size() - tail.size(), tail.size(), tail) == 0; };
  if (name == "superiorMesenteric")
    return "the lowest anterior visceral trunk (at least " + FormatNumber(visceralShareOfWidest, 1) +
           " x the widest anterior branch's calibre)";
  if (name == "coeliac")
    return "the anterior visceral trunk above the superior mesenteric";
  if (name == "inferiorMesenteric")
    return "the widest thinner anterior branch more than 20 mm below the superior mesenteric and the renals";
  if (ends("AccessoryRenal"))
    return "a narrower lateral branch of the renal range on that side";
  if (ends("Renal"))
    return "the widest lateral branch on that side running level to 65° down, between 20 mm above the "
           "bifurcation and 15 mm above the superior mesenteric";
  return "no rule names it (not anterior or lateral, outside the heights or calibres the rules read, or a second "
         "candidate), so it is not forced";
}

/// The partial Y (the file comment, step 1): how much of each cut common iliac the scan holds
/// below the aortic bifurcation B (where the axes meet, VesselOrigins.h; the skeleton's junction
/// lies 2–4 mm lower, in the merged cross-section): from B's foot on the iliac's first tangent
/// along its centerline to its end, then straight on along its last tangent to the lowest slice's
/// centre (the thinned end may stop short of the border). Fewer than `minimumIliacCoverageMm` on
/// a side is an AlgorithmError: the scan ends just below the bifurcation.
void MeasureIliacCoverage(const SkeletonGraph& graph,
                          const CenterlineParams& params,
                          CenterlineTree& tree,
                          const std::array<bool, 2>& cut)
{
  const Point3 b = FindAorticBifurcation(tree).lps;
  const Centerline* iliacs[2] = { &tree.rightIliac, &tree.leftIliac };
  for (int side = 0; side < 2; ++side)
  {
    if (!cut[side])
      continue;
    const Centerline& iliac = *iliacs[side];
    const Point3 start = iliac.points.row(0).transpose();
    const double offset = (start - b).dot(TangentAt(iliac, 0.0));
    const double endZ = iliac.points(iliac.Size() - 1, 2);
    const double descent = std::max(0.5, -TangentAt(iliac, iliac.LengthMm()).z());
    tree.iliacCoverageMm[side] =
      std::max(0.0, offset + iliac.LengthMm() + std::max(0.0, endZ - graph.scanLowestZMm) / descent);
  }
  const double shortest = std::min(cut[0] ? tree.iliacCoverageMm[0] : 1e9, cut[1] ? tree.iliacCoverageMm[1] : 1e9);
  if (shortest >= params.minimumIliacCoverageMm)
    return;
  const auto covered = [&](int side)
  { return cut[side] ? FormatNumber(tree.iliacCoverageMm[side], 1) + " mm" : std::string("all it follows"); };
  throw AlgorithmError("The scan ends just below the aortic bifurcation (at " + FormatPoint(b) +
                       " mm LPS; the scan spans z " + FormatNumber(graph.scanLowestZMm, 1) + " to " +
                       FormatNumber(graph.scanHighestZMm, 1) + " mm, inferior to superior): it holds " + covered(0) +
                       " of the right common iliac below it and " + covered(1) +
                       " of the left; a plan needs at least " + FormatNumber(params.minimumIliacCoverageMm, 0) +
                       " mm of each to tell the Y and place the graft's legs.");
}

/// What the scan covers, for the no-bifurcation error: its z extent, and the vessels its inferior
/// border cuts (a scan that ends above the bifurcation, or too little below it to follow both
/// iliacs `minimumIliacDescentMm` down). Ends with "; ".
std::string ScanCoverage(const SkeletonGraph& graph, const CenterlineParams& params)
{
  std::string text = "the scan spans z " + FormatNumber(graph.scanLowestZMm, 1) + " to " +
                     FormatNumber(graph.scanHighestZMm, 1) + " mm (LPS, inferior to superior)";
  int cut = 0, widest = -1;
  for (int n = 0; n < int(graph.nodes.size()); ++n)
  {
    const SkeletonGraph::Node& node = graph.nodes[n];
    if (AtInferiorBorder(graph, n))
    {
      ++cut;
      if (widest < 0 || node.radiusMm > graph.nodes[widest].radiusMm)
        widest = n;
    }
  }
  if (cut == 0)
    return text + "; ";
  return text + ", and its inferior border cuts " + std::to_string(cut) + (cut == 1 ? " vessel" : " vessels") +
         " (the widest " + FormatNumber(2.0 * graph.nodes[widest].radiusMm, 1) + " mm across at " +
         FormatPoint(graph.nodes[widest].position) + " mm LPS): the scan ends above the aortic bifurcation, or less " +
         "than " + FormatNumber(params.minimumIliacCoverageMm, 0) +
         " mm below it, too little of the common iliacs to tell the Y; ";
}

} // namespace

void ValidateCenterlineParams(const CenterlineParams& params)
{
  CheckRange("centerlineStepMm", params.stepMm, 0.1, 10, "mm");
  CheckRange("centerlineSmoothingMm", params.smoothingMm, 0, 20, "mm");
  CheckRange("directionReachMm", params.directionReachMm, 1, 100, "mm");
  CheckRange("minimumBranchLengthMm", params.minimumBranchLengthMm, 1, 500, "mm");
  CheckRange("minimumIliacLengthMm", params.minimumIliacLengthMm, 1, 500, "mm");
  CheckRange("minimumIliacDescentMm", params.minimumIliacDescentMm, 0, 500, "mm");
  CheckRange("minimumIliacCoverageMm", params.minimumIliacCoverageMm, 0, 500, "mm");
  CheckRange("minimumIliacRadiusRatio", params.minimumIliacRadiusRatio, 0, 1, "");
  CheckRange("internalIliacRadiusRatio", params.internalIliacRadiusRatio, 0, 1, "");
  CheckRange("minimumAortaToIliacRatio", params.minimumAortaToIliacRatio, 0, 10, "");
  CheckRange("visceralRadiusMm", params.visceralRadiusMm, 0, 20, "mm");
  CheckRange("maximumJunctionsInTangle", params.maximumJunctionsInTangle, 1, 100000, "");
}

TangleMeasure MeasureTangle(const SkeletonGraph& graph, double radiusMm)
{
  TangleMeasure t;
  std::vector<int> junctions;
  for (int n = 0; n < int(graph.nodes.size()); ++n)
    if (graph.Degree(n) >= 3)
      junctions.push_back(n);
  for (const SkeletonGraph::Edge& e : graph.edges)
    t.lengthMm += e.lengthMm;
  t.loops = int(graph.edges.size()) - int(graph.nodes.size()) + graph.CountComponents();
  for (const int a : junctions)
  {
    int near = 0;
    for (const int b : junctions)
      near += (graph.nodes[a].position - graph.nodes[b].position).norm() <= radiusMm;
    if (near > t.densestJunctions)
    {
      t.densestJunctions = near;
      t.densestAt = graph.nodes[a].position;
    }
  }
  return t;
}

CenterlineTree LabelAortoIliacTree(const SkeletonGraph& graph, const CenterlineParams& params)
{
  ValidateCenterlineParams(params);
  int ends = 0, junctions = 0;
  for (int n = 0; n < int(graph.nodes.size()); ++n)
  {
    ends += graph.Degree(n) == 1;
    junctions += graph.Degree(n) >= 3;
  }
  const std::string found = std::to_string(ends) + " end points, " + std::to_string(junctions) +
                            " junctions, longest path " + FormatNumber(LongestPathMm(graph), 0) + " mm";
  const int pieces = graph.CountComponents();
  if (pieces != 1)
  {
    throw AlgorithmError("The lumen skeleton breaks into " + std::to_string(pieces) + " pieces (" + found +
                         "); expected one connected aorto-iliac tree; check the segmentation for gaps.");
  }
  const TangleMeasure tangle = MeasureTangle(graph, TangleRadiusMm);
  if (tangle.densestJunctions > params.maximumJunctionsInTangle)
  {
    throw AlgorithmError("The lumen skeleton is a tangle: " + std::to_string(tangle.densestJunctions) +
                         " junctions within " + FormatNumber(TangleRadiusMm, 0) + " mm of " +
                         FormatPoint(tangle.densestAt) + " mm LPS (" + std::to_string(tangle.loops) + " loops in " +
                         FormatNumber(tangle.lengthMm, 0) + " mm of skeleton; " + found +
                         "), where an aorto-iliac tree has at most " + std::to_string(params.maximumJunctionsInTangle) +
                         "; the lumen has leaked into a structure that is no vessel (bowel, bone marrow, a venous "
                         "plexus): check that the seed lies in the aorta and narrow the window (lowerHu, upperHu).");
  }
  std::vector<RefusedY> refused;
  const std::vector<Bifurcation> candidates = FindBifurcations(graph, params, refused);
  if (candidates.empty())
  {
    std::string refusal;
    if (!refused.empty())
    {
      const auto widest = std::max_element(refused.begin(), refused.end(),
                                           [](const auto& a, const auto& b) { return a.score < b.score; });
      refusal = widest->reason + "; ";
    }
    throw AlgorithmError("No aortic bifurcation found in the lumen skeleton (" + found +
                         "); expected a junction with the aorta above and an iliac artery to each side below; " +
                         refusal + ScanCoverage(graph, params) +
                         "check that the scan covers the common iliac arteries and the seed lies in the aorta.");
  }
  const Bifurcation& y = candidates.front();
  if (candidates.size() > 1 && candidates[1].score >= 0.9 * y.score &&
      (graph.nodes[candidates[1].node].position - graph.nodes[y.node].position).norm() > 20.0)
  {
    throw AlgorithmError("Two junctions look like the aortic bifurcation, at " +
                         FormatPoint(graph.nodes[y.node].position) + " and " +
                         FormatPoint(graph.nodes[candidates[1].node].position) + " mm LPS (" + found +
                         "); check the segmentation for a leak into another vessel tree.");
  }

  CenterlineTree tree;
  tree.scanLowestZMm = graph.scanLowestZMm;
  tree.largestSpacingMm = graph.largestSpacingMm;
  tree.scanHighestZMm = graph.scanHighestZMm;
  const double reach = params.directionReachMm;
  const Point3 bifurcation = graph.nodes[y.node].position;
  tree.landmarks.push_back({ "aorticBifurcation", bifurcation });

  // The aorta, upward from the bifurcation; split at its top if it comes down again (the arch).
  VesselPath up = FollowVessel(graph, y.node, y.up, {}, reach);
  std::set<int> mainNodes(up.nodes.begin(), up.nodes.end());
  std::size_t top = 0;
  for (std::size_t i = 0; i < up.points.size(); ++i)
    if (up.points[i].z() > up.points[top].z())
      top = i;
  double topAbscissa = PathLength(std::vector<Point3>(up.points.begin(), up.points.begin() + long(top) + 1));
  std::vector<SideBranch> aorticSides;
  if (PathLength(std::vector<Point3>(up.points.begin() + long(top), up.points.end())) > params.minimumBranchLengthMm)
  {
    tree.sideBranches.push_back(Finish("ascendingAorta",
                                       std::vector<Point3>(up.points.begin() + long(top), up.points.end()),
                                       std::vector<double>(up.radii.begin() + long(top), up.radii.end()), params));
  }
  else
  {
    top = up.points.size() - 1;
    topAbscissa = PathLength(up.points);
  }
  std::vector<Point3> aortaPoints(up.points.begin(), up.points.begin() + long(top) + 1);
  std::vector<double> aortaRadii(up.radii.begin(), up.radii.begin() + long(top) + 1);
  std::reverse(aortaPoints.begin(), aortaPoints.end());
  std::reverse(aortaRadii.begin(), aortaRadii.end());
  tree.aorta = Finish("aorta", aortaPoints, aortaRadii, params);

  // The iliacs, each with its internal iliac. Both are followed first: a side edge of one that
  // runs into the other or back into the aorta is a loop in the skeleton (across the crotch just
  // below the bifurcation, where the two lumens merge), not a branch — followed as one, it led down
  // the other iliac, was long enough and wide enough, and became an internal iliac 5–10 mm below
  // the bifurcation, which left the stent's leg no room.
  const VesselPath iliacPaths[2] = { FollowVessel(graph, y.node, y.right, mainNodes, reach),
                                     FollowVessel(graph, y.node, y.left, mainNodes, reach) };
  const auto iliac = [&](int index, int edge, const std::string& side, Centerline& out)
  {
    const VesselPath& path = iliacPaths[index];
    std::set<int> elsewhere(mainNodes);
    elsewhere.insert(iliacPaths[1 - index].nodes.begin(), iliacPaths[1 - index].nodes.end());
    out = Finish(side + "Iliac", path.points, path.radii, params);
    const double commonRadius = BranchRadius(graph, edge, y.node, reach);
    bool internalFound = false;
    int numbered = 0;
    for (const auto& junction : path.junctions)
      for (int e : junction.sideEdges)
      {
        const VesselPath branch =
          FollowVessel(graph, junction.node, e, std::set<int>(path.nodes.begin(), path.nodes.end()), reach);
        if (std::any_of(branch.nodes.begin() + 1, branch.nodes.end(), [&](int n) { return elsewhere.count(n) > 0; }))
          continue; // a loop into the other iliac or the aorta
        const bool internal =
          !internalFound && ReachableLength(graph, e, junction.node) >= params.minimumBranchLengthMm / 2 &&
          BranchRadius(graph, e, junction.node, reach) >= params.internalIliacRadiusRatio * commonRadius;
        std::string name = internal ? side + "InternalIliac" : side + "IliacBranch" + std::to_string(++numbered);
        if (internal)
        {
          internalFound = true;
          tree.landmarks.push_back({ side + "IliacBifurcation", graph.nodes[junction.node].position });
        }
        tree.sideBranches.push_back(Finish(name, branch.points, branch.radii, params));
      }
  };
  iliac(0, y.right, "right", tree.rightIliac);
  iliac(1, y.left, "left", tree.leftIliac);
  if (y.Partial())
    MeasureIliacCoverage(graph, params, tree, y.cut);

  // Side branches of the aorta (those past the top belong to the ascending aorta: numbered).
  for (const auto& junction : up.junctions)
    for (int e : junction.sideEdges)
    {
      SideBranch side{ FollowVessel(graph, junction.node, e, mainNodes, reach), junction.node,
                       BranchDirection(graph, e, junction.node, reach), BranchRadius(graph, e, junction.node, reach) };
      side.direction = DirectionOutsideParent(side.path.points, tree.aorta, reach, side.direction);
      side.offset = OffsetOutsideParent(side.path.points, tree.aorta);
      if (junction.abscissa > topAbscissa + 1e-6)
        side.direction = side.offset = Eigen::Vector3d::Zero(); // not abdominal: never a renal or visceral branch
      aorticSides.push_back(side);
    }
  // Two side edges whose paths meet again beyond the aorta are one vessel joined to the aorta
  // twice (a loop of the skeleton where a branch leaves obliquely through a long mouth: a renal
  // running 60° down showed it): the narrower path is left out, as on the iliacs.
  const auto beyond = [](const SideBranch& b) { return std::set<int>(b.path.nodes.begin() + 1, b.path.nodes.end()); };
  std::vector<bool> loop(aorticSides.size(), false);
  for (std::size_t i = 0; i < aorticSides.size(); ++i)
    for (std::size_t j = i + 1; j < aorticSides.size(); ++j)
    {
      const std::set<int> a = beyond(aorticSides[i]), b = beyond(aorticSides[j]);
      if (std::any_of(a.begin(), a.end(), [&](int n) { return b.count(n) > 0; }))
        loop[aorticSides[i].radius < aorticSides[j].radius ? i : j] = true;
    }
  std::vector<SideBranch> kept;
  for (std::size_t i = 0; i < aorticSides.size(); ++i)
    if (!loop[i])
      kept.push_back(std::move(aorticSides[i]));
  aorticSides = std::move(kept);
  std::sort(aorticSides.begin(), aorticSides.end(),
            [&](const SideBranch& a, const SideBranch& b)
            { return graph.nodes[a.node].position.z() > graph.nodes[b.node].position.z(); });
  std::vector<std::string> names =
    NameAorticBranches(graph, aorticSides, bifurcation, params.visceralRadiusMm, tree.landmarks);
  int numbered = 0;
  for (int i = 0; i < int(aorticSides.size()); ++i)
  {
    const std::string rule = NamingRule(names[i]);
    if (names[i].empty())
      names[i] = "aorticBranch" + std::to_string(++numbered);
    tree.sideBranches.push_back(Finish(names[i], aorticSides[i].path.points, aorticSides[i].path.radii, params));
    tree.sideBranches.back().evidence =
      DescribeBranch(aorticSides[i], graph.nodes[aorticSides[i].node].position.z() - bifurcation.z()) + ": " + rule;
  }
  // Names are keys: a second accessory renal on one side becomes rightAccessoryRenal2, ….
  for (std::size_t i = 0; i < tree.sideBranches.size(); ++i)
  {
    int copy = 1;
    for (std::size_t j = i + 1; j < tree.sideBranches.size(); ++j)
      if (tree.sideBranches[j].name == tree.sideBranches[i].name)
        tree.sideBranches[j].name += std::to_string(++copy);
  }
  return tree;
}

} // namespace sgp
