#include "gkt/collision/rough_collision_rule.hpp"

#include <stdexcept>
#include <string>

#include "collision/ring.hpp"

namespace gkt {

namespace {

void check_parameters(int dimension, const Rational& alpha, const Rational& beta, const Rational& kappa) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
  if (alpha.sign() <= 0 || alpha > Rational(1))
    throw std::invalid_argument("alpha: must be a number in (0, 1], got " + alpha.to_decimal_string());
  if (beta < Rational(-1) || beta > Rational(1))
    throw std::invalid_argument("beta: must be a number in [-1, 1], got " + beta.to_decimal_string());
  if (kappa.sign() <= 0 || kappa > Rational(1))
    throw std::invalid_argument("moment_of_inertia: must be a number in (0, 1], got " + kappa.to_decimal_string());
}

}  // namespace

template <class Ring>
Ring RoughCollisionParameters<Ring>::normal_factor() const {
  Ring eta = alpha + Ring(1L);
  detail::divide(eta, Rational(2));
  return eta;
}

template <class Ring>
Ring RoughCollisionParameters<Ring>::tangential_factor() const {
  Ring eta = beta + Ring(1L);
  detail::scale(eta, kappa / (Rational(2) * (Rational(1) + kappa)));
  return eta;
}

RoughCollisionParameters<Rational> rough_parameters(int dimension, const Rational& alpha, const Rational& beta,
                                                    const Rational& kappa, const Rational& temperature_ratio) {
  check_parameters(dimension, alpha, beta, kappa);
  if (temperature_ratio.sign() <= 0)
    throw std::invalid_argument("temperature_ratio: must be > 0, got " + temperature_ratio.to_decimal_string());
  return {dimension, alpha, beta, kappa, Rational(1), kappa / temperature_ratio};
}

RoughCollisionParameters<RationalPolynomial> rough_parameters_symbolic_temperature(int dimension, const Rational& alpha,
                                                                                   const Rational& beta,
                                                                                   const Rational& kappa) {
  check_parameters(dimension, alpha, beta, kappa);
  return {dimension, RationalPolynomial(alpha),      RationalPolynomial(beta),
          kappa,     RationalPolynomial::variable(), Rational(1)};
}

template struct RoughCollisionParameters<Rational>;
template struct RoughCollisionParameters<RationalPolynomial>;

}  // namespace gkt
