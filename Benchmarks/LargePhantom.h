/// \file LargePhantom.h
/// The benchmarks' input: a 512 × 512 × 400 aneurysm phantom (0.7 × 0.7 × 1.0 mm, a typical
/// abdominal CTA) with a vertebra and enhancing kidneys, built once per process; and the wall
/// benchmarks' parameters on the same grid.
#pragma once

#include "Phantom/AorticPhantom.h"

namespace sgp::benchmarks
{

inline const AorticPhantom& LargePhantom()
{
  static const AorticPhantom phantom = []
  {
    PhantomParams p;
    p.spacingMm = { 0.7, 0.7, 1.0 };
    p.sizeVoxels = { 512, 512, 400 };
    p.includeBone = true;
    p.includeKidneys = true;
    return GenerateAorticPhantom(p);
  }();
  return phantom;
}

/// The wall benchmarks' grid, the same 512 × 512 × 400 (0.7 × 0.7 × 1.0 mm), with a 1.5 mm wall, a
/// 12 mm crescent of sac thrombus and a 90° anterior sac plaque, in fat (no bone or kidneys).
inline PhantomParams LargeWallPhantomParams()
{
  PhantomParams p;
  p.spacingMm = { 0.7, 0.7, 1.0 };
  p.sizeVoxels = { 512, 512, 400 };
  p.wallThicknessMm = 1.5;
  p.thrombusMaxThicknessMm = 12.0;
  p.sacCalcificationArcDeg = 90.0;
  p.sacCalcificationSide = PhantomSide::Anterior;
  p.tissueHu = -100.0;
  return p;
}

} // namespace sgp::benchmarks
