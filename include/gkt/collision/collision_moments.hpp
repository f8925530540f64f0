// Collision moments between Sonine basis functions: the building blocks of every
// linearized-collision-operator matrix (docs/theory.md §4).
//
// Basis at a slot u of species s: ψ_n(u) = S_m^(n)(x) Y_r(c), x = θ_s u², c = √θ_s u,
// m = d/2 − 1 + r, Y_0 = 1, Y_1 = c, Y_2 = c c − (c²/d) I (traceless).
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "gkt/algebra/dense_matrix.hpp"
#include "gkt/algebra/rational.hpp"
#include "gkt/algebra/rational_polynomial.hpp"
#include "gkt/collision/collision_rule.hpp"
#include "gkt/collision/quadratic_form_moments.hpp"

namespace gkt {

/// Returns M with M(p, q) = ⟨ψ_q(unknown) · ψ_p(test)⟩ / J0 for p, q = 0..n_max (tensor
/// indices contracted), where ⟨X⟩ = ∫dv1 dv2 dσ̂ Θ(σ̂·g)(σ̂·g) e^{−θ_i v1² − θ_j v2²} X and
/// J0 = ⟨1⟩ (see reference_collision_integral). Exact in Ring = Rational (numeric α) or
/// RationalPolynomial (symbolic α). Requires θ at the two slots to have a rational
/// geometric mean when rank is odd and the slots differ.
template <class Ring>
DenseMatrix<Ring> sonine_collision_moments(const CollisionPair& pair, const Ring& alpha, Slot unknown, Slot test,
                                           int rank, int n_max);

/// Table of scalar three-slot moments E(a, b, c) = ⟨X1^a X2^b X1'^c⟩ / J0 (X = θu²), a ≤ 2K,
/// b ≤ K, c ≤ K; the loss moments ⟨X1^{a+c} X2^b⟩/J0 are the entries with c = 0.
template <class Ring>
struct ScalarMomentTable {
  /// The truncation K: a ≤ 2K, b ≤ K, c ≤ K.
  int k_max = 0;
  std::vector<Ring> values;  ///< index (a·(K+1) + b)·(K+1) + c
  /// Returns E(a, b, c) (exact).
  [[nodiscard]] const Ring& operator()(int a, int b, int c) const {
    return values[(static_cast<std::size_t>(a) * (k_max + 1) + b) * (k_max + 1) + c];
  }
};

/// Returns E(a, b, c) = ⟨X1^a X2^b X1'^c⟩/J0 for the pair (exact), the building block of the
/// nonlinear (bilinear) collision moments of the homogeneous cooling state (theory.md §9).
template <class Ring>
ScalarMomentTable<Ring> scalar_collision_moments(const CollisionPair& pair, const Ring& alpha, int k_max);

/// Moments ⟨Π_i X_{s_i}^{k_i} (c_a·c_b)^j⟩/J0 for up to three distinct slots s_i carrying
/// X = θu² and an optional contraction c_a·c_b (c = √θ u) between two distinct slots; one exact
/// Taylor expansion of J serves every polynomial integrand of this shape (theory.md (4.1)).
template <class Ring>
class CollisionMomentTable {
 public:
  /// Expands J up to degree max_degree[i] in X_{x_slots[i]} and max_contraction in c_a·c_b; with
  /// power = s the integrand carries the extra factor (σ̂·g)^s (theory.md (2.9)).
  CollisionMomentTable(const CollisionPair& pair, const Ring& alpha, const std::vector<Slot>& x_slots,
                       const std::vector<int>& max_degree, std::optional<std::pair<Slot, Slot>> contraction,
                       int max_contraction, const Rational& power = Rational(0));
  /// Returns ⟨(σ̂·g)^s Π_i X_{x_slots[i]}^{k[i]} (c_a·c_b)^j⟩/J_s0 (exact), J_s0 = ⟨(σ̂·g)^s⟩.
  [[nodiscard]] Ring moment(const std::vector<int>& k, int j = 0) const;
  /// Returns J_s0/J0 = Γ(1 + s/2)(A0/N2_0)^{s/2} (double; 1 for s = 0): multiply moment() by it
  /// to normalise by J0.
  [[nodiscard]] double power_factor() const { return moments_.power_factor(); }

 private:
  QuadraticFormMoments<Ring> moments_;  // forms θ_s u_s² (positions 0..2) and c_a·c_b (position 3)
};

/// Returns J0 = ∫dv1 dv2 dσ̂ Θ(σ̂·g)(σ̂·g) e^{−θ_i v1² − θ_j v2²} = K_d √(θ_i+θ_j) (θ_iθ_j)^{−(d+1)/2}
/// (velocity units of the pair's θ; double precision).
double reference_collision_integral(const CollisionPair& pair);

/// Explicit instantiation for a numeric α (compiled once in the library).
extern template ScalarMomentTable<Rational> scalar_collision_moments<Rational>(const CollisionPair&, const Rational&,
                                                                               int);
/// Explicit instantiation for a symbolic α (compiled once in the library).
extern template ScalarMomentTable<RationalPolynomial> scalar_collision_moments<RationalPolynomial>(
    const CollisionPair&, const RationalPolynomial&, int);
extern template class CollisionMomentTable<Rational>;
extern template class CollisionMomentTable<RationalPolynomial>;
/// Explicit instantiation for a numeric α (compiled once in the library).
extern template DenseMatrix<Rational> sonine_collision_moments<Rational>(const CollisionPair&, const Rational&, Slot,
                                                                         Slot, int, int);
/// Explicit instantiation for a symbolic α (compiled once in the library).
extern template DenseMatrix<RationalPolynomial> sonine_collision_moments<RationalPolynomial>(const CollisionPair&,
                                                                                             const RationalPolynomial&,
                                                                                             Slot, Slot, int, int);

}  // namespace gkt
