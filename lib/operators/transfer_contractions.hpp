// The partner factors of an HCS reference with cumulants and the contractions that turn raw
// collision moments (powers of X1, X2 and the test function's variable) into Sonine-weighted
// tables (docs/theory.md §15.2, §17.11): shared by the one-component collisional transfer and
// the mixture pair's weighted transfer.
#pragma once

#include <algorithm>
#include <vector>

#include "algebra/coefficient_polynomial.hpp"
#include "collision/ring.hpp"
#include "gkt/algebra/rational.hpp"
#include "gkt/algebra/sonine.hpp"

namespace gkt::detail {

using Table = std::vector<std::vector<Rational>>;  // rows: coefficients of x^j

/// Returns the polynomials of `t` in X rewritten as polynomials in x for X = w x (row j scaled by w^j).
inline Table scaled_argument(Table t, const Rational& w) {
  for (auto& row : t) {
    Rational power(1);
    for (auto& c : row) {
      c *= power;
      power *= w;
    }
  }
  return t;
}

/// D_l = 2(S_l' − S_l), the partner factor of ∂_c φ = f_M c Σ a_l D_l (theory.md (15.2)).
inline Table derivative_factors(int d, int k_max) {
  Table out;
  for (const auto& s : sonine_table(sonine_twice_m(d, 0), k_max))
    out.push_back(detail::add(detail::add({}, detail::derivative(s), Rational(2)), s, Rational(-2)));
  return out;
}

/// T_l = x S_l − x S_l' − (d/2) S_l, the partner factor of −½∂_c·(cφ) = f_M Σ a_l T_l.
inline Table temperature_factors(int d, int k_max) {
  Table out;
  for (const auto& s : sonine_table(sonine_twice_m(d, 0), k_max)) {
    const auto xs = detail::times_x(s);
    out.push_back(
        detail::add(detail::add(xs, detail::times_x(detail::derivative(s)), Rational(-1)), s, Rational(-d, 2)));
  }
  return out;
}

/// out[p][k][l] = Σ_{j,a,b} tp[p][j] tk[k][a] tl[l][b] raw(a, b, j), one index at a time.
template <class Ring, class Raw>
std::vector<Ring> contract3(const Raw& raw, const Table& tp, const Table& tk, const Table& tl) {
  std::size_t na = 0, nb = 0;
  for (const auto& r : tk) na = std::max(na, r.size());
  for (const auto& r : tl) nb = std::max(nb, r.size());
  const std::size_t np = tp.size(), nk = tk.size(), nl = tl.size();
  std::vector<Ring> r1(np * na * nb, Ring(0L));
  for (std::size_t p = 0; p < np; ++p)
    for (std::size_t a = 0; a < na; ++a)
      for (std::size_t b = 0; b < nb; ++b) {
        Ring acc(0L);
        for (std::size_t j = 0; j < tp[p].size(); ++j)
          if (!tp[p][j].is_zero())
            acc.add_product(Ring(tp[p][j]), raw(static_cast<int>(a), static_cast<int>(b), static_cast<int>(j)));
        r1[(p * na + a) * nb + b] = std::move(acc);
      }
  std::vector<Ring> r2(np * nk * nb, Ring(0L));
  for (std::size_t p = 0; p < np; ++p)
    for (std::size_t k = 0; k < nk; ++k)
      for (std::size_t b = 0; b < nb; ++b) {
        Ring acc(0L);
        for (std::size_t a = 0; a < tk[k].size(); ++a) acc.add_product(Ring(tk[k][a]), r1[(p * na + a) * nb + b]);
        r2[(p * nk + k) * nb + b] = std::move(acc);
      }
  std::vector<Ring> out(np * nk * nl, Ring(0L));
  for (std::size_t p = 0; p < np; ++p)
    for (std::size_t k = 0; k < nk; ++k)
      for (std::size_t l = 0; l < nl; ++l) {
        Ring acc(0L);
        for (std::size_t b = 0; b < tl[l].size(); ++b) acc.add_product(Ring(tl[l][b]), r2[(p * nk + k) * nb + b]);
        out[(p * nk + k) * nl + l] = std::move(acc);
      }
  return out;
}

/// out[i][j] = Σ_{a,b} ti[i][b] tj[j][a] raw(a, b): i runs with the second raw index.
template <class Ring, class Raw>
std::vector<Ring> contract2(const Raw& raw, const Table& ti, const Table& tj) {
  std::vector<Ring> out(ti.size() * tj.size(), Ring(0L));
  for (std::size_t i = 0; i < ti.size(); ++i)
    for (std::size_t j = 0; j < tj.size(); ++j) {
      Ring acc(0L);
      for (std::size_t b = 0; b < ti[i].size(); ++b)
        for (std::size_t a = 0; a < tj[j].size(); ++a)
          acc.add_product(Ring(ti[i][b] * tj[j][a]), raw(static_cast<int>(a), static_cast<int>(b)));
      out[i * tj.size() + j] = std::move(acc);
    }
  return out;
}

inline int max_degree(const Table& t) {
  std::size_t n = 1;
  for (const auto& r : t) n = std::max(n, r.size());
  return static_cast<int>(n) - 1;
}

}  // namespace gkt::detail
