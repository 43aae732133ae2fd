/// \file PipelineSupport.h
/// The planning pipeline up to the centerlines, as the CLI runs it, for tests.
#pragma once

#include "AssignInscribedRadii.h"
#include "GrowLumenRegion.h"
#include "LabelAortoIliacTree.h"
#include "ThinLabelMap.h"

namespace sgp::testing
{

inline CenterlineTree CenterlinesFromMask(const LabelImage& mask)
{
  const Skeleton skeleton = ThinLabelMap(mask);
  CenterlineTree tree = LabelAortoIliacTree(BuildSkeletonGraph(skeleton, mask));
  AssignInscribedRadii(tree, skeleton);
  return tree;
}

inline CenterlineTree CenterlinesFromCt(const CtImage& ct, const Point3& seedLps)
{
  return CenterlinesFromMask(*GrowLumenRegion(ct, seedLps, RegionGrowingParams{}).mask);
}

} // namespace sgp::testing
