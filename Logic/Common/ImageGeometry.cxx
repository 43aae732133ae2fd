#include "Common/ImageGeometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "Common/Errors.h"
#include "Common/Format.h"

namespace sgp
{

Point3 IndexToLps(const itk::ImageBase<3>& image, const itk::Index<3>& index)
{
  itk::Point<double, 3> p;
  image.TransformIndexToPhysicalPoint(index, p);
  return { p[0], p[1], p[2] };
}

std::array<double, 6> ImageBoundsLps(const itk::ImageBase<3>& image)
{
  const auto size = image.GetLargestPossibleRegion().GetSize();
  std::array<double, 6> bounds{ std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
                                std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
                                std::numeric_limits<double>::max(), -std::numeric_limits<double>::max() };
  for (int corner = 0; corner < 8; ++corner)
  {
    itk::ContinuousIndex<double, 3> c;
    for (unsigned a = 0; a < 3; ++a)
    {
      c[a] = (corner >> a) & 1 ? double(size[a]) - 0.5 : -0.5;
    }
    itk::Point<double, 3> p;
    image.TransformContinuousIndexToPhysicalPoint(c, p);
    for (unsigned a = 0; a < 3; ++a)
    {
      bounds[2 * a] = std::min(bounds[2 * a], p[a]);
      bounds[2 * a + 1] = std::max(bounds[2 * a + 1], p[a]);
    }
  }
  return bounds;
}

itk::Index<3> LpsToIndexInside(const itk::ImageBase<3>& image, const Point3& lps, const std::string& what)
{
  itk::Point<double, 3> p;
  p[0] = lps.x();
  p[1] = lps.y();
  p[2] = lps.z();
  itk::ContinuousIndex<double, 3> c;
  image.TransformPhysicalPointToContinuousIndex(p, c);
  const auto size = image.GetLargestPossibleRegion().GetSize();
  itk::Index<3> index;
  bool inside = true;
  for (unsigned a = 0; a < 3; ++a)
  {
    index[a] = static_cast<itk::IndexValueType>(std::floor(c[a] + 0.5));
    inside = inside && index[a] >= 0 && index[a] < static_cast<itk::IndexValueType>(size[a]);
  }
  if (!inside)
  {
    const auto b = ImageBoundsLps(image);
    throw InputError(what + " " + FormatPoint(lps) + " mm LPS lies outside the image (x " + FormatNumber(b[0]) +
                     " to " + FormatNumber(b[1]) + ", y " + FormatNumber(b[2]) + " to " + FormatNumber(b[3]) + ", z " +
                     FormatNumber(b[4]) + " to " + FormatNumber(b[5]) + " mm LPS); place it inside this volume.");
  }
  return index;
}

} // namespace sgp
