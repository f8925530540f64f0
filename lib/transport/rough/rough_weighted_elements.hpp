// The collision elements of the rough gas's linearised operator about the Sonine HCS (docs/theory.md §19.16,
// "Cumulant reference"): with f0 = f_M [1 + Σ a_pq S_p(x) S_q(y)] (theory.md (19.26)) the operator of the
// Chapman–Enskog equations, ⟨ψ', 𝓛ψ⟩ = −⟨[(1 + Φ(2)) ψ(1) + (1 + Φ(1)) ψ(2)] (ψ'(1') − ψ'(1))⟩, gains one term per
// cumulant: the same slot pairs as RoughCollisionElements with the partner weight S_p(x_c) S_q(y_c) on the slot c
// of the reference partner. Every element is exact (a polynomial in τ = θ/κ) until it is evaluated at θ.
#pragma once

#include <array>
#include <vector>

#include "gkt/algebra/rational_polynomial.hpp"
#include "gkt/collision/rough_collision_rule.hpp"

namespace gkt::detail {

/// The elements W^{(p_w q_w)}_{p'q', pq} = −⟨[S_pw(x2)L_qw(y2) ψ(1) + S_pw(x1)L_qw(y1) ψ(2)] (ψ'(1') − ψ'(1))⟩ for
/// trial ψ = T_r S_p L_q and test ψ' = T_r S_p' L_q' (p + q, p' + q' ≤ K; K − 1 for rank 2) and every weight
/// 2 ≤ p_w + q_w ≤ W (S^(d/2−1), L = S^(d_r/2−1), the HCS's polynomials of theory.md (19.26)); `oriented` (3D) adds
/// the same with the weight P S_pb^(5/2)(x) S_qb^(5/2)(y), P = (c·ŵ)² − xy/3, p_b + q_b ≤ W − 2 (theory.md (19.26a)).
class RoughWeightedCollisionElements {
 public:
  /// Builds the elements for Sonine orders up to K = highest_order and cumulants of total degree ≤ W = weight_degree
  /// from four engine tables (two of seven forms: the pair (c_a·c_b)^r X_a^i Y_a^j X_b^k Y_b^l and X_c^m Y_c^n; eight
  /// with (c_c·w_c) when `oriented`). Throws std::invalid_argument for W < 2 or `oriented` with d = 2.
  RoughWeightedCollisionElements(const RoughCollisionParameters<RationalPolynomial>& parameters, int highest_order,
                                 int weight_degree, bool oriented = false);
  /// Returns W^{(p_w q_w)} between test (p', q') and trial (p, q) of one rank at τ = θ/κ (exact coefficients rounded
  /// once, summed in long double); std::out_of_range outside the tables.
  [[nodiscard]] double element(int rank, int p_test, int q_test, int p_trial, int q_trial, int p_weight, int q_weight,
                               double tau) const;
  /// Returns the element of the orientation weight P S_pb^(5/2) S_qb^(5/2) (std::out_of_range unless `oriented`).
  [[nodiscard]] double orientation_element(int rank, int p_test, int q_test, int p_trial, int q_trial, int p_weight,
                                           int q_weight, double tau) const;
  /// Returns true when the orientation elements were built.
  [[nodiscard]] bool oriented() const { return oriented_; }
  /// Returns K.
  [[nodiscard]] int highest_order() const { return k_; }
  /// Returns W.
  [[nodiscard]] int weight_degree() const { return w_; }

 private:
  [[nodiscard]] double evaluate(const std::vector<std::vector<long double>>& c, int rank, int p_test, int q_test,
                                int p_trial, int q_trial, double tau) const;
  int k_, w_;
  bool oriented_;
  /// Per weight index p_w (W + 1) + q_w, per rank, per (p, q, p', q'): the coefficients of τ^{j − 2K − W}.
  std::vector<std::array<std::vector<std::vector<long double>>, 3>> contracted_, oriented_contracted_;
};

}  // namespace gkt::detail
