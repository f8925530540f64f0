// Private: exact polynomials in α stored as long-double coefficients and evaluated per α by
// Horner's rule — how the solvers reuse matrices built once with α symbolic (docs/theory.md §9.2:
// measured relative error ≤ 4e-14 against exact evaluation), and the one check on α they share.
#pragma once

#include <charconv>
#include <stdexcept>
#include <string>
#include <vector>

#include "gkt/algebra/rational_polynomial.hpp"

namespace gkt::detail {

/// Coefficients c_j of α^j, rounded to long double.
using AlphaPolynomial = std::vector<long double>;

/// Returns the coefficients of p rounded to long double (a zero polynomial gives {0}).
inline AlphaPolynomial to_alpha_polynomial(const RationalPolynomial& p) {
  AlphaPolynomial c(static_cast<std::size_t>(p.degree() > 0 ? p.degree() : 0) + 1, 0.0L);
  for (long k = 0; k <= p.degree(); ++k) c[static_cast<std::size_t>(k)] = p.coefficient(k).to_double();
  return c;
}

/// Returns p(α) by Horner's rule in long double, rounded to double.
inline double evaluate(const AlphaPolynomial& c, long double alpha) {
  long double v = 0;
  for (auto it = c.rbegin(); it != c.rend(); ++it) v = v * alpha + *it;
  return static_cast<double>(v);
}

/// Returns the one error of a restitution coefficient out of range: "<key>: must be a number in (0, 1], got <value>".
inline std::invalid_argument restitution_error(const std::string& key, const std::string& value) {
  return std::invalid_argument(key + ": must be a number in (0, 1], got " + value);
}

/// Throws restitution_error naming `key` unless 0 < α ≤ 1 (exact α of the engine).
inline void require_restitution(const Rational& alpha, const std::string& key = "alpha") {
  if (alpha.sign() <= 0 || alpha > Rational(1)) throw restitution_error(key, alpha.to_decimal_string());
}

/// Throws restitution_error naming `key` unless 0 < α ≤ 1 (α at the double solver boundary; NaN refused),
/// the value written in its shortest round-trip form.
inline void require_restitution(double alpha, const std::string& key = "alpha") {
  if (alpha > 0 && alpha <= 1) return;
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, alpha);
  throw restitution_error(key, std::string(buffer, r.ptr));
}

}  // namespace gkt::detail
