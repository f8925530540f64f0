// Linear stability of the homogeneous cooling state of the dilute rough gas (spheres or disks with
// spin; docs/theory.md §19.15): the Navier–Stokes equations for n, u and the mean temperature
// T = (dT_t + d_rT_r)/(d + d_r), with T_r slaved to T in the normal solution, linearised about the HCS;
// [garzo2018rough] (their stored copy is the abstract only).
//
// Units as for smooth spheres but at the translational temperature: k* = k v0/ν0, L* = L ν0/v0 with
// v0 = √(2T_t/m), ν0 = nT_t/η0(T_t) (docs/conventions.md).
#pragma once

#include <array>
#include <complex>
#include <limits>

#include "gkt/evolution/hcs_stability.hpp"

namespace gkt {

/// The first-order coefficients of the rough gas at one state, reduced at T_t as in the `rough` model.
struct RoughStabilityInput {
  int dimension = 3;  ///< d = 2 (disks, d_r = 1) or 3 (spheres, d_r = 3)
  /// θ = T_r/T_t on the HCS; +∞: the spin decouples (β = −1, no torque), the hydrodynamic temperature is
  /// T_t and the equations are the smooth gas's (bulk_viscosity and cooling_rate_first_order ignored).
  double temperature_ratio = 1;
  double cooling_rate = 0;              ///< ζ* = ζ/ν0(T_t), ζ the cooling rate of T (and of T_t, T_r)
  double shear_viscosity = 1;           ///< η/η0(T_t)
  double bulk_viscosity = 0;            ///< η_b/η0(T_t), nT_t − nτ_tT = −η_b∇·u (theory.md (19.18))
  double thermal_conductivity = 1;      ///< κ/κ0(T_t), q = −κ∇T_t − μ∇n, q the total energy flux
  double density_heat_coefficient = 0;  ///< nμ/(T_tκ0(T_t))
  double cooling_rate_first_order = 0;  ///< ζ_U, ζ = ζ⁽⁰⁾ + ζ_U∇·u (theory.md (19.19))
  /// Γ* = θ∂(ζ_r* − ζ_t*)/∂θ at fixed T_t (theory.md (19.17)): the relaxation rate of θ; used only by the
  /// four-field analysis (rough_longitudinal_matrix_with_spin), where it must be > 0 unless θ = +∞.
  double relaxation_rate = 0;
  /// Z_δ = ∂(ζ/ν0)/∂δ at fixed n, T (theory.md (19.37), (19.142)); used only by the four-field analysis. NaN (the
  /// default): (d/2)(ζ*/2 + Γ*)ζ_U, exact for the Maxwellian rates; about the Sonine HCS, rough_split_slopes's value.
  double cooling_split_slope = std::numeric_limits<double>::quiet_NaN();
};

/// Returns the translational share of the heat capacity, d/(d + d_rθ) = (d/(d + d_r)) T_t/T on the
/// HCS (1 when θ = +∞: the spin decoupled); theory.md (19.30).
double rough_translational_share(int dimension, double temperature_ratio);

/// Returns the 3×3 matrix M(k*) of the longitudinal modes (ρ, δT/T, w∥) of the rough gas, ∂_τ X = M X
/// (theory.md (19.31)); the d − 1 transverse modes obey (14.1) unchanged.
std::array<std::array<std::complex<double>, 3>, 3> rough_longitudinal_matrix(const RoughStabilityInput& in, double k);

/// Returns the 4×4 matrix M(k*) of the longitudinal modes with the temperature split as a fourth field,
/// X = (ρ, δT/T, w∥, δ), δ = ln(T_r/(θT_t)), ∂_τ X = M X (theory.md (19.36)); T_r is not slaved, so the
/// bulk viscosity and ζ_U of `in` enter only through the split (ζ_U gives ∂ζ*/∂δ, (19.37)). At θ = +∞ (the
/// spin decoupled) the fourth field is δT_r/T_r, decoupled, with eigenvalue 0 (theory.md §19.15.1).
/// Throws std::invalid_argument naming the field as rough_hcs_stability, or if Γ* is not > 0 at finite θ.
std::array<std::array<std::complex<double>, 4>, 4> rough_longitudinal_matrix_with_spin(const RoughStabilityInput& in,
                                                                                       double k);

/// Returns the four eigenvalues of rough_longitudinal_matrix_with_spin(in, k) (growth rates in units of
/// ν0(T_t) of the HCS; Re > 0 grows), ordered by decreasing real part.
std::array<std::complex<double>, 4> rough_longitudinal_modes_with_spin(const RoughStabilityInput& in, double k);

/// Returns the three eigenvalues of rough_longitudinal_matrix(in, k) (units of ν0(T_t); Re > 0 grows),
/// ordered by decreasing real part.
std::array<std::complex<double>, 3> rough_longitudinal_modes(const RoughStabilityInput& in, double k);

/// Returns the critical values with T_r as a fourth field (theory.md §19.15.1): k⊥c* = √(ζ*/η*) as before (the
/// transverse modes do not couple to the scalar δ), k∥c* the largest k* at which an eigenvalue of the 4×4
/// matrix (19.36) crosses Re λ = 0 (0 if none above k* = 0, and where κ* ≤ μ*: a mode grows at every k*), located by a
/// scan and bisection to 1e-12 relative, and L_c* = 2π/max(k⊥c*, k∥c*). Throws as rough_longitudinal_matrix_with_spin.
HcsStability rough_hcs_stability_with_spin(const RoughStabilityInput& in);

/// Returns k⊥c* = √(ζ*/η*), k∥c* of theory.md (19.32) (0 if the heat mode never grows) and
/// L_c* = 2π/max(k⊥c*, k∥c*) (+∞ when both are 0). Throws std::invalid_argument naming the field if
/// d ∉ {2, 3}, θ is not > 0, or η*, κ* are not > 0.
HcsStability rough_hcs_stability(const RoughStabilityInput& in);

}  // namespace gkt
