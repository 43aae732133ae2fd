/// \file PipelineSupport.h
/// The planning pipeline as the CLI runs it — up to the centerlines, or on to the measurements —
/// for tests.
#pragma once

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "Centerlines/AssignInscribedRadii.h"
#include "Centerlines/LabelAortoIliacTree.h"
#include "Centerlines/ThinLabelMap.h"
#include "Measurement/MeasureAnatomy.h"
#include "Phantom/AorticPhantom.h"
#include "Segmentation/GrowLumenRegion.h"
#include "Stent/ActiveContour.h"
#include "Wall/VesselWall.h"

namespace sgp::testing
{

/// Whether any of `warnings` contains `part`.
inline bool AnyWarningContains(const std::vector<std::string>& warnings, const std::string& part)
{
  return std::any_of(warnings.begin(), warnings.end(),
                     [&](const std::string& w) { return w.find(part) != std::string::npos; });
}

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
  VesselWall vesselWall; ///< traced when the CT was given (MeasureFromCt)
  Measurements measurements;
};

/// Builds the stent mesh with `meshParams` (its proximal start defaulting to the plan's site),
/// the wall field around it, the measure-mode fit, the outer wall (when `ct` is given; calcium
/// above `calciumHu`) and the measurements, as the CLI does.
inline void FitAndMeasure(MeasuredPlan& plan,
                          StentMeshParams meshParams = {},
                          const CtImage* ct = nullptr,
                          double calciumHu = 1000.0)
{
  if (meshParams.proximalAbscissaMm < 0.0)
    meshParams.proximalAbscissaMm = plan.site.abscissaMm;
  plan.mesh = BuildStentMesh(plan.tree, meshParams);
  plan.wall = WallDistanceField::FromLumen(*plan.lumen, 5.0, StentReach(plan.mesh, plan.tree));
  plan.fit = FitActiveContour(plan.mesh, plan.wall, ActiveContourParams::Measure());
  if (ct)
  {
    VesselWallParams wallParams;
    wallParams.calciumHu = std::min(calciumHu, wallParams.calciumHu);
    plan.vesselWall = TraceVesselWall(*ct, *plan.lumen, plan.tree, plan.site.abscissaMm, wallParams);
  }
  plan.measurements = MeasureAnatomy(plan.tree, plan.mesh, plan.fit.V, plan.site, ct ? &plan.vesselWall : nullptr,
                                     plan.lumen.GetPointer());
}

/// Segmentation, centerlines, proximal site, stent mesh from the site, measure-mode fit, outer
/// wall and measurements, with the CLI's default parameters (the region growing's may be given).
inline MeasuredPlan MeasureFromCt(const CtImage& ct,
                                  const Point3& seedLps,
                                  const std::optional<Point3>& lowestRenalOstiumLps = {},
                                  const RegionGrowingParams& growing = {})
{
  MeasuredPlan plan;
  const LumenSegmentation lumen = GrowLumenRegion(ct, seedLps, growing);
  plan.lumen = lumen.mask;
  plan.tree = CenterlinesFromMask(*plan.lumen);
  plan.site = FindProximalSite(plan.tree, lowestRenalOstiumLps);
  FitAndMeasure(plan, {}, &ct, lumen.calciumHu);
  return plan;
}

/// The lumen (a)–(f) of `m` each within `diameterMm` of the phantom's lumen truth (the same six
/// in every test).
inline void ExpectDiametersNear(const Measurements& m, const PhantomSizing& truth, double diameterMm)
{
  EXPECT_NEAR(m.Value("proximalNeckLumenDiameter"), truth.proximalNeckDiameter, diameterMm);
  EXPECT_NEAR(m.Value("neckLumenDiameter15mm"), truth.neckDiameter15mm, diameterMm);
  EXPECT_NEAR(m.Value("maxAneurysmLumenDiameter"), truth.maxAneurysmDiameter, diameterMm);
  EXPECT_NEAR(m.Value("distalNeckMinLumenDiameter"), truth.distalNeckMinDiameter, diameterMm);
  EXPECT_NEAR(m.Value("rightIliacLumenDiameter"), truth.rightIliacDiameter, diameterMm);
  EXPECT_NEAR(m.Value("leftIliacLumenDiameter"), truth.leftIliacDiameter, diameterMm);
}

/// The outer-wall (a)–(f) of `m` each within `diameterMm` of the phantom's outer-wall truth.
inline void ExpectOuterDiametersNear(const Measurements& m, const PhantomSizing& truth, double diameterMm)
{
  EXPECT_NEAR(m.Value("proximalNeckDiameter"), truth.outerProximalNeckDiameter, diameterMm);
  EXPECT_NEAR(m.Value("neckDiameter15mm"), truth.outerNeckDiameter15mm, diameterMm);
  EXPECT_NEAR(m.Value("maxAneurysmDiameter"), truth.outerMaxAneurysmDiameter, diameterMm);
  EXPECT_NEAR(m.Value("distalNeckMinDiameter"), truth.outerDistalNeckMinDiameter, diameterMm);
  EXPECT_NEAR(m.Value("rightIliacDiameter"), truth.outerRightIliacDiameter, diameterMm);
  EXPECT_NEAR(m.Value("leftIliacDiameter"), truth.outerLeftIliacDiameter, diameterMm);
}

} // namespace sgp::testing
