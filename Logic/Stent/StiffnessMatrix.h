/// \file StiffnessMatrix.h
/// The stent surface's internal forces: the five difference operators of Egger et al. (2007),
/// equation 2, and the sparse stiffness matrix K = Σ_k w_k D_kᵀ D_k (DESIGN.md, "The active
/// contour").
///
/// Symbols (all #rows × #V sparse matrices, acting on each coordinate column of V, #V×3):
///   D_s  = ∂/∂s   : one row per consecutive pair (a, b) of an s-chain: e_b − e_a        (w1)
///   D_t  = ∂/∂t   : one row per consecutive pair around a ring (periodic): e_{j+1} − e_j (w2)
///   D_ss = ∂²/∂s² : one row per consecutive triple (a, b, c) of an s-chain: e_a − 2e_b + e_c (w3)
///   D_tt = ∂²/∂t² : e_{j−1} − 2e_j + e_{j+1} around each ring                          (w4)
///   D_st = ∂²/∂s∂t: per consecutive chain pair (a, b): (e_{b⁺} − e_b) − (e_{a⁺} − e_a), x⁺
///                   the next vertex around x's ring                                    (w5)
/// Differences are in grid steps (as in the paper); the weights absorb the spacing. The s-chains
/// cross the connection element (StentMesh.h), so the stencils reach across the junction. A pair
/// or triple on more than one chain (the junction's shared trunk rings) gives one row, not one
/// per chain: the surface is equally stiff all round every ring.
///
/// Guarantees: K is symmetric positive semi-definite (a sum of Gram matrices with non-negative
/// weights); every stencil's coefficients sum to zero, so K·1 = 0 and translations cost nothing;
/// ½ Σ_c V_cᵀ K V_c = ½ Σ_k w_k ‖D_k V‖² = E_int.
/// Errors: InputError for a negative or non-finite weight.
/// Complexity: O(#V) non-zeros (about 25 per row of K).
#pragma once

#include <array>

#include <Eigen/SparseCore>

#include "Stent/StentMesh.h"

namespace sgp
{

using SparseMatrix = Eigen::SparseMatrix<double>;

/// w1 … w5 of equation 2, each ≥ 0.
struct StiffnessWeights
{
  double w1 = 0.0, w2 = 0.0, w3 = 0.0, w4 = 0.0, w5 = 0.0;
};

struct DifferenceOperators
{
  SparseMatrix Ds, Dt, Dss, Dtt, Dst;
};

DifferenceOperators BuildDifferenceOperators(const StentMesh& mesh);

SparseMatrix AssembleStiffnessMatrix(const StentMesh& mesh, const StiffnessWeights& weights);

/// E_int = ½ Σ over the three coordinate columns of V of Vᵀ K V.
double InternalEnergy(const SparseMatrix& K, const Points& V);

} // namespace sgp
