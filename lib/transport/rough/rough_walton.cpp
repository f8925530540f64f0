#include "gkt/transport/rough/rough_walton.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "gkt/transport/rough/rough_bulk_viscosity.hpp"
#include "gkt/transport/rough/rough_thermal_conductivity.hpp"
#include "transport/rough/rough_walton_quadrature.hpp"

namespace gkt {

namespace {

using detail::condition;
using detail::ConditionedGaussian;
using detail::gauss_legendre;

/// A1 = ⟨η_t G²⟩ and A2 = ⟨η_t² G²⟩ over collisions (weight Θ(u)u, velocities in units of √(2T_t/m)),
/// G = |g_c,t|, η_t = min{η0, M u/G}, M = μ_f(1+α)/2 (theory.md (19.21)). u has density u e^{−u²/2};
/// each tangential component of g_c has variance s² = 1 + τ, τ = θ/κ.
struct Averages {
  double a1 = 0, a2 = 0;
};

/// ⟨u; u < a⟩ = √(π/2) erf(a/√2) − a e^{−a²/2} and ⟨u²; u < a⟩ = 2 − (a² + 2)e^{−a²/2} for the density
/// u e^{−u²/2}; below a = 1 by their series (the closed forms cancel to a³/3 and a⁴/4: with μ_f large,
/// M² ⟨u²; u < a⟩ would lose every digit).
void truncated_moments(double a, double& u1, double& u2) {
  const double x = a * a / 2, e = std::exp(-x);
  if (a >= 1) {
    u1 = std::sqrt(std::numbers::pi / 2) * std::erf(a / std::sqrt(2.0)) - a * e;
    u2 = 2 - (a * a + 2) * e;
    return;
  }
  // u1 = Σ_k (−x)^k/k! · a³/(2k + 3);  u2 = 2e^{−x} Σ_{k≥2} x^k/k!.
  double term = a * a * a, sum1 = 0, power = x * x / 2, sum2 = 0;
  for (int k = 0; k < 40; ++k) {
    sum1 += term / (2 * k + 3);
    term *= -x / (k + 1);
    sum2 += power;
    power *= x / (k + 3);
  }
  u1 = sum1;
  u2 = 2 * e * sum2;
}

Averages averages(int d, double eta0, double m, double s, int intervals) {
  const double tangential = (d - 1) * s * s;  // ⟨G²⟩
  if (std::isinf(m)) return {eta0 * tangential, eta0 * eta0 * tangential};
  if (m == 0) return {0, 0};
  const double c = eta0 / m;  // sticking for u ≥ cG
  // Integrand over r = G/s, weighted by the density of r: r e^{−r²/2} (d = 3), √(2/π) e^{−r²/2} (d = 2).
  const auto integrand = [&](double r, double& i1, double& i2) {
    const double g = s * r, a = c * g, e = std::exp(-a * a / 2);
    double u1 = 0, u2 = 0;
    truncated_moments(a, u1, u2);
    const double density = (d == 3 ? r : std::sqrt(2 / std::numbers::pi)) * std::exp(-r * r / 2);
    i1 = density * (eta0 * g * g * e + m * g * u1);
    i2 = density * (eta0 * eta0 * g * g * e + m * m * u2);
  };
  const double upper = 12, h = upper / intervals;
  Averages out;
  for (int k = 0; k <= intervals; ++k) {
    const double weight = (k == 0 || k == intervals) ? 1 : (k % 2 == 1 ? 4 : 2);
    double i1 = 0, i2 = 0;
    integrand(k * h, i1, i2);
    out.a1 += weight * i1;
    out.a2 += weight * i2;
  }
  out.a1 *= h / 3;
  out.a2 *= h / 3;
  return out;
}

/// E[Y1Y2Y3Y4] for jointly Gaussian Y with means mu and covariances s (Isserlis with means).
double quartic(const double* mu, const double (*s)[4]) {
  return mu[0] * mu[1] * mu[2] * mu[3] + s[0][1] * mu[2] * mu[3] + s[0][2] * mu[1] * mu[3] + s[0][3] * mu[1] * mu[2] +
         s[1][2] * mu[0] * mu[3] + s[1][3] * mu[0] * mu[2] + s[2][3] * mu[0] * mu[1] + s[0][1] * s[2][3] +
         s[0][2] * s[1][3] + s[0][3] * s[1][2];
}

/// E[Y2(a):Y2(b)] = Σ_kl E[a_k b_k a_l b_l] − (1/d) Σ_kl E[a_k a_k b_l b_l]; a, b ∈ {c1, c2, c1'} given by
/// their conditional means and their index into the covariance of (v1, v2) (c1' shares c1's).
double y2_pair(int d, const std::array<double, 3>& mean_a, int base_a, const std::array<double, 3>& mean_b, int base_b,
               const ConditionedGaussian& g) {
  double cross = 0, trace = 0;
  for (int k = 0; k < d; ++k)
    for (int l = 0; l < d; ++l) {
      const int idx1[4] = {base_a + k, base_b + k, base_a + l, base_b + l};
      const double mu1[4] = {mean_a[k], mean_b[k], mean_a[l], mean_b[l]};
      const int idx2[4] = {base_a + k, base_a + k, base_b + l, base_b + l};
      const double mu2[4] = {mean_a[k], mean_a[k], mean_b[l], mean_b[l]};
      double s1[4][4], s2[4][4];
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
          s1[i][j] = g.cov[idx1[i]][idx1[j]];
          s2[i][j] = g.cov[idx2[i]][idx2[j]];
        }
      cross += quartic(mu1, s1);
      trace += quartic(mu2, s2);
    }
  return cross - trace / d;
}

/// E[Π_i X_{idx_i}] for the conditioned Gaussian with the given means (Isserlis' theorem with means,
/// by recursion on the first factor: E[Y1 R] = μ1 E[R] + Σ_j C_1j E[R without Y_j]); count ≤ 6.
double gaussian_moment(const int* idx, const double* mean, int count, const ConditionedGaussian& g) {
  if (count == 0) return 1;
  int rest_idx[6] = {};
  double rest_mean[6] = {};
  for (int i = 1; i < count; ++i) {
    rest_idx[i - 1] = idx[i];
    rest_mean[i - 1] = mean[i];
  }
  double value = mean[0] * gaussian_moment(rest_idx, rest_mean, count - 1, g);
  for (int j = 1; j < count; ++j) {
    const double c = g.cov[static_cast<std::size_t>(idx[0])][static_cast<std::size_t>(idx[j])];
    if (c == 0) continue;
    int sub_idx[6] = {};
    double sub_mean[6] = {};
    int k = 0;
    for (int i = 1; i < count; ++i) {
      if (i == j) continue;
      sub_idx[k] = idx[i];
      sub_mean[k++] = mean[i];
    }
    value += c * gaussian_moment(sub_idx, sub_mean, count - 2, g);
  }
  return value;
}

/// One particle's velocities in the conditioned Gaussian: the index of its first translational and spin
/// component and their conditional means (post-collisional: shifted by the collision at (u, G)).
struct Particle {
  int v = 0, w = 0;
  std::array<double, 3> v_mean{}, w_mean{};
};

/// E[ψ_a(X)·ψ_b(Y)], ψ1 = c(c² − (d+2)/2), ψ2 = c(ŵ² − d_r/2), ŵ² = w²/τ (theory.md (19.15)).
double heat_pair(const Particle& x, int a, const Particle& y, int b, int d, double tau, const ConditionedGaussian& g) {
  const int dr = d == 3 ? 3 : 1;
  const double ca = a == 1 ? (d + 2) / 2.0 : dr / 2.0, cb = b == 1 ? (d + 2) / 2.0 : dr / 2.0;
  const double sa = a == 1 ? 1 : 1 / tau, sb = b == 1 ? 1 : 1 / tau;
  const int la = a == 1 ? d : dr, lb = b == 1 ? d : dr;
  const auto sq = [&](const Particle& p, int kind, int l, int& index, double& mean) {
    index = kind == 1 ? p.v + l : p.w + l;
    mean = kind == 1 ? p.v_mean[static_cast<std::size_t>(l)] : p.w_mean[static_cast<std::size_t>(l)];
  };
  double total = 0;
  for (int k = 0; k < d; ++k) {
    const int xk = x.v + k, yk = y.v + k;
    const double mxk = x.v_mean[static_cast<std::size_t>(k)], myk = y.v_mean[static_cast<std::size_t>(k)];
    {
      const int idx[2] = {xk, yk};
      const double mu[2] = {mxk, myk};
      total += ca * cb * gaussian_moment(idx, mu, 2, g);
    }
    for (int l = 0; l < la; ++l) {
      int i = 0;
      double m = 0;
      sq(x, a, l, i, m);
      const int idx[4] = {xk, yk, i, i};
      const double mu[4] = {mxk, myk, m, m};
      total -= cb * sa * gaussian_moment(idx, mu, 4, g);
    }
    for (int l = 0; l < lb; ++l) {
      int i = 0;
      double m = 0;
      sq(y, b, l, i, m);
      const int idx[4] = {xk, yk, i, i};
      const double mu[4] = {mxk, myk, m, m};
      total -= ca * sb * gaussian_moment(idx, mu, 4, g);
    }
    for (int l = 0; l < la; ++l)
      for (int q = 0; q < lb; ++q) {
        int i = 0, j = 0;
        double mi = 0, mj = 0;
        sq(x, a, l, i, mi);
        sq(y, b, q, j, mj);
        const int idx[6] = {xk, yk, i, i, j, j};
        const double mu[6] = {mxk, myk, mi, mi, mj, mj};
        total += sa * sb * gaussian_moment(idx, mu, 6, g);
      }
  }
  return total;
}

}  // namespace

RoughHeatOperator rough_walton_heat_operator(int dimension, double alpha, double beta0, double kappa, double friction,
                                             double temperature_ratio, int panels) {
  detail::check_walton_parameters(dimension, alpha, beta0, kappa, friction);
  if (!(temperature_ratio > 0)) throw std::invalid_argument("temperature_ratio: must be > 0");
  if (panels < 1) throw std::invalid_argument("panels: must be >= 1");
  const int d = dimension, dr = d == 3 ? 3 : 1;
  const double tau = temperature_ratio / kappa, s = std::sqrt(1 + tau), eta_n = (1 + alpha) / 2;
  const double eta0 = (1 + beta0) * kappa / (2 * (1 + kappa));
  const double m = std::isinf(friction) ? friction : friction * (1 + alpha) / 2;
  const double c = std::isinf(m) ? 0 : (m == 0 ? std::numeric_limits<double>::infinity() : eta0 / m);
  const ConditionedGaussian g = condition(d, tau);
  const auto integrand = [&](double u, double big_g) {
    const double eta_t = (big_g == 0 || u >= c * big_g) ? eta0 : m * u / big_g;
    const auto mean = [&](int i) {
      return g.gain[static_cast<std::size_t>(i)][0] * u + g.gain[static_cast<std::size_t>(i)][1] * big_g;
    };
    Particle p1{0, 2 * d, {}, {}}, p2{d, 2 * d + dr, {}, {}};
    for (int k = 0; k < d; ++k) {
      p1.v_mean[static_cast<std::size_t>(k)] = mean(k);
      p2.v_mean[static_cast<std::size_t>(k)] = mean(d + k);
    }
    for (int k = 0; k < dr; ++k) {
      p1.w_mean[static_cast<std::size_t>(k)] = mean(2 * d + k);
      p2.w_mean[static_cast<std::size_t>(k)] = mean(2 * d + dr + k);
    }
    // 1': v1 − η_n u σ̂ − η_t g_c,t and w1 − (η_t/κ) σ̂ × g_c,t (σ̂ × G e1 = G e2 for spheres; disks: the scalar).
    Particle post = p1;
    post.v_mean[0] -= eta_n * u;
    post.v_mean[1] -= eta_t * big_g;
    post.w_mean[d == 3 ? 2 : 0] -= eta_t / kappa * big_g;
    std::array<double, 4> l{};
    for (int i = 1; i <= 2; ++i)
      for (int j = 1; j <= 2; ++j)
        l[static_cast<std::size_t>(2 * (i - 1) + (j - 1))] =
            heat_pair(p1, j, p1, i, d, tau, g) - heat_pair(p1, j, post, i, d, tau, g) +
            heat_pair(p2, j, p1, i, d, tau, g) - heat_pair(p2, j, post, i, d, tau, g);
    return l;
  };
  const double upper = 12;
  const auto over_u = [&](double big_g) {
    const auto f = [&](double u) {
      std::array<double, 4> v = integrand(u, big_g);
      for (auto& x : v) x *= u * std::exp(-u * u / 2);
      return v;
    };
    const double kink = big_g > 0 ? std::min(c * big_g, upper) : 0.0;
    std::array<double, 4> v = gauss_legendre<4>(0, kink, panels, f);
    const std::array<double, 4> rest = gauss_legendre<4>(kink, upper, panels, f);
    for (std::size_t k = 0; k < 4; ++k) v[k] += rest[k];
    return v;
  };
  const auto outer = [&](double r) {
    const double density = (d == 3 ? r : std::sqrt(2 / std::numbers::pi)) * std::exp(-r * r / 2);
    std::array<double, 4> v = over_u(s * r);
    for (auto& x : v) x *= density;
    return v;
  };
  // The kink u = cG leaves the u-range at r = upper/(cs): a panel edge there too.
  const double edge = c > 0 && std::isfinite(c) ? std::min(upper / (c * s), upper) : upper;
  const std::array<double, 4> a = gauss_legendre<4>(0, edge, panels, outer),
                              b = gauss_legendre<4>(edge, upper, panels, outer);
  return RoughHeatOperator{{{a[0] + b[0], a[1] + b[1]}, {a[2] + b[2], a[3] + b[3]}}};
}

RoughThermalConductivity rough_walton_thermal_conductivity(int dimension, double alpha, double beta0, double kappa,
                                                           double friction, double temperature_ratio, int panels) {
  const RoughHeatOperator l =
      rough_walton_heat_operator(dimension, alpha, beta0, kappa, friction, temperature_ratio, panels);
  const double zeta = rough_walton_rates(dimension, alpha, beta0, kappa, friction, temperature_ratio).translational;
  return rough_heat_flux_response(dimension, l, temperature_ratio, zeta);
}

double rough_walton_shear_viscosity(int dimension, double alpha, double beta0, double kappa, double friction,
                                    double temperature_ratio, int intervals) {
  detail::check_walton_parameters(dimension, alpha, beta0, kappa, friction);
  if (!(temperature_ratio > 0)) throw std::invalid_argument("temperature_ratio: must be > 0");
  if (intervals < 2 || intervals % 2 != 0) throw std::invalid_argument("intervals: must be even and >= 2");
  const int d = dimension;
  const double tau = temperature_ratio / kappa, s = std::sqrt(1 + tau), eta_n = (1 + alpha) / 2;
  const double eta0 = (1 + beta0) * kappa / (2 * (1 + kappa));
  const double m = std::isinf(friction) ? friction : friction * (1 + alpha) / 2;
  const double c = std::isinf(m) ? 0 : (m == 0 ? std::numeric_limits<double>::infinity() : eta0 / m);
  const ConditionedGaussian g = condition(d, tau);
  // The conditional L_η integrand at (u, G) with η_t fixed.
  const auto integrand = [&](double u, double big_g) {
    const double eta_t = (big_g == 0 || u >= c * big_g) ? eta0 : m * u / big_g;  // G = 0: head-on, sticking
    std::array<double, 3> c1{}, c2{}, c1p{};
    for (int k = 0; k < d; ++k) {
      c1[k] = g.gain[k][0] * u + g.gain[k][1] * big_g;
      c2[k] = g.gain[d + k][0] * u + g.gain[d + k][1] * big_g;
      c1p[k] = c1[k] - (k == 0 ? eta_n * u : 0) - (k == 1 ? eta_t * big_g : 0);
    }
    return y2_pair(d, c1, 0, c1, 0, g) + y2_pair(d, c2, d, c1, 0, g) - y2_pair(d, c1, 0, c1p, 0, g) -
           y2_pair(d, c2, d, c1p, 0, g);
  };
  const auto simpson = [&](double lo, double hi, const auto& f) {
    if (!(hi > lo)) return 0.0;
    const double h = (hi - lo) / intervals;
    double sum = 0;
    for (int k = 0; k <= intervals; ++k) {
      const double w = (k == 0 || k == intervals) ? 1 : (k % 2 == 1 ? 4 : 2);
      sum += w * f(lo + k * h);
    }
    return sum * h / 3;
  };
  const double upper = 12;
  const auto over_u = [&](double big_g) {
    const auto f = [&](double u) { return u * std::exp(-u * u / 2) * integrand(u, big_g); };
    const double kink = big_g > 0 ? std::min(c * big_g, upper) : 0.0;
    return simpson(0, kink, f) + simpson(kink, upper, f);
  };
  const auto outer = [&](double r) {
    const double density = (d == 3 ? r : std::sqrt(2 / std::numbers::pi)) * std::exp(-r * r / 2);
    return density * over_u(s * r);
  };
  // The kink u = cG leaves the u-range at r = upper/(cs): a panel edge there too.
  const double edge = c > 0 && std::isfinite(c) ? std::min(upper / (c * s), upper) : upper;
  const double l_eta = simpson(0, edge, outer) + simpson(edge, upper, outer);
  const double zeta = rough_walton_rates(d, alpha, beta0, kappa, friction, temperature_ratio).translational;
  return 1 / (l_eta / (d - 1) - zeta / 2);  // theory.md (19.13)
}

RoughWaltonRates rough_walton_rates(int dimension, double alpha, double beta0, double kappa, double friction,
                                    double temperature_ratio, int intervals) {
  detail::check_walton_parameters(dimension, alpha, beta0, kappa, friction);
  if (!(temperature_ratio > 0)) throw std::invalid_argument("temperature_ratio: must be > 0");
  if (intervals < 2 || intervals % 2 != 0) throw std::invalid_argument("intervals: must be even and >= 2");
  const int d = dimension;
  const double dr = d == 3 ? 3.0 : 1.0, g = (d + 2.0) / 4.0;  // g: ν of (5.3) → ν0
  const double tau = temperature_ratio / kappa, eta0 = (1 + beta0) * kappa / (2 * (1 + kappa));
  const double m = std::isinf(friction) ? friction : friction * (1 + alpha) / 2;
  const Averages a = averages(d, eta0, m, std::sqrt(1 + tau), intervals);
  // ⟨Δc1²⟩ = −(1−α²)/2 − A1/(1+τ) + A2 and ⟨Δw1²⟩ = −(τ/κ)A1/(1+τ) + A2/κ² (theory.md (19.22);
  // constant η_t gives (19.7)–(19.8)); ζ_t/ν = −(2/d)⟨Δc1²⟩, ζ_r/ν = −(2/(d_rτ))⟨Δw1²⟩.
  const double dv = -(1 - alpha * alpha) / 2 - a.a1 / (1 + tau) + a.a2;
  const double dw = -(tau / kappa) * a.a1 / (1 + tau) + a.a2 / (kappa * kappa);
  return {-g * 2.0 / d * dv, -g * 2.0 / (dr * tau) * dw};
}

double rough_walton_temperature_ratio(int dimension, double alpha, double beta0, double kappa, double friction) {
  detail::check_walton_parameters(dimension, alpha, beta0, kappa, friction);
  const double none = std::numeric_limits<double>::infinity();
  if (friction == 0 || beta0 == -1) return none;
  const auto residual = [&](double log_theta) {
    const RoughWaltonRates r = rough_walton_rates(dimension, alpha, beta0, kappa, friction, std::exp(log_theta));
    return r.translational - r.rotational;
  };
  // ζ_t − ζ_r > 0 as θ → 0 (the cold spin is heated); take the first sign change upwards in log θ.
  double lo = -20, f_lo = residual(lo), hi = lo;
  bool found = false;
  for (double x = lo + 0.25; x <= 20; x += 0.25) {
    const double f = residual(x);
    if ((f_lo > 0) != (f > 0)) {
      hi = x;
      found = true;
      break;
    }
    lo = x;
    f_lo = f;
  }
  if (!found) return none;
  while (hi - lo > 1e-13) {
    const double mid = (lo + hi) / 2, f = residual(mid);
    if ((f > 0) == (f_lo > 0)) {
      lo = mid;
      f_lo = f;
    } else {
      hi = mid;
    }
  }
  return std::exp((lo + hi) / 2);
}

RoughWaltonState rough_walton_cooling_state(int dimension, const Rational& alpha, const Rational& beta0,
                                            const Rational& kappa, const Rational& friction) {
  const double a = alpha.to_double(), b = beta0.to_double(), k = kappa.to_double(), mu = friction.to_double();
  detail::check_walton_parameters(dimension, a, b, k, mu);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  RoughWaltonState out;
  const auto decoupled = [&]() {
    out.temperature_ratio = std::numeric_limits<double>::infinity();
    out.cooling_rate = out.bulk_viscosity = out.cooling_rate_first_order = out.shear_viscosity = nan;
    out.thermal_conductivity = out.density_heat_coefficient = nan;
    out.spin_decoupled = true;
    return out;
  };
  const double theta = rough_walton_temperature_ratio(dimension, a, b, k, mu);
  if (std::isinf(theta)) return decoupled();
  const RoughWaltonRates r = rough_walton_rates(dimension, a, b, k, mu, theta);
  out.temperature_ratio = theta;
  out.cooling_rate = r.translational;
  // Slopes θ∂ζ/∂θ = ∂ζ/∂ln θ by central differences in ln θ.
  const double h = 1e-4;
  const RoughWaltonRates up = rough_walton_rates(dimension, a, b, k, mu, theta * std::exp(h));
  const RoughWaltonRates down = rough_walton_rates(dimension, a, b, k, mu, theta * std::exp(-h));
  const RoughScalarResponse s =
      rough_scalar_response(dimension, theta, r.translational, (up.translational - down.translational) / (2 * h),
                            (up.rotational - down.rotational) / (2 * h));
  out.bulk_viscosity = s.bulk_viscosity;
  out.cooling_rate_first_order = s.cooling_rate_first_order;
  out.shear_viscosity = rough_walton_shear_viscosity(dimension, a, b, k, mu, theta);
  const RoughThermalConductivity heat = rough_walton_thermal_conductivity(dimension, a, b, k, mu, theta);
  out.thermal_conductivity = heat.total;
  out.density_heat_coefficient = heat.density_heat_total;
  return out;
}

}  // namespace gkt
