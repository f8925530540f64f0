#include "gkt/transport/viscoelastic/viscoelastic_transport.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "gkt/algebra/sonine.hpp"
#include "gkt/operators/linearized_operator.hpp"
#include "transport/common/galerkin_pieces.hpp"

namespace gkt {

namespace {

using Series = std::vector<double>;  // coefficients of δ'^j, j = 0 … J

/// Returns the truncated product of two series of equal length.
Series product(const Series& a, const Series& b) {
  Series c(a.size(), 0.0);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; i + j < a.size(); ++j) c[i + j] += a[i] * b[j];
  return c;
}

/// Returns Σ_{J1+J2+J3 = j} Σ_kl a_k[J2] a_l[J3] x(J1, k, l): a bilinear form with δ'-dependent
/// coefficients x evaluated on the cumulant series.
template <class X>
Series bilinear(const std::vector<Series>& a, int orders, X&& x) {
  const int kn = static_cast<int>(a.size());
  Series out(static_cast<std::size_t>(orders) + 1, 0.0);
  for (int k = 0; k < kn; ++k)
    for (int l = 0; l < kn; ++l) {
      const Series kl = product(a[k], a[l]);
      for (int j1 = 0; j1 <= orders; ++j1) {
        const double c = x(j1, k, l);
        if (c == 0) continue;
        for (int j = j1; j <= orders; ++j) out[j] += c * kl[j - j1];
      }
    }
  return out;
}

/// The adiabatic HCS as series (theory.md (13.8)): F_p(a, δ') = N_p (s/2)(2/d) R_1 δ' da_p/dδ',
/// p = 2 … K, solved order by order with the elastic Jacobian.
std::vector<Series> cumulant_series(const ViscoelasticHierarchy& h, double gamma) {
  const int d = 3, k_max = h.k_max(), orders = h.orders(), unknowns = k_max - 1;
  std::vector<Series> a(static_cast<std::size_t>(k_max) + 1, Series(static_cast<std::size_t>(orders) + 1, 0.0));
  a[0][0] = 1;
  Eigen::MatrixXd jacobian(unknowns, unknowns);
  for (int p = 2; p <= k_max; ++p)
    for (int q = 2; q <= k_max; ++q) jacobian(p - 2, q - 2) = h.transfer(0, p, 0, q) + h.transfer(0, p, q, 0);
  const auto lu = jacobian.partialPivLu();
  for (int order = 1; order <= orders; ++order) {  // a[·][order] is still 0 here
    const Series r1 = bilinear(a, orders, [&](int j, int k, int l) { return h.energy(j, k, l); });
    Eigen::VectorXd rhs(unknowns);
    for (int p = 2; p <= k_max; ++p) {
      const Series rp = bilinear(a, orders, [&](int j, int k, int l) { return h.transfer(j, p, k, l); });
      Series wp(static_cast<std::size_t>(orders) + 1, 0.0);
      for (int k = 0; k <= k_max; ++k)
        for (int j = 0; j <= orders; ++j) wp[j] += a[k][j] * scaling_weight(d, p, k).to_double();
      const double f = rp[order] - 2.0 / d * product(r1, wp)[order];
      double drift = 0;
      for (int j = 1; j < order; ++j) drift += j * a[p][j] * r1[order - j];
      drift *= sonine_norm(sonine_twice_m(d, 0), p).to_double() * gamma * 2.0 / d;
      rhs(p - 2) = drift - f;
    }
    const Eigen::VectorXd x = lu.solve(rhs);
    for (int p = 2; p <= k_max; ++p) a[p][order] = x(p - 2);
  }
  return a;
}

/// Returns the operator series L_J = Σ_k Σ_i a_k[i] G[J − i][k] restricted to rows/columns
/// first … first + n − 1.
std::vector<Eigen::MatrixXd> operator_series(const std::vector<std::vector<DenseMatrix<double>>>& g,
                                             const std::vector<Series>& a, int first, int n) {
  const int orders = static_cast<int>(g.size()) - 1;
  std::vector<Eigen::MatrixXd> out(static_cast<std::size_t>(orders) + 1, Eigen::MatrixXd::Zero(n, n));
  for (int order = 0; order <= orders; ++order)
    for (int i = 0; i <= order; ++i)
      for (std::size_t k = 0; k < a.size(); ++k) {
        if (a[k][i] == 0) continue;
        for (int p = 0; p < n; ++p)
          for (int q = 0; q < n; ++q) out[order](p, q) += a[k][i] * g[order - i][k](first + p, first + q);
      }
  return out;
}

/// Block rows/columns first … first + n − 1 of a piece table.
Eigen::MatrixXd block(const std::vector<std::vector<double>>& m, int first, int n) {
  Eigen::MatrixXd b(n, n);
  for (int p = 0; p < n; ++p)
    for (int q = 0; q < n; ++q) b(p, q) = m[first + p][first + q];
  return b;
}

/// One Galerkin mode as a δ'-series (theory.md (13.9)):
///   Σ_i [L_i − (2/d)(R_1[i] D − (R_1λ)[i] M)] x[J − i] + (2/d) γ M Σ_i R_1[i] (J − i) x[J − i] = s[J],
/// where `source(J, x)` returns s[J] given the solutions x[0 … J − 1].
template <class Source>
std::vector<Eigen::VectorXd> solve_mode(const std::vector<Eigen::MatrixXd>& l, const Eigen::MatrixXd& dm,
                                        const Eigen::MatrixXd& mass, const Series& r1, const Series& r1_lambda,
                                        double gamma, Source&& source) {
  const double two_over_d = 2.0 / 3.0;
  const int orders = static_cast<int>(l.size()) - 1;
  auto matrix = [&](int i) -> Eigen::MatrixXd { return l[i] - two_over_d * (r1[i] * dm - r1_lambda[i] * mass); };
  const auto lu = matrix(0).partialPivLu();
  std::vector<Eigen::VectorXd> x;
  for (int order = 0; order <= orders; ++order) {
    Eigen::VectorXd rhs = source(order, x);
    for (int i = 1; i <= order; ++i)
      rhs -= (matrix(i) + two_over_d * gamma * r1[i] * (order - i) * mass) * x[order - i];
    x.push_back(lu.solve(rhs));
  }
  return x;
}

}  // namespace

ViscoelasticTransportSeries viscoelastic_transport_series(int sonine_order,
                                                          const ViscoelasticRestitution& restitution) {
  if (sonine_order < 1 || sonine_order > 8)
    throw std::invalid_argument("order: must be an integer in [1, 8], got " + std::to_string(sonine_order));
  const int d = 3, n = sonine_order, k_max = n + 1;
  const double gamma = restitution.exponent.to_double() / 2;  // δ' ∝ T^γ
  const ViscoelasticHierarchy h(k_max, restitution, 0);       // the series needs T^(J) for J ≤ orders only
  const int orders = h.orders();

  ViscoelasticTransportSeries out;
  out.sonine_order = n;
  out.cumulants = cumulant_series(h, gamma);
  const auto& a = out.cumulants;
  const Series r1 = bilinear(a, orders, [&](int j, int k, int l) { return h.energy(j, k, l); });
  for (double r : r1) out.cooling_rate.push_back(-(d + 2.0) / (2.0 * d) * r);  // (9.4)
  // λ_T = ∂ln ζ/∂ln T = 1/2 + γ q, q = δ' R_1'/R_1 = Σ (j+1) ρ_j δ'^j / Σ ρ_j δ'^j with R_1 = δ' Σ ρ_j δ'^j
  // (R_1 starts at δ'^1). Only λ_0 … λ_{J−1} enter (R_1 λ)[J]; λ_J stays 0.
  Series q(static_cast<std::size_t>(orders), 0.0), lambda(static_cast<std::size_t>(orders) + 1, 0.0);
  for (int j = 0; j < orders; ++j) {
    q[j] = (j + 1) * r1[j + 1];
    for (int i = 1; i <= j; ++i) q[j] -= r1[i + 1] * q[j - i];
    q[j] /= r1[1];
    lambda[j] = (j == 0 ? 0.5 : 0.0) + gamma * q[j];
  }
  const Series r1_lambda = product(r1, lambda);
  out.cooling_temperature_exponent = lambda;

  // Heat (A) and density (B) modes: basis c S_1 … c S_N.
  {
    const auto v = detail::rounded(detail::vector_pieces(d, n, k_max));
    const auto l = operator_series(viscoelastic_operator_series(1, n, k_max, restitution), a, 1, n);
    const Eigen::MatrixXd dm = block(v.d, 1, n), mass = block(v.m, 1, n);
    const Series zero(static_cast<std::size_t>(orders) + 1, 0.0);
    // A: U^A with the cumulants at order J, and −γ δ' c ∂_δ'φ: −γ J Σ_k a_k[J] ⟨x S_p S_k⟩.
    const auto alpha_t = solve_mode(l, dm, mass, r1, r1_lambda, gamma, [&](int order, const auto&) {
      Eigen::VectorXd s = Eigen::VectorXd::Zero(n);
      for (int p = 0; p < n; ++p)
        for (int k = 0; k <= k_max; ++k)
          s(p) += a[k][order] * (v.u[p + 1][k] - gamma * order * v.product[k][0][p + 1] * v.m[p + 1][p + 1]);
      return s;
    });
    // B: U^B − (2/d) M Σ_i R_1[i] α̃[J − i]; no λ_T term (∂_t ∇ln n = 0).
    const auto beta_t = solve_mode(l, dm, mass, r1, zero, gamma, [&](int order, const auto&) {
      Eigen::VectorXd s = Eigen::VectorXd::Zero(n);
      for (int p = 0; p < n; ++p)
        for (int k = 0; k <= k_max; ++k) s(p) += a[k][order] * v.u2[p + 1][k];
      for (int i = 1; i <= order; ++i) s -= 2.0 / d * r1[i] * (mass * alpha_t[order - i]);
      return s;
    });
    Eigen::VectorXd flux(n);
    for (int q = 0; q < n; ++q) flux(q) = v.flux[q + 1];
    const double reduce = -16.0 * (d - 1) / (d * d * (d + 2.0) * (d + 2.0));  // (10.6)
    for (int j = 0; j <= orders; ++j) {
      out.thermal_conductivity.push_back(reduce * alpha_t[j].dot(flux));
      out.density_heat_coefficient.push_back(reduce * beta_t[j].dot(flux));
    }
  }
  // Shear (C) mode: basis Y_2 S_0 … Y_2 S_{N−1}; −ζ T∂_T of the extra 1/v0 is in D^η.
  {
    const auto t = detail::rounded(detail::tensor_pieces(d, n - 1, k_max));
    const auto l = operator_series(viscoelastic_operator_series(2, n - 1, k_max, restitution), a, 0, n);
    const Series zero(static_cast<std::size_t>(orders) + 1, 0.0);
    const auto gamma_t =
        solve_mode(l, block(t.d, 0, n), block(t.m, 0, n), r1, zero, gamma, [&](int order, const auto&) {
          Eigen::VectorXd s = Eigen::VectorXd::Zero(n);
          for (int p = 0; p < n; ++p)
            for (int k = 0; k <= k_max; ++k) s(p) += a[k][order] * t.u[p][k];
          return s;
        });
    Eigen::VectorXd flux(n);
    for (int q = 0; q < n; ++q) flux(q) = t.flux[q];
    for (int j = 0; j <= orders; ++j)
      out.shear_viscosity.push_back(-8.0 / (d * (d + 2.0) * (d + 2.0)) * gamma_t[j].dot(flux));  // (10.7)
  }
  return out;
}

ViscoelasticState viscoelastic_state(const ViscoelasticTransportSeries& series, double delta_prime, int orders) {
  const int last = static_cast<int>(series.cooling_rate.size()) - 1;
  auto sum = [delta_prime](const std::vector<double>& c, int top) {  // Horner, terms j ≤ top
    double v = 0;
    for (int j = top; j >= 0; --j) v = v * delta_prime + c[static_cast<std::size_t>(j)];
    return v;
  };
  const int top = orders < 0 ? last : std::min(orders, last);
  return {sum(series.cumulants[2], top),
          sum(series.cooling_rate, top),
          sum(series.shear_viscosity, top),
          sum(series.thermal_conductivity, top),
          sum(series.density_heat_coefficient, top),
          sum(series.cooling_temperature_exponent, std::min(top, last - 1))};
}

ViscoelasticConstants viscoelastic_constants(const ViscoelasticRestitution& restitution) {
  if (restitution.series().size() < 2)
    throw std::invalid_argument("restitution: the constants need h_1 and h_2 (second order in delta')");
  const ViscoelasticHierarchy h(2, restitution, 0);
  const double nu = linearized_operator_prefactor(3);
  const auto s = viscoelastic_transport_series(1, restitution);
  ViscoelasticConstants c{};
  c.omega0 = -nu * h.energy(1, 0, 0);
  c.omega1 = nu * h.energy(2, 0, 0);
  c.q0 = c.omega0 * std::pow(2.0, 0.1) / (16 * std::sqrt(2 * std::numbers::pi));
  c.a2_1 = s.cumulants[2][1];
  c.a2_2 = s.cumulants[2][2];
  c.shear_viscosity_1 = s.shear_viscosity[1];
  c.shear_viscosity_2 = s.shear_viscosity[2];
  c.thermal_conductivity_1 = s.thermal_conductivity[1];
  c.thermal_conductivity_2 = s.thermal_conductivity[2];
  c.density_heat_coefficient_1 = s.density_heat_coefficient[1];
  c.density_heat_coefficient_2 = s.density_heat_coefficient[2];
  return c;
}

}  // namespace gkt
