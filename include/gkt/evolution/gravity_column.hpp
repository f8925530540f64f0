// The steady heat-conducting granular gas in gravity (seed 001 §3.3.2, eq. (17); docs/theory.md
// §23): a dilute gas of smooth inelastic hard disks (d = 2) or spheres (d = 3), at rest, with
// gravity g along −z, heated from a floor at z = 0 and closed by an elastic lid at z = H.
// Navier–Stokes hydrodynamics with the engine's κ*, μ*, ζ* (given by the caller).
//
// Reduced units (docs/conventions.md "gravity-column"): m = σ = g = 1, temperature in units of
// mgσ, so z in σ, n in σ^{−d}, T in mgσ, q in m g^{3/2} σ^{5/2−d}. In the pressure coordinate
// x = p = nT the problem is linear in s = √T (theory.md (23.5)); it is solved by second-order
// finite differences in u = ln x on nodes that equidistribute the floor's boundary layer and the
// dilute top (theory.md §23.2), and the lid pressure by GSL's Brent root finder.
#pragma once

#include <vector>

namespace gkt {

/// The reduced Navier–Stokes coefficients the column needs (docs/conventions.md): κ* = κ/κ0,
/// μ* = nμ/(Tκ0), ζ* = ζ/ν0 at one α (dilute).
struct ColumnTransport {
  double thermal_conductivity = 1;      ///< κ*
  double density_heat_coefficient = 0;  ///< μ*
  double cooling_rate = 0;              ///< ζ*
};

/// What the vibrating floor fixes at z = 0.
enum class FloorCondition { temperature, heat_flux };

/// One column: dimension, transport, N = ∫ n dz (in σ^{1−d}), floor condition and value (T(0) in
/// mgσ or q(0) in m g^{3/2} σ^{5/2−d}), lid height H (in σ) and the number of grid intervals.
struct GravityColumnProblem {
  /// Spatial dimension d: 2 or 3.
  int dimension = 3;
  /// The reduced transport coefficients κ*, μ*, ζ* at the column's α.
  ColumnTransport transport;
  /// N = ∫ n dz, particles per unit area (σ^{1−d}).
  double particles_per_area = 1;
  /// Whether the floor fixes T(0) or q(0).
  FloorCondition floor = FloorCondition::temperature;
  /// T(0) in mgσ or q(0) in m g^{3/2} σ^{5/2−d}, as `floor` says; finite and > 0.
  double floor_value = 1;
  /// Height H of the lid (σ); finite and > 0.
  double lid_height = 10;
  /// Number of grid intervals, at least 16.
  int intervals = 4000;
};

/// The solved column on its grid, floor (index 0) to lid (last index), reduced as the problem.
struct GravityColumnProfile {
  /// Per grid point: height z (σ), n σ^d, T (mgσ), upward heat flux q (m g^{3/2} σ^{5/2−d}) and the local Knudsen
  /// number ℓ max(|∂_z ln T|, |∂_z ln n|) (ℓ the dilute mean free path).
  /// @{
  std::vector<double> z, number_density, temperature, heat_flux, knudsen_number;
  /// @}
  double lid_pressure = 0;     ///< p(H), the lid's push per area (m g σ^{1−d})
  double floor_heat_flux = 0;  ///< q(0)
  double dissipation = 0;      ///< ∫ (d/2) ζ n T dz (trapezoid on the grid; equals q(0) − q(H))
  double particles = 0;        ///< ∫ n dz (trapezoid on the grid; equals N up to the grid error)
  double knudsen_height = -1;  ///< lowest z with knudsen_number > 0.1; −1 if none below the lid
};

/// Returns the steady column of `problem` (theory.md (23.1)–(23.7)). Throws
/// std::invalid_argument naming the field for d ∉ {2, 3}, N, floor_value or H not finite and > 0,
/// intervals < 16, κ* ≤ μ* or ζ* < 0, or a heat-flux floor with ζ* = 0 (an elastic column
/// conducts no heat), a height H no lid pressure in [e^−690 N, e^600 N] gives, or coefficients with
/// no column of positive temperature (α far from 1: name `alpha`).
GravityColumnProfile solve_gravity_column(const GravityColumnProblem& problem);

/// n, T, q and the local Knudsen number at one height.
struct GravityColumnPoint {
  /// n σ^d, T (mgσ), q (m g^{3/2} σ^{5/2−d}) and the local Knudsen number at the height asked for.
  /// @{
  double number_density = 0, temperature = 0, heat_flux = 0, knudsen_number = 0;
  /// @}
};

/// Returns the profile at height z (between grid heights: n, T linear in their logarithm, q and the
/// Knudsen number linear). Throws
/// std::invalid_argument naming `height` unless 0 ≤ z ≤ H.
GravityColumnPoint column_at(const GravityColumnProfile& profile, double z);

}  // namespace gkt
