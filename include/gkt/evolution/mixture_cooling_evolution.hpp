// Free cooling of a homogeneous granular mixture: the partial temperatures T_i(t)/T and the species
// cumulants a_k,i(t) relaxing from a given start (equipartition, Maxwellians by default) to the
// mixture's homogeneous cooling state, then Haff's law; SUNDIALS CVODE (BDF, dense direct solver,
// difference-quotient Jacobian). docs/theory.md §16.7.
//
// Time τ = ν0(0) t, ν0 = nT/η0 with T the initial mixture temperature and η0 the elastic viscosity of
// the reference gas (m̄, σ̄) of docs/conventions.md "Mixtures" (the reduction of ζ*).
#pragma once

#include <span>
#include <vector>

#include "gkt/evolution/homogeneous_cooling_evolution.hpp"
#include "gkt/transport/mixture/mixture.hpp"
#include "gkt/transport/mixture/mixture_cooling_state.hpp"

namespace gkt {

/// One output time of a mixture's free cooling.
struct MixtureEvolutionSample {
  double time = 0;                             ///< τ = ν0(0) t
  double temperature = 1;                      ///< T(τ)/T(0), T = Σ_i x_i T_i
  std::vector<double> temperature_ratio;       ///< γ_i = T_i/T
  std::vector<std::vector<double>> cumulants;  ///< a_k,i at [i][k], k = 0 … K (a_0 = 1, a_1 = 0; all 0 if Maxwellian)
  double cooling_rate = 0;                     ///< ζ* = Σ_i x_i γ_i ζ_i* at the current state (ν0(T))
};

/// The samples at the requested times and CVODE's counters.
struct MixtureEvolutionResult {
  /// One sample per requested time, in order.
  std::vector<MixtureEvolutionSample> samples;
  /// CVODE's counters for the whole integration.
  EvolutionCounters counters;
};

/// Returns the trajectory of `mixture` (validated) in the HCS scheme `scheme` carrying a_2 … a_K
/// (K = hcs_order ∈ [2, 6]; none for the Maxwellian scheme) from the temperature ratios
/// `initial_temperature_ratio` (T_i(0)/T(0), Σ x_i γ_i = 1 within 1e-12) and cumulants
/// `initial_cumulants` (a_2,i … a_K,i per species; empty: all 0) at the increasing positive `times`,
/// with CVODE tolerances rtol, atol and at most `max_steps` (≥ 1) CVODE steps over the whole trajectory. The rest
/// point is mixture_cooling_state(mixture, scheme, K). Throws std::invalid_argument naming the field on bad input,
/// EvolutionFailure if CVODE stops early ("max_steps: …" when the budget runs out).
MixtureEvolutionResult evolve_mixture_cooling(const Mixture& mixture, MixtureHcsScheme scheme, int hcs_order,
                                              std::span<const double> initial_temperature_ratio,
                                              const std::vector<std::vector<double>>& initial_cumulants,
                                              const std::vector<double>& times, double rtol, double atol,
                                              long max_steps = kEvolutionMaxSteps);

}  // namespace gkt
