// Direct simulation Monte Carlo of the granular column in gravity (docs/theory.md §23.3): smooth
// inelastic disks (d = 2) or spheres (d = 3) at constant α, gravity g along −z, a thermal floor at
// z = 0 (diffuse re-emission at the wall temperature) and a specular (elastic) lid at z = H; NTC
// pair selection in cells of equal height, the collision rule of the homogeneous DSMC. The referee
// of the hydrodynamic column (gravity_column.hpp): it reports the energy the floor gives the gas,
// the flux condition under which the two are compared. Units m = σ = g = 1, T in mgσ.
#pragma once

#include <cstdint>
#include <vector>

namespace gkt {

/// One column: α in (0, 1], N = ∫ n dz (σ^{1−d}), wall temperature (mgσ), lid height (σ), and the
/// simulation's particles, cell height, time step and times (in √(σ/g)).
struct GravityColumnDsmcParameters {
  /// Spatial dimension d: 2 (disks) or 3 (spheres).
  int dimension = 3;
  /// Normal restitution α, in (0, 1].
  double alpha = 1;
  /// N = ∫ n dz, particles per unit area (σ^{1−d}).
  double particles_per_area = 5;
  /// Wall temperature of the thermal floor (mgσ).
  double floor_temperature = 50;
  /// Height H of the specular lid (σ).
  double lid_height = 150;
  /// Number of simulated particles (at least 100).
  int particles = 20000;
  /// Height of a collision cell (σ).
  double cell_height = 1;
  /// Time step (√(σ/g)).
  double time_step = 0.02;
  double settle_time = 300;  ///< run before sampling starts
  double sample_time = 600;  ///< sampled (every 5th step)
  /// Seed of the run's random stream.
  std::uint64_t seed = 1;
};

/// The sampled column: cell centres z, n σ^d, T = m⟨V²⟩/d, T_z = m⟨V_z²⟩ (mgσ), the upward energy
/// flux q (m g^{3/2} σ^{5/2−d}) and its two parts, the collisional dissipation per unit volume, and
/// the energy per unit time and area the floor gave the gas; T and T_z are NaN in a cell no sampled
/// particle was ever in.
struct GravityColumnDsmcProfile {
  /// Per cell: centre z (σ), n σ^d, T = m⟨V²⟩/d and T_z = m⟨V_z²⟩ (mgσ), upward energy flux
  /// q = kinetic + collisional (m g^{3/2} σ^{5/2−d}); all averaged over the cell.
  /// @{
  std::vector<double> z, number_density, temperature, vertical_temperature, heat_flux;
  /// @}
  /// Per cell: the kinetic flux n⟨(m/2)V²V_z⟩ (the flight of particles across a plane), and the
  /// collisional cell transfer Σ ½(δE_j − δE_i)(z_j − z_i)/(Δz t A): the energy NTC collisions move
  /// between partners at different heights of one cell (docs/theory.md §23.3, [alexander1998cell]),
  /// both m g^{3/2} σ^{5/2−d}.
  /// @{
  std::vector<double> kinetic_heat_flux, collisional_heat_flux;
  /// @}
  /// Per cell: energy lost in collisions per unit time and volume (m g^{3/2} σ^{3/2−d}).
  std::vector<double> dissipation;
  /// Energy per unit time and area the floor gave the gas (m g^{3/2} σ^{5/2−d}).
  double floor_heat_flux = 0;
};

/// Runs the column DSMC; throws std::invalid_argument naming the field on a bad dimension, α,
/// N, wall temperature, lid height, particle number (< 100), cell height (not dividing into at
/// least 2 cells), time step or times.
GravityColumnDsmcProfile run_gravity_column_dsmc(const GravityColumnDsmcParameters& parameters);

}  // namespace gkt
