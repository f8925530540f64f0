// The slopes of the rough gas's energy production rates with respect to the temperature split δ = ln(T_r/(θT_t)) about
// the Sonine homogeneous cooling state (docs/theory.md §19.27, (19.140)–(19.144)): the relaxation rate Γ* of θ and the
// slope Z_δ = ∂(ζ/ν0)/∂δ of the cooling rate of T that the four-field stability analysis (19.36) needs, from the
// cumulant-corrected rates of the linear Sonine scheme (rough_sonine_cooling_rates.hpp, §19.14), with the cumulants
// held at their HCS values (the closure used) or slaved quasi-statically to θ, and the slowest relaxation rate of the
// homogeneous linear scheme for comparison.
#pragma once

#include <span>

#include "gkt/transport/rough/rough_sonine_cooling_rates.hpp"

namespace gkt {

/// Γ*, Z_δ of one state, reduced by ν0(T_t) (the units of every rough column).
struct RoughSplitSlopes {
  double temperature_ratio = 1;  ///< θ = T_r/T_t of the state
  double cooling_rate = 0;       ///< ζ* = ((d + 2)/4) z_t at the state (z_t of the rates)
  /// Γ* = θ∂(ζ_r* − ζ_t*)/∂θ at fixed T_t with the a_pq, b_pq held (theory.md (19.141)).
  double relaxation_rate = 0;
  /// Z_δ = ∂(ζ/ν0)/∂δ at fixed n, T with the a_pq, b_pq held (theory.md (19.142)); (19.37) at zero cumulants.
  double cooling_split_slope = 0;
  /// Γ* with the a_pq, b_pq following θ on the static solution of their balances (theory.md (19.143)); NaN unless the
  /// state is a stationary point of the linear scheme (residuals ≤ 1e-9).
  double relaxation_rate_slaved = 0;
  double cooling_split_slope_slaved = 0;  ///< Z_δ with the cumulants slaved as relaxation_rate_slaved; NaN likewise
  /// −max Re λ over the eigenvalues λ of the linearised homogeneous scheme (ln θ and every unknown, theory.md
  /// (19.25b)): the late-time rate at which θ approaches the HCS in free cooling (theory.md (19.144)); NaN likewise.
  double homogeneous_relaxation_rate = 0;
  /// |Im λ| of that slowest eigenvalue (0: real; > 0: θ and a cumulant mode relax together as a damped oscillation,
  /// theory.md (19.144)); NaN likewise.
  double homogeneous_relaxation_frequency = 0;
};

/// Returns Γ*, Z_δ of the linear-scheme rates `rates` at θ = temperature_ratio and the unknowns (a_pq then b_pq, in
/// the order of rates.cumulant_indices(), rates.orientation_indices()), from central differences in ln θ (Richardson
/// step 1e-3 → 5e-4) and in the unknowns; the slaved and homogeneous values only at a stationary point (the HCS of
/// rough_sonine_cooling_state at the rates' order, linear scheme). Needs ζ_t* = ζ_r* at the state (|z_r − z_t| ≤
/// 1e-9: the HCS, or the Maxwellian θ with zero unknowns). Throws std::invalid_argument naming the field if θ is not
/// finite and > 0, the unknowns' count differs from rates.unknowns(), the rates differ, or the spin is decoupled.
RoughSplitSlopes rough_split_slopes(const RoughSonineCoolingRates& rates, double temperature_ratio,
                                    std::span<const double> unknowns);

}  // namespace gkt
