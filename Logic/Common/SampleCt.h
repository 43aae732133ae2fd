/// \file SampleCt.h
/// Trilinear samples of a CT at LPS points (spacing, origin and direction cosines honoured), for
/// the stages that look at the CT on planes of their own (the automatic seed's axial levels, the
/// report's straightened views and cross-sections).
///
/// The LPS → continuous-index map is computed once; a point outside the image's voxel centres
/// reads `outsideHu`. Cost: eight voxel reads per sample; the object holds a reference to the CT,
/// which must outlive it.
#pragma once

#include "Common/Types.h"

namespace sgp
{

class CtSampler
{
public:
  CtSampler(const CtImage& ct, float outsideHu);
  /// HU at `lps` (mm), trilinear between the eight surrounding voxels.
  float operator()(const Eigen::Vector3d& lps) const;

private:
  float m_Outside;
  Eigen::Matrix3d m_ToIndex;
  Eigen::Vector3d m_Origin;
  long m_Size[3];
  long m_Start[3];
  const short* m_Buffer = nullptr;
};

} // namespace sgp
