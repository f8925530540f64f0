#include "gkt/collision/rough_collision_rule.hpp"

#include <array>
#include <cstddef>
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

template <class Ring>
RoughCollisionMap<Ring> RoughCollisionParameters<Ring>::collision_map() const {
  // Coordinates at fixed σ̂ (theory.md §19.2): normal velocity block (v1n, v2n), normal spin block
  // (ŵ1n, ŵ2n) (d = 3), and, per tangential direction, (v1t, v2t, ŝ1, ŝ2) with ŝ = ŵ × σ̂
  // (disks: ŝ = ŵ ẑ × σ̂), a rotation of the tangential spin, so that g_c,t = v1t − v2t + λ(ŝ1 + ŝ2).
  const Ring zero(0L), one(1L);
  const Ring en = normal_factor(), et = tangential_factor();
  Ring et_over_kappa = et;
  detail::divide(et_over_kappa, kappa);
  const Ring& lambda = spin_scale;
  RoughCollisionMap<Ring> r;
  r.dimension = dimension;
  r.width = {Rational(1), Rational(1), spin_width, spin_width};
  for (auto& row : r.normal) row.fill(zero);
  for (auto& row : r.tangential) row.fill(zero);
  // Pre-collisional slots.
  r.normal[0] = {one, zero};
  r.normal[1] = {zero, one};
  r.normal[2] = {lambda, zero};
  r.normal[3] = {zero, lambda};
  r.tangential[0][0] = one;
  r.tangential[1][1] = one;
  r.tangential[2][2] = lambda;
  r.tangential[3][3] = lambda;
  // Post-collisional: normal parts (u = v1n − v2n), spin normal parts unchanged.
  r.normal[4] = {one - en, en};
  r.normal[5] = {en, one - en};
  r.normal[6] = r.normal[2];
  r.normal[7] = r.normal[3];
  // Tangential parts: g_c,t = (1, −1, λ, λ); Δv1 = −η_t g_c,t, Δv2 = +η_t g_c,t, Δŝ_k·λ = −(η_t/κ) g_c,t.
  const std::array<Ring, 4> gct{one, -one, lambda, lambda};
  for (std::size_t c = 0; c < 4; ++c) {
    r.tangential[4][c] = r.tangential[0][c] - et * gct[c];
    r.tangential[5][c] = r.tangential[1][c] + et * gct[c];
    r.tangential[6][c] = r.tangential[2][c] - et_over_kappa * gct[c];
    r.tangential[7][c] = r.tangential[3][c] - et_over_kappa * gct[c];
  }
  return r;
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
