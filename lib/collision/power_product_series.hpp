// Private: exact Taylor coefficients of a product of real powers of polynomials,
//   f(x) = Π_i p_i(x)^{r_i},   p_i(0) ≠ 0,   x = (x0, …, x3),
// by the Euler-operator recurrence of docs/theory.md (3.2)–(3.3): with Π = Π_i p_i (normalised
// to constant term 1) and Qc = Σ_i r_i (E p_i) Π_{j≠i} p_j, Π·Ef = f·Qc gives
//   |m| f_m = Σ_{e≠0} (Qc_e − |m−e| Π_e) f_{m−e},   f_0 = 1.
// Every product is truncated to the requested box (terms outside it never feed back).
// The rough-sphere integral (docs/theory.md §19) has four factors; the smooth engine's three
// (generating_series.hpp) are the special case a^{1/2} n1^{−(d−1)/2} n2^{−1}.
#pragma once

#include <stdexcept>
#include <utility>
#include <vector>

#include "collision/generating_series.hpp"

namespace gkt::detail {

/// Returns a·b keeping only the monomials inside the box.
template <class Ring>
SmallPolynomial<Ring> truncated_product(const SmallPolynomial<Ring>& a, const SmallPolynomial<Ring>& b,
                                        const Exponents& box) {
  SmallPolynomial<Ring> r;
  for (const auto& x : a.terms)
    for (const auto& y : b.terms) {
      Exponents e{};
      bool inside = true;
      for (int v = 0; v < kVariables; ++v) {
        e[v] = x.e[v] + y.e[v];
        inside = inside && e[v] <= box[v];
      }
      if (inside) r.add(e, x.c * y.c);
    }
  return r;
}

/// One factor p^r of the product.
template <class Ring>
struct PowerFactor {
  SmallPolynomial<Ring> polynomial;
  Rational exponent;
};

/// Returns the Taylor coefficients f(k) of Π_i (p_i(x)/p_i(0))^{r_i}, 0 ≤ k_v ≤ box_v, in the
/// index order of GeneratingSeries (k0 slowest). Throws std::domain_error if some p_i(0) = 0.
template <class Ring>
std::vector<Ring> expand_power_product(std::vector<PowerFactor<Ring>> factors, const Exponents& box) {
  for (auto& f : factors) {
    const Rational c = f.polynomial.constant();
    if (c.is_zero()) throw std::domain_error("expand_power_product: a factor vanishes at the expansion point");
    f.polynomial.divide_by(c);
  }
  SmallPolynomial<Ring> pi;
  pi.add(Exponents{}, Ring(1L));
  for (const auto& f : factors) pi = truncated_product(pi, f.polynomial, box);
  SmallPolynomial<Ring> qc;
  for (std::size_t i = 0; i < factors.size(); ++i) {
    SmallPolynomial<Ring> term = Ring(factors[i].exponent) * factors[i].polynomial.euler();
    for (std::size_t j = 0; j < factors.size(); ++j)
      if (j != i) term = truncated_product(term, factors[j].polynomial, box);
    qc = qc + term;
  }
  struct RecurrenceTerm {
    Exponents e;
    Ring q, p;
  };
  std::vector<RecurrenceTerm> rec;
  for (const auto& t : pi.terms)
    if (t.e != Exponents{}) rec.push_back({t.e, Ring(0L), t.c});
  for (const auto& t : qc.terms) {
    bool merged = false;
    for (auto& r : rec)
      if (r.e == t.e) {
        r.q = t.c;
        merged = true;
      }
    if (!merged && t.e != Exponents{}) rec.push_back({t.e, t.c, Ring(0L)});
  }
  auto index = [&](int k0, int k1, int k2, int k3) {
    return ((static_cast<std::size_t>(k0) * (box[1] + 1) + k1) * (box[2] + 1) + k2) * (box[3] + 1) + k3;
  };
  std::size_t size = 1;
  for (int v = 0; v < kVariables; ++v) size *= static_cast<std::size_t>(box[v] + 1);
  std::vector<Ring> f(size, Ring(0L)), weighted(size, Ring(0L));  // f_m and |m| f_m
  f[0] = Ring(1L);
  for (int k0 = 0; k0 <= box[0]; ++k0)
    for (int k1 = 0; k1 <= box[1]; ++k1)
      for (int k2 = 0; k2 <= box[2]; ++k2)
        for (int k3 = 0; k3 <= box[3]; ++k3) {
          const int degree = k0 + k1 + k2 + k3;
          if (degree == 0) continue;
          Ring acc(0L);
          for (const auto& r : rec) {
            const int j0 = k0 - r.e[0], j1 = k1 - r.e[1], j2 = k2 - r.e[2], j3 = k3 - r.e[3];
            if (j0 < 0 || j1 < 0 || j2 < 0 || j3 < 0) continue;
            const std::size_t src = index(j0, j1, j2, j3);
            if (!r.q.is_zero()) acc.add_product(r.q, f[src]);
            if (!r.p.is_zero()) acc.sub_product(r.p, weighted[src]);
          }
          const std::size_t dst = index(k0, k1, k2, k3);
          weighted[dst] = acc;
          divide(acc, Rational(degree));
          f[dst] = std::move(acc);
        }
  return f;
}

}  // namespace gkt::detail
