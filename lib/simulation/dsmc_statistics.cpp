// Sample means with standard errors, and the restitution of smooth grains (homogeneous_dsmc.hpp).
#include <cmath>
#include <stdexcept>

#include "gkt/simulation/homogeneous_dsmc.hpp"

namespace gkt {

DsmcEstimate mean_and_error(std::span<const double> values) {
  if (values.empty()) throw std::invalid_argument("mean_and_error: no values");
  const auto n = static_cast<double>(values.size());
  double mean = 0;
  for (double x : values) mean += x / n;
  if (values.size() == 1) return {mean, 0};
  double variance = 0;
  for (double x : values) variance += (x - mean) * (x - mean) / (n - 1);
  return {mean, std::sqrt(variance / n)};
}

double SmoothRestitution::at(double u) const {
  if (series.empty()) return alpha;
  const double w = delta_prime * std::pow(u, 0.2);
  double value = 0;  // Horner in w: Σ_k h_k w^k
  for (auto h = series.rbegin(); h != series.rend(); ++h) value = (value + *h) * w;
  return 1 + value;
}

}  // namespace gkt
