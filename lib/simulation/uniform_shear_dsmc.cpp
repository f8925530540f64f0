// DSMC of the uniform shear flow (uniform_shear_dsmc.hpp; docs/theory.md §22.5). Streaming is
// applied lazily: a particle's V_x is brought to the current time t, V_x −= a (t − t_i) V_y, only
// when it is drawn or at a flush (every N/8 accepted collisions and at the end of each batch), exact
// because V_y is constant between its collisions. The majorant grows with the shear:
// |V(t)| ≤ |V(t_f)| (1 + |a|(t − t_f)) for a particle last updated at t_f ≥ t_ref, so
// g_max(t) = 2 v_ref (1 + a (t − t_ref)), v_ref the largest speed at the last flush or since.
// The Enskog gas (φ > 0; [montanero1997], docs/theory.md §22.8): the partner sits at
// r + σσ̂, so its velocity relative to u(r) is V_j + a σ σ̂_y x̂ and the pair collides with rate
// χ (σ̂·g)_+, g = V_i − V_j − a σ σ̂_y x̂ (22.13a); σ̂ is drawn uniformly and accepted against
// g_max + a σ; the impulses, carried over the distance σσ̂, are the collisional stress (22.13b).
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "dsmc_support.hpp"
#include "gkt/simulation/uniform_shear_dsmc.hpp"

namespace gkt {

using detail::Vec3;

UniformShearDsmcRun run_uniform_shear_dsmc(int d, const UniformShearDsmcParameters& parameters,
                                           const DsmcSchedule& schedule) {
  detail::check_schedule(d, schedule);
  if (!(parameters.alpha > 0 && parameters.alpha < 1))
    throw std::invalid_argument("alpha: must be a number in (0, 1) (no steady shear flow at alpha = 1), got " +
                                std::to_string(parameters.alpha));
  if (!(parameters.shear_rate > 0 && parameters.shear_rate <= 100))
    throw std::invalid_argument("shear_rate: must be a number in (0, 100], got " +
                                std::to_string(parameters.shear_rate));
  const double phi_max = d == 2 ? 0.7 : 0.5;  // max_packing_fraction (pair_correlation.hpp)
  if (!(parameters.packing_fraction >= 0 && parameters.packing_fraction <= phi_max))
    throw std::invalid_argument("packing_fraction: must be a number in [0, " + std::to_string(phi_max) + "], got " +
                                std::to_string(parameters.packing_fraction));
  if (!(parameters.pair_correlation >= 1 && std::isfinite(parameters.pair_correlation)))
    throw std::invalid_argument("pair_correlation: the contact value chi must be a finite number >= 1, got " +
                                std::to_string(parameters.pair_correlation));
  RandomStream rng(schedule.seed);
  const auto n = static_cast<std::size_t>(schedule.particles);
  const double count = static_cast<double>(n), initial = 0.5;      // units n = σ = m = 1, 2T/m = 1 at start
  const double frequency = detail::reference_frequency_factor(d);  // ν0(T) = frequency √T
  const double a = parameters.shear_rate * frequency * std::sqrt(initial);
  const double length = d == 2 ? 0.5 : 1 / std::numbers::pi;  // ℓ = 1/(2nσ), 1/(πnσ²)
  const double alpha = parameters.alpha;
  // Units n σ^{d−1} = 1 (the rates); the diameter is then n σ^d = φ/v_d, v_d = π/4 (2D), π/6 (3D).
  const bool dense = parameters.packing_fraction > 0 || parameters.pair_correlation != 1;
  const double chi = parameters.pair_correlation,
               diameter = parameters.packing_fraction / (d == 2 ? std::numbers::pi / 4 : std::numbers::pi / 6);
  std::array<double, 4> impulse{};  // Σ J σ̂_i σ̂_j over the batch (xx, yy, zz, xy), J = ((1+α)/2) σ̂·g
  std::vector<Vec3> v(n, Vec3{0, 0, 0});
  for (auto& p : v)
    for (int k = 0; k < d; ++k) p[k] = std::sqrt(initial) * rng.gaussian();
  std::vector<double> updated(n, 0.0);  // the time each particle's V_x was last streamed to
  double t = 0, t_ref = 0, v_ref = 0;
  auto stream = [&](std::size_t i) {
    v[i][0] -= a * (t - updated[i]) * v[i][1];
    updated[i] = t;
  };
  // Streams every particle to t, removes the centre-of-mass velocity (collisions conserve it, the
  // streaming only turns ⟨V_y⟩ into ⟨V_x⟩) and restarts the majorant.
  auto flush = [&] {
    Vec3 mean{0, 0, 0};
    for (std::size_t i = 0; i < n; ++i) {
      stream(i);
      for (int k = 0; k < d; ++k) mean[k] += v[i][k] / count;
    }
    v_ref = 0;
    for (auto& p : v) {
      for (int k = 0; k < d; ++k) p[k] -= mean[k];
      v_ref = std::max(v_ref, std::sqrt(detail::dot3(p, p)));
    }
    t_ref = t;
  };
  const double pair_time = 2 / ((count - 1) * detail::collision_solid_angle(d));
  const double dense_pair_time = 2 / ((count - 1) * (d == 2 ? 2 * std::numbers::pi : 4 * std::numbers::pi) * chi);
  const long flush_every = std::max(1L, static_cast<long>(n) / 8);
  // One candidate of the dilute gas: σ̂ drawn with weight (σ̂·ĝ)_+ after the acceptance by |g|.
  auto dilute_candidate = [&](std::size_t i, std::size_t j) {
    // The candidate rate uses g_max at the start of the step; it grows by a relative a Δt = O(1/N).
    const double gmax = 2 * v_ref * (1 + a * (t - t_ref));
    t += pair_time / gmax;
    stream(i);
    stream(j);
    Vec3 g{0, 0, 0};
    for (int k = 0; k < d; ++k) g[k] = v[i][k] - v[j][k];
    const double gn = std::sqrt(detail::dot3(g, g));
    if (rng.uniform() * gmax >= gn) return false;  // rejected: the pair's rate is |g|/g_max of the majorant
    const Vec3 ghat{g[0] / gn, g[1] / gn, g[2] / gn};
    const Vec3 sigma = detail::collision_direction(rng, d, ghat);
    const double sg = detail::dot3(sigma, g);
    for (int k = 0; k < d; ++k) {
      v[i][k] -= 0.5 * (1 + alpha) * sg * sigma[k];
      v[j][k] += 0.5 * (1 + alpha) * sg * sigma[k];
    }
    return true;
  };
  // One candidate of the Enskog gas: σ̂ uniform on the sphere (circle), accepted with probability
  // (σ̂·g)_+/(g_max + a σ), g shifted by the partner's streaming velocity (22.13a).
  auto dense_candidate = [&](std::size_t i, std::size_t j) {
    const double gmax = 2 * v_ref * (1 + a * (t - t_ref)) + a * diameter;
    t += dense_pair_time / gmax;
    stream(i);
    stream(j);
    Vec3 sigma{0, 0, 0};
    const double angle = 2 * std::numbers::pi * rng.uniform();
    if (d == 2) {
      sigma = {std::cos(angle), std::sin(angle), 0};
    } else {
      const double z = 2 * rng.uniform() - 1, r = std::sqrt(1 - z * z);
      sigma = {r * std::cos(angle), r * std::sin(angle), z};
    }
    Vec3 g{0, 0, 0};
    for (int k = 0; k < d; ++k) g[k] = v[i][k] - v[j][k];
    g[0] -= a * diameter * sigma[1];
    const double sg = detail::dot3(sigma, g);
    if (rng.uniform() * gmax >= sg) return false;  // also every receding pair (σ̂·g ≤ 0)
    const double impulse_size = 0.5 * (1 + alpha) * sg;
    for (int k = 0; k < d; ++k) {
      v[i][k] -= impulse_size * sigma[k];
      v[j][k] += impulse_size * sigma[k];
    }
    impulse[0] += impulse_size * sigma[0] * sigma[0];
    impulse[1] += impulse_size * sigma[1] * sigma[1];
    impulse[2] += impulse_size * sigma[2] * sigma[2];
    impulse[3] += impulse_size * sigma[0] * sigma[1];
    return true;
  };
  auto collide = [&](long target) {
    long accepted = 0, since_flush = 0;
    while (accepted < target) {
      const std::size_t i = rng.below(n);
      std::size_t j = rng.below(n - 1);
      if (j >= i) ++j;
      if (!(dense ? dense_candidate(i, j) : dilute_candidate(i, j))) continue;
      v_ref = std::max({v_ref, std::sqrt(detail::dot3(v[i], v[i])), std::sqrt(detail::dot3(v[j], v[j]))});
      ++accepted;
      if (++since_flush == flush_every) {
        flush();
        since_flush = 0;
      }
    }
    flush();
  };
  flush();
  collide(detail::collision_target(schedule.relaxation, schedule.particles));
  UniformShearDsmcRun run;
  const long per_batch = detail::collision_target(schedule.per_batch, schedule.particles);
  for (int b = 0; b < schedule.batches; ++b) {
    const double batch_start = t;
    double start_temperature = 0;  // velocities are current after collide()'s closing flush
    for (const auto& p : v) start_temperature += detail::dot3(p, p) / (d * count);
    impulse = {};
    collide(per_batch);
    std::array<double, 4> sum{};  // Σ V_x², V_y², V_z², V_x V_y
    for (const auto& p : v) {
      sum[0] += p[0] * p[0];
      sum[1] += p[1] * p[1];
      sum[2] += p[2] * p[2];
      sum[3] += p[0] * p[1];
    }
    const double temperature = (sum[0] + sum[1] + sum[2]) / (d * count), thermal2 = 2 * temperature * count;
    run.reduced_shear_rate.push_back(a * length / std::sqrt(2 * temperature));
    run.stress_xx.push_back(sum[0] / thermal2);
    run.stress_yy.push_back(sum[1] / thermal2);
    run.stress_zz.push_back(sum[2] / thermal2);
    run.stress_xy.push_back(sum[3] / thermal2);
    run.temperature.push_back(temperature / initial);
    // P^c_ij = (n σ/(N Δt)) Σ J σ̂_i σ̂_j (22.13b), in units n σ^{d−1} = 1 (n = nσ^d/σ = diameter);
    // over 2nT with T averaged over the batch (Σ J ∝ ∫T dt: exact for a T linear in t).
    const double collisional = diameter / (count * (t - batch_start) * (start_temperature + temperature));
    const std::array<double, 4> c{impulse[0] * collisional, impulse[1] * collisional, impulse[2] * collisional,
                                  impulse[3] * collisional};
    run.collisional_xx.push_back(c[0]);
    run.collisional_yy.push_back(c[1]);
    run.collisional_zz.push_back(c[2]);
    run.collisional_xy.push_back(c[3]);
    run.stress_xx.back() += c[0];
    run.stress_yy.back() += c[1];
    run.stress_zz.back() += c[2];
    run.stress_xy.back() += c[3];
  }
  return run;
}

}  // namespace gkt
