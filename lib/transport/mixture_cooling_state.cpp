#include "gkt/mixture_cooling_state.hpp"

#include <algorithm>
#include <cmath>

namespace gkt {

double pair_energy_change(double mu_ji, double alpha, double theta_ratio) {
  // [garzo1999mixture]; derived in theory.md (16.3) and checked against the engine's exact
  // moments E(0,0,1) − E(1,0,0) (tests/test_mixture.cpp).
  return -2 * mu_ji * (1 + alpha) * (1 - 0.5 * mu_ji * (1 + alpha) * (1 + theta_ratio));
}

void species_cooling_rates(const Mixture& mixture, std::span<const double> temperature_ratio,
                           std::span<const double> chi, std::span<double> rates) {
  const std::size_t s = mixture.size();
  const int d = mixture.dimension;
  const double m_ref = mixture.mean_mass(), sigma_ref = mixture.mean_diameter();
  const double prefactor = -(d + 2) * std::sqrt(2.0) / (4.0 * d);  // (16.4)
  for (std::size_t i = 0; i < s; ++i) {
    const Species& a = mixture.species[i];
    const double theta_i = a.mass / (m_ref * temperature_ratio[i]);  // θ = m/(2T) in units of √(2T/m̄)
    double sum = 0;
    for (std::size_t j = 0; j < s; ++j) {
      const Species& b = mixture.species[j];
      const double theta_j = b.mass / (m_ref * temperature_ratio[j]);
      const double mu_ji = b.mass / (a.mass + b.mass);
      const double sigma_ij = 0.5 * (a.diameter + b.diameter) / sigma_ref;
      sum += b.fraction * chi[i * s + j] * std::pow(sigma_ij, d - 1) * std::sqrt(1 / theta_i + 1 / theta_j) *
             pair_energy_change(mu_ji, mixture.restitution(i, j), theta_i / theta_j);
    }
    rates[i] = prefactor * sum;
  }
}

MixtureCoolingState mixture_cooling_state(const Mixture& mixture) {
  mixture.validate();
  const std::size_t s = mixture.size();
  MixtureCoolingState out;
  out.chi = mixture.contact_values();
  // ζ_i(λγ) = √λ ζ_i(γ): the conditions ζ_i = ζ_s fix the ratios only. Unknowns u_i = ln(γ_i/γ_s),
  // i < s (u_s = 0), solved by nonlinear Gauss–Seidel — for each i in turn the bracketed 1D root of
  // h_i(u_i) = ζ_i − ζ_s, which exists and is unique (h_i → ∓∞ as u_i → ∓∞ as long as α_ij < 1
  // somewhere; at α = 1 every ζ_i vanishes and equipartition is returned) — then normalised.
  std::vector<double> u(s, 0.0), gamma(s), rates(s);
  auto evaluate = [&] {
    for (std::size_t i = 0; i < s; ++i) gamma[i] = std::exp(u[i]);
    species_cooling_rates(mixture, gamma, out.chi, rates);
  };
  auto h = [&](std::size_t i, double t) {
    u[i] = t;
    evaluate();
    return rates[i] - rates[s - 1];
  };
  evaluate();
  double scale = 0;
  for (const double r : rates) scale = std::max(scale, std::abs(r));
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
      out.iterations = sweep + 1;
      if (change < 1e-14) break;
    }
  }
  evaluate();
  double norm = 0;
  for (std::size_t i = 0; i < s; ++i) norm += mixture.species[i].fraction * gamma[i];
  for (std::size_t i = 0; i < s; ++i) gamma[i] /= norm;
  species_cooling_rates(mixture, gamma, out.chi, rates);
  out.temperature_ratio = gamma;
  out.cooling_rate = rates[s - 1];
  double spread = 0;
  for (std::size_t i = 0; i < s; ++i) spread = std::max(spread, std::abs(rates[i] - rates[s - 1]));
  out.solved = spread <= 1e-12 * std::max(1.0, std::abs(out.cooling_rate)) && std::isfinite(out.cooling_rate);
  return out;
}

}  // namespace gkt
