// Shear viscosity of the dilute rough gas in the first Sonine approximation with Maxwellian
// weights at the temperature ratio θ (docs/theory.md §19.7): η* = η/η0(T_t) = 1/(ν_η* − ζ*/2),
// ν_η* = L_η/(d − 1), L_η = ⟨(Y2(c1) + Y2(c2)) : (Y2(c1) − Y2(c1'))⟩/⟨1⟩ from the rough engine.
#pragma once

#include "gkt/algebra/rational.hpp"

namespace gkt {

/// Returns η* (exact) for given θ = T_r/T_t, with ζ* the Maxwellian cooling rate at that θ
/// (theory.md (19.12), not necessarily the HCS value). α = β = 1, θ = 1 is Pidduck's gas.
/// Throws std::invalid_argument naming the field for parameters out of range.
Rational rough_shear_viscosity_at(int dimension, const Rational& alpha, const Rational& beta, const Rational& kappa,
                                  const Rational& temperature_ratio);

/// Returns η* at the Maxwellian HCS θ (double; θ irrational). At β = −1 the spin decouples and η*
/// is the smooth gas's first Sonine 1/(ν_η* − ζ*/2).
double rough_shear_viscosity(int dimension, const Rational& alpha, const Rational& beta, const Rational& kappa);

}  // namespace gkt
