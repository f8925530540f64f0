// The homogeneous cooling state of the Walton gas (rough spheres or disks with Coulomb friction,
// rough_walton.hpp) in the linear first-Sonine scheme: θ, ζ* and the cumulants a20, a02, a11
// (docs/theory.md §19.19). The collision averages of (19.10) are computed at fixed τ = θ/κ on the
// Gaussian of the pre-collisional velocities conditioned on the normal relative velocity u and the
// tangential contact velocity |g_c,t| (which fix η_t, (19.23)): every average is a product of at most four
// quadratic forms (c1², ŵ1², c2², ŵ2², c1'², ŵ1'²), whose joint cumulants are traces and chains of the
// conditioned covariance (19.71); (u, |g_c,t|) by composite Gauss–Legendre with the sticking–sliding kink
// a panel edge, as for the heat operator.
#pragma once

#include <array>

#include "gkt/transport/rough/rough_cooling_rates.hpp"

namespace gkt {

/// The linear-scheme collision averages of the Walton gas at one τ.
struct RoughWaltonProductions {
  /// R_X[ψ_t] (weights X ∈ {1, S2(x), S2(y), S1(x)S1(y)}, tests t ∈ {x, y, x², y², xy}), reduced as
  /// RoughCoolingRates::production (theory.md (19.10)).
  RoughProductionTable table{};
  /// 2⟨S_2(x1)⟩ over collisions: the collision frequency is 1 + collision_a20 · a20 times the Maxwellian one.
  double collision_a20 = 0;
};

/// Returns the collision averages at τ = θ/κ > 0 for d ∈ {2, 3}, α ∈ (0, 1], β0 ∈ [−1, 1], κ ∈ (0, 1],
/// μ_f ≥ 0 (+inf: constant β = β0, the exact tables of RoughCoolingRates to ≈1e-10); `panels` 8-point
/// Gauss–Legendre panels per piece in u and in |g_c,t| (theory.md §19.19). Throws std::invalid_argument
/// naming the field.
RoughWaltonProductions rough_walton_productions(int dimension, double alpha, double beta0, double kappa,
                                                double friction, double tau, int panels = 8);

/// The Walton HCS in the linear first-Sonine scheme, with the Maxwellian state it corrects.
struct RoughWaltonCumulantState {
  double temperature_ratio = 0;  ///< θ = T_r/T_t of the linear scheme
  double cooling_rate = 0;       ///< ζ* = ζ/ν0(T_t) of the linear scheme
  /// The cumulants a20, a02, a11 (theory.md (19.9)).
  /// @{
  double a20 = 0, a02 = 0, a11 = 0;
  /// @}
  double maxwellian_temperature_ratio = 0;  ///< θ of the Maxwellian approximation (rough_walton.hpp)
  double maxwellian_cooling_rate = 0;       ///< ζ* of the Maxwellian approximation
  /// True when the Maxwellian ζ_t = ζ_r has no finite root (μ_f = 0, β0 = −1, or friction too weak;
  /// rough_walton.hpp): every field is then +inf (θ) or NaN.
  bool spin_decoupled = false;
  /// False when the linear scheme has no root with realizable cumulants (rough_cumulants_realizable)
  /// within a factor e² of the Maxwellian τ: θ, ζ* and the cumulants are then NaN.
  bool linear_scheme_solved = true;
};

/// Returns the linear-scheme HCS for d ∈ {2, 3}, α ∈ (0, 1], β0 ∈ [−1, 1], κ ∈ (0, 1], μ_f ≥ 0 (ranges
/// as rough_walton_rates): τ by a scan of ln τ (steps 1/16 on a 4-panel rule, outward from the Maxwellian root, ±2) for
/// sign changes of ζ_t − ζ_r after the fourth-degree balances are solved for a(τ), then regula falsi to 1e-12
/// (theory.md §19.19). Cost: ≈ 15–25 quadratures of rough_walton_productions.
RoughWaltonCumulantState rough_walton_linear_cooling_state(int dimension, double alpha, double beta0, double kappa,
                                                           double friction, int panels = 8);

}  // namespace gkt
