// Sonine (associated Laguerre) polynomials S_m^(n)(x) with exact rational
// coefficients, for integer and half-integer m.
//
// Convention (docs/conventions.md, [chapman1970] §7.5):
//   S_m^(n)(x) = Σ_{k=0}^{n} (-1)^k Γ(m+n+1) / (Γ(m+k+1) (n-k)! k!) x^k,
//   Σ_n s^n S_m^(n)(x) = (1-s)^{-m-1} exp(-x s/(1-s))           (generating function),
//   ∫_0^∞ x^m e^{-x} S_m^(p) S_m^(q) dx = δ_pq Γ(m+p+1)/p!       (orthogonality).
// The index m is passed as twice_m = 2m so that half-integers stay exact.
#pragma once

#include <vector>

#include "gkt/algebra/rational.hpp"

namespace gkt {

/// Returns the exact coefficients c_k (k = 0..n) of S_m^(n)(x) = Σ c_k x^k, m = twice_m/2 > -1.
std::vector<Rational> sonine_coefficients(long twice_m, int n);

/// Returns S_m^(n)(x) in double precision (three-term recurrence, stable for x >= 0).
double sonine_value(long twice_m, int n, double x);

/// Returns the normalised square norm Γ(m+n+1)/(n! Γ(m+1)) = <S_m^(n) S_m^(n)> under the
/// probability weight x^m e^{-x}/Γ(m+1); exact.
Rational sonine_norm(long twice_m, int n);

/// Returns the generating function (1-s)^{-m-1} exp(-x s/(1-s)) for |s| < 1 (double).
double sonine_generating_function(long twice_m, double x, double s);

/// Returns rows[n][k] = coefficient of x^k in S_m^(n)(x), n = 0..n_max (exact).
std::vector<std::vector<Rational>> sonine_table(long twice_m, int n_max);

/// Returns ⟨P(x)⟩ = Σ_j P_j (d/2)_j, the average of the polynomial P (coefficients of x^j) under the
/// d-dimensional Maxwellian in x = c² (weight x^{d/2−1} e^{−x}/Γ(d/2)); exact.
Rational maxwell_average(int dimension, const std::vector<Rational>& polynomial);

/// Returns ⟨x S_p'(x) S_k(x)⟩ under that Maxwellian, S = S_{d/2−1} (the weight of the scaling term
/// of the homogeneous cooling state, theory.md (9.2)); exact.
Rational scaling_weight(int dimension, int p, int k);

/// Returns the Sonine index 2m used for a velocity basis of tensor rank `rank` (0 scalar,
/// 1 vector, 2 traceless tensor) in `dimension` dimensions: m = d/2 - 1 + rank.
constexpr long sonine_twice_m(int dimension, int rank) { return dimension - 2 + 2L * rank; }

}  // namespace gkt
