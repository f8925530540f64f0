// Direct simulation Monte Carlo of the uniform shear flow (USF) of smooth inelastic disks (d = 2)
// or spheres (d = 3): the homogeneous DSMC of homogeneous_dsmc.hpp (same pair selection, majorant
// and collision rule) in the Lagrangian frame of the flow u = a y x̂, where the peculiar velocities
// stream as dV_x/dt = −a V_y between collisions (Lees–Edwards conditions in velocity space; the
// shear heating balances the collisional cooling in the steady state). docs/theory.md §22.5.
#pragma once

#include <vector>

#include "gkt/simulation/homogeneous_dsmc.hpp"

namespace gkt {

/// The sheared gas: constant restitution α and the shear rate a/ν0(T_initial) (ν0 = nT/η0,
/// docs/conventions.md); a fixed, so T relaxes to the steady temperature where a/ν0(T) takes its
/// steady value whatever the initial choice (only the relaxation time depends on it).
struct UniformShearDsmcParameters {
  double alpha = 1;       ///< in (0, 1)
  double shear_rate = 0;  ///< a/ν0(T_initial), in (0, 100]
  /// The Enskog gas (docs/theory.md §22.8): packing fraction φ in [0, 0.5] (3D), [0, 0.7] (2D) and
  /// the contact value χ(φ) ≥ 1 (φ = 0, χ = 1: the Boltzmann gas, the dilute scheme unchanged).
  /// @{
  double packing_fraction = 0, pair_correlation = 1;
  /// @}
};

/// One run: per batch (sampled at its end) the reduced shear rate γ = a ℓ/√(2T/m) (ℓ = 1/(2nσ)
/// in 2D, 1/(πnσ²) in 3D), the stresses P_ij/(2nT) (stress_zz zero in 2D; kinetic plus, for the
/// Enskog gas, collisional) and T/T_initial; the collisional parts alone (zero for φ = 0).
struct UniformShearDsmcRun {
  /// Per batch: γ = a ℓ/√(2T/m), the stresses P_ij/(2nT) (stress_zz zero in 2D) and T/T_initial.
  /// @{
  std::vector<double> reduced_shear_rate, stress_xx, stress_yy, stress_zz, stress_xy, temperature;
  /// @}
  /// Per batch: the collisional transfer P^c_ij/(2nT) over the batch (included in stress_ij).
  /// @{
  std::vector<double> collisional_xx, collisional_yy, collisional_zz, collisional_xy;
  /// @}
};

/// Runs the USF DSMC (`schedule.histogram_bins` is ignored); throws std::invalid_argument naming
/// the field on a bad dimension, α, shear rate, packing fraction, contact value or schedule.
UniformShearDsmcRun run_uniform_shear_dsmc(int d, const UniformShearDsmcParameters& parameters,
                                           const DsmcSchedule& schedule);

}  // namespace gkt
