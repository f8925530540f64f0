// Bulk viscosity and first-order cooling rate of the dilute rough gas (d = 2, 3) in the first
// Sonine approximation with Maxwellian weights at the Maxwellian HCS θ (docs/theory.md §19.9).
// A compression ∇·u heats the translation alone (p = nT_t), so the normal solution carries a
// translational–rotational temperature split δ = ln(T_r/(θT_t)) ∝ ∇·u, held against the collisional
// relaxation of T_r/T_t:  Π = −η_b ∇·u and ζ = ζ⁽⁰⁾ + ζ_U ∇·u, with T = (dT_t + d_rT_r)/(d + d_r).
#pragma once

#include "gkt/algebra/rational.hpp"

namespace gkt {

/// The scalar (∇·u) response of the rough gas.
struct RoughScalarResponse {
  double bulk_viscosity = 0;            ///< η_b/η0(T_t): the translational pressure nT_t − nτ_tT = −η_b∇·u
  double cooling_rate_first_order = 0;  ///< ζ_U (dimensionless): ζ = ζ⁽⁰⁾ + ζ_U∇·u, ζ the cooling rate of T
  double relaxation_rate = 0;           ///< Γ* = θ∂(ζ_r − ζ_t)/∂θ / ν0 at fixed T_t (theory.md (19.17))
};

/// Returns η_b* and ζ_U for d ∈ {2, 3}, α ∈ (0, 1], β ∈ (−1, 1], κ ∈ (0, 1] at the Maxwellian HCS θ
/// (theory.md (19.18)–(19.19)). At β = −1 the spin has no cooling state: both NaN. Throws
/// std::invalid_argument naming the field otherwise.
RoughScalarResponse rough_bulk_viscosity(int dimension, const Rational& alpha, const Rational& beta,
                                         const Rational& kappa);

/// Returns the same at a given θ = T_r/T_t with ζ* the Maxwellian cooling rate at that θ
/// (α = β = 1, θ = 1: Pidduck's gas, η_b* = 4d_r²(1+κ)²/((d+d_r)²(d+2)(d−1)κ), theory.md (19.20)).
RoughScalarResponse rough_bulk_viscosity_at(int dimension, const Rational& alpha, const Rational& beta,
                                            const Rational& kappa, double temperature_ratio);

/// Returns η_b* and ζ_U from the Maxwellian energy rates of any rough collision rule (constant β or
/// Coulomb friction): θ = T_r/T_t on the HCS, ζ* = ζ/ν0(T_t) and the slopes θ∂ζ_t*/∂θ, θ∂ζ_r*/∂θ at
/// fixed T_t (ζ_{t,r}* = ζ_{t,r}/ν0(T_t)), theory.md (19.17)–(19.19).
RoughScalarResponse rough_scalar_response(int dimension, double theta, double zeta_star, double translational_slope,
                                          double rotational_slope);

}  // namespace gkt
