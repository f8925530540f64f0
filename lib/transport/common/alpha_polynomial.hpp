// Private: exact polynomials in α stored as long-double coefficients and evaluated per α by
// Horner's rule — how the solvers reuse matrices built once with α symbolic (docs/theory.md §9.2:
// measured relative error ≤ 4e-14 against exact evaluation), and the one check on α they share.
#pragma once

#include <stdexcept>
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

/// Throws std::invalid_argument naming `alpha` and its range (0, 1] unless 0 < α ≤ 1.
inline void require_restitution(const Rational& alpha) {
  if (alpha.sign() <= 0 || alpha > Rational(1))
    throw std::invalid_argument("alpha: must be a number in (0, 1], got " + alpha.to_decimal_string());
}

}  // namespace gkt::detail
