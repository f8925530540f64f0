#include "transport/common/galerkin_pieces.hpp"

#include <algorithm>

#include "algebra/coefficient_polynomial.hpp"
#include "gkt/algebra/sonine.hpp"

namespace gkt::detail {

namespace {
using Poly = CoefficientPolynomial;

std::vector<std::vector<double>> rounded(const std::vector<std::vector<Rational>>& m) {
  std::vector<std::vector<double>> out;
  out.reserve(m.size());
  for (const auto& row : m) {
    out.emplace_back();
    for (const auto& v : row) out.back().push_back(v.to_double());
  }
  return out;
}
}  // namespace

/// Returns product[k][q][r] = ⟨x^rank S_k S_q S_r⟩/⟨x^rank S_r²⟩ (S_k of index d/2 − 1, S_q, S_r of
/// the mode's index): S_k S_q = Σ_r product[k][q][r] S_r (theory.md (10.9)), exact.
std::vector<std::vector<std::vector<Rational>>> exact_product_table(int d, int rank, int n_max, int k_max) {
  const auto s = sonine_table(sonine_twice_m(d, rank), n_max);
  const auto w = sonine_table(sonine_twice_m(d, 0), k_max);
  std::vector<std::vector<std::vector<Rational>>> out(
      k_max + 1, std::vector<std::vector<Rational>>(n_max + 1, std::vector<Rational>(n_max + 1, Rational(0))));
  std::vector<Rational> norm;
  for (int r = 0; r <= n_max; ++r) norm.push_back(maxwell_average(d, times_x(multiply(s[r], s[r]), rank)));
  for (int k = 0; k <= k_max; ++k)
    for (int q = 0; q <= n_max; ++q) {
      const Poly kq = times_x(multiply(w[k], s[q]), rank);
      for (int r = 0; r <= std::min(n_max, q + k); ++r) out[k][q][r] = maxwell_average(d, multiply(kq, s[r])) / norm[r];
    }
  return out;
}

GalerkinPieces<Rational> vector_pieces(int d, int n_max, int k_max) {
  GalerkinPieces<Rational> r;
  const auto s = sonine_table(sonine_twice_m(d, 1), n_max);
  const auto w = sonine_table(sonine_twice_m(d, 0), k_max);
  const Rational half_d(d, 2);
  r.d.assign(n_max + 1, std::vector<Rational>(n_max + 1));
  r.m = r.d;
  for (int p = 0; p <= n_max; ++p) {
    const Poly dp = add(s[p], times_x(derivative(s[p])), Rational(2));  // S_p + 2x S_p'
    for (int q = 0; q <= n_max; ++q) {
      r.m[p][q] = maxwell_average(d, times_x(multiply(s[p], s[q])));
      r.d[p][q] = (Rational(-1, 2) * maxwell_average(d, times_x(multiply(s[q], dp))));
    }
  }
  r.u.assign(n_max + 1, std::vector<Rational>(k_max + 1));
  r.u2 = r.u;
  r.u_pressure = r.u;
  for (int p = 0; p <= n_max; ++p) {
    const Poly& sp = s[p];
    const Poly spp = derivative(sp);
    // heat: (d/2)S_p + xS_p' − xS_p − x²S_p';  density: (d/2)S_p + xS_p' − xS_p
    Poly density = add(add(Poly{}, sp, half_d), times_x(spp));
    density = add(density, times_x(sp), Rational(-1));
    const Poly heat = add(density, times_x(spp, 2), Rational(-1));
    const Poly pressure = add(add(Poly{}, sp, half_d), times_x(spp));
    for (int k = 0; k <= k_max; ++k) {
      r.u[p][k] = maxwell_average(d, multiply(heat, w[k]));
      r.u2[p][k] = maxwell_average(d, multiply(density, w[k]));
      r.u_pressure[p][k] = maxwell_average(d, multiply(pressure, w[k]));
    }
  }
  for (int q = 0; q <= n_max; ++q) r.flux.push_back(maxwell_average(d, times_x(s[q], 2)));
  r.product = exact_product_table(d, 1, n_max, k_max);
  return r;
}

GalerkinPieces<Rational> tensor_pieces(int d, int n_max, int k_max) {
  GalerkinPieces<Rational> r;
  const auto s = sonine_table(sonine_twice_m(d, 2), n_max);
  const auto w = sonine_table(sonine_twice_m(d, 0), k_max);
  const Rational yy(d - 1, static_cast<unsigned long>(d));  // Y:Y = ((d−1)/d) x²
  r.d.assign(n_max + 1, std::vector<Rational>(n_max + 1));
  r.m = r.d;
  for (int p = 0; p <= n_max; ++p) {
    const Poly dp = add(s[p], times_x(derivative(s[p])), Rational(2));
    for (int q = 0; q <= n_max; ++q) {
      r.d[p][q] = (Rational(-1, 2) * yy * maxwell_average(d, times_x(multiply(s[q], dp), 2)));
      r.m[p][q] = yy * maxwell_average(d, times_x(multiply(s[p], s[q]), 2));  // ⟨Y_2 S_p : Y_2 S_q⟩
    }
  }
  r.u.assign(n_max + 1, std::vector<Rational>(k_max + 1));
  const Rational c1 = Rational(d + 1) - Rational(2, static_cast<unsigned long>(d));
  for (int p = 0; p <= n_max; ++p) {
    // −x[(d + 1 − 2/d) S_p + 2((d−1)/d) x S_p']
    const Poly src = add(add(Poly{}, times_x(s[p]), -c1), times_x(derivative(s[p]), 2), Rational(-2) * yy);
    for (int k = 0; k <= k_max; ++k) r.u[p][k] = maxwell_average(d, multiply(src, w[k]));
  }
  for (int q = 0; q <= n_max; ++q) r.flux.push_back(maxwell_average(d, times_x(s[q], 2)));
  r.product = exact_product_table(d, 2, n_max, k_max);
  return r;
}

GalerkinPieces<Rational> scalar_pieces(int d, int n_max, int k_max) {
  GalerkinPieces<Rational> r;
  const auto s = sonine_table(sonine_twice_m(d, 0), n_max);
  r.d.assign(n_max + 1, std::vector<Rational>(n_max + 1));
  for (int p = 0; p <= n_max; ++p) {
    const Poly dp = add(times_x(derivative(s[p]), 1), s[p], Rational(-1, 2));  // x S_p' − S_p/2
    for (int q = 0; q <= n_max; ++q) r.d[p][q] = (Rational(-1) * maxwell_average(d, multiply(s[q], dp)));
  }
  r.u.assign(n_max + 1, std::vector<Rational>(k_max + 1));
  for (int p = 0; p <= n_max; ++p)
    for (int k = 0; k <= k_max; ++k) r.u[p][k] = scaling_weight(d, p, k);
  r.product = exact_product_table(d, 0, n_max, k_max);
  return r;
}

GalerkinPieces<double> rounded(const GalerkinPieces<Rational>& exact) {
  GalerkinPieces<double> r;
  r.d = rounded(exact.d);
  r.m = rounded(exact.m);
  r.u = rounded(exact.u);
  r.u2 = rounded(exact.u2);
  r.u_pressure = rounded(exact.u_pressure);
  for (const auto& v : exact.flux) r.flux.push_back(v.to_double());
  for (const auto& table : exact.product) r.product.push_back(rounded(table));
  return r;
}

}  // namespace gkt::detail
