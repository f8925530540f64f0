// DSMC of the homogeneous cooling state of a granular mixture (homogeneous_dsmc.hpp):
// v1' = v1 − μ_ji(1+α_ij)(σ̂·g)σ̂, v2' = v2 + μ_ij(1+α_ij)(σ̂·g)σ̂ (docs/theory.md (16.1)).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dsmc_support.hpp"

namespace gkt {

using detail::Vec3;

namespace {

void check_species(const std::vector<DsmcSpecies>& species, const std::vector<double>& alpha) {
  auto fail = [](const std::string& m) { throw std::invalid_argument(m); };
  const std::size_t s = species.size();
  if (s < 1 || s > 16) fail("species: must be 1 to 16 species, got " + std::to_string(s));
  long total = 0;
  for (std::size_t a = 0; a < s; ++a) {
    const std::string i = std::to_string(a + 1);
    if (species[a].count < 1)
      fail("particles_" + i + ": must be an integer >= 1, got " + std::to_string(species[a].count));
    if (!(species[a].mass > 0 && std::isfinite(species[a].mass)))
      fail("mass_" + i + ": must be a finite number > 0, got " + std::to_string(species[a].mass));
    if (!(species[a].diameter > 0 && std::isfinite(species[a].diameter)))
      fail("diameter_" + i + ": must be a finite number > 0, got " + std::to_string(species[a].diameter));
    total += species[a].count;
  }
  if (total < 2 || total > 100000000) fail("particles: must be an integer in [2, 10^8], got " + std::to_string(total));
  if (alpha.size() != s * s)
    fail("alpha: must hold " + std::to_string(s * s) + " values (s x s), got " + std::to_string(alpha.size()));
  for (std::size_t a = 0; a < s; ++a)
    for (std::size_t b = 0; b < s; ++b) {
      const std::string name = "alpha_" + std::to_string(std::min(a, b) + 1) + "_" + std::to_string(std::max(a, b) + 1);
      if (!(alpha[a * s + b] > 0 && alpha[a * s + b] <= 1))
        fail(name + ": must be a number in (0, 1], got " + std::to_string(alpha[a * s + b]));
      if (alpha[a * s + b] != alpha[b * s + a]) fail(name + ": the alpha matrix must be symmetric");
    }
}

}  // namespace

MixtureDsmcRun run_mixture_hcs_dsmc(int d, const std::vector<DsmcSpecies>& species, const std::vector<double>& alpha,
                                    const DsmcSchedule& schedule) {
  detail::check_schedule(d, schedule, true);
  check_species(species, alpha);
  const std::size_t s = species.size();
  std::vector<std::size_t> kind;
  for (std::size_t a = 0; a < s; ++a) kind.insert(kind.end(), static_cast<std::size_t>(species[a].count), a);
  const std::size_t n = kind.size();
  const double count = static_cast<double>(n), reference = 0.5;
  double mean_mass = 0, mean_diameter = 0, sigma_max = 0;  // m̄, σ̄ (mole fractions), max σ_ij^{d−1}
  for (std::size_t a = 0; a < s; ++a) {
    mean_mass += species[a].count / count * species[a].mass;
    mean_diameter += species[a].count / count * species[a].diameter;
    for (std::size_t b = 0; b < s; ++b)
      sigma_max = std::max(sigma_max, std::pow(0.5 * (species[a].diameter + species[b].diameter), d - 1));
  }
  std::vector<double> weight(s * s);  // σ_ij^{d−1}/σ_max^{d−1}
  for (std::size_t a = 0; a < s; ++a)
    for (std::size_t b = 0; b < s; ++b)
      weight[a * s + b] = std::pow(0.5 * (species[a].diameter + species[b].diameter), d - 1) / sigma_max;
  RandomStream rng(schedule.seed);
  std::vector<Vec3> v(n, Vec3{0, 0, 0});
  for (std::size_t p = 0; p < n; ++p)
    for (int k = 0; k < d; ++k) v[p][k] = rng.gaussian() / std::sqrt(species[kind[p]].mass);
  double energy = 0, vmax = 0;  // Σ m v²
  detail::DsmcClock clock;
  auto temperature = [&] { return energy / (d * count); };
  auto rescale = [&] {  // zero momentum, then T = Σ m v²/(dN) = 1/2 by one common factor
    Vec3 momentum{0, 0, 0};
    double total_mass = 0;
    for (std::size_t p = 0; p < n; ++p) {
      total_mass += species[kind[p]].mass;
      for (int k = 0; k < d; ++k) momentum[k] += species[kind[p]].mass * v[p][k];
    }
    energy = 0;
    for (std::size_t p = 0; p < n; ++p)
      for (int k = 0; k < d; ++k) {
        v[p][k] -= momentum[k] / total_mass;
        energy += species[kind[p]].mass * v[p][k] * v[p][k];
      }
    const double before = temperature(), scale = std::sqrt(reference / before);
    clock.rescaled(before, reference);
    vmax = 0;
    for (auto& p : v) {
      for (int k = 0; k < d; ++k) p[k] *= scale;
      vmax = std::max(vmax, std::sqrt(detail::dot3(p, p)));
    }
    energy = reference * d * count;
  };
  const double frequency =
                   detail::reference_frequency_factor(d) * std::pow(mean_diameter, d - 1) / std::sqrt(mean_mass),
               pair_time = 2 / ((count - 1) * detail::collision_solid_angle(d) * sigma_max);
  auto collide = [&](long target) {
    long accepted = 0, since_rescale = 0;
    while (accepted < target) {
      const double gmax = 2 * vmax;
      clock.candidate(frequency, temperature(), pair_time / gmax);
      const auto rate = [&](std::size_t i, std::size_t j) { return weight[kind[i] * s + kind[j]]; };
      detail::CandidateCollision c;
      if (!detail::draw_candidate(rng, v, d, d, gmax, rate, c)) continue;
      const std::size_t i = c.i, j = c.j;
      const std::size_t a = kind[i], b = kind[j];
      const Vec3& g = c.g;
      const Vec3& sigma = c.sigma;
      const double sg = detail::dot3(sigma, g);
      const double ma = species[a].mass, mb = species[b].mass, impulse = (1 + alpha[a * s + b]) * sg / (ma + mb);
      energy -= ma * detail::dot3(v[i], v[i]) + mb * detail::dot3(v[j], v[j]);
      for (int k = 0; k < d; ++k) {
        v[i][k] -= mb * impulse * sigma[k];
        v[j][k] += ma * impulse * sigma[k];
      }
      energy += ma * detail::dot3(v[i], v[i]) + mb * detail::dot3(v[j], v[j]);
      vmax = std::max({vmax, std::sqrt(detail::dot3(v[i], v[i])), std::sqrt(detail::dot3(v[j], v[j]))});
      ++accepted;
      if (++since_rescale == static_cast<long>(n)) {
        rescale();
        since_rescale = 0;
      }
    }
    rescale();
  };
  rescale();
  collide(detail::collision_target(schedule.relaxation, static_cast<long>(n)));
  clock.start(temperature());
  MixtureDsmcRun run;
  run.temperature_ratio.assign(s, {});
  run.a2.assign(s, {});
  const long per_batch = detail::collision_target(schedule.per_batch, static_cast<long>(n));
  for (int batch = 0; batch < schedule.batches; ++batch) {
    const double tau = clock.tau(), log_t = clock.log_temperature(temperature());
    collide(per_batch);
    run.cooling_rate.push_back(-(clock.log_temperature(temperature()) - log_t) / (clock.tau() - tau));
    run.trace.time.push_back(clock.time());
    run.trace.temperature.push_back(std::exp(clock.log_temperature(temperature())));
    std::vector<double> v2(s, 0), v4(s, 0);
    for (std::size_t p = 0; p < n; ++p) {
      const double q = detail::dot3(v[p], v[p]);
      v2[kind[p]] += q;
      v4[kind[p]] += q * q;
    }
    for (std::size_t a = 0; a < s; ++a) {
      const double m = species[a].mass, t = m * v2[a] / (d * species[a].count);  // T_a
      run.temperature_ratio[a].push_back(t / temperature());
      const double c4 = v4[a] / species[a].count * m * m / (4 * t * t);  // ⟨c⁴⟩, c² = m v²/(2T_a)
      run.a2[a].push_back(c4 / (d * (d + 2) / 4.0) - 1);
    }
  }
  return run;
}

}  // namespace gkt
