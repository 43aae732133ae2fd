#include "Views/ResliceCt.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "Common/Errors.h"

namespace sgp
{
namespace
{

/// Trilinear samples of a CT in LPS mm: the LPS → continuous index map is precomputed once.
class CtSampler
{
public:
  CtSampler(const CtImage& ct, float outsideHu)
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

  float operator()(const Eigen::Vector3d& lps) const
  {
    const Eigen::Vector3d c = m_ToIndex * (lps - m_Origin);
    long i0[3];
    double f[3];
    for (int a = 0; a < 3; ++a)
    {
      const double x = c[a] - static_cast<double>(m_Start[a]);
      if (!(x >= 0.0 && x <= static_cast<double>(m_Size[a] - 1)))
        return m_Outside;
      i0[a] = std::min(static_cast<long>(std::floor(x)), m_Size[a] - 2 >= 0 ? m_Size[a] - 2 : 0);
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

private:
  float m_Outside;
  Eigen::Matrix3d m_ToIndex;
  Eigen::Vector3d m_Origin;
  long m_Size[3];
  long m_Start[3];
  const short* m_Buffer = nullptr;
};

int HalfPixels(double halfWidthMm, double pixelMm)
{
  if (!(halfWidthMm > 0.0 && halfWidthMm <= 100.0))
    throw InputError("A resliced view's half width is " + std::to_string(halfWidthMm) + " mm; expected (0, 100] mm.");
  if (!(pixelMm > 0.0 && pixelMm <= 5.0))
    throw InputError("A resliced view's pixel is " + std::to_string(pixelMm) + " mm; expected (0, 5] mm.");
  return static_cast<int>(std::round(halfWidthMm / pixelMm));
}

} // namespace

PlaneImage StraightenAlongPath(const CtImage& ct, const VesselPath& path, double halfWidthMm, float outsideHu)
{
  const int half = HalfPixels(halfWidthMm, path.stepMm);
  const CtSampler sample(ct, outsideHu);
  PlaneImage image;
  image.width = 2 * half + 1;
  image.height = static_cast<int>(path.points.rows());
  image.pixelMm = path.stepMm;
  image.hu.resize(static_cast<size_t>(image.width) * image.height);
  for (int row = 0; row < image.height; ++row)
  {
    const Eigen::Vector3d p = path.points.row(row).transpose(), u = path.u.row(row).transpose();
    for (int col = 0; col < image.width; ++col)
      image.hu[static_cast<size_t>(row) * image.width + col] = sample(p + (col - half) * path.stepMm * u);
  }
  return image;
}

CtImage::Pointer StraightenVolume(const CtImage& ct, const VesselPath& path, double halfWidthMm, short outsideHu)
{
  const int half = HalfPixels(halfWidthMm, path.stepMm);
  const CtSampler sample(ct, outsideHu);
  const int n = 2 * half + 1;
  const auto rows = path.points.rows();
  CtImage::Pointer out = CtImage::New();
  CtImage::RegionType region;
  region.SetSize(
    { static_cast<itk::SizeValueType>(n), static_cast<itk::SizeValueType>(n), static_cast<itk::SizeValueType>(rows) });
  out->SetRegions(region);
  const double d = path.stepMm;
  out->SetSpacing(itk::Vector<double, 3>(d));
  CtImage::PointType origin;
  origin[0] = -half * d;
  origin[1] = -half * d;
  origin[2] = 0.0;
  out->SetOrigin(origin);
  CtImage::DirectionType direction;
  direction.SetIdentity();
  direction[2][2] = -1.0;
  out->SetDirection(direction);
  out->Allocate();
  short* buffer = out->GetBufferPointer();
  for (Eigen::Index k = 0; k < rows; ++k)
  {
    const Eigen::Vector3d p = path.points.row(k).transpose(), u = path.u.row(k).transpose(),
                          v = path.v.row(k).transpose();
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        buffer[(static_cast<size_t>(k) * n + j) * n + i] =
          static_cast<short>(std::lround(sample(p + (i - half) * d * u + (j - half) * d * v)));
  }
  return out;
}

PlaneImage CrossSection(const CtImage& ct,
                        const Point3& centreLps,
                        const Eigen::Vector3d& u,
                        const Eigen::Vector3d& v,
                        double halfWidthMm,
                        double pixelMm,
                        float outsideHu)
{
  const int half = HalfPixels(halfWidthMm, pixelMm);
  const CtSampler sample(ct, outsideHu);
  PlaneImage image;
  image.width = image.height = 2 * half + 1;
  image.pixelMm = pixelMm;
  image.hu.resize(static_cast<size_t>(image.width) * image.height);
  for (int row = 0; row < image.height; ++row)
    for (int col = 0; col < image.width; ++col)
      image.hu[static_cast<size_t>(row) * image.width + col] =
        sample(centreLps + (col - half) * pixelMm * u + (row - half) * pixelMm * v);
  return image;
}

} // namespace sgp
