// Linear stability of the homogeneous cooling state of the dilute and the dense (Enskog) gas:
// critical wave numbers of the shear and heat modes and the critical system size (docs/theory.md
// §14; [garzo2019] ch. 4; seed 003 for the mixture version).
//
// Units: k* = k v0/ν0 and L* = L ν0/v0 with v0 = √(2T/m), ν0 = nT/η0 (docs/conventions.md).
#pragma once

#include <array>
#include <complex>
#include <vector>

#include "gkt/transport/mixture/mixture.hpp"
#include "gkt/transport/mixture/mixture_navier_stokes.hpp"

namespace gkt {

/// What the dense (Enskog) gas and a temperature-dependent restitution add to the linearised
/// equations (theory.md (14.4), (14.6)); the default is the dilute gas with constant α.
struct StabilityDensity {
  double pressure = 1;                  ///< p* = p/(nT)
  double pressure_derivative = 0;       ///< φ ∂p*/∂φ
  double log_chi_derivative = 0;        ///< λ = φ ∂ln χ/∂φ (ζ0 ∝ χ(φ) n T^{1/2})
  double bulk_viscosity = 0;            ///< bulk viscosity / η0 (longitudinal momentum only)
  double cooling_rate_first_order = 0;  ///< ζ_U (energy equation only)
  /// λ_T = ∂ln ζ/∂ln T at fixed n: ½ for constant α (ζ ∝ n T^{1/2}); ½ + γ δ'ζ'/ζ for viscoelastic
  /// spheres (3/5 as δ' → 0; viscoelastic_transport.hpp).
  double cooling_temperature_exponent = 0.5;
};

/// Critical values of one state.
struct HcsStability {
  double shear_wavenumber = 0;  ///< k⊥c* = √(ζ*/η*): shear modes grow for k* < k⊥c*
  double heat_wavenumber = 0;   ///< k∥c* of (14.3)/(14.5): the heat mode grows below it (0 if it never does)
  double critical_length = 0;   ///< L_c* = 2π/max(k⊥c*, k∥c*): boxes larger than this are unstable
};

/// Returns k⊥c* = √(ζ*/η*), below which the shear (vortex) modes grow (theory.md (14.1)); 0 if ζ* ≤ 0.
double shear_critical_wavenumber(double cooling_rate, double shear_viscosity);

/// Returns L_c* = 2π/k* for the largest critical wave number k* (∞ when k* = 0: never unstable).
double critical_length(double largest_wavenumber);

/// Returns the critical values for dimension d from the reduced ζ*, η*, κ*, μ* (theory.md (14.3);
/// dense gas (14.5), with ζ* = χ ζ*_dilute and the dense η*, κ*, μ*).
HcsStability hcs_stability(int dimension, double cooling_rate, double shear_viscosity, double thermal_conductivity,
                           double density_heat_coefficient, const StabilityDensity& dense = {});

/// Returns the 3×3 matrix M(k*) of the longitudinal modes (ρ, θ, w∥): ∂_τ X = M X (theory.md (14.2),
/// dense (14.4)).
std::array<std::array<std::complex<double>, 3>, 3> longitudinal_matrix(int dimension, double cooling_rate,
                                                                       double shear_viscosity,
                                                                       double thermal_conductivity,
                                                                       double density_heat_coefficient, double k,
                                                                       const StabilityDensity& dense = {});

/// What the longitudinal modes of a mixture need (reduced as in docs/conventions.md "Mixtures";
/// theory.md §17.7, dense §18.8).
struct MixtureStabilityInput {
  /// Spatial dimension d (2 or 3).
  int dimension = 3;
  std::vector<double> fraction;            ///< x_i
  double cooling_rate = 0;                 ///< ζ*
  std::vector<double> cooling_derivative;  ///< n (∂ζ/∂n_j)/ν0 (MixtureCoolingSensitivity::cooling_rate)
  double shear_viscosity = 0;              ///< η*
  double thermal_conductivity = 0;         ///< λ*
  std::vector<double> dufour;              ///< D''_j*
  std::vector<double> drift;               ///< w_i = D0 Σ_j drift[i·s + j] ∇ln n_j + … (s × s)
  std::vector<double> thermal_drift;       ///< … + D0 thermal_drift[i] ∇ln T
  // The dense (Enskog) mixture (theory.md (18.13)); the defaults are the dilute gas.
  double pressure = 1;                      ///< p* = p/(nT)
  std::vector<double> pressure_derivative;  ///< P_j = (∂p/∂n_j)/T (empty: all 1)
  double bulk_viscosity = 0;                ///< κ/η0
  double cooling_rate_first_order = 0;      ///< ζ_U
};

/// Returns the stability input of `mixture` from its Navier–Stokes solver and the coefficients of one
/// order (dilute or dense).
MixtureStabilityInput mixture_stability_input(const Mixture& mixture, const MixtureNavierStokes& solver,
                                              const MixtureTransportValues& values);

/// Returns the critical values of a mixture's HCS: k⊥c* = √(ζ*/η*) and k∥c*, the largest k* at
/// which det M(k*) of (17.14)/(18.13) vanishes (a real eigenvalue crosses zero; 0 if none).
HcsStability mixture_hcs_stability(const MixtureStabilityInput& in);

}  // namespace gkt
