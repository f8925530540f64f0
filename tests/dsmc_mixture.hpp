// Test helper: Direct Simulation Monte Carlo of the homogeneous cooling state of a dilute granular
// mixture (Bird's scheme, spatially homogeneous), independent of the Sonine engine and of the
// cooling-rate formulas. Pairs are drawn uniformly and accepted with probability
// ∝ σ_ij^{d−1}|g| (majorant); σ̂ has density ∝ (σ̂·ĝ)_+; velocities are rescaled by one common factor
// between samples (the scaled HCS, and every temperature ratio, is invariant under it).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include "dsmc.hpp"

namespace gkt::test {

/// Batch means with their standard errors: T_i/T and a2,i = ⟨c⁴⟩_i/(d(d+2)/4) − 1 per species.
struct MixtureHcsSample {
  std::vector<double> temperature_ratio, temperature_ratio_error, a2, a2_error;
};

/// Runs the DSMC with `counts[i]` particles of mass `mass[i]` and diameter `diameter[i]`,
/// restitution alpha[i·s + j]; `relax` collisions per particle of relaxation, then `batches`
/// batches of `per_batch` collisions per particle.
inline MixtureHcsSample run_mixture_hcs_dsmc(int d, const std::vector<int>& counts, const std::vector<double>& mass,
                                             const std::vector<double>& diameter, const std::vector<double>& alpha,
                                             double relax, int batches, double per_batch, unsigned long seed) {
  const std::size_t s = counts.size();
  gsl_rng* rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, seed);
  std::vector<std::size_t> species;
  for (std::size_t a = 0; a < s; ++a) species.insert(species.end(), static_cast<std::size_t>(counts[a]), a);
  const auto n = static_cast<long>(species.size());
  std::vector<std::array<double, 3>> v(species.size(), {0, 0, 0});
  for (std::size_t p = 0; p < v.size(); ++p)
    for (int k = 0; k < d; ++k) v[p][k] = gsl_ran_gaussian(rng, 1.0 / std::sqrt(mass[species[p]]));
  double sigma_max = 0;
  for (std::size_t a = 0; a < s; ++a)
    for (std::size_t b = 0; b < s; ++b)
      sigma_max = std::max(sigma_max, std::pow(0.5 * (diameter[a] + diameter[b]), d - 1));
  auto rescale = [&]() {  // zero momentum, total kinetic energy fixed; returns a majorant of |g|
    std::array<double, 3> momentum{0, 0, 0};
    double total_mass = 0;
    for (std::size_t p = 0; p < v.size(); ++p) {
      total_mass += mass[species[p]];
      for (int k = 0; k < d; ++k) momentum[k] += mass[species[p]] * v[p][k];
    }
    double energy = 0;
    for (std::size_t p = 0; p < v.size(); ++p)
      for (int k = 0; k < d; ++k) {
        v[p][k] -= momentum[k] / total_mass;
        energy += 0.5 * mass[species[p]] * v[p][k] * v[p][k];
      }
    const double scale = std::sqrt(0.5 * d * static_cast<double>(n) / energy);  // T = 1
    double vmax = 0;
    for (auto& p : v) {
      double q = 0;
      for (int k = 0; k < d; ++k) {
        p[k] *= scale;
        q += p[k] * p[k];
      }
      vmax = std::max(vmax, std::sqrt(q));
    }
    return 2.2 * vmax;
  };
  auto collide = [&](double collisions_per_particle) {
    double gmax = rescale();
    long accepted = 0, since_rescale = 0;
    const auto target = static_cast<long>(collisions_per_particle * static_cast<double>(n) / 2);
    while (accepted < target) {
      const auto i = gsl_rng_uniform_int(rng, static_cast<unsigned long>(n));
      auto j = gsl_rng_uniform_int(rng, static_cast<unsigned long>(n - 1));
      if (j >= i) ++j;
      const std::size_t a = species[i], b = species[j];
      std::array<double, 3> g{0, 0, 0};
      double gn = 0;
      for (int k = 0; k < d; ++k) {
        g[k] = v[i][k] - v[j][k];
        gn += g[k] * g[k];
      }
      gn = std::sqrt(gn);
      const double weight = std::pow(0.5 * (diameter[a] + diameter[b]), d - 1) / sigma_max;
      if (gsl_rng_uniform(rng) * gmax >= weight * gn) continue;
      const std::array<double, 3> ghat{g[0] / gn, g[1] / gn, g[2] / gn};
      const std::array<double, 3> sigma = collision_direction(rng, d, ghat);
      double sg = 0;
      for (int k = 0; k < d; ++k) sg += sigma[k] * g[k];
      // v1' = v1 − μ_ji(1+α)(σ̂·g)σ̂, v2' = v2 + μ_ij(1+α)(σ̂·g)σ̂ (seed 003; theory.md (2.1)).
      const double restitution = alpha[a * s + b], total = mass[a] + mass[b];
      for (int k = 0; k < d; ++k) {
        v[i][k] -= mass[b] / total * (1 + restitution) * sg * sigma[k];
        v[j][k] += mass[a] / total * (1 + restitution) * sg * sigma[k];
      }
      ++accepted;
      if (++since_rescale == n) {
        gmax = rescale();
        since_rescale = 0;
      }
    }
    rescale();
  };
  collide(relax);
  std::vector<std::vector<double>> ratio(s), a2(s);
  for (int batch = 0; batch < batches; ++batch) {
    collide(per_batch);
    std::vector<double> v2(s, 0), v4(s, 0);
    for (std::size_t p = 0; p < v.size(); ++p) {
      double q = 0;
      for (int k = 0; k < d; ++k) q += v[p][k] * v[p][k];
      v2[species[p]] += q;
      v4[species[p]] += q * q;
    }
    for (std::size_t a = 0; a < s; ++a) {
      const double t = mass[a] * v2[a] / (d * counts[a]);  // T_a (T = 1 after the rescale)
      ratio[a].push_back(t);
      const double c4 = v4[a] / counts[a] * mass[a] * mass[a] / (4 * t * t);  // ⟨c⁴⟩, c² = m v²/(2T_a)
      a2[a].push_back(c4 / (d * (d + 2) / 4.0) - 1);
    }
  }
  gsl_rng_free(rng);
  MixtureHcsSample out;
  out.temperature_ratio.resize(s);
  out.temperature_ratio_error.resize(s);
  out.a2.resize(s);
  out.a2_error.resize(s);
  for (std::size_t a = 0; a < s; ++a) {
    batch_mean(ratio[a], out.temperature_ratio[a], out.temperature_ratio_error[a]);
    batch_mean(a2[a], out.a2[a], out.a2_error[a]);
  }
  return out;
}

}  // namespace gkt::test
