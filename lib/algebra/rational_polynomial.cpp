#include "gkt/algebra/rational_polynomial.hpp"

#include <sstream>
#include <stdexcept>

namespace gkt {

RationalPolynomial RationalPolynomial::variable() {
  RationalPolynomial x;
  fmpq_poly_set_coeff_si(x.value_, 1, 1);
  return x;
}

RationalPolynomial& RationalPolynomial::operator/=(const Rational& c) {
  if (c.is_zero()) throw std::domain_error("RationalPolynomial: division by zero");
  fmpq_poly_scalar_div_fmpq(value_, value_, c.raw());
  return *this;
}

void RationalPolynomial::add_product(const RationalPolynomial& a, const RationalPolynomial& b) {
  fmpq_poly_t t;
  fmpq_poly_init(t);
  fmpq_poly_mul(t, a.value_, b.value_);
  fmpq_poly_add(value_, value_, t);
  fmpq_poly_clear(t);
}

void RationalPolynomial::sub_product(const RationalPolynomial& a, const RationalPolynomial& b) {
  fmpq_poly_t t;
  fmpq_poly_init(t);
  fmpq_poly_mul(t, a.value_, b.value_);
  fmpq_poly_sub(value_, value_, t);
  fmpq_poly_clear(t);
}

Rational RationalPolynomial::coefficient(long k) const {
  Rational c;
  fmpq_poly_get_coeff_fmpq(c.raw(), value_, k);
  return c;
}

Rational RationalPolynomial::evaluate(const Rational& x) const {
  Rational r;
  fmpq_poly_evaluate_fmpq(r.raw(), value_, x.raw());
  return r;
}

Rational RationalPolynomial::constant_value() const {
  if (degree() > 0) throw std::domain_error("RationalPolynomial: not a constant: " + to_string());
  return coefficient(0);
}

std::string RationalPolynomial::to_string(const std::string& variable) const {
  if (is_zero()) return "0";
  std::ostringstream out;
  bool first = true;
  for (long k = degree(); k >= 0; --k) {
    const Rational c = coefficient(k);
    if (c.is_zero()) continue;
    const bool negative = c.sign() < 0;
    if (!first)
      out << (negative ? " - " : " + ");
    else if (negative)
      out << '-';
    first = false;
    const Rational a = c.abs();
    const bool unit = a == Rational(1);
    if (k == 0 || !unit) out << a;
    if (k > 0) {
      if (!unit) out << '*';
      out << variable;
      if (k > 1) out << '^' << k;
    }
  }
  return out.str();
}

}  // namespace gkt
