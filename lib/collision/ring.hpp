// Private: the coefficient rings the engine is instantiated for. A ring element must
// support +=, −=, *=, add_product/sub_product, scaling by an exact Rational, and
// expose its constant term as a Rational (the engine's expansion point never
// involves α, so constant terms are always plain rationals). For the integer recurrence
// (euler_recurrence.hpp) a ring element also converts to and from an integer polynomial
// (a Rational is a constant polynomial) under a given denominator.
#pragma once

#include <flint/fmpq.h>
#include <flint/fmpq_poly.h>
#include <flint/fmpz.h>
#include <flint/fmpz_poly.h>

#include "gkt/algebra/rational.hpp"
#include "gkt/algebra/rational_polynomial.hpp"

namespace gkt::detail {

inline Rational constant_term(const Rational& x) { return x; }
inline Rational constant_term(const RationalPolynomial& x) { return x.constant_value(); }

inline void scale(Rational& x, const Rational& c) { x *= c; }
inline void scale(RationalPolynomial& x, const Rational& c) { x *= c; }
inline void divide(Rational& x, const Rational& c) { x /= c; }
inline void divide(RationalPolynomial& x, const Rational& c) { x /= c; }

/// acc += y·s for a rational scalar s (`scratch`: reusable storage of the product).
inline void add_scaled(Rational& acc, const Rational& y, const Rational& s, Rational& /*scratch*/) {
  acc.add_product(y, s);
}
inline void add_scaled(RationalPolynomial& acc, const RationalPolynomial& y, const Rational& s,
                       RationalPolynomial& scratch) {
  fmpq_poly_scalar_mul_fmpq(scratch.raw(), y.raw(), s.raw());
  fmpq_poly_add(acc.raw(), acc.raw(), scratch.raw());
}

/// c ← lcm(c, denominator of x).
inline void accumulate_denominator(fmpz* c, const Rational& x) { fmpz_lcm(c, c, fmpq_denref(x.raw())); }
inline void accumulate_denominator(fmpz* c, const RationalPolynomial& x) { fmpz_lcm(c, c, fmpq_poly_denref(x.raw())); }

/// out ← c·x, an integer polynomial when the denominator of x divides c.
inline void integer_numerator(fmpz_poly_struct* out, const Rational& x, const fmpz* c) {
  fmpz_poly_zero(out);
  if (x.is_zero()) return;
  fmpz_t v;
  fmpz_init(v);
  fmpz_divexact(v, c, fmpq_denref(x.raw()));
  fmpz_mul(v, v, fmpq_numref(x.raw()));
  fmpz_poly_set_fmpz(out, v);
  fmpz_clear(v);
}
inline void integer_numerator(fmpz_poly_struct* out, const RationalPolynomial& x, const fmpz* c) {
  fmpq_poly_get_numerator(out, x.raw());
  fmpz_t v;
  fmpz_init(v);
  fmpz_divexact(v, c, fmpq_poly_denref(x.raw()));
  fmpz_poly_scalar_mul_fmpz(out, out, v);
  fmpz_clear(v);
}

/// Returns numerator/denominator in the ring, in canonical (reduced) form.
template <class Ring>
Ring ring_from_integer(const fmpz_poly_struct* numerator, const fmpz* denominator);
template <>
inline Rational ring_from_integer<Rational>(const fmpz_poly_struct* numerator, const fmpz* denominator) {
  Rational r;
  if (numerator->length > 0) fmpq_set_fmpz_frac(r.raw(), numerator->coeffs, denominator);
  return r;
}
template <>
inline RationalPolynomial ring_from_integer<RationalPolynomial>(const fmpz_poly_struct* numerator,
                                                                const fmpz* denominator) {
  RationalPolynomial r;
  fmpq_poly_set_fmpz_poly(r.raw(), numerator);
  fmpq_poly_scalar_div_fmpz(r.raw(), r.raw(), denominator);
  return r;
}

}  // namespace gkt::detail
