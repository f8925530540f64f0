// DSMC of the quasi-smooth limit (quasi_smooth_limit_dsmc.hpp; docs/theory.md §19.18, (19.60)): the
// translation of N particles with frozen spins W (|W| = 1), smooth inelastic collisions plus the
// momentum-conserving kick ∓(W1 + W2) × σ̂. No rescaling is needed: the kicks feed what the inelastic
// collisions take, and T_t is stationary. The cooling rate is that of the spins, from (19.61):
// ζ/η_t = (2/κ) Σ_collisions Σ_p |W_p − (σ̂·W_p)σ̂|² / (Σ_q |W_q|² Δt).
#include "gkt/simulation/quasi_smooth_limit_dsmc.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dsmc_support.hpp"

namespace gkt {

using detail::Vec3;

namespace {

void check_limit(int d, const QuasiSmoothLimitParameters& p) {
  if (d != 2 && d != 3) throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(d));
  if (!(p.alpha > 0 && p.alpha < 1))
    throw std::invalid_argument("alpha: must be a number in (0, 1) (no stationary state at 1), got " +
                                std::to_string(p.alpha));
  if (!(p.kappa > 0 && p.kappa <= 1))
    throw std::invalid_argument("kappa: must be a number in (0, 1], got " + std::to_string(p.kappa));
}

}  // namespace

double quasi_smooth_limit_spin_cumulant(int d) {
  if (d != 2 && d != 3) throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(d));
  const double dr = d == 3 ? 3 : 1;
  return -2 / (dr + 2);
}

QuasiSmoothLimitRun run_quasi_smooth_limit_dsmc(int d, const QuasiSmoothLimitParameters& parameters,
                                                const DsmcSchedule& schedule) {
  detail::check_schedule(d, schedule);
  check_limit(d, parameters);
  const double alpha = parameters.alpha, kappa = parameters.kappa, dr = d == 3 ? 3 : 1;
  RandomStream rng(schedule.seed);
  const auto n = static_cast<std::size_t>(schedule.particles);
  const double count = static_cast<double>(n);
  std::vector<Vec3> v(n, Vec3{0, 0, 0}), w(n, Vec3{0, 0, 1});
  // Start near the Maxwellian limit (d − 1)η_t²θ/κ = (1 − α²)/2 (theory.md §19.5): ⟨v²⟩ = (d/d_r) κ/(θη_t²).
  const double start_sd = std::sqrt(2 * (d - 1) / (dr * (1 - alpha * alpha)));
  for (std::size_t q = 0; q < n; ++q) {
    for (int k = 0; k < d; ++k) v[q][k] = rng.gaussian() * start_sd;
    if (d == 3) {  // uniform direction
      Vec3 g{rng.gaussian(), rng.gaussian(), rng.gaussian()};
      const double norm = std::sqrt(detail::dot3(g, g));
      for (double& c : g) c /= norm;
      w[q] = g;
    } else if (rng.uniform() < 0.5) {
      w[q][2] = -1;
    }
  }
  double energy = detail::remove_mean_velocity(v, d), vmax = 0;
  auto refresh = [&] {  // the exact Σv² and the majorant max|v|, against round-off drift
    energy = detail::remove_mean_velocity(v, d);
    vmax = 0;
    for (const auto& x : v) vmax = std::max(vmax, std::sqrt(detail::dot3(x, x)));
  };
  refresh();
  detail::DsmcClock clock;
  const double frequency = detail::reference_frequency_factor(d),
               pair_time = 2 / ((count - 1) * detail::collision_solid_angle(d));
  double perpendicular = 0;  // Σ over collisions and partners of |W_p − (σ̂·W_p)σ̂|²
  // Snapshot sums (every N collisions within a batch): ⟨v²⟩, ⟨v⁴⟩, C, and their count.
  double snap_v2 = 0, snap_v4 = 0, snap_c = 0, snaps = 0;
  auto snapshot = [&] {
    double v2 = 0, v4 = 0, c = 0;
    for (std::size_t q = 0; q < n; ++q) {
      const double x = detail::dot3(v[q], v[q]), proj = detail::dot3(v[q], w[q]);
      v2 += x / count;
      v4 += x * x / count;
      if (x > 0) c += proj * proj / x / count;
    }
    snap_v2 += v2;
    snap_v4 += v4 / (v2 * v2);
    snap_c += c;
    snaps += 1;
  };
  auto collide = [&](long target, bool sample) {
    long accepted = 0, since_refresh = 0;
    while (accepted < target) {
      const double gmax = 2 * vmax;
      clock.candidate(frequency, energy / (d * count), pair_time / gmax);
      detail::CandidateCollision c;
      // rejected with probability 1 − rate·|g|/g_max (the majorant)
      if (!detail::draw_candidate(rng, v, d, 3, gmax, detail::unit_rate, c)) continue;
      const std::size_t i = c.i, j = c.j;
      const Vec3& g = c.g;
      const Vec3& sigma = c.sigma;
      const double u = detail::dot3(sigma, g);
      const Vec3 kick = detail::cross(Vec3{w[i][0] + w[j][0], w[i][1] + w[j][1], w[i][2] + w[j][2]}, sigma);
      energy -= detail::dot3(v[i], v[i]) + detail::dot3(v[j], v[j]);
      for (int k = 0; k < 3; ++k) {
        const double dv = 0.5 * (1 + alpha) * u * sigma[k] + kick[k];
        v[i][k] -= dv;
        v[j][k] += dv;
      }
      energy += detail::dot3(v[i], v[i]) + detail::dot3(v[j], v[j]);
      vmax = std::max({vmax, std::sqrt(detail::dot3(v[i], v[i])), std::sqrt(detail::dot3(v[j], v[j]))});
      const double ci = detail::dot3(sigma, w[i]), cj = detail::dot3(sigma, w[j]);
      perpendicular += 2 - ci * ci - cj * cj;
      ++accepted;
      if (++since_refresh == static_cast<long>(n)) {
        refresh();
        if (sample) snapshot();
        since_refresh = 0;
      }
    }
    refresh();
    if (sample) snapshot();
  };
  collide(detail::collision_target(schedule.relaxation, schedule.particles), false);
  QuasiSmoothLimitRun run;
  const long per_batch = detail::collision_target(schedule.per_batch, schedule.particles);
  for (int b = 0; b < schedule.batches; ++b) {
    const double tau = clock.tau();
    perpendicular = snap_v2 = snap_v4 = snap_c = snaps = 0;
    collide(per_batch, true);
    run.cooling_rate_over_eta.push_back(2 / kappa * perpendicular / (count * (clock.tau() - tau)));
    run.temperature_ratio_eta_squared.push_back(d / dr * kappa * snaps / snap_v2);
    run.a20.push_back(snap_v4 / snaps * d / (d + 2) - 1);
    if (d == 3) run.orientation.push_back(snap_c / snaps);
  }
  return run;
}

}  // namespace gkt
