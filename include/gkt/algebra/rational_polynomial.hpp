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
  RationalPolynomial(long c) {  // NOLINT(google-explicit-constructor): constants are polynomials
    fmpq_poly_init(value_);
    fmpq_poly_set_si(value_, c);
  }
  RationalPolynomial(const Rational& c) {  // NOLINT(google-explicit-constructor)
    fmpq_poly_init(value_);
    fmpq_poly_set_fmpq(value_, c.raw());
  }
  /// The polynomial x (the variable itself).
  static RationalPolynomial variable();

  RationalPolynomial(const RationalPolynomial& o) {
    fmpq_poly_init(value_);
    fmpq_poly_set(value_, o.value_);
  }
  RationalPolynomial(RationalPolynomial&& o) noexcept {
    fmpq_poly_init(value_);
    fmpq_poly_swap(value_, o.value_);
  }
  RationalPolynomial& operator=(const RationalPolynomial& o) {
    if (this != &o) fmpq_poly_set(value_, o.value_);
    return *this;
  }
  RationalPolynomial& operator=(RationalPolynomial&& o) noexcept {
    fmpq_poly_swap(value_, o.value_);
    return *this;
  }
  ~RationalPolynomial() { fmpq_poly_clear(value_); }

  RationalPolynomial& operator+=(const RationalPolynomial& b) {
    fmpq_poly_add(value_, value_, b.value_);
    return *this;
  }
  RationalPolynomial& operator-=(const RationalPolynomial& b) {
    fmpq_poly_sub(value_, value_, b.value_);
    return *this;
  }
  RationalPolynomial& operator*=(const RationalPolynomial& b) {
    fmpq_poly_mul(value_, value_, b.value_);
    return *this;
  }
  RationalPolynomial& operator*=(const Rational& c) {
    fmpq_poly_scalar_mul_fmpq(value_, value_, c.raw());
    return *this;
  }
  RationalPolynomial& operator/=(const Rational& c);
  void add_product(const RationalPolynomial& a, const RationalPolynomial& b);
  void sub_product(const RationalPolynomial& a, const RationalPolynomial& b);

  friend RationalPolynomial operator+(RationalPolynomial a, const RationalPolynomial& b) { return a += b; }
  friend RationalPolynomial operator-(RationalPolynomial a, const RationalPolynomial& b) { return a -= b; }
  friend RationalPolynomial operator*(RationalPolynomial a, const RationalPolynomial& b) { return a *= b; }
  friend RationalPolynomial operator-(RationalPolynomial a) {
    fmpq_poly_neg(a.value_, a.value_);
    return a;
  }
  friend bool operator==(const RationalPolynomial& a, const RationalPolynomial& b) {
    return fmpq_poly_equal(a.value_, b.value_) != 0;
  }

  [[nodiscard]] bool is_zero() const { return fmpq_poly_is_zero(value_) != 0; }
  [[nodiscard]] long degree() const { return fmpq_poly_degree(value_); }
  /// Coefficient of x^k.
  [[nodiscard]] Rational coefficient(long k) const;
  /// The value at x (exact).
  [[nodiscard]] Rational evaluate(const Rational& x) const;
  /// The constant polynomial's value; throws if the polynomial is not constant.
  [[nodiscard]] Rational constant_value() const;
  /// Pretty form in the named variable, e.g. "3/5*alpha^2 - 1".
  [[nodiscard]] std::string to_string(const std::string& variable = "alpha") const;

  fmpq_poly_struct* raw() { return value_; }
  [[nodiscard]] const fmpq_poly_struct* raw() const { return value_; }

 private:
  fmpq_poly_t value_;
};

}  // namespace gkt
