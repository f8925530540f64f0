// Rough spheres and disks with Coulomb friction (Walton's model; docs/theory.md §19.10): the
// tangential restitution depends on the impact angle γ, cot γ = (σ̂·g_c)/|g_c,t|,
//   β(γ) = min{β0, −1 + ((1+κ)/κ)(1+α) μ_f cot γ}
// (sticking, β = β0, at grazing angles below γ0; sliding, the tangential impulse μ_f times the normal
// one, above). Homogeneous cooling state in the first (Maxwellian) approximation and the scalar
// Navier–Stokes response (bulk viscosity, first-order cooling rate) of rough_bulk_viscosity.hpp.
#pragma once

#include "gkt/algebra/rational.hpp"
#include "gkt/transport/rough/rough_thermal_conductivity.hpp"

namespace gkt {

/// The Maxwellian energy rates ζ_t/ν0(T_t), ζ_r/ν0(T_t) (ν0 = nT_t/η0(T_t)).
struct RoughWaltonRates {
  /// ζ_t/ν0(T_t).
  double translational = 0;
  /// ζ_r/ν0(T_t).
  double rotational = 0;
};

/// Returns the rates for two Maxwellians at T_t and T_r = θT_t, d ∈ {2, 3}, α ∈ (0, 1],
/// β0 ∈ [−1, 1], κ ∈ (0, 1], μ_f ≥ 0 (μ_f = +inf: constant β = β0). The angular average is a 1D
/// integral (composite Simpson, `intervals` panels on |g_c,t| ≤ 12 standard deviations) after the
/// normal relative velocity is integrated in closed form; relative error below 1e-10 with the
/// default (theory.md (19.21)). Throws std::invalid_argument naming the field.
RoughWaltonRates rough_walton_rates(int dimension, double alpha, double beta0, double kappa, double friction,
                                    double temperature_ratio, int intervals = 4000);

/// Returns the Maxwellian HCS temperature ratio θ = T_r/T_t of the Walton gas: the first sign change of
/// ζ_t − ζ_r (rough_walton_rates) upwards in ln θ ∈ [−20, 20] (steps 1/4, then bisection to 1e-13 in ln θ;
/// the stable root, theory.md §19.10), or +inf when there is none (μ_f = 0, β0 = −1, or friction too weak
/// for the spin to keep up). Ranges as rough_walton_rates; throws std::invalid_argument naming the field.
double rough_walton_temperature_ratio(int dimension, double alpha, double beta0, double kappa, double friction);

/// Returns the first-Sonine shear viscosity η* = η/η0(T_t) = 1/(L_η/(d − 1) − ζ*/2) (theory.md (19.13))
/// of the Walton gas at θ (Maxwellians at T_t and θT_t), ranges as above. L_η is a collision average of
/// quartic forms: conditioned on the normal relative velocity u and g_c,t (which fix η_t) the velocities
/// are Gaussian, the quartic moments follow from Isserlis' theorem, and (u, |g_c,t|) are integrated by
/// composite Simpson with the sticking–sliding kink u = (η0/M)|g_c,t| as a panel edge (`intervals`
/// panels per piece; relative error ≈ 1e-8 with the default, h⁴; theory.md (19.23)).
double rough_walton_shear_viscosity(int dimension, double alpha, double beta0, double kappa, double friction,
                                    double temperature_ratio, int intervals = 400);

/// Returns the first-Sonine heat operator L_ij = ⟨ψ_i, 𝓛ψ_j⟩ of the Walton gas at θ (as
/// rough_thermal_conductivity.hpp; sextic forms by Isserlis' theorem on the conditioned Gaussian of
/// (19.23), (u, |g_c,t|) by composite 8-point Gauss–Legendre, `panels` panels per piece, the
/// sticking–sliding kink a panel edge; relative error ≈ 1e-10 with the default).
RoughHeatOperator rough_walton_heat_operator(int dimension, double alpha, double beta0, double kappa, double friction,
                                             double temperature_ratio, int panels = 8);

/// Returns κ*, μ* of the Walton gas at θ (theory.md (19.15)–(19.16) with the operator above and the
/// Maxwellian ζ* of rough_walton_rates).
RoughThermalConductivity rough_walton_thermal_conductivity(int dimension, double alpha, double beta0, double kappa,
                                                           double friction, double temperature_ratio, int panels = 8);

/// The Walton HCS (Maxwellian) and its scalar response.
struct RoughWaltonState {
  double temperature_ratio = 0;         ///< θ = T_r/T_t; +inf when the spin decouples (see below)
  double cooling_rate = 0;              ///< ζ* = ζ/ν0(T_t)
  double bulk_viscosity = 0;            ///< η_b/η0(T_t), theory.md (19.18)
  double cooling_rate_first_order = 0;  ///< ζ_U, theory.md (19.19)
  double shear_viscosity = 0;           ///< η/η0(T_t) at first Sonine, theory.md (19.23)
  double thermal_conductivity = 0;      ///< κ/κ0(T_t), total energy flux (theory.md (19.15))
  double density_heat_coefficient = 0;  ///< nμ/(T_tκ0(T_t)), q = −κ∇T_t − μ∇n (theory.md (19.16))
  /// True when ζ_t = ζ_r has no finite root: μ_f = 0 or β0 = −1 (no torque), or friction too weak
  /// for the spin to keep up (θ grows without bound); then θ = +inf and the rest NaN.
  bool spin_decoupled = false;
};

/// Returns the Walton HCS for exact (α, β0, κ, μ_f) (ranges as above); θ by bisection of
/// ζ_t = ζ_r on log θ to 1e-13, the slopes of (19.17) by central differences (≈1e-7 relative).
RoughWaltonState rough_walton_cooling_state(int dimension, const Rational& alpha, const Rational& beta0,
                                            const Rational& kappa, const Rational& friction);

}  // namespace gkt
