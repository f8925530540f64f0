#include "gkt/collision/collision_rule.hpp"

#include <stdexcept>

namespace gkt {

void CollisionPair::validate() const {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
  if (mass_i.sign() <= 0) throw std::invalid_argument("mass_i: must be > 0, got " + mass_i.to_decimal_string());
  if (mass_j.sign() <= 0) throw std::invalid_argument("mass_j: must be > 0, got " + mass_j.to_decimal_string());
  if (theta_i.sign() <= 0) throw std::invalid_argument("theta_i: must be > 0, got " + theta_i.to_decimal_string());
  if (theta_j.sign() <= 0) throw std::invalid_argument("theta_j: must be > 0, got " + theta_j.to_decimal_string());
}

std::array<std::array<Rational, 3>, 4> CollisionPair::velocity_map() const {
  const Rational total = mass_i + mass_j;
  const Rational mu_i = mass_i / total;  // weight of v1 in G
  const Rational mu_j = mass_j / total;  // weight of v2 in G
  // v1 = G + μ_j g, v2 = G − μ_i g, v1' = G + μ_j g', v2' = G − μ_i g'.
  return {{{Rational(1), mu_j, Rational(0)},
           {Rational(1), -mu_i, Rational(0)},
           {Rational(1), Rational(0), mu_j},
           {Rational(1), Rational(0), -mu_i}}};
}

}  // namespace gkt
