#include "gkt/homogeneous_cooling_state.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "gkt/sonine.hpp"

namespace gkt {

namespace {

/// w(p, k) = ⟨x S_p'(x) S_k(x)⟩ under the Maxwellian weight x^m e^{−x}/Γ(m+1), m = d/2 − 1 (exact).
Rational derivative_weight(int dimension, int p, int k) {
  const long twice_m = sonine_twice_m(dimension, 0);
  const auto sp = sonine_coefficients(twice_m, p);
  const auto sk = sonine_coefficients(twice_m, k);
  Rational sum;
  for (int j = 1; j <= p; ++j)
    for (int i = 0; i <= k; ++i)
      sum += Rational(j) * sp[static_cast<std::size_t>(j)] * sk[static_cast<std::size_t>(i)] *
             Rational::rising_half(twice_m + 2, static_cast<unsigned long>(i + j));
  return sum;
}

}  // namespace

FirstSonineHcs first_sonine_hcs(int dimension) {
  const auto alpha = RationalPolynomial::variable();
  const auto m = bilinear_collision_moments<RationalPolynomial>(dimension, alpha, 2);
  const Rational two_over_d(2, static_cast<unsigned long>(dimension));
  // F_2 linearised in a2: c0 + c1 a2 = 0 with R_1 ≈ e00 + a2 (e20 + e02), ⟨xS_2'⟩ ≈ w20 + a2 w22.
  const RationalPolynomial e0 = m.e(0, 0);
  const RationalPolynomial e1 = m.e(2, 0) + m.e(0, 2);
  const Rational w0 = derivative_weight(dimension, 2, 0);
  const Rational w2 = derivative_weight(dimension, 2, 2);
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
  auto to_coefficients = [](const RationalPolynomial& p) {
    std::vector<long double> c(static_cast<std::size_t>(std::max(p.degree(), 0L)) + 1, 0.0L);
    for (long k = 0; k <= p.degree(); ++k) c[static_cast<std::size_t>(k)] = p.coefficient(k).to_double();
    return c;
  };
  tables_.k_max = target;
  derivative_weights_.assign(static_cast<std::size_t>(target) + 1, std::vector<double>(target + 1));
  for (int p = 0; p <= target; ++p)
    for (int k = 0; k <= target; ++k) derivative_weights_[p][k] = derivative_weight(dimension_, p, k).to_double();
  tables_.t.clear();
  tables_.e.clear();
  for (const auto& p : m.sonine) tables_.t.push_back(to_coefficients(p));
  for (const auto& p : m.energy) tables_.e.push_back(to_coefficients(p));
}

HcsState HomogeneousCoolingState::solve(const Rational& alpha, int k_max, HcsScheme scheme) {
  if (alpha.sign() <= 0 || alpha > Rational(1))
    throw std::invalid_argument("alpha: must be a number in (0, 1], got " + alpha.to_string());
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

  ensure_tables(k_max);
  const int n = tables_.k_max + 1;
  const long double x = alpha.to_double();
  auto horner = [x](const std::vector<long double>& c) {
    long double v = 0;
    for (auto it = c.rbegin(); it != c.rend(); ++it) v = v * x + *it;
    return static_cast<double>(v);
  };
  const int kn = k_max + 1;
  std::vector<double> t_values(static_cast<std::size_t>(kn) * kn * kn), e_values(static_cast<std::size_t>(kn) * kn);
  for (int p = 0; p < kn; ++p)
    for (int k = 0; k < kn; ++k) {
      e_values[static_cast<std::size_t>(p) * kn + k] = horner(tables_.e[static_cast<std::size_t>(p) * n + k]);
      for (int l = 0; l < kn; ++l)
        t_values[(static_cast<std::size_t>(p) * kn + k) * kn + l] =
            horner(tables_.t[(static_cast<std::size_t>(p) * n + k) * n + l]);
    }
  auto t = [&](int p, int k, int l) { return t_values[(static_cast<std::size_t>(p) * kn + k) * kn + l]; };
  auto e = [&](int k, int l) { return e_values[static_cast<std::size_t>(k) * kn + l]; };
  std::vector<std::vector<double>> w(static_cast<std::size_t>(k_max) + 1, std::vector<double>(k_max + 1));
  for (int p = 2; p <= k_max; ++p)
    for (int k = 0; k <= k_max; ++k) w[p][k] = derivative_weights_[p][k];
  const double two_over_d = 2.0 / dimension_;
  const int unknowns = k_max - 1;  // a_2..a_K

  std::vector<double> a(static_cast<std::size_t>(k_max) + 1, 0.0);
  a[0] = 1.0;
  a[2] = a2_lin.to_double();
  auto residual = [&](const std::vector<double>& x, Eigen::VectorXd& f, Eigen::MatrixXd* jac) {
    double r1 = 0;
    std::vector<double> dr1(static_cast<std::size_t>(k_max) + 1, 0.0);
    for (int k = 0; k <= k_max; ++k)
      for (int l = 0; l <= k_max; ++l) {
        r1 += x[k] * x[l] * e(k, l);
        dr1[k] += x[l] * (e(k, l) + e(l, k));
      }
    for (int p = 2; p <= k_max; ++p) {
      double rp = 0, wp = 0;
      for (int k = 0; k <= k_max; ++k) {
        wp += x[k] * w[p][k];
        for (int l = 0; l <= k_max; ++l) rp += x[k] * x[l] * t(p, k, l);
      }
      f(p - 2) = rp - two_over_d * r1 * wp;
      if (jac != nullptr)
        for (int q = 2; q <= k_max; ++q) {
          double drp = 0;
          for (int l = 0; l <= k_max; ++l) drp += x[l] * (t(p, q, l) + t(p, l, q));
          (*jac)(p - 2, q - 2) = drp - two_over_d * (dr1[q] * wp + r1 * w[p][q]);
        }
    }
    return r1;
  };
  Eigen::VectorXd f(unknowns), trial_f(unknowns);
  Eigen::MatrixXd jac(unknowns, unknowns);
  state.solved = false;
  for (int iteration = 0; iteration < 100; ++iteration) {
    residual(a, f, &jac);
    const Eigen::VectorXd step = jac.partialPivLu().solve(-f);
    double lambda = 1.0;
    std::vector<double> trial = a;
    for (int halving = 0; halving < 30; ++halving) {
      for (int k = 2; k <= k_max; ++k) trial[k] = a[k] + lambda * step(k - 2);
      residual(trial, trial_f, nullptr);
      if (trial_f.norm() < f.norm() || f.norm() < 1e-300) break;
      lambda /= 2;
    }
    a = trial;
    if (step.lpNorm<Eigen::Infinity>() * lambda < 1e-15) {
      state.solved = true;
      break;
    }
  }
  const double r1 = residual(a, f, nullptr);
  if (!std::isfinite(f.norm()) || f.norm() > 1e-10) state.solved = false;
  state.a = a;
  state.cooling_rate = -(dimension_ + 2) * r1 / (2.0 * dimension_);
  return state;
}

}  // namespace gkt
