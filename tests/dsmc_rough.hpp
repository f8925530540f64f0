// Test helper: DSMC of the homogeneous cooling state of rough spheres (d = 3) or disks (d = 2),
// independent of the engine (the pattern of tests/dsmc.hpp, plus spin). Pairs are accepted with
// probability |g|/g_max (g_max = 2 max|v|, updated after every collision, a valid majorant), σ̂
// has density ∝ (σ̂·ĝ)_+ (the collision rate does not depend on the spin), the collision is the
// impulse form of tests/rough_monte_carlo.hpp, and v and w are rescaled by one common factor to
// ⟨v²⟩ = d/2 after every N collisions (the HCS, and θ, are invariant under common rescaling).
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include "dsmc.hpp"
#include "rough_monte_carlo.hpp"

namespace gkt::test {

/// Batch means and standard errors of θ = T_r/T_t, the cumulants a20, a02, a11 and C.
struct RoughHcsSample {
  double theta = 0, theta_error = 0, a20 = 0, a20_error = 0, a02 = 0, a02_error = 0, a11 = 0, a11_error = 0;
  double orientation = 0, orientation_error = 0;  ///< C = ⟨(v·w)²/(v²w²)⟩ (d = 3)
};

inline RoughHcsSample run_rough_hcs_dsmc(int d, double alpha, double beta, double kappa, double theta_start,
                                         int particles, double relax, int batches, double per_batch, unsigned long seed,
                                         double friction = std::numeric_limits<double>::infinity(),
                                         double dilatation = 0) {
  gsl_rng* rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, seed);
  const int dr = d == 3 ? 3 : 1;
  std::vector<Vec3> v(static_cast<std::size_t>(particles), {0, 0, 0}), w = v;
  for (std::size_t p = 0; p < v.size(); ++p) {
    for (int k = 0; k < d; ++k) v[p][k] = gsl_ran_gaussian(rng, std::sqrt(0.5));
    for (int k = 3 - dr; k < 3; ++k) w[p][k] = gsl_ran_gaussian(rng, std::sqrt(theta_start / (2 * kappa)));
  }
  double vmax = 0;
  // Uniform dilatation ∇·u = ε ν0(T_t) (3D; ε = `dilatation`): peculiar velocities shrink as
  // dV/dt = −(∇·u/d)V, the spin is untouched. One accepted collision advances ν0 t by (4/5)(2/N)
  // (collision frequency per particle 4nσ²√(πT/m) = (5/4)ν0); applied to v before every rescaling.
  long pending = 0;
  auto dilate = [&]() {
    if (dilatation != 0 && pending > 0) {
      const double shrink = std::exp(-dilatation / d * 1.6 * static_cast<double>(pending) / particles);
      for (auto& p : v)
        for (int k = 0; k < d; ++k) p[k] *= shrink;
    }
    pending = 0;
  };
  auto rescale = [&]() {
    dilate();
    Vec3 mean{0, 0, 0};
    for (const auto& p : v)
      for (int k = 0; k < d; ++k) mean[k] += p[k] / particles;
    double c2 = 0;
    for (auto& p : v)
      for (int k = 0; k < d; ++k) {
        p[k] -= mean[k];
        c2 += p[k] * p[k];
      }
    const double scale = std::sqrt(0.5 * d * particles / c2);
    vmax = 0;
    for (auto& p : v) {
      for (int k = 0; k < d; ++k) p[k] *= scale;
      vmax = std::max(vmax, std::sqrt(dot3(p, p)));
    }
    for (auto& p : w)
      for (auto& x : p) x *= scale;
  };
  auto collide = [&](double collisions_per_particle) {
    rescale();
    long accepted = 0, since_rescale = 0;
    const long target = static_cast<long>(collisions_per_particle * particles / 2);
    while (accepted < target) {
      const auto i = gsl_rng_uniform_int(rng, static_cast<unsigned long>(particles));
      auto j = gsl_rng_uniform_int(rng, static_cast<unsigned long>(particles - 1));
      if (j >= i) ++j;
      Vec3 g{};
      for (int k = 0; k < 3; ++k) g[k] = v[i][k] - v[j][k];
      const double gn = std::sqrt(dot3(g, g));
      if (gsl_rng_uniform(rng) * 2 * vmax >= gn) continue;
      const Vec3 ghat{g[0] / gn, g[1] / gn, g[2] / gn};
      const Vec3 sigma = collision_direction(rng, d, ghat);
      RoughCollision c;
      c.w[0] = v[i];
      c.w[1] = v[j];
      c.w[2] = w[i];
      c.w[3] = w[j];
      apply_rough_rule(c, sigma, alpha, walton_beta(c, sigma, alpha, beta, kappa, friction), kappa);
      v[i] = c.w[4];
      v[j] = c.w[5];
      w[i] = c.w[6];
      w[j] = c.w[7];
      vmax = std::max({vmax, std::sqrt(dot3(v[i], v[i])), std::sqrt(dot3(v[j], v[j]))});
      ++accepted;
      // in small steps (every N/100 collisions), so that no sawtooth phase biases the batch means
      if (dilatation != 0 && ++pending * 100 >= particles) dilate();
      if (++since_rescale == particles) {
        rescale();
        since_rescale = 0;
      }
    }
  };
  collide(relax);
  std::vector<double> thetas, a20s, a02s, a11s, cs;
  for (int b = 0; b < batches; ++b) {
    collide(per_batch);
    double v2 = 0, v4 = 0, w2 = 0, w4 = 0, vw = 0, c = 0;
    for (std::size_t p = 0; p < v.size(); ++p) {
      const double x = dot3(v[p], v[p]), y = dot3(w[p], w[p]);
      v2 += x / particles;
      v4 += x * x / particles;
      w2 += y / particles;
      w4 += y * y / particles;
      vw += x * y / particles;
      const double proj = dot3(v[p], w[p]);
      if (x > 0 && y > 0) c += proj * proj / (x * y) / particles;
    }
    cs.push_back(c);
    thetas.push_back((kappa * w2 / dr) / (v2 / d));
    a20s.push_back(v4 / (v2 * v2) * d / (d + 2) - 1);
    a02s.push_back(w4 / (w2 * w2) * dr / (dr + 2) - 1);
    a11s.push_back(vw / (v2 * w2) - 1);
  }
  gsl_rng_free(rng);
  RoughHcsSample s;
  batch_mean(thetas, s.theta, s.theta_error);
  batch_mean(a20s, s.a20, s.a20_error);
  batch_mean(a02s, s.a02, s.a02_error);
  batch_mean(a11s, s.a11, s.a11_error);
  batch_mean(cs, s.orientation, s.orientation_error);
  return s;
}

}  // namespace gkt::test
