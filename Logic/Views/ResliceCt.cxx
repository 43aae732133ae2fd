#include "Views/ResliceCt.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "Common/Errors.h"
#include "Common/SampleCt.h"

namespace sgp
{
namespace
{

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
