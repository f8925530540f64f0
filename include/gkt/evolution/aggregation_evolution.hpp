#pragma once
// The population balance of sticking grains (sizes k = 1 … K in monomer units) coupled to the
// granular temperature, integrated with CVODE (BDF). docs/theory.md §20.3; reduced units of
// gkt/transport/aggregation/aggregation_kernel.hpp (n_1(0) = 1, θ0 = 1, time in t_0).

#include <string>
#include <vector>

#include "gkt/evolution/homogeneous_cooling_evolution.hpp"
#include "gkt/transport/aggregation/aggregation_kernel.hpp"

namespace gkt {

/// One output time of evolve_aggregation.
struct AggregationSample {
  double time = 0;                   ///< t/t_0
  double temperature = 1;            ///< θ/θ0
  double number_density = 1;         ///< M0/M0(0), M0 = Σ n_k
  double mass = 1;                   ///< M1/M1(0), M1 = Σ k n_k (1 up to rounding: exact conservation)
  double mean_size = 1;              ///< M1/M0 in monomers
  double success_factor = 0;         ///< collision-averaged ψ: sticking events per collision, all pairs
  std::vector<double> distribution;  ///< n_k/n_1(0), k = 1 … K (only when asked for)
};

/// The trajectory and what CVODE did; linear_solver is "dense" (K ≤ 64) or "spgmr" (Krylov).
struct AggregationResult {
  /// One sample per requested time, in order.
  std::vector<AggregationSample> samples;
  /// CVODE's counters for the whole integration.
  EvolutionCounters counters;
  /// The linear solver CVODE used: "dense" (K ≤ 64) or "spgmr" (Krylov).
  std::string linear_solver;
};

/// Returns n_k(t) and θ(t) from monomers at θ0 = 1 at the given increasing times > 0, sizes K ≥ 2;
/// mergers into sizes > K do not happen (those pairs rebound), so Σ k n_k is conserved exactly.
/// CVODE gets at most `max_steps` (≥ 1) steps over the whole trajectory. Throws std::invalid_argument for bad input
/// (one line naming the field) and EvolutionFailure when CVODE cannot reach a time ("max_steps: …" when the budget
/// runs out).
AggregationResult evolve_aggregation(const AggregationGas& gas, int sizes, const std::vector<double>& times,
                                     double rtol, double atol, bool keep_distribution,
                                     long max_steps = kEvolutionMaxSteps);

/// Returns the pivots of a geometric sectional grid: x_1 = 1, x_{k+1} = max(x_k + 1, r x_k), up to
/// the first pivot ≥ largest (ratio r ∈ (1, 2], largest ≥ 2); sizes below 1/(r − 1) stay integers.
std::vector<double> geometric_pivots(double ratio, double largest);

/// As above on a sectional grid (fixed pivot, theory.md (20.15)): n_k counts clusters represented
/// by pivot x_k (increasing, x_1 = 1, pivots 1 … K give the discrete balance); a merger of mass
/// x_i + x_j between two pivots is shared between them so that number and mass are both conserved,
/// one beyond the last pivot rebounds. distribution holds n_k per pivot.
AggregationResult evolve_aggregation(const AggregationGas& gas, const std::vector<double>& pivots,
                                     const std::vector<double>& times, double rtol, double atol, bool keep_distribution,
                                     long max_steps = kEvolutionMaxSteps);

}  // namespace gkt
