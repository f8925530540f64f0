// Collision moments of rough spheres and disks with one triple product: averages over collisions of
// W_a·(W_b × W_c) Π_v F_v^{k_v}, W the eight vectors of RoughSlot and F_v quadratic forms
// (rough_collision_moments.hpp), exact in Ring up to the factor √(π/2) (docs/theory.md §19.22).
//
// At fixed σ̂ the triple product is Σ_cyc W_an σ̂·(W_bt × W_ct): a normal component times a tangential bilinear,
// symmetric in the tangential coordinates (v_t, ŝ = ŵ × σ̂) when one factor is a spin, antisymmetric otherwise
// ((19.90)). A linear normal factor k·X against the weight Θ(u)u e^{−XᵀMX} integrates to
// π^{m/2} kᵀ adj(M) ℓ det(M)^{−3/2}/4 ((19.91)); the tangential bilinear is the ε-derivative of det(A + iB)^{−1}
// (d = 3) or det(A)^{−1/2} (d = 2) with the bilinear added to the exponent, so every moment is a Taylor coefficient
// of kᵀ adj(M) ℓ · det(M)^{−3/2} det(A + iB + ε(…))^{−1} ((19.92)). The moments are odd in the normal velocities and
// carry √(π/2) where those of the quadratic forms alone are rational.
#pragma once

#include <array>
#include <vector>

#include "gkt/algebra/rational.hpp"
#include "gkt/algebra/rational_polynomial.hpp"
#include "gkt/collision/rough_collision_map.hpp"
#include "gkt/collision/rough_collision_moments.hpp"
#include "gkt/collision/rough_collision_rule.hpp"

namespace gkt {

/// The triple product W_a·(W_b × W_c) of three RoughSlot vectors (disks: exactly one spin slot, the spin along ẑ).
using RoughTripleProduct = std::array<RoughSlot, 3>;

/// Most quadratic forms beside the triple product: seven (the eighth Taylor variable carries the triple product).
inline constexpr std::size_t kMaxTripleProductForms = 7;

/// Moments ⟨W_a·(W_b × W_c) Π_v F_v^{k_v}⟩/⟨1⟩ / √(π/2) for up to seven rough forms, 0 ≤ k_v ≤ degree_v.
template <class Ring>
class RoughTripleProductMoments {
 public:
  /// Throws std::invalid_argument for more than seven forms, mismatched sizes, negative degrees, a form
  /// pairing v and w when d = 2, a disk triple product without exactly one spin slot, or translational
  /// widths other than 1.
  RoughTripleProductMoments(const RoughCollisionParameters<Ring>& parameters, const RoughTripleProduct& triple,
                            const std::vector<RoughForm>& forms, const std::vector<int>& degrees);
  /// As above for any rough collision map with unit translational widths.
  RoughTripleProductMoments(const RoughCollisionMap<Ring>& map, const RoughTripleProduct& triple,
                            const std::vector<RoughForm>& forms, const std::vector<int>& degrees);
  /// Returns ⟨W_a·(W_b × W_c) Π F_v^{k_v}⟩/⟨1⟩ divided by √(π/2) (velocities in units of √(2T_t/m));
  /// throws std::out_of_range outside the expanded box. Unlisted trailing exponents are 0.
  [[nodiscard]] Ring moment(const RoughExponents& k) const;
  /// Returns moment(k) for a shorter exponent array (the forms past K at exponent 0).
  template <std::size_t K>
  requires(K < kMaxRoughForms) [[nodiscard]] Ring moment(const std::array<int, K>& k) const {
    return moment(rough_exponents(k));
  }

 private:
  RoughExponents box_{};
  std::vector<Ring> values_;
};

extern template class RoughTripleProductMoments<Rational>;
extern template class RoughTripleProductMoments<RationalPolynomial>;

}  // namespace gkt
