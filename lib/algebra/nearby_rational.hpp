// Private: short exact rationals for doubles — a caller's number (ExactValue) or a computed width ratio.
#pragma once

#include "gkt/algebra/rational.hpp"

namespace gkt::detail {

/// Returns the continued-fraction convergent of x > 0 with the largest denominator ≤
/// max_denominator if it is within 1e-12 of x (relative), else x itself as an exact dyadic
/// rational. The engine's exact moments cost grows with the size of these numbers.
Rational nearby_rational(double x, long max_denominator = 1L << 26);

}  // namespace gkt::detail
