#include "gkt/algebra/rational.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <ostream>
#include <stdexcept>

#include <flint/fmpz.h>
#include <mpfr.h>

namespace gkt {

Rational::Rational(long numerator, unsigned long denominator) {
  if (denominator == 0) throw std::domain_error("Rational: zero denominator");
  fmpq_init(value_);
  fmpq_set_si(value_, numerator, denominator);
}

Rational& Rational::operator/=(const Rational& b) {
  if (b.is_zero()) throw std::domain_error("Rational: division by zero");
  fmpq_div(value_, value_, b.value_);
  return *this;
}

Rational Rational::abs() const {
  Rational r;
  fmpq_abs(r.value_, value_);
  return r;
}

Rational Rational::pow(long exponent) const {
  if (exponent < 0 && is_zero()) throw std::domain_error("Rational: zero to a negative power");
  Rational r;
  fmpq_pow_si(r.value_, value_, exponent);
  return r;
}

bool Rational::is_square() const {
  if (sign() < 0) return false;
  return fmpz_is_square(fmpq_numref(value_)) != 0 && fmpz_is_square(fmpq_denref(value_)) != 0;
}

Rational Rational::exact_sqrt() const {
  if (!is_square()) throw std::domain_error("Rational: " + to_string() + " is not the square of a rational");
  Rational r;
  fmpz_sqrt(fmpq_numref(r.value_), fmpq_numref(value_));
  fmpz_sqrt(fmpq_denref(r.value_), fmpq_denref(value_));
  return r;
}

double Rational::to_double() const {
  // Correctly rounded (round-to-nearest) through a 53-bit MPFR number.
  mpfr_t r;
  mpfr_init2(r, 53);
  fmpq_get_mpfr(r, value_, MPFR_RNDN);
  const double x = mpfr_get_d(r, MPFR_RNDN);
  mpfr_clear(r);
  return x;
}

std::string Rational::to_string() const {
  char* s = fmpq_get_str(nullptr, 10, value_);
  std::string out(s);
  flint_free(s);
  return out;
}

std::string Rational::to_decimal_string() const {
  constexpr long kMaxEchoBits = 80;  // about 24 decimal digits
  if (bits() > kMaxEchoBits) {
    // 1e300 is "1e+300", not 301 digits: the shortest decimal that reads back as the same double,
    // which is what the user typed when the number came from a scene.
    char buffer[32];
    const auto r = std::to_chars(buffer, buffer + sizeof buffer, to_double());
    return {buffer, r.ptr};
  }
  // q = 2^a 5^b  ⇒  |p|/q = |p| 2^(k−a) 5^(k−b) / 10^k with k = max(a, b).
  fmpz_t rest, factor;
  fmpz_init(rest);
  fmpz_init_set_ui(factor, 2);
  const auto twos = static_cast<unsigned long>(fmpz_remove(rest, fmpq_denref(value_), factor));
  fmpz_set_ui(factor, 5);
  const auto fives = static_cast<unsigned long>(fmpz_remove(rest, rest, factor));
  const bool terminating = fmpz_is_one(rest) != 0;
  fmpz_clear(rest);
  if (!terminating) {
    fmpz_clear(factor);
    return to_string();
  }
  const unsigned long digits = std::max(twos, fives);
  fmpz_pow_ui(factor, factor, digits - fives);
  fmpz_mul(factor, factor, fmpq_numref(value_));
  fmpz_mul_2exp(factor, factor, digits - twos);
  fmpz_abs(factor, factor);
  char* raw = fmpz_get_str(nullptr, 10, factor);
  const std::string magnitude(raw);
  flint_free(raw);
  fmpz_clear(factor);
  // Left-pad with zeros so that at least one digit stands before the point.
  std::string padded(magnitude.size() <= digits ? digits + 1 - magnitude.size() : 0, '0');
  padded.append(magnitude);
  const std::size_t point = padded.size() - digits;
  std::string out(sign() < 0 ? "-" : "");
  out.append(padded, 0, point);
  if (digits > 0) {
    out.push_back('.');
    out.append(padded, point);
  }
  return out;
}

long Rational::bits() const {
  return static_cast<long>(fmpz_bits(fmpq_numref(value_)) + fmpz_bits(fmpq_denref(value_)));
}

Rational Rational::factorial(unsigned long n) {
  Rational r;
  fmpz_fac_ui(fmpq_numref(r.value_), n);
  return r;
}

Rational Rational::rising_half(long twice_a, unsigned long n) {
  // (a)_n with a = twice_a/2: prod_{k<n} (twice_a + 2k)/2.
  Rational r(1);
  for (unsigned long k = 0; k < n; ++k) r *= Rational(twice_a + 2 * static_cast<long>(k), 2);
  return r;
}

Rational Rational::from_double(double x) {
  if (!std::isfinite(x)) throw std::domain_error("Rational: non-finite double");
  int exponent = 0;
  const double mantissa = std::frexp(x, &exponent);
  const auto scaled = static_cast<long long>(std::ldexp(mantissa, 53));
  Rational r(static_cast<long>(scaled));
  const long e = exponent - 53;
  r *= Rational(2).pow(e);
  return r;
}

Rational Rational::parse(const std::string& text) {
  auto fail = [&]() { return std::invalid_argument("not a rational number: '" + text + "'"); };
  if (text.empty()) throw fail();
  const auto slash = text.find('/');
  if (slash != std::string::npos) {
    Rational p = parse(text.substr(0, slash));
    Rational q = parse(text.substr(slash + 1));
    if (q.is_zero()) throw fail();
    return p / q;
  }
  // decimal: [sign] digits [. digits] [e|E [sign] digits]
  std::size_t i = 0;
  bool negative = false;
  if (text[i] == '+' || text[i] == '-') negative = text[i++] == '-';
  std::string digits;
  long frac_digits = 0;
  bool seen_point = false;
  for (; i < text.size() && text[i] != 'e' && text[i] != 'E'; ++i) {
    const char c = text[i];
    if (c == '.' && !seen_point) {
      seen_point = true;
    } else if (c >= '0' && c <= '9') {
      digits += c;
      if (seen_point) ++frac_digits;
    } else if (c == '_') {
      continue;
    } else {
      throw fail();
    }
  }
  if (digits.empty()) throw fail();
  long exp10 = 0;
  if (i < text.size()) {
    const std::string e = text.substr(i + 1);
    if (e.empty()) throw fail();
    std::size_t used = 0;
    try {
      exp10 = std::stol(e, &used);
    } catch (...) {
      throw fail();
    }
    if (used != e.size() || exp10 > 4000 || exp10 < -4000) throw fail();
  }
  Rational r;
  if (fmpz_set_str(fmpq_numref(r.value_), digits.c_str(), 10) != 0) throw fail();
  r *= Rational(10).pow(exp10 - frac_digits);
  return negative ? -r : r;
}

std::ostream& operator<<(std::ostream& os, const Rational& q) { return os << q.to_string(); }

}  // namespace gkt
