#include "Stent/ActiveContour.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>

#include "Common/CheckRange.h"
#include "Common/Errors.h"

namespace sgp
{

namespace
{

/// The vertex's offset from its centerline point within the ring's plane (the axial part removed),
/// so that the balloon pushes radially and never along the vessel.
Eigen::Vector3d RadialOffset(const StentMesh& mesh, Eigen::Index i, const Point3& v)
{
  const Eigen::Vector3d d = v - mesh.centre.row(i).transpose();
  const Eigen::Vector3d a = mesh.axis.row(i).transpose();
  return d - d.dot(a) * a;
}

/// φ at vertex i, with the crotch plane as a wall for the legs (see FitActiveContour's header).
double EffectiveWallDistance(const StentMesh& mesh,
                             const WallDistanceField& wall,
                             Eigen::Index i,
                             const Point3& v,
                             Eigen::Vector3d* gradient)
{
  double phi = wall.Sample(v, gradient);
  if (mesh.segment[i] != TrunkSegment)
  {
    const Eigen::Vector3d m =
      mesh.segment[i] == RightLegSegment ? mesh.crotchNormal : Eigen::Vector3d(-mesh.crotchNormal);
    const double beyond = (v - mesh.crotchPoint).dot(m);
    // Only for the leg's medial side (its radial direction toward the other leg): where a tortuous
    // iliac swings across the plane, its lateral side must answer to the real wall alone.
    const bool medial = RadialOffset(mesh, i, v).dot(m) > 0.0;
    if (beyond > phi && medial)
    {
      phi = beyond;
      if (gradient)
        *gradient = m;
    }
  }
  return phi;
}

} // namespace

Points ActiveContourForces(const StentMesh& mesh,
                           const WallDistanceField& wall,
                           const ActiveContourParams& p,
                           std::vector<bool>& contact,
                           const Points& V)
{
  Points F = Points::Zero(V.rows(), 3);
  for (Eigen::Index i = 0; i < V.rows(); ++i)
  {
    const Point3 v = V.row(i).transpose();
    const double phi = EffectiveWallDistance(mesh, wall, i, v, nullptr);
    const Eigen::Vector3d out = RadialOffset(mesh, i, v);
    const double r = out.norm();
    if (phi > 0.0 && r > 1e-9)
    {
      // Back along the ring's radius, with the magnitude of −∇D (1 beyond δ): on the voxel
      // staircase ∇D has tangential parts that would slide vertices into its outward pockets, and
      // where the wall does not face the ring's centre (the crotch, a branch ostium) ∇D may even
      // point along the radius outward. The centerline is inside the lumen, so inward is home.
      const Eigen::Vector3d n = out / r;
      F.row(i) -= p.wallWeight * std::min(phi / p.wallSofteningMm, 1.0) * n.transpose();
      contact[i] = true;
    }
    const double R = BalloonRadius(mesh, p, i);
    if (r < R && r > 1e-9)
      F.row(i) += (contact[i] ? p.contactPressureFactor : 1.0) * p.balloonPressure * (R - r) * (out / r).transpose();
  }
  return F;
}

double BalloonRadius(const StentMesh& mesh, const ActiveContourParams& p, Eigen::Index i)
{
  return p.vertexBalloonRadiusMm.empty() ? p.balloonRadiusMm[std::size_t(mesh.segment[i])]
                                         : p.vertexBalloonRadiusMm[std::size_t(i)];
}

namespace
{

/// D softened within δ of the wall: φ²/(2δ) for 0 < φ < δ, φ − δ/2 beyond, 0 inside.
double WallPotential(double phi, double delta)
{
  if (phi <= 0.0)
    return 0.0;
  return phi < delta ? phi * phi / (2.0 * delta) : phi - 0.5 * delta;
}

/// Each vertex's ring plane: an orthonormal basis (u, w) ⊥ its ring's axis, u along its initial
/// radial direction where it has one.
struct RingPlanes
{
  Points u, w; ///< #V×3
};

RingPlanes MakeRingPlanes(const StentMesh& mesh)
{
  const Eigen::Index n = mesh.V.rows();
  RingPlanes planes{ Points(n, 3), Points(n, 3) };
  for (Eigen::Index i = 0; i < n; ++i)
  {
    const Eigen::Vector3d a = mesh.axis.row(i).transpose().normalized();
    Eigen::Vector3d u = RadialOffset(mesh, i, mesh.V.row(i).transpose());
    u = u.norm() > 1e-9 ? Eigen::Vector3d(u.normalized()) : a.unitOrthogonal();
    planes.u.row(i) = u.transpose();
    planes.w.row(i) = a.cross(u).transpose();
  }
  return planes;
}

/// K_r = Uᵀ (K ⊗ I₃) U: block (i, j) is K_ij · U_iᵀ U_j (2×2), in the order (q_0u, q_0w, q_1u, …).
SparseMatrix ReducedStiffness(const SparseMatrix& K, const RingPlanes& planes)
{
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(std::size_t(K.nonZeros()) * 4);
  for (int col = 0; col < K.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(K, col); it; ++it)
    {
      const Eigen::Index i = it.row(), j = it.col();
      const Eigen::Vector3d basis[2][2] = { { planes.u.row(i).transpose(), planes.w.row(i).transpose() },
                                            { planes.u.row(j).transpose(), planes.w.row(j).transpose() } };
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b)
          entries.emplace_back(int(2 * i + a), int(2 * j + b), it.value() * basis[0][a].dot(basis[1][b]));
    }
  SparseMatrix Kr(2 * K.rows(), 2 * K.cols());
  Kr.setFromTriplets(entries.begin(), entries.end());
  return Kr;
}

/// Uᵀ X for X #V×3: the in-plane components, stacked (#2V).
Eigen::VectorXd ToPlane(const RingPlanes& planes, const Eigen::MatrixXd& X)
{
  Eigen::VectorXd q(2 * X.rows());
  for (Eigen::Index i = 0; i < X.rows(); ++i)
  {
    q[2 * i] = X.row(i).dot(planes.u.row(i));
    q[2 * i + 1] = X.row(i).dot(planes.w.row(i));
  }
  return q;
}

/// V = C + U q.
Eigen::MatrixXd FromPlane(const RingPlanes& planes, const StentMesh& mesh, const Eigen::VectorXd& q)
{
  Eigen::MatrixXd V = mesh.centre;
  for (Eigen::Index i = 0; i < V.rows(); ++i)
    V.row(i) += q[2 * i] * planes.u.row(i) + q[2 * i + 1] * planes.w.row(i);
  return V;
}

} // namespace

ActiveContourParams ActiveContourParams::Measure()
{
  return ActiveContourParams{};
}

ActiveContourParams ActiveContourParams::Simulate(const std::array<double, 3>& stentDiametersMm)
{
  ActiveContourParams p;
  p.weights = { 0.5, 0.5, 1.0, 1.0, 0.5 };
  for (int s = 0; s < 3; ++s)
    p.balloonRadiusMm[s] = stentDiametersMm[s] / 2.0;
  // The balloon dominates the rings' own stiffness (≈ 0.1 r here) so that they open to within
  // 2 % of R; τ·p = 0.75 keeps the explicit step stable.
  p.balloonPressure = 5.0;
  // A self-expanding graft keeps its radial force on the wall: with the pressure dropped after
  // contact, the stiff rings would pull back ~0.4 mm inside an oversized graft's neck.
  p.contactPressureFactor = 1.0;
  return p;
}

void ValidateActiveContourParams(const ActiveContourParams& p)
{
  CheckRange("tau", p.tau, 1e-6, 10, "");
  CheckRange("wallWeight", p.wallWeight, 0, 1e3, "");
  CheckRange("wallSofteningMm", p.wallSofteningMm, 1e-3, 10, "mm");
  CheckRange("balloonPressure", p.balloonPressure, 0, 1e2, "");
  CheckRange("contactPressureFactor", p.contactPressureFactor, 0, 1, "");
  for (std::size_t i = 0; i < p.vertexBalloonRadiusMm.size(); ++i)
    CheckRange("balloon radius of vertex " + std::to_string(i), p.vertexBalloonRadiusMm[i], 1e-3, 200, "mm");
  const char* names[3] = { "trunk balloon radius", "right leg balloon radius", "left leg balloon radius" };
  for (int s = 0; s < 3; ++s)
    CheckRange(names[s], p.balloonRadiusMm[s], 1e-3, 200, "mm");
  CheckRange("maxIterations", p.maxIterations, 1, 100000, "");
  CheckRange("toleranceMm", p.toleranceMm, 1e-9, 10, "mm");
}

double ActiveContourEnergy(const StentMesh& mesh,
                           const SparseMatrix& K,
                           const WallDistanceField& wall,
                           const ActiveContourParams& p,
                           const std::vector<bool>& contact,
                           const Points& V)
{
  double energy = InternalEnergy(K, V);
  for (Eigen::Index i = 0; i < V.rows(); ++i)
  {
    const Point3 v = V.row(i).transpose();
    energy += p.wallWeight * WallPotential(EffectiveWallDistance(mesh, wall, i, v, nullptr), p.wallSofteningMm);
    const bool held = !contact.empty() && contact[std::size_t(i)];
    const double r = RadialOffset(mesh, i, v).norm();
    const double R = BalloonRadius(mesh, p, i);
    if (r < R)
      energy += 0.5 * (held ? p.contactPressureFactor : 1.0) * p.balloonPressure * (R - r) * (R - r);
  }
  return energy;
}

ActiveContourResult FitActiveContour(const StentMesh& mesh,
                                     const WallDistanceField& wall,
                                     const ActiveContourParams& p,
                                     const ProgressCallback& progress)
{
  ValidateActiveContourParams(p);
  const Eigen::Index n = mesh.V.rows();
  if (!p.vertexBalloonRadiusMm.empty() && Eigen::Index(p.vertexBalloonRadiusMm.size()) != n)
    throw InputError("The active contour was given " + std::to_string(p.vertexBalloonRadiusMm.size()) +
                     " per-vertex balloon radii; expected one per vertex of the mesh, " + std::to_string(n) + ".");
  const SparseMatrix K = AssembleStiffnessMatrix(mesh, p.weights);
  const RingPlanes planes = MakeRingPlanes(mesh);
  const SparseMatrix Kr = ReducedStiffness(K, planes);
  SparseMatrix A(2 * n, 2 * n);
  A.setIdentity();
  A += p.tau * Kr;
  Eigen::SimplicialLDLT<SparseMatrix> solver;
  ActiveContourResult result;
  const auto factor = [&]
  {
    solver.compute(A);
    ++result.factorizations;
  };
  factor();                            // once per run: every step below reuses it
  if (solver.info() != Eigen::Success) // cannot happen: I + τK_r is symmetric positive definite
    throw std::logic_error("ActiveContour: the LDLT factorization of I + tau K_r failed");
  // The constant part of the internal force in plane coordinates: Uᵀ K C.
  const Eigen::MatrixXd KC = K * mesh.centre;
  const Eigen::VectorXd g = ToPlane(planes, KC);
  Eigen::VectorXd q = ToPlane(planes, Eigen::MatrixXd(mesh.V - mesh.centre));
  Eigen::MatrixXd V = FromPlane(planes, mesh, q);
  std::vector<bool> contact(static_cast<std::size_t>(n), false);
  result.energy.push_back(ActiveContourEnergy(mesh, K, wall, p, contact, V));
  for (int step = 1; step <= p.maxIterations; ++step)
  {
    const Points F = ActiveContourForces(mesh, wall, p, contact, V);
    const Eigen::VectorXd b = q + p.tau * (ToPlane(planes, F) - g);
    const Eigen::VectorXd next = solver.solve(b);
    result.maxRelativeResidual =
      std::max(result.maxRelativeResidual, (A * next - b).norm() / std::max(b.norm(), 1e-300));
    double moved = 0.0;
    for (Eigen::Index i = 0; i < n; ++i)
      moved = std::max(moved, std::hypot(next[2 * i] - q[2 * i], next[2 * i + 1] - q[2 * i + 1]));
    q = next;
    V = FromPlane(planes, mesh, q);
    result.iterations = step;
    result.energy.push_back(ActiveContourEnergy(mesh, K, wall, p, contact, V));
    ReportProgress(progress, double(step) / p.maxIterations, "Active contour");
    if (moved < p.toleranceMm)
    {
      result.converged = true;
      break;
    }
  }
  result.verticesInContact = static_cast<int>(std::count(contact.begin(), contact.end(), true));
  result.V = V;
  result.wallDistanceMm.resize(n);
  result.radiusMm.resize(n);
  for (Eigen::Index i = 0; i < n; ++i)
  {
    result.wallDistanceMm[i] = wall.Sample(V.row(i).transpose());
    result.radiusMm[i] = RadialOffset(mesh, i, V.row(i).transpose()).norm();
    result.maxAxialOffsetMm =
      std::max(result.maxAxialOffsetMm, std::abs((V.row(i) - mesh.centre.row(i)).dot(mesh.axis.row(i))));
  }
  ReportProgress(progress, 1.0, "Done");
  return result;
}

} // namespace sgp
