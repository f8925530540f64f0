#include "gkt/dilute_navier_stokes.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "gkt/homogeneous_cooling_state.hpp"
#include "gkt/linearized_operator.hpp"
#include "gkt/nonlinear_collision_moments.hpp"
#include "gkt/sonine.hpp"
#include "transport/alpha_polynomial.hpp"

namespace gkt {

namespace {

using Poly = std::vector<Rational>;  // coefficients of x^j

Poly multiply(const Poly& a, const Poly& b) {
  Poly r(a.size() + b.size() - 1);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  return r;
}
Poly add(Poly a, const Poly& b, const Rational& scale = Rational(1)) {
  if (a.size() < b.size()) a.resize(b.size());
  for (std::size_t i = 0; i < b.size(); ++i) a[i] += scale * b[i];
  return a;
}
Poly derivative(const Poly& a) {
  Poly r(a.size() > 1 ? a.size() - 1 : 1);
  for (std::size_t i = 1; i < a.size(); ++i) r[i - 1] = Rational(static_cast<long>(i)) * a[i];
  return r;
}
Poly times_x(const Poly& a, int power = 1) {
  Poly r(static_cast<std::size_t>(power), Rational(0));
  r.insert(r.end(), a.begin(), a.end());
  return r;
}

/// The α-independent, exact pieces of the Galerkin systems (theory.md (10.4)–(10.7)) for one mode.
struct ModePieces {
  std::vector<std::vector<double>> d, m;  // D(p, q), M(p, q)
  std::vector<std::vector<double>> u;     // source projections U(p, k) per HCS weight S_k
  std::vector<std::vector<double>> u2;    // second source (density mode), vector only
  std::vector<double> flux;               // ⟨x² S_q⟩_M
};

ModePieces vector_pieces(int d, int n_max, int k_max) {
  ModePieces r;
  const long tm = sonine_twice_m(d, 1);
  std::vector<Poly> s;
  for (int n = 0; n <= n_max; ++n) s.push_back(sonine_coefficients(tm, n));
  std::vector<Poly> w;
  for (int k = 0; k <= k_max; ++k) w.push_back(sonine_coefficients(sonine_twice_m(d, 0), k));
  const Rational half_d(d, 2);
  r.d.assign(n_max + 1, std::vector<double>(n_max + 1));
  r.m = r.d;
  for (int p = 0; p <= n_max; ++p) {
    const Poly dp = add(s[p], times_x(derivative(s[p])), Rational(2));  // S_p + 2x S_p'
    for (int q = 0; q <= n_max; ++q) {
      r.m[p][q] = maxwell_average(d, times_x(multiply(s[p], s[q]))).to_double();
      r.d[p][q] = (Rational(-1, 2) * maxwell_average(d, times_x(multiply(s[q], dp)))).to_double();
    }
  }
  r.u.assign(n_max + 1, std::vector<double>(k_max + 1));
  r.u2 = r.u;
  for (int p = 0; p <= n_max; ++p) {
    const Poly sp = s[p], spp = derivative(s[p]);
    // heat: (d/2)S_p + xS_p' − xS_p − x²S_p';  density: (d/2)S_p + xS_p' − xS_p
    Poly density = add(add(Poly{}, sp, half_d), times_x(spp));
    density = add(density, times_x(sp), Rational(-1));
    const Poly heat = add(density, times_x(spp, 2), Rational(-1));
    for (int k = 0; k <= k_max; ++k) {
      r.u[p][k] = maxwell_average(d, multiply(heat, w[k])).to_double();
      r.u2[p][k] = maxwell_average(d, multiply(density, w[k])).to_double();
    }
  }
  for (int q = 0; q <= n_max; ++q) r.flux.push_back(maxwell_average(d, times_x(s[q], 2)).to_double());
  return r;
}

ModePieces tensor_pieces(int d, int n_max, int k_max) {
  ModePieces r;
  const long tm = sonine_twice_m(d, 2);
  std::vector<Poly> s;
  for (int n = 0; n <= n_max; ++n) s.push_back(sonine_coefficients(tm, n));
  std::vector<Poly> w;
  for (int k = 0; k <= k_max; ++k) w.push_back(sonine_coefficients(sonine_twice_m(d, 0), k));
  const Rational yy(d - 1, static_cast<unsigned long>(d));  // Y:Y = ((d−1)/d) x²
  r.d.assign(n_max + 1, std::vector<double>(n_max + 1));
  for (int p = 0; p <= n_max; ++p) {
    const Poly dp = add(s[p], times_x(derivative(s[p])), Rational(2));
    for (int q = 0; q <= n_max; ++q)
      r.d[p][q] = (Rational(-1, 2) * yy * maxwell_average(d, times_x(multiply(s[q], dp), 2))).to_double();
  }
  r.u.assign(n_max + 1, std::vector<double>(k_max + 1));
  const Rational c1 = Rational(d + 1) - Rational(2, static_cast<unsigned long>(d));
  for (int p = 0; p <= n_max; ++p) {
    // −x[(d + 1 − 2/d) S_p + 2((d−1)/d) x S_p']
    const Poly src = add(add(Poly{}, times_x(s[p]), -c1), times_x(derivative(s[p]), 2), Rational(-2) * yy);
    for (int k = 0; k <= k_max; ++k) r.u[p][k] = maxwell_average(d, multiply(src, w[k])).to_double();
  }
  for (int q = 0; q <= n_max; ++q) r.flux.push_back(maxwell_average(d, times_x(s[q], 2)).to_double());
  return r;
}

}  // namespace

std::vector<Rational> FirstSonineNavierStokes::evaluate(const Rational& alpha, const Rational& a2) const {
  const Rational nu_eta = nu_eta_0.evaluate(alpha) + a2 * nu_eta_a2.evaluate(alpha);
  const Rational nu_kappa = nu_kappa_0.evaluate(alpha) + a2 * nu_kappa_a2.evaluate(alpha);
  const Rational zeta = zeta_0.evaluate(alpha) + a2 * zeta_a2.evaluate(alpha);
  const Rational d_ratio = nu_kappa_0.evaluate(Rational(1));  // (d − 1)/d
  // theory.md (10.8): η* = 1/(ν_η − ζ/2), κ* = ((d−1)/d)(1 + 2a2)/(ν_κ − 2ζ),
  // μ* = 2ζ (κ* + ((d−1)/d) a2/ζ)/(2ν_κ − 3ζ) = (2ζκ* + 2((d−1)/d) a2)/(2ν_κ − 3ζ).
  const Rational eta = Rational(1) / (nu_eta - zeta / Rational(2));
  const Rational kappa = d_ratio * (Rational(1) + Rational(2) * a2) / (nu_kappa - Rational(2) * zeta);
  const Rational mu =
      (Rational(2) * zeta * kappa + Rational(2) * d_ratio * a2) / (Rational(2) * nu_kappa - Rational(3) * zeta);
  return {eta, kappa, mu};
}

FirstSonineNavierStokes first_sonine_navier_stokes(int dimension) {
  const auto alpha = RationalPolynomial::variable();
  const auto vec = hcs_linearized_operator_matrices<RationalPolynomial>(dimension, alpha, 1, 1, 2);
  const auto ten = hcs_linearized_operator_matrices<RationalPolynomial>(dimension, alpha, 2, 0, 2);
  const auto hcs = first_sonine_hcs(dimension);
  FirstSonineNavierStokes out;
  const Rational inv_dm1(1, static_cast<unsigned long>(dimension - 1)), inv_d(1, static_cast<unsigned long>(dimension));
  out.nu_eta_0 = ten[0](0, 0) * RationalPolynomial(inv_dm1);
  out.nu_eta_a2 = ten[2](0, 0) * RationalPolynomial(inv_dm1);
  out.nu_kappa_0 = vec[0](1, 1) * RationalPolynomial(inv_d);
  out.nu_kappa_a2 = vec[2](1, 1) * RationalPolynomial(inv_d);
  out.zeta_0 = hcs.cooling_rate_0;
  out.zeta_a2 = hcs.cooling_rate_a2;
  return out;
}

DiluteNavierStokes::DiluteNavierStokes(int dimension) : dimension_(dimension) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
}

void DiluteNavierStokes::ensure_built(int order, int k_max) {
  const auto alpha = RationalPolynomial::variable();
  auto build = [&](PolynomialMatrices& target, int rank, int n_max) {
    if (target.n_max >= n_max && target.k_max >= k_max) return;
    // Headroom: the error estimate asks for N+1 and N+2 next, and tolerance mode steps N up one
    // at a time; grow by at least 4 so that neither rebuilds at every call.
    const int n = std::max(n_max + 2, target.n_max + 4);
    const int k = std::max(k_max + 2, target.k_max + 4);
    const auto ms = hcs_linearized_operator_matrices<RationalPolynomial>(dimension_, alpha, rank, n, k);
    target.by_weight.clear();
    for (const auto& m : ms) {
      DenseMatrix<std::vector<long double>> c(n + 1, n + 1);
      for (int p = 0; p <= n; ++p)
        for (int q = 0; q <= n; ++q) c(p, q) = detail::to_alpha_polynomial(m(p, q));
      target.by_weight.push_back(std::move(c));
    }
    target.n_max = n;
    target.k_max = k;
  };
  const int vector_before = vector_.n_max, tensor_before = tensor_.n_max, k_before = vector_.k_max;
  build(vector_, 1, order);      // S_1 … S_N (index 0 is momentum)
  build(tensor_, 2, order - 1);  // S_0 … S_{N−1}
  if (vector_.n_max != vector_before || vector_.k_max != k_before) {
    const ModePieces v = vector_pieces(dimension_, vector_.n_max, vector_.k_max);
    vector_pieces_ = {v.d, v.m, v.u, v.u2, v.flux};
  }
  if (tensor_.n_max != tensor_before || tensor_.k_max != k_before) {
    const ModePieces t = tensor_pieces(dimension_, tensor_.n_max, tensor_.k_max);
    tensor_pieces_ = {t.d, t.m, t.u, t.u2, t.flux};
  }
  if (energy_k_ < k_max) {
    const int k = std::max({k_max + 2, energy_k_ + 4, 1});
    const auto e = bilinear_collision_moments<RationalPolynomial>(dimension_, alpha, k);
    energy_.emplace();
    for (const auto& p : e.energy) energy_->push_back(detail::to_alpha_polynomial(p));
    energy_k_ = k;
  }
}

NavierStokesValues DiluteNavierStokes::solve(const Rational& alpha, int order, const std::vector<double>& hcs_a) {
  if (order < 1) throw std::invalid_argument("order: must be >= 1");
  if (alpha.sign() <= 0 || alpha > Rational(1))
    throw std::invalid_argument("alpha: must be a number in (0, 1], got " + alpha.to_string());
  const int k_max = static_cast<int>(hcs_a.size()) - 1;
  ensure_built(order, k_max);
  const int d = dimension_;
  const long double x = alpha.to_double();

  // R_1 = Σ a_k a_l E(k, l)  (theory.md (9.2)); ζ_r/ν = −(2/d) R_1.
  double r1 = 0;
  const int ne = energy_k_ + 1;
  for (int k = 0; k <= k_max; ++k)
    for (int l = 0; l <= k_max; ++l)
      r1 += hcs_a[k] * hcs_a[l] * detail::evaluate((*energy_)[static_cast<std::size_t>(k) * ne + l], x);
  const double zeta_term = -2.0 / d * r1;

  auto operator_matrix = [&](const PolynomialMatrices& pm, int first, int n) {
    Eigen::MatrixXd l = Eigen::MatrixXd::Zero(n, n);
    for (int k = 0; k <= k_max; ++k)
      for (int p = 0; p < n; ++p)
        for (int q = 0; q < n; ++q) l(p, q) += hcs_a[k] * detail::evaluate(pm.by_weight[k](first + p, first + q), x);
    return l;
  };

  NavierStokesValues out;
  {  // heat and density modes: S_1 … S_N
    const int n = order;
    const Pieces& v = vector_pieces_;
    const Eigen::MatrixXd l = operator_matrix(vector_, 1, n);
    Eigen::MatrixXd a_matrix(n, n), b_matrix(n, n), mass(n, n);
    Eigen::VectorXd sa(n), sb(n);
    for (int p = 0; p < n; ++p) {
      for (int q = 0; q < n; ++q) {
        a_matrix(p, q) = l(p, q) + zeta_term * (v.d[p + 1][q + 1] - 0.5 * v.m[p + 1][q + 1]);
        b_matrix(p, q) = l(p, q) + zeta_term * v.d[p + 1][q + 1];
        mass(p, q) = v.m[p + 1][q + 1];
      }
      sa(p) = 0;
      sb(p) = 0;
      for (int k = 0; k <= k_max; ++k) {
        sa(p) += hcs_a[k] * v.u[p + 1][k];
        sb(p) += hcs_a[k] * v.u2[p + 1][k];
      }
    }
    const Eigen::VectorXd alpha_t = a_matrix.partialPivLu().solve(sa);
    const Eigen::VectorXd beta_t = b_matrix.partialPivLu().solve(sb + zeta_term * (mass * alpha_t));
    const double reduce = -16.0 * (d - 1) / (static_cast<double>(d) * d * (d + 2) * (d + 2));  // (10.6)
    double kappa = 0, mu = 0;
    for (int q = 0; q < n; ++q) {
      kappa += alpha_t(q) * v.flux[q + 1];
      mu += beta_t(q) * v.flux[q + 1];
    }
    out.thermal_conductivity = reduce * kappa;
    out.density_heat_coefficient = reduce * mu;
  }
  {  // shear mode: S_0 … S_{N−1}
    const int n = order;
    const Pieces& t = tensor_pieces_;
    const Eigen::MatrixXd l = operator_matrix(tensor_, 0, n);
    Eigen::MatrixXd c_matrix(n, n);
    Eigen::VectorXd sc(n);
    for (int p = 0; p < n; ++p) {
      for (int q = 0; q < n; ++q) c_matrix(p, q) = l(p, q) + zeta_term * t.d[p][q];
      sc(p) = 0;
      for (int k = 0; k <= k_max; ++k) sc(p) += hcs_a[k] * t.u[p][k];
    }
    const Eigen::VectorXd gamma_t = c_matrix.partialPivLu().solve(sc);
    double eta = 0;
    for (int q = 0; q < n; ++q) eta += gamma_t(q) * t.flux[q];
    out.shear_viscosity = -8.0 / (d * (d + 2.0) * (d + 2.0)) * eta;  // (10.7)
  }
  return out;
}

}  // namespace gkt
