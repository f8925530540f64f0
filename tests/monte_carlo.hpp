// Test helper: Monte Carlo estimates of collision integrals with an error bar (GSL RNG).
// Independent of the engine: samples v1, v2 from the reference Gaussians and σ̂ uniformly,
// applies the collision rule directly, and averages the integrand.
#pragma once

#include <array>
#include <cmath>
#include <functional>
#include <vector>

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include "ratio_averages.hpp"

namespace gkt::test {

using Vec = std::array<double, 3>;

inline double dot(const Vec& a, const Vec& b, int d) {
  double s = 0;
  for (int k = 0; k < d; ++k) s += a[k] * b[k];
  return s;
}

/// The four velocities of one sampled collision.
struct Collision {
  Vec v1{}, v2{}, v1p{}, v2p{};
  double weight = 0;  ///< Θ(σ̂·g)(σ̂·g)
};

/// Draws collisions: v1 ~ exp(−θ_i v²), v2 ~ exp(−θ_j v²), σ̂ uniform, restitution α.
class CollisionSampler {
 public:
  CollisionSampler(int d, double mi, double mj, double theta_i, double theta_j, double alpha, unsigned long seed)
      : d_(d),
        mi_(mi),
        mj_(mj),
        si_(1 / std::sqrt(2 * theta_i)),
        sj_(1 / std::sqrt(2 * theta_j)),
        alpha_(alpha),
        rng_(gsl_rng_alloc(gsl_rng_mt19937)) {
    gsl_rng_set(rng_, seed);
  }
  CollisionSampler(const CollisionSampler&) = delete;
  CollisionSampler& operator=(const CollisionSampler&) = delete;
  ~CollisionSampler() { gsl_rng_free(rng_); }

  Collision draw() {
    Collision c;
    Vec n{};
    for (int k = 0; k < d_; ++k) {
      c.v1[k] = gsl_ran_gaussian(rng_, si_);
      c.v2[k] = gsl_ran_gaussian(rng_, sj_);
      n[k] = gsl_ran_gaussian(rng_, 1.0);
    }
    const double norm = std::sqrt(dot(n, n, d_));
    for (int k = 0; k < d_; ++k) n[k] /= norm;
    Vec g{};
    for (int k = 0; k < d_; ++k) g[k] = c.v1[k] - c.v2[k];
    const double sg = dot(n, g, d_);
    c.weight = sg > 0 ? sg : 0;
    const double mu_i = mi_ / (mi_ + mj_), mu_j = mj_ / (mi_ + mj_);
    for (int k = 0; k < d_; ++k) {
      c.v1p[k] = c.v1[k] - mu_j * (1 + alpha_) * sg * n[k];
      c.v2p[k] = c.v2[k] + mu_i * (1 + alpha_) * sg * n[k];
    }
    return c;
  }

 private:
  int d_;
  double mi_, mj_, si_, sj_, alpha_;
  gsl_rng* rng_;
};

/// Returns Σ w h / Σ w over `samples` collisions with its standard error (delta method),
/// for each integrand h in `integrands`.
inline std::vector<Estimate> weighted_averages(CollisionSampler& sampler, long samples,
                                               const std::vector<std::function<double(const Collision&)>>& integrands) {
  RatioAverages acc(integrands.size());
  for (long s = 0; s < samples; ++s) {
    const Collision c = sampler.draw();
    if (c.weight == 0) continue;
    acc.sample(c.weight);
    for (std::size_t k = 0; k < integrands.size(); ++k) acc.add(k, c.weight, integrands[k](c));
  }
  std::vector<Estimate> out(integrands.size());
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = acc.estimate(k);
  return out;
}

/// Returns E[w] = E[Θ(σ̂·g)(σ̂·g)] with its standard error, from plain sampling.
inline Estimate mean_weight(CollisionSampler& sampler, long samples,
                            const std::function<double(const Collision&)>& factor) {
  double s = 0, s2 = 0;
  for (long k = 0; k < samples; ++k) {
    const Collision c = sampler.draw();
    const double x = c.weight * factor(c);
    s += x;
    s2 += x * x;
  }
  const double mean = s / samples;
  return {mean, std::sqrt(std::max(s2 / samples - mean * mean, 0.0) / samples)};
}

}  // namespace gkt::test
