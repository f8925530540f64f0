// Closed forms of the first Sonine approximation of the dilute smooth inelastic gas, as exact
// rational functions of α derived by the engine (standard or modified scheme, linear in a2, with the van
// Noije–Ernst a2(α) inserted; docs/theory.md (9.2), (10.8)).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "gkt/algebra/rational_function.hpp"
#include "gkt/transport/common/sonine_scheme.hpp"

namespace gkt {

/// Names of the coefficients that have first-Sonine closed forms, in the order used by
/// FirstSonineValues.
inline const std::array<std::string, 5> kFirstSonineCoefficients{"a2", "cooling_rate", "shear_viscosity",
                                                                 "thermal_conductivity", "density_heat_coefficient"};

/// Returns the exact closed form in α of `coefficient` (one of kFirstSonineCoefficients) for
/// dimension 2 or 3 in the standard or modified scheme (theory.md (10.8), (10.10)); throws
/// std::invalid_argument naming the valid coefficients otherwise.
RationalFunction first_sonine_closed_form(int dimension, const std::string& coefficient,
                                          SonineScheme scheme = SonineScheme::standard);

/// The five first-Sonine coefficients at one α, in double.
struct FirstSonineValues {
  /// a2, ζ* = ζ/ν0, η* = η/η0, κ* = κ/κ0 and μ* = nμ/(Tκ0) at that α.
  /// @{
  double a2, cooling_rate, shear_viscosity, thermal_conductivity, density_heat_coefficient;
  /// @}
};

/// Returns a2, ζ*, η*, κ*, μ* at α from the generated closed forms (lib/transport/generated/,
/// made by `gkt formula --format cpp`): no allocation, ~10² flops, for per-cell use in solvers.
/// Throws std::invalid_argument naming the argument for α outside (0, 1] (nan included) or d ∉ {2, 3}.
FirstSonineValues first_sonine_values(int dimension, double alpha);

}  // namespace gkt
