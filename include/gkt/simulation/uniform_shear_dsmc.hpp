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
};

/// One run: per batch (sampled at its end) the reduced shear rate γ = a ℓ/√(2T/m) (ℓ = 1/(2nσ)
/// in 2D, 1/(πnσ²) in 3D), the stresses P_ij/(2nT) (stress_zz zero in 2D) and T/T_initial.
struct UniformShearDsmcRun {
  /// Per batch: γ = a ℓ/√(2T/m), the stresses P_ij/(2nT) (stress_zz zero in 2D) and T/T_initial.
  /// @{
  std::vector<double> reduced_shear_rate, stress_xx, stress_yy, stress_zz, stress_xy, temperature;
  /// @}
};

/// Runs the USF DSMC (`schedule.histogram_bins` is ignored); throws std::invalid_argument naming
/// the field on a bad dimension, α, shear rate or schedule.
UniformShearDsmcRun run_uniform_shear_dsmc(int d, const UniformShearDsmcParameters& parameters,
                                           const DsmcSchedule& schedule);

}  // namespace gkt
