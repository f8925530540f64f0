#pragma once
// The collision success factor ψ of sticking grains and the energy a collision loses, averaged over
// colliding pairs (collision-rate weighted). docs/theory.md §20 (derivations; the errata of
// liu2011aggregation eqs. 44–49).

namespace gkt {

/// When a colliding pair sticks (docs/theory.md §20.1).
enum class StickingCriterion {
  relative_speed,  ///< μ g²/2 < θ* (liu2011aggregation, assumption 4 and eq. 47)
  normal_impact,   ///< μ (ĝ·σ̂)² g²/2 < θ*: only the normal part of the impact decides
  always,          ///< every collision sticks (ψ = 1; ballistic aggregation)
};

/// Per-collision averages over the colliding pairs of one pair of species (docs/theory.md (20.3)–(20.6)).
struct PairCollisionAverages {
  double success_factor = 0;   ///< ψ: fraction of the collisions that stick
  double sticking_energy = 0;  ///< ⟨μ g²/2; stick⟩ / T_ij: relative kinetic energy lost by sticking, per collision
  double normal_energy = 0;  ///< ⟨μ g_n²/2; bounce⟩ / T_ij: normal relative energy of the rebounding collisions;
                             ///< a rebound with restitution α loses (1 − α²) times it
  double rate_factor = 1;    ///< collision rate over its Maxwellian value (3D: 1 − a2/16 − 15a2²/1024)
};

/// Returns ψ and the energy averages of pairs at reduced critical energy x = θ*_ij/T_ij ≥ 0 in
/// dimension 2 or 3. a2 (default 0: Maxwellian) is the HCS kurtosis cumulant of both partners, valid
/// for a pair of equal masses in a one-component gas, kept exactly to order a2² (theory.md (20.7));
/// a2 ∈ [−8/(d(d+2)), 4/(d+2)] (a positive distribution). Throws std::invalid_argument otherwise.
PairCollisionAverages pair_collision_averages(int dimension, StickingCriterion criterion, double x, double a2 = 0);

/// Returns ψ alone (see pair_collision_averages): 3D relative speed and a2 = 0 give 1 − (1 + x)e^{−x}.
double success_factor(int dimension, StickingCriterion criterion, double x, double a2 = 0);

/// Returns the pair temperature T_ij = μ_ij (T_i/m_i + T_j/m_j) (an energy): the relative velocity of
/// partners at temperatures T_i, T_j is Gaussian with variance T_ij/μ_ij per component; x = θ*_ij/T_ij.
double pair_temperature(double mass_i, double temperature_i, double mass_j, double temperature_j);

}  // namespace gkt
