#include "algebra/nearby_rational.hpp"

#include <cmath>

namespace gkt::detail {

Rational nearby_rational(double x, long max_denominator) {
  long p0 = 0, q0 = 1, p1 = 1, q1 = 0;
  double rest = x;
  for (int k = 0; k < 64; ++k) {
    const double a = std::floor(rest);
    if (a > 1e15) break;
    const auto ai = static_cast<long>(a);
    // a ≤ 1e15 and q1 ≤ max_denominator: q2 cannot overflow; p2 can for a large x (stop there).
    const long q2 = ai * q1 + q0;
    if (q2 > max_denominator) break;
    long p2 = 0;
    if (__builtin_mul_overflow(ai, p1, &p2) || __builtin_add_overflow(p2, p0, &p2)) break;
    p0 = p1, q0 = q1, p1 = p2, q1 = q2;
    const double frac = rest - a;
    if (frac < 1e-300 || std::abs(static_cast<double>(p1) / static_cast<double>(q1) - x) <= 1e-17 * x) break;
    rest = 1 / frac;
  }
  if (q1 == 0 || std::abs(static_cast<double>(p1) / static_cast<double>(q1) - x) > 1e-12 * x)
    return Rational::from_double(x);
  return Rational(p1, static_cast<unsigned long>(q1));
}

}  // namespace gkt::detail
