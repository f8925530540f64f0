// The Galerkin systems of the rough gas's Navier–Stokes modes at Sonine order N (docs/theory.md §19.16):
// basis functions ψ = T_r(c) S_p(x) L_q(y) (x = c², y = ŵ², ŵ the spin scaled by √(2T_r/(κm)); T_0 = 1,
// T_1 = c, T_2 = (c c)°), their collision matrix L = ⟨ψ_p, 𝓛ψ_q⟩ (normalisation of theory.md (5.2)) and the
// Maxwellian products N_pq = ⟨ψ_p ψ_q⟩, G_pq = ⟨ψ_q C·∂_C ψ_p⟩ (C = (c, ŵ)) of the cooling term
// (ζ/2)∂_C·(C ·). Every element is exact (a polynomial in τ = θ/κ) until it is evaluated at θ.
#pragma once

#include <array>
#include <vector>

#include "gkt/algebra/rational.hpp"
#include "gkt/algebra/rational_polynomial.hpp"
#include "gkt/collision/rough_collision_rule.hpp"
#include "gkt/transport/rough/rough_sonine_transport.hpp"

namespace gkt::detail {

/// ψ = T_rank(c) (Σ_i s[i] x^i)(Σ_j l[j] y^j) (exact), e.g. T_rank S_p^(d/2−1+rank)(x) L_q^(d_r/2−1)(y).
struct RoughTrialFunction {
  int rank = 0;
  int p = 0, q = 0;            ///< the Sonine indices (of a basis function)
  std::vector<Rational> s, l;  ///< coefficients of x^i and y^j
};

/// Returns T_rank S_p L_q (d_r = 3 spheres, 1 disks).
RoughTrialFunction rough_sonine_function(int dimension, int rank, int p, int q);

/// Returns ⟨a b⟩ over the Maxwellians (a, b of equal rank, contracted), exact.
Rational rough_maxwell_product(int dimension, const RoughTrialFunction& a, const RoughTrialFunction& b);
/// Returns ⟨b C·∂_C a⟩ over the Maxwellians (C = (c, ŵ); the cooling term's G), exact.
Rational rough_maxwell_scaling_product(int dimension, const RoughTrialFunction& a, const RoughTrialFunction& b);

/// The exact collision elements ⟨T_r S_p' L_q', 𝓛 T_r S_p L_q⟩ for p + q, p' + q' ≤ K (K − 1 for rank 2), as
/// polynomials in λ = √(θ/κ) times λ^{4K}: the engine's slot-pair tables (1,1), (1,1'), (2,1), (2,1') of
/// (c_a·c_b)^r X_a^i Y_a^j X_b^k Y_b^l combined and contracted with the Sonine coefficients one index at a time.
class RoughCollisionElements {
 public:
  /// Builds the elements up to K = highest_order (the engine tables are dropped after the contraction).
  RoughCollisionElements(const RoughCollisionParameters<RationalPolynomial>& parameters, int highest_order);
  /// Returns ⟨T_r S_p' L_q', 𝓛 T_r S_p L_q⟩ (test p', q'; trial p, q) at τ = θ/κ: the exact coefficients in τ,
  /// rounded once, summed in long double.
  [[nodiscard]] double element(int rank, int p_test, int q_test, int p_trial, int q_trial, double tau) const;
  /// Returns K.
  [[nodiscard]] int highest_order() const { return k_; }

 private:
  int k_;
  /// Per rank, index (p, q, p', q'): the coefficients of τ^{j − 2K}, j = 0, 1, … (rounded from the exact ones).
  std::array<std::vector<std::vector<long double>>, 3> contracted_;
};

using RoughMatrix = std::vector<std::vector<double>>;

/// One mode's basis and its Galerkin pieces (row p = test ψ_p, column q = trial ψ_q).
struct RoughGalerkinSystem {
  std::vector<RoughTrialFunction> basis;
  RoughMatrix collision;  ///< L_pq
  RoughMatrix cooling;    ///< G_pq = ⟨ψ_q C·∂_C ψ_p⟩
  RoughMatrix product;    ///< N_pq = ⟨ψ_p ψ_q⟩
};

/// Where the systems are evaluated: dimension, τ = θ/κ, and whether the spin is decoupled (β = −1: translational
/// families only; the spin blocks neither feel nor feed them and can be singular).
struct RoughModeState {
  int dimension = 3;
  double tau = 1;
  bool spin_decoupled = false;
};

/// Returns the shear system of order N: (c c)° S_p L_q, p + q ≤ N − 1 (theory.md (19.41)).
RoughGalerkinSystem rough_tensor_system(const RoughCollisionElements& elements, const RoughModeState& state, int order);
/// Returns the heat system of order N: c S_p L_q, 1 ≤ p + q ≤ N (no momentum; theory.md (19.42)).
RoughGalerkinSystem rough_vector_system(const RoughCollisionElements& elements, const RoughModeState& state, int order);
/// Returns the scalar system of order N: S_p L_q, 1 ≤ p + q ≤ N (no mass; theory.md (19.43)).
RoughGalerkinSystem rough_scalar_system(const RoughCollisionElements& elements, const RoughModeState& state, int order);

/// Returns η*, κ*, μ*, η_b*, ζ_U at order N about Maxwellians at θ (θ = +inf: spin decoupled).
RoughTransportValues solve_rough_navier_stokes(const RoughCollisionElements& elements, const RoughModeState& state,
                                               int order, double theta);

}  // namespace gkt::detail
