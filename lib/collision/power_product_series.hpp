// Private: exact Taylor coefficients of a product of real powers of polynomials,
//   f(x) = Π_i p_i(x)^{r_i},   p_i(0) ≠ 0,   x = (x0, …, x_{N−1}),
// by the Euler-operator recurrence of docs/theory.md (3.2)–(3.3) (euler_recurrence of
// generating_series.hpp): with Π = Π_i p_i (normalised to constant term 1) and
// Qc = Σ_i r_i (E p_i) Π_{j≠i} p_j, Π·Ef = f·Qc gives
//   |m| f_m = Σ_{e≠0} (Qc_e − |m−e| Π_e) f_{m−e},   f_0 = 1.
// Every product is truncated to the requested box (terms outside it never feed back).
// The rough-sphere integral (docs/theory.md §19) has four factors in up to nine variables
// (N = kRoughVariables); the smooth engine's three
// (generating_series.hpp) are the special case a^{1/2} n1^{−(d−1)/2} n2^{−1}.
#pragma once

#include <functional>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "collision/generating_series.hpp"

namespace gkt::detail {

/// Returns a·b keeping only the monomials inside the box (and accepted by `keep`, if given).
template <class Ring, std::size_t N>
SmallPolynomial<Ring, N> truncated_product(
    const SmallPolynomial<Ring, N>& a, const SmallPolynomial<Ring, N>& b, const ExponentVector<N>& box,
    const std::type_identity_t<std::function<bool(const ExponentVector<N>&)>>& keep = {}) {
  SmallPolynomial<Ring, N> r;
  for (const auto& x : a.terms)
    for (const auto& y : b.terms) {
      ExponentVector<N> e{};
      bool inside = true;
      for (std::size_t v = 0; v < N; ++v) {
        e[v] = x.e[v] + y.e[v];
        inside = inside && e[v] <= box[v];
      }
      if (inside && (!keep || keep(e))) r.add(e, x.c * y.c);
    }
  return r;
}

/// One factor p^r of the product.
template <class Ring, std::size_t N = kVariables>
struct PowerFactor {
  SmallPolynomial<Ring, N> polynomial;
  Rational exponent;
};

/// Returns the Taylor coefficients f(k) of Π_i (p_i(x)/p_i(0))^{r_i}, 0 ≤ k_v ≤ box_v, in the
/// index order of GeneratingSeries (k0 slowest). Throws std::domain_error if some p_i(0) = 0.
/// `keep`: only a down-closed subset of the box (the rest left 0; solve_euler_recurrence).
template <class Ring, std::size_t N>
std::vector<Ring> expand_power_product(
    std::vector<PowerFactor<Ring, N>> factors, const ExponentVector<N>& box,
    const std::type_identity_t<std::function<bool(const ExponentVector<N>&)>>& keep = {}) {
  for (auto& f : factors) {
    const Rational c = f.polynomial.constant();
    if (c.is_zero()) throw std::domain_error("expand_power_product: a factor vanishes at the expansion point");
    f.polynomial.divide_by(c);
  }
  SmallPolynomial<Ring, N> pi;
  pi.add(ExponentVector<N>{}, Ring(1L));
  for (const auto& f : factors) pi = truncated_product(pi, f.polynomial, box, keep);
  SmallPolynomial<Ring, N> qc;
  for (std::size_t i = 0; i < factors.size(); ++i) {
    SmallPolynomial<Ring, N> term = Ring(factors[i].exponent) * factors[i].polynomial.euler();
    for (std::size_t j = 0; j < factors.size(); ++j)
      if (j != i) term = truncated_product(term, factors[j].polynomial, box, keep);
    qc = qc + term;
  }
  return euler_recurrence(pi, qc, box, keep);
}

}  // namespace gkt::detail
