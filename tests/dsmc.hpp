// Test helper: Direct Simulation Monte Carlo of the homogeneous cooling state (Bird's scheme
// for a spatially homogeneous gas), independent of the Sonine engine. Collisions are drawn with
// probability ∝ |g| (majorant frequency) and σ̂ with density ∝ (σ̂·ĝ)_+; velocities are rescaled
// to unit temperature between samples (the scaled HCS is invariant under rescaling; for a
// speed-dependent restitution at fixed δ' too, since it sees u = σ̂·g/√(2T/m)).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

namespace gkt::test {

/// Returns σ̂ with density ∝ (σ̂·ĝ)_+ on the half sphere (d = 3) or half circle (d = 2):
/// σ̂ = cosθ ĝ + sinθ ê⊥ with density ∝ cosθ, ê⊥ uniform in azimuth.
inline std::array<double, 3> collision_direction(gsl_rng* rng, int d, const std::array<double, 3>& ghat) {
  std::array<double, 3> sigma{0, 0, 0};
  if (d == 3) {
    const double cos_t = std::sqrt(gsl_rng_uniform(rng)), sin_t = std::sqrt(1 - cos_t * cos_t);
    std::array<double, 3> e{0, 0, 0};
    do {  // a unit vector orthogonal to ĝ, uniform in azimuth
      for (int k = 0; k < 3; ++k) e[k] = gsl_ran_gaussian(rng, 1.0);
      const double proj = e[0] * ghat[0] + e[1] * ghat[1] + e[2] * ghat[2];
      for (int k = 0; k < 3; ++k) e[k] -= proj * ghat[k];
    } while (e[0] * e[0] + e[1] * e[1] + e[2] * e[2] < 1e-12);
    const double en = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
    for (int k = 0; k < 3; ++k) sigma[k] = cos_t * ghat[k] + sin_t * e[k] / en;
  } else {
    const double sin_t = 2 * gsl_rng_uniform(rng) - 1, cos_t = std::sqrt(1 - sin_t * sin_t);
    sigma = {cos_t * ghat[0] - sin_t * ghat[1], cos_t * ghat[1] + sin_t * ghat[0], 0};
  }
  return sigma;
}

/// Returns the mean of batch values and its standard error (batches taken as independent).
inline void batch_mean(const std::vector<double>& x, double& mean, double& error) {
  mean = 0;
  for (double y : x) mean += y / static_cast<double>(x.size());
  double var = 0;
  for (double y : x) var += (y - mean) * (y - mean) / static_cast<double>(x.size() - 1);
  error = std::sqrt(var / static_cast<double>(x.size()));
}

/// Sample means of the reduced moments ⟨c^4⟩, ⟨c^6⟩ (c = v/√(2T/m)) with batch-mean errors.
struct HcsMoments {
  double c4 = 0, c4_error = 0, c6 = 0, c6_error = 0;
};

/// Runs the DSMC for `particles` particles, `relax` collisions per particle of relaxation and
/// `batches` batches of `per_batch` collisions per particle; returns the moments. The restitution
/// is `restitution(u)`, u = σ̂·g in units of the thermal speed √(2T/m) (constant α: ignore u).
template <class Restitution>
HcsMoments run_hcs_dsmc(int d, Restitution&& restitution, int particles, double relax, int batches, double per_batch,
                        unsigned long seed) {
  gsl_rng* rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, seed);
  std::vector<std::array<double, 3>> v(static_cast<std::size_t>(particles), {0, 0, 0});
  for (auto& p : v)
    for (int k = 0; k < d; ++k) p[k] = gsl_ran_gaussian(rng, 1.0);
  auto rescale = [&]() {  // zero momentum, temperature such that ⟨c²⟩ = d/2
    std::array<double, 3> mean{0, 0, 0};
    for (const auto& p : v)
      for (int k = 0; k < d; ++k) mean[k] += p[k] / particles;
    double c2 = 0;
    for (auto& p : v)
      for (int k = 0; k < d; ++k) {
        p[k] -= mean[k];
        c2 += p[k] * p[k];
      }
    const double scale = std::sqrt(0.5 * d * particles / c2);
    double vmax = 0;
    for (auto& p : v) {
      double s = 0;
      for (int k = 0; k < d; ++k) {
        p[k] *= scale;
        s += p[k] * p[k];
      }
      vmax = std::max(vmax, std::sqrt(s));
    }
    return 2.2 * vmax;  // majorant of |g| until the next rescale (energy only decreases)
  };
  // Σ c² (= dN/2 right after a rescale), updated at every collision: the speed u the restitution sees
  // is σ̂·g in units of the current thermal speed.
  double energy = 0;
  auto collide = [&](double collisions_per_particle) {
    double gmax = rescale();
    energy = 0.5 * d * particles;
    long accepted = 0;
    const long target = static_cast<long>(collisions_per_particle * particles / 2);
    long since_rescale = 0;
    while (accepted < target) {
      const auto i = gsl_rng_uniform_int(rng, static_cast<unsigned long>(particles));
      auto j = gsl_rng_uniform_int(rng, static_cast<unsigned long>(particles - 1));
      if (j >= i) ++j;
      std::array<double, 3> g{0, 0, 0};
      double gn = 0;
      for (int k = 0; k < d; ++k) {
        g[k] = v[i][k] - v[j][k];
        gn += g[k] * g[k];
      }
      gn = std::sqrt(gn);
      if (gsl_rng_uniform(rng) * gmax >= gn) continue;
      const std::array<double, 3> ghat{g[0] / gn, g[1] / gn, g[2] / gn};
      const std::array<double, 3> sigma = collision_direction(rng, d, ghat);
      double sg = 0;
      for (int k = 0; k < d; ++k) sg += sigma[k] * g[k];
      const double alpha = restitution(sg / std::sqrt(2 * energy / (d * particles)));
      for (int k = 0; k < d; ++k) {
        energy -= v[i][k] * v[i][k] + v[j][k] * v[j][k];
        v[i][k] -= 0.5 * (1 + alpha) * sg * sigma[k];
        v[j][k] += 0.5 * (1 + alpha) * sg * sigma[k];
        energy += v[i][k] * v[i][k] + v[j][k] * v[j][k];
      }
      ++accepted;
      if (++since_rescale == particles) {  // keep the temperature O(1) for the majorant
        gmax = rescale();
        energy = 0.5 * d * particles;
        since_rescale = 0;
      }
    }
    rescale();
  };
  collide(relax);
  std::vector<double> c4s, c6s;
  for (int b = 0; b < batches; ++b) {
    collide(per_batch);
    double c4 = 0, c6 = 0;
    for (const auto& p : v) {
      double c2 = 0;
      for (int k = 0; k < d; ++k) c2 += p[k] * p[k];
      c4 += c2 * c2 / particles;
      c6 += c2 * c2 * c2 / particles;
    }
    c4s.push_back(c4);
    c6s.push_back(c6);
  }
  gsl_rng_free(rng);
  HcsMoments m;
  batch_mean(c4s, m.c4, m.c4_error);
  batch_mean(c6s, m.c6, m.c6_error);
  return m;
}

/// Constant restitution α.
inline HcsMoments run_hcs_dsmc(int d, double alpha, int particles, double relax, int batches, double per_batch,
                               unsigned long seed) {
  return run_hcs_dsmc(
      d, [alpha](double) { return alpha; }, particles, relax, batches, per_batch, seed);
}

}  // namespace gkt::test
