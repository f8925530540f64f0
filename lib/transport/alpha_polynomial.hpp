// Private: exact polynomials in α stored as long-double coefficients and evaluated per α by
// Horner's rule — how the solvers reuse matrices built once with α symbolic (docs/theory.md §9.2:
// measured relative error ≤ 4e-14 against exact evaluation).
#pragma once

#include <vector>

#include "gkt/rational_polynomial.hpp"

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

}  // namespace gkt::detail
