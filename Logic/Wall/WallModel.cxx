#include "Wall/WallModel.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

namespace sgp
{

double Ellipse::AxisRatio() const
{
  Eigen::Matrix2d m;
  m << q[0], 0.5 * q[1], 0.5 * q[1], q[2];
  const Eigen::Vector2d l = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(m).eigenvalues();
  return l[0] > 0.0 ? std::sqrt(l[1] / l[0]) : std::numeric_limits<double>::infinity();
}

double Ellipse::Along(const Eigen::Vector2d& u) const
{
  const double a = q[0] * u.x() * u.x() + q[1] * u.x() * u.y() + q[2] * u.y() * u.y();
  const double b = q[3] * u.x() + q[4] * u.y();
  return scale * (-b + std::sqrt(std::max(0.0, b * b + 4 * a))) / (2 * a);
}

std::vector<Eigen::Vector2d> KeptPoints(const std::vector<bool>& kept,
                                        const std::vector<double>& candidate,
                                        const std::vector<Eigen::Vector2d>& direction)
{
  std::vector<Eigen::Vector2d> points;
  for (std::size_t k = 0; k < kept.size(); ++k)
    if (kept[k])
      points.push_back(candidate[k] * direction[k]);
  return points;
}

Eigen::Vector3d FitCircle(const std::vector<Eigen::Vector2d>& points)
{
  Eigen::MatrixXd A(points.size(), 3);
  Eigen::VectorXd b(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    A.row(i) << 2 * points[i].x(), 2 * points[i].y(), 1.0;
    b[i] = points[i].squaredNorm();
  }
  const Eigen::Vector3d x = A.colPivHouseholderQr().solve(b);
  return { x[0], x[1], std::sqrt(std::max(0.0, x[2] + x[0] * x[0] + x[1] * x[1])) };
}

double RayCircle(const Eigen::Vector3d& circle, const Eigen::Vector2d& u)
{
  const Eigen::Vector2d c = circle.head<2>();
  const double b = u.dot(c);
  return b + std::sqrt(std::max(0.0, b * b - c.squaredNorm() + circle[2] * circle[2]));
}

Ellipse FitEllipse(const std::vector<Eigen::Vector2d>& points)
{
  Ellipse e;
  double sum = 0.0;
  for (const Eigen::Vector2d& p : points)
    sum += p.norm();
  e.scale = std::max(1e-6, sum / double(points.size()));
  Eigen::MatrixXd A(points.size(), 5);
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const Eigen::Vector2d p = points[i] / e.scale;
    A.row(Eigen::Index(i)) << p.x() * p.x(), p.x() * p.y(), p.y() * p.y(), p.x(), p.y();
  }
  e.q = A.colPivHouseholderQr().solve(Eigen::VectorXd::Ones(Eigen::Index(points.size())));
  return e;
}

bool EllipseExplainsBetter(const Ellipse& ellipse,
                           const std::vector<bool>& kept,
                           const std::vector<double>& candidate,
                           const std::vector<Eigen::Vector2d>& direction)
{
  const std::vector<Eigen::Vector2d> points = KeptPoints(kept, candidate, direction);
  const Eigen::Vector3d circle = FitCircle(points);
  double circleRss = 0.0, ellipseRss = 0.0;
  for (std::size_t k = 0; k < kept.size(); ++k)
    if (kept[k])
    {
      circleRss += std::pow(candidate[k] - RayCircle(circle, direction[k]), 2);
      ellipseRss += std::pow(candidate[k] - ellipse.Along(direction[k]), 2);
    }
  const double n = double(points.size()), floor = 1e-12; // exact data: the ellipse's RSS is 0
  return n * std::log(std::max(ellipseRss, floor) / n) + 5 * std::log(n) <
         n * std::log(std::max(circleRss, floor) / n) + 3 * std::log(n);
}

} // namespace sgp
