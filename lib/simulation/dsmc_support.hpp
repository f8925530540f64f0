// Private pieces shared by the homogeneous DSMC runs (lib/simulation): the direction of a
// collision, the clock, the speed histogram and the schedule checks.
#pragma once

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "gkt/simulation/homogeneous_dsmc.hpp"
#include "gkt/simulation/random_stream.hpp"

namespace gkt::detail {

using Vec3 = std::array<double, 3>;

inline double dot3(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// Returns σ̂ with density ∝ (σ̂·ĝ)_+ on the half sphere (d = 3: cos θ = √U, azimuth uniform) or
/// the half circle (d = 2: sin θ uniform in (−1, 1)), for a unit vector ĝ.
inline Vec3 collision_direction(RandomStream& rng, int d, const Vec3& ghat) {
  if (d == 2) {
    const double sin_t = 2 * rng.uniform() - 1, cos_t = std::sqrt(1 - sin_t * sin_t);
    return {cos_t * ghat[0] - sin_t * ghat[1], cos_t * ghat[1] + sin_t * ghat[0], 0};
  }
  const double cos_t = std::sqrt(rng.uniform()), sin_t = std::sqrt(1 - cos_t * cos_t);
  // an orthonormal pair (e1, e2) orthogonal to ĝ, built from the axis least aligned with ĝ
  const Vec3 axis = std::abs(ghat[0]) < 0.6 ? Vec3{1, 0, 0} : (std::abs(ghat[1]) < 0.6 ? Vec3{0, 1, 0} : Vec3{0, 0, 1});
  Vec3 e1 = cross(ghat, axis);
  const double norm = std::sqrt(dot3(e1, e1));
  for (double& x : e1) x /= norm;
  const Vec3 e2 = cross(ghat, e1);
  const double phi = 2 * std::numbers::pi * rng.uniform(), c = std::cos(phi), s = std::sin(phi);
  Vec3 sigma{};
  for (int k = 0; k < 3; ++k) sigma[k] = cos_t * ghat[k] + sin_t * (c * e1[k] + s * e2[k]);
  return sigma;
}

/// One accepted candidate of the majorant (NTC) collision scheme: the pair i ≠ j, its relative velocity g
/// (the first `components` components, the rest 0), |g| and the collision direction σ̂.
struct CandidateCollision {
  std::size_t i = 0, j = 0;
  Vec3 g{0, 0, 0};
  double speed = 0;
  Vec3 sigma{0, 0, 0};
};

/// Draws a pair i ≠ j uniformly among the particles of `v` and accepts it with probability
/// rate(i, j)·|g|/g_max (the pair's rate over the majorant; rate ≤ 1); on acceptance draws σ̂ (density
/// ∝ (σ̂·ĝ)_+ in dimension d) and returns true. The random numbers are drawn in this order: i, j, the
/// acceptance, then σ̂.
template <class Rate>
bool draw_candidate(RandomStream& rng, const std::vector<Vec3>& v, int d, int components, double gmax, Rate rate,
                    CandidateCollision& out) {
  const std::size_t n = v.size();
  const std::size_t i = rng.below(n);
  std::size_t j = rng.below(n - 1);
  if (j >= i) ++j;
  Vec3 g{0, 0, 0};
  for (int k = 0; k < components; ++k) g[k] = v[i][k] - v[j][k];
  const double gn = std::sqrt(dot3(g, g));
  if (rng.uniform() * gmax >= rate(i, j) * gn) return false;
  out.i = i;
  out.j = j;
  out.g = g;
  out.speed = gn;
  out.sigma = collision_direction(rng, d, Vec3{g[0] / gn, g[1] / gn, g[2] / gn});
  return true;
}

/// The rate factor of a single-species run: every pair at its |g|.
inline double unit_rate(std::size_t, std::size_t) { return 1.0; }

/// Removes the mean velocity from the first d components of every particle (collisions conserve it;
/// a rescaling would amplify its round-off) and returns Σ v² afterwards (m = 1).
inline double remove_mean_velocity(std::vector<Vec3>& v, int d) {
  const double count = static_cast<double>(v.size());
  Vec3 mean{0, 0, 0};
  for (const auto& p : v)
    for (int k = 0; k < d; ++k) mean[k] += p[k] / count;
  double energy = 0;
  for (auto& p : v)
    for (int k = 0; k < d; ++k) {
      p[k] -= mean[k];
      energy += p[k] * p[k];
    }
  return energy;
}

/// β_d = ∫dσ̂ Θ(σ̂·ĝ)(σ̂·ĝ): π (d = 3), 2 (d = 2).
inline double collision_solid_angle(int d) { return d == 3 ? std::numbers::pi : 2.0; }

/// ν0/(n σ̄^{d−1} √(T/m̄)) = 8π^{(d−1)/2}/((d+2)Γ(d/2)) with η0 the elastic first-Sonine viscosity
/// (docs/conventions.md): 16√π/5 (d = 3), 2√π (d = 2).
inline double reference_frequency_factor(int d) {
  return 8 * std::pow(std::numbers::pi, 0.5 * (d - 1)) / ((d + 2) * std::tgamma(0.5 * d));
}

/// The clock of a run in units of ν0: τ = ∫ν0(T(t)) dt (the collision count of the scaled state)
/// and t ν0(T0); ln(T/T0) kept across rescalings.
class DsmcClock {
 public:
  /// Advances by one candidate pair: Δτ = ν0(T) × 2V/(N(N−1) β_d σ_max^{d−1} g_max), with T the
  /// current temperature in the run's units (ν0 ∝ √T with the factor `frequency`).
  void candidate(double frequency, double temperature, double candidate_time) {
    const double dtau = frequency * std::sqrt(temperature) * candidate_time;
    tau_ += dtau;
    time_ += dtau * std::exp(-0.5 * (log_scale_ + std::log(temperature / reference_)));
  }
  /// Records a rescaling of the velocities from temperature `before` to `after`.
  void rescaled(double before, double after) { log_scale_ += std::log(before / after); }
  /// Starts the sampled part: T0 = the current temperature, t = 0 (τ keeps counting).
  void start(double temperature) {
    reference_ = temperature;
    log_scale_ = 0;
    time_ = 0;
  }
  [[nodiscard]] double tau() const { return tau_; }
  [[nodiscard]] double time() const { return time_; }
  /// Returns ln(T/T0) at the run's current temperature `temperature`.
  [[nodiscard]] double log_temperature(double temperature) const {
    return log_scale_ + std::log(temperature / reference_);
  }

 private:
  double tau_ = 0, time_ = 0, log_scale_ = 0, reference_ = 1;
};

/// Adds one speed c = |v|/√(2T/m), given as c², to the histogram (dropped above its last bin).
inline void add_to_histogram(std::vector<double>& counts, double width, double c2) {
  const auto bin = static_cast<std::size_t>(std::sqrt(c2) / width);
  if (bin < counts.size()) counts[bin] += 1;
}

/// Throws std::invalid_argument unless the schedule (and d) are valid; `mixture`: particles unused.
inline void check_schedule(int d, const DsmcSchedule& s, bool mixture = false) {
  auto fail = [](const std::string& m) { throw std::invalid_argument(m); };
  if (d != 2 && d != 3) fail("dimension: must be 2 or 3, got " + std::to_string(d));
  if (!mixture && (s.particles < 2 || s.particles > 100000000))
    fail("particles: must be an integer in [2, 10^8], got " + std::to_string(s.particles));
  if (!(s.relaxation >= 0 && s.relaxation <= 1e6))
    fail("relaxation: collisions per particle must be in [0, 10^6], got " + std::to_string(s.relaxation));
  if (s.batches < 1) fail("batches: must be an integer >= 1, got " + std::to_string(s.batches));
  if (!(s.per_batch > 0 && s.per_batch <= 1e6))
    fail("collisions_per_particle: must be in (0, 10^6] per batch, got " + std::to_string(s.per_batch));
  if (s.histogram_bins < 0 || s.histogram_bins > 100000)
    fail("histogram_bins: must be an integer in [0, 100000], got " + std::to_string(s.histogram_bins));
  if (!(s.histogram_width > 0 && std::isfinite(s.histogram_width)))
    fail("histogram_width: must be a finite number > 0, got " + std::to_string(s.histogram_width));
}

/// Returns the number of accepted collisions of `per_particle` collisions per particle (2 particles
/// per collision): 0 for none, else at least 1.
inline long collision_target(double per_particle, long particles) {
  if (per_particle <= 0) return 0;
  const auto t = static_cast<long>(per_particle * static_cast<double>(particles) / 2);
  return t < 1 ? 1 : t;
}

}  // namespace gkt::detail
