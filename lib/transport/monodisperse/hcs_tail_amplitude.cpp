// The HCS tail amplitude 𝒜 of φ ~ 𝒜 c^γ e^{−A c} (hcs_tail_amplitude.hpp; docs/theory.md §10.7).
//
// The HCS equation (ζ_r/2) ∂_c·(c φ) = G − ν φ, written for R = φ/(c^γ e^{−A c}) with A = 2β/ζ_r, is
// d ln R/dc = H(c) = [G/φ − (ν − β c) − (ζ_r/2)(d + γ)]/((ζ_r/2) c)   (theory.md (10.16)),
// exact, and H = O(c^{−2}). So 𝒜 = R(c_m) exp ∫_{c_m}^∞ H: R(c_m) from the tail scheme's φ_N where it is
// converged, and H from the collision integrals of φ̃ = φ_N (c ≤ c_m), continued for c > c_m by
// R(c_m) c^γ e^{−A c} exp ∫_{c_m}^c H (a fixed point, iterated from H = 0). In t = 1/c, ∫ H dc = ∫ K dt
// with K = H/t² finite at t = 0, done by a Chebyshev interpolant on [0, 1/c_m].
#include "gkt/transport/monodisperse/hcs_tail_amplitude.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "gkt/transport/monodisperse/tail_galerkin.hpp"

namespace gkt {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kPartnerSpeed = 6;       // the loss: partners up to this speed (weight below e^{−30} beyond)
constexpr double kNegligible = 37;        // the gain: partners with φ(u)/φ(c) below e^{−37} are dropped
constexpr double kMatchTolerance = 1e-3;  // φ_N, φ_{N−1} agree to this where c_m may lie
constexpr int kChebyshevNodes = 16;       // nodes of K(t) on [0, 1/c_m]
constexpr int kFixedPointPasses = 12;     // at most; stop when ∫_{c_m}^∞ H changes by less than:
constexpr double kFixedPointTolerance = 1e-6;

/// β = π^{(d−1)/2}/Γ((d+1)/2): the loss rate of a fast particle is β c ([vannoije1998]).
double loss_rate_factor(int d) { return std::pow(kPi, (d - 1) / 2.0) / std::tgamma((d + 1) / 2.0); }

/// ν = √2 π^{(d−1)/2}/Γ(d/2) of theory.md (9.4): ζ* = (d + 2) ζ_r/(4ν).
double frequency_factor(int d) { return std::sqrt(2.0) * std::pow(kPi, (d - 1) / 2.0) / std::tgamma(d / 2.0); }

struct Rule {
  std::vector<double> x, w;  // Gauss–Legendre on [0, 1]
};

Rule gauss_legendre(int n) {
  Rule r;
  for (int i = 0; i < n; ++i) {
    double z = std::cos(kPi * (i + 0.75) / (n + 0.5)), dp = 1;
    for (int it = 0; it < 100; ++it) {
      double p1 = 1, p2 = 0;
      for (int j = 0; j < n; ++j) {
        const double p3 = p2;
        p2 = p1;
        p1 = ((2 * j + 1) * z * p2 - j * p3) / (j + 1);
      }
      dp = n * (z * p1 - p2) / (z * z - 1);
      const double step = p1 / dp;
      z -= step;
      if (std::fabs(step) < 1e-16) break;
    }
    r.x.push_back(0.5 * (1 - z));
    r.w.push_back(1.0 / ((1 - z * z) * dp * dp));
  }
  return r;
}

/// Panels on [lo, hi] graded geometrically toward both ends from the width `finest` (the grazing ends,
/// where the gain integrand peaks), at most half the interval each.
std::vector<double> graded_edges(double lo, double hi, double finest) {
  const double mid = 0.5 * (lo + hi);
  std::vector<double> left{lo}, right{hi};
  for (double w = finest; lo + w < mid; w *= 2) {
    left.push_back(lo + w);
    right.push_back(hi - w);
  }
  left.push_back(mid);
  left.insert(left.end(), right.rbegin(), right.rend());
  return left;
}

}  // namespace

BoltzmannGainLoss boltzmann_gain_loss(int dimension, double alpha, double c,
                                      const std::function<double(double)>& log_phi) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
  if (!(alpha > 0 && alpha < 1))
    throw std::invalid_argument("alpha: must be a number in (0, 1), got " + std::to_string(alpha));
  if (!(c > 0 && std::isfinite(c)))
    throw std::invalid_argument("speed: must be a finite number > 0, got " + std::to_string(c));
  static const Rule u_rule = gauss_legendre(8), theta_rule = gauss_legendre(32), psi_rule = gauss_legendre(12),
                    chi_rule = gauss_legendre(8);
  const double lambda = (1 + alpha) / (1 - alpha), log_phi_c = log_phi(c), beta = loss_rate_factor(dimension);
  // Width of the grazing peak in h = (v − v2)·σ̂: the fast pre-collision speed is c + λ(2 + λ)h²/(2c) + …,
  // so h ~ √(c/(λ(2 + λ))) (A ≳ 1); its angle, h/c, sets the finest panel.
  const double finest = std::min(0.05, 0.1 / std::sqrt(c * lambda * (2 + lambda)));
  BoltzmannGainLoss out;
  // Partners up to kPartnerSpeed, and beyond while φ(u)/φ(c) > e^{−kNegligible}: a fast partner (speed ≈ 2c/(1 + α))
  // that stops on a slow particle also feeds the gain at c (the loss then needs only u ≤ kPartnerSpeed).
  // A slow particle (speed ≤ kPartnerSpeed) reaches c only from a partner faster than 2(c − 6)/(1 + α) − 6.
  const int far_start = std::max(static_cast<int>(kPartnerSpeed), static_cast<int>(2 * (c - 6) / (1 + alpha)) - 7);
  // Unit panels in u, the one holding c split at u = c (the loss and gain kernels are not smooth there).
  std::vector<std::pair<double, double>> panels;
  for (int panel = 0; panel < static_cast<int>(kPartnerSpeed) || log_phi(panel) - log_phi_c > -kNegligible;
       panel = panel + 1 == static_cast<int>(kPartnerSpeed) ? far_start : panel + 1) {
    if (panel < c && c < panel + 1) {
      panels.emplace_back(panel, c);
      panels.emplace_back(c, panel + 1);
    } else {
      panels.emplace_back(panel, panel + 1);
    }
  }
  for (const auto& [from, to] : panels)
    for (std::size_t iu = 0; iu < u_rule.x.size(); ++iu) {
      const double u = from + u_rule.x[iu] * (to - from), wu = u_rule.w[iu] * (to - from);
      const bool near = to <= kPartnerSpeed;
      const double log_partner = log_phi(u), partner = std::exp(log_partner);  // for the loss (u ≤ 6)
      if (!near && log_partner - log_phi_c < -kNegligible) continue;
      if (near) {
        // Loss: β ∫ φ(v2)|v − v2|; 3D: ∫dμ |v − v2| = ((c + u)³ − |c − u|³)/(3cu); 2D: ∫_0^π |v − v2| dθ =
        // 2(c + u) E(2√(cu)/(c + u)), E the complete elliptic integral of the second kind.
        const double mean = dimension == 3 ? (std::pow(c + u, 3) - std::pow(std::fabs(c - u), 3)) / (3 * c * u)
                                           : 2 * (c + u) * std::comp_ellint_2(2 * std::sqrt(c * u) / (c + u));
        const double shell = dimension == 3 ? 4 * kPi * u * u : 2 * kPi * u;
        out.loss += beta * shell * wu * partner * mean / (dimension == 3 ? 2.0 : kPi);
        out.partner_mass += shell * wu * partner;
      }
      // Gain over the pre-collision partner v2 = u(cos θ, sin θ, 0) and σ̂ (theory.md (10.18)):
      // G(v) = ∫d v2 φ(v2) ∫dσ̂ Θ(h) 4h/(1 − α)² φ(v + λ h σ̂), h = (v − v2)·σ̂, v = c x̂. σ̂ is measured from
      // ĝ = (v − v2)/|v − v2|: σ̂ = cos χ ĝ + sin χ (cos ψ e1 + sin ψ e2), so h = |v − v2| cos χ > 0 on
      // χ < π/2 for every ψ; the fast particle's grazing peak is at χ → π/2, a fast partner stopping on a slow
      // particle at χ → 0: the χ panels are graded toward both ends.
      double gain = 0;
      const auto edges = graded_edges(0, kPi / 2, finest);
      for (std::size_t it = 0; it < theta_rule.x.size(); ++it) {
        const double th = kPi * theta_rule.x[it], wt = kPi * theta_rule.w[it];
        const double gx = c - u * std::cos(th), gy = -u * std::sin(th), g = std::hypot(gx, gy);
        if (!(g > 0)) continue;
        const double hx = gx / g, hy = gy / g;  // ĝ; e1 = (−ĝ_y, ĝ_x, 0), e2 = ẑ
        // v·ĝ, v·e1 with v = c x̂.
        const double v_par = c * hx, v_perp = -c * hy;
        auto integrand = [&](double chi, double cos_psi) {
          const double h = g * std::cos(chi);
          const double v_sigma = std::cos(chi) * v_par + std::sin(chi) * cos_psi * v_perp;  // v·σ̂
          const double speed2 = c * c + 2 * lambda * h * v_sigma + lambda * lambda * h * h;
          return 4 * h / ((1 - alpha) * (1 - alpha)) *
                 std::exp(log_partner + log_phi(std::sqrt(std::max(0.0, speed2))) - log_phi_c);
        };
        double theta_sum = 0;
        for (std::size_t e = 0; e + 1 < edges.size(); ++e)
          for (std::size_t k = 0; k < chi_rule.x.size(); ++k) {
            const double chi = edges[e] + chi_rule.x[k] * (edges[e + 1] - edges[e]);
            const double w_chi = chi_rule.w[k] * (edges[e + 1] - edges[e]);
            if (dimension == 2) {
              theta_sum += w_chi * (integrand(chi, 1.0) + integrand(chi, -1.0));  // σ̂ on either side of ĝ
            } else {
              double psi_sum = 0;  // ψ ∈ (0, 2π): twice (0, π) by the reflection z → −z
              for (std::size_t ip = 0; ip < psi_rule.x.size(); ++ip)
                psi_sum += 2 * kPi * psi_rule.w[ip] * integrand(chi, std::cos(kPi * psi_rule.x[ip]));
              theta_sum += w_chi * std::sin(chi) * psi_sum;
            }
          }
        gain += (dimension == 3 ? 2 * kPi * u * u * std::sin(th) : 2 * u) * wu * wt * theta_sum;
      }
      out.gain_ratio += gain;
    }
  return out;
}

namespace {

/// ln φ on [0, c_m] from the profile's nodes (local 8-point Lagrange in c of ln φ), tabulated.
struct CoreLog {
  std::vector<double> c, v;
  [[nodiscard]] double operator()(double x) const {
    const auto it = std::lower_bound(c.begin(), c.end(), x);
    const auto n = static_cast<std::ptrdiff_t>(c.size());
    std::ptrdiff_t i0 = std::clamp<std::ptrdiff_t>((it - c.begin()) - 4, 0, n - 8);
    double sum = 0;
    for (std::ptrdiff_t i = i0; i < i0 + 8; ++i) {
      double l = 1;
      for (std::ptrdiff_t j = i0; j < i0 + 8; ++j)
        if (j != i)
          l *= (x - c[static_cast<std::size_t>(j)]) / (c[static_cast<std::size_t>(i)] - c[static_cast<std::size_t>(j)]);
      sum += l * v[static_cast<std::size_t>(i)];
    }
    return sum;
  }
};

/// A smooth function tabulated on a uniform grid of [lo, hi], evaluated by 4-point Lagrange interpolation.
struct UniformTable {
  double lo = 0, step = 1;
  std::vector<double> v;
  template <class F>
  UniformTable(double from, double to, int intervals, const F& f) : lo(from), step((to - from) / intervals) {
    for (int i = 0; i <= intervals; ++i) v.push_back(f(from + i * step));
  }
  [[nodiscard]] double operator()(double x) const {
    const double u = (x - lo) / step;
    const auto last = static_cast<std::ptrdiff_t>(v.size()) - 4;
    const std::ptrdiff_t i = std::clamp<std::ptrdiff_t>(static_cast<std::ptrdiff_t>(u) - 1, 0, last);
    const double s = u - static_cast<double>(i);
    const double* y = &v[static_cast<std::size_t>(i)];
    return -y[0] * (s - 1) * (s - 2) * (s - 3) / 6 + y[1] * s * (s - 2) * (s - 3) / 2 -
           y[2] * s * (s - 1) * (s - 3) / 2 + y[3] * s * (s - 1) * (s - 2) / 6;
  }
};

/// A function on [0, T] from its values at the Chebyshev points t_j = T(1 + cos(π(j + ½)/n))/2, with its
/// integral from t to T.
struct Chebyshev {
  double span = 1;
  std::vector<double> coef;  // f ≈ Σ a_k T_k(2t/T − 1)
  static std::vector<double> nodes(double span, int n) {
    std::vector<double> t(static_cast<std::size_t>(n));
    for (int j = 0; j < n; ++j) t[static_cast<std::size_t>(j)] = 0.5 * span * (1 + std::cos(kPi * (j + 0.5) / n));
    return t;
  }
  Chebyshev(double t_span, const std::vector<double>& values) : span(t_span) {
    const auto n = values.size();
    coef.assign(n, 0.0);
    for (std::size_t k = 0; k < n; ++k) {
      for (std::size_t j = 0; j < n; ++j)
        coef[k] += values[j] *
                   std::cos(kPi * static_cast<double>(k) * (static_cast<double>(j) + 0.5) / static_cast<double>(n));
      coef[k] *= (k == 0 ? 1.0 : 2.0) / static_cast<double>(n);
    }
  }
  [[nodiscard]] double operator()(double t) const {
    const double x = 2 * t / span - 1;
    double sum = 0;
    for (std::size_t k = 0; k < coef.size(); ++k) sum += coef[k] * std::cos(static_cast<double>(k) * std::acos(x));
    return sum;
  }
  /// ∫_t^T f: ∫ T_k dx = (T_{k+1}/(k+1) − T_{k−1}/(k−1))/2 (k ≥ 2), T_1 (k = 0), T_2/4 (k = 1).
  [[nodiscard]] double integral_from(double t) const {
    auto antiderivative = [&](double x) {
      const double th = std::acos(std::clamp(x, -1.0, 1.0));
      double sum = 0;
      for (std::size_t k = 0; k < coef.size(); ++k) {
        const double kd = static_cast<double>(k);
        double v = 0;
        if (k == 0)
          v = x;
        else if (k == 1)
          v = 0.5 * x * x;
        else
          v = 0.5 * (std::cos((kd + 1) * th) / (kd + 1) - std::cos((kd - 1) * th) / (kd - 1));
        sum += coef[k] * v;
      }
      return sum;
    };
    return 0.5 * span * (antiderivative(1.0) - antiderivative(2 * t / span - 1));
  }
};

/// 𝒜 from one profile and matching speed c_m, and K(0) = −b_1.
HcsTailMatch match_at(int d, double alpha, const TailHcsProfile& p, double gamma, double c_m, double* k0) {
  const double zeta_r = 4 * frequency_factor(d) * p.values.cooling_rate / (d + 2), mu = zeta_r / 2;
  const double A = p.values.tail_exponent, beta = loss_rate_factor(d);
  CoreLog core;
  for (std::size_t i = 0; i < p.speed.size() && p.distribution[i] > 0 && (i < 8 || p.speed[i - 8] <= c_m + 1); ++i) {
    core.c.push_back(p.speed[i]);
    core.v.push_back(std::log(p.distribution[i]));
  }
  const UniformTable core_table(0, c_m, std::max(64, static_cast<int>(500 * c_m)), core);
  const double log_phi_m = core(c_m), span = 1 / c_m;
  const auto t = Chebyshev::nodes(span, kChebyshevNodes);
  Chebyshev k_of_t(span, std::vector<double>(t.size(), 0.0));
  bool settled = false;
  for (int pass = 0; pass < kFixedPointPasses; ++pass) {
    // ∫_{c_m}^x H = ∫_{1/x}^{1/c_m} K dt, tabulated in t.
    const UniformTable continuation(0, span, 4096, [&](double tt) { return k_of_t.integral_from(tt); });
    auto log_phi = [&](double x) {
      if (x <= c_m) return core_table(x);
      return log_phi_m + gamma * std::log(x / c_m) - A * (x - c_m) + continuation(1 / x);
    };
    std::vector<double> k(t.size());
    for (std::size_t j = 0; j < t.size(); ++j) {
      const double c = 1 / t[j];
      const auto gl = boltzmann_gain_loss(d, alpha, c, log_phi);
      // Normalised by the partners' mass on the rule: ν − βc is O(1/c) only for ∫φ = 1, and a mass off by ε
      // would add β c² ε/μ to K (measured: K ≈ 10 at c = 1000 without this).
      k[j] = (gl.gain_ratio / gl.partner_mass - (gl.loss / gl.partner_mass - beta * c) - mu * (d + gamma)) / (mu * c) *
             c * c;
    }
    const double before = k_of_t.integral_from(0);
    k_of_t = Chebyshev(span, k);
    settled = std::fabs(k_of_t.integral_from(0) - before) < kFixedPointTolerance;
    if (settled || !std::isfinite(k_of_t.integral_from(0))) break;
  }
  *k0 = k_of_t(0);
  HcsTailMatch m;
  m.settled = settled && std::isfinite(k_of_t.integral_from(0));
  m.matching_speed = c_m;
  m.ratio_at_match = std::exp(log_phi_m - gamma * std::log(c_m) + A * c_m);
  m.amplitude = m.ratio_at_match * std::exp(k_of_t.integral_from(0));
  return m;
}

}  // namespace

HcsTailAmplitude hcs_tail_amplitude(int dimension, double alpha, int order) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
  if (!(alpha >= kHcsTailAmplitudeMinAlpha && alpha <= kHcsTailAmplitudeMaxAlpha))
    throw std::invalid_argument(
        "alpha: must be a number in [0.05, 0.7] for the tail amplitude, where it was measured to work (above, the "
        "tail scheme's HCS is converged only inside the Gaussian core; alpha = 1 has no exponential tail), got " +
        std::to_string(alpha));
  if (order < 3 || order > kTailGalerkinMaxOrder)
    throw std::invalid_argument("order: must be an integer in [3, " + std::to_string(kTailGalerkinMaxOrder) +
                                "] for the tail amplitude, got " + std::to_string(order));
  const auto profiles = tail_galerkin_hcs_profiles(dimension, alpha, order, TailTrialSpace::power_law);
  const auto& now = profiles[static_cast<std::size_t>(order - 1)];
  const auto& before = profiles[static_cast<std::size_t>(order - 2)];
  if (!now.values.solved || !before.values.solved)
    throw std::runtime_error("hcs_tail_amplitude: the tail scheme found no HCS at resolution " + std::to_string(order));
  HcsTailAmplitude out;
  out.order = order;
  out.exponent = now.values.tail_exponent;
  out.power = hcs_tail_power(dimension, alpha);
  // Matching speeds: where φ_N and φ_{N−1} agree to kMatchTolerance, the last third of that range.
  double converged = 0;
  for (std::size_t i = 0; i < now.speed.size(); ++i) {
    if (!(std::fabs(now.distribution[i] / before.distribution[i] - 1) <= kMatchTolerance)) break;
    converged = now.speed[i];
  }
  const std::vector<double> speeds{std::max(1.0, 2 * converged / 3), std::max(1.0, 5 * converged / 6),
                                   std::max(1.0, converged)};
  for (const double c_m : speeds) {
    double k_now = 0, k_before = 0;
    out.matches.push_back(match_at(dimension, alpha, now, out.power, c_m, &k_now));
    out.previous_matches.push_back(match_at(dimension, alpha, before, out.power, c_m, &k_before));
    if (c_m == speeds[1]) out.first_correction = -k_now;
  }
  // Matching deep in the Gaussian core (c_m ≪ A/2: 2D α = 0.9, A = 16.9, c_m ≤ 4) the continuation must build the
  // whole crossover and the fixed point diverges: no amplitude then (theory.md §10.7).
  for (std::size_t i = 0; i < speeds.size(); ++i)
    if (!out.matches[i].settled || !out.previous_matches[i].settled)
      throw std::runtime_error("hcs_tail_amplitude: the continuation from c_m = " + std::to_string(speeds[i]) +
                               " did not settle (the tail scheme's HCS is converged only far inside the Gaussian "
                               "core, A/2 = " +
                               std::to_string(out.exponent / 2) + "); raise the resolution");
  // The value from the middle matching speed at N; the error the largest distance of the other five from it.
  out.amplitude = out.matches[1].amplitude;
  for (std::size_t i = 0; i < speeds.size(); ++i)
    out.error = std::max({out.error, std::fabs(out.matches[i].amplitude - out.amplitude),
                          std::fabs(out.previous_matches[i].amplitude - out.amplitude)});
  return out;
}

}  // namespace gkt
