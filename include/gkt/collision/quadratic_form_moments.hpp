// Collision moments of products of arbitrary quadratic forms in the four collision velocities
// W = (v1, v2, v1', v2'): the building block of integrands that carry the collision vector σ̂
// itself, as the Enskog collisional-transfer terms do (docs/theory.md §15).
//
// A vector in "slot space" is a linear combination Σ_a w_a W_a; the collision vector enters
// through H = g − g' = (v1 − v2) − (v1' − v2') = (1+α)(σ̂·g)σ̂ (theory.md (2.1)). The scalar
// product of two slot vectors is a quadratic form W·Q W, so any polynomial in such products is
// a Taylor coefficient of the closed-form integral J(Q) (theory.md §3).
#pragma once

#include <array>
#include <vector>

#include "gkt/algebra/rational.hpp"
#include "gkt/algebra/rational_polynomial.hpp"
#include "gkt/collision/collision_rule.hpp"

namespace gkt {

/// Coefficients of a vector Σ_a w_a W_a over the slots (v1, v2, v1', v2').
using SlotVector = std::array<Rational, 4>;

/// Returns the slot vector of one velocity.
SlotVector slot_vector(Slot s);
/// Returns H = v1 − v2 − v1' + v2' = (1+α)(σ̂·g)σ̂.
SlotVector collision_vector();
/// Returns a + c·b.
SlotVector combine(const SlotVector& a, const SlotVector& b, const Rational& c);

/// The scalar product a·b of two slot vectors, as a symmetric 4×4 form.
using VelocityForm = std::array<std::array<Rational, 4>, 4>;
/// Returns the symmetric form Q with W·Q W = a·b.
VelocityForm dot_form(const SlotVector& a, const SlotVector& b);

/// Moments ⟨(σ̂·g)^s Π_v F_v^{k_v}⟩ / J_s0 for up to four quadratic forms F_v, 0 ≤ k_v ≤ degree_v,
/// where ⟨X⟩ = ∫dv1 dv2 dσ̂ Θ(σ̂·g)(σ̂·g) e^{−θ_i v1² − θ_j v2²} X and J_s0 = ⟨(σ̂·g)^s⟩. Exact in
/// Ring (α a number or symbolic). power_factor() = J_s0/J0 (double) converts to J0 units.
template <class Ring>
class QuadraticFormMoments {
 public:
  /// Throws std::invalid_argument if more than four forms are given or the sizes differ.
  QuadraticFormMoments(const CollisionPair& pair, const Ring& alpha, const std::vector<VelocityForm>& forms,
                       const std::vector<int>& degrees, const Rational& power = Rational(0));
  /// Returns ⟨(σ̂·g)^s Π F_v^{k_v}⟩/J_s0 (exact); throws std::out_of_range outside the box.
  [[nodiscard]] Ring moment(const std::array<int, 4>& k) const;
  /// Returns J_s0/J0 = Γ(1 + s/2)(A0/N2_0)^{s/2}.
  [[nodiscard]] double power_factor() const { return power_factor_; }

 private:
  std::array<int, 4> box_{};
  std::vector<Ring> values_;
  double power_factor_ = 1.0;
};

extern template class QuadraticFormMoments<Rational>;
extern template class QuadraticFormMoments<RationalPolynomial>;

}  // namespace gkt
