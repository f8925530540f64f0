// DSMC of a homogeneous gas of sticking grains (homogeneous_dsmc.hpp), independent of the
// population balance: clusters carry a size k (mass k, diameter k^{1/d}) and a velocity.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dsmc_support.hpp"

namespace gkt {

using detail::Vec3;

std::vector<AggregationDsmcSample> run_aggregation_dsmc(int d, double alpha, double critical_energy, int criterion,
                                                        int particles, const std::vector<double>& times,
                                                        std::uint64_t seed) {
  auto fail = [](const std::string& m) { throw std::invalid_argument(m); };
  if (d != 2 && d != 3) fail("dimension: must be 2 or 3, got " + std::to_string(d));
  if (!(alpha > 0 && alpha <= 1)) fail("alpha: must be a number in (0, 1], got " + std::to_string(alpha));
  if (!(critical_energy >= 0 && std::isfinite(critical_energy)))
    fail("critical_energy: must be a finite number >= 0, got " + std::to_string(critical_energy));
  if (criterion != 0 && criterion != 1) fail("criterion: must be 0 (relative speed) or 1 (normal impact)");
  if (particles < 2 || particles > 100000000)
    fail("particles: must be an integer in [2, 10^8], got " + std::to_string(particles));
  for (std::size_t k = 0; k < times.size(); ++k)
    if (!(times[k] > 0 && std::isfinite(times[k])) || (k > 0 && times[k] <= times[k - 1]))
      fail("times: must be finite, positive and increasing");
  RandomStream rng(seed);
  std::vector<int> size(static_cast<std::size_t>(particles), 1);
  std::vector<Vec3> v(static_cast<std::size_t>(particles), Vec3{0, 0, 0});
  Vec3 mean{0, 0, 0};
  for (auto& u : v)
    for (int a = 0; a < d; ++a) {
      u[a] = rng.gaussian();
      mean[a] += u[a] / particles;
    }
  for (auto& u : v)
    for (int a = 0; a < d; ++a) u[a] -= mean[a];
  const double volume = particles, solid = detail::collision_solid_angle(d);
  const auto speed = [](const Vec3& u) { return std::sqrt(detail::dot3(u, u)); };
  double v_max = 0;
  int k_max = 1;
  for (const auto& u : v) v_max = std::max(v_max, speed(u));
  double t = 0;
  std::vector<AggregationDsmcSample> out;
  AggregationDsmcSample window;
  std::size_t next = 0;
  while (next < times.size()) {
    const auto n = static_cast<double>(size.size());
    const double bound = std::pow(std::pow(k_max, 1.0 / d), d - 1) * 2 * v_max;  // ≥ σ_ij^{d−1} |g_ij|
    const double majorant = 0.5 * n * (n - 1) * solid * bound / volume;
    t += -std::log(1 - rng.uniform()) / majorant;
    while (next < times.size() && t > times[next]) {
      double e = 0;
      for (std::size_t p = 0; p < size.size(); ++p) e += size[p] * detail::dot3(v[p], v[p]);
      window.number = n / particles;
      window.temperature = e / (d * n);
      out.push_back(window);
      window = AggregationDsmcSample{};
      ++next;
    }
    if (next == times.size() || size.size() < 2) break;
    const std::size_t a = rng.below(size.size());
    std::size_t b = rng.below(size.size() - 1);
    if (b >= a) ++b;
    Vec3 g{0, 0, 0};
    for (int c = 0; c < d; ++c) g[c] = v[a][c] - v[b][c];
    const double gm = speed(g);
    const double sigma = 0.5 * (std::pow(size[a], 1.0 / d) + std::pow(size[b], 1.0 / d));
    if (rng.uniform() * bound >= std::pow(sigma, d - 1) * gm) continue;  // null collision
    ++window.collisions;
    const Vec3 ghat{g[0] / gm, g[1] / gm, g[2] / gm};
    const Vec3 s = detail::collision_direction(rng, d, ghat);
    const double gn = detail::dot3(g, s);
    const double ma = size[a], mb = size[b], mu = ma * mb / (ma + mb);
    const double threshold = critical_energy * mu / 0.5;  // θ*_ij = θ*_11 μ_ij/μ_11, μ_11 = 1/2
    const double energy = criterion == 0 ? 0.5 * mu * gm * gm : 0.5 * mu * gn * gn;
    if (energy < threshold) {  // merge into a: centre-of-mass velocity, mass a + b
      ++window.sticks;
      for (int c = 0; c < d; ++c) v[a][c] = (ma * v[a][c] + mb * v[b][c]) / (ma + mb);
      size[a] += size[b];
      k_max = std::max(k_max, size[a]);
      size[b] = size.back();
      v[b] = v.back();
      size.pop_back();
      v.pop_back();
      continue;
    }
    const double impulse = (1 + alpha) * gn;
    for (int c = 0; c < d; ++c) {
      v[a][c] -= mb / (ma + mb) * impulse * s[c];
      v[b][c] += ma / (ma + mb) * impulse * s[c];
    }
    v_max = std::max({v_max, speed(v[a]), speed(v[b])});
  }
  return out;
}

}  // namespace gkt
