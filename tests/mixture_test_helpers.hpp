// Small helpers shared by the mixture tests.
#pragma once

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "evolution/mixture_longitudinal_matrix.hpp"

namespace gkt::test {

/// Returns |a − b| / max(1, |b|).
inline double relative(double a, double b) { return std::abs(a - b) / std::max(1.0, std::abs(b)); }

/// Returns the number of eigenvalues of m with a positive real part (growing modes).
inline int growing_modes(const Eigen::MatrixXcd& m) {
  int n = 0;
  for (const auto& e : m.eigenvalues()) n += e.real() > 0;
  return n;
}

}  // namespace gkt::test
