/// \file ResliceCt.h
/// The CT resampled on planes the centerlines define: the straightened (stretched curved planar)
/// view along a VesselPath, the straightened volume, and the cross-section perpendicular to the
/// centerline at one point. Trilinear interpolation in LPS mm (spacing, origin and direction
/// honoured); a sample outside the image takes `outsideHu`.
///
/// Shapes and frames:
///  - PlaneImage: `width` × `height` pixels of `pixelMm`, row-major, row 0 at the top. Pixel
///    (col, row) of a **straightened view** samples the path's point at abscissa row·stepMm moved
///    (col − centre)·pixelMm along u (the patient's left to the image's right: radiological
///    convention); of a **cross-section**, centre + (col − centre)·pixelMm·u + (row − centre)·
///    pixelMm·v (u the patient's left, v posterior when the vessel runs inferior: the axial
///    view's orientation). `centre` = (width − 1)/2; width is odd, so the centerline is a pixel.
///  - StraightenVolume: an image whose index (i, j, k) samples path point k + (i − c)·Δ·u_k +
///    (j − c)·Δ·v_k, Δ = the path's step; written with origin (−c·Δ, −c·Δ, 0), spacing Δ and
///    direction diag(1, 1, −1), so in Slicer the axial slices are cross-sections, the coronal and
///    sagittal slices are stretched views with the vessel's top at the top, and a slice's
///    S coordinate is minus the path abscissa (RAS S = −s, mm).
/// Errors: InputError when the half width is not in (0, 100] mm or the pixel size not in (0, 5] mm.
/// Cost: one trilinear sample per output pixel (a 0.5 mm view of 300 mm × 80 mm: 97 k samples).
#pragma once

#include <vector>

#include "Common/Types.h"
#include "Views/VesselPath.h"

namespace sgp
{

struct PlaneImage
{
  int width = 0;
  int height = 0;
  double pixelMm = 1.0;
  std::vector<float> hu; ///< width × height, row-major
  float At(int col, int row) const { return hu[static_cast<size_t>(row) * width + col]; }
  double CentreColumn() const { return (width - 1) / 2.0; }
};

/// The straightened view of `ct` along `path`, ±halfWidthMm across it, pixels of path.stepMm.
PlaneImage StraightenAlongPath(const CtImage& ct, const VesselPath& path, double halfWidthMm, float outsideHu = -1024);

/// The straightened volume (see the file comment), ±halfWidthMm in u and v.
CtImage::Pointer StraightenVolume(const CtImage& ct,
                                  const VesselPath& path,
                                  double halfWidthMm,
                                  short outsideHu = -1024);

/// The cross-section at `centreLps` spanned by unit vectors u and v (⟂ the centerline).
PlaneImage CrossSection(const CtImage& ct,
                        const Point3& centreLps,
                        const Eigen::Vector3d& u,
                        const Eigen::Vector3d& v,
                        double halfWidthMm,
                        double pixelMm,
                        float outsideHu = -1024);

} // namespace sgp
