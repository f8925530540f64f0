// The shear viscosity from the relaxation of a strained HCS (shear_viscosity_dsmc.hpp;
// docs/theory.md §21.6). Same pair selection, majorant, collision rule, clock and rescaling as
// run_smooth_hcs_dsmc; in addition the running sum S = Σ v_x v_y is kept per collision and the
// integrand M w = (S/(2NT)) √(T_phys/T_kick) is integrated exactly over the clock τ (it is constant
// between accepted collisions).
#include "gkt/simulation/shear_viscosity_dsmc.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dsmc_support.hpp"

namespace gkt {

using detail::Vec3;

ShearViscosityDsmcRun run_shear_viscosity_dsmc(int d, const ShearViscosityDsmcParameters& parameters,
                                               const DsmcSchedule& schedule) {
  detail::check_schedule(d, schedule);
  if (!(parameters.alpha > 0 && parameters.alpha <= 1))
    throw std::invalid_argument("alpha: must be a number in (0, 1], got " + std::to_string(parameters.alpha));
  if (!(parameters.kick > 0 && parameters.kick <= 0.5))
    throw std::invalid_argument("viscosity_kick: must be a number in (0, 0.5], got " + std::to_string(parameters.kick));
  RandomStream rng(schedule.seed);
  const auto n = static_cast<std::size_t>(schedule.particles);
  const double count = static_cast<double>(n), reference = 0.5, alpha = parameters.alpha, eps = parameters.kick;
  std::vector<Vec3> v(n, Vec3{0, 0, 0});
  for (auto& p : v)
    for (int k = 0; k < d; ++k) p[k] = rng.gaussian();
  double energy = 0, vmax = 0, shear = 0;  // Σ v², max |v| since the last rescaling, Σ v_x v_y
  detail::DsmcClock clock;
  auto temperature = [&] { return energy / (d * count); };
  // The weight √(T_phys/T_kick) = √(factor · T), factor = e^{ln(T_phys/T0) − ln(T_kick/T0)}/T_run
  // refreshed at each rescaling (T_run the run's temperature, T_phys its physical one).
  double log_kick = 0, factor = 1;
  auto rescale = [&] {
    energy = detail::remove_mean_velocity(v, d);
    const double before = temperature(), scale = std::sqrt(reference / before);
    clock.rescaled(before, reference);
    vmax = 0;
    shear = 0;
    for (auto& p : v) {
      for (int k = 0; k < d; ++k) p[k] *= scale;
      vmax = std::max(vmax, std::sqrt(detail::dot3(p, p)));
      shear += p[0] * p[1];
    }
    energy = reference * d * count;
    factor = std::exp(clock.log_temperature(reference) - log_kick) / reference;
  };
  const double frequency = detail::reference_frequency_factor(d),
               pair_time = 2 / ((count - 1) * detail::collision_solid_angle(d));
  // Runs `target` accepted collisions; returns ∫ M w dτ over them (M = S/(2NT), w = √(factor T)).
  auto collide = [&](long target) {
    long accepted = 0, since_rescale = 0;
    double integral = 0, tau_last = clock.tau();
    double integrand = shear / (2 * count * temperature()) * std::sqrt(factor * temperature());
    while (accepted < target) {
      const double gmax = 2 * vmax;
      clock.candidate(frequency, temperature(), pair_time / gmax);
      detail::CandidateCollision c;
      // rejected with probability 1 − rate·|g|/g_max (the majorant)
      if (!detail::draw_candidate(rng, v, d, d, gmax, detail::unit_rate, c)) continue;
      integral += integrand * (clock.tau() - tau_last);  // the state before this collision held until now
      tau_last = clock.tau();
      const std::size_t i = c.i, j = c.j;
      const Vec3& g = c.g;
      const Vec3& sigma = c.sigma;
      const double sg = detail::dot3(sigma, g);
      energy -= detail::dot3(v[i], v[i]) + detail::dot3(v[j], v[j]);
      shear -= v[i][0] * v[i][1] + v[j][0] * v[j][1];
      for (int k = 0; k < d; ++k) {
        v[i][k] -= 0.5 * (1 + alpha) * sg * sigma[k];
        v[j][k] += 0.5 * (1 + alpha) * sg * sigma[k];
      }
      energy += detail::dot3(v[i], v[i]) + detail::dot3(v[j], v[j]);
      shear += v[i][0] * v[i][1] + v[j][0] * v[j][1];
      vmax = std::max({vmax, std::sqrt(detail::dot3(v[i], v[i])), std::sqrt(detail::dot3(v[j], v[j]))});
      ++accepted;
      if (++since_rescale == static_cast<long>(n)) {  // keep T = O(1), g_max tight, S free of round-off
        rescale();
        since_rescale = 0;
      }
      integrand = shear / (2 * count * temperature()) * std::sqrt(factor * temperature());
    }
    rescale();
    return integral;
  };
  rescale();
  collide(detail::collision_target(schedule.relaxation, schedule.particles));
  clock.start(temperature());
  ShearViscosityDsmcRun run;
  const long per_batch = detail::collision_target(schedule.per_batch, schedule.particles);
  for (int b = 0; b < schedule.batches; ++b) {
    // The kick: a pure strain of sign ±1 (random), V_x += s(ε/2)V_y, V_y += s(ε/2)V_x. It heats the
    // gas by 1 + δ; the scaled stress it makes is (ε/2)/(1 + δ) instead of ε/2, which the estimate
    // divides out (exact for Maxwell molecules, whose second moments relax linearly; §21.6).
    const double sign = rng.uniform() < 0.5 ? -1.0 : 1.0, half = 0.5 * sign * eps, before = temperature();
    energy = 0;
    for (auto& p : v) {
      const double x = p[0], y = p[1];
      p[0] = x + half * y;
      p[1] = y + half * x;
      energy += detail::dot3(p, p);
    }
    const double heating = temperature() / before;
    log_kick = clock.log_temperature(temperature());
    rescale();
    const double tau = clock.tau();
    const double integral = collide(per_batch);
    run.shear_viscosity.push_back(sign * (2 / eps) * heating * integral);
    run.cooling_rate.push_back(-(clock.log_temperature(temperature()) - log_kick) / (clock.tau() - tau));
  }
  return run;
}

}  // namespace gkt
