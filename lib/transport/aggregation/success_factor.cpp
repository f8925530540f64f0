#include "gkt/transport/aggregation/success_factor.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace gkt {

namespace {

/// The regularised incomplete gamma functions P(a, x) and Q(a, x) = 1 − P(a, x), a ∈ ½N, a > 0,
/// each computed from sums of positive terms: the power series of P for x < a + 1, otherwise the
/// upward recurrence Q(b + 1, x) = Q(b, x) + x^b e^{−x}/Γ(b + 1) from Q(1) = e^{−x} or
/// Q(½) = erfc(√x).
struct IncompleteGamma {
  double p = 0, q = 1;
};

/// ln Γ(a) for a ∈ ½N, 0 < a ≤ 12, from a table built once (the population balance asks for
/// these in every pair of every right-hand side).
double log_gamma(double a) {
  static const auto table = [] {
    std::array<double, 25> t{};
    for (std::size_t i = 1; i < t.size(); ++i) t[i] = std::lgamma(0.5 * static_cast<double>(i));
    return t;
  }();
  const double twice = 2 * a;
  if (twice == std::floor(twice) && twice >= 1 && twice < 25) return table[static_cast<std::size_t>(twice)];
  return std::lgamma(a);
}

IncompleteGamma incomplete_gamma(double a, double x) {
  if (x <= 0) return {0.0, 1.0};
  IncompleteGamma r;
  if (x < a + 1) {
    double term = 1.0 / a, sum = term;
    for (int n = 1; n < 1000 && term > 1e-17 * sum; ++n) {
      term *= x / (a + n);
      sum += term;
    }
    r.p = std::exp(a * std::log(x) - x - log_gamma(a)) * sum;
    r.q = 1.0 - r.p;
    return r;
  }
  const bool half = std::fmod(a, 1.0) != 0.0;
  double b = half ? 0.5 : 1.0;
  double q = half ? std::erfc(std::sqrt(x)) : std::exp(-x);
  const double log_x = std::log(x);
  for (; b < a - 0.25; b += 1.0) q += std::exp(b * log_x - x - log_gamma(b + 1.0));
  r.q = q;
  r.p = 1.0 - q;
  return r;
}

/// Coefficients of 1 + (a2/2) S_2^{(m)}(y) + (3 a2²/8) S_4^{(m)}(y) in powers of y (theory.md (20.7)):
/// the flux-free density of the reduced relative energy of two HCS partners, over e^{−y} y^m.
std::array<double, 5> sonine_weight(double m, double a2) {
  std::array<double, 5> w{};
  w[0] = 1.0;
  const auto add = [&](int n, double factor) {
    double fact_n = 1;
    for (int i = 2; i <= n; ++i) fact_n *= i;
    for (int k = 0; k <= n; ++k) {
      double fk = 1, fnk = 1;
      for (int i = 2; i <= k; ++i) fk *= i;
      for (int i = 2; i <= n - k; ++i) fnk *= i;
      const double c = std::exp(std::lgamma(m + n + 1) - std::lgamma(m + k + 1)) / (fnk * fk);
      w[static_cast<std::size_t>(k)] += factor * ((k % 2) != 0 ? -c : c);
    }
  };
  if (a2 != 0) {
    add(2, a2 / 2);
    add(4, 3 * a2 * a2 / 8);
  }
  return w;
}

/// Σ_k w_k Γ(p + k) {P or Q}(p + k, x): a moment of y^{p−1} e^{−y} w(y) over y < x (lower) or y > x.
struct Moments {
  double lower = 0, upper = 0;
};
Moments moments(const std::array<double, 5>& w, double p, double x) {
  Moments r;
  for (std::size_t k = 0; k < w.size(); ++k) {
    if (w[k] == 0) continue;
    const double a = p + static_cast<double>(k);
    const IncompleteGamma g = incomplete_gamma(a, x);
    const double gamma = std::exp(log_gamma(a));
    r.lower += w[k] * gamma * g.p;
    r.upper += w[k] * gamma * g.q;
  }
  return r;
}

}  // namespace

PairCollisionAverages pair_collision_averages(int dimension, StickingCriterion criterion, double x, double a2) {
  if (dimension != 2 && dimension != 3) throw std::invalid_argument("dimension: must be 2 or 3");
  if (!(x >= 0)) throw std::invalid_argument("critical_energy: must be >= 0 (theta*/T)");
  const double d = dimension;
  const double a2_lo = -8.0 / (d * (d + 2)), a2_hi = 4.0 / (d + 2);
  if (!(a2 >= a2_lo && a2 <= a2_hi))
    throw std::invalid_argument("a2: must be in [" + std::to_string(a2_lo) + ", " + std::to_string(a2_hi) + "]");
  PairCollisionAverages r;
  if (criterion == StickingCriterion::normal_impact) {
    // y_n = μ g_n²/(2T): flux-weighted density e^{−y_n} w_n(y_n), w_n with m = −1/2 (theory.md (20.5)).
    const auto wn = sonine_weight(-0.5, a2);
    const Moments m1 = moments(wn, 1, x), m2 = moments(wn, 2, x);
    const double norm = m1.lower + m1.upper;
    // Transverse relative energy ⟨μ g_t²/2 | y_n⟩/T as a polynomial in y_n (theory.md (20.6)).
    const double t = (d - 1) / 2;
    const std::array<double, 5> wt{t * (1 - a2 / 16 - 15 * a2 * a2 / 1024), t * (-a2 / 4 - 15 * a2 * a2 / 128),
                                   t * (a2 / 4 + 45 * a2 * a2 / 128), t * (-10 * a2 * a2 / 64), t * (a2 * a2 / 64)};
    const Moments mt = moments(wt, 1, x);
    r.rate_factor = norm;  // Γ(1) = 1
    r.success_factor = m1.lower / norm;
    r.sticking_energy = (m2.lower + mt.lower) / norm;
    r.normal_energy = m2.upper / norm;
    return r;
  }
  // y = μ g²/(2T): flux-weighted density y^{s−1} e^{−y} w(y), s = (d+1)/2, m = d/2 − 1 (theory.md (20.3)).
  const double s = (d + 1) / 2;
  const auto w = sonine_weight(d / 2 - 1, a2);
  if (criterion == StickingCriterion::always) {
    const Moments m0 = moments(w, s, 0), m1 = moments(w, s + 1, 0);
    r.rate_factor = m0.upper / std::exp(log_gamma(s));
    r.success_factor = 1;
    r.sticking_energy = m1.upper / m0.upper;
    r.normal_energy = 0;
    return r;
  }
  const Moments m0 = moments(w, s, x), m1 = moments(w, s + 1, x);
  const double norm = m0.lower + m0.upper;
  r.rate_factor = norm / std::exp(log_gamma(s));
  r.success_factor = m0.lower / norm;
  r.sticking_energy = m1.lower / norm;
  r.normal_energy = m1.upper / (s * norm);  // ⟨(ĝ·σ̂)²⟩ over the impact directions = 1/s = 2/(d+1)
  return r;
}

double success_factor(int dimension, StickingCriterion criterion, double x, double a2) {
  return pair_collision_averages(dimension, criterion, x, a2).success_factor;
}

double pair_temperature(double mass_i, double temperature_i, double mass_j, double temperature_j) {
  if (!(mass_i > 0) || !(mass_j > 0)) throw std::invalid_argument("mass: must be > 0");
  if (!(temperature_i >= 0) || !(temperature_j >= 0)) throw std::invalid_argument("temperature: must be >= 0");
  const double reduced_mass = mass_i * mass_j / (mass_i + mass_j);
  return reduced_mass * (temperature_i / mass_i + temperature_j / mass_j);
}

}  // namespace gkt
