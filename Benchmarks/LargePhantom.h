/// \file LargePhantom.h
/// The benchmarks' input: a 512 × 512 × 400 aneurysm phantom (0.7 × 0.7 × 1.0 mm, a typical
/// abdominal CTA) with a vertebra and enhancing kidneys, built once per process.
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

} // namespace sgp::benchmarks
