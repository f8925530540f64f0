#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

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

bool rough_cumulants_realizable(int dimension, double a20, double a02, double a11) {
  const double d = dimension, dr = dimension == 3 ? 3 : 1;
  const double var_x = 2 + (d + 2) * a20, var_y = 2 + (dr + 2) * a02;  // 4 Var/(d or d_r)
  return var_x >= 0 && var_y >= 0 && d * dr * a11 * a11 <= var_x * var_y;
}

std::string rough_linear_no_root_region(int dimension) {
  // The 0.01-resolved edges of the maps in theory.md §19.6 (gkt table, hcs = "linear-or-maxwellian").
  if (dimension == 2)
    return "the strongly inelastic, weakly rough region; for disks with moment_of_inertia = 0.5: alpha <= 0.48 at "
           "beta = 0.5, <= 0.64 at beta = 0, <= 0.78 at beta = -0.5, none for beta >= 0.75; map in docs/theory.md "
           "section 19.6";
  return "the strongly inelastic, weakly rough region; for spheres with moment_of_inertia = 0.4: alpha <= 0.18 at "
         "beta = 0.3, <= 0.60 at beta = 0, <= 0.81 at beta = -0.5, none for beta >= 0.33; map in docs/theory.md "
         "section 19.6";
}

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
    struct Bracket {
      double lo, hi, distance;
    };
    std::vector<Bracket> brackets;
    Point prev = at(center - span);
    for (double lt = center - span + step; lt <= center + span + step / 2; lt += step) {
      const Point cur = at(lt);
      const bool sign_change = (prev.g0 < 0) != (cur.g0 < 0);
      const bool pole = (prev.det < 0) != (cur.det < 0);
      if (sign_change && !pole) brackets.push_back({lt - step, lt, std::abs(lt - step / 2 - center)});
      prev = cur;
    }
    // Nearest the Maxwellian τ first; a root whose cumulants no distribution can have is skipped.
    std::stable_sort(brackets.begin(), brackets.end(),
                     [](const Bracket& x, const Bracket& y) { return x.distance < y.distance; });
    bool found = false;
    for (Bracket b : brackets) {
      const bool rising = at(b.lo).g0 < 0;
      for (int it = 0; it < 200 && b.hi - b.lo > 1e-15 * std::max(1.0, std::abs(b.lo)); ++it) {
        const double mid = 0.5 * (b.lo + b.hi);
        ((at(mid).g0 < 0) == rising ? b.lo : b.hi) = mid;
      }
      log_tau = 0.5 * (b.lo + b.hi);
      a = at(log_tau).a;
      if (rough_cumulants_realizable(dimension, a[0], a[1], a[2])) {
        found = true;
        break;
      }
    }
    if (!found) {
      s.temperature_ratio = s.cooling_rate = s.a20 = s.a02 = s.a11 = std::numeric_limits<double>::quiet_NaN();
      s.linear_scheme_solved = false;
      return s;
    }
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
