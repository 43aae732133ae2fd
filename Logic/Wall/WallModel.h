/// \file WallModel.h
/// The outer wall's model in one plane of SegmentOuterWall: the circle (Kåsa's algebraic fit) and
/// the ellipse (the algebraic conic with the plane's origin, the lumen's centre, inside), the
/// radius each gives along a ray, and the choice between them by the Bayesian information
/// criterion.
///
/// Coordinates: 2-D, mm, in the plane's (u, v) frame with the origin at the lumen's centre; rays
/// are unit vectors from that origin. Errors: none (a degenerate fit gives a radius of 0 or an
/// axis ratio of +∞, which the caller rejects).
#pragma once

#include <vector>

#include <Eigen/Core>

namespace sgp
{

/// The points candidate[k]·direction[k] (mm) of the rays where kept[k].
std::vector<Eigen::Vector2d> KeptPoints(const std::vector<bool>& kept,
                                        const std::vector<double>& candidate,
                                        const std::vector<Eigen::Vector2d>& direction);

/// Kåsa's algebraic circle fit: centre (x, y) and radius from points (n × 2), n ≥ 3.
Eigen::Vector3d FitCircle(const std::vector<Eigen::Vector2d>& points);

/// Where the ray from the origin along u (unit) meets the circle (x, y, R), mm.
double RayCircle(const Eigen::Vector3d& circle, const Eigen::Vector2d& u);

/// An ellipse around the origin as the conic q·(x², xy, y², x, y) = 1, coordinates in units of
/// `scale` mm (the conditioning of the algebraic fit).
struct Ellipse
{
  Eigen::Matrix<double, 5, 1> q = Eigen::Matrix<double, 5, 1>::Zero();
  double scale = 1.0;
  /// Its semi-axes' ratio, major / minor (≥ 1); +∞ when the conic is no ellipse around the origin.
  double AxisRatio() const;
  /// Where the ray from the origin along u (unit) meets it, mm.
  double Along(const Eigen::Vector2d& u) const;
};

/// The algebraic least-squares conic through points (n × 2, mm, n ≥ 5): q·(x², xy, y², x, y) = 1.
Ellipse FitEllipse(const std::vector<Eigen::Vector2d>& points);

/// Whether the ellipse explains the kept candidates (candidate[k]·direction[k] where kept[k])
/// better than the circle fitted to the same ones, by the Bayesian information criterion
/// n·ln(RSS/n) + p·ln(n) on the radial residuals (p = 5 against 3): two more parameters must pay
/// for themselves — noise on a round wall lowers the ellipse's residuals by about 2/n, which the
/// penalty of 2·ln(n) outweighs.
bool EllipseExplainsBetter(const Ellipse& ellipse,
                           const std::vector<bool>& kept,
                           const std::vector<double>& candidate,
                           const std::vector<Eigen::Vector2d>& direction);

/// The wall's model in a plane: the robust circle, or the ellipse where a neighbour hides an arc
/// of an elliptical sac.
struct WallModel
{
  Eigen::Vector3d circle = Eigen::Vector3d::Zero();
  bool elliptical = false;
  Ellipse ellipse;
  double Along(const Eigen::Vector2d& u) const { return elliptical ? ellipse.Along(u) : RayCircle(circle, u); }
};

} // namespace sgp
