// Test helper: DSMC of a homogeneous gas of sticking grains, independent of the population
// balance. Clusters carry a size k (mass k, diameter k^{1/d}) and a velocity; candidate pairs are
// drawn uniformly at the rate of a majorant and accepted with probability σ_ij^{d−1}|g|/bound
// (null collisions: exact in continuous time), σ̂ with density ∝ (σ̂·ĝ)_+. A pair sticks by the
// criterion of docs/theory.md §20.1 (then merges: mass and momentum conserved) or rebounds with
// restitution α.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include "dsmc.hpp"

namespace gkt::test {

struct AggregationDsmcSample {
  double number = 0;                  ///< N(t)/N(0)
  double temperature = 0;             ///< θ = Σ k v²/(d N) (total momentum is zero)
  double sticks = 0, collisions = 0;  ///< events since the previous sample
};

/// Runs one replica of `particles` monomers at θ = 1 (number density 1: volume = particles) to
/// the increasing `times`; criterion 0 relative speed, 1 normal impact; θ*_ij = θ*_11 μ_ij/μ_11.
inline std::vector<AggregationDsmcSample> run_aggregation_dsmc(int d, double alpha, double critical_energy,
                                                               int criterion, int particles,
                                                               const std::vector<double>& times, unsigned long seed) {
  gsl_rng* rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, seed);
  std::vector<int> size(static_cast<std::size_t>(particles), 1);
  std::vector<std::array<double, 3>> v(static_cast<std::size_t>(particles), {0, 0, 0});
  std::array<double, 3> mean{0, 0, 0};
  for (auto& u : v)
    for (int a = 0; a < d; ++a) {
      u[a] = gsl_ran_gaussian(rng, 1.0);
      mean[a] += u[a] / particles;
    }
  for (auto& u : v)
    for (int a = 0; a < d; ++a) u[a] -= mean[a];
  const double volume = particles;
  // ∫dσ̂ Θ(ĝ·σ̂)(ĝ·σ̂): π (3D), 2 (2D).
  const double solid = d == 3 ? std::numbers::pi : 2.0;
  const auto speed = [&](const std::array<double, 3>& u) { return std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]); };
  double v_max = 0;
  int k_max = 1;
  for (const auto& u : v) v_max = std::max(v_max, speed(u));
  double t = 0;
  std::vector<AggregationDsmcSample> out;
  AggregationDsmcSample window;
  std::size_t next = 0;
  while (next < times.size()) {
    const auto n = static_cast<double>(size.size());
    const double sigma_max = std::pow(k_max, 1.0 / d);
    const double bound = std::pow(sigma_max, d - 1) * 2 * v_max;  // ≥ σ_ij^{d−1} |g_ij|
    const double majorant = 0.5 * n * (n - 1) * solid * bound / volume;
    t += -std::log(1 - gsl_rng_uniform(rng)) / majorant;
    while (next < times.size() && t > times[next]) {
      double e = 0;
      for (std::size_t p = 0; p < size.size(); ++p)
        e += size[p] * (v[p][0] * v[p][0] + v[p][1] * v[p][1] + v[p][2] * v[p][2]);
      window.number = n / particles;
      window.temperature = e / (d * n);
      out.push_back(window);
      window = AggregationDsmcSample{};
      ++next;
    }
    if (next == times.size()) break;
    const auto a = static_cast<std::size_t>(gsl_rng_uniform_int(rng, size.size()));
    auto b = static_cast<std::size_t>(gsl_rng_uniform_int(rng, size.size() - 1));
    if (b >= a) ++b;
    std::array<double, 3> g{0, 0, 0};
    for (int c = 0; c < d; ++c) g[c] = v[a][c] - v[b][c];
    const double gm = speed(g);
    const double sigma = 0.5 * (std::pow(size[a], 1.0 / d) + std::pow(size[b], 1.0 / d));
    if (gsl_rng_uniform(rng) * bound >= std::pow(sigma, d - 1) * gm) continue;  // null collision
    ++window.collisions;
    const std::array<double, 3> ghat{g[0] / gm, g[1] / gm, g[2] / gm};
    const std::array<double, 3> s = collision_direction(rng, d, ghat);
    const double gn = g[0] * s[0] + g[1] * s[1] + g[2] * s[2];
    const double ma = size[a], mb = size[b], mu = ma * mb / (ma + mb);
    const double threshold = critical_energy * mu / 0.5;
    const double energy = criterion == 0 ? 0.5 * mu * gm * gm : 0.5 * mu * gn * gn;
    if (energy < threshold) {  // merge into a: centre-of-mass velocity, mass a + b
      ++window.sticks;
      for (int c = 0; c < d; ++c) v[a][c] = (ma * v[a][c] + mb * v[b][c]) / (ma + mb);
      size[a] += size[b];
      k_max = std::max(k_max, size[a]);
      size[b] = size.back();
      v[b] = v.back();
      size.pop_back();
      v.pop_back();
      continue;
    }
    const double impulse = (1 + alpha) * gn;
    for (int c = 0; c < d; ++c) {
      v[a][c] -= mb / (ma + mb) * impulse * s[c];
      v[b][c] += ma / (ma + mb) * impulse * s[c];
    }
    v_max = std::max({v_max, speed(v[a]), speed(v[b])});
  }
  gsl_rng_free(rng);
  return out;
}

}  // namespace gkt::test
