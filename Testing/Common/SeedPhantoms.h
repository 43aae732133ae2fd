/// \file SeedPhantoms.h
/// The phantoms the automatic-seed tests run on (issue 16 item 1: "every phantom the tests
/// generate, including rotated and flipped grids, bone and kidneys"): six named variants that
/// between them hold every option the phantom generator has that changes what lies around the
/// aorta, and random anatomies drawn over the random-anatomy sweep's ranges. Shared by the seed
/// finder's test (the seed lies in the lumen) and the plan test (the plan equals the truth seed's).
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "Phantom/AorticPhantom.h"
#include "PhantomTestSupport.h"

namespace sgp::testing
{

/// One named phantom.
struct SeedPhantom
{
  std::string name;
  PhantomParams params;
};

/// Seven variants: default; bone and kidneys; an oblique flipped grid with bone 1 mm behind the sac;
/// 3 mm slices with a 60° neck and kidneys; low contrast with kidneys nearly as bright and a small
/// sac; an 80 mm sac with thrombus in fat beside the IVC, psoas, duodenum, left renal vein and bone;
/// calcium arcs in the neck and sac with neck thrombus and a bolus whose HU changes with height (so
/// two seeds at different levels sit in lumen of different HU).
inline std::vector<SeedPhantom> SeedTestPhantoms()
{
  std::vector<SeedPhantom> v;
  v.push_back({ "default", PhantomParams{} });
  PhantomParams p;
  p.includeBone = true;
  p.includeKidneys = true;
  v.push_back({ "bone and kidneys", p });
  p = PhantomParams{};
  p.directionLps = ObliqueFlippedDirection();
  p.includeBone = true;
  p.boneGapMm = 1.0;
  v.push_back({ "oblique flipped grid, bone 1 mm behind the sac", p });
  p = PhantomParams{};
  p.spacingMm = { 0.79, 0.79, 3.0 };
  p.neckAngleDeg = 60.0;
  p.includeKidneys = true;
  v.push_back({ "3 mm slices, neck at 60 degrees", p });
  p = PhantomParams{};
  p.lumenHu = 265.0;
  p.includeKidneys = true;
  p.kidneyHu = 230.0;
  p.neckDiameterMm = 18.0;
  p.distalNeckDiameterMm = 16.0;
  p.maxAneurysmDiameterMm = 40.0;
  v.push_back({ "low contrast, kidneys nearly as bright, small sac", p });
  p = WithWallInFat(PhantomParams{});
  p.thrombusMaxThicknessMm = 15.0;
  p.maxAneurysmDiameterMm = 80.0;
  p.includePsoas = p.includeIvc = p.includeDuodenum = p.includeLeftRenalVein = true;
  p.includeBone = true;
  v.push_back({ "80 mm sac with thrombus in fat, IVC, psoas, duodenum, renal vein, bone", p });
  p = WithWallInFat(PhantomParams{});
  p.thrombusMaxThicknessMm = 15.0;
  p.neckThrombusThicknessMm = 4.0;
  p.neckThrombusLengthMm = 20.0;
  p.neckCalcificationArcDeg = 120.0;
  p.sacCalcificationArcDeg = 90.0;
  p.bolusGradientHuPerCm = -4.0;
  p.rightIliacDiameterMm = p.leftIliacDiameterMm = 14.0;
  v.push_back({ "calcium in the neck and sac, neck thrombus, bolus fading 4 HU/cm upward", p });
  return v;
}

/// `count` random anatomies over the random-anatomy sweep's ranges (issue 13 item 5: neck 18–30 mm,
/// 12–40 mm long, β 0–60°, sac 40–80 mm, iliacs 8–18 mm, 0.6–0.95 mm pixels × 0.625–3 mm slices,
/// rotations up to 25° with flipped axes, noise 8–35 HU, lumen 265–480 HU, bone and enhancing
/// kidneys at random), from the fixed generator seed `generatorSeed`: the same draws on every run.
inline std::vector<SeedPhantom> RandomSeedPhantoms(int count, unsigned generatorSeed = 16)
{
  std::mt19937 random(generatorSeed);
  const auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(random); };
  std::vector<SeedPhantom> v;
  for (int draw = 0; draw < count; ++draw)
  {
    PhantomParams p;
    p.neckDiameterMm = uniform(18, 30);
    p.neckLengthMm = uniform(12, 40);
    p.neckAngleDeg = uniform(0, 60);
    p.maxAneurysmDiameterMm = uniform(std::max(40.0, p.neckDiameterMm + 10), 80);
    p.distalNeckDiameterMm = uniform(14, std::min(24.0, p.neckDiameterMm));
    p.rightIliacDiameterMm = uniform(8, 18);
    p.leftIliacDiameterMm = uniform(8, 18);
    const double pixel = uniform(0.6, 0.95);
    p.spacingMm = { pixel, pixel, uniform(0.625, 3.0) };
    const Eigen::Vector3d axis = Eigen::Vector3d(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)).normalized();
    const Eigen::Vector3d flips(uniform(0, 1) < 0.3 ? -1 : 1, uniform(0, 1) < 0.3 ? -1 : 1, 1);
    p.directionLps = Eigen::AngleAxisd(uniform(0, 25) * M_PI / 180, axis).toRotationMatrix() * flips.asDiagonal();
    p.noiseSigmaHu = uniform(8, 35);
    p.lumenHu = uniform(265, 480);
    p.includeBone = uniform(0, 1) < 0.5;
    p.boneGapMm = uniform(1, 6);
    p.includeKidneys = uniform(0, 1) < 0.5;
    p.kidneyHu = uniform(150, 200);
    p.noiseSeed = draw;
    v.push_back({ "draw " + std::to_string(draw), p });
  }
  return v;
}

} // namespace sgp::testing
