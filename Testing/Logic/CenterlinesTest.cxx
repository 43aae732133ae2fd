// The labelled Y on the aneurysm phantom, against its analytic axes (issue: centerlines).
#include <gtest/gtest.h>

#include "AssignInscribedRadii.h"
#include "CenterlineTestSupport.h"
#include "GrowLumenRegion.h"
#include "LabelAortoIliacTree.h"
#include "ThinLabelMap.h"

namespace sgp
{
namespace
{

TEST(LabelAortoIliacTree, Explore)
{
  PhantomParams p;
  p.includeKidneys = true;
  p.includeBone = true;
  const AorticPhantom ph = GenerateAorticPhantom(p);
  const auto lumen = GrowLumenRegion(*ph.ct, ph.truth.seedLps, {});
  const auto sk = ThinLabelMap(*lumen.mask);
  const auto g = BuildSkeletonGraph(sk, *lumen.mask);
  for (int n = 0; n < int(g.nodes.size()); ++n)
    std::cout << " node " << n << " deg " << g.Degree(n) << " at " << g.nodes[n].position.transpose() << " r "
              << g.nodes[n].radiusMm << "\n";
  auto tree = LabelAortoIliacTree(g);
  AssignInscribedRadii(tree, sk);
  for (auto& l : tree.landmarks)
    std::cout << " landmark " << l.name << " " << l.lps.transpose() << "\n";
  std::vector<const Centerline*> all{ &tree.aorta, &tree.rightIliac, &tree.leftIliac };
  for (auto& c : tree.sideBranches)
    all.push_back(&c);
  for (auto* c : all)
  {
    std::vector<std::string> names{ c->name };
    if (c->name == "rightIliac" || c->name == "leftIliac")
      names.push_back(c->name.substr(0, c->name.size() - 5) + "ExternalIliac");
    const auto a = testing::CompareWithAxes(*c, ph.truth, names, 15, 5);
    std::cout << c->name << " len " << c->LengthMm() << " meanDist " << a.meanDistanceMm << " maxDist "
              << a.maxDistanceMm << " meanRadErr " << a.meanRadiusErrorMm << " maxRadErr " << a.maxRadiusErrorMm << " signed " << a.meanSignedRadiusErrorMm
              << " start " << c->points.row(0) << " end " << c->points.row(c->Size() - 1) << "\n";
  }
}

} // namespace
} // namespace sgp
