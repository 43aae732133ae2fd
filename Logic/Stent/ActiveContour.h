/// \file ActiveContour.h
/// Fits the stent surface to the vessel with the active contour (ACM) of Egger et al. (2007),
/// sections 2.1–2.2, in the semi-implicit form of DESIGN.md, with every vertex held in its ring's
/// plane:
///
///     v_i = c_i + U_i q_i          (U_i: #3×2, an orthonormal basis of ring i's plane ⊥ a_i)
///     (I + τ K_r) q⁺ = q + τ (Uᵀ F_ext(V) − Uᵀ K C),   K_r = Uᵀ (K ⊗ I₃) U,
///     F_ext = −w_wall · |∇D| n [D > 0] + F_balloon,
///     F_balloon = p (R − r) n  while r < R, else 0,
///
/// V: #V×3 vertices (LPS mm); C: #V×3 their rings' centerline points c_i; q: #V×2 in-plane
/// coordinates; K: the stiffness matrix (StiffnessMatrix.h, weights w1…w5); D: the distance to
/// the lumen outside it, 0 inside (WallDistanceField.h); r: a vertex's distance from its centerline
/// point, n the unit vector from that point to the vertex (in the plane, so the balloon never
/// pushes along the vessel); R the balloon radius of the vertex (its segment's, or per vertex:
/// `vertexBalloonRadiusMm`; equation 5: the stent and balloon cannot expand further). I + τK_r
/// (#2V×2V, symmetric positive definite) is factored once per run (sparse LDLᵀ, Eigen
/// SimplicialLDLT); each step is one solve. The run stops when no vertex moves more than
/// `toleranceMm` in a step (converged) or after `maxIterations` steps, and says which.
///
/// **Why the ring planes are held** (the axial constraint; the design decision of issue 30).
/// Internal energy and balloon are blind to sliding along the vessel (translations cost nothing),
/// and the first-order term w1‖D_s V‖² is a membrane tension along s: it pulls each s-chain's end
/// rings inward. An earlier version held each vertex near its ring's plane with a weak spring
/// −k_a((v − c)·a)a (k_a = 0.05); against simulate mode's stiffer weights (w1 = 0.5) it let the
/// graft's proximal edge slide 6–10 mm below where it was deployed and its legs end 8.6 mm short.
/// A stronger spring only shrinks the slide (it balances w1's pull at a displacement ∝ w1/k_a)
/// and makes the explicit step stiff (τk_a < 2). Instead each vertex is confined to its ring's
/// plane exactly, by solving in the plane's two coordinates: a graft's fabric does not stretch or
/// shorten along its length (foreshortening is not modelled: the only figure found, 5–7 %, is a
/// planning parameter, not a measurement — device-configuration.md §1.5), every ring stays at the
/// abscissa where it was placed, so the proximal edge stays at its deployment target and each
/// component keeps its catalogue length along the centerline, in both modes (measure mode's free
/// ends reach the vessel's ends the same way). The scheme is the same semi-implicit gradient step,
/// restricted to an affine subspace, so its stability and energy behaviour are unchanged; it costs
/// one factorization of a 2#V system instead of #V with three right-hand sides (about 2× the
/// solve time, milliseconds).
///
/// The wall force acts back along −n with the magnitude of ∇D (1 outside the lumen): taken along
/// ∇D itself, its tangential parts on the voxel staircase of the wall slide vertices into the
/// staircase's outward pockets (+0.16 mm on every radius), and where the wall does not face the
/// ring's centre (under the crotch, at a branch ostium) ∇D·n can even be negative and push the
/// vertex further out. The centerline lies inside the lumen, so back along the radius is back in.
///
/// The wall force is applied explicitly, so its jump from 0 inside to w_wall outside would make
/// vertices chatter across the wall by τ·w_wall. It therefore ramps up linearly over the first
/// `wallSofteningMm` (δ) outside the wall — D is replaced by its Huber form, φ²/2δ for φ < δ —
/// which is the paper's force beyond δ; τ·w_wall/δ ≤ 1 keeps the step stable.
///
/// The flow divider: where the iliacs leave the aorta their lumens overlap, and the balloon would
/// push each leg's medial side into the other leg. The plane midway between the legs' first rings
/// (StentMesh::crotchPoint, crotchNormal) is where the two legs of a graft meet, so beyond it a leg
/// vertex on its medial side (radial direction toward the other leg) feels the wall force as if the
/// plane were the wall: D there is the larger of the wall distance and the distance past the plane.
/// (A tortuous iliac may swing across the plane farther down; its lateral side then answers to the
/// real wall alone.)
///
/// Contact: once a vertex has passed the wall (φ > 0) its balloon pressure drops to
/// `contactPressureFactor` × p for the rest of the run — the balloon has pressed that part of the
/// stent against the wall, and now only holds it there against the internal forces. With the
/// full pressure, balloon and wall would balance δ·F_balloon/w_wall outside the wall, and at the
/// flow divider, where the wall is a thin ridge between the two iliac lumens, the balloon would
/// push medial leg vertices across it into the other lumen and back. Simulate mode keeps the full
/// pressure (factor 1): a self-expanding graft's radial force does not relax at the wall, and an
/// oversized graft presses up to δ·p(R − r)/w_wall into it.
///
/// Two modes, one engine (ActiveContourParams::Measure / ::Simulate): *measure* — w1…w5 small,
/// R large, so the surface expands until it lies on the vessel wall; *simulate* — R per segment
/// from the stent's nominal diameters, stiffer weights, so the surface stops at R where the vessel
/// is wider.
///
/// Energy: E = ½ Σ_c V_cᵀ K V_c + w_wall Σ_v D_δ(v) + Σ_v (p_v/2)(R − r)²₊ (p_v the vertex's
/// pressure), recorded before the first and after every step. Its negative
/// gradient is −KV + F_ext except that the wall force acts along −n rather than −∇D (above), so E
/// is only guaranteed to fall where the wall faces the ring's centre or is not touched; the tests
/// check that it never rises on a Y of tubes in both modes.
/// Errors: InputError for parameters out of range, or a per-vertex radius list whose size is not
/// the mesh's. (I + τK_r is symmetric positive definite for valid parameters, so its
/// factorization cannot fail.)
/// Complexity: one sparse factorization (near-linear for these banded meshes) plus O(#V) a step.
#pragma once

#include <array>
#include <vector>

#include "Stent/StiffnessMatrix.h"
#include "Stent/WallDistanceField.h"

namespace sgp
{

struct ActiveContourParams
{
  StiffnessWeights weights{ 0.005, 0.005, 0.005, 0.005, 0.005 };
  double tau = 0.15;                                         ///< step, in (0, 10]
  double wallWeight = 5.0;                                   ///< w_wall, in [0, 1e3]
  double wallSofteningMm = 1.0;                              ///< δ, in (0, 10] mm
  double balloonPressure = 0.02;                             ///< p, in [0, 1e2]
  double contactPressureFactor = 0.1;                        ///< pressure kept after contact, in [0, 1]
  std::array<double, 3> balloonRadiusMm{ 60.0, 60.0, 60.0 }; ///< R per StentSegment, (0, 200]
  /// Empty: R per segment (balloonRadiusMm). Else R per vertex (#V, each in (0, 200]): a graft of
  /// several components whose diameters differ along a segment (ActiveContour's file comment).
  std::vector<double> vertexBalloonRadiusMm;
  int maxIterations = 3000;   ///< in [1, 100000]
  double toleranceMm = 0.005; ///< in (0, 10]

  /// Measure mode (paper, section 2.2): small weights, R large.
  static ActiveContourParams Measure();
  /// Simulate mode: R from the stent diameters (trunk, right leg, left leg, mm), stiffer weights.
  static ActiveContourParams Simulate(const std::array<double, 3>& stentDiametersMm);
};

struct ActiveContourResult
{
  Points V; ///< #V×3, the fitted surface
  int iterations = 0;
  bool converged = false;
  std::vector<double> energy;       ///< before the first step and after each
  int verticesInContact = 0;        ///< vertices that have reached the wall
  int factorizations = 0;           ///< factorizations of I + τK performed (one per run)
  double maxRelativeResidual = 0.0; ///< max over steps of ‖(I+τK)V⁺ − b‖ / ‖b‖
  Eigen::VectorXd wallDistanceMm;   ///< #V: φ at each vertex (negative inside the lumen)
  Eigen::VectorXd radiusMm;         ///< #V: r, distance from the vertex's centerline point in its ring's plane
  /// The largest distance of any vertex from its ring's plane at the end, mm (0 up to rounding:
  /// the constraint's guarantee, which the tests check).
  double maxAxialOffsetMm = 0.0;
};

/// \throws InputError for a parameter out of range (the per-vertex radii are checked against the
///         mesh by FitActiveContour).
void ValidateActiveContourParams(const ActiveContourParams& params);

ActiveContourResult FitActiveContour(const StentMesh& mesh,
                                     const WallDistanceField& wall,
                                     const ActiveContourParams& params,
                                     const ProgressCallback& progress = {});

/// F_ext(V) (#V×3) as defined above; sets `contact` (#V flags) for vertices past the wall.
Points ActiveContourForces(const StentMesh& mesh,
                           const WallDistanceField& wall,
                           const ActiveContourParams& params,
                           std::vector<bool>& contact,
                           const Points& V);

/// R of vertex i: its own (vertexBalloonRadiusMm) or its segment's.
double BalloonRadius(const StentMesh& mesh, const ActiveContourParams& params, Eigen::Index i);

/// E(V) as defined above; `contact` flags the vertices in contact (empty: none).
double ActiveContourEnergy(const StentMesh& mesh,
                           const SparseMatrix& K,
                           const WallDistanceField& wall,
                           const ActiveContourParams& params,
                           const std::vector<bool>& contact,
                           const Points& V);

} // namespace sgp
