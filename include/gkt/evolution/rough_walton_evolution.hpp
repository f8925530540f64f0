// Free cooling of the Walton gas (rough spheres or disks with Coulomb friction, rough_walton.hpp) in the
// linear first-Sonine scheme: T_t(τ), T_r(τ), a20, a02, a11 (docs/theory.md §19.19). The collision averages
// of rough_walton_cumulants.hpp cost a two-dimensional quadrature each, so they are tabulated once on a
// Chebyshev grid in ln τ over the range the trajectory can visit and interpolated at every right-hand side
// of CVODE (rough_cooling_evolution.hpp, evolve_rough_linear_cooling).
#pragma once

#include <vector>

#include "gkt/evolution/rough_cooling_evolution.hpp"
#include "gkt/transport/rough/rough_walton_cumulants.hpp"

namespace gkt {

/// The Walton linear-scheme averages interpolated in ln τ (Chebyshev, `nodes` nodes on [ln τ_lo, ln τ_hi]).
class RoughWaltonInterpolant {
 public:
  /// Tabulates rough_walton_productions at the Chebyshev nodes of [tau_lo, tau_hi] (0 < tau_lo < tau_hi);
  /// ranges as rough_walton_productions, nodes ≥ 4. Cost: `nodes` quadratures.
  RoughWaltonInterpolant(int dimension, double alpha, double beta0, double kappa, double friction, double tau_lo,
                         double tau_hi, int nodes);
  /// Returns the interpolated averages at τ in [tau_lo, tau_hi]; NaN outside (the caller's integrator then
  /// retries with a smaller step, and fails with a message if the trajectory leaves the range).
  [[nodiscard]] RoughProductionTable operator()(double tau) const;
  /// Returns 2⟨S_2(x1)⟩ over collisions (independent of τ).
  [[nodiscard]] double collision_a20() const { return collision_a20_; }
  /// Returns the largest difference between the interpolant and a direct quadrature at the midpoints between
  /// the first `samples` pairs of neighbouring nodes, relative to 1 + |value| (the interpolation check).
  [[nodiscard]] double check(int samples) const;

 private:
  int dimension_;
  double alpha_, beta0_, kappa_, friction_, lo_, hi_;
  std::vector<RoughProductionTable> coefficients_;  // Chebyshev coefficients per table entry
  double collision_a20_ = 0;
};

/// Returns the first-Sonine trajectory of the Walton gas from T_t(0) = translational0, T_r(0) = rotational0
/// (units T_ref) with initial cumulants `initial_cumulants` (theory.md (19.24)–(19.25) with the averages of
/// rough_walton_cumulants.hpp, interpolated over τ between 0.5 below the smaller and 0.5 above the larger of
/// ln τ(0) and the linear HCS's ln τ, 16 nodes per unit of ln τ, at least 24). Throws std::invalid_argument
/// naming the field where the linear scheme has no HCS (spin decoupled or no realizable root) or on bad input;
/// otherwise as evolve_rough_linear_cooling (at most `max_steps` CVODE steps over the whole trajectory).
RoughEvolutionResult evolve_rough_walton_cooling(int dimension, double alpha, double beta0, double kappa,
                                                 double friction, double translational0, double rotational0,
                                                 const std::vector<double>& times, double rtol, double atol,
                                                 const RoughCumulants& initial_cumulants = {},
                                                 long max_steps = kEvolutionMaxSteps);

}  // namespace gkt
