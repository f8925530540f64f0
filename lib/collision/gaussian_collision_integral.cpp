#include "gkt/collision/gaussian_collision_integral.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gkt {

double gaussian_integral_constant(int dimension) {
  const double d = dimension;
  const double surface = 2.0 * std::pow(std::numbers::pi, d / 2.0) / std::tgamma(d / 2.0);
  return 0.5 * surface * std::pow(std::numbers::pi, d - 0.5);
}

double gaussian_collision_integral(int dimension, double mass_i, double mass_j, double alpha, const QuadraticForm& q) {
  const double mu_i = mass_i / (mass_i + mass_j);
  const double mu_j = mass_j / (mass_i + mass_j);
  const double t[4][3] = {{1, mu_j, 0}, {1, -mu_i, 0}, {1, 0, mu_j}, {1, 0, -mu_i}};
  double m[3][3] = {};
  for (int r = 0; r < 3; ++r)
    for (int s = 0; s < 3; ++s)
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) m[r][s] += t[a][r] * q[a][b] * t[b][s];
  const double A = m[0][0], D = m[0][1], E = m[0][2], B = m[1][1], H = m[1][2], C = m[2][2];
  const double n1 = A * (B + C + 2 * H) - (D + E) * (D + E);
  const double n2 = A * (B + alpha * alpha * C - 2 * alpha * H) - (D - alpha * E) * (D - alpha * E);
  if (!(A > 0 && n1 > 0 && n2 > 0)) throw std::domain_error("gaussian_collision_integral: form not integrable");
  return gaussian_integral_constant(dimension) * std::sqrt(A) / (std::pow(n1, 0.5 * (dimension - 1)) * n2);
}

}  // namespace gkt
