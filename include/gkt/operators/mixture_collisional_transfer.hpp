// Exact Enskog collisional-transfer averages of one ordered pair (i, j) of a dense granular
// mixture about Maxwellian species distributions (docs/theory.md §18): the projections of the
// gradient part of the Enskog operator on the Sonine test functions, and the pair's collisional
// parts of the momentum and heat fluxes and of the cooling rate at first order in gradients.
//
// Every entry is a collision average
//     ⟨⟨Y⟩⟩ = ∫dv1 dv2 dσ̂ Θ(σ̂·g)(σ̂·g) f̂_i(v1) f̂_j(v2) Y / ∫dv1 dv2 dσ̂ Θ(σ̂·g)(σ̂·g) f̂_i f̂_j,
// f̂ the normalised Maxwellians of widths θ = m/(2T), σ̂ the unit vector from particle 1 (species
// i) to its partner (species j), v1' the post-collisional velocity, c1 = √θ_i v1, c2 = √θ_j v2,
// X = c². It is built from the engine's exact moments of H = g − g' = (1+α)(σ̂·g)σ̂
// (quadratic_form_moments.hpp) and rounded to double once.
#pragma once

#include <vector>

#include "gkt/algebra/rational.hpp"

namespace gkt {

/// The averages of one ordered pair; Sonine indices p, q = 0 … n_max (vector: S^(d/2), tensor:
/// S^(d/2+1), scalar: S^(d/2−1)), velocities and ΔE_1 = ½m_i(v1'² − v1²) in the caller's units.
struct PairTransferMoments {
  /// The largest Sonine index: p, q = 0 … n_max.
  int n_max = 0;
  std::vector<double> source_density;      ///< [p] ⟨⟨σ̂·[c1' S_p(X1') − c1 S_p(X1)]⟩⟩
  std::vector<double> source_temperature;  ///< [p] the same times (X2 − d/2)
  std::vector<double> source_shear;  ///< [p] ⟨⟨[Y(c1') S_p(X1') − Y(c1) S_p(X1)] : σ̂c2⟩⟩, Y(c) = cc − c²I/d
  std::vector<double> source_scalar;       ///< [p] ⟨⟨(σ̂·c2)[S_p(X1') − S_p(X1)]⟩⟩
  std::vector<double> shear_flux_partner;  ///< [q] ⟨⟨(σ̂·g)((σ̂·c2)² − X2/d) S_q(X2)⟩⟩
  std::vector<double> shear_flux_self;     ///< [q] ⟨⟨(σ̂·g)((σ̂·c1)² − X1/d) S_q(X1)⟩⟩
  std::vector<double> heat_flux_partner;   ///< [q] ⟨⟨(σ̂·c2) ΔE_1 S_q(X2)⟩⟩
  std::vector<double> heat_flux_self;      ///< [q] ⟨⟨(σ̂·c1) ΔE_1 S_q(X1)⟩⟩
  std::vector<double> pressure_partner;    ///< [q] ⟨⟨(σ̂·g) S_q(X2)⟩⟩
  std::vector<double> pressure_self;       ///< [q] ⟨⟨(σ̂·g) S_q(X1)⟩⟩
  std::vector<double> cooling_partner;     ///< [q] ⟨⟨(σ̂·g)² S_q(X2)⟩⟩
  std::vector<double> cooling_self;        ///< [q] ⟨⟨(σ̂·g)² S_q(X1)⟩⟩
  double shear_gradient = 0;               ///< ⟨⟨(σ̂·g) σ̂·(2θ_j v2 − 2θ_i v1)⟩⟩
  double cooling_gradient = 0;             ///< ⟨⟨(σ̂·g)² σ̂·(2θ_j v2)⟩⟩
  double energy = 0;                       ///< ⟨⟨ΔE_1⟩⟩
  double energy_self = 0;                  ///< ⟨⟨ΔE_1 X1⟩⟩
  double energy_partner = 0;               ///< ⟨⟨ΔE_1 X2⟩⟩
};

/// Returns the averages of the pair (i, j) for d = 2, 3: mass_ratio = m_i/m_j, width_root =
/// √(θ_i/θ_j) (both exact), restitution α ∈ (0, 1], Sonine indices to n_max; mass_i and theta_j
/// (the caller's units) fix the scale of ΔE_1 and of the velocities. Throws
/// std::invalid_argument on a bad dimension, ratio, α or n_max.
PairTransferMoments pair_transfer_moments(int dimension, const Rational& mass_ratio, const Rational& width_root,
                                          const Rational& alpha, int n_max, double mass_i, double theta_j);

}  // namespace gkt
