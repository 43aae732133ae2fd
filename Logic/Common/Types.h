/// \file Types.h
/// The shared vocabulary of StentGraftPlanner's Logic (STYLE.md B2).
///
/// Images are ITK images in LPS physical millimetres: spacing, origin and direction cosines
/// are always honoured; index space appears only inside the file that needs it.
#pragma once

#include <functional>
#include <string_view>

#include <Eigen/Core>
#include <itkImage.h>

namespace sgp
{

/// CT volume; each value is in Hounsfield units (HU).
using CtImage = itk::Image<short, 3>;
/// Binary or multi-class mask; 0 is background.
using LabelImage = itk::Image<unsigned char, 3>;
/// Distances in mm.
using DistanceImage = itk::Image<float, 3>;

/// One point in LPS mm.
using Point3 = Eigen::Vector3d;
/// n×3 points, one per row, LPS mm.
using Points = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
/// n×3 vertex indices of triangles, one per row.
using Triangles = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;

/// A ball: centre in LPS mm, radius in mm.
struct Ball
{
  Point3 centre;
  double radiusMm = 0.0;
};

/// Progress of a stage: `fraction` in [0, 1] of that stage, `stage` a short description of the
/// current step. Optional everywhere: an empty function is never called.
using ProgressCallback = std::function<void(double fraction, std::string_view stage)>;

/// Calls `progress` if it is set.
inline void ReportProgress(const ProgressCallback& progress, double fraction, std::string_view stage)
{
  if (progress)
  {
    progress(fraction, stage);
  }
}

} // namespace sgp
