// Branches and vessels followed through the skeleton graph (AortoIliacSteps.h).
#include "Centerlines/AortoIliacSteps.h"

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
#include "Common/Errors.h"
#include "Common/Format.h"
#include "Common/Median.h"

namespace sgp::aorto_iliac
{

namespace
{

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

/// How far a side branch must run outside its parent's wall before its direction is read, mm (as
/// the renal axis of ProximalSite.h, which starts 1 mm outside the wall).
constexpr double outsideParentStartMm = 1.0;

/// Where `edge` leads from `node`, never passing `node` or a node of `blocked`: to an end point
/// (degree 1) the path has not passed; or, reaching none, to nothing but itself and `node` — a
/// branch that ends in a loop of the skeleton (a one-voxel hole in a thin renal's blurred lumen
/// made a ring at its tip, and the renal was dropped as a way back into the path); or back into
/// the path (a node of `blocked` other than `node`).
enum class WayOn
{
  NewEnd,
  ClosedOff,
  BackIntoPath
};

WayOn FollowWayOn(const SkeletonGraph& graph, int node, int edge, const std::set<int>& blocked)
{
  std::set<int> seen;
  std::vector<int> stack{ graph.Other(edge, node) };
  bool touches = false;
  while (!stack.empty())
  {
    const int n = stack.back();
    stack.pop_back();
    if (n == node)
      continue; // back at the junction only: a loop of its own
    if (blocked.count(n))
    {
      touches = true; // into the path
      continue;
    }
    if (!seen.insert(n).second)
      continue;
    if (graph.Degree(n) == 1)
      return WayOn::NewEnd;
    for (int e : graph.nodes[n].edges)
      if (e != edge) // not back the way in
        stack.push_back(graph.Other(e, n));
  }
  return touches ? WayOn::BackIntoPath : WayOn::ClosedOff;
}

} // namespace

/// Median radius of `edge` leaving `node`, beyond the junction's own radius (where the
/// inscribed sphere still touches the parent vessel) and within `reach` mm after it. An edge that
/// ends inside that sphere is followed on through the widest way (by its own edges' median radii)
/// until the window starts: a sac's dome thins into a spur whose first edge, a few mm long, lies
/// in the sac's sphere and carried the sac's radius, so a blind spur 1–2 mm wide beyond it
/// outscored the neck it sat beside (a 58° neck narrowed by thrombus was left for the spur).
double BranchRadius(const SkeletonGraph& graph, int edge, int node, double reach)
{
  const double from = graph.Degree(node) >= 3 ? graph.nodes[node].radiusMm : 0.0;
  std::vector<double> inside, first;
  double s = 0.0;
  std::set<int> seen{ node };
  for (int e = edge, at = node; e >= 0;)
  {
    const auto points = PointsFrom(graph, e, at);
    const auto radii = RadiiFrom(graph, e, at);
    for (std::size_t i = 1; i < points.size(); ++i)
    {
      s += (points[i] - points[i - 1]).norm();
      if (e == edge)
        first.push_back(radii[i]);
      if (s >= from && s <= from + reach)
        inside.push_back(radii[i]);
    }
    at = graph.Other(e, at);
    if (!inside.empty() || !seen.insert(at).second)
      break;
    // Still inside the junction's sphere: on along the widest edge (its own median radius).
    int next = -1;
    double widest = -1.0;
    for (int c : graph.nodes[at].edges)
      if (c != e && graph.edges[c].a != graph.edges[c].b)
      {
        const double r = Median(graph.edges[c].radiusMm);
        if (r > widest)
          next = c, widest = r;
      }
    e = next;
  }
  return Median(inside.empty() ? first : inside);
}

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

double PathLength(const std::vector<Point3>& points)
{
  double s = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i)
    s += (points[i] - points[i - 1]).norm();
  return s;
}

VesselPath FollowVessel(const SkeletonGraph& graph, int start, int firstEdge, std::set<int> blocked, double reach)
{
  VesselPath path;
  path.points = PointsFrom(graph, firstEdge, start);
  path.radii = RadiiFrom(graph, firstEdge, start);
  path.nodes.push_back(start);
  blocked.insert(start);
  int node = graph.Other(firstEdge, start), incoming = firstEdge;
  path.runsBack = blocked.count(node) > 0; // the first edge leads straight back
  while (blocked.insert(node).second)
  {
    path.nodes.push_back(node);
    // Ways on that reach an end the path has not passed: a loop in the skeleton (a tunnel through
    // a sac) leads only back into the path, and taken, it ended the aorta in the sac.
    // A branch closed off in a loop is a side branch, never the way on.
    std::vector<int> options, closedOff;
    bool leadsBack = false;
    for (int e : graph.nodes[node].edges)
      if (e != incoming && graph.edges[e].a != graph.edges[e].b)
      {
        const WayOn way = FollowWayOn(graph, node, e, blocked);
        if (way == WayOn::NewEnd)
          options.push_back(e);
        else if (way == WayOn::ClosedOff)
          closedOff.push_back(e);
        else
          leadsBack = true;
      }
    if (options.empty())
    {
      path.runsBack = leadsBack && closedOff.empty();
      break;
    }
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
    VesselPath::Junction junction{ node, PathLength(path.points), closedOff };
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

} // namespace sgp::aorto_iliac
