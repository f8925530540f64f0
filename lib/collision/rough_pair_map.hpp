// Private: the linear map of one rough pair collision at fixed σ̂, shared by the one-species rule
// (rough_collision_rule.cpp, theory.md (19.2)) and the two-species rule (rough_mixture_collision_rule.cpp,
// theory.md (19.50)). Both are the same map with species-dependent impulse factors; the one-species rule is
// the case n_i = n_j, t_i = t_j, s_i = s_j.
#pragma once

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>

#include "gkt/algebra/rational.hpp"
#include "gkt/collision/rough_collision_map.hpp"

namespace gkt::detail {

/// The impulse factors of one pair (particle 1 of species i, particle 2 of species j).
template <class Ring>
struct RoughPairImpulse {
  std::array<Rational, 4> width;    ///< Gaussian widths of v1, v2, ŵ1, ŵ2
  Ring spin_scale_i, spin_scale_j;  ///< λ_k: w_k = λ_k ŵ_k in the contact velocity
  Ring normal_i, normal_j;          ///< v1n' = v1n − normal_i u, v2n' = v2n + normal_j u (u = v1n − v2n)
  Ring tangential_i, tangential_j;  ///< Δv1t = −tangential_i g_c,t, Δv2t = +tangential_j g_c,t
  Ring spin_i, spin_j;              ///< λ_k Δŝ_k = −spin_k g_c,t (ŝ = ŵ × σ̂)
};

/// Returns the collision map of the pair: slots 0–3 the pre-collisional (v1, v2, ŵ1, ŵ2), 4–7 the
/// post-collisional ones, in the normal block (v1n, v2n) and the tangential block (v1t, v2t, ŝ1, ŝ2),
/// with g_c,t = v1t − v2t + λ_i ŝ1 + λ_j ŝ2 (theory.md §19.2, (19.50)).
template <class Ring>
RoughCollisionMap<Ring> assemble_rough_pair_map(int dimension, const RoughPairImpulse<Ring>& p) {
  const Ring zero(0L), one(1L);
  RoughCollisionMap<Ring> r;
  r.dimension = dimension;
  r.width = p.width;
  for (auto& row : r.normal) row.fill(zero);
  for (auto& row : r.tangential) row.fill(zero);
  r.normal[0] = {one, zero};
  r.normal[1] = {zero, one};
  r.normal[2] = {p.spin_scale_i, zero};
  r.normal[3] = {zero, p.spin_scale_j};
  r.tangential[0][0] = one;
  r.tangential[1][1] = one;
  r.tangential[2][2] = p.spin_scale_i;
  r.tangential[3][3] = p.spin_scale_j;
  // Normal parts: the normal spin is unchanged.
  r.normal[4] = {one - p.normal_i, p.normal_i};
  r.normal[5] = {p.normal_j, one - p.normal_j};
  r.normal[6] = r.normal[2];
  r.normal[7] = r.normal[3];
  const std::array<Ring, 4> gct{one, -one, p.spin_scale_i, p.spin_scale_j};
  for (std::size_t c = 0; c < 4; ++c) {
    r.tangential[4][c] = r.tangential[0][c] - p.tangential_i * gct[c];
    r.tangential[5][c] = r.tangential[1][c] + p.tangential_j * gct[c];
    r.tangential[6][c] = r.tangential[2][c] - p.spin_i * gct[c];
    r.tangential[7][c] = r.tangential[3][c] - p.spin_j * gct[c];
  }
  return r;
}

/// Throws std::invalid_argument naming `dimension`, `alpha` or `beta` unless d ∈ {2, 3}, α ∈ (0, 1],
/// β ∈ [−1, 1].
inline void check_rough_restitution(int dimension, const Rational& alpha, const Rational& beta) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
  if (alpha.sign() <= 0 || alpha > Rational(1))
    throw std::invalid_argument("alpha: must be a number in (0, 1], got " + alpha.to_decimal_string());
  if (beta < Rational(-1) || beta > Rational(1))
    throw std::invalid_argument("beta: must be a number in [-1, 1], got " + beta.to_decimal_string());
}

}  // namespace gkt::detail
