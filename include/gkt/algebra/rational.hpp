// Exact rational numbers: a value-semantics RAII wrapper around FLINT's fmpq.
//
// Layer: exact algebra (bottom). All big-number arithmetic is FLINT's; this
// header only gives it C++ value semantics so the engine can be written as
// ordinary algebra.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>

#include <flint/fmpq.h>

namespace gkt {

/// An exact rational number p/q in lowest terms (FLINT fmpq).
class Rational {
 public:
  /// Zero.
  Rational() { fmpq_init(value_); }
  /// The integer `numerator` (implicit: integers are rationals).
  Rational(long numerator) {  // NOLINT(google-explicit-constructor): integers are rationals
    fmpq_init(value_);
    fmpq_set_si(value_, numerator, 1);
  }
  /// numerator/denominator in lowest terms; throws std::domain_error if denominator is 0.
  Rational(long numerator, unsigned long denominator);
  /// Parses "p", "p/q" or a finite decimal such as "0.6" or "-1.25e-3" exactly.
  static Rational parse(const std::string& text);
  /// The exact binary value of a finite double.
  static Rational from_double(double x);

  /// Copies the value.
  Rational(const Rational& other) {
    fmpq_init(value_);
    fmpq_set(value_, other.value_);
  }
  /// Takes the value; `other` is left zero.
  Rational(Rational&& other) noexcept {
    fmpq_init(value_);
    fmpq_swap(value_, other.value_);
  }
  /// Copies the value.
  Rational& operator=(const Rational& other) {
    if (this != &other) fmpq_set(value_, other.value_);
    return *this;
  }
  /// Swaps values with `other`.
  Rational& operator=(Rational&& other) noexcept {
    fmpq_swap(value_, other.value_);
    return *this;
  }
  ~Rational() { fmpq_clear(value_); }

  /// Adds `b` exactly; returns *this.
  Rational& operator+=(const Rational& b) {
    fmpq_add(value_, value_, b.value_);
    return *this;
  }
  /// Subtracts `b` exactly; returns *this.
  Rational& operator-=(const Rational& b) {
    fmpq_sub(value_, value_, b.value_);
    return *this;
  }
  /// Multiplies by `b` exactly; returns *this.
  Rational& operator*=(const Rational& b) {
    fmpq_mul(value_, value_, b.value_);
    return *this;
  }
  /// Divides by `b` exactly; returns *this; throws std::domain_error if `b` is zero.
  Rational& operator/=(const Rational& b);
  /// this += a*b without a temporary.
  void add_product(const Rational& a, const Rational& b) { fmpq_addmul(value_, a.value_, b.value_); }
  /// this -= a*b without a temporary.
  void sub_product(const Rational& a, const Rational& b) { fmpq_submul(value_, a.value_, b.value_); }

  /// Returns the exact sum a + b.
  friend Rational operator+(Rational a, const Rational& b) { return a += b; }
  /// Returns the exact difference a - b.
  friend Rational operator-(Rational a, const Rational& b) { return a -= b; }
  /// Returns the exact product a·b.
  friend Rational operator*(Rational a, const Rational& b) { return a *= b; }
  /// Returns the exact quotient a/b; throws std::domain_error if `b` is zero.
  friend Rational operator/(Rational a, const Rational& b) { return a /= b; }
  /// Returns -a.
  friend Rational operator-(Rational a) {
    fmpq_neg(a.value_, a.value_);
    return a;
  }
  /// True if a and b are the same rational.
  friend bool operator==(const Rational& a, const Rational& b) { return fmpq_equal(a.value_, b.value_) != 0; }
  /// True if a < b (exact comparison).
  friend bool operator<(const Rational& a, const Rational& b) { return fmpq_cmp(a.value_, b.value_) < 0; }
  /// True if a > b (exact comparison).
  friend bool operator>(const Rational& a, const Rational& b) { return b < a; }
  /// True if a <= b (exact comparison).
  friend bool operator<=(const Rational& a, const Rational& b) { return !(b < a); }
  /// True if a >= b (exact comparison).
  friend bool operator>=(const Rational& a, const Rational& b) { return !(a < b); }

  /// True if the value is 0.
  [[nodiscard]] bool is_zero() const { return fmpq_is_zero(value_) != 0; }
  /// Returns the sign: -1, 0 or +1.
  [[nodiscard]] int sign() const { return fmpq_sgn(value_); }
  /// Returns |this| (exact).
  [[nodiscard]] Rational abs() const;
  /// Integer power (negative exponents allowed for non-zero values).
  [[nodiscard]] Rational pow(long exponent) const;
  /// The exact square root if this is the square of a rational; throws otherwise.
  [[nodiscard]] Rational exact_sqrt() const;
  /// True if the value is the square of a rational (numerator and denominator perfect squares, value >= 0).
  [[nodiscard]] bool is_square() const;
  /// Returns the nearest double (correctly rounded, via MPFR).
  [[nodiscard]] double to_double() const;
  /// "p/q" or "p" in lowest terms.
  [[nodiscard]] std::string to_string() const;
  /// The exact terminating decimal ("0.5001", "-1.25", "3") when the denominator is 2^a 5^b, else
  /// "p/q": how a number the user typed as a decimal is echoed back in messages. Numbers of more
  /// than 80 bits (numerator plus denominator) are written as the shortest decimal of the nearest
  /// double ("1e+300", "1e-30"), never as hundreds of digits.
  [[nodiscard]] std::string to_decimal_string() const;
  /// Number of bits of numerator plus denominator (a measure of size).
  [[nodiscard]] long bits() const;

  /// n! as a rational.
  static Rational factorial(unsigned long n);
  /// Γ(k/2 + n) / Γ(k/2) for integer k > 0, n >= 0 (a rational: rising factorial (k/2)_n).
  static Rational rising_half(long twice_a, unsigned long n);

  /// The underlying FLINT fmpq (for calling FLINT directly).
  fmpq* raw() { return value_; }
  /// The underlying FLINT fmpq, read-only.
  [[nodiscard]] const fmpq* raw() const { return value_; }

 private:
  fmpq_t value_;
};

/// Writes q as to_string() does ("p/q" or "p").
std::ostream& operator<<(std::ostream& os, const Rational& q);

}  // namespace gkt
