#include "gkt/transport/common/chebyshev_axis.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gkt {

ChebyshevAxis::ChebyshevAxis(int count, double low, double high) {
  const int last = high > low ? count - 1 : 0;
  for (int k = 0; k <= last; ++k) {
    nodes.push_back(last == 0 ? low : low + 0.5 * (high - low) * (1 - std::cos(std::numbers::pi * k / last)));
    weights.push_back((k % 2 == 0 ? 1.0 : -1.0) * (k == 0 || k == last ? 0.5 : 1.0));
  }
}

double ChebyshevAxis::at_angle(double position) const {
  const auto last = static_cast<double>(nodes.size() - 1);
  if (last == 0) return nodes[0];
  const double low = nodes.front(), high = nodes.back();
  return low + 0.5 * (high - low) * (1 - std::cos(std::numbers::pi * position / last));
}

void ChebyshevAxis::factors(double t, std::span<double> w) const {
  const std::size_t n = nodes.size();
  double sum = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double difference = t - nodes[k];
    // At a node (or within 1e-290 of it, where weight/difference would overflow and the
    // interpolant equals the node value in double anyway: found by fuzz_per_cell at t = 4e-315).
    if (std::abs(difference) < 1e-290) {
      std::fill_n(w.begin(), n, 0.0);
      w[k] = 1;
      return;
    }
    w[k] = weights[k] / difference;
    sum += w[k];
  }
  for (std::size_t k = 0; k < n; ++k) w[k] /= sum;
}

}  // namespace gkt
