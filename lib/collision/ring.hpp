// Private: the coefficient rings the engine is instantiated for. A ring element must
// support +=, −=, *=, add_product/sub_product, scaling by an exact Rational, and
// expose its constant term as a Rational (the engine's expansion point never
// involves α, so constant terms are always plain rationals).
#pragma once

#include "gkt/algebra/rational.hpp"
#include "gkt/algebra/rational_polynomial.hpp"

namespace gkt::detail {

inline Rational constant_term(const Rational& x) { return x; }
inline Rational constant_term(const RationalPolynomial& x) { return x.constant_value(); }

inline void scale(Rational& x, const Rational& c) { x *= c; }
inline void scale(RationalPolynomial& x, const Rational& c) { x *= c; }
inline void divide(Rational& x, const Rational& c) { x /= c; }
inline void divide(RationalPolynomial& x, const Rational& c) { x /= c; }

}  // namespace gkt::detail
