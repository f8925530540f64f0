// Free cooling of a homogeneous binary mixture of rough spheres (d = 3) or disks (d = 2) in the Maxwellian
// approximation: the four temperatures T_t,1, T_t,2, T_r,1, T_r,2 relaxing from any start to the Maxwellian HCS
// of rough_mixture_cooling_state.hpp, then Haff's law (docs/theory.md §19.31); SUNDIALS CVODE (BDF, dense,
// difference-quotient Jacobian).
//
// Time τ = ν0(T_ref) t, ν0 = nT/η0(T) of the mixture's reference gas (m̄ = Σx_i m_i, σ̄ = Σx_i σ_i; the reduction of
// its ζ*, theory.md (16.4), (19.55)) at the temperature T_ref in which the temperatures are given.
#pragma once

#include <array>
#include <vector>

#include "gkt/evolution/homogeneous_cooling_evolution.hpp"
#include "gkt/transport/rough/rough_mixture_cooling_state.hpp"

namespace gkt {

/// One output time of a rough binary mixture's free cooling.
struct RoughMixtureEvolutionSample {
  double time = 0;                                    ///< τ = ν0(T_ref) t
  std::array<double, 2> translational_temperature{};  ///< T_t,i/T_ref
  std::array<double, 2> rotational_temperature{};     ///< T_r,i/T_ref
  double temperature = 1;                             ///< T/T_ref, T = Σ x_i T_t,i
  /// ζ* = −(d ln T/dt)/ν0(T) = Σ x_i γ_i ζ*_t,i at the current temperatures (the HCS's common ζ* at rest).
  double cooling_rate = 0;
};

/// The samples at the requested times and CVODE's counters.
struct RoughMixtureEvolutionResult {
  /// One sample per requested time, in order.
  std::vector<RoughMixtureEvolutionSample> samples;
  /// CVODE's counters for the whole integration.
  EvolutionCounters counters;
};

/// Default CVODE step budget of evolve_rough_mixture_cooling over a whole trajectory: the runs of theory.md §19.31 take
/// 550 (rtol = 1e-8) to 1150 (rtol = 1e-10) steps to τ = 10⁴, 7200 for its slow 2D state to τ = 10³⁰ (the one gas's
/// Sonine schemes have the same default).
inline constexpr long kRoughMixtureMaxSteps = 10000;

/// Returns the Maxwellian trajectory of `mixture` (validated) from the temperatures `initial` = (T_t,1, T_t,2, T_r,1,
/// T_r,2)(0)/T_ref (finite, > 0) at the increasing positive `times` (theory.md (19.180)–(19.182)), CVODE tolerances
/// rtol, atol on (ln T_t,1, ln T_t,2, ln T_r,1, ln T_r,2), at most `max_steps` (≥ 1) CVODE steps over the whole
/// trajectory. Its rest point (ratios) is rough_mixture_cooling_state(mixture); a decoupled spin (theory.md (19.130))
/// keeps its T_r exactly. Throws std::invalid_argument naming the field on bad input, EvolutionFailure
/// ("max_steps: …", "times: …", "rtol: …") if CVODE stops early.
RoughMixtureEvolutionResult evolve_rough_mixture_cooling(const RoughBinaryMixture& mixture,
                                                         const std::array<double, 4>& initial,
                                                         const std::vector<double>& times, double rtol, double atol,
                                                         long max_steps = kRoughMixtureMaxSteps);

}  // namespace gkt
