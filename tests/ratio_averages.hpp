// The ratio estimator Σ w h / Σ w of weighted Monte Carlo samples (collisions weighted by Θ(σ̂·g)(σ̂·g)), for
// several integrands at once, with its standard error by the delta method. Shared by the smooth and rough samplers'
// tests.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace gkt::test {

/// Mean and standard error of a ratio estimator Σ w h / Σ w.
struct Estimate {
  double mean = 0, error = 0;
};

/// Accumulates Σ w h_k / Σ w for integrands k = 0 … n − 1 over weighted samples.
class RatioAverages {
 public:
  explicit RatioAverages(std::size_t n) : swh_(n, 0), swh2_(n, 0), sw2h_(n, 0) {}
  /// Counts one sample of weight w (call once per sample, before or after its add calls).
  void sample(double w) {
    sw_ += w;
    sw2_ += w * w;
  }
  /// Adds integrand k's value h on a sample of weight w.
  void add(std::size_t k, double w, double h) {
    swh_[k] += w * h;
    swh2_[k] += w * w * h * h;
    sw2h_[k] += w * w * h;
  }
  /// Returns Σ w h_k / Σ w and its standard error: Var of Σ w(h − r) per sample, divided by (Σ w)².
  [[nodiscard]] Estimate estimate(std::size_t k) const {
    const double r = swh_[k] / sw_;
    const double var = swh2_[k] - 2 * r * sw2h_[k] + r * r * sw2_;
    return {r, std::sqrt(std::max(var, 0.0)) / sw_};
  }

 private:
  std::vector<double> swh_, swh2_, sw2h_;
  double sw_ = 0, sw2_ = 0;
};

}  // namespace gkt::test
