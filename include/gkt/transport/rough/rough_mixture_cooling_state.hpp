// The homogeneous cooling state of a binary mixture of rough inelastic hard spheres (d = 3) or
// disks (d = 2) in the Maxwellian approximation (docs/theory.md §19.17): four temperatures
// T_t,1, T_t,2, T_r,1, T_r,2 cooling at one rate. The energy change of every degree of freedom per
// i–j collision is linear in the four temperatures with exact coefficients from the two-species
// rough engine (rough_mixture_collision_moments.hpp); the collision rate carries the factor
// √(T_t,i/m_i + T_t,j/m_j). Reduction as for the smooth mixture (theory.md (16.4)):
// ν0 = nT/η0(T) of a one-component gas of mass m̄ = Σx_i m_i and diameter σ̄ = Σx_i σ_i at the
// mixture's translational temperature T = Σx_i T_t,i.
#pragma once

#include <array>

#include "gkt/algebra/rational.hpp"

namespace gkt {

/// One component of a rough binary mixture.
struct RoughMixtureComponent {
  Rational mass{1};       ///< m_i (> 0; only ratios enter)
  Rational kappa{2, 5};   ///< κ_i = 4I_i/(m_iσ_i²) in (0, 1]
  double diameter = 1;    ///< σ_i (> 0; only ratios enter)
  double fraction = 0.5;  ///< mole fraction x_i in [0, 1], x_1 + x_2 = 1
};

/// A rough binary mixture: pair restitutions at index 0 (1–1), 1 (1–2 = 2–1), 2 (2–2).
struct RoughBinaryMixture {
  int dimension = 3;                                                       ///< d (2 or 3)
  std::array<RoughMixtureComponent, 2> species;                            ///< the two components
  std::array<Rational, 3> alpha{Rational(1), Rational(1), Rational(1)};    ///< α_11, α_12, α_22 in (0, 1]
  std::array<Rational, 3> beta{Rational(-1), Rational(-1), Rational(-1)};  ///< β_11, β_12, β_22 in [−1, 1]
  /// Throws std::invalid_argument naming the field and its range on bad input.
  void validate() const;
};

/// Exact energy changes per i–j collision (normalised by the collision rate, Maxwellians at the four
/// temperatures): row r of `coefficient` gives ⟨ΔE_r⟩ = Σ_c coefficient[r][c] T_c for
/// r, c over (translational i, translational j, rotational i, rotational j); ΔE_t = Δ(m v²/2),
/// ΔE_r = Δ(κ m w²/2) of the particle of that species (theory.md (19.54)).
struct RoughPairEnergyChanges {
  std::array<std::array<Rational, 4>, 4> coefficient{};  ///< [row][column] as above
};

/// Returns the energy-change coefficients of an i–j collision from the two-species engine (the
/// values at five temperature sets); throws std::invalid_argument as rough_mixture_parameters does.
RoughPairEnergyChanges rough_pair_energy_changes(int dimension, const Rational& alpha, const Rational& beta,
                                                 const RoughMixtureComponent& species_i,
                                                 const RoughMixtureComponent& species_j);

/// Returns ζ* = −(d ln T_k/dt)/ν0(T) for k = (translational 1, translational 2, rotational 1,
/// rotational 2) at the temperatures T_k (any unit; T = Σx_i T_t,i sets ν0) in the Maxwellian
/// approximation (theory.md (19.55)). Throws std::invalid_argument on bad input or T_k ≤ 0.
std::array<double, 4> rough_mixture_cooling_rates(const RoughBinaryMixture& mixture,
                                                  const std::array<double, 4>& temperatures);

/// The Maxwellian HCS of a rough binary mixture.
struct RoughMixtureCoolingState {
  std::array<double, 2> temperature_ratio{};  ///< γ_i = T_t,i/T, T = Σx_i T_t,i (Σ x_i γ_i = 1)
  std::array<double, 2> rotational_ratio{};   ///< θ_i = T_r,i/T_t,i (+∞ for a decoupled spin)
  double cooling_rate = 0;                    ///< the common ζ* = ζ/ν0(T)
};

/// Returns the Maxwellian HCS: the positive eigenvector of the linear cooling dynamics at fixed
/// T_t,2/T_t,1, made consistent with that ratio by bisection (theory.md §19.17). A species whose spin
/// is decoupled (β = −1 on every pair it meets with non-zero weight x_j) keeps its T_r: θ_i = +∞, and
/// γ_i, ζ* are the translational ones (theory.md (19.130)). Throws std::invalid_argument on bad input.
RoughMixtureCoolingState rough_mixture_cooling_state(const RoughBinaryMixture& mixture);

}  // namespace gkt
