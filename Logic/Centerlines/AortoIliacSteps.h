/// \file AortoIliacSteps.h
/// The steps of LabelAortoIliacTree (LabelAortoIliacTree.h, whose file comment describes the rules),
/// shared by the files that hold them: SkeletonPaths.cxx (branches and vessels followed through the
/// skeleton graph), FindBifurcation.cxx (step 1, the Y and the scan's coverage), NameSideBranches.cxx
/// (step 4). Internal to Logic/Centerlines. Frame: LPS mm, z superior.
#pragma once

#include <set>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "Centerlines/Centerlines.h"
#include "Centerlines/LabelAortoIliacTree.h"
#include "Centerlines/SkeletonGraph.h"

namespace sgp::aorto_iliac
{

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
  /// It ran back into the path it left or into `blocked` — its first edge leads straight there, or
  /// it ended where every way on leads back (not at an end point, nor closed off in a loop of its
  /// own): the other strand of a loop along a vessel, not a vessel of its own.
  bool runsBack = false;
};

struct Bifurcation
{
  int node = -1;
  int up = -1, right = -1, left = -1;
  double score = 0.0;
  std::array<bool, 2> cut{ false, false }; ///< right, left: cut by the scan's inferior border first
  bool Partial() const { return cut[0] || cut[1]; }
};

/// A junction with the shape of a Y that is refused as the bifurcation, and why.
struct RefusedY
{
  int node = -1;
  double score = 0.0; ///< as Bifurcation::score
  std::string reason;
};

/// A side branch before naming: the path and how it leaves its parent.
struct SideBranch
{
  VesselPath path;
  int node;
  Eigen::Vector3d direction; ///< its course as it leaves (DirectionOutsideParent)
  double radius;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero(); ///< the side it leaves from (OffsetOutsideParent)
};

// SkeletonPaths.cxx
/// See SkeletonPaths.cxx.

/// Median radius of `edge` leaving `node`, beyond the junction's own radius (where the
/// inscribed sphere still touches the parent vessel) and within `reach` mm after it.
double BranchRadius(const SkeletonGraph& graph, int edge, int node, double reach);

/// Unit direction from `node` to the point `reach` mm along `edge`, continuing through the
/// widest branch at junctions when the edge is shorter.
Eigen::Vector3d BranchDirection(const SkeletonGraph& graph, int edge, int node, double reach);

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
                                       const Eigen::Vector3d& fromJunction);

/// Where around its parent a side branch leaves (step 4): the unit vector from the parent's axis,
/// perpendicular to it, to the branch's first point at least `outsideParentStartMm` outside the
/// parent's wall — the side of the aorta the branch lies on as it leaves, whatever its course
/// then (an SMA that turns down at once runs in front of the aorta: anterior). Zero when the path
/// never leaves the parent.
Eigen::Vector3d OffsetOutsideParent(const std::vector<Point3>& branch, const Centerline& parent);

/// Total length of vessel reachable through `edge` from `node` without passing `node` again.
double ReachableLength(const SkeletonGraph& graph, int edge, int node);

/// See SkeletonPaths.cxx.
double PathLength(const std::vector<Point3>& points);

/// Follows the vessel: at each junction the branch scoring best on radius × (1 + cos turn)/2,
/// among those that lead to an end the path has not passed; the others that do, and those closed
/// off in a loop of their own (touching neither the path nor `blocked`), are the junction's side
/// edges; a way back into the path is neither.
VesselPath FollowVessel(const SkeletonGraph& graph, int start, int firstEdge, std::set<int> blocked, double reach);

/// Longest shortest-path distance in the graph, by two Dijkstra sweeps (exact on a tree).
double LongestPathMm(const SkeletonGraph& graph);

// FindBifurcation.cxx
/// See FindBifurcation.cxx.
std::vector<Bifurcation> FindBifurcations(const SkeletonGraph& graph,
                                          const CenterlineParams& params,
                                          std::vector<RefusedY>& refused);

/// The partial Y (the file comment, step 1): how much of each cut common iliac the scan holds
/// below the aortic bifurcation B (where the axes meet, VesselOrigins.h; the skeleton's junction
/// lies 2–4 mm lower, in the merged cross-section): from B's foot on the iliac's first tangent
/// along its centerline to its end, then straight on along its last tangent to the lowest slice's
/// centre (the thinned end may stop short of the border). Fewer than `minimumIliacCoverageMm` on
/// a side is an AlgorithmError: the scan ends just below the bifurcation.
void MeasureIliacCoverage(const SkeletonGraph& graph,
                          const CenterlineParams& params,
                          CenterlineTree& tree,
                          const std::array<bool, 2>& cut);

/// What the scan covers, for the no-bifurcation error: its z extent, and the vessels its inferior
/// border cuts (a scan that ends above the bifurcation, or too little below it to follow both
/// iliacs `minimumIliacDescentMm` down). Ends with "; ".
std::string ScanCoverage(const SkeletonGraph& graph, const CenterlineParams& params);

// NameSideBranches.cxx
/// Names the aorta's side branches by how they leave it (see the header, step 4); unnamed ones
/// stay empty. `sides` are sorted from the top down; landmarks are appended.
std::vector<std::string> NameAorticBranches(const SkeletonGraph& graph,
                                            const std::vector<SideBranch>& sides,
                                            const Point3& bifurcation,
                                            double visceralRadiusMm,
                                            std::vector<Landmark>& landmarks);

/// How a side branch leaves the aorta, in words: its side (degrees from the front toward the
/// patient's left or right), its course (degrees below or above horizontal), its calibre
/// (twice its median inscribed radius) and its height above the bifurcation.
std::string DescribeBranch(const SideBranch& b, double heightMm);

/// The rule that gave `name` (NameAorticBranches), or why none did (empty name).
std::string NamingRule(const std::string& name);

} // namespace sgp::aorto_iliac
