#include "gkt/algebra/rational_function.hpp"

#include <stdexcept>

namespace gkt {

Rational RationalFunction::evaluate(const Rational& alpha) const {
  const Rational d = denominator.evaluate(alpha);
  if (d.is_zero()) throw std::domain_error("RationalFunction: pole at " + alpha.to_string());
  return numerator.evaluate(alpha) / d;
}

RationalFunction RationalFunction::reduced() const {
  RationalFunction r;
  fmpq_poly_t g;
  fmpq_poly_init(g);
  fmpq_poly_gcd(g, numerator.raw(), denominator.raw());
  fmpq_poly_div(r.numerator.raw(), numerator.raw(), g);
  fmpq_poly_div(r.denominator.raw(), denominator.raw(), g);
  fmpq_poly_clear(g);
  const long deg = r.denominator.degree();
  if (deg < 0) throw std::domain_error("RationalFunction: zero denominator");
  const Rational lead = r.denominator.coefficient(deg);
  r.numerator /= lead;
  r.denominator /= lead;
  return r;
}

bool RationalFunction::equals(const RationalFunction& other) const {
  return numerator * other.denominator == denominator * other.numerator;
}

RationalFunction operator/(const RationalFunction& a, const RationalFunction& b) {
  if (b.numerator.is_zero()) throw std::domain_error("RationalFunction: division by zero");
  return RationalFunction{a.numerator * b.denominator, a.denominator * b.numerator}.reduced();
}

}  // namespace gkt
