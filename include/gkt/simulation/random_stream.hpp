// The random numbers of the DSMC: std::mt19937_64 (whose output sequence the C++ standard fixes)
// turned into uniforms, indices and Gaussians by gkt's own formulas, so a seed gives the same run
// with every standard library (std::uniform_real_distribution and std::normal_distribution are
// implementation-defined). One stream per independent run, seeded by dsmc_run_seed(seed, run).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>

namespace gkt {

/// Returns the seed of run `run` of a DSMC seeded with `seed`: SplitMix64 of the pair (Steele,
/// Lea & Flood 2014), so the streams of neighbouring runs and seeds are unrelated.
constexpr std::uint64_t dsmc_run_seed(std::uint64_t seed, std::uint64_t run) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (run + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

/// A deterministic stream of uniforms, indices and standard Gaussians.
class RandomStream {
 public:
  /// A stream seeded with `seed` (same seed, same sequence).
  explicit RandomStream(std::uint64_t seed) : engine_(seed) {}

  /// Returns a uniform number in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

  /// Returns an integer uniform in [0, n) for n ≥ 1 (rejection: no modulo bias).
  std::size_t below(std::size_t n) {
    const auto m = static_cast<std::uint64_t>(n);
    const std::uint64_t limit =
        std::numeric_limits<std::uint64_t>::max() - std::numeric_limits<std::uint64_t>::max() % m;
    std::uint64_t x = engine_();
    while (x >= limit) x = engine_();
    return static_cast<std::size_t>(x % m);
  }

  /// Returns a standard Gaussian (Box–Muller; the second value of each pair is kept for the next call).
  double gaussian() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double r = std::sqrt(-2 * std::log(1 - uniform())), phi = 2 * std::numbers::pi * uniform();
    spare_ = r * std::sin(phi);
    has_spare_ = true;
    return r * std::cos(phi);
  }

 private:
  std::mt19937_64 engine_;
  bool has_spare_ = false;
  double spare_ = 0;
};

}  // namespace gkt
