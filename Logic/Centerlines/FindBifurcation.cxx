// Step 1 of LabelAortoIliacTree: the aortic bifurcation, and the scan's coverage (AortoIliacSteps.h).
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

/// A lower limb at least this share of the upper branch's radius, with another Y below it, is
/// the aorta running on (FindBifurcations); the same share as the rule that the upper branch is at
/// least 0.8 × the wider lower one.
constexpr double AortaRunsOnShare = 0.8;

/// How far past its junction's inscribed sphere a side branch must reach to be a vessel leaving
/// (the visceral rule of FindBifurcations), mm: as a branch stub's end (SkeletonGraph.h).
constexpr double VisceralBeyondJunctionMm = 5.0;

/// Whether the vessel followed from `node` along `edge` reaches VisceralBeyondJunctionMm past the
/// node's inscribed sphere.
bool ReachesBeyond(const SkeletonGraph& graph, int node, int edge, double reach)
{
  const Point3& centre = graph.nodes[node].position;
  const double sphere = graph.nodes[node].radiusMm + VisceralBeyondJunctionMm;
  const VesselPath path = FollowVessel(graph, node, edge, {}, reach);
  return std::any_of(path.points.begin(), path.points.end(),
                     [&](const Point3& p) { return (p - centre).norm() > sphere; });
}

} // namespace

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
      // The median radius along the vessel followed up — the whole aorta, not the sac or the
      // funnel the junction may lie in — computed when a rule needs it.
      double aortaMedian = -1.0;
      const auto aortaRadius = [&]
      {
        if (aortaMedian < 0.0)
          aortaMedian = Median(FollowVessel(graph, n, up.edge, {}, params.directionReachMm).radii);
        return aortaMedian;
      };
      for (const Branch& right : branches)
        for (const Branch& left : branches)
        {
          const bool lower = right.direction.z() < -0.2 && left.direction.z() < -0.2;
          // Toward opposite sides of each other: the aorta may run obliquely, so the two
          // directions are compared with each other rather than with the x axis.
          const bool sides = left.direction.x() - right.direction.x() > 0.3;
          // The iliacs are narrower than the aorta, but not much: this also rejects the arch in
          // a chest scan, whose two limbs go down under a narrow supra-aortic branch. The
          // narrowest iliac is compared with the narrower of the aorta's radius at the junction
          // and its median: a junction in a sac's floor or a funnel has the sac's radius there
          // (15 mm over a 4.4 mm iliac lumen, a ratio of 0.15), the aorta's median is its own.
          if (!(lower && sides && up.radius >= 0.8 * std::max(right.radius, left.radius)))
            continue;
          const double narrower = std::min(right.radius, left.radius);
          if (narrower < params.minimumIliacRadiusRatio * up.radius &&
              narrower < params.minimumIliacRadiusRatio * aortaRadius())
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
          // Two lower limbs that meet again are one vessel's skeleton looping round something in
          // its lumen (a plaque's blurred end grown into the lumen as a thin shell round it), not
          // two vessels parting: the wider strand, followed down, and the other join and run on
          // as one.
          const std::set<int> rightNodes(rightPath.nodes.begin() + 1, rightPath.nodes.end());
          const auto rejoined = std::find_if(leftPath.nodes.begin() + 1, leftPath.nodes.end(),
                                             [&](int node) { return rightNodes.count(node) > 0; });
          if (rejoined != leftPath.nodes.end())
          {
            refused.push_back({ n, score,
                                where + "its two lower limbs meet again at " +
                                  FormatPoint(graph.nodes[*rejoined].position) +
                                  " mm LPS: a loop of one vessel's skeleton, not two vessels parting" });
            continue;
          }
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
          const double iliacRadius = std::max(Median(rightPath.radii), Median(leftPath.radii));
          if (aortaRadius() < params.minimumAortaToIliacRatio * iliacRadius)
          {
            refused.push_back({ n, score,
                                where + "the vessel above it (median " + FormatNumber(2.0 * aortaRadius(), 1) +
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
          // (A branch is a vessel leaving: its skeleton reaches VisceralBeyondJunctionMm past the
          // junction's inscribed sphere. A strand inside a 14 mm iliac's own sphere, 2 mm from the
          // junction with 6.5 mm of radius there, refused the real Y: the sweep's seed 246 #45.)
          std::string visceral;
          for (const auto* path : { &rightPath, &leftPath })
            for (const auto& junction : path->junctions)
              for (int e : junction.sideEdges)
                if (visceral.empty() && BranchDirection(graph, e, junction.node, params.directionReachMm).y() < -0.6 &&
                    BranchRadius(graph, e, junction.node, params.directionReachMm) >= params.visceralRadiusMm &&
                    ReachableLength(graph, e, junction.node) >= params.minimumBranchLengthMm / 2 &&
                    ReachesBeyond(graph, junction.node, e, params.directionReachMm))
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
  // A Y with another Y below it on a lower limb that is as wide as the vessel above (at least
  // AortaRunsOnShare of it) is the aorta running on down to its bifurcation with a branch leaving
  // it — the superior mesenteric running down in front of it scored 3.4 mm where the real Y's
  // narrower iliac (a 4.6 mm lumen) scored 2.2 — not the bifurcation: the aorta does not divide
  // twice. Judged over every candidate, partial ones too, so that the real Y cut by the scan's
  // border still removes the one above it.
  std::vector<Bifurcation> kept;
  for (const Bifurcation& a : found)
  {
    int below = -1;
    const double upRadius = BranchRadius(graph, a.up, a.node, params.directionReachMm);
    for (const int edge : { a.right, a.left })
    {
      if (BranchRadius(graph, edge, a.node, params.directionReachMm) < AortaRunsOnShare * upRadius)
        continue;
      const VesselPath path = FollowVessel(graph, a.node, edge, {}, params.directionReachMm);
      for (const Bifurcation& b : found)
        if (b.node != a.node && std::find(path.nodes.begin() + 1, path.nodes.end(), b.node) != path.nodes.end())
          below = b.node;
    }
    if (below < 0)
    {
      kept.push_back(a);
      continue;
    }
    refused.push_back({ a.node, a.score,
                        "the junction at " + FormatPoint(graph.nodes[a.node].position) +
                          " mm LPS has the shape of a Y, but a lower limb as wide as the vessel above it runs on to "
                          "another Y at " +
                          FormatPoint(graph.nodes[below].position) +
                          " mm LPS: the aorta running on with a branch leaving it, not its bifurcation" });
  }
  found.swap(kept);
  // A partial Y only where the scan holds no whole one.
  if (std::any_of(found.begin(), found.end(), [](const Bifurcation& b) { return !b.Partial(); }))
    found.erase(std::remove_if(found.begin(), found.end(), [](const Bifurcation& b) { return b.Partial(); }),
                found.end());
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.score > b.score; });
  return found;
}

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

} // namespace sgp::aorto_iliac
