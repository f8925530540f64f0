// The quadrature pieces shared by the tail scheme's collision kernel (tail_galerkin.cpp) and its
// collisional-transfer kernel (tail_collisional_transfer.cpp): Gauss–Legendre rules on [0, 1] and the
// Sonine recurrence in double precision (theory.md §10.6, §15.8).
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

namespace gkt::detail {

/// Gauss–Legendre rule on [0, 1]: nodes and weights.
struct Rule {
  std::vector<double> x, w;
};

/// Returns the n-point Gauss–Legendre rule on [0, 1] (Newton on P_n in long double from Tricomi's guesses).
inline Rule gauss_legendre(int n) {
  constexpr double kPi = 3.14159265358979323846;
  Rule r;
  r.x.resize(static_cast<std::size_t>(n));
  r.w.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    long double z = std::cos(static_cast<long double>(kPi) * (i + 0.75L) / (n + 0.5L)), dp = 1;
    for (int it = 0; it < 100; ++it) {
      long double p1 = 1, p2 = 0;
      for (int j = 0; j < n; ++j) {
        const long double p3 = p2;
        p2 = p1;
        p1 = ((2 * j + 1) * z * p2 - j * p3) / (j + 1);
      }
      dp = n * (z * p1 - p2) / (z * z - 1);
      const long double step = p1 / dp;
      z -= step;
      if (std::fabs(step) < 1e-19L) break;
    }
    r.x[static_cast<std::size_t>(i)] = static_cast<double>(0.5L * (1 - z));
    r.w[static_cast<std::size_t>(i)] = static_cast<double>(1.0L / ((1 - z * z) * dp * dp));
  }
  return r;
}

/// Writes the Sonine polynomials S_index^(p)(x), p = 0 … p_max, to out ([chapman1970] §7.5; theory.md (1.1)).
inline void sonine_values(int p_max, double index, double x, double* out) {
  out[0] = 1;
  if (p_max >= 1) out[1] = 1 + index - x;
  for (int n = 1; n < p_max; ++n) out[n + 1] = ((2 * n + 1 + index - x) * out[n] - (n + index) * out[n - 1]) / (n + 1);
}

}  // namespace gkt::detail
