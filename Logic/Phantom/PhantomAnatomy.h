/// \file PhantomAnatomy.h
/// The synthetic phantom's anatomy before it is drawn (AorticPhantom.h describes it): the vessels
/// as tubes (an axis polyline and a radius along it), the kidneys, the vertebral column and the
/// aorta's wall, with their analytic truth. Internal to Logic/Phantom (AorticPhantom.cxx draws
/// it, PhantomRaster.h holds the drawing). Frame: LPS mm, z superior.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "Common/Types.h"
#include "Phantom/AorticPhantom.h"
#include "Phantom/AorticWall.h"

namespace sgp::phantom
{

constexpr double pi = 3.14159265358979323846;
constexpr double renalHilumLateralMm = 64.0, renalHilumPosteriorMm = 10.0; ///< from the renal's origin
constexpr double visceralRadiusMm = 3.5;
constexpr double accessoryRenalRadiusMm = 2.0;
constexpr double imaRadiusMm = 1.75;
constexpr double renalBranchRadiusMm = 2.2;
constexpr double renalBranchTurnDeg = 25.0;
constexpr double kinkFromBifurcationMm = 10.0; ///< where a kinked common iliac bends
constexpr double vertebraRadiusMm = 20.0;
constexpr double corticalThicknessMm = 2.0;
constexpr double corticalHu = 1100.0; // blurred by 1 mm, the 2 mm shell peaks near 800 HU
constexpr double cancellousHu = 250.0;
constexpr double marginMm = 10.0;

/// A vessel to voxelize: an axis polyline and the radius as a function of arc length from its
/// first vertex.
struct Tube
{
  std::string name;
  std::vector<Point3> axis;
  std::function<double(double)> radiusAt;
  double maxRadius = 0.0;
};

struct Ellipsoid
{
  Point3 centre;
  Point3 semiAxes;
};

struct Anatomy
{
  std::vector<Tube> tubes;          ///< lumens
  std::vector<Tube> wallTubes;      ///< the iliacs' outer walls (drawn at wallHu; their lumens override)
  std::unique_ptr<AorticWall> wall; ///< the aorta's wall, thrombus, calcium and neighbours, if any
  double siteZ = 0.0;               ///< the proximal implantation site's height (bolus gradient reference)
  std::vector<Ellipsoid> kidneys;
  bool column = false;
  double columnY = 0.0; ///< centre of the vertebral column (x = 0), LPS mm
  PhantomTruth truth;
};

/// See PhantomAnatomy.cxx.
Anatomy BuildAnatomy(const PhantomParams& p);

class TubeDistance; // PhantomRaster.h

/// The signed distance (mm, negative inside) at `x` of `anatomy`'s tube `tube` (`distance` its
/// TubeDistance): for the aorta's lumen (tube 0) drawn level by level in the neck thrombus's
/// stretch (AorticWall::NeckLumenSignedDistance), every other point and tube the tube's own. What
/// the raster draws the lumens with, and the truths read off them.
double LumenSignedDistance(const Anatomy& anatomy, std::size_t tube, TubeDistance& distance, const Point3& x);

/// Samples each tube's axis every 1 mm (and at its end) with the radius there.
void SampleVessels(const Anatomy& anatomy, PhantomTruth& truth);

/// LPS bounding box {min, max} of the anatomy plus the margin.
std::array<Point3, 2> AnatomyBounds(const Anatomy& anatomy);

/// The LPS box {min, max} of a tube's voxels, its radius and `reach` (the blur) around its axis.
std::array<Point3, 2> TubeBox(const Tube& tube, double reach);

} // namespace sgp::phantom
