#include "gkt/transport/monodisperse/navier_stokes.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "gkt/algebra/dense_matrix.hpp"
#include "gkt/algebra/sonine.hpp"
#include "gkt/operators/collisional_transfer.hpp"
#include "gkt/operators/linearized_operator.hpp"
#include "gkt/operators/nonlinear_collision_moments.hpp"
#include "gkt/transport/monodisperse/homogeneous_cooling_state.hpp"
#include "transport/common/alpha_polynomial.hpp"
#include "transport/common/galerkin_pieces.hpp"

namespace gkt {

std::vector<Rational> FirstSonineNavierStokes::evaluate(const Rational& alpha, const Rational& a2,
                                                        SonineScheme scheme) const {
  const bool modified = scheme == SonineScheme::modified;
  const Rational nu_eta = nu_eta_0.evaluate(alpha) + a2 * (modified ? modified_nu_eta_a2 : nu_eta_a2).evaluate(alpha);
  const Rational nu_kappa =
      nu_kappa_0.evaluate(alpha) + a2 * (modified ? modified_nu_kappa_a2 : nu_kappa_a2).evaluate(alpha);
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
  const auto vec = hcs_linearized_operator_matrices<RationalPolynomial>(dimension, alpha, 1, 3, 2);
  const auto ten = hcs_linearized_operator_matrices<RationalPolynomial>(dimension, alpha, 2, 2, 2);
  const auto hcs = first_sonine_hcs(dimension);
  FirstSonineNavierStokes out;
  const Rational inv_dm1(1, static_cast<unsigned long>(dimension - 1)), inv_d(1, static_cast<unsigned long>(dimension));
  out.nu_eta_0 = ten[0](0, 0) * RationalPolynomial(inv_dm1);
  out.nu_eta_a2 = ten[2](0, 0) * RationalPolynomial(inv_dm1);
  out.nu_kappa_0 = vec[0](1, 1) * RationalPolynomial(inv_d);
  out.nu_kappa_a2 = vec[2](1, 1) * RationalPolynomial(inv_d);
  out.zeta_0 = hcs.cooling_rate_0;
  out.zeta_a2 = hcs.cooling_rate_a2;
  // Modified scheme (theory.md (10.10)): the trial function f_M(1 + a2 S_2) Y S_q is expanded as
  // f_M Σ_r (δ_qr + a2 P_qr) Y S_r (P = exact_product_table[2]; the vector mode drops r = 0, the
  // momentum), and ν is normalised by the trial's own weight 1 + a2 P_qq; linear in a2.
  const auto pv = detail::exact_product_table(dimension, 1, 3, 2), pt = detail::exact_product_table(dimension, 2, 2, 2);
  RationalPolynomial eta_a2 = out.nu_eta_a2 - out.nu_eta_0 * RationalPolynomial(pt[2][0][0]);
  for (int r = 0; r <= 2; ++r) eta_a2 = eta_a2 + ten[0](0, r) * RationalPolynomial(inv_dm1 * pt[2][0][r]);
  out.modified_nu_eta_a2 = eta_a2;
  RationalPolynomial kappa_a2 = out.nu_kappa_a2 - out.nu_kappa_0 * RationalPolynomial(pv[2][1][1]);
  for (int r = 1; r <= 3; ++r) kappa_a2 = kappa_a2 + vec[0](1, r) * RationalPolynomial(inv_d * pv[2][1][r]);
  out.modified_nu_kappa_a2 = kappa_a2;
  return out;
}

/// The solver's state: the exact operators as α-polynomials (long double coefficients), built
/// lazily and grown with headroom, and the α-independent Galerkin pieces rounded once.
struct NavierStokesSolver::Impl {
  explicit Impl(int dimension);
  struct PolynomialMatrices {
    int n_max = -1, k_max = -1;
    std::vector<DenseMatrix<std::vector<long double>>> by_weight;  // [k](p, q): coefficients of α^j
  };
  using Pieces = detail::GalerkinPieces<double>;
  /// Builds the exact operators for `order` trial functions plus `extra_columns` more (the
  /// modified scheme's trial functions reach degree order + K).
  void ensure_built(int order, int k_max, int extra_columns, bool dense);
  /// NavierStokesSolver::solve.
  NavierStokesValues solve(const Rational& alpha, int order, const std::vector<double>& hcs_a, SonineScheme scheme,
                           const EnskogState& dense);
  /// Collisional-transfer tensors (theory.md §15) as α-polynomials, built on the first dense call.
  struct DensePieces {
    int n_max = -1, k_max = -1, n_test = -1;
    std::vector<std::vector<long double>> shear_source, shear_flux, shear_gradient, heat_source_temperature,
        heat_source_density, heat_flux, heat_gradient_temperature, heat_gradient_density, scalar_source,
        cooling_gradient, cooling_scalar;
  };
  DensePieces dense_;
  Pieces vector_pieces_, tensor_pieces_, scalar_pieces_;
  int dimension_;
  double transfer_factor_ = 0, gradient_factor_ = 0;             // e_d and g_d of theory.md (15.3), (15.8)
  PolynomialMatrices vector_, tensor_, scalar_;                  // scalar: built on the first dense call
  std::optional<std::vector<std::vector<long double>>> energy_;  // E(k, l) polynomials
  int energy_k_ = -1;
};

NavierStokesSolver::Impl::Impl(int dimension) : dimension_(dimension) {
  transfer_factor_ = collisional_transfer_factor(dimension);
  gradient_factor_ = collisional_gradient_factor(dimension);
}

NavierStokesSolver::NavierStokesSolver(int dimension) : dimension_(dimension) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
  impl_ = std::make_unique<Impl>(dimension);
}

NavierStokesSolver::~NavierStokesSolver() = default;
NavierStokesSolver::NavierStokesSolver(const NavierStokesSolver& other)
    : dimension_(other.dimension_), impl_(other.impl_ ? std::make_unique<Impl>(*other.impl_) : nullptr) {}
NavierStokesSolver& NavierStokesSolver::operator=(const NavierStokesSolver& other) {
  if (this != &other) {
    dimension_ = other.dimension_;
    impl_ = other.impl_ ? std::make_unique<Impl>(*other.impl_) : nullptr;
  }
  return *this;
}
NavierStokesSolver::NavierStokesSolver(NavierStokesSolver&&) noexcept = default;
NavierStokesSolver& NavierStokesSolver::operator=(NavierStokesSolver&&) noexcept = default;

NavierStokesValues NavierStokesSolver::solve(const Rational& alpha, int order, const std::vector<double>& hcs_a,
                                             SonineScheme scheme, const EnskogState& dense) {
  return impl_->solve(alpha, order, hcs_a, scheme, dense);
}

void NavierStokesSolver::Impl::ensure_built(int order, int k_max, int extra_columns, bool dense) {
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
  build(vector_, 1, order + extra_columns);      // S_1 … S_N (index 0 is momentum)
  build(tensor_, 2, order - 1 + extra_columns);  // S_0 … S_{N−1}
  if (vector_.n_max != vector_before || vector_.k_max != k_before) {
    vector_pieces_ = detail::rounded(detail::vector_pieces(dimension_, vector_.n_max, vector_.k_max));
  }
  if (tensor_.n_max != tensor_before || tensor_.k_max != k_before) {
    tensor_pieces_ = detail::rounded(detail::tensor_pieces(dimension_, tensor_.n_max, tensor_.k_max));
  }
  if (dense) {
    const int scalar_before = scalar_.n_max, scalar_k_before = scalar_.k_max;
    build(scalar_, 0, order + 1 + extra_columns);  // S_2 … S_{N+1} (S_0, S_1: density, energy)
    if (scalar_.n_max != scalar_before || scalar_.k_max != scalar_k_before) {
      scalar_pieces_ = detail::rounded(detail::scalar_pieces(dimension_, scalar_.n_max, scalar_.k_max));
    }
  }
  // The scalar mode reaches one index further than the vector mode (S_2 … S_{N+1}).
  // Source tables: test rows up to N + 1 (scalar S_{N+1}), with the same headroom as the operators.
  if (dense &&
      (dense_.n_max < std::max(vector_.n_max, scalar_.n_max) || dense_.k_max < k_max || dense_.n_test < order + 1)) {
    const int n = std::max(vector_.n_max, scalar_.n_max), k = std::max(k_max, vector_.k_max);
    const int n_test = std::min(n, std::max(order + 3, dense_.n_test + 4));
    const auto c = collisional_transfer_moments<RationalPolynomial>(dimension_, alpha, n, k, n_test);
    auto convert = [](const std::vector<RationalPolynomial>& v) {
      std::vector<std::vector<long double>> out;
      out.reserve(v.size());
      for (const auto& p : v) out.push_back(detail::to_alpha_polynomial(p));
      return out;
    };
    dense_ = {n,
              k,
              n_test,
              convert(c.shear_source),
              convert(c.shear_flux),
              convert(c.shear_gradient),
              convert(c.heat_source_temperature),
              convert(c.heat_source_density),
              convert(c.heat_flux),
              convert(c.heat_gradient_temperature),
              convert(c.heat_gradient_density),
              convert(c.scalar_source),
              convert(c.cooling_gradient),
              convert(c.cooling_scalar)};
  }
  if (energy_k_ < k_max) {
    const int k = std::max({k_max + 2, energy_k_ + 4, 1});
    const auto e = bilinear_collision_moments<RationalPolynomial>(dimension_, alpha, k);
    energy_.emplace();
    for (const auto& p : e.energy) energy_->push_back(detail::to_alpha_polynomial(p));
    energy_k_ = k;
  }
}

NavierStokesValues NavierStokesSolver::Impl::solve(const Rational& alpha, int order, const std::vector<double>& hcs_a,
                                                   SonineScheme scheme, const EnskogState& dense) {
  if (order < 1) throw std::invalid_argument("order: must be >= 1");
  detail::require_restitution(alpha);
  const int k_max = static_cast<int>(hcs_a.size()) - 1;
  const bool modified = scheme == SonineScheme::modified;
  const bool is_dense = dense.packing_fraction > 0;
  const int extra = modified ? k_max : 0;
  ensure_built(order, k_max, extra, is_dense);
  const int d = dimension_;
  const long double x = alpha.to_double();
  const double a = alpha.to_double();

  // R_1 = Σ a_k a_l E(k, l)  (theory.md (9.2)); ζ_r/ν = −(2/d) R_1.
  auto bilinear = [&](const std::vector<std::vector<long double>>& t, int stride) {  // Σ_kl a_k a_l t[k][l]
    double acc = 0;
    for (int k = 0; k <= k_max; ++k)
      for (int l = 0; l <= k_max; ++l)
        acc += hcs_a[k] * hcs_a[l] * detail::evaluate(t[static_cast<std::size_t>(k) * stride + l], x);
    return acc;
  };
  const double zeta_term = -2.0 / d * bilinear(*energy_, energy_k_ + 1);

  // Enskog (theory.md §15): the operator and ζ0 carry χ; sources, fluxes and gradients gain the
  // collisional-transfer terms. e φχ/(1+α)^{n_H} turns the exact H-moments into Galerkin terms.
  const double chi = dense.chi, phi_chi = dense.packing_fraction * dense.chi;
  const double e = transfer_factor_, g_d = gradient_factor_, inv = 1.0 / (1.0 + a);
  const double p_star = dense.pressure(d, a);
  const double phi_dp = std::pow(2.0, d - 2) * (1.0 + a) * phi_chi * (1.0 + dense.phi_dchi / chi);  // φ ∂p*/∂φ
  const double dlnchi = dense.phi_dchi / chi;                                                       // φ ∂ln χ/∂φ
  const int nk = dense_.k_max + 1;
  auto weighted3 = [&](const std::vector<std::vector<long double>>& t, int p) {  // Σ_kl a_k a_l t[p][k][l]
    double acc = 0;
    for (int k = 0; k <= k_max; ++k)
      for (int l = 0; l <= k_max; ++l)
        acc += hcs_a[k] * hcs_a[l] * detail::evaluate(t[(static_cast<std::size_t>(p) * nk + k) * nk + l], x);
    return acc;
  };
  auto weighted2 = [&](const std::vector<std::vector<long double>>& t, int q) {  // Σ_k a_k t[q][k]
    double acc = 0;
    for (int k = 0; k <= k_max; ++k) acc += hcs_a[k] * detail::evaluate(t[static_cast<std::size_t>(q) * nk + k], x);
    return acc;
  };

  // Rows: test functions first … first+n−1; columns: basis functions first … first+cols−1.
  auto operator_matrix = [&](const PolynomialMatrices& pm, int first, int n, int cols) {
    Eigen::MatrixXd l = Eigen::MatrixXd::Zero(n, cols);
    for (int k = 0; k <= k_max; ++k)
      for (int p = 0; p < n; ++p)
        for (int q = 0; q < cols; ++q) l(p, q) += hcs_a[k] * detail::evaluate(pm.by_weight[k](first + p, first + q), x);
    return l;
  };
  auto block = [](const std::vector<std::vector<double>>& m, int first, int n, int cols) {
    Eigen::MatrixXd b(n, cols);
    for (int p = 0; p < n; ++p)
      for (int q = 0; q < cols; ++q) b(p, q) = m[first + p][first + q];
    return b;
  };
  // W(q, c): trial function q in the Maxwellian basis (theory.md (10.9)); identity when standard.
  // The modified vector trials drop the momentum component c f_M (c = first − 1), as
  // [garzo2007modified] do, so that they carry no momentum.
  auto trial_weights = [&](const Pieces& pieces, int first, int n, int cols) {
    if (!modified) return Eigen::MatrixXd(Eigen::MatrixXd::Identity(n, n));
    Eigen::MatrixXd w = Eigen::MatrixXd::Zero(n, cols);
    for (int k = 0; k <= k_max; ++k)
      for (int q = 0; q < n; ++q)
        for (int c = 0; c < cols; ++c) w(q, c) += hcs_a[k] * pieces.product[k][first + q][first + c];
    return w;
  };
  auto flux_vector = [](const std::vector<double>& f, int first, int cols) {
    Eigen::VectorXd v(cols);
    for (int c = 0; c < cols; ++c) v(c) = f[first + c];
    return v;
  };

  NavierStokesValues out;
  const int n = order, cols = order + extra;
  {  // heat and density modes: S_1 … S_N
    const Pieces& v = vector_pieces_;
    const Eigen::MatrixXd w = trial_weights(v, 1, n, cols);
    const Eigen::MatrixXd l = operator_matrix(vector_, 1, n, cols) * w.transpose();
    const Eigen::MatrixXd dm = block(v.d, 1, n, cols) * w.transpose();
    const Eigen::MatrixXd mass = block(v.m, 1, n, cols) * w.transpose();
    const Eigen::MatrixXd a_matrix = l + zeta_term * (dm - 0.5 * mass);
    const Eigen::MatrixXd b_matrix = l + zeta_term * dm;
    Eigen::VectorXd sa = Eigen::VectorXd::Zero(n), sb = Eigen::VectorXd::Zero(n);
    for (int p = 0; p < n; ++p)
      for (int k = 0; k <= k_max; ++k) {
        sa(p) += hcs_a[k] * (v.u[p + 1][k] + (p_star - 1.0) * v.u_pressure[p + 1][k]);            // (15.6)
        sb(p) += hcs_a[k] * (v.u2[p + 1][k] + (p_star + phi_dp - 1.0) * v.u_pressure[p + 1][k]);  // (15.6)
      }
    Eigen::VectorXd flux = flux_vector(v.flux, 1, cols);
    if (is_dense) {
      for (int p = 0; p < n; ++p) {
        sa(p) += e * phi_chi * inv * weighted3(dense_.heat_source_temperature, p + 1);
        sb(p) += e * phi_chi * (1.0 + 0.5 * dlnchi) * inv * weighted3(dense_.heat_source_density, p + 1);
      }
      for (int c = 0; c < cols; ++c) flux(c) += e * phi_chi * inv * weighted2(dense_.heat_flux, c + 1);  // (15.10)
    }
    const Eigen::VectorXd alpha_t = a_matrix.partialPivLu().solve(sa) / chi;
    const Eigen::VectorXd beta_t =
        b_matrix.partialPivLu().solve(sb / chi + zeta_term * (1.0 + dlnchi) * (mass * alpha_t));
    flux = w * flux;
    const double reduce = -16.0 * (d - 1) / (static_cast<double>(d) * d * (d + 2) * (d + 2));  // (10.6)
    out.thermal_conductivity = reduce * alpha_t.dot(flux);
    out.density_heat_coefficient = reduce * beta_t.dot(flux);
    if (is_dense) {  // (15.11)
      const double gradient =
          -8.0 * (d - 1) / d * g_d * (1.0 + a) * chi * dense.packing_fraction * dense.packing_fraction * inv;
      out.thermal_conductivity += gradient * bilinear(dense_.heat_gradient_temperature, nk);
      out.density_heat_coefficient += gradient * bilinear(dense_.heat_gradient_density, nk);
    }
  }
  {  // shear mode: S_0 … S_{N−1}
    const Pieces& t = tensor_pieces_;
    const Eigen::MatrixXd w = trial_weights(t, 0, n, cols);
    const Eigen::MatrixXd c_matrix =
        operator_matrix(tensor_, 0, n, cols) * w.transpose() + zeta_term * block(t.d, 0, n, cols) * w.transpose();
    Eigen::VectorXd sc = Eigen::VectorXd::Zero(n);
    for (int p = 0; p < n; ++p)
      for (int k = 0; k <= k_max; ++k) sc(p) += hcs_a[k] * t.u[p][k];
    Eigen::VectorXd flux = flux_vector(t.flux, 0, cols);
    if (is_dense) {
      for (int p = 0; p < n; ++p) sc(p) -= e * phi_chi * inv * weighted3(dense_.shear_source, p);  // (15.4)
      for (int c = 0; c < cols; ++c)
        flux(c) +=
            0.5 * (1.0 + a) * d / (d - 1.0) * e * phi_chi * inv * inv * weighted2(dense_.shear_flux, c);  // (15.7)
    }
    const Eigen::VectorXd gamma_t = c_matrix.partialPivLu().solve(sc) / chi;
    flux = w * flux;
    out.shear_viscosity = -8.0 / (d * (d + 2.0) * (d + 2.0)) * gamma_t.dot(flux);  // (10.7)
    if (is_dense) {                                                                // (15.8), (15.9)
      const double gradient = 0.25 * 8.0 * g_d * (1.0 + a) * chi * dense.packing_fraction * dense.packing_fraction *
                              inv * bilinear(dense_.shear_gradient, nk);
      out.shear_viscosity += gradient;
      out.bulk_viscosity = (d + 2.0) / d * gradient;
    }
  }
  if (is_dense) {  // scalar mode and ζ_U (theory.md §15.5)
    const Pieces& sp = scalar_pieces_;
    const Eigen::MatrixXd w = trial_weights(sp, 2, n, cols);
    const Eigen::MatrixXd s_matrix =
        operator_matrix(scalar_, 2, n, cols) * w.transpose() + zeta_term * block(sp.d, 2, n, cols) * w.transpose();
    Eigen::VectorXd u_fixed = Eigen::VectorXd::Zero(n), u_zeta = Eigen::VectorXd::Zero(n);
    for (int p = 0; p < n; ++p) {
      for (int k = 0; k <= k_max; ++k) u_zeta(p) += hcs_a[k] * sp.u[p + 2][k];
      u_fixed(p) =
          -2.0 / d * (1.0 - p_star) * u_zeta(p) - e * phi_chi * inv / d * weighted3(dense_.scalar_source, p + 2);
    }
    const auto lu = s_matrix.partialPivLu();
    const Eigen::VectorXd delta_fixed = lu.solve(u_fixed) / chi, delta_zeta = lu.solve(u_zeta) / chi;
    Eigen::VectorXd cooling(cols);  // (15.13): ζ11 = (2(1−α²)χ/d) Σ a_k δ̃_q ⟨S_k S_q⟩_{+2}
    for (int c = 0; c < cols; ++c) cooling(c) = 2.0 * (1.0 - a * a) * chi / d * weighted2(dense_.cooling_scalar, c + 2);
    cooling = w * cooling;
    const double zeta10 = -(1.0 - a) * e * phi_chi / (2.0 * d * d) * bilinear(dense_.cooling_gradient, nk);  // (15.12)
    out.cooling_rate_first_order = (zeta10 + cooling.dot(delta_fixed)) / (1.0 - cooling.dot(delta_zeta));
  }
  return out;
}

}  // namespace gkt
