// Time evolution of a freely cooling homogeneous granular gas with constant restitution: the
// temperature T(t)/T(0) and the cumulants a_2(t) … a_K(t), integrated with SUNDIALS CVODE
// (BDF, dense direct solver, analytic Jacobian from the cumulant hierarchy). docs/theory.md §12.
//
// Time τ is in units of the initial Maxwellian mean free time 1/ω_M(0), ω_M = n σ^{d−1} v0 ν
// (ν of theory.md (5.3)); `collisions` counts collisions per particle.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "gkt/transport/monodisperse/homogeneous_cooling_state.hpp"

namespace gkt {

/// One output time.
struct EvolutionSample {
  double time = 0;          ///< τ = ω_M(0) t
  double collisions = 0;    ///< collisions per particle since τ = 0
  double temperature = 1;   ///< T(τ)/T(0)
  std::vector<double> a;    ///< a_0 = 1, a_1 = 0, a_2 … a_K
  double cooling_rate = 0;  ///< ζ*(a(τ)) = ζ/ν0 at the current state
};

/// CVODE's integration counters.
struct EvolutionCounters {
  /// CVODE's counts: internal steps, right-hand-side evaluations, Jacobian evaluations, local error test failures and
  /// nonlinear solver iterations.
  /// @{
  long steps = 0, rhs_evaluations = 0, jacobian_evaluations = 0, error_test_failures = 0, nonlinear_iterations = 0;
  /// @}
};

/// CVODE stopped before a requested time: the times or tolerances asked for are beyond what it
/// resolves in double precision (an input error, hence std::invalid_argument). what() is one line
/// naming the parameter ("rtol: …" when rtol/atol ask for more accuracy than double precision
/// gives, CV_TOO_MUCH_ACC; "times: …" when a time cannot be reached, e.g. because the temperature
/// fell below what atol resolves) with CVODE's own message; CVODE itself prints nothing.
class EvolutionFailure : public std::invalid_argument {
 public:
  /// The failure with one-line `message`, CVODE's return code `flag` and the τ where it stopped.
  EvolutionFailure(const std::string& message, int flag, double time)
      : std::invalid_argument(message), flag_(flag), time_(time) {}
  /// Returns CVODE's return code (negative).
  [[nodiscard]] int flag() const { return flag_; }
  /// Returns τ where the integration stopped.
  [[nodiscard]] double time() const { return time_; }
  /// Returns true if the tolerances were the cause (too much accuracy requested).
  [[nodiscard]] bool tolerances() const;

 private:
  int flag_;
  double time_;
};

/// Default CVODE step budget over a whole `gkt evolve` trajectory of the smooth, viscoelastic, mixture, aggregation
/// and rough low-order schemes: 47× the 2126 steps the most demanding shipped scene, golden or CLI test takes
/// (cooling_viscoelastic.toml to τ = 10⁴; docs/conventions.md); before, 10⁶ steps per output time.
inline constexpr long kEvolutionMaxSteps = 100000;

/// The samples at the requested times and the counters.
struct EvolutionResult {
  /// One sample per requested time, in order.
  std::vector<EvolutionSample> samples;
  /// CVODE's counters for the whole integration.
  EvolutionCounters counters;
};

/// Returns the trajectory for viscoelastic spheres (d = 3): the hierarchy is evaluated at
/// δ'(θ) = δ 2^{1/10} θ^{1/10} (BP's δ' = δ[2T/T0]^{1/10}, δ at the initial temperature T0 = 1);
/// CVODE uses its difference-quotient Jacobian here. Otherwise as evolve_homogeneous_cooling.
EvolutionResult evolve_viscoelastic_cooling(const class ViscoelasticHierarchy& hierarchy, double delta,
                                            const std::vector<double>& initial_a, const std::vector<double>& times,
                                            double rtol, double atol, long max_steps = kEvolutionMaxSteps);

/// Returns the trajectory from T/T0 = temperature0 and cumulants initial_a (a_2 … a_K; missing
/// ones 0) at the increasing positive `times`, with CVODE tolerances rtol (relative) and atol
/// (absolute). `chi` ≥ 1 is the Enskog contact value of a dense gas: its homogeneous collision
/// operator is χ times Boltzmann's (theory.md (15.1)), so every rate and the reported ζ* = χ ζ*_dilute
/// carry χ while τ stays in units of the dilute initial mean free time (theory.md §12.4). CVODE gets at most
/// `max_steps` (≥ 1) steps over the whole trajectory. Throws std::invalid_argument on bad input, EvolutionFailure
/// (an invalid_argument) if CVODE stops early ("max_steps: …" when the budget runs out), std::runtime_error if CVODE
/// cannot even be set up.
EvolutionResult evolve_homogeneous_cooling(const CumulantHierarchy& hierarchy, double temperature0,
                                           const std::vector<double>& initial_a, const std::vector<double>& times,
                                           double rtol, double atol, double chi = 1,
                                           long max_steps = kEvolutionMaxSteps);

}  // namespace gkt
