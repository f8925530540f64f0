// Test helper: a DSMC of the free cooling of a homogeneous binary mixture of rough spheres (d = 3) from
// Maxwellians at four given temperatures, with physical time: the same collision rule and acceptance as
// rough_mixture_dsmc.hpp (pairs ∝ σ_pq² Θ(u) u, σ̂ uniform, the impulse solved numerically), no rescaling, and
// every candidate pair advancing t by 2/(n (N − 1) 4π σ_max² u_max) (the total collision rate of N(N − 1)/2 pairs).
// Records (T_t,1, T_t,2, T_r,1, T_r,2)/T_ref at the requested τ = ν0(T_ref) t, ν0 = (16/5) n σ̄² √(π T_ref/m̄) of
// the mixture's reference gas (η0 = (5/16σ̄²)√(m̄T/π); docs/conventions.md "Mixtures", theory.md (16.4)).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include "rough_mixture_monte_carlo.hpp"

namespace gkt::test {

/// Returns the four temperatures (T_t,1, T_t,2, T_r,1, T_r,2) at each of the increasing `times` (τ = ν0(T_ref) t) of
/// one run with n_k particles of species k (the species' translational_temperature, rotational_temperature the
/// start, T_ref = 1), pair restitutions at 0 (1–1), 1 (1–2), 2 (2–2).
inline std::vector<std::array<double, 4>> run_rough_mixture_cooling_dsmc(
    const std::array<McRoughSpecies, 2>& species, const std::array<int, 2>& count, const std::array<double, 3>& alpha,
    const std::array<double, 3>& beta, const std::vector<double>& times, unsigned long seed) {
  gsl_rng* rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, seed);
  const int n = count[0] + count[1];
  const auto at = [](int p) { return static_cast<std::size_t>(p); };
  std::vector<int> kind(at(n));
  std::vector<Vec3> v(at(n)), omega(at(n));
  double speed = 0;
  for (int p = 0; p < n; ++p) {
    const int k = p < count[0] ? 0 : 1;
    kind[at(p)] = k;
    const auto& s = species[at(k)];
    for (int c = 0; c < 3; ++c) {
      v[at(p)][c] = gsl_ran_gaussian(rng, std::sqrt(s.translational_temperature / s.mass));
      omega[at(p)][c] = gsl_ran_gaussian(rng, std::sqrt(s.rotational_temperature / s.inertia()));
    }
  }
  // Remove the sample's mean velocity (the homogeneous state at rest).
  Vec3 momentum{};
  double mass = 0;
  for (int p = 0; p < n; ++p) {
    mass += species[at(kind[at(p)])].mass;
    for (int c = 0; c < 3; ++c) momentum[c] += species[at(kind[at(p)])].mass * v[at(p)][c];
  }
  for (int p = 0; p < n; ++p) {
    for (int c = 0; c < 3; ++c) v[at(p)][c] -= momentum[c] / mass;
    speed = std::max(speed, std::sqrt(dot3(v[at(p)], v[at(p)])));
  }
  const auto temperatures = [&] {
    std::array<double, 4> t{};
    for (int p = 0; p < n; ++p) {
      const int k = kind[at(p)];
      const auto& s = species[at(k)];
      t[at(k)] += s.mass * dot3(v[at(p)], v[at(p)]) / 3 / count[at(k)];
      t[at(2 + k)] += s.inertia() * dot3(omega[at(p)], omega[at(p)]) / 3 / count[at(k)];
    }
    return t;
  };
  const double x1 = static_cast<double>(count[0]) / n, x2 = 1 - x1;
  const double mean_mass = x1 * species[0].mass + x2 * species[1].mass;
  const double mean_diameter = x1 * species[0].diameter + x2 * species[1].diameter;
  const double sigma_max = std::max(species[0].diameter, species[1].diameter);
  double u_max = 2 * speed;
  // Δτ per candidate = ν0(T_ref) · 2/(n (N − 1) 4π σ_max² u_max) (the density n cancels).
  const auto step = [&] {
    return (16.0 / 5) * mean_diameter * mean_diameter * std::sqrt(std::numbers::pi / mean_mass) * 2 /
           ((n - 1) * 4 * std::numbers::pi * sigma_max * sigma_max * u_max);
  };
  double tau = 0;
  std::vector<std::array<double, 4>> out;
  for (const double target : times) {
    while (tau + step() <= target) {
      tau += step();
      const auto [p, q, sigma] = draw_candidate(rng, n);
      const auto& a = v[at(p)];
      const auto& b = v[at(q)];
      const double u = (a[0] - b[0]) * sigma[0] + (a[1] - b[1]) * sigma[1] + (a[2] - b[2]) * sigma[2];
      if (u <= 0) continue;
      const int kp = kind[at(p)], kq = kind[at(q)];
      const double d_pq = 0.5 * (species[at(kp)].diameter + species[at(kq)].diameter);
      if (u > u_max) u_max = u;  // rare: the bound is re-set, the step follows it
      if (gsl_rng_uniform(rng) * sigma_max * sigma_max * u_max > d_pq * d_pq * u) continue;
      RoughMixtureCollision c;
      c.w.w[0] = a;
      c.w.w[1] = b;
      c.omega[0] = omega[at(p)];
      c.omega[1] = omega[at(q)];
      c.sigma = sigma;
      const auto pair = at(kp + kq);
      apply_rough_mixture_rule(c, species[at(kp)], species[at(kq)], alpha[pair], beta[pair], false);
      v[at(p)] = c.w.w[4];
      v[at(q)] = c.w.w[5];
      omega[at(p)] = c.omega[2];
      omega[at(q)] = c.omega[3];
    }
    out.push_back(temperatures());
    // The bound |u| ≤ 2 max|v| tightens as the gas cools (fewer rejected candidates; no bias).
    speed = 0;
    for (int p = 0; p < n; ++p) speed = std::max(speed, std::sqrt(dot3(v[at(p)], v[at(p)])));
    u_max = 2 * speed;
  }
  gsl_rng_free(rng);
  return out;
}

}  // namespace gkt::test
