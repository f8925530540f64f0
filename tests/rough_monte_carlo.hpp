// Test helper: rough-sphere collisions drawn independently of the engine. Velocities and spins
// are sampled from their Maxwellians, σ̂ uniformly, and the collision is applied in vector form
// from the impulse J (cross products, no reduction to components):
//   g_c = v1 − v2 + (w1 + w2) × σ̂  (disks: (w1 + w2) ẑ × σ̂),   w = (σ/2)ω,
//   J/m = −((1+α)/2) u σ̂ − (κ/(1+κ))((1+β)/2) g_c,t,
//   v1' = v1 + J/m, v2' = v2 − J/m, w_k' = w_k + (1/κ) σ̂ × J/m  (disks: z component).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include "ratio_averages.hpp"

namespace gkt::test {

using Vec3 = std::array<double, 3>;

inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double dot3(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// Pre- and post-collisional (v, w) of both partners; for disks v has z = 0 and w = (0, 0, w_z).
struct RoughCollision {
  std::array<Vec3, 8> w{};  // v1, v2, w1, w2, v1', v2', w1', w2' (the order of gkt::RoughSlot)
  double weight = 0;        // Θ(u) u
};

/// Applies the rough collision rule for unit vector sigma (from 1 to 2) in place on c.w[4..7].
inline void apply_rough_rule(RoughCollision& c, const Vec3& sigma, double alpha, double beta, double kappa) {
  Vec3 gc{};
  const Vec3 spin_sum{c.w[2][0] + c.w[3][0], c.w[2][1] + c.w[3][1], c.w[2][2] + c.w[3][2]};
  const Vec3 rim = cross(spin_sum, sigma);
  for (int k = 0; k < 3; ++k) gc[k] = c.w[0][k] - c.w[1][k] + rim[k];
  const double u = dot3(sigma, gc);  // = σ̂·(v1 − v2): the rim term is tangential
  Vec3 j{};
  for (int k = 0; k < 3; ++k) {
    const double gct = gc[k] - u * sigma[k];
    j[k] = -0.5 * (1 + alpha) * u * sigma[k] - kappa / (1 + kappa) * 0.5 * (1 + beta) * gct;
  }
  const Vec3 torque = cross(sigma, j);
  for (int k = 0; k < 3; ++k) {
    c.w[4][k] = c.w[0][k] + j[k];
    c.w[5][k] = c.w[1][k] - j[k];
    c.w[6][k] = c.w[2][k] + torque[k] / kappa;
    c.w[7][k] = c.w[3][k] + torque[k] / kappa;
  }
  c.weight = u > 0 ? u : 0;
}

/// Walton's tangential restitution for this pre-collisional pair (docs/theory.md §19.10):
/// β(γ) = min{β0, −1 + ((1+κ)/κ)(1+α) μ_f cot γ}, cot γ = (σ̂·g_c)/|g_c,t|; μ_f = inf gives β0.
inline double walton_beta(const RoughCollision& c, const Vec3& sigma, double alpha, double beta0, double kappa,
                          double friction) {
  if (std::isinf(friction)) return beta0;
  const Vec3 spin_sum{c.w[2][0] + c.w[3][0], c.w[2][1] + c.w[3][1], c.w[2][2] + c.w[3][2]};
  const Vec3 rim = cross(spin_sum, sigma);
  Vec3 gc{};
  for (int k = 0; k < 3; ++k) gc[k] = c.w[0][k] - c.w[1][k] + rim[k];
  const double u = dot3(sigma, gc);
  double t2 = 0;
  for (int k = 0; k < 3; ++k) t2 += (gc[k] - u * sigma[k]) * (gc[k] - u * sigma[k]);
  if (t2 == 0) return beta0;
  return std::min(beta0, -1 + (1 + kappa) / kappa * (1 + alpha) * friction * u / std::sqrt(t2));
}

/// Draws collisions: v ~ exp(−v²), w ~ exp(−(κ/θ) w²) (θ = T_r/T_t), σ̂ uniform; with a finite
/// friction the tangential restitution of each collision is walton_beta(…, beta, …, friction).
class RoughCollisionSampler {
 public:
  RoughCollisionSampler(int d, double alpha, double beta, double kappa, double theta, unsigned long seed,
                        double friction = std::numeric_limits<double>::infinity())
      : d_(d),
        alpha_(alpha),
        beta_(beta),
        kappa_(kappa),
        friction_(friction),
        spin_sd_(std::sqrt(theta / (2 * kappa))),
        rng_(gsl_rng_alloc(gsl_rng_mt19937)) {
    gsl_rng_set(rng_, seed);
  }
  RoughCollisionSampler(const RoughCollisionSampler&) = delete;
  RoughCollisionSampler& operator=(const RoughCollisionSampler&) = delete;
  ~RoughCollisionSampler() { gsl_rng_free(rng_); }

  RoughCollision draw() {
    RoughCollision c;
    Vec3 n{};
    for (int k = 0; k < d_; ++k) {
      c.w[0][k] = gsl_ran_gaussian(rng_, std::sqrt(0.5));
      c.w[1][k] = gsl_ran_gaussian(rng_, std::sqrt(0.5));
      n[k] = gsl_ran_gaussian(rng_, 1.0);
    }
    for (int k = d_ == 3 ? 0 : 2; k < 3; ++k) {
      c.w[2][k] = gsl_ran_gaussian(rng_, spin_sd_);
      c.w[3][k] = gsl_ran_gaussian(rng_, spin_sd_);
    }
    const double norm = std::sqrt(dot3(n, n));
    for (auto& x : n) x /= norm;
    apply_rough_rule(c, n, alpha_, walton_beta(c, n, alpha_, beta_, kappa_, friction_), kappa_);
    sigma_ = n;
    return c;
  }
  /// Returns σ̂ of the last draw (to replay the collision with another rule).
  [[nodiscard]] const Vec3& last_sigma() const { return sigma_; }

 private:
  int d_;
  double alpha_, beta_, kappa_, friction_, spin_sd_;
  Vec3 sigma_{};
  gsl_rng* rng_;
};

}  // namespace gkt::test
