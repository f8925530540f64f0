// The homogeneous cooling state of rough inelastic hard spheres (d = 3) or disks (d = 2) of one
// species: the temperature ratio θ = T_r/T_t, the reduced cooling rate and the fourth-degree
// cumulants of the joint distribution of c = v/√(2T_t/m) and ŵ = (σ/2)ω/√(2T_r/(κm))
// (docs/theory.md §19.4–19.6):
//   a20 = ⟨c⁴⟩/⟨c⁴⟩_M − 1,   a02 = ⟨ŵ⁴⟩/⟨ŵ⁴⟩_M − 1,   a11 = ⟨c²ŵ²⟩/(⟨c²⟩⟨ŵ²⟩) − 1.
// Every collision average comes from the rough engine (rough_collision_moments.hpp) with θ
// symbolic, as an exact Laurent polynomial in θ/κ; θ is then the root of one equation.
#pragma once

#include <string>
#include <vector>

#include "gkt/algebra/rational.hpp"

namespace gkt {

/// First approximation (Maxwellian: θ only; [huthmann1997]; [luding1998]) or the linear Sonine
/// scheme with a20, a02, a11 (products of cumulants dropped; cf. [santos2011rough]).
enum class RoughHcsScheme { maxwellian, linear };

/// The rough HCS. At β = −1 the spin is not changed by collisions: the translational part is the
/// smooth gas (cooling_rate and a20 as for smooth spheres), the spin has no cooling state and
/// temperature_ratio = +inf, a02 = a11 = NaN (spin_decoupled = true).
struct RoughCoolingState {
  double temperature_ratio = 1;  ///< θ = T_r/T_t
  double cooling_rate = 0;       ///< ζ* = ζ/ν0, ν0 = n T_t/η0(T_t) (the smooth gas's reduction, conventions.md)
  /// The cumulants a20, a02, a11 (docs/theory.md §19.6); a02 = a11 = NaN when spin_decoupled.
  /// @{
  double a20 = 0, a02 = 0, a11 = 0;
  /// @}
  /// True at β = −1: the spin is not changed by collisions (temperature_ratio = +inf, a02 = a11 = NaN).
  bool spin_decoupled = false;
  /// False when the linear scheme has no real solution near the Maxwellian θ with realizable
  /// cumulants (rough_cumulants_realizable; every field NaN):
  /// the fourth-degree balance of the spin is then not damped by collisions faster than the
  /// scaling 2ζ amplifies it (theory.md §19.6).
  bool linear_scheme_solved = true;
};

/// Returns the HCS for d ∈ {2, 3}, α ∈ (0, 1], β ∈ [−1, 1], κ ∈ (0, 1] (std::invalid_argument
/// naming the field otherwise). Cost: three exact engine tables, ~0.1 s.
RoughCoolingState rough_homogeneous_cooling_state(int dimension, const Rational& alpha, const Rational& beta,
                                                  const Rational& kappa, RoughHcsScheme scheme);

/// Returns true if (a20, a02, a11) are cumulants some non-negative distribution can have: the
/// variances of x = c² and y = ŵ² are non-negative, a20 ≥ −2/(d+2), a02 ≥ −2/(d_r+2), and their
/// covariance obeys Cauchy–Schwarz, d d_r a11² ≤ (2 + (d+2)a20)(2 + (d_r+2)a02) (theory.md §19.6).
bool rough_cumulants_realizable(int dimension, double a20, double a02, double a11);

/// Returns a one-line description of where in (α, β, κ) the linear scheme has no root for
/// dimension d (mapped in theory.md §19.6), for error messages.
std::string rough_linear_no_root_region(int dimension);

/// Returns the exact coefficients (c0, c1, c2) of the Maxwellian temperature-ratio equation
/// c0 + c1 τ + c2 τ² = 0, τ = θ/κ (energy balance ζ_t = ζ_r with both temperatures' Maxwellians).
std::vector<Rational> rough_maxwellian_temperature_equation(int dimension, const Rational& alpha, const Rational& beta,
                                                            const Rational& kappa);

}  // namespace gkt
