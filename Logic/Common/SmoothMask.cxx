#include "Common/SmoothMask.h"

#include <cmath>

#include <Eigen/Dense>

namespace sgp
{

SmoothMask::SmoothMask(const LabelImage& mask)
  : m_Mask(mask)
{
  const auto& d = mask.GetDirection();
  const auto& sp = mask.GetSpacing();
  const auto& o = mask.GetOrigin();
  Eigen::Matrix3d m;
  for (unsigned r = 0; r < 3; ++r)
  {
    for (unsigned c = 0; c < 3; ++c)
      m(r, c) = d[r][c] * sp[c];
    m_Origin[r] = o[r];
  }
  m_ToIndex = m.inverse();
  const auto region = mask.GetLargestPossibleRegion();
  for (unsigned a = 0; a < 3; ++a)
  {
    m_Start[a] = static_cast<long>(region.GetIndex()[a]);
    m_Size[a] = static_cast<long>(region.GetSize()[a]);
  }
}

double SmoothMask::operator()(const Point3& lps) const
{
  const Eigen::Vector3d f = m_ToIndex * (lps - m_Origin);
  const long i0 = static_cast<long>(std::floor(f.x())), j0 = static_cast<long>(std::floor(f.y())),
             k0 = static_cast<long>(std::floor(f.z()));
  const double wx = f.x() - double(i0), wy = f.y() - double(j0), wz = f.z() - double(k0);
  double value = 0.0;
  for (int dk = 0; dk < 2; ++dk)
    for (int dj = 0; dj < 2; ++dj)
      for (int di = 0; di < 2; ++di)
      {
        const long i = i0 + di, j = j0 + dj, k = k0 + dk;
        if (i < m_Start[0] || j < m_Start[1] || k < m_Start[2] || i >= m_Start[0] + m_Size[0] ||
            j >= m_Start[1] + m_Size[1] || k >= m_Start[2] + m_Size[2])
          continue;
        LabelImage::IndexType index{ { i, j, k } };
        if (m_Mask.GetPixel(index) == 0)
          continue;
        value += (di ? wx : 1.0 - wx) * (dj ? wy : 1.0 - wy) * (dk ? wz : 1.0 - wz);
      }
  return value;
}

} // namespace sgp
