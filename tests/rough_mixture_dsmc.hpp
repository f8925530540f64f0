// Test helper: a minimal DSMC of the homogeneous binary mixture of rough spheres (d = 3), independent
// of the engine: pairs drawn uniformly and accepted with probability σ_pq² Θ(u) u/(σ_max² u_max),
// σ̂ uniform, the collision applied by the rigid-body rule of rough_mixture_monte_carlo.hpp (impulse
// solved numerically). Velocities and spins are rescaled by one common factor after every N accepted
// collisions (all temperature ratios unchanged), the mean velocity removed. Measures per batch
// γ_i = T_t,i/T (T = Σx_i T_t,i) and θ_i = T_r,i/T_t,i.
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include "rough_mixture_monte_carlo.hpp"

namespace gkt::test {

/// Batch means of γ_1, γ_2, θ_1, θ_2 and their standard errors; and of the cumulants (a20_1, a02_1, a11_1,
/// a20_2, a02_2, a11_2) of theory.md (19.170), each batch's from its own moments: a20 = (d/(d+2))⟨X²⟩/⟨X⟩² − 1,
/// a02 likewise in Y (d_r = 3), a11 = ⟨XY⟩/(⟨X⟩⟨Y⟩) − 1, X ∝ m v², Y ∝ Iω² per species.
struct RoughMixtureDsmcResult {
  std::array<double, 4> mean{}, error{};
  std::array<double, 6> cumulant_mean{}, cumulant_error{};
};

/// Runs the DSMC with n_k particles of species k, pair restitutions at 0 (1–1), 1 (1–2), 2 (2–2).
inline RoughMixtureDsmcResult run_rough_mixture_dsmc(const std::array<McRoughSpecies, 2>& species,
                                                     const std::array<int, 2>& count,
                                                     const std::array<double, 3>& alpha,
                                                     const std::array<double, 3>& beta, double relaxation, int batches,
                                                     double per_batch, unsigned long seed) {
  gsl_rng* rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, seed);
  const int n = count[0] + count[1];
  std::vector<int> kind(static_cast<std::size_t>(n));
  std::vector<Vec3> v(static_cast<std::size_t>(n)), omega(static_cast<std::size_t>(n));
  for (int p = 0; p < n; ++p) {
    const int k = p < count[0] ? 0 : 1;
    kind[static_cast<std::size_t>(p)] = k;
    const auto& s = species[static_cast<std::size_t>(k)];
    for (int c = 0; c < 3; ++c) {
      v[static_cast<std::size_t>(p)][c] = gsl_ran_gaussian(rng, std::sqrt(1.0 / s.mass));
      omega[static_cast<std::size_t>(p)][c] = gsl_ran_gaussian(rng, std::sqrt(1.0 / s.inertia()));
    }
  }
  const auto temperatures = [&] {
    std::array<double, 4> t{};  // T_t,1, T_t,2, T_r,1, T_r,2
    for (int p = 0; p < n; ++p) {
      const int k = kind[static_cast<std::size_t>(p)];
      const auto& s = species[static_cast<std::size_t>(k)];
      t[static_cast<std::size_t>(k)] +=
          s.mass * dot3(v[static_cast<std::size_t>(p)], v[static_cast<std::size_t>(p)]) / 3;
      t[static_cast<std::size_t>(2 + k)] +=
          s.inertia() * dot3(omega[static_cast<std::size_t>(p)], omega[static_cast<std::size_t>(p)]) / 3;
    }
    for (int k = 0; k < 2; ++k) {
      t[static_cast<std::size_t>(k)] /= count[static_cast<std::size_t>(k)];
      t[static_cast<std::size_t>(2 + k)] /= count[static_cast<std::size_t>(k)];
    }
    return t;
  };
  const double x1 = static_cast<double>(count[0]) / n, x2 = 1 - x1;
  double u_max = 0;
  const auto rescale = [&] {
    Vec3 momentum{};
    double mass = 0;
    for (int p = 0; p < n; ++p) {
      const double m = species[static_cast<std::size_t>(kind[static_cast<std::size_t>(p)])].mass;
      mass += m;
      for (int c = 0; c < 3; ++c) momentum[c] += m * v[static_cast<std::size_t>(p)][c];
    }
    const auto t = temperatures();
    const double factor = std::sqrt(1.0 / (x1 * t[0] + x2 * t[1]));
    double speed = 0;
    for (int p = 0; p < n; ++p) {
      for (int c = 0; c < 3; ++c) {
        v[static_cast<std::size_t>(p)][c] = (v[static_cast<std::size_t>(p)][c] - momentum[c] / mass) * factor;
        omega[static_cast<std::size_t>(p)][c] *= factor;
      }
      speed = std::max(speed, std::sqrt(dot3(v[static_cast<std::size_t>(p)], v[static_cast<std::size_t>(p)])));
    }
    u_max = 2 * speed;
  };
  rescale();
  const double sigma_max = std::max(species[0].diameter, species[1].diameter);
  const auto collide = [&](long accepted_target) {
    long accepted = 0;
    while (accepted < accepted_target) {
      const auto [p, q, sigma] = draw_candidate(rng, n);
      const auto& a = v[static_cast<std::size_t>(p)];
      const auto& b = v[static_cast<std::size_t>(q)];
      const double u = (a[0] - b[0]) * sigma[0] + (a[1] - b[1]) * sigma[1] + (a[2] - b[2]) * sigma[2];
      if (u <= 0) continue;
      const int kp = kind[static_cast<std::size_t>(p)], kq = kind[static_cast<std::size_t>(q)];
      const double d_pq =
          0.5 * (species[static_cast<std::size_t>(kp)].diameter + species[static_cast<std::size_t>(kq)].diameter);
      if (u > u_max) u_max = u;
      if (gsl_rng_uniform(rng) * sigma_max * sigma_max * u_max > d_pq * d_pq * u) continue;
      RoughMixtureCollision c;
      c.w.w[0] = a;
      c.w.w[1] = b;
      c.omega[0] = omega[static_cast<std::size_t>(p)];
      c.omega[1] = omega[static_cast<std::size_t>(q)];
      c.sigma = sigma;
      const std::size_t pair = static_cast<std::size_t>(kp + kq);
      apply_rough_mixture_rule(c, species[static_cast<std::size_t>(kp)], species[static_cast<std::size_t>(kq)],
                               alpha[pair], beta[pair], false);
      v[static_cast<std::size_t>(p)] = c.w.w[4];
      v[static_cast<std::size_t>(q)] = c.w.w[5];
      omega[static_cast<std::size_t>(p)] = c.omega[2];
      omega[static_cast<std::size_t>(q)] = c.omega[3];
      ++accepted;
      if (accepted % n == 0) rescale();
    }
  };
  collide(static_cast<long>(relaxation * n / 2));
  std::vector<std::array<double, 4>> samples;
  std::vector<std::array<double, 6>> cumulant_samples;
  for (int b = 0; b < batches; ++b) {
    collide(static_cast<long>(per_batch * n / 2));
    const auto t = temperatures();
    const double mix = x1 * t[0] + x2 * t[1];
    samples.push_back({t[0] / mix, t[1] / mix, t[2] / t[0], t[3] / t[1]});
    std::array<std::array<double, 5>, 2> sums{};  // ⟨X⟩, ⟨Y⟩, ⟨X²⟩, ⟨Y²⟩, ⟨XY⟩ (unnormalised X = m v², Y = Iω²)
    for (int p = 0; p < n; ++p) {
      const auto k = static_cast<std::size_t>(kind[static_cast<std::size_t>(p)]);
      const double x = species[k].mass * dot3(v[static_cast<std::size_t>(p)], v[static_cast<std::size_t>(p)]);
      const double y =
          species[k].inertia() * dot3(omega[static_cast<std::size_t>(p)], omega[static_cast<std::size_t>(p)]);
      sums[k][0] += x;
      sums[k][1] += y;
      sums[k][2] += x * x;
      sums[k][3] += y * y;
      sums[k][4] += x * y;
    }
    std::array<double, 6> c{};
    for (std::size_t k = 0; k < 2; ++k) {
      const double cnt = count[k];
      const double mx = sums[k][0] / cnt, my = sums[k][1] / cnt;
      c[3 * k] = 0.6 * sums[k][2] / cnt / (mx * mx) - 1;
      c[3 * k + 1] = 0.6 * sums[k][3] / cnt / (my * my) - 1;
      c[3 * k + 2] = sums[k][4] / cnt / (mx * my) - 1;
    }
    cumulant_samples.push_back(c);
  }
  gsl_rng_free(rng);
  RoughMixtureDsmcResult r;
  for (std::size_t k = 0; k < 4; ++k) {
    double s = 0, s2 = 0;
    for (const auto& x : samples) {
      s += x[k];
      s2 += x[k] * x[k];
    }
    r.mean[k] = s / batches;
    r.error[k] = std::sqrt(std::max(s2 / batches - r.mean[k] * r.mean[k], 0.0) / (batches - 1));
  }
  for (std::size_t k = 0; k < 6; ++k) {
    double s = 0, s2 = 0;
    for (const auto& x : cumulant_samples) {
      s += x[k];
      s2 += x[k] * x[k];
    }
    r.cumulant_mean[k] = s / batches;
    r.cumulant_error[k] =
        std::sqrt(std::max(s2 / batches - r.cumulant_mean[k] * r.cumulant_mean[k], 0.0) / (batches - 1));
  }
  return r;
}

}  // namespace gkt::test
