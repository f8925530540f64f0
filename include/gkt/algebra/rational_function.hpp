// Quotients of polynomials in α over Q: the closed forms of first-Sonine results.
#pragma once

#include <string>

#include "gkt/algebra/rational_polynomial.hpp"

namespace gkt {

/// numerator(α)/denominator(α), exact, with a common content removed (denominator monic).
struct RationalFunction {
  /// The numerator polynomial in α.
  RationalPolynomial numerator;
  /// The denominator polynomial in α (1 by default; monic once reduced()).
  RationalPolynomial denominator{1L};

  /// Returns the value at α (exact); throws std::domain_error at a pole.
  [[nodiscard]] Rational evaluate(const Rational& alpha) const;
  /// Returns the function with gcd(numerator, denominator) removed and the denominator monic.
  [[nodiscard]] RationalFunction reduced() const;
  /// True if a/b == c/d as rational functions (a·d == b·c).
  [[nodiscard]] bool equals(const RationalFunction& other) const;

  /// Returns a + b, reduced.
  friend RationalFunction operator+(const RationalFunction& a, const RationalFunction& b) {
    return RationalFunction{a.numerator * b.denominator + b.numerator * a.denominator, a.denominator * b.denominator}
        .reduced();
  }
  /// Returns a - b, reduced.
  friend RationalFunction operator-(const RationalFunction& a, const RationalFunction& b) {
    return RationalFunction{a.numerator * b.denominator - b.numerator * a.denominator, a.denominator * b.denominator}
        .reduced();
  }
  /// Returns a·b, reduced.
  friend RationalFunction operator*(const RationalFunction& a, const RationalFunction& b) {
    return RationalFunction{a.numerator * b.numerator, a.denominator * b.denominator}.reduced();
  }
  /// Throws std::domain_error when b is identically zero.
  friend RationalFunction operator/(const RationalFunction& a, const RationalFunction& b);
};

}  // namespace gkt
