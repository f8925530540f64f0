#include "gkt/algebra/sonine.hpp"

#include <cmath>
#include <stdexcept>

namespace gkt {

std::vector<Rational> sonine_coefficients(long twice_m, int n) {
  if (twice_m <= -2) throw std::domain_error("sonine: m must exceed -1");
  if (n < 0) throw std::domain_error("sonine: order must be non-negative");
  // c_k = (-1)^k Γ(m+n+1)/(Γ(m+k+1)(n-k)! k!) = (-1)^k (m+k+1)_{n-k} / ((n-k)! k!).
  std::vector<Rational> c;
  c.reserve(static_cast<std::size_t>(n) + 1);
  for (int k = 0; k <= n; ++k) {
    Rational ck = Rational::rising_half(twice_m + 2 * (k + 1), static_cast<unsigned long>(n - k));
    ck /= Rational::factorial(static_cast<unsigned long>(n - k)) * Rational::factorial(static_cast<unsigned long>(k));
    c.push_back(k % 2 == 0 ? ck : -ck);
  }
  return c;
}

double sonine_value(long twice_m, int n, double x) {
  // (n+1) S^(n+1) = (2n + m + 1 - x) S^(n) - (n + m) S^(n-1).
  const double m = 0.5 * static_cast<double>(twice_m);
  double prev = 1.0;
  if (n == 0) return prev;
  double cur = m + 1.0 - x;
  for (int k = 1; k < n; ++k) {
    const double next = ((2.0 * k + m + 1.0 - x) * cur - (k + m) * prev) / (k + 1.0);
    prev = cur;
    cur = next;
  }
  return cur;
}

Rational sonine_norm(long twice_m, int n) {
  return Rational::rising_half(twice_m + 2, static_cast<unsigned long>(n)) /
         Rational::factorial(static_cast<unsigned long>(n));
}

std::vector<std::vector<Rational>> sonine_table(long twice_m, int n_max) {
  std::vector<std::vector<Rational>> rows;
  rows.reserve(static_cast<std::size_t>(n_max) + 1);
  for (int n = 0; n <= n_max; ++n) rows.push_back(sonine_coefficients(twice_m, n));
  return rows;
}

Rational maxwell_average(int dimension, const std::vector<Rational>& polynomial) {
  Rational s;
  for (std::size_t j = 0; j < polynomial.size(); ++j)
    s += polynomial[j] * Rational::rising_half(dimension, static_cast<unsigned long>(j));
  return s;
}

Rational scaling_weight(int dimension, int p, int k) {
  const long twice_m = sonine_twice_m(dimension, 0);
  const auto sp = sonine_coefficients(twice_m, p);
  const auto sk = sonine_coefficients(twice_m, k);
  std::vector<Rational> product(static_cast<std::size_t>(p + k) + 1);  // x S_p'(x) S_k(x)
  for (int j = 1; j <= p; ++j)
    for (int i = 0; i <= k; ++i)
      product[static_cast<std::size_t>(i + j)] +=
          Rational(j) * sp[static_cast<std::size_t>(j)] * sk[static_cast<std::size_t>(i)];
  return maxwell_average(dimension, product);
}

double sonine_generating_function(long twice_m, double x, double s) {
  const double m = 0.5 * static_cast<double>(twice_m);
  return std::pow(1.0 - s, -m - 1.0) * std::exp(-x * s / (1.0 - s));
}

}  // namespace gkt
