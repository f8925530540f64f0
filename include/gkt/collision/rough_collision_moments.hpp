// Collision moments of rough spheres and disks: averages over collisions of products of
// quadratic forms in the translational and spin velocities of both partners before and after
// the collision, exact in Ring (docs/theory.md §19.2–19.3).
//
//   ⟨X⟩ = ∫dv1 dv2 dŵ1 dŵ2 dσ̂ Θ(u) u e^{−v1² − v2² − s(ŵ1² + ŵ2²)} X,   u = σ̂·(v1 − v2),
//
// with w = λŵ, s = spin_width (rough_collision_rule.hpp). At fixed σ̂ the spin enters the
// collision only through the tangential part of (w1 + w2) × σ̂, so the integrand is Gaussian in
// the normal components and in the tangential components separately; the closed form is
//   J = const · a^{1/2} n_v^{−1} n_w^{−1/2 (d = 3 only)} t^{−(d−1)/2}     (theory.md (19.5)),
// a, n_v, n_w, t determinants of the normal-velocity, normal-spin and tangential blocks, and
// every moment is a Taylor coefficient of it (the Euler recurrence of theory.md §3). Forms
// coupling v and w (d = 3) join the normal blocks and add a Hermitian part to the tangential one:
//   J = const · a^{1/2} n^{−1} det(A + iB)^{−1}                             (theory.md (19.5a)).
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <vector>

#include "gkt/algebra/rational.hpp"
#include "gkt/algebra/rational_polynomial.hpp"
#include "gkt/collision/rough_collision_rule.hpp"

namespace gkt {

/// A quadratic form Σ_ab F_ab W_a·W_b in the eight vectors W of RoughSlot (symmetric 8×8).
/// Entries pairing a translational with a spin slot (v·w) are allowed for d = 3 (theory.md (19.5a)).
using RoughForm = std::array<std::array<Rational, 8>, 8>;

/// Returns the form W_a·W_b (symmetrised).
RoughForm rough_dot_form(RoughSlot a, RoughSlot b);
/// Returns c·F.
RoughForm scaled(const RoughForm& f, const Rational& c);
/// Returns F + G.
RoughForm operator+(const RoughForm& f, const RoughForm& g);

/// Most forms one RoughCollisionMoments expands in: nine, the products P(1)P(2)P(1') of the oriented nonlinear HCS
/// (theory.md §19.14); the recurrence runs in eight variables up to eight forms.
inline constexpr std::size_t kMaxRoughForms = 9;

/// Exponents k_v of the forms in a moment; forms past the ones given have exponent 0.
using RoughExponents = std::array<int, kMaxRoughForms>;

/// Returns the exponents k of the first K forms padded with zeros to all kMaxRoughForms forms.
template <std::size_t K>
requires(K <= kMaxRoughForms) [[nodiscard]] constexpr RoughExponents rough_exponents(const std::array<int, K>& k) {
  RoughExponents all{};
  for (std::size_t v = 0; v < K; ++v) all[v] = k[v];
  return all;
}

/// Moments ⟨Π_v F_v^{k_v}⟩/⟨1⟩ for up to nine rough forms F_v, 0 ≤ k_v ≤ degree_v (exact in Ring).
template <class Ring>
class RoughCollisionMoments {
 public:
  /// Throws std::invalid_argument for more than kMaxRoughForms forms, mismatched sizes, negative
  /// degrees or a form that pairs a translational with a spin slot when d = 2 (v·w vanishes for
  /// disks).
  RoughCollisionMoments(const RoughCollisionParameters<Ring>& parameters, const std::vector<RoughForm>& forms,
                        const std::vector<int>& degrees);
  /// As above, computing only the moments whose exponents `keep` accepts inside the box. The
  /// accepted set must be down-closed (k kept and k' ≤ k componentwise ⇒ k' kept), e.g. caps on the
  /// total degree of groups of forms; the cost falls with its size (docs/performance.md).
  RoughCollisionMoments(const RoughCollisionParameters<Ring>& parameters, const std::vector<RoughForm>& forms,
                        const std::vector<int>& degrees, std::function<bool(const RoughExponents&)> keep);
  /// As above for any rough collision map (e.g. a pair of species, rough_mixture_collision_moments.hpp):
  /// moments ⟨Π F_v^{k_v}⟩/⟨1⟩ with the map's Gaussian weights. Throws std::invalid_argument as
  /// above and for a width ≤ 0.
  RoughCollisionMoments(const RoughCollisionMap<Ring>& map, const std::vector<RoughForm>& forms,
                        const std::vector<int>& degrees, std::function<bool(const RoughExponents&)> keep = {});
  /// Returns ⟨Π F_v^{k_v}⟩/⟨1⟩ (velocities in units of √(2T_t/m)); throws std::out_of_range
  /// outside the expanded box or the kept set. Unlisted trailing exponents are 0 (`moment({i, j})`).
  [[nodiscard]] Ring moment(const RoughExponents& k) const;
  /// Returns moment(k) for a shorter exponent array (the forms past K at exponent 0).
  template <std::size_t K>
  requires(K < kMaxRoughForms) [[nodiscard]] Ring moment(const std::array<int, K>& k) const {
    return moment(rough_exponents(k));
  }

 private:
  RoughExponents box_{};
  std::function<bool(const RoughExponents&)> keep_;
  std::vector<Ring> values_;
};

extern template class RoughCollisionMoments<Rational>;
extern template class RoughCollisionMoments<RationalPolynomial>;

}  // namespace gkt
