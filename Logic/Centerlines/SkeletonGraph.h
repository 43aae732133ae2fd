/// \file SkeletonGraph.h
/// Turns skeleton voxels into a graph of vessel segments: nodes at curve ends and junctions,
/// edges along the voxel paths between them, with spurs pruned.
///
/// 1. Each skeleton voxel's 26-neighbours in the skeleton give its degree. Voxels of degree 1 are
///    end nodes; 26-connected clusters of voxels of degree ≥ 3 are merged into one junction node
///    (at their mean position, with their largest radius).
/// 2. Edges follow the voxels of degree 2 from node to node; their points run from the first
///    node's position through the voxel centres to the second node's position (LPS mm), each
///    with its inscribed radius (mm).
/// 3. Simplification, repeated until nothing changes:
///    - a *spur* — an edge from an end node to a junction — shorter than
///      max(`minimumSpurLengthMm`, `spurLengthRatio` × the junction's radius) is noise on the
///      vessel wall, not a vessel (a surface bump thins into a hair from the wall to the axis,
///      about one radius long), and is removed — unless the inscribed ball at its end reaches
///      within one voxel of the image's border: a vessel the scan cuts (ThinLabelMap runs its
///      skeleton to the border), such as the aorta's stump above the coeliac when the scan ends
///      there — or unless it is a *branch stub*: its end lies more than 5 mm beyond the junction's
///      inscribed ball and its median inscribed radius beyond the ball is 1.5 mm or more and at
///      most half the junction's (a renal artery the mask holds only 8 mm of; issue 31). (A rule
///      keeping a short branch as wide as its parent was tried and dropped: the
///      irregular real sacs of AVT D3 and D4 grow such bulges, and kept, they moved D4's
///      bifurcation by 35 mm and cut D3's right iliac to 64 mm.)
///    - a node left with two edges is dissolved, joining them;
///    - two junctions joined by an edge shorter than `junctionMergeRatio` × the smaller radius
///      are one branching seen twice by the voxel grid, and are merged at the edge's midpoint.
///
/// Input: a Skeleton (ThinLabelMap) and the image it was computed on (for index adjacency and
/// its border).
/// Output: nodes and edges; removed ones are dropped, so every index is live.
/// Errors: InputError for an empty skeleton or parameters out of range.
/// Complexity: linear in the skeleton's voxels, times the simplification rounds (few).
#pragma once

#include <vector>

#include "Centerlines/ThinLabelMap.h"
#include "Common/Types.h"

namespace sgp
{

struct SkeletonGraphParams
{
  double spurLengthRatio = 2.0;     ///< see the file comment; in [0, 10]
  double minimumSpurLengthMm = 3.0; ///< in [0, 50]
  double junctionMergeRatio = 0.25; ///< in [0, 2]
};

struct SkeletonGraph
{
  struct Node
  {
    Point3 position;        ///< LPS mm
    double radiusMm = 0.0;  ///< inscribed radius at the node
    std::vector<int> edges; ///< incident edges
    bool atBorder = false;  ///< an end whose inscribed ball reaches the image's border (a cut vessel)
  };
  struct Edge
  {
    int a = -1, b = -1;           ///< end nodes; points run from a to b
    std::vector<Point3> points;   ///< LPS mm, first = node a, last = node b
    std::vector<double> radiusMm; ///< per point
    double lengthMm = 0.0;        ///< polyline length
  };
  std::vector<Node> nodes;
  std::vector<Edge> edges;
  /// The image's extent along LPS z (inferior to superior): the lowest and highest z of its
  /// corner voxel centres, mm; for error messages about what the scan covers.
  double scanLowestZMm = 0.0, scanHighestZMm = 0.0;
  double largestSpacingMm = 0.0; ///< the image's coarsest voxel spacing (its slice thickness, mostly), mm

  int Degree(int node) const { return static_cast<int>(nodes[node].edges.size()); }
  int Other(int edge, int node) const { return edges[edge].a == node ? edges[edge].b : edges[edge].a; }
  /// Number of connected components (isolated nodes count).
  int CountComponents() const;
};

void ValidateSkeletonGraphParams(const SkeletonGraphParams& params);

SkeletonGraph BuildSkeletonGraph(const Skeleton& skeleton,
                                 const LabelImage& reference,
                                 const SkeletonGraphParams& params = {});

/// The edge's points from `node`'s end: reversed when `node` is its b end.
std::vector<Point3> PointsFrom(const SkeletonGraph& graph, int edge, int node);
/// The edge's radii from `node`'s end.
std::vector<double> RadiiFrom(const SkeletonGraph& graph, int edge, int node);

} // namespace sgp
