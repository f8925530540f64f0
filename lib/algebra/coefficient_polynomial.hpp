// Private: polynomials in x = c² as exact coefficient vectors (p[j] multiplies x^j) — the form
// sonine_table and maxwell_average use — with the few operations the Galerkin pieces need.
#pragma once

#include <vector>

#include "gkt/algebra/rational.hpp"

namespace gkt::detail {

using CoefficientPolynomial = std::vector<Rational>;

/// Returns a·b.
inline CoefficientPolynomial multiply(const CoefficientPolynomial& a, const CoefficientPolynomial& b) {
  CoefficientPolynomial r(a.size() + b.size() - 1);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  return r;
}
/// Returns a + scale·b.
inline CoefficientPolynomial add(CoefficientPolynomial a, const CoefficientPolynomial& b,
                                 const Rational& scale = Rational(1)) {
  if (a.size() < b.size()) a.resize(b.size());
  for (std::size_t i = 0; i < b.size(); ++i) a[i] += scale * b[i];
  return a;
}
/// Returns da/dx.
inline CoefficientPolynomial derivative(const CoefficientPolynomial& a) {
  CoefficientPolynomial r(a.size() > 1 ? a.size() - 1 : 1);
  for (std::size_t i = 1; i < a.size(); ++i) r[i - 1] = Rational(static_cast<long>(i)) * a[i];
  return r;
}
/// Returns x^power · a.
inline CoefficientPolynomial times_x(const CoefficientPolynomial& a, int power = 1) {
  CoefficientPolynomial r(static_cast<std::size_t>(power), Rational(0));
  r.insert(r.end(), a.begin(), a.end());
  return r;
}

}  // namespace gkt::detail
