#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

#include <Eigen/Dense>

#include "gkt/collision/rough_collision_moments.hpp"
#include "gkt/transport/rough/rough_cooling_rates.hpp"

namespace gkt {

namespace {

void check(int d, const Rational& alpha, const Rational& beta, const Rational& kappa) {
  // rough_parameters_symbolic_temperature validates the ranges; call it once for its checks.
  (void)rough_parameters_symbolic_temperature(d, alpha, beta, kappa);
}

}  // namespace

std::vector<Rational> rough_maxwellian_temperature_equation(int dimension, const Rational& alpha, const Rational& beta,
                                                            const Rational& kappa) {
  check(dimension, alpha, beta, kappa);
  const auto c = RoughCoolingRates(dimension, alpha, beta, kappa).maxwellian_temperature_equation();
  return {c[0], c[1], c[2]};
}

std::string rough_linear_no_root_region(int dimension) { return dimension == 2 ? "TODO" : "TODO"; }

RoughCoolingState rough_homogeneous_cooling_state(int dimension, const Rational& alpha, const Rational& beta,
                                                  const Rational& kappa, RoughHcsScheme scheme) {
  check(dimension, alpha, beta, kappa);
  const RoughCoolingRates rates(dimension, alpha, beta, kappa);
  auto r = [&rates](std::size_t weight, std::size_t test) {
    return [&rates, weight, test](double tau) { return rates.production(weight, test, tau); };
  };
  const bool linear = scheme == RoughHcsScheme::linear;
  const double d = dimension;
  RoughCoolingState s;
  if (beta == Rational(-1)) {
    // Spin frozen: the x and x² balances alone (their spin weights average to zero).
    s.spin_decoupled = true;
    s.temperature_ratio = std::numeric_limits<double>::infinity();
    s.a02 = s.a11 = std::numeric_limits<double>::quiet_NaN();
    const double z0 = -2 / d * r(0, 0)(1.0);
    if (linear) {
      const double base = d / 2 * (d / 2 + 1);
      s.a20 = -(2 * z0 * base + r(0, 2)(1.0)) / (r(1, 2)(1.0) + 2 * (-2 / d * r(1, 0)(1.0)) * base + 2 * z0 * base);
    }
    s.cooling_rate = (d + 2) / 4 * (-2 / d) * (r(0, 0)(1.0) + s.a20 * r(1, 0)(1.0));
    return s;
  }
  // Maxwellian: G_0(τ) = 0 alone. Its τ·G_0 is a quadratic with one positive root (G_0 < 0 for a cold
  // spin, > 0 for a hot one): bisect in log τ.
  const std::array<double, 3> zero{};
  auto g0 = [&](double log_tau) { return rates.at(std::exp(log_tau), zero).residual[0]; };
  double lo = 0, hi = 0;
  while (g0(lo) > 0 && lo > -80) lo -= 1;
  while (g0(hi) < 0 && hi < 80) hi += 1;
  if (g0(lo) > 0 || g0(hi) < 0) throw std::runtime_error("rough HCS: no temperature ratio found");
  for (int it = 0; it < 200 && hi - lo > 1e-15 * std::max(1.0, std::abs(lo)); ++it) {
    const double mid = 0.5 * (lo + hi);
    (g0(mid) < 0 ? lo : hi) = mid;
  }
  double log_tau = 0.5 * (lo + hi);
  std::array<double, 3> a{};
  if (linear) {
    // At fixed τ the three fourth-degree balances are linear in a: a(τ) = −M(τ)⁻¹ g(τ); then
    // G_0(τ, a(τ)) = 0 fixes τ. M(τ) can be singular (a pole of a(τ), where G_0 changes sign
    // without a root): scan log τ around the Maxwellian root for sign changes of G_0 on
    // intervals where det M keeps its sign, take the one nearest the Maxwellian τ, and bisect.
    struct Point {
      double g0, det;
      std::array<double, 3> a;
    };
    auto at = [&](double lt) {
      const RoughBalances b = rates.at(std::exp(lt), std::array<double, 3>{});
      Eigen::Matrix3d m;
      Eigen::Vector3d g;
      for (int p = 0; p < 3; ++p) {
        g(p) = b.residual[static_cast<std::size_t>(p) + 1];
        for (int q = 0; q < 3; ++q) m(p, q) = b.jacobian[static_cast<std::size_t>(p) + 1][static_cast<std::size_t>(q)];
      }
      const Eigen::Vector3d x = m.fullPivLu().solve(-g);
      Point pt{b.residual[0], m.determinant(), {x(0), x(1), x(2)}};
      for (std::size_t q = 0; q < 3; ++q) pt.g0 += b.jacobian[0][q] * pt.a[q];
      return pt;
    };
    const double center = log_tau, step = 1.0 / 64, span = 4;
    double best_lo = 0, best_hi = 0, best_distance = std::numeric_limits<double>::infinity();
    Point prev = at(center - span);
    for (double lt = center - span + step; lt <= center + span + step / 2; lt += step) {
      const Point cur = at(lt);
      const bool sign_change = (prev.g0 < 0) != (cur.g0 < 0);
      const bool pole = (prev.det < 0) != (cur.det < 0);
      const double distance = std::abs(lt - step / 2 - center);
      if (sign_change && !pole && distance < best_distance) {
        best_distance = distance;
        best_lo = lt - step;
        best_hi = lt;
      }
      prev = cur;
    }
    if (!std::isfinite(best_distance)) {
      s.temperature_ratio = s.cooling_rate = s.a20 = s.a02 = s.a11 = std::numeric_limits<double>::quiet_NaN();
      s.linear_scheme_solved = false;
      return s;
    }
    const bool rising = at(best_lo).g0 < 0;
    for (int it = 0; it < 200 && best_hi - best_lo > 1e-15 * std::max(1.0, std::abs(best_lo)); ++it) {
      const double mid = 0.5 * (best_lo + best_hi);
      ((at(mid).g0 < 0) == rising ? best_lo : best_hi) = mid;
    }
    log_tau = 0.5 * (best_lo + best_hi);
    a = at(log_tau).a;
  }
  const double tau = std::exp(log_tau);
  const RoughBalances e = rates.at(tau, a);
  s.temperature_ratio = tau * kappa.to_double();
  s.cooling_rate = (d + 2) / 4 * e.translational_rate;
  s.a20 = a[0];
  s.a02 = a[1];
  s.a11 = a[2];
  return s;
}

}  // namespace gkt
