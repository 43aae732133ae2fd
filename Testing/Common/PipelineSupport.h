/// \file PipelineSupport.h
/// The planning pipeline as the CLI runs it — up to the centerlines, or on to the measurements —
/// for tests.
#pragma once

#include <optional>

#include <gtest/gtest.h>

#include "Centerlines/AssignInscribedRadii.h"
#include "Centerlines/LabelAortoIliacTree.h"
#include "Centerlines/ThinLabelMap.h"
#include "Measurement/MeasureAnatomy.h"
#include "Phantom/AorticPhantom.h"
#include "Segmentation/GrowLumenRegion.h"
#include "Stent/ActiveContour.h"

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

/// Everything the measurement stage produced, and what it was measured on.
struct MeasuredPlan
{
  LabelImage::Pointer lumen;
  CenterlineTree tree;
  ProximalSite site;
  StentMesh mesh;
  WallDistanceField wall;
  ActiveContourResult fit;
  Measurements measurements;
};

/// Builds the stent mesh with `meshParams` (its proximal start defaulting to the plan's site),
/// the wall field around it, the measure-mode fit and the measurements, as the CLI does.
inline void FitAndMeasure(MeasuredPlan& plan, StentMeshParams meshParams = {})
{
  if (meshParams.proximalAbscissaMm < 0.0)
    meshParams.proximalAbscissaMm = plan.site.abscissaMm;
  plan.mesh = BuildStentMesh(plan.tree, meshParams);
  plan.wall = WallDistanceField::FromLumen(*plan.lumen, 5.0, StentReach(plan.mesh, plan.tree));
  plan.fit = FitActiveContour(plan.mesh, plan.wall, ActiveContourParams::Measure());
  plan.measurements = MeasureAnatomy(plan.tree, plan.mesh, plan.fit.V, plan.site);
}

/// Segmentation, centerlines, proximal site, stent mesh from the site, measure-mode fit and
/// measurements, with the CLI's default parameters.
inline MeasuredPlan MeasureFromCt(const CtImage& ct,
                                  const Point3& seedLps,
                                  const std::optional<Point3>& lowestRenalOstiumLps = {})
{
  MeasuredPlan plan;
  plan.lumen = GrowLumenRegion(ct, seedLps, RegionGrowingParams{}).mask;
  plan.tree = CenterlinesFromMask(*plan.lumen);
  plan.site = FindProximalSite(plan.tree, lowestRenalOstiumLps);
  FitAndMeasure(plan);
  return plan;
}

/// (a)–(f) of `m` each within `diameterMm` of the phantom's truth (the same six in every test).
inline void ExpectDiametersNear(const Measurements& m, const PhantomSizing& truth, double diameterMm)
{
  EXPECT_NEAR(m.Value("proximalNeckDiameter"), truth.proximalNeckDiameter, diameterMm);
  EXPECT_NEAR(m.Value("neckDiameter15mm"), truth.neckDiameter15mm, diameterMm);
  EXPECT_NEAR(m.Value("maxAneurysmDiameter"), truth.maxAneurysmDiameter, diameterMm);
  EXPECT_NEAR(m.Value("distalNeckMinDiameter"), truth.distalNeckMinDiameter, diameterMm);
  EXPECT_NEAR(m.Value("rightIliacDiameter"), truth.rightIliacDiameter, diameterMm);
  EXPECT_NEAR(m.Value("leftIliacDiameter"), truth.leftIliacDiameter, diameterMm);
}

} // namespace sgp::testing
