#include "Common/SampleCt.h"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

namespace sgp
{

CtSampler::CtSampler(const CtImage& ct, float outsideHu)
  : m_Outside(outsideHu)
{
  const auto& d = ct.GetDirection();
  const auto& sp = ct.GetSpacing();
  Eigen::Matrix3d m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      m(r, c) = d[r][c] * sp[c];
  m_ToIndex = m.inverse();
  for (int a = 0; a < 3; ++a)
  {
    m_Origin[a] = ct.GetOrigin()[a];
    m_Size[a] = static_cast<long>(ct.GetBufferedRegion().GetSize()[a]);
    m_Start[a] = ct.GetBufferedRegion().GetIndex()[a];
  }
  m_Buffer = ct.GetBufferPointer();
}

float CtSampler::operator()(const Eigen::Vector3d& lps) const
{
  const Eigen::Vector3d c = m_ToIndex * (lps - m_Origin);
  long i0[3];
  double f[3];
  for (int a = 0; a < 3; ++a)
  {
    const double x = c[a] - static_cast<double>(m_Start[a]);
    if (!(x >= 0.0 && x <= static_cast<double>(m_Size[a] - 1)))
      return m_Outside;
    i0[a] = std::min(static_cast<long>(std::floor(x)), std::max(m_Size[a] - 2, 0L));
    f[a] = x - static_cast<double>(i0[a]);
  }
  double sum = 0.0;
  for (int dz = 0; dz < 2; ++dz)
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx)
      {
        const double w = (dx ? f[0] : 1 - f[0]) * (dy ? f[1] : 1 - f[1]) * (dz ? f[2] : 1 - f[2]);
        if (w == 0.0)
          continue;
        const long x = std::min(i0[0] + dx, m_Size[0] - 1), y = std::min(i0[1] + dy, m_Size[1] - 1),
                   z = std::min(i0[2] + dz, m_Size[2] - 1);
        sum += w * m_Buffer[(z * m_Size[1] + y) * m_Size[0] + x];
      }
  return static_cast<float>(sum);
}

} // namespace sgp
