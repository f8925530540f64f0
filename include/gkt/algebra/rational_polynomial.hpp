// Univariate polynomials over Q: a value-semantics RAII wrapper around FLINT's
// fmpq_poly. The engine uses it to keep the restitution coefficient α symbolic.
#pragma once

#include <string>

#include <flint/fmpq_poly.h>

#include "gkt/algebra/rational.hpp"

namespace gkt {

/// An exact polynomial in one variable (α by convention) with rational coefficients.
class RationalPolynomial {
 public:
  RationalPolynomial() { fmpq_poly_init(value_); }
  /// The constant polynomial c (implicit: constants are polynomials).
  RationalPolynomial(long c) {  // NOLINT(google-explicit-constructor): constants are polynomials
    fmpq_poly_init(value_);
    fmpq_poly_set_si(value_, c);
  }
  /// The constant polynomial c (implicit).
  RationalPolynomial(const Rational& c) {  // NOLINT(google-explicit-constructor)
    fmpq_poly_init(value_);
    fmpq_poly_set_fmpq(value_, c.raw());
  }
  /// The polynomial x (the variable itself).
  static RationalPolynomial variable();

  /// Copies the polynomial.
  RationalPolynomial(const RationalPolynomial& o) {
    fmpq_poly_init(value_);
    fmpq_poly_set(value_, o.value_);
  }
  /// Takes the polynomial; `o` is left zero.
  RationalPolynomial(RationalPolynomial&& o) noexcept {
    fmpq_poly_init(value_);
    fmpq_poly_swap(value_, o.value_);
  }
  /// Copies the polynomial.
  RationalPolynomial& operator=(const RationalPolynomial& o) {
    if (this != &o) fmpq_poly_set(value_, o.value_);
    return *this;
  }
  /// Swaps polynomials with `o`.
  RationalPolynomial& operator=(RationalPolynomial&& o) noexcept {
    fmpq_poly_swap(value_, o.value_);
    return *this;
  }
  ~RationalPolynomial() { fmpq_poly_clear(value_); }

  /// Adds `b` exactly; returns *this.
  RationalPolynomial& operator+=(const RationalPolynomial& b) {
    fmpq_poly_add(value_, value_, b.value_);
    return *this;
  }
  /// Subtracts `b` exactly; returns *this.
  RationalPolynomial& operator-=(const RationalPolynomial& b) {
    fmpq_poly_sub(value_, value_, b.value_);
    return *this;
  }
  /// Multiplies by `b` exactly; returns *this.
  RationalPolynomial& operator*=(const RationalPolynomial& b) {
    fmpq_poly_mul(value_, value_, b.value_);
    return *this;
  }
  /// Multiplies every coefficient by `c`; returns *this.
  RationalPolynomial& operator*=(const Rational& c) {
    fmpq_poly_scalar_mul_fmpq(value_, value_, c.raw());
    return *this;
  }
  /// Divides every coefficient by `c`; returns *this; throws std::domain_error if `c` is zero.
  RationalPolynomial& operator/=(const Rational& c);
  /// this += a*b.
  void add_product(const RationalPolynomial& a, const RationalPolynomial& b);
  /// this -= a*b.
  void sub_product(const RationalPolynomial& a, const RationalPolynomial& b);

  /// Returns the exact sum a + b.
  friend RationalPolynomial operator+(RationalPolynomial a, const RationalPolynomial& b) { return a += b; }
  /// Returns the exact difference a - b.
  friend RationalPolynomial operator-(RationalPolynomial a, const RationalPolynomial& b) { return a -= b; }
  /// Returns the exact product a·b.
  friend RationalPolynomial operator*(RationalPolynomial a, const RationalPolynomial& b) { return a *= b; }
  /// Returns -a.
  friend RationalPolynomial operator-(RationalPolynomial a) {
    fmpq_poly_neg(a.value_, a.value_);
    return a;
  }
  /// True if a and b have the same coefficients.
  friend bool operator==(const RationalPolynomial& a, const RationalPolynomial& b) {
    return fmpq_poly_equal(a.value_, b.value_) != 0;
  }

  /// True if this is the zero polynomial.
  [[nodiscard]] bool is_zero() const { return fmpq_poly_is_zero(value_) != 0; }
  /// Returns the degree (-1 for the zero polynomial, FLINT's convention).
  [[nodiscard]] long degree() const { return fmpq_poly_degree(value_); }
  /// Coefficient of x^k.
  [[nodiscard]] Rational coefficient(long k) const;
  /// The value at x (exact).
  [[nodiscard]] Rational evaluate(const Rational& x) const;
  /// The constant polynomial's value; throws if the polynomial is not constant.
  [[nodiscard]] Rational constant_value() const;
  /// Pretty form in the named variable, e.g. "3/5*alpha^2 - 1".
  [[nodiscard]] std::string to_string(const std::string& variable = "alpha") const;

  /// The underlying FLINT fmpq_poly (for calling FLINT directly).
  fmpq_poly_struct* raw() { return value_; }
  /// The underlying FLINT fmpq_poly, read-only.
  [[nodiscard]] const fmpq_poly_struct* raw() const { return value_; }

 private:
  fmpq_poly_t value_;
};

}  // namespace gkt
