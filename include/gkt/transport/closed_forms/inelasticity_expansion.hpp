// Taylor coefficients of the dilute smooth inelastic coefficients in the inelasticity
// ε = 1 − α² at ε = 0 ([goldhirsch2005] §3; docs/theory.md §11).
#pragma once

#include <array>
#include <string>

#include "gkt/algebra/rational.hpp"

namespace gkt {

/// Returns the exact coefficients c0, c1, c2 of the first-Sonine closed form of `coefficient`
/// (a name of kFirstSonineCoefficients), f = c0 + c1 ε + c2 ε² + O(ε³), α = √(1 − ε).
std::array<Rational, 3> first_sonine_inelasticity_expansion(int dimension, const std::string& coefficient);

/// Taylor coefficients with an error estimate each.
struct EpsilonSeries {
  std::array<double, 3> coefficients{};  ///< c0, c1, c2
  std::array<double, 3> errors{};        ///< estimated |error| of each
};

/// The series of η*, κ*, μ* and ζ* (in this order).
struct InelasticityExpansion {
  /// The series of η*, κ*, μ* and ζ*.
  /// @{
  EpsilonSeries shear_viscosity, thermal_conductivity, density_heat_coefficient, cooling_rate;
  /// @}
};

/// Returns the coefficients at Sonine order `order` (≥ 3): polynomial fit of degree 5 in ε to
/// values at α = 1 − k/400, k = 0…10 (ε ≤ 0.05); error = difference from order − 2 plus the change
/// when the fit degree drops to 4.
InelasticityExpansion inelasticity_expansion(int dimension, int order);

}  // namespace gkt
