// What `gkt evolve` asks a model for: the free cooling of a homogeneous gas, T(τ), the cumulants
// a_k(τ), ζ*(τ), and transport coefficients along the trajectory (docs/theory.md §12).
#pragma once

#include <string>
#include <vector>

#include "gkt/evolution/homogeneous_cooling_evolution.hpp"
#include "gkt/models/parameter_spec.hpp"

namespace gkt {

/// One trajectory to integrate: the model's evolution parameters (TransportModel::
/// evolution_parameters()), the output times and the coefficients wanted along the way. A model
/// whose evolution parameters declare `t_end` sets its own output times: `times` stays empty.
struct TrajectoryRequest {
  /// The model's evolution parameters (TransportModel::evolution_parameters()).
  ParameterPoint parameters;
  std::vector<double> times;              ///< increasing, > 0 (τ = ω_M(0) t); empty if the model sets them
  std::vector<std::string> coefficients;  ///< from TransportModel::trajectory_coefficients()
};

/// The integrated trajectory: one row per output time, in the named columns `time`, `collisions`,
/// `temperature`, `a2` … `aK`, `cooling_rate`, then the requested coefficients (the aggregation
/// model: its own columns, docs/conventions.md).
struct Trajectory {
  /// Column names, in order.
  std::vector<std::string> columns;
  /// One row per output time, one value per column.
  std::vector<std::vector<double>> rows;
  EvolutionCounters counters;  ///< CVODE's work
  /// The linear solver CVODE used, if the model chooses one (e.g. "dense", "spgmr"); empty
  /// otherwise. When set, CVODE counts no Jacobian evaluations of ours.
  std::string linear_solver;
};

/// Returns true if `evolution_parameters` declare `t_end`: the model sets its own output times.
bool sets_own_output_times(const std::vector<ParameterSpec>& evolution_parameters);

/// Returns the specs of the output times of a trajectory given as a range: `t_end`, a number > 0,
/// and `points`, an integer in [1, 1000000] (the alternative is an explicit list of times).
std::vector<ParameterSpec> output_time_parameters();

/// Returns τ log-spaced from the first collisions (τ = 0.01, or t_end/100 if earlier) to t_end
/// (`points` ≥ 1 values; t_end alone for one point).
std::vector<double> log_spaced_times(double t_end, int points);

}  // namespace gkt
