#include "gkt/transport/monodisperse/homogeneous_cooling_state.hpp"

#include <cmath>
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

HomogeneousCoolingState::HomogeneousCoolingState(int dimension) : dimension_(dimension) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
}

void HomogeneousCoolingState::ensure_tables(int k_max) {
  if (tables_.k_max >= k_max) return;
  const int target = std::max(k_max, tables_.k_max + 4);
  const auto m = bilinear_collision_moments<RationalPolynomial>(dimension_, RationalPolynomial::variable(), target);
  tables_.k_max = target;
  derivative_weights_.assign(static_cast<std::size_t>(target) + 1, std::vector<double>(target + 1));
  for (int p = 0; p <= target; ++p)
    for (int k = 0; k <= target; ++k) derivative_weights_[p][k] = scaling_weight(dimension_, p, k).to_double();
  tables_.t.clear();
  tables_.e.clear();
  for (const auto& p : m.sonine) tables_.t.push_back(detail::to_alpha_polynomial(p));
  for (const auto& p : m.energy) tables_.e.push_back(detail::to_alpha_polynomial(p));
  tables_.c.clear();
  for (const auto& p : m.frequency) tables_.c.push_back(detail::to_alpha_polynomial(p));
}

HcsState HomogeneousCoolingState::solve(const Rational& alpha, int k_max, HcsScheme scheme) {
  detail::require_restitution(alpha);
  if (k_max < 2) throw std::invalid_argument("hcs order: the highest cumulant must be >= 2");
  if (!first_sonine_) first_sonine_ = first_sonine_hcs(dimension_);
  const Rational a2_lin = first_sonine_->a2.evaluate(alpha);
  HcsState state;
  if (scheme == HcsScheme::linear) {
    if (k_max != 2) throw std::invalid_argument("hcs: \"linear\" keeps a2 only (first Sonine)");
    state.exact_a2 = a2_lin;
    state.exact_cooling_rate = first_sonine_->cooling_rate.evaluate(alpha);
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
  ensure_tables(k_max);
  const int n = tables_.k_max + 1;
  const long double x = alpha.to_double();
  const int kn = k_max + 1;
  std::vector<double> t(static_cast<std::size_t>(kn) * kn * kn), e(static_cast<std::size_t>(kn) * kn), c(e.size());
  for (int p = 0; p < kn; ++p)
    for (int k = 0; k < kn; ++k) {
      e[static_cast<std::size_t>(p) * kn + k] = detail::evaluate(tables_.e[static_cast<std::size_t>(p) * n + k], x);
      c[static_cast<std::size_t>(p) * kn + k] = detail::evaluate(tables_.c[static_cast<std::size_t>(p) * n + k], x);
      for (int l = 0; l < kn; ++l)
        t[(static_cast<std::size_t>(p) * kn + k) * kn + l] =
            detail::evaluate(tables_.t[(static_cast<std::size_t>(p) * n + k) * n + l], x);
    }
  std::vector<std::vector<double>> w(static_cast<std::size_t>(kn), std::vector<double>(static_cast<std::size_t>(kn)));
  std::vector<double> norms(static_cast<std::size_t>(kn));
  for (int p = 0; p < kn; ++p) {
    norms[static_cast<std::size_t>(p)] = sonine_norm(sonine_twice_m(dimension_, 0), p).to_double();
    for (int k = 0; k < kn; ++k) w[p][k] = derivative_weights_[p][k];
  }
  return CumulantHierarchy(dimension_, k_max, std::move(t), std::move(e), std::move(c), std::move(w), std::move(norms));
}

CumulantHierarchy::CumulantHierarchy(int dimension, int k_max, std::vector<double> t, std::vector<double> e,
                                     std::vector<double> c, std::vector<std::vector<double>> w,
                                     std::vector<double> norms)
    : dimension_(dimension),
      k_max_(k_max),
      t_(std::move(t)),
      e_(std::move(e)),
      c_(std::move(c)),
      w_(std::move(w)),
      norms_(std::move(norms)) {}

double CumulantHierarchy::energy_moment(const std::vector<double>& a) const {
  const int kn = k_max_ + 1;
  double r = 0;
  for (int k = 0; k < kn; ++k)
    for (int l = 0; l < kn; ++l) r += a[k] * a[l] * e_[static_cast<std::size_t>(k) * kn + l];
  return r;
}

double CumulantHierarchy::collision_rate(const std::vector<double>& a) const {
  const int kn = k_max_ + 1;
  double r = 0;
  for (int k = 0; k < kn; ++k)
    for (int l = 0; l < kn; ++l) r += a[k] * a[l] * c_[static_cast<std::size_t>(k) * kn + l];
  return r;
}

void CumulantHierarchy::gradients(const std::vector<double>& a, std::vector<double>& energy,
                                  std::vector<double>& rate) const {
  const int kn = k_max_ + 1;
  energy.assign(static_cast<std::size_t>(kn), 0.0);
  rate.assign(static_cast<std::size_t>(kn), 0.0);
  for (int k = 0; k < kn; ++k)
    for (int l = 0; l < kn; ++l) {
      energy[k] += a[l] * (e_[static_cast<std::size_t>(k) * kn + l] + e_[static_cast<std::size_t>(l) * kn + k]);
      rate[k] += a[l] * (c_[static_cast<std::size_t>(k) * kn + l] + c_[static_cast<std::size_t>(l) * kn + k]);
    }
}

void CumulantHierarchy::residual(const std::vector<double>& a, std::vector<double>& f,
                                 std::vector<double>* jacobian) const {
  // theory.md (9.3): F_p = R[S_p](a) − (2/d) R_1(a) ⟨x S_p'⟩_a, p = 2..K.
  const int kn = k_max_ + 1, unknowns = k_max_ - 1;
  auto t = [&](int p, int k, int l) { return t_[(static_cast<std::size_t>(p) * kn + k) * kn + l]; };
  auto e = [&](int k, int l) { return e_[static_cast<std::size_t>(k) * kn + l]; };
  const double two_over_d = 2.0 / dimension_;
  double r1 = 0;
  std::vector<double> dr1(static_cast<std::size_t>(kn), 0.0);
  for (int k = 0; k < kn; ++k)
    for (int l = 0; l < kn; ++l) {
      r1 += a[k] * a[l] * e(k, l);
      dr1[k] += a[l] * (e(k, l) + e(l, k));
    }
  f.assign(static_cast<std::size_t>(unknowns), 0.0);
  for (int p = 2; p <= k_max_; ++p) {
    double rp = 0, wp = 0;
    for (int k = 0; k < kn; ++k) {
      wp += a[k] * w_[p][k];
      for (int l = 0; l < kn; ++l) rp += a[k] * a[l] * t(p, k, l);
    }
    f[static_cast<std::size_t>(p - 2)] = rp - two_over_d * r1 * wp;
    if (jacobian != nullptr)
      for (int q = 2; q <= k_max_; ++q) {
        double drp = 0;
        for (int l = 0; l < kn; ++l) drp += a[l] * (t(p, q, l) + t(p, l, q));
        (*jacobian)[static_cast<std::size_t>(p - 2) * unknowns + (q - 2)] =
            drp - two_over_d * (dr1[q] * wp + r1 * w_[p][q]);
      }
  }
}

}  // namespace gkt
