/// \file VesselPath.h
/// The path a straightened (curved planar) view follows: the aorta from its top in the scan, then
/// one iliac from the aortic bifurcation on, resampled every `stepMm` of arc length, with an
/// orthonormal frame per sample.
///
/// Frame (u, v, t) at each sample: t the unit tangent (downstream; central differences over
/// ±1 sample); u the patient's left (LPS +x) made perpendicular to t, so that the view stays in
/// the coronal plane wherever the vessel runs cranio-caudally or obliquely, as a surgeon reads a
/// stretched view; v = u × t (posterior where t points inferior). Where the vessel runs within
/// 30° of the left–right axis (|x ⟂ t| < 0.5) u is the previous sample's u made perpendicular to t
/// (a rotation-minimising step), so the frame never flips; at the first sample, LPS y ⟂ t.
///
/// Abscissa: the sample k lies at k·stepMm along the path; the aorta's abscissa s is the path's
/// s, an iliac abscissa s (from the bifurcation, as MeasureAnatomy gives it) is the path's
/// `iliacStartMm` + s.
///
/// Input: two centerlines with at least two points each (LPS mm). Errors: InputError when either
/// has fewer, or stepMm is not in (0, 10].
#pragma once

#include <string>

#include "Centerlines/Centerlines.h"
#include "Common/Types.h"

namespace sgp
{

struct VesselPath
{
  std::string name;          ///< e.g. "aorta → rightIliac"
  std::string iliac;         ///< rightIliac or leftIliac
  double stepMm = 0.5;       ///< between samples
  Points points;             ///< rows × 3, LPS mm
  Points tangent;            ///< rows × 3, unit
  Points u;                  ///< rows × 3, unit, ⟂ tangent (the image's columns)
  Points v;                  ///< rows × 3, unit, u × tangent
  double iliacStartMm = 0.0; ///< path abscissa of the iliac's first point
  double LengthMm() const { return points.rows() > 0 ? (points.rows() - 1) * stepMm : 0.0; }
  /// Path abscissa of an abscissa along `vessel` (aorta or this path's iliac); NaN for another vessel.
  double PathAbscissa(const std::string& vessel, double abscissaMm) const;
  /// Path abscissa of the sample nearest `p` (the point projected onto the path), mm; the
  /// distance from `p` to the path through `distanceMm` when given.
  double Project(const Point3& p, double* distanceMm = nullptr) const;
};

/// The frame's u for the unit tangent t (the file comment): LPS x ⟂ t, normalised; within 30° of
/// the left–right axis `previous` ⟂ t, or LPS y ⟂ t without one. Also the cross-sections' axis.
Eigen::Vector3d CoronalAxis(const Eigen::Vector3d& t, const Eigen::Vector3d* previous = nullptr);

/// See the file comment.
VesselPath SampleVesselPath(const Centerline& aorta, const Centerline& iliac, double stepMm);

} // namespace sgp
