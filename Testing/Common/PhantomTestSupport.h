/// \file PhantomTestSupport.h
/// Comparisons of segmentations against the phantom's truth labels, shared by the tests and
/// benchmarks. Both images must be on the same grid (checked).
#pragma once

#include <array>
#include <limits>
#include <string>
#include <stdexcept>

#include <Eigen/Geometry>

#include "Phantom/AorticPhantom.h"

namespace sgp::testing
{

/// The truth's landmark called `name` (NaN when absent).
inline Point3 TruthLandmark(const PhantomTruth& truth, const std::string& name)
{
  for (const PhantomLandmark& l : truth.landmarks)
    if (l.name == name)
      return l.lps;
  return Point3::Constant(std::numeric_limits<double>::quiet_NaN());
}

/// An oblique grid with one axis flipped (det = −1): rotated 30° about z and 20° about x, j
/// reversed — what a gantry-tilted scan stored in a flipped order looks like.
inline Eigen::Matrix3d ObliqueFlippedDirection()
{
  const Eigen::Matrix3d rotation = (Eigen::AngleAxisd(30.0 * M_PI / 180.0, Eigen::Vector3d::UnitZ()) *
                                    Eigen::AngleAxisd(20.0 * M_PI / 180.0, Eigen::Vector3d::UnitX()))
                                     .toRotationMatrix();
  return rotation * Eigen::Vector3d(1.0, -1.0, 1.0).asDiagonal(); // j axis flipped: det = −1
}

/// `p` as a patient's CTA shows an aorta without thrombus: a 1.5 mm wall (vessel-wall.md §2:
/// 1.5–2.3 mm on CT) in periaortic fat (−100 HU), so that the outer wall is visible; its
/// diameters are then outer-wall diameters and the lumen lies inside the wall.
inline PhantomParams WithWallInFat(PhantomParams p, double wallMm = 1.5)
{
  p.wallThicknessMm = wallMm;
  p.tissueHu = -100.0;
  return p;
}

/// Voxel counts of a binary segmentation against the truth labels.
struct Overlap
{
  long truthLumen = 0;                              ///< voxels labelled lumen in the truth
  long segmented = 0;                               ///< voxels set in the segmentation
  long both = 0;                                    ///< set in both
  std::array<long, PhantomLabelCount> perLabel{};   ///< segmented voxels per truth label
  std::array<long, PhantomLabelCount> labelCount{}; ///< truth voxels per label

  double Dice() const { return 2.0 * double(both) / double(truthLumen + segmented); }
  /// Fraction of the truth voxels of `label` that were segmented.
  double FractionOf(PhantomLabel label) const
  {
    return labelCount[label] ? double(perLabel[label]) / double(labelCount[label]) : 0.0;
  }
};

inline Overlap CompareWithTruth(const LabelImage& segmentation, const LabelImage& truth)
{
  if (segmentation.GetLargestPossibleRegion() != truth.GetLargestPossibleRegion())
  {
    throw std::invalid_argument("CompareWithTruth: the images are on different grids");
  }
  Overlap overlap;
  const long count = static_cast<long>(truth.GetLargestPossibleRegion().GetNumberOfPixels());
  const unsigned char* s = segmentation.GetBufferPointer();
  const unsigned char* t = truth.GetBufferPointer();
  for (long i = 0; i < count; ++i)
  {
    const bool set = s[i] != 0;
    const unsigned label = t[i] < PhantomLabelCount ? t[i] : 0;
    overlap.truthLumen += label == LumenLabel;
    overlap.segmented += set;
    overlap.both += set && label == LumenLabel;
    overlap.perLabel[label] += set;
    overlap.labelCount[label] += 1;
  }
  return overlap;
}

} // namespace sgp::testing
