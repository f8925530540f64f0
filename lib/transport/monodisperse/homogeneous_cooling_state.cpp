#include "gkt/transport/monodisperse/homogeneous_cooling_state.hpp"

#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "gkt/algebra/sonine.hpp"
#include "transport/common/alpha_polynomial.hpp"

namespace gkt {

FirstSonineHcs first_sonine_hcs(int dimension) {
  const auto alpha = RationalPolynomial::variable();
  const auto m = bilinear_collision_moments<RationalPolynomial>(dimension, alpha, 2);
  const Rational two_over_d(2, static_cast<unsigned long>(dimension));
  // F_2 linearised in a2: c0 + c1 a2 = 0 with R_1 ≈ e00 + a2 (e20 + e02), ⟨xS_2'⟩ ≈ w20 + a2 w22.
  const RationalPolynomial& e0 = m.e(0, 0);
  const RationalPolynomial e1 = m.e(2, 0) + m.e(0, 2);
  const Rational w0 = scaling_weight(dimension, 2, 0);
  const Rational w2 = scaling_weight(dimension, 2, 2);
  RationalPolynomial c0 = m.t(2, 0, 0) - e0 * RationalPolynomial(two_over_d * w0);
  RationalPolynomial c1 = m.t(2, 2, 0) + m.t(2, 0, 2) -
                          (e1 * RationalPolynomial(w0) + e0 * RationalPolynomial(w2)) * RationalPolynomial(two_over_d);
  FirstSonineHcs out;
  out.a2 = RationalFunction{-c0, c1}.reduced();
  // ζ* = −(d+2)/(2d) R_1, linear in a2.
  const Rational factor(-(dimension + 2), static_cast<unsigned long>(2 * dimension));
  out.cooling_rate_0 = e0 * RationalPolynomial(factor);
  out.cooling_rate_a2 = e1 * RationalPolynomial(factor);
  out.cooling_rate = RationalFunction{out.cooling_rate_0 * out.a2.denominator + out.cooling_rate_a2 * out.a2.numerator,
                                      out.a2.denominator}
                         .reduced();
  return out;
}

/// The exact tensors T(p; k, l), E(k, l), C(k, l) as polynomials in α, coefficients rounded to
/// long double, and the first-Sonine closed forms, built on first use.
struct HomogeneousCoolingState::Impl {
  explicit Impl(int d) : dimension(d) {}
  /// Builds the tables for cumulants up to at least a_K (with headroom).
  void ensure_tables(int k_max);
  struct Tables {
    int k_max = 0;
    std::vector<std::vector<long double>> t, e, c;  // T(p; k, l), E(k, l), C(k, l): coefficients of α^j
  };
  int dimension;
  std::optional<FirstSonineHcs> first_sonine;
  Tables tables;
  std::vector<std::vector<double>> derivative_weights;  // ⟨x S_p' S_k⟩, p, k ≤ tables.k_max
};

HomogeneousCoolingState::HomogeneousCoolingState(int dimension) : dimension_(dimension) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
  impl_ = std::make_unique<Impl>(dimension);
}

HomogeneousCoolingState::~HomogeneousCoolingState() = default;
HomogeneousCoolingState::HomogeneousCoolingState(const HomogeneousCoolingState& other)
    : dimension_(other.dimension_), impl_(other.impl_ ? std::make_unique<Impl>(*other.impl_) : nullptr) {}
HomogeneousCoolingState& HomogeneousCoolingState::operator=(const HomogeneousCoolingState& other) {
  if (this != &other) {
    dimension_ = other.dimension_;
    impl_ = other.impl_ ? std::make_unique<Impl>(*other.impl_) : nullptr;
  }
  return *this;
}
HomogeneousCoolingState::HomogeneousCoolingState(HomogeneousCoolingState&&) noexcept = default;
HomogeneousCoolingState& HomogeneousCoolingState::operator=(HomogeneousCoolingState&&) noexcept = default;

void HomogeneousCoolingState::Impl::ensure_tables(int k_max) {
  if (tables.k_max >= k_max) return;
  const int target = std::max(k_max, tables.k_max + 4);
  const auto m = bilinear_collision_moments<RationalPolynomial>(dimension, RationalPolynomial::variable(), target);
  tables.k_max = target;
  derivative_weights.assign(static_cast<std::size_t>(target) + 1, std::vector<double>(target + 1));
  for (int p = 0; p <= target; ++p)
    for (int k = 0; k <= target; ++k) derivative_weights[p][k] = scaling_weight(dimension, p, k).to_double();
  tables.t.clear();
  tables.e.clear();
  for (const auto& p : m.sonine) tables.t.push_back(detail::to_alpha_polynomial(p));
  for (const auto& p : m.energy) tables.e.push_back(detail::to_alpha_polynomial(p));
  tables.c.clear();
  for (const auto& p : m.frequency) tables.c.push_back(detail::to_alpha_polynomial(p));
}

HcsState HomogeneousCoolingState::solve(const Rational& alpha, int k_max, HcsScheme scheme) {
  detail::require_restitution(alpha);
  if (k_max < 2) throw std::invalid_argument("hcs order: the highest cumulant must be >= 2");
  if (!impl_->first_sonine) impl_->first_sonine = first_sonine_hcs(dimension_);
  const Rational a2_lin = impl_->first_sonine->a2.evaluate(alpha);
  HcsState state;
  if (scheme == HcsScheme::linear) {
    if (k_max != 2) throw std::invalid_argument("hcs: \"linear\" keeps a2 only (first Sonine)");
    state.exact_a2 = a2_lin;
    state.exact_cooling_rate = impl_->first_sonine->cooling_rate.evaluate(alpha);
    state.a = {1.0, 0.0, a2_lin.to_double()};
    state.cooling_rate = state.exact_cooling_rate->to_double();
    return state;
  }

  const CumulantHierarchy h = hierarchy(alpha, k_max);
  const int unknowns = k_max - 1;  // a_2..a_K
  std::vector<double> a(static_cast<std::size_t>(k_max) + 1, 0.0);
  a[0] = 1.0;
  a[2] = a2_lin.to_double();
  std::vector<double> f(static_cast<std::size_t>(unknowns)), trial_f(f.size()),
      jac(static_cast<std::size_t>(unknowns) * unknowns);
  auto norm = [](const std::vector<double>& v) {
    double s2 = 0;
    for (double x : v) s2 += x * x;
    return std::sqrt(s2);
  };
  state.solved = false;
  for (int iteration = 0; iteration < 100; ++iteration) {
    h.residual(a, f, &jac);
    const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> j(
        jac.data(), unknowns, unknowns);
    const Eigen::VectorXd step = j.partialPivLu().solve(-Eigen::Map<const Eigen::VectorXd>(f.data(), unknowns));
    double lambda = 1.0;
    std::vector<double> trial = a;
    for (int halving = 0; halving < 30; ++halving) {
      for (int k = 2; k <= k_max; ++k) trial[k] = a[k] + lambda * step(k - 2);
      h.residual(trial, trial_f, nullptr);
      if (norm(trial_f) < norm(f) || norm(f) < 1e-300) break;
      lambda /= 2;
    }
    a = trial;
    if (step.lpNorm<Eigen::Infinity>() * lambda < 1e-15) {
      state.solved = true;
      break;
    }
  }
  h.residual(a, f, nullptr);
  if (!std::isfinite(norm(f)) || norm(f) > 1e-10) state.solved = false;
  state.a = a;
  state.cooling_rate = -(dimension_ + 2) * h.energy_moment(a) / (2.0 * dimension_);
  return state;
}

CumulantHierarchy HomogeneousCoolingState::hierarchy(const Rational& alpha, int k_max) {
  detail::require_restitution(alpha);
  if (k_max < 2) throw std::invalid_argument("hcs order: the highest cumulant must be >= 2");
  impl_->ensure_tables(k_max);
  const int n = impl_->tables.k_max + 1;
  const long double x = alpha.to_double();
  const int kn = k_max + 1;
  std::vector<double> t(static_cast<std::size_t>(kn) * kn * kn), e(static_cast<std::size_t>(kn) * kn), c(e.size());
  for (int p = 0; p < kn; ++p)
    for (int k = 0; k < kn; ++k) {
      e[static_cast<std::size_t>(p) * kn + k] =
          detail::evaluate(impl_->tables.e[static_cast<std::size_t>(p) * n + k], x);
      c[static_cast<std::size_t>(p) * kn + k] =
          detail::evaluate(impl_->tables.c[static_cast<std::size_t>(p) * n + k], x);
      for (int l = 0; l < kn; ++l)
        t[(static_cast<std::size_t>(p) * kn + k) * kn + l] =
            detail::evaluate(impl_->tables.t[(static_cast<std::size_t>(p) * n + k) * n + l], x);
    }
  std::vector<std::vector<double>> w(static_cast<std::size_t>(kn), std::vector<double>(static_cast<std::size_t>(kn)));
  std::vector<double> norms(static_cast<std::size_t>(kn));
  for (int p = 0; p < kn; ++p) {
    norms[static_cast<std::size_t>(p)] = sonine_norm(sonine_twice_m(dimension_, 0), p).to_double();
    for (int k = 0; k < kn; ++k) w[p][k] = impl_->derivative_weights[p][k];
  }
  return CumulantHierarchy(dimension_, k_max, std::move(t), std::move(e), std::move(c), std::move(w), std::move(norms));
}

}  // namespace gkt
