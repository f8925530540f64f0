#include "gkt/algebra/exact_value.hpp"

#include <cmath>
#include <utility>

#include "algebra/nearby_rational.hpp"

namespace gkt {

ExactValue::ExactValue(double x) : value_(x) {
  if (!std::isfinite(x)) return;
  exact_ = x > 0 ? detail::nearby_rational(x) : x < 0 ? -detail::nearby_rational(-x) : Rational(0);
  value_ = exact_.to_double();
}

ExactValue::ExactValue(Rational x) : exact_(std::move(x)), value_(exact_.to_double()) {}

}  // namespace gkt
