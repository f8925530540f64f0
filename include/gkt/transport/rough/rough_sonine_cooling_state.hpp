// The homogeneous cooling state of rough spheres and disks at any Sonine order (docs/theory.md
// §19.14): θ = T_r/T_t, ζ* and the cumulants a_pq of the joint distribution of x = c² and y = ŵ²,
//   φ = φ_M(c) φ_M(ŵ) [1 + Σ_{2 ≤ p+q ≤ N+1} a_pq S_p^(d/2−1)(x) S_q^(d_r/2−1)(y)],
// in the linear scheme (products of cumulants dropped) or the nonlinear one (all kept). Order 1
// is a20, a02, a11 (rough_homogeneous_cooling_state.hpp, the same linear scheme); order N adds
// every a_pq with p + q ≤ N + 1.
//
// The oriented ansatz (spheres; linear and nonlinear schemes) adds the velocity–spin orientation family
//   φ_M(c) φ_M(ŵ) Σ_{p + q ≤ N − 1} b_pq P S_p^(5/2)(x) S_q^(5/2)(y),   P = (c·ŵ)² − xy/3,
// of the same total degree in c², ŵ² as the a_pq (order 1: b00 alone), and the orientation correlation
// C = ⟨(c·ŵ)²/(xy)⟩ it implies (theory.md §19.14). The isotropic ansatz (no b) has C = 1/3.
#pragma once

#include <array>
#include <vector>

#include "gkt/algebra/rational.hpp"

namespace gkt {

/// Cumulant scheme of the Sonine HCS: products of cumulants dropped (linear) or kept (nonlinear).
enum class RoughSonineScheme { linear, nonlinear };

/// Distribution of the Sonine HCS: the a_pq alone (isotropic in the directions of c and ŵ) or with the
/// b_pq P S_p S_q family (oriented; spheres; both schemes).
enum class RoughSonineAnsatz { isotropic, oriented };

/// The rough HCS at Sonine order N.
struct RoughSonineCoolingState {
  int order = 1;                 ///< N: the cumulants a_pq with 2 ≤ p + q ≤ N + 1
  double temperature_ratio = 1;  ///< θ = T_r/T_t (+inf when the spin decouples, β = −1)
  double cooling_rate = 0;       ///< ζ* = ζ/ν0 (conventions.md; the smooth gas's reduction)
  /// The indices (p, q) of the cumulants (q = 0 only at β = −1).
  std::vector<std::array<int, 2>> indices;
  std::vector<double> cumulants;  ///< a_pq, in the order of `indices`
  /// The indices (p, q) of the orientation coefficients b_pq (oriented ansatz, d = 3, β > −1; else empty).
  std::vector<std::array<int, 2>> orientation_indices;
  std::vector<double> orientation_coefficients;  ///< b_pq, in the order of `orientation_indices`
  /// C = ⟨(c·ŵ)²/(c²ŵ²)⟩ of the solution: 1/3 + (4/45) Σ b_pq ⟨x S_p(x)⟩_M ⟨y S_q(y)⟩_M
  /// (theory.md (19.28)); exactly 1/3
  /// for the isotropic ansatz and at β = −1; NaN for disks (c·ŵ ≡ 0, no orientation variable) or not solved.
  double orientation_correlation = 1.0 / 3;
  bool spin_decoupled = false;  ///< β = −1: only a_p0; spin cumulants undefined
  /// False when no real root with realizable fourth-degree cumulants was found (every field NaN).
  bool solved = true;
  /// Returns a_pq: 0 beyond the order (the truncation), NaN for a spin cumulant at β = −1 or when
  /// not solved.
  [[nodiscard]] double cumulant(int p, int q) const;
  /// Returns b_pq: 0 beyond the order or without orientation terms (isotropic ansatz, β = −1), NaN for disks
  /// (no orientation variable) or when not solved.
  [[nodiscard]] double orientation_coefficient(int p, int q) const;
};

/// Returns the HCS at Sonine order N ≥ 1 for d ∈ {2, 3}, α ∈ (0, 1], β ∈ [−1, 1], κ ∈ (0, 1]
/// (std::invalid_argument naming the field otherwise). The linear scheme is solved like the first
/// Sonine one (scan in τ, bisection); the nonlinear one by damped Newton's method in (ln τ, a) from
/// the linear solution of the same order (or the Maxwellian). Cost: two exact engine tables with θ
/// symbolic, six forms of degree N + 1 (docs/performance.md).
RoughSonineCoolingState rough_sonine_cooling_state(int dimension, const Rational& alpha, const Rational& beta,
                                                   const Rational& kappa, int order, RoughSonineScheme scheme);

/// Returns the HCS at Sonine order N with the given ansatz: `isotropic` is the call above; `oriented` adds the
/// b_pq (p + q ≤ N − 1) and their balances ⟨P x^k y^l⟩, in either scheme (nonlinear: every product a·a, a·b, b·b
/// kept, Newton from the oriented linear solution; theory.md §19.14). For disks the oriented ansatz is the
/// isotropic one (c·ŵ ≡ 0). Cost: three exact engine tables with the forms c·w (theory.md (19.5a)) in the linear
/// scheme, two (one of nine forms) in the nonlinear one (docs/performance.md).
RoughSonineCoolingState rough_sonine_cooling_state(int dimension, const Rational& alpha, const Rational& beta,
                                                   const Rational& kappa, int order, RoughSonineScheme scheme,
                                                   RoughSonineAnsatz ansatz);

}  // namespace gkt
