#pragma once
// Aggregation kernels β_ij and the granular energy lost per unit time by collisions of sizes i, j
// (monomer units: mass ∝ i, diameter ∝ i^{1/d}). docs/theory.md §20.2; reduced units: monomer mass
// m_1 = 1, monomer diameter σ_1 = 1, initial temperature θ0 = 1, initial monomer density n_1(0) = 1,
// so time is in units of t_0 = 1/(n_1(0) σ_1^{d−1} √(θ0/m_1)).

#include "gkt/transport/aggregation/success_factor.hpp"

namespace gkt {

/// Which aggregation kernel β_ij drives the size distribution.
enum class AggregationKernel {
  kinetic,   ///< β_ij = R_ij(θ) ψ_ij(θ*_ij/θ): collision rate times success factor (theory.md (20.9))
  constant,  ///< β_ij = β0 (velocity-blind; analytic Smoluchowski solution)
  sum,       ///< β_ij = β0 (i + j) (Golovin; analytic solution)
};

/// A granular gas of sticking grains, all at one granular temperature θ (Maxwellian, equipartition).
struct AggregationGas {
  /// Spatial dimension d (2 or 3).
  int dimension = 3;
  double alpha = 1;            ///< normal restitution of the rebounding collisions, (0, 1]
  double critical_energy = 0;  ///< θ*_11/θ0 of two monomers; θ*_ij = θ*_11 μ_ij/μ_11 (one critical speed)
  /// Which collisions stick (StickingCriterion: which energy is compared with the critical one).
  StickingCriterion criterion = StickingCriterion::relative_speed;
  /// The kernel β_ij that drives the size distribution.
  AggregationKernel kernel = AggregationKernel::kinetic;
  double pair_correlation = 1;  ///< χ, one contact value for every pair (dilute: 1)
  double kernel_constant = 1;   ///< β0 of the constant and sum kernels (reduced units)
};

/// Throws std::invalid_argument (one line, naming the field and the allowed range) unless gas is valid.
void validate(const AggregationGas& gas);

/// Returns R_ij = χ σ_ij^{d−1} (π^{(d−1)/2}/Γ(d/2)) √(2θ/μ_ij) (reduced units): collisions per unit
/// time and volume are R_ij n_i n_j for i ≠ j and R_ii n_i²/2 (theory.md (20.8)).
double collision_rate_coefficient(int dimension, double i, double j, double theta, double pair_correlation);

/// Returns θ*_ij = θ*_11 μ_ij/μ_11 with μ_ij = ij/(i + j): one critical relative speed for all pairs.
double critical_pair_energy(const AggregationGas& gas, double i, double j);

/// Rates per n_i n_j (i ≠ j; halve for i = j), reduced units (theory.md (20.9)–(20.11)).
struct PairRates {
  double aggregation = 0;  ///< β_ij
  double collisions = 0;   ///< R_ij
  double energy_loss = 0;  ///< granular energy lost by sticking and by inelastic rebounds
};

/// Returns β_ij, R_ij and the energy loss of sizes i, j ≥ 1 (monomers; a sectional grid's pivots need not be integers)
/// at temperature θ > 0; with may_stick = false (a merger the size grid cannot hold) every collision rebounds.
PairRates pair_rates(const AggregationGas& gas, double i, double j, double theta, bool may_stick = true);

}  // namespace gkt
