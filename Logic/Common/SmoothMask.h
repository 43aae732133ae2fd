/// \file SmoothMask.h
/// A binary mask (nonzero = inside) interpolated trilinearly at LPS points: 1 inside, 0 outside,
/// and in between where the eight surrounding voxel centres disagree, so the 0.5 level lies
/// halfway between an inside and an outside voxel centre. For the stages that read an edge on the
/// lumen mask below the voxel size (SectionTilt.h, FlowDivider.h).
///
/// The LPS → continuous-index map (spacing, origin, direction cosines) is computed once; voxels
/// outside the image read 0. Cost: eight voxel reads per sample; the object holds a reference to
/// the mask, which must outlive it.
#pragma once

#include "Common/Types.h"

namespace sgp
{

class SmoothMask
{
public:
  explicit SmoothMask(const LabelImage& mask);
  /// The interpolated value at `lps` (mm), in [0, 1].
  double operator()(const Point3& lps) const;

private:
  const LabelImage& m_Mask;
  Eigen::Matrix3d m_ToIndex;
  Eigen::Vector3d m_Origin;
  long m_Start[3] = { 0, 0, 0 };
  long m_Size[3] = { 0, 0, 0 };
};

} // namespace sgp
