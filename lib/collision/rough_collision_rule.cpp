#include "gkt/collision/rough_collision_rule.hpp"

#include <stdexcept>
#include <string>

#include "collision/ring.hpp"
#include "collision/rough_pair_map.hpp"

namespace gkt {

namespace {

void check_parameters(int dimension, const Rational& alpha, const Rational& beta, const Rational& kappa) {
  detail::check_rough_restitution(dimension, alpha, beta);
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

template <class Ring>
RoughCollisionMap<Ring> RoughCollisionParameters<Ring>::collision_map() const {
  // Coordinates at fixed σ̂ (theory.md §19.2): normal velocity block (v1n, v2n), normal spin block
  // (ŵ1n, ŵ2n) (d = 3), and, per tangential direction, (v1t, v2t, ŝ1, ŝ2) with ŝ = ŵ × σ̂
  // (disks: ŝ = ŵ ẑ × σ̂), a rotation of the tangential spin, so that g_c,t = v1t − v2t + λ(ŝ1 + ŝ2).
  const Ring en = normal_factor(), et = tangential_factor();
  Ring et_over_kappa = et;
  detail::divide(et_over_kappa, kappa);
  // Δv1n = −η_n u, Δv2n = +η_n u; Δv1t = −η_t g_c,t, Δv2t = +η_t g_c,t, Δŝ_k·λ = −(η_t/κ) g_c,t.
  return detail::assemble_rough_pair_map<Ring>(dimension, {.width = {Rational(1), Rational(1), spin_width, spin_width},
                                                           .spin_scale_i = spin_scale,
                                                           .spin_scale_j = spin_scale,
                                                           .normal_i = en,
                                                           .normal_j = en,
                                                           .tangential_i = et,
                                                           .tangential_j = et,
                                                           .spin_i = et_over_kappa,
                                                           .spin_j = et_over_kappa});
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
