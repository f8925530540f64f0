// DSMC of the homogeneous cooling state of smooth disks and spheres (homogeneous_dsmc.hpp):
// v1' = v1 − ((1+α)/2)(σ̂·g)σ̂, v2' = v2 + ((1+α)/2)(σ̂·g)σ̂ (docs/theory.md (1.2)); the dense
// (Enskog) gas collides χ times as often (docs/theory.md §21.7).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dsmc_support.hpp"

namespace gkt {

using detail::Vec3;

namespace {

void check_restitution(const SmoothRestitution& r) {
  if (r.series.empty()) {
    if (!(r.alpha > 0 && r.alpha <= 1))
      throw std::invalid_argument("alpha: must be a number in (0, 1], got " + std::to_string(r.alpha));
    return;
  }
  if (!(r.delta_prime >= 0 && std::isfinite(r.delta_prime)))
    throw std::invalid_argument("delta_prime: must be a finite number >= 0, got " + std::to_string(r.delta_prime));
}

}  // namespace

SmoothDsmcRun run_smooth_hcs_dsmc(int d, const SmoothRestitution& restitution, const DsmcSchedule& schedule,
                                  double pair_correlation) {
  detail::check_schedule(d, schedule);
  check_restitution(restitution);
  if (!(pair_correlation >= 1 && std::isfinite(pair_correlation)))
    throw std::invalid_argument("pair_correlation: the contact value chi must be a finite number >= 1, got " +
                                std::to_string(pair_correlation));
  RandomStream rng(schedule.seed);
  const auto n = static_cast<std::size_t>(schedule.particles);
  const double count = static_cast<double>(n), reference = 0.5;  // rescaled to 2T/m = 1: c = v
  std::vector<Vec3> v(n, Vec3{0, 0, 0});
  for (auto& p : v)
    for (int k = 0; k < d; ++k) p[k] = rng.gaussian();
  double energy = 0, vmax = 0;  // Σ v² (m = 1), max |v| since the last rescaling
  detail::DsmcClock clock;
  auto temperature = [&] { return energy / (d * count); };
  // Zero momentum (collisions conserve it; a rescaling would amplify its round-off), then T = 1/2.
  auto rescale = [&] {
    energy = detail::remove_mean_velocity(v, d);
    const double before = temperature(), scale = std::sqrt(reference / before);
    clock.rescaled(before, reference);
    vmax = 0;
    for (auto& p : v) {
      for (int k = 0; k < d; ++k) p[k] *= scale;
      vmax = std::max(vmax, std::sqrt(detail::dot3(p, p)));
    }
    energy = reference * d * count;
  };
  // Enskog, homogeneous: the rate of every pair is χ times the Boltzmann one (theory.md (21.4)).
  const double frequency = detail::reference_frequency_factor(d),
               pair_time = 2 / ((count - 1) * detail::collision_solid_angle(d) * pair_correlation);
  auto collide = [&](long target) {
    long accepted = 0, since_rescale = 0;
    while (accepted < target) {
      const double gmax = 2 * vmax;
      clock.candidate(frequency, temperature(), pair_time / gmax);
      detail::CandidateCollision c;
      // rejected with probability 1 − rate·|g|/g_max (the majorant)
      if (!detail::draw_candidate(rng, v, d, d, gmax, detail::unit_rate, c)) continue;
      const std::size_t i = c.i, j = c.j;
      const Vec3& g = c.g;
      const Vec3& sigma = c.sigma;
      const double sg = detail::dot3(sigma, g);
      const double alpha = restitution.at(sg / std::sqrt(2 * temperature()));
      energy -= detail::dot3(v[i], v[i]) + detail::dot3(v[j], v[j]);
      for (int k = 0; k < d; ++k) {
        v[i][k] -= 0.5 * (1 + alpha) * sg * sigma[k];
        v[j][k] += 0.5 * (1 + alpha) * sg * sigma[k];
      }
      energy += detail::dot3(v[i], v[i]) + detail::dot3(v[j], v[j]);
      vmax = std::max({vmax, std::sqrt(detail::dot3(v[i], v[i])), std::sqrt(detail::dot3(v[j], v[j]))});
      ++accepted;
      if (++since_rescale == static_cast<long>(n)) {  // keep T = O(1), g_max tight
        rescale();
        since_rescale = 0;
      }
    }
    rescale();
  };
  rescale();
  collide(detail::collision_target(schedule.relaxation, schedule.particles));
  clock.start(temperature());
  SmoothDsmcRun run;
  run.speed_histogram.assign(static_cast<std::size_t>(schedule.histogram_bins), 0.0);
  const long per_batch = detail::collision_target(schedule.per_batch, schedule.particles);
  for (int b = 0; b < schedule.batches; ++b) {
    const double tau = clock.tau(), log_t = clock.log_temperature(temperature());
    collide(per_batch);
    run.cooling_rate.push_back(-(clock.log_temperature(temperature()) - log_t) / (clock.tau() - tau));
    run.trace.time.push_back(clock.time());
    run.trace.temperature.push_back(std::exp(clock.log_temperature(temperature())));
    double c4 = 0, c6 = 0;
    const double thermal2 = 2 * temperature();
    for (const auto& p : v) {
      const double c2 = detail::dot3(p, p) / thermal2;
      c4 += c2 * c2 / count;
      c6 += c2 * c2 * c2 / count;
      if (!run.speed_histogram.empty()) detail::add_to_histogram(run.speed_histogram, schedule.histogram_width, c2);
    }
    run.c4.push_back(c4);
    run.c6.push_back(c6);
  }
  const double samples = count * schedule.batches;
  for (double& h : run.speed_histogram) h /= samples;
  return run;
}

}  // namespace gkt
