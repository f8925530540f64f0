// The shear viscosity of the dilute inelastic hard-sphere (d = 3) or hard-disk (d = 2) gas
// measured by DSMC, with no Sonine input: the homogeneous DSMC of homogeneous_dsmc.hpp in its
// scaled homogeneous cooling state (HCS), kicked by a small uniform strain and left to relax.
//
// The response formula (docs/theory.md §21.6, derived there from the Chapman–Enskog equation
// (10.3)): a pure strain V_x += (ε/2)V_y, V_y += (ε/2)V_x changes the HCS distribution φ by
// δφ = −ε c_y ∂φ/∂c_x, exactly the source of (10.3) times −ε, whatever φ is and whatever the
// N-particle velocity correlations are. The scaled shear stress M(τ) = ⟨c_x c_y⟩ (c = v/√(2T/m)
// at the current T) then relaxes with the linearized scaled Boltzmann operator, and
//
//     η* = (2/ε) ∫_0^∞ M(τ) √(T(τ)/T(0)) dτ,    √(T(τ)/T(0)) → e^{−ζ*τ/2},
//
// τ = ∫ν0 dt the clock in units of ν0 = nT/η0 (docs/conventions.md). The weight is the gas's own
// measured temperature ratio, so ζ* is not an input either; at α = 1 it is 1 and the formula is the
// elastic relaxation (Green–Kubo) form η* = 2∫M dτ/ε.
#pragma once

#include <vector>

#include "gkt/simulation/homogeneous_dsmc.hpp"

namespace gkt {

/// The kicked HCS: constant restitution α and the strain amplitude ε of each kick.
struct ShearViscosityDsmcParameters {
  double alpha = 1;    ///< constant normal restitution in (0, 1]
  double kick = 0.25;  ///< ε in (0, 0.5]: the bias is O(ε²) (docs/theory.md §21.6)
};

/// One run: one η* per kick (each from one window of `schedule.per_batch` collisions per particle
/// after the kick; the window truncates the integral, relative error ~e^{−τ_window/η*}, τ_window the
/// window in units 1/ν0: docs/theory.md §21.6)
/// and the cooling rate ζ* measured over the same window (kicked gas, so O(ε²) off the HCS value).
struct ShearViscosityDsmcRun {
  /// Per kick: the estimate of η* = η/η0 and of ζ* = ζ/ν0 over its window.
  /// @{
  std::vector<double> shear_viscosity, cooling_rate;
  /// @}
};

/// Returns the run of `schedule.batches` kicks, each followed by `schedule.per_batch` collisions per
/// particle, after `schedule.relaxation` collisions per particle from Maxwellians (histogram fields
/// ignored); the sign of each kick is drawn at random so that the O(ε²) response and the remains
/// of the previous kick average out. Throws std::invalid_argument naming the field on bad input.
ShearViscosityDsmcRun run_shear_viscosity_dsmc(int d, const ShearViscosityDsmcParameters& parameters,
                                               const DsmcSchedule& schedule);

}  // namespace gkt
