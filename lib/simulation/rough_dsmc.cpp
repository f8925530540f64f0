// DSMC of the homogeneous cooling state of rough spheres and disks (homogeneous_dsmc.hpp). The
// collision in impulse form (docs/theory.md §19.1), w = (σ/2)ω:
//   g_c = v1 − v2 + (w1 + w2) × σ̂,  J/m = −((1+α)/2)(σ̂·g_c)σ̂ − (κ/(1+κ))((1+β)/2) g_c,t,
//   v1' = v1 + J/m, v2' = v2 − J/m, w_k' = w_k + (1/κ) σ̂ × J/m;
// the collision rate depends on σ̂·(v1 − v2) only (the rim velocity is tangential).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dsmc_support.hpp"

namespace gkt {

using detail::Vec3;

namespace {

void check_rough(const RoughDsmcParameters& p) {
  auto fail = [](const std::string& m) { throw std::invalid_argument(m); };
  if (!(p.alpha > 0 && p.alpha <= 1)) fail("alpha: must be a number in (0, 1], got " + std::to_string(p.alpha));
  if (!(p.beta >= -1 && p.beta <= 1)) fail("beta: must be a number in [-1, 1], got " + std::to_string(p.beta));
  if (!(p.kappa > 0 && p.kappa <= 1)) fail("kappa: must be a number in (0, 1], got " + std::to_string(p.kappa));
  if (!(p.friction >= 0))
    fail("friction: must be a number >= 0 (inf: constant beta), got " + std::to_string(p.friction));
  if (!(p.initial_temperature_ratio > 0 && std::isfinite(p.initial_temperature_ratio)))
    fail("temperature_ratio: the initial T_r/T_t must be a finite number > 0, got " +
         std::to_string(p.initial_temperature_ratio));
  if (!(std::abs(p.dilatation) <= 10))
    fail("dilatation: must be a number in [-10, 10], got " + std::to_string(p.dilatation));
}

/// Applies one collision with unit vector σ̂ to (v1, v2, w1, w2) in place.
void collide_rough(Vec3& v1, Vec3& v2, Vec3& w1, Vec3& w2, const Vec3& sigma, const RoughDsmcParameters& p) {
  const Vec3 rim = detail::cross(Vec3{w1[0] + w2[0], w1[1] + w2[1], w1[2] + w2[2]}, sigma);
  Vec3 gc{};
  for (int k = 0; k < 3; ++k) gc[k] = v1[k] - v2[k] + rim[k];
  const double u = detail::dot3(sigma, gc);
  Vec3 tangential{};
  for (int k = 0; k < 3; ++k) tangential[k] = gc[k] - u * sigma[k];
  double beta = p.beta;
  if (std::isfinite(p.friction)) {  // Walton: the sliding contact takes at most μ_f times the normal impulse
    const double t = std::sqrt(detail::dot3(tangential, tangential));
    if (t > 0) beta = std::min(p.beta, -1 + (1 + p.kappa) / p.kappa * (1 + p.alpha) * p.friction * u / t);
  }
  Vec3 j{};
  for (int k = 0; k < 3; ++k)
    j[k] = -0.5 * (1 + p.alpha) * u * sigma[k] - p.kappa / (1 + p.kappa) * 0.5 * (1 + beta) * tangential[k];
  const Vec3 torque = detail::cross(sigma, j);
  for (int k = 0; k < 3; ++k) {
    v1[k] += j[k];
    v2[k] -= j[k];
    w1[k] += torque[k] / p.kappa;
    w2[k] += torque[k] / p.kappa;
  }
}

}  // namespace

RoughDsmcRun run_rough_hcs_dsmc(int d, const RoughDsmcParameters& parameters, const DsmcSchedule& schedule) {
  detail::check_schedule(d, schedule);
  check_rough(parameters);
  const RoughDsmcParameters& p = parameters;
  const int dr = d == 3 ? 3 : 1;  // rotational degrees of freedom
  RandomStream rng(schedule.seed);
  const auto n = static_cast<std::size_t>(schedule.particles);
  const double count = static_cast<double>(n), reference = 0.5;
  std::vector<Vec3> v(n, Vec3{0, 0, 0}), w = v;
  const double spin_sd = std::sqrt(p.initial_temperature_ratio / (2 * p.kappa));  // T_r = θ T_t, T_t = 1/2
  for (std::size_t q = 0; q < n; ++q) {
    for (int k = 0; k < d; ++k) v[q][k] = rng.gaussian() * std::sqrt(0.5);
    for (int k = 3 - dr; k < 3; ++k) w[q][k] = rng.gaussian() * spin_sd;
  }
  double energy = 0, vmax = 0, pending = 0;  // Σ v², max |v|, ν0 t not yet dilated
  detail::DsmcClock clock;
  auto temperature = [&] { return energy / (d * count); };  // T_t
  auto dilate = [&] {
    if (p.dilatation == 0 || pending == 0) return;
    const double shrink = std::exp(-p.dilatation / d * pending);
    for (auto& x : v)
      for (int k = 0; k < d; ++k) x[k] *= shrink;
    energy *= shrink * shrink;
    vmax *= std::max(shrink, 1.0);
    pending = 0;
  };
  auto rescale = [&] {  // zero momentum, then T_t = 1/2; v and w by one common factor
    dilate();
    Vec3 mean{0, 0, 0};
    for (const auto& x : v)
      for (int k = 0; k < d; ++k) mean[k] += x[k] / count;
    energy = 0;
    for (auto& x : v)
      for (int k = 0; k < d; ++k) {
        x[k] -= mean[k];
        energy += x[k] * x[k];
      }
    const double before = temperature(), scale = std::sqrt(reference / before);
    clock.rescaled(before, reference);
    vmax = 0;
    for (auto& x : v) {
      for (int k = 0; k < d; ++k) x[k] *= scale;
      vmax = std::max(vmax, std::sqrt(detail::dot3(x, x)));
    }
    for (auto& x : w)
      for (double& c : x) c *= scale;
    energy = reference * d * count;
  };
  const double frequency = detail::reference_frequency_factor(d),
               pair_time = 2 / ((count - 1) * detail::collision_solid_angle(d));
  auto collide = [&](long target) {
    long accepted = 0, since_rescale = 0, since_dilation = 0;
    while (accepted < target) {
      const double gmax = 2 * vmax, tau = clock.tau();
      clock.candidate(frequency, temperature(), pair_time / gmax);
      pending += clock.tau() - tau;
      detail::CandidateCollision c;
      // rejected with probability 1 − rate·|g|/g_max (the majorant)
      if (!detail::draw_candidate(rng, v, d, 3, gmax, detail::unit_rate, c)) continue;
      const std::size_t i = c.i, j = c.j;
      const Vec3& sigma = c.sigma;
      energy -= detail::dot3(v[i], v[i]) + detail::dot3(v[j], v[j]);
      collide_rough(v[i], v[j], w[i], w[j], sigma, p);
      energy += detail::dot3(v[i], v[i]) + detail::dot3(v[j], v[j]);
      vmax = std::max({vmax, std::sqrt(detail::dot3(v[i], v[i])), std::sqrt(detail::dot3(v[j], v[j]))});
      ++accepted;
      // the dilatation in small steps (every N/100 collisions): no sawtooth phase biases the batch means
      if (p.dilatation != 0 && ++since_dilation * 100 >= static_cast<long>(n)) {
        dilate();
        since_dilation = 0;
      }
      if (++since_rescale == static_cast<long>(n)) {
        rescale();
        since_rescale = 0;
      }
    }
    rescale();
  };
  rescale();
  collide(detail::collision_target(schedule.relaxation, schedule.particles));
  clock.start(temperature());
  RoughDsmcRun run;
  run.speed_histogram.assign(static_cast<std::size_t>(schedule.histogram_bins), 0.0);
  const long per_batch = detail::collision_target(schedule.per_batch, schedule.particles);
  for (int b = 0; b < schedule.batches; ++b) {
    const double tau = clock.tau(), log_t = clock.log_temperature(temperature());
    collide(per_batch);
    run.cooling_rate.push_back(-(clock.log_temperature(temperature()) - log_t) / (clock.tau() - tau));
    run.trace.time.push_back(clock.time());
    run.trace.temperature.push_back(std::exp(clock.log_temperature(temperature())));
    double v2 = 0, v4 = 0, w2 = 0, w4 = 0, w6 = 0, vw = 0, c = 0;
    for (std::size_t q = 0; q < n; ++q) {
      const double x = detail::dot3(v[q], v[q]), y = detail::dot3(w[q], w[q]);
      v2 += x / count;
      v4 += x * x / count;
      w2 += y / count;
      w4 += y * y / count;
      w6 += y * y * y / count;
      vw += x * y / count;
      const double proj = detail::dot3(v[q], w[q]);
      if (x > 0 && y > 0) c += proj * proj / (x * y) / count;
      if (!run.speed_histogram.empty())
        detail::add_to_histogram(run.speed_histogram, schedule.histogram_width, x / (2 * temperature()));
    }
    run.temperature_ratio.push_back((p.kappa * w2 / dr) / (v2 / d));
    run.a20.push_back(v4 / (v2 * v2) * d / (d + 2) - 1);
    run.a02.push_back(w4 / (w2 * w2) * dr / (dr + 2) - 1);
    run.a11.push_back(vw / (v2 * w2) - 1);
    run.a03.push_back(w6 / (w2 * w2 * w2) * dr * dr / ((dr + 2) * (dr + 4)) - 1);
    run.orientation.push_back(c);
  }
  const double samples = count * schedule.batches;
  for (double& h : run.speed_histogram) h /= samples;
  return run;
}

}  // namespace gkt
