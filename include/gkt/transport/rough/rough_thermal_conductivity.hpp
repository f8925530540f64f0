// Thermal conductivity of the dilute rough gas (d = 3; d = 2 by the dimension overloads) in the first Sonine
// approximation with Maxwellian weights at the Maxwellian HCS θ (docs/theory.md §19.7): translational and rotational
// heat-flux trial functions ψ1 = c(c² − 5/2), ψ2 = c(ŵ² − 3/2), the Chapman–Enskog equation (𝓛 − 2ζ)𝔄 = ψ1 + ψ2 and the
// total energy flux q = −κ∇T_t − μ∇n; μ from (𝓛 − (3/2)ζ)𝔅 = ζ𝔄.
#pragma once

#include <array>

#include "gkt/algebra/rational.hpp"

namespace gkt {

/// The conductivity and its translational part.
struct RoughThermalConductivity {
  double total = 0;          ///< κ/κ0(T_t), q = total energy flux (translational + rotational)
  double translational = 0;  ///< the translational flux alone, same reduction
  /// μ* = nμ/(T_t κ0) in q = −κ∇T_t − μ∇n, from (𝓛 − (3/2)ζ)𝔅 = ζ𝔄 (theory.md (19.16))
  double density_heat_total = 0;
  double density_heat_translational = 0;  ///< its translational flux alone
};

/// The 2×2 first-Sonine heat operator L_ij = ⟨ψ_i, 𝓛ψ_j⟩ (ψ1 = c(c² − (d+2)/2), ψ2 = c(ŵ² − d_r/2); the
/// normalisation of theory.md (5.2)).
using RoughHeatOperator = std::array<std::array<double, 2>, 2>;

/// Returns κ*, μ* (reduction as above) from L at θ and ζ* = ζ/ν0(T_t) (theory.md (19.15)–(19.16)), for
/// any collision rule with Maxwellian weights (constant β or Coulomb friction); θ = +inf: the spin
/// decoupled (β = −1), translational channel only.
RoughThermalConductivity rough_heat_flux_response(int dimension, const RoughHeatOperator& l, double theta,
                                                  double zeta_star);

/// Returns κ* for spheres with α ∈ (0, 1], β ∈ (−1, 1], κ ∈ (0, 1] at the Maxwellian HCS θ. At
/// β = −1 the rotational flux of the non-cooling spin has no HCS value: total = NaN, translational
/// = the smooth first-Sonine κ*. Throws std::invalid_argument naming the field otherwise.
RoughThermalConductivity rough_thermal_conductivity(const Rational& alpha, const Rational& beta, const Rational& kappa);

/// Returns the same at a given θ = T_r/T_t, with ζ* the Maxwellian cooling rate at that θ
/// (α = β = 1, θ = 1: Pidduck's gas).
RoughThermalConductivity rough_thermal_conductivity_at(const Rational& alpha, const Rational& beta,
                                                       const Rational& kappa, double temperature_ratio);

/// Returns κ*, μ* (reduced as above) for spheres (d = 3) or disks (d = 2, one rotational degree of
/// freedom: ψ1 = c(c² − 2), ψ2 = c(ŵ² − 1/2)) at the Maxwellian HCS θ; the 3D overloads above are
/// dimension = 3 (theory.md (19.15)–(19.16)).
RoughThermalConductivity rough_thermal_conductivity(int dimension, const Rational& alpha, const Rational& beta,
                                                    const Rational& kappa);

/// Returns the same at a given θ with the Maxwellian ζ* at that θ, d ∈ {2, 3}.
RoughThermalConductivity rough_thermal_conductivity_at(int dimension, const Rational& alpha, const Rational& beta,
                                                       const Rational& kappa, double temperature_ratio);

}  // namespace gkt
