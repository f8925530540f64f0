// Time evolution of a freely cooling homogeneous gas of rough spheres or disks: the translational
// and rotational temperatures T_t(τ), T_r(τ) and, in the linear first-Sonine scheme, the cumulants
// a20, a02, a11 (and for spheres, optionally, the orientation coefficient b00), or at Sonine order N every a_pq
// (and b_pq) of the linear or nonlinear scheme (docs/theory.md §19.13, §19.24), integrated with
// SUNDIALS CVODE (BDF, dense, difference- quotient Jacobian). From any θ(0) = T_r(0)/T_t(0) the ratio relaxes to the
// HCS value of rough_homogeneous_cooling_state (the same balances) and T_t then follows Haff's law.
//
// Time τ = ω_M t with ω_M = nσ^{d−1}v_ref ν (ν of theory.md (5.3)) the Maxwellian collision
// frequency at the reference temperature T_ref in which the temperatures are given
// (v_ref = √(2T_ref/m)); `collisions` counts collisions per particle.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "gkt/evolution/homogeneous_cooling_evolution.hpp"
#include "gkt/transport/rough/rough_cooling_rates.hpp"
#include "gkt/transport/rough/rough_oriented_cooling_rates.hpp"
#include "gkt/transport/rough/rough_sonine_cooling_rates.hpp"

namespace gkt {

/// One output time of a rough-gas trajectory.
struct RoughEvolutionSample {
  double time = 0;                       ///< τ = ω_M(T_ref) t
  double collisions = 0;                 ///< collisions per particle since τ = 0
  double translational_temperature = 1;  ///< T_t/T_ref
  double rotational_temperature = 1;     ///< T_r/T_ref
  double cooling_rate = 0;               ///< ζ* = ζ_t/ν0(T_t) = ((d+2)/4) z_t (the table's `cooling_rate`)
  /// The cumulants a20, a02, a11 (docs/theory.md §19.6); 0 in the Maxwellian scheme.
  /// @{
  double a20 = 0, a02 = 0, a11 = 0;  ///< 0 in the Maxwellian scheme
  /// @}
  double b00 = 0;  ///< the orientation coefficient of b00 P (evolve_rough_oriented_cooling; else 0)
  /// C = ⟨(c·ŵ)²/(c²ŵ²)⟩ = 1/3 + b00/5 (theory.md (19.28)); 1/3 without the orientation term.
  double orientation_correlation = 1.0 / 3;
  /// evolve_rough_sonine_cooling: every a_pq and b_pq, in the order of the rates' indices (else empty).
  /// @{
  std::vector<double> cumulants, orientation_coefficients;
  /// @}
};

/// The samples at the requested times and CVODE's counters.
struct RoughEvolutionResult {
  /// One sample per requested time, in order.
  std::vector<RoughEvolutionSample> samples;
  /// CVODE's counters for the whole integration.
  EvolutionCounters counters;
};

/// Initial cumulants (a20, a02, a11) of the first-Sonine distribution (theory.md (19.9)).
using RoughCumulants = std::array<double, 3>;

/// Throws std::invalid_argument naming the field (a20, a02 or a11) and its allowed range unless the
/// cumulants are finite and realizable for dimension d (theory.md (19.24a): Var c² ≥ 0, Var ŵ² ≥ 0,
/// Cauchy–Schwarz for their covariance).
void check_rough_initial_cumulants(int dimension, const RoughCumulants& a);

/// Returns the trajectory from T_t(0) = translational0, T_r(0) = rotational0 (units T_ref, both
/// > 0) at the increasing positive `times`. linear = false: the Maxwellian two-temperature equations
/// (theory.md (19.12), (19.24)) from Maxwellians; true: the first-Sonine scheme carrying a20, a02, a11
/// (theory.md (19.25)) from `initial_cumulants` (checked by check_rough_initial_cumulants; nonzero
/// values need linear = true); CVODE gets at most `max_steps` (≥ 1) steps over the whole trajectory. Throws
/// std::invalid_argument naming the field on bad input, EvolutionFailure (an invalid_argument) if CVODE stops early
/// ("max_steps: …" when the budget runs out).
RoughEvolutionResult evolve_rough_cooling(const RoughCoolingRates& rates, bool linear, double translational0,
                                          double rotational0, const std::vector<double>& times, double rtol,
                                          double atol, const RoughCumulants& initial_cumulants = {},
                                          long max_steps = kEvolutionMaxSteps);

/// Returns the trajectory of the oriented first-Sonine scheme of spheres (theory.md §19.13, (19.25) with the
/// orientation balance): a20, a02, a11 and b00 (b00(0) = 0, the others from `initial_cumulants`), the balances of
/// `oriented` and the collision frequency of `rates` (the same α, β, κ, d = 3; std::invalid_argument otherwise).
/// Its stationary point is rough_sonine_cooling_state(3, α, β, κ, 1, linear, oriented). Otherwise as
/// evolve_rough_cooling with linear = true.
RoughEvolutionResult evolve_rough_oriented_cooling(const RoughCoolingRates& rates,
                                                   const RoughOrientedCoolingRates& oriented, double translational0,
                                                   double rotational0, const std::vector<double>& times, double rtol,
                                                   double atol, const RoughCumulants& initial_cumulants = {},
                                                   long max_steps = kEvolutionMaxSteps);

/// Default CVODE step budget of evolve_rough_sonine_cooling over a whole trajectory: 5× the ~2000 steps the healthy
/// runs of theory.md §19.24 take to τ = 10⁴; the N = 3 nonlinear stall from θ(0) = 0.01 uses 25732 by τ = 0.01.
inline constexpr long kRoughSonineMaxSteps = 10000;

/// Returns the trajectory of the scheme of `rates` (linear, or nonlinear with every product of the unknowns kept,
/// theory.md (19.110)–(19.112)) at their Sonine order N (theory.md §19.13, (19.25b)–(19.25c), §19.24):
/// every a_pq (p + q ≤ N + 1) and, with the oriented rates (3D), every b_pq (p + q ≤ N − 1), from a20, a02, a11 =
/// `initial_cumulants` and the others 0 (realizable, check_rough_initial_cumulants; at β = −1 a02 = a11 = 0: the spin
/// decouples). Its stationary point is rough_sonine_cooling_state(d, α, β, κ, N, the rates' scheme and ansatz); in
/// the linear scheme at N = 1 it is the trajectory of evolve_rough_cooling (isotropic) or
/// evolve_rough_oriented_cooling (oriented) from other engine tables. Otherwise as evolve_rough_cooling with linear =
/// true, except that CVODE gets at most `max_steps` steps over the whole trajectory (≥ 1; the healthy runs of
/// §19.24 need ~2000 to τ = 10⁴): past it EvolutionFailure "max_steps: …" names the scheme, order, the τ and the
/// largest cumulant where it stopped and what to do (lower order, linear scheme, warmer spin) — the stall of N = 3
/// from a cold spin (theory.md §19.24, "Where it stalls").
RoughEvolutionResult evolve_rough_sonine_cooling(const RoughSonineCoolingRates& rates, double translational0,
                                                 double rotational0, const std::vector<double>& times, double rtol,
                                                 double atol, const RoughCumulants& initial_cumulants = {},
                                                 long max_steps = kRoughSonineMaxSteps);

/// The linear scheme's collision averages as a function of τ = θ/κ, for a gas without exact engine tables (the
/// Walton gas, rough_walton_evolution.hpp).
struct RoughLinearProductions {
  std::function<RoughProductionTable(double tau)> table;  ///< R_X[ψ_t] at τ (RoughCoolingRates::production)
  double collision_a20 = 0;  ///< the collision frequency is 1 + collision_a20 · a20 times the Maxwellian one
  double kappa = 0;          ///< κ (τ = θ/κ)
};

/// Returns the first-Sonine trajectory (theory.md (19.24)–(19.25)) with the balances of rough_linear_balances
/// from `productions`; otherwise as evolve_rough_cooling with linear = true.
RoughEvolutionResult evolve_rough_linear_cooling(int dimension, const RoughLinearProductions& productions,
                                                 double translational0, double rotational0,
                                                 const std::vector<double>& times, double rtol, double atol,
                                                 const RoughCumulants& initial_cumulants = {},
                                                 long max_steps = kEvolutionMaxSteps);

/// Maxwellian rates at θ = T_r/T_t: (z_t, z_r) = (ζ_t, ζ_r)/(nσ^{d−1}v_t ν) (e.g. from the Walton
/// quadrature of rough_walton.hpp, times 4/(d+2)).
using RoughMaxwellianRates = std::function<std::array<double, 2>(double temperature_ratio)>;

/// Returns the Maxwellian trajectory (theory.md (19.24) with a = 0) for rates given as a function of
/// θ, d ∈ {2, 3}; otherwise as evolve_rough_cooling (a20 = a02 = a11 = 0 in every sample).
RoughEvolutionResult evolve_rough_maxwellian_cooling(int dimension, const RoughMaxwellianRates& rates,
                                                     double translational0, double rotational0,
                                                     const std::vector<double>& times, double rtol, double atol,
                                                     long max_steps = kEvolutionMaxSteps);

}  // namespace gkt
