#include "gkt/transport/mixture/mixture_cooling_state.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "algebra/nearby_rational.hpp"
#include "gkt/algebra/sonine.hpp"
#include "gkt/collision/collision_moments.hpp"

namespace gkt {

namespace {

/// Λ = (d+2)√2/8: ζ_i* = −(2/d) Λ W_i, W_i = Σ_j c_ij ⟨X1' − X1⟩_ij (theory.md (16.4)–(16.5)).
double lambda(int d) { return (d + 2) * std::sqrt(2.0) / 8.0; }

/// Returns θ_i = m_i/(m̄ γ_i), the Maxwellian width in units of √(2T/m̄).
double theta(const Mixture& m, std::size_t i, double gamma) {
  return m.species[i].mass.value() / (m.mean_mass() * gamma);
}

/// c_ij = x_j χ_ij (σ_ij/σ̄)^{d−1} √(1/θ_i + 1/θ_j).
double pair_weight(const Mixture& m, std::span<const double> chi, std::size_t i, std::size_t j, double theta_i,
                   double theta_j) {
  const double sigma_ij = 0.5 * (m.species[i].diameter + m.species[j].diameter) / m.mean_diameter();
  return m.species[j].fraction * chi[i * m.size() + j] * std::pow(sigma_ij, m.dimension - 1) *
         std::sqrt(1 / theta_i + 1 / theta_j);
}

/// Solves ζ_1 = … = ζ_s (rates from `rates_at`) for the ratios by nonlinear Gauss–Seidel on
/// u_i = ln(γ_i/γ_s), starting from `gamma`; returns the sweeps used and leaves Σ x_i γ_i = 1.
int solve_equal_rates(const Mixture& mixture, std::vector<double>& gamma,
                      const std::function<void(std::span<const double>, std::span<double>)>& rates_at) {
  const std::size_t s = mixture.size();
  std::vector<double> u(s), g(s), rates(s);
  for (std::size_t i = 0; i < s; ++i) u[i] = std::log(gamma[i] / gamma[s - 1]);
  auto evaluate = [&] {
    for (std::size_t i = 0; i < s; ++i) g[i] = std::exp(u[i]);
    rates_at(g, rates);
  };
  auto h = [&](std::size_t i, double t) {
    u[i] = t;
    evaluate();
    return rates[i] - rates[s - 1];
  };
  evaluate();
  double scale = 0;
  for (const double r : rates) scale = std::max(scale, std::abs(r));
  int sweeps = 0;
  if (scale > 0) {
    for (int sweep = 0; sweep < 500; ++sweep) {
      double change = 0;
      for (std::size_t i = 0; i + 1 < s; ++i) {
        const double start = u[i];
        double lo = start, hi = start, step = 1;
        // h_i increases with u_i (a hotter species cools faster relative to the others).
        while (h(i, lo) > 0 && step < 1e3) lo -= (step *= 2);
        step = 1;
        while (h(i, hi) < 0 && step < 1e3) hi += (step *= 2);
        for (int k = 0; k < 200 && hi - lo > 4e-16 * std::max(1.0, std::abs(lo)); ++k) {
          const double mid = 0.5 * (lo + hi);
          (h(i, mid) < 0 ? lo : hi) = mid;
        }
        u[i] = 0.5 * (lo + hi);
        change = std::max(change, std::abs(u[i] - start));
      }
      sweeps = sweep + 1;
      if (change < 1e-14) break;
    }
  }
  double norm = 0;
  for (std::size_t i = 0; i < s; ++i) norm += mixture.species[i].fraction * std::exp(u[i]);
  for (std::size_t i = 0; i < s; ++i) gamma[i] = std::exp(u[i]) / norm;
  return sweeps;
}

/// Δ^p[k, l] = ⟨(X1'^p − X1^p) S_k(X1) S_l(X2)⟩/J0 for p = 1 … K and k, l = 0 … K (S_1 unused: the
/// cumulant a_1 vanishes), from E(a, b, c) at the pair's widths (theory.md (16.5) at any K).
struct PairCumulantMoments {
  int k_max = 2;
  std::vector<double> values;  // ((p·(K+1) + k)·(K+1) + l)
  [[nodiscard]] double operator()(int p, int k, int l) const {
    return values[(static_cast<std::size_t>(p) * (k_max + 1) + k) * (k_max + 1) + l];
  }
};

PairCumulantMoments pair_cumulant_moments(const Mixture& m, std::size_t i, std::size_t j, double theta_i,
                                          double theta_j, int k_max) {
  const int d = m.dimension;
  // The moments depend on the mass and width ratios only: m_j = θ_j = 1, the exact mass ratio and a
  // short rational for the computed width ratio (theory.md §16.3).
  const CollisionPair pair{d, m.species[i].mass.exact() / m.species[j].mass.exact(), Rational(1),
                           detail::nearby_rational(theta_i / theta_j), Rational(1)};
  const auto e = scalar_collision_moments<Rational>(pair, Rational::from_double(m.restitution(i, j)), k_max);
  const auto sk = sonine_table(sonine_twice_m(d, 0), k_max);
  PairCumulantMoments out{k_max,
                          std::vector<double>(static_cast<std::size_t>((k_max + 1) * (k_max + 1) * (k_max + 1)))};
  for (int p = 1; p <= k_max; ++p)
    for (int k = 0; k <= k_max; ++k)
      for (int l = 0; l <= k_max; ++l) {
        Rational sum(0);
        for (int a = 0; a <= k; ++a)
          for (int b = 0; b <= l; ++b) sum += sk[k][a] * sk[l][b] * (e(a, b, p) - e(a + p, b, 0));
        out.values[(static_cast<std::size_t>(p) * (k_max + 1) + k) * (k_max + 1) + l] = sum.to_double();
      }
  return out;
}

/// M_p = ⟨X^p⟩ = (d/2)_p and overlap[p][k] = ⟨X^p S_k(X)⟩ under the Maxwellian, p, k ≤ K.
struct CumulantOverlaps {
  std::vector<double> moment;
  std::vector<std::vector<double>> overlap;
};

CumulantOverlaps cumulant_overlaps(int d, int k_max) {
  const auto sk = sonine_table(sonine_twice_m(d, 0), k_max);
  const auto size = static_cast<std::size_t>(k_max) + 1;
  CumulantOverlaps out{std::vector<double>(size), std::vector<std::vector<double>>(size, std::vector<double>(size))};
  for (std::size_t p = 0; p < size; ++p) {
    std::vector<Rational> xp(p + 1, Rational(0));
    xp[p] = Rational(1);
    out.moment[p] = maxwell_average(d, xp).to_double();
    for (std::size_t k = 0; k < size; ++k) {
      std::vector<Rational> product(sk[k].size() + p, Rational(0));
      for (std::size_t a = 0; a < sk[k].size(); ++a) product[a + p] = sk[k][a];
      out.overlap[p][k] = maxwell_average(d, product).to_double();
    }
  }
  return out;
}

}  // namespace

double pair_energy_change(double mu_ji, double alpha, double theta_ratio) {
  // [garzo1999mixture]; derived in theory.md (16.3) and checked against the engine's exact
  // moments E(0,0,1) − E(1,0,0) (tests/test_mixture.cpp).
  return -2 * mu_ji * (1 + alpha) * (1 - 0.5 * mu_ji * (1 + alpha) * (1 + theta_ratio));
}

void species_cooling_rates(const Mixture& mixture, std::span<const double> temperature_ratio,
                           std::span<const double> chi, std::span<double> rates, std::span<const double> correction) {
  const std::size_t s = mixture.size();
  const double prefactor = -2.0 / mixture.dimension * lambda(mixture.dimension);  // (16.4)
  for (std::size_t i = 0; i < s; ++i) {
    const Species& a = mixture.species[i];
    const double theta_i = theta(mixture, i, temperature_ratio[i]);
    double sum = 0;
    for (std::size_t j = 0; j < s; ++j) {
      const double theta_j = theta(mixture, j, temperature_ratio[j]);
      const double mu_ji = mixture.species[j].mass.value() / (a.mass.value() + mixture.species[j].mass.value());
      double change = pair_energy_change(mu_ji, mixture.restitution(i, j), theta_i / theta_j);
      if (!correction.empty()) change += correction[i * s + j];
      sum += pair_weight(mixture, chi, i, j, theta_i, theta_j) * change;
    }
    rates[i] = prefactor * sum;
  }
}

MixtureCoolingState mixture_cooling_state(const Mixture& mixture, MixtureHcsScheme scheme, int sonine_order) {
  mixture.validate();
  if (sonine_order < 2 || sonine_order > 6)
    throw std::invalid_argument("hcs_order: must be an integer in [2, 6], got " + std::to_string(sonine_order));
  const std::size_t s = mixture.size();
  const int d = mixture.dimension;
  MixtureCoolingState out;
  out.chi = mixture.contact_values();
  std::vector<double> gamma(s, 1.0), rates(s), correction;
  auto rates_at = [&](std::span<const double> g, std::span<double> r) {
    species_cooling_rates(mixture, g, out.chi, r, correction);
  };
  out.iterations = solve_equal_rates(mixture, gamma, rates_at);
  out.a2.assign(s, 0.0);
  out.cumulants.assign(s, std::vector<double>(static_cast<std::size_t>(sonine_order) + 1, 0.0));
  for (auto& c : out.cumulants) c[0] = 1;
  bool fixed_point = true;
  if (scheme != MixtureHcsScheme::maxwellian) {
    // Cumulants a_2 … a_K of every species (theory.md §16.3, (16.7a)): for every species and p = 2 … K,
    // p ζ_i(a) ⟨X^p⟩_i(a) + Λ B^p_i(a) = 0, B^p_i = Σ_j c_ij Σ_{k,l} A_ik A_jl Δ^p_ij[k,l] (A_i0 = 1,
    // A_ik = a_k,i), ζ_i = −(2/d) Λ B^1_i, ⟨X^p⟩_i(a) = M_p + Σ_k a_k,i ⟨X^p S_k⟩. The nonlinear scheme
    // keeps every product; the linear one drops the a_k,i a_l,j terms of B and the product
    // (ζ_i − ζ_i^M)(⟨X^p⟩_i − M_p), so that Newton's method is exact in one step. Newton at fixed γ,
    // then γ with the a-terms of ζ_i held, until both stop moving.
    const bool products = scheme == MixtureHcsScheme::nonlinear;
    const int K = sonine_order;
    const auto nk = static_cast<std::size_t>(K - 1);  // a_2 … a_K per species
    const auto n = static_cast<Eigen::Index>(s * nk);
    const double lam = lambda(d);
    const CumulantOverlaps ov = cumulant_overlaps(d, K);
    auto index = [&](std::size_t i, int k) {
      return static_cast<Eigen::Index>(i * nk + static_cast<std::size_t>(k - 2));
    };
    Eigen::VectorXd a = Eigen::VectorXd::Zero(n);
    auto coefficient = [&](std::size_t i, int k) { return k == 0 ? 1.0 : k == 1 ? 0.0 : a(index(i, k)); };
    auto kept = [&](int k, int l) { return k != 1 && l != 1 && (products || k == 0 || l == 0); };
    fixed_point = false;
    for (int outer = 0; outer < 50 && !fixed_point; ++outer) {
      std::vector<PairCumulantMoments> pm(s * s);
      std::vector<double> c(s * s), th(s);
      for (std::size_t i = 0; i < s; ++i) th[i] = theta(mixture, i, gamma[i]);
      for (std::size_t i = 0; i < s; ++i)
        for (std::size_t j = 0; j < s; ++j) {
          pm[i * s + j] = pair_cumulant_moments(mixture, i, j, th[i], th[j], K);
          c[i * s + j] = pair_weight(mixture, out.chi, i, j, th[i], th[j]);
        }
      auto bilinear = [&](std::size_t i, int p, Eigen::VectorXd& gradient) {  // B^p_i and ∂B^p_i/∂a
        gradient.setZero();
        double value = 0;
        for (std::size_t j = 0; j < s; ++j) {
          const PairCumulantMoments& q = pm[i * s + j];
          for (int k = 0; k <= K; ++k)
            for (int l = 0; l <= K; ++l) {
              if (!kept(k, l)) continue;
              const double term = c[i * s + j] * q(p, k, l);
              value += term * coefficient(i, k) * coefficient(j, l);
              if (k >= 2) gradient(index(i, k)) += term * coefficient(j, l);
              if (l >= 2) gradient(index(j, l)) += term * coefficient(i, k);
            }
        }
        return value;
      };
      const Eigen::VectorXd start = a;
      Eigen::VectorXd g1(n), gp(n);
      for (int newton = 0; newton < 50; ++newton) {
        Eigen::VectorXd residual(n);
        Eigen::MatrixXd jacobian(n, n);
        for (std::size_t i = 0; i < s; ++i) {
          const double zeta = -2.0 / d * lam * bilinear(i, 1, g1);
          double zeta_m = 0;  // ζ_i^M: the a-free part
          for (std::size_t j = 0; j < s; ++j) zeta_m += -2.0 / d * lam * c[i * s + j] * pm[i * s + j](1, 0, 0);
          const Eigen::VectorXd dzeta = -2.0 / d * lam * g1;
          for (int p = 2; p <= K; ++p) {
            const auto P = static_cast<std::size_t>(p);
            double xp = ov.moment[P];
            Eigen::VectorXd dxp = Eigen::VectorXd::Zero(n);
            for (int k = 2; k <= p; ++k) {
              xp += coefficient(i, k) * ov.overlap[P][static_cast<std::size_t>(k)];
              dxp(index(i, k)) = ov.overlap[P][static_cast<std::size_t>(k)];
            }
            const double bp = bilinear(i, p, gp);
            const Eigen::Index row = index(i, p);
            // ζ⟨X^p⟩ whole, or ζ^M ⟨X^p⟩ + (ζ − ζ^M) M_p without the product.
            const double zeta_x = products ? zeta : zeta_m, x_zeta = products ? xp : ov.moment[P];
            residual(row) = p * (zeta_x * xp + (zeta - zeta_x) * x_zeta) + lam * bp;
            jacobian.row(row) = (p * (x_zeta * dzeta + zeta_x * dxp) + lam * gp).transpose();
          }
        }
        const Eigen::VectorXd step = jacobian.fullPivLu().solve(-residual);
        a += step;
        if (step.lpNorm<Eigen::Infinity>() < 1e-15 * (1 + a.lpNorm<Eigen::Infinity>())) break;
      }
      correction.assign(s * s, 0.0);
      for (std::size_t i = 0; i < s; ++i)
        for (std::size_t j = 0; j < s; ++j)
          for (int k = 0; k <= K; ++k)
            for (int l = 0; l <= K; ++l)
              if (kept(k, l) && (k != 0 || l != 0))
                correction[i * s + j] += coefficient(i, k) * coefficient(j, l) * pm[i * s + j](1, k, l);
      const std::vector<double> before = gamma;
      solve_equal_rates(mixture, gamma, rates_at);
      double change = (a - start).lpNorm<Eigen::Infinity>();
      for (std::size_t i = 0; i < s; ++i) change = std::max(change, std::abs(gamma[i] - before[i]));
      out.iterations = outer + 1;
      fixed_point = change < 1e-12;
    }
    for (std::size_t i = 0; i < s; ++i) {
      for (int k = 2; k <= K; ++k) out.cumulants[i][static_cast<std::size_t>(k)] = a(index(i, k));
      out.a2[i] = out.cumulants[i][2];
    }
  }
  rates_at(gamma, rates);
  out.temperature_ratio = gamma;
  out.cooling_rate = rates[s - 1];
  double spread = 0;
  for (std::size_t i = 0; i < s; ++i) spread = std::max(spread, std::abs(rates[i] - rates[s - 1]));
  out.solved =
      fixed_point && std::isfinite(out.cooling_rate) && spread <= 1e-12 * std::max(1.0, std::abs(out.cooling_rate));
  return out;
}

namespace {

/// The pair moments Δ^p_ij at the widths θ_i, θ_j (exact, or from MixtureCoolingDynamics' interpolants).
using PairMoments = std::function<PairCumulantMoments(std::size_t, std::size_t, double, double)>;

/// mixture_cooling_rates with the pair moments from `moments`.
MixtureCoolingRates cooling_rates(const Mixture& mixture, std::span<const double> temperature_ratio,
                                  const std::vector<std::vector<double>>& cumulants, MixtureHcsScheme scheme,
                                  const PairMoments& moments) {
  const std::size_t s = mixture.size();
  const int d = mixture.dimension;
  if (temperature_ratio.size() != s)
    throw std::invalid_argument("temperature_ratio: one ratio per species (" + std::to_string(s) + "), got " +
                                std::to_string(temperature_ratio.size()));
  for (const double g : temperature_ratio)
    if (!(g > 0) || !std::isfinite(g))
      throw std::invalid_argument("temperature_ratio: must be finite numbers > 0, got " + std::to_string(g));
  const bool maxwellian = scheme == MixtureHcsScheme::maxwellian;
  const int K = maxwellian ? 2 : static_cast<int>(cumulants.empty() ? 0 : cumulants[0].size()) - 1;
  if (!maxwellian && (cumulants.size() != s || K < 2 || K > 6))
    throw std::invalid_argument("cumulants: a_0 … a_K (K in [2, 6]) for each of the " + std::to_string(s) + " species");
  if (!maxwellian)
    for (const auto& c : cumulants)
      if (static_cast<int>(c.size()) != K + 1)
        throw std::invalid_argument("cumulants: every species carries a_0 … a_K with the same K");
  const bool products = scheme == MixtureHcsScheme::nonlinear;
  const std::vector<double> chi = mixture.contact_values();
  MixtureCoolingRates out;
  out.cooling_rate.assign(s, 0.0);
  out.cumulant_rate.assign(s, std::vector<double>(static_cast<std::size_t>(K) + 1, 0.0));
  // ζ_i^M of (16.4) (the Maxwellian scheme's rates, and the a-free part of the others).
  std::vector<double> zeta_m(s);
  species_cooling_rates(mixture, temperature_ratio, chi, zeta_m);
  if (maxwellian) {
    out.cooling_rate = zeta_m;
    for (std::size_t i = 0; i < s; ++i)
      out.mixture_cooling_rate += mixture.species[i].fraction * temperature_ratio[i] * zeta_m[i];
    return out;
  }
  const double lam = lambda(d);
  std::vector<double> th(s), c(s * s), correction(s * s, 0.0);
  for (std::size_t i = 0; i < s; ++i) th[i] = theta(mixture, i, temperature_ratio[i]);
  std::vector<PairCumulantMoments> pm(s * s);
  auto coefficient = [&](std::size_t i, int k) {
    return k < 2 ? (k == 0 ? 1.0 : 0.0) : cumulants[i][static_cast<std::size_t>(k)];
  };
  auto kept = [&](int k, int l) { return k != 1 && l != 1 && (products || k == 0 || l == 0); };
  for (std::size_t i = 0; i < s; ++i)
    for (std::size_t j = 0; j < s; ++j) {
      const std::size_t P = i * s + j;
      c[P] = pair_weight(mixture, chi, i, j, th[i], th[j]);
      pm[P] = moments(i, j, th[i], th[j]);
      for (int k = 0; k <= K; ++k)
        for (int l = 0; l <= K; ++l)
          if (kept(k, l) && (k != 0 || l != 0)) correction[P] += coefficient(i, k) * coefficient(j, l) * pm[P](1, k, l);
    }
  // ζ_i(a) as the HCS solver's equal-rate conditions take it: (16.6) with the scheme's a-terms.
  species_cooling_rates(mixture, temperature_ratio, chi, out.cooling_rate, correction);
  const CumulantOverlaps ov = cumulant_overlaps(d, K);
  for (std::size_t i = 0; i < s; ++i) {
    const double zeta = out.cooling_rate[i];
    out.mixture_cooling_rate += mixture.species[i].fraction * temperature_ratio[i] * zeta;
    // d⟨X^p⟩_i/dτ = Σ_{k≤p} ⟨X^p S_k⟩ da_k,i/dτ = R_p, the residual of (16.7a) (p ζ_i⟨X^p⟩_i + Λ B^p_i with
    // the scheme's products): triangular in k.
    std::vector<double>& rate = out.cumulant_rate[i];
    for (int p = 2; p <= K; ++p) {
      const auto P = static_cast<std::size_t>(p);
      double xp = ov.moment[P], bp = 0;
      for (int k = 2; k <= p; ++k) xp += coefficient(i, k) * ov.overlap[P][static_cast<std::size_t>(k)];
      for (std::size_t j = 0; j < s; ++j)
        for (int k = 0; k <= K; ++k)
          for (int l = 0; l <= K; ++l)
            if (kept(k, l)) bp += c[i * s + j] * pm[i * s + j](p, k, l) * coefficient(i, k) * coefficient(j, l);
      const double zeta_x = products ? zeta : zeta_m[i], x_zeta = products ? xp : ov.moment[P];
      double residual = p * (zeta_x * xp + (zeta - zeta_x) * x_zeta) + lam * bp;
      for (int k = 2; k < p; ++k)
        residual -= ov.overlap[P][static_cast<std::size_t>(k)] * rate[static_cast<std::size_t>(k)];
      rate[P] = residual / ov.overlap[P][P];
    }
  }
  return out;
}

/// Chebyshev–Lobatto interpolation of a pair's moments in u = ln(θ_i/θ_j) on [lo, hi].
struct PairMomentInterpolant {
  double lo = 0, hi = 0;
  std::vector<PairCumulantMoments> nodes;  // at u_k = mid + half cos(kπ/n), k = 0 … n
  [[nodiscard]] bool covers(double u) const { return u >= lo && u <= hi; }
  [[nodiscard]] PairCumulantMoments operator()(double u) const {
    const std::size_t n = nodes.size() - 1;
    const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    PairCumulantMoments out{nodes[0].k_max, std::vector<double>(nodes[0].values.size(), 0.0)};
    double norm = 0;
    for (std::size_t k = 0; k <= n; ++k) {
      const double x = mid + half * std::cos(std::numbers::pi * static_cast<double>(k) / static_cast<double>(n));
      if (u == x) return nodes[k];
      const double w = ((k % 2 == 0) ? 1.0 : -1.0) * ((k == 0 || k == n) ? 0.5 : 1.0) / (u - x);
      norm += w;
      for (std::size_t q = 0; q < out.values.size(); ++q) out.values[q] += w * nodes[k].values[q];
    }
    for (double& v : out.values) v /= norm;
    return out;
  }
};

}  // namespace

MixtureCoolingRates mixture_cooling_rates(const Mixture& mixture, std::span<const double> temperature_ratio,
                                          const std::vector<std::vector<double>>& cumulants, MixtureHcsScheme scheme) {
  const int K = cumulants.empty() ? 2 : static_cast<int>(cumulants[0].size()) - 1;
  return cooling_rates(mixture, temperature_ratio, cumulants, scheme,
                       [&](std::size_t i, std::size_t j, double theta_i, double theta_j) {
                         return pair_cumulant_moments(mixture, i, j, theta_i, theta_j, std::max(K, 2));
                       });
}

struct MixtureCoolingDynamics::Tables {
  std::vector<PairMomentInterpolant> pairs;  // i·s + j
};

MixtureCoolingDynamics::MixtureCoolingDynamics(const Mixture& mixture, MixtureHcsScheme scheme, int hcs_order,
                                               std::span<const double> log_ratio_low,
                                               std::span<const double> log_ratio_high)
    : mixture_(mixture), scheme_(scheme), k_max_(hcs_order) {
  mixture_.validate();
  if (hcs_order < 2 || hcs_order > 6)
    throw std::invalid_argument("hcs_order: must be an integer in [2, 6], got " + std::to_string(hcs_order));
  const std::size_t s = mixture_.size();
  if (log_ratio_low.size() != s * s || log_ratio_high.size() != s * s)
    throw std::invalid_argument("temperature_ratio: bounds of ln(T_i/T_j) for every pair");
  auto tables = std::make_shared<Tables>();
  tables_ = tables;
  if (scheme == MixtureHcsScheme::maxwellian) return;  // (16.4) in closed form: nothing to tabulate
  tables->pairs.resize(s * s);
  const double mbar = mixture_.mean_mass();
  for (std::size_t i = 0; i < s; ++i)
    for (std::size_t j = 0; j < s; ++j) {
      // u = ln(θ_i/θ_j) = ln(m_i/m_j) − ln(γ_i/γ_j); the same species: u = 0 (one node).
      const double mass = std::log(mixture_.species[i].mass.value() / mixture_.species[j].mass.value());
      PairMomentInterpolant& t = tables->pairs[i * s + j];
      if (i == j) {
        t.lo = t.hi = 0;
        t.nodes.push_back(pair_cumulant_moments(mixture_, i, i, 1.0, 1.0, k_max_));
        continue;
      }
      const double low = std::min(log_ratio_low[i * s + j], log_ratio_high[i * s + j]);
      const double high = std::max(log_ratio_low[i * s + j], log_ratio_high[i * s + j]);
      // A margin of 0.05 + 20 % of the span; the moments are analytic in u (their nearest
      // singularities at Im u = ±π, θ_i/θ_j = −1), so n ∝ half-width nodes give round-off accuracy.
      const double margin = 0.05 + 0.2 * (high - low);
      t.lo = mass - high - margin;
      t.hi = mass - low + margin;
      const double half = 0.5 * (t.hi - t.lo);
      const auto n = static_cast<std::size_t>(std::min(96.0, 16 + std::ceil(16 * half)));
      for (std::size_t k = 0; k <= n; ++k) {
        const double u =
            0.5 * (t.lo + t.hi) + half * std::cos(std::numbers::pi * static_cast<double>(k) / static_cast<double>(n));
        const double theta_j = mixture_.species[j].mass.value() / mbar;  // γ_j = 1
        t.nodes.push_back(pair_cumulant_moments(mixture_, i, j, theta_j * std::exp(u), theta_j, k_max_));
      }
    }
}

MixtureCoolingRates MixtureCoolingDynamics::rates(std::span<const double> temperature_ratio,
                                                  const std::vector<std::vector<double>>& cumulants) const {
  const std::size_t s = mixture_.size();
  return cooling_rates(mixture_, temperature_ratio, cumulants, scheme_,
                       [&](std::size_t i, std::size_t j, double theta_i, double theta_j) {
                         const PairMomentInterpolant& t = tables_->pairs[i * s + j];
                         if (i == j) return t.nodes.front();
                         const double u = std::log(theta_i / theta_j);
                         // Outside the tabulated range: the exact moments (slower, never wrong).
                         return t.covers(u) ? t(u) : pair_cumulant_moments(mixture_, i, j, theta_i, theta_j, k_max_);
                       });
}

MixtureCoolingSensitivity mixture_cooling_sensitivity(const Mixture& mixture, const MixtureCoolingState& state) {
  // Fixed units n = 1, m̄ = 1, σ̄ = 1, T = 1/2 (velocity unit √(2T/m̄)), θ_k = m_k/γ_k. Then
  // ζ_i = −(2c_d/d) Σ_l n_l χ_il σ_il^{d−1} w_il E_il(θ_i/θ_l), w_il = √(γ_i/m_i + γ_l/m_l), E_il of
  // (16.3): (16.4) before the reduction by ν0 = 4√2 c_d/(d+2); `zeta` below omits the factor 2c_d/d.
  // In the dense gas χ_il depends on every n_j (theory.md (18.1)).
  const std::vector<double> chi = mixture.contact_values(), dchi = mixture.contact_value_derivatives();
  const std::size_t s = mixture.size();
  const int d = mixture.dimension;
  const double mbar = mixture.mean_mass(), sbar = mixture.mean_diameter();
  const std::vector<double>& g = state.temperature_ratio;
  std::vector<double> m(s), x(s);
  for (std::size_t k = 0; k < s; ++k) {
    m[k] = mixture.species[k].mass.value() / mbar;
    x[k] = mixture.species[k].fraction;
  }
  // dF(i, k) = ∂ζ_i/∂γ_k, dn(i, j) = ∂ζ_i/∂n_j; ζ(i) the rates (all equal).
  const auto n = static_cast<Eigen::Index>(s);
  Eigen::MatrixXd dF = Eigen::MatrixXd::Zero(n, n), dn = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd zeta = Eigen::VectorXd::Zero(n);
  for (std::size_t i = 0; i < s; ++i)
    for (std::size_t l = 0; l < s; ++l) {
      const auto I = static_cast<Eigen::Index>(i), L = static_cast<Eigen::Index>(l);
      const double sigma = 0.5 * (mixture.species[i].diameter + mixture.species[l].diameter) / sbar;
      const double f = -std::pow(sigma, d - 1);
      const double a = mixture.restitution(i, l), mu = m[l] / (m[i] + m[l]);
      const double w = std::sqrt(g[i] / m[i] + g[l] / m[l]);
      const double r = m[i] * g[l] / (m[l] * g[i]);  // θ_i/θ_l
      const double e = pair_energy_change(mu, a, r), de = mu * mu * (1 + a) * (1 + a);
      const double c = chi[i * s + l], fc = f * c;
      zeta(I) += fc * x[l] * w * e;
      dn(I, L) += fc * w * e;
      for (std::size_t j = 0; j < s; ++j)
        dn(I, static_cast<Eigen::Index>(j)) += f * x[l] * w * e * dchi[(i * s + l) * s + j];
      if (l == i) {
        dF(I, I) += fc * x[l] * e / (m[i] * w);
      } else {
        dF(I, I) += fc * x[l] * (e / (2 * m[i] * w) - w * de * r / g[i]);
        dF(I, L) += fc * x[l] * (e / (2 * m[l] * w) + w * de * r / g[l]);
      }
    }
  // Rows 0 … s−2: d(ζ_i − ζ_{s−1}) = 0; row s−1: d(Σ_k n_k γ_k − n) = 0 (∂/∂n_j of it: γ_j − 1).
  Eigen::MatrixXd jac(n, n);
  for (Eigen::Index i = 0; i + 1 < n; ++i) jac.row(i) = dF.row(i) - dF.row(n - 1);
  for (Eigen::Index k = 0; k < n; ++k) jac(n - 1, k) = x[static_cast<std::size_t>(k)];
  const auto lu = jac.fullPivLu();
  MixtureCoolingSensitivity out;
  out.temperature_ratio.assign(s * s, 0.0);
  out.cooling_rate.assign(s, 0.0);
  const double to_reduced = (d + 2) / (2 * std::sqrt(2.0) * d);  // ζ* = to_reduced · zeta (ν0 of (16.4))
  for (std::size_t j = 0; j < s; ++j) {
    const auto J = static_cast<Eigen::Index>(j);
    Eigen::VectorXd rhs(n);
    for (Eigen::Index i = 0; i + 1 < n; ++i) rhs(i) = -(dn(i, J) - dn(n - 1, J));
    rhs(n - 1) = 1 - g[j];
    const Eigen::VectorXd dg = lu.solve(rhs);
    for (std::size_t i = 0; i < s; ++i) out.temperature_ratio[i * s + j] = dg(static_cast<Eigen::Index>(i)) / g[i];
    out.cooling_rate[j] = to_reduced * (dn(n - 1, J) + dF.row(n - 1).dot(dg));
  }
  return out;
}

/// The HCS density derivatives of a cumulant reference at fixed T (theory.md §17.11): n ∂ln γ_i/∂n_j,
/// n (∂ζ/∂n_j)/ν0 (ν0 held at the state) and n ∂a_k,i/∂n_j, by a central stencil in n_j (step 10⁻³ n; five
/// points dilute, seven dense; one-sided five points when x_j < 2·10⁻³, dense 3·10⁻³) of the solved HCS. The
/// reduced HCS depends on the composition and, dense, on φ = v_d Σ_k n_k σ_k^d (moved with n_j);
/// ζ = ζ*(x, φ) ν0 with ν0 ∝ n σ̄^{d−1} (T/m̄)^{1/2}.
MixtureCoolingSensitivity mixture_cooling_sensitivity(const Mixture& mixture, const MixtureReference& reference,
                                                      std::vector<std::vector<double>>* cumulant_derivatives) {
  mixture.validate();
  std::vector<std::vector<double>> local;
  std::vector<std::vector<double>>& cumulants = cumulant_derivatives ? *cumulant_derivatives : local;
  const std::size_t s = mixture.size();
  const int d = mixture.dimension;
  const auto K = static_cast<std::size_t>(reference.scheme == MixtureHcsScheme::maxwellian ? 2 : reference.hcs_order);
  const double m_bar = mixture.mean_mass(), sigma_bar = mixture.mean_diameter(), h = 1e-3;
  double volume = 0;  // Σ_k x_k σ_k^d
  for (const auto& species : mixture.species) volume += species.fraction * std::pow(species.diameter, d);
  MixtureCoolingSensitivity out;
  out.temperature_ratio.assign(s * s, 0.0);
  out.cooling_rate.assign(s, 0.0);
  cumulants.assign(s * s, std::vector<double>(K + 1, 0.0));
  for (std::size_t j = 0; j < s; ++j) {
    // Dense: seven points (truncation h⁶ f⁽⁷⁾/140), since χ(φ) makes f⁽⁵⁾ large (the five-point stencil's
    // h⁴ f⁽⁵⁾/30 reached 1.5·10⁻¹¹ in n∂ζ/∂n_j at φ = 0.4); dilute: five.
    const bool dense = mixture.packing_fraction > 0;
    const bool central = mixture.species[j].fraction >= (dense ? 3 : 2) * h;
    std::vector<int> steps{0, 1, 2, 3, 4};
    std::vector<double> weights{-25, 48, -36, 16, -3};
    double denominator = 12;
    if (central && dense) {
      steps = {-3, -2, -1, 1, 2, 3};
      weights = {-1, 9, -45, 45, -9, 1};
      denominator = 60;
    } else if (central) {
      steps = {-2, -1, 1, 2};
      weights = {1, -8, 8, -1};
    }
    for (std::size_t m = 0; m < steps.size(); ++m) {
      const double dn = steps[m] * h, w = weights[m] / (denominator * h);
      Mixture moved = mixture;
      for (std::size_t k = 0; k < s; ++k)
        moved.species[k].fraction = (mixture.species[k].fraction + (k == j ? dn : 0.0)) / (1 + dn);
      // Dense: φ = v_d Σ_k n_k σ_k^d grows with n_j (theory.md §17.11).
      moved.packing_fraction = mixture.packing_fraction * (1 + dn * std::pow(mixture.species[j].diameter, d) / volume);
      const MixtureCoolingState state = mixture_cooling_state(moved, reference.scheme, reference.hcs_order);
      if (!state.solved) throw std::invalid_argument("reference_state: the HCS did not converge near the state");
      const double scale =
          (1 + dn) * std::pow(moved.mean_diameter() / sigma_bar, d - 1) * std::sqrt(m_bar / moved.mean_mass());
      out.cooling_rate[j] += w * state.cooling_rate * scale;
      for (std::size_t i = 0; i < s; ++i) {
        out.temperature_ratio[i * s + j] += w * std::log(state.temperature_ratio[i]);
        for (std::size_t k = 2; k <= K && k < state.cumulants[i].size(); ++k)
          cumulants[i * s + j][k] += w * state.cumulants[i][k];
      }
    }
  }
  return out;
}

}  // namespace gkt
