// Linear stability of the homogeneous cooling state of the dilute gas: critical wave numbers of
// the shear and heat modes and the critical system size (docs/theory.md §14; [garzo2019] ch. 4;
// seed 003 for the mixture version).
//
// Units: k* = k v0/ν0 and L* = L ν0/v0 with v0 = √(2T/m), ν0 = nT/η0 (docs/conventions.md).
#pragma once

#include <array>
#include <complex>

namespace gkt {

/// Critical values of one state.
struct HcsStability {
  double shear_wavenumber = 0;  ///< k⊥c* = √(ζ*/η*): shear modes grow for k* < k⊥c*
  double heat_wavenumber = 0;  ///< k∥c* = √((d−1)ζ*/((d+2)(κ* − μ*))): the heat mode grows below it (0 if κ* ≤ μ*)
  double critical_length = 0;  ///< L_c* = 2π/max(k⊥c*, k∥c*): boxes larger than this are unstable
};

/// Returns the critical values for dimension d from the reduced ζ*, η*, κ*, μ* (theory.md (14.3)).
HcsStability hcs_stability(int dimension, double cooling_rate, double shear_viscosity, double thermal_conductivity,
                           double density_heat_coefficient);

/// Returns the 3×3 matrix M(k*) of the longitudinal modes (ρ, θ, w∥): ∂_τ X = M X (theory.md (14.2)).
std::array<std::array<std::complex<double>, 3>, 3> longitudinal_matrix(int dimension, double cooling_rate,
                                                                       double shear_viscosity,
                                                                       double thermal_conductivity,
                                                                       double density_heat_coefficient, double k);

}  // namespace gkt
