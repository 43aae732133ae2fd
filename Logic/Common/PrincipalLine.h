/// \file PrincipalLine.h
/// The least-squares line through points (LPS mm): their centroid and the unit principal direction
/// (the scatter matrix's eigenvector of the largest eigenvalue; its sign as the solver gives it).
/// Input: at least two distinct points (fewer: the direction is the solver's arbitrary unit vector).
/// Errors: none. Complexity: linear in the points.
#pragma once

#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>

#include "Common/Types.h"

namespace sgp
{

inline std::pair<Point3, Eigen::Vector3d> PrincipalLine(const std::vector<Point3>& points)
{
  Point3 centroid = Point3::Zero();
  for (const Point3& p : points)
    centroid += p;
  centroid /= double(points.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Point3& p : points)
    scatter += (p - centroid) * (p - centroid).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter);
  return { centroid, solver.eigenvectors().col(2).normalized() };
}

} // namespace sgp
