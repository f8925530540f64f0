// Pidduck's perfectly rough elastic spheres (α = β = 1, θ = 1): the first approximation to the
// thermal conductivity from the rough engine, with the translational and rotational heat-flux
// trial functions ψ1 = c(c² − 5/2), ψ2 = c(ŵ² − 3/2) (docs/theory.md §19.7), equals
//   λ/λ0 = 12(1+κ)²(37 + 151κ + 50κ²) / (25(12 + 75κ + 101κ² + 102κ³))
// ([chapman1970] §11.6), exactly. λ0: the smooth elastic first approximation (β = −1 here).
#include <gtest/gtest.h>

#include "gkt/collision/rough_collision_moments.hpp"

using gkt::Rational;
using gkt::RoughCollisionMoments;
using gkt::RoughForm;
using S = gkt::RoughSlot;

namespace {

/// ⟨ψ_i(A)·ψ_j(B)⟩/⟨1⟩ for the slot pairs A = (va, wa), B = (vb, wb); ŵ² = κ w² at θ = 1.
Rational pair(const gkt::RoughCollisionParameters<Rational>& p, S va, S wa, S vb, S wb, int i, int j) {
  const Rational& kappa = p.kappa;
  const RoughForm c = gkt::rough_dot_form(va, vb);
  const RoughForm sa = i == 1 ? gkt::rough_dot_form(va, va) : gkt::scaled(gkt::rough_dot_form(wa, wa), kappa);
  const RoughForm sb = j == 1 ? gkt::rough_dot_form(vb, vb) : gkt::scaled(gkt::rough_dot_form(wb, wb), kappa);
  const Rational ca = i == 1 ? Rational(5, 2) : Rational(3, 2), cb = j == 1 ? Rational(5, 2) : Rational(3, 2);
  const RoughCollisionMoments<Rational> m(p, {c, sa, sb}, {1, 1, 1});
  return m.moment({1, 1, 1, 0}) - cb * m.moment({1, 1, 0, 0}) - ca * m.moment({1, 0, 1, 0}) +
         ca * cb * m.moment({1, 0, 0, 0});
}

/// ⟨ψ_i, 𝓛ψ_j⟩ in the normalisation of theory.md (5.2).
Rational operator_element(const gkt::RoughCollisionParameters<Rational>& p, int i, int j) {
  return pair(p, S::v1, S::w1, S::v1, S::w1, j, i) - pair(p, S::v1, S::w1, S::v1_post, S::w1_post, j, i) +
         pair(p, S::v2, S::w2, S::v1, S::w1, j, i) - pair(p, S::v2, S::w2, S::v1_post, S::w1_post, j, i);
}

}  // namespace

TEST(RoughPidduckGas, ThermalConductivityFirstApproximation) {
  for (const Rational& kappa : {Rational(2, 5), Rational(1, 10), Rational(1), Rational(1, 2)}) {
    const auto rough = gkt::rough_parameters(3, Rational(1), Rational(1), kappa, Rational(1));
    const auto smooth = gkt::rough_parameters(3, Rational(1), Rational(-1), kappa, Rational(1));
    const Rational l11 = operator_element(rough, 1, 1), l12 = operator_element(rough, 1, 2),
                   l21 = operator_element(rough, 2, 1), l22 = operator_element(rough, 2, 2);
    EXPECT_EQ(l12, l21);  // elastic: the operator is symmetric
    // Driving term c(c² + ŵ² − 4) = ψ1 + ψ2; projections b = (⟨ψ1²⟩, ⟨ψ2²⟩) = (15/4, 9/4); the heat
    // flux is ⟨(ψ1 + ψ2)·𝔄⟩ = bᵀ L⁻¹ b.
    const Rational b1(15, 4), b2(9, 4);
    const Rational flux = (b1 * (l22 * b1 - l12 * b2) + b2 * (l11 * b2 - l21 * b1)) / (l11 * l22 - l12 * l21);
    const Rational smooth_flux = b1 * b1 / operator_element(smooth, 1, 1);
    const Rational one(1), k = kappa;
    const Rational pidduck =
        Rational(12) * (one + k) * (one + k) * (Rational(37) + Rational(151) * k + Rational(50) * k * k) /
        (Rational(25) * (Rational(12) + Rational(75) * k + Rational(101) * k * k + Rational(102) * k * k * k));
    EXPECT_EQ(flux / smooth_flux, pidduck) << "kappa=" << kappa;
  }
}
