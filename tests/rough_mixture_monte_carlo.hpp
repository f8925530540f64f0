// Test helper: collisions of two rough species drawn independently of the engine. Velocities v
// and angular velocities ω (not the spin velocities w of the engine) are sampled from each
// species' Maxwellians, σ̂ uniformly, and the impulse J is found by solving the rigid-body contact
// law numerically: the contact points r1 = (σ_i/2)σ̂, r2 = −(σ_j/2)σ̂ move with v + ω × r, an
// impulse J on 1 (−J on 2) changes v1 by J/m_i, ω1 by (r1 × J)/I_i (and 2 likewise), and J solves
//   K J = −(1+α)(σ̂·g_c)σ̂ − (1+β) g_c,t,   K = the 3×3 response of g_c to J,
// with K assembled from these rigid-body equations (no effective mass taken from the derivation).
// The collision is reported in the engine's variables w = (σ/2)ω.
#pragma once

#include <array>
#include <cmath>

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include "rough_monte_carlo.hpp"

namespace gkt::test {

/// One species: mass, diameter, I = κ m σ²/4, temperatures.
struct McRoughSpecies {
  double mass, diameter, kappa, translational_temperature, rotational_temperature;
  [[nodiscard]] double inertia() const { return kappa * mass * diameter * diameter / 4; }
};

/// Pre- and post-collisional state in ω (for conservation checks) and in w (RoughCollision).
struct RoughMixtureCollision {
  RoughCollision w;             // v1, v2, w1, w2, v1', v2', w1', w2'
  std::array<Vec3, 4> omega{};  // ω1, ω2, ω1', ω2'
  Vec3 sigma{};                 // σ̂
};

/// Returns two distinct particles (p, q) of n, uniformly, and a uniform unit vector σ̂ (three Gaussians normalised),
/// the draw of every DSMC collision candidate here.
struct CandidatePair {
  int p = 0, q = 0;
  Vec3 sigma{};
};
inline CandidatePair draw_candidate(gsl_rng* rng, int n) {
  CandidatePair c;
  c.p = static_cast<int>(gsl_rng_uniform_int(rng, static_cast<unsigned long>(n)));
  c.q = static_cast<int>(gsl_rng_uniform_int(rng, static_cast<unsigned long>(n - 1)));
  if (c.q >= c.p) ++c.q;
  c.sigma = {gsl_ran_gaussian(rng, 1.0), gsl_ran_gaussian(rng, 1.0), gsl_ran_gaussian(rng, 1.0)};
  const double norm = std::sqrt(dot3(c.sigma, c.sigma));
  for (auto& s : c.sigma) s /= norm;
  return c;
}

/// Returns the solution x of A x = b (Cramer's rule; A nonsingular).
inline Vec3 solve3(const std::array<Vec3, 3>& a, const Vec3& b) {
  const auto det = [](const std::array<Vec3, 3>& m) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  const double d = det(a);
  Vec3 x{};
  for (int c = 0; c < 3; ++c) {
    auto m = a;
    for (int r = 0; r < 3; ++r) m[r][c] = b[r];
    x[c] = det(m) / d;
  }
  return x;
}

/// Applies the contact law to the pre-collisional part of c (v, ω) for the unit vector sigma.
inline void apply_rough_mixture_rule(RoughMixtureCollision& c, const McRoughSpecies& i, const McRoughSpecies& j,
                                     double alpha, double beta, bool disks) {
  const Vec3& n = c.sigma;
  Vec3 r1{}, r2{};
  for (int k = 0; k < 3; ++k) {
    r1[k] = 0.5 * i.diameter * n[k];
    r2[k] = -0.5 * j.diameter * n[k];
  }
  // Contact velocity difference of 1 relative to 2 after an impulse J (response to J only).
  const auto response = [&](const Vec3& jv) {
    Vec3 dw1 = cross(r1, jv), dw2 = cross(r2, jv);
    for (int k = 0; k < 3; ++k) {
      dw1[k] /= i.inertia();
      dw2[k] = -dw2[k] / j.inertia();
    }
    if (disks) dw1[0] = dw1[1] = dw2[0] = dw2[1] = 0;
    const Vec3 a = cross(dw1, r1), b = cross(dw2, r2);
    Vec3 out{};
    for (int k = 0; k < 3; ++k) out[k] = jv[k] / i.mass + jv[k] / j.mass + a[k] - b[k];
    return out;
  };
  std::array<Vec3, 3> kmat{};
  for (int col = 0; col < 3; ++col) {
    Vec3 e{};
    e[col] = 1;
    const Vec3 r = response(e);
    for (int row = 0; row < 3; ++row) kmat[row][col] = r[row];
  }
  const Vec3 rim1 = cross(c.omega[0], r1), rim2 = cross(c.omega[1], r2);
  Vec3 gc{};
  for (int k = 0; k < 3; ++k) gc[k] = c.w.w[0][k] + rim1[k] - c.w.w[1][k] - rim2[k];
  const double u = dot3(n, gc);
  Vec3 target{};
  for (int k = 0; k < 3; ++k) target[k] = -(1 + alpha) * u * n[k] - (1 + beta) * (gc[k] - u * n[k]);
  const Vec3 jv = solve3(kmat, target);
  const Vec3 t1 = cross(r1, jv), t2 = cross(r2, jv);
  for (int k = 0; k < 3; ++k) {
    c.w.w[4][k] = c.w.w[0][k] + jv[k] / i.mass;
    c.w.w[5][k] = c.w.w[1][k] - jv[k] / j.mass;
    c.omega[2][k] = c.omega[0][k] + t1[k] / i.inertia();
    c.omega[3][k] = c.omega[1][k] - t2[k] / j.inertia();
  }
  for (int k = 0; k < 3; ++k) {
    c.w.w[2][k] = 0.5 * i.diameter * c.omega[0][k];
    c.w.w[3][k] = 0.5 * j.diameter * c.omega[1][k];
    c.w.w[6][k] = 0.5 * i.diameter * c.omega[2][k];
    c.w.w[7][k] = 0.5 * j.diameter * c.omega[3][k];
  }
  c.w.weight = u > 0 ? u : 0;
}

/// Draws i–j collisions: v ~ exp(−m v²/(2T_t)), ω ~ exp(−I ω²/(2T_r)) per species, σ̂ uniform.
class RoughMixtureCollisionSampler {
 public:
  RoughMixtureCollisionSampler(int d, McRoughSpecies i, McRoughSpecies j, double alpha, double beta, unsigned long seed)
      : d_(d), i_(i), j_(j), alpha_(alpha), beta_(beta), rng_(gsl_rng_alloc(gsl_rng_mt19937)) {
    gsl_rng_set(rng_, seed);
  }
  RoughMixtureCollisionSampler(const RoughMixtureCollisionSampler&) = delete;
  RoughMixtureCollisionSampler& operator=(const RoughMixtureCollisionSampler&) = delete;
  ~RoughMixtureCollisionSampler() { gsl_rng_free(rng_); }

  RoughMixtureCollision draw() {
    RoughMixtureCollision c;
    Vec3 n{};
    for (int k = 0; k < d_; ++k) {
      c.w.w[0][k] = gsl_ran_gaussian(rng_, std::sqrt(i_.translational_temperature / i_.mass));
      c.w.w[1][k] = gsl_ran_gaussian(rng_, std::sqrt(j_.translational_temperature / j_.mass));
      n[k] = gsl_ran_gaussian(rng_, 1.0);
    }
    for (int k = d_ == 3 ? 0 : 2; k < 3; ++k) {
      c.omega[0][k] = gsl_ran_gaussian(rng_, std::sqrt(i_.rotational_temperature / i_.inertia()));
      c.omega[1][k] = gsl_ran_gaussian(rng_, std::sqrt(j_.rotational_temperature / j_.inertia()));
    }
    const double norm = std::sqrt(dot3(n, n));
    for (auto& x : n) x /= norm;
    c.sigma = n;
    apply_rough_mixture_rule(c, i_, j_, alpha_, beta_, d_ == 2);
    return c;
  }

 private:
  int d_;
  McRoughSpecies i_, j_;
  double alpha_, beta_;
  gsl_rng* rng_;
};

}  // namespace gkt::test
