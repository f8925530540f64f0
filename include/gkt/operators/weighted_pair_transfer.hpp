// Exact Enskog collisional-transfer averages of one ordered pair (i, j) of a dense granular
// mixture about species distributions with HCS cumulants, f_i^(0) = f_M,i Σ_k a_k,i S_k(X_i)
// (docs/theory.md §17.11, (17.22)–(17.24)): every average of PairTransferMoments split by the
// Sonine weight of particle 1 (index k) and of its partner (index l), so that a solver contracts
// them with the a_k,i, a_l,j of its reference and with their density derivatives.
//
// The averages are those of mixture_collisional_transfer.hpp (the Maxwellian collision average
// ⟨⟨·⟩⟩ of species i at v1 and j at v2, same normalisation, same units), with the extra factors
//     S_k = S^{(d/2−1)}_k,   T_k = X S_k − X S_k' − (d/2) S_k,   G_k = −½ D_k = S_k − S_k'
// of X1 (particle 1) or X2 (partner): T_k and G_k are the factors of T∂_T f and ∂_V f of a
// cumulant term, T∂_T(f_M S_k) = f_M T_k, ∂_V(f_M S_k) = −2θV f_M G_k (T_0 = X − d/2, G_0 = 1:
// the Maxwellian factors of pair_transfer_moments).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "gkt/algebra/rational.hpp"
#include "gkt/operators/mixture_collisional_transfer.hpp"

namespace gkt {

/// The weighted averages of one ordered pair; Sonine indices p, q = 0 … n_max as in
/// PairTransferMoments, weight indices k, l = 0 … k_max.
struct WeightedPairTransferMoments {
  int dimension = 3;  ///< d
  int n_max = 0;      ///< largest Sonine index p, q
  int k_max = 0;      ///< largest weight index k, l
  /// [p][k][l]: S_k(X1) S_l(X2) × source_density of PairTransferMoments.
  std::vector<double> source_density;
  /// [p][k][l]: S_k(X1) T_l(X2) × ⟨⟨σ̂·[c1' S_p(X1') − c1 S_p(X1)]⟩⟩ (the source_temperature factor X2 − d/2 is T_0).
  std::vector<double> source_temperature;
  /// [p][k][l]: S_k(X1) G_l(X2) × source_shear.
  std::vector<double> source_shear;
  /// [p][k][l]: S_k(X1) G_l(X2) × source_scalar.
  std::vector<double> source_scalar;
  /// [q][k]: S_k(X1) × the partner's flux averages (f^(1) on the partner, f^(0) of species i on particle 1).
  /// @{
  std::vector<double> shear_flux_partner, heat_flux_partner, pressure_partner, cooling_partner;
  /// @}
  /// [q][l]: S_l(X2) × the self flux averages (f^(1) on particle 1, f^(0) of species j on the partner).
  /// @{
  std::vector<double> shear_flux_self, heat_flux_self, pressure_self, cooling_self;
  /// @}
  /// [k][l]: ⟨⟨(σ̂·g) σ̂·[S_k(X1) G_l(X2) 2θ_j v2 − G_k(X1) S_l(X2) 2θ_i v1]⟩⟩.
  std::vector<double> shear_gradient;
  /// [k][l]: ⟨⟨(σ̂·g)² σ̂·2θ_j v2 S_k(X1) G_l(X2)⟩⟩.
  std::vector<double> cooling_gradient;
  /// [k][l]: ⟨⟨ΔE_1 S_k(X1) S_l(X2)⟩⟩.
  std::vector<double> energy;
  /// [k][l]: ⟨⟨ΔE_1 T_k(X1) S_l(X2)⟩⟩.
  std::vector<double> energy_temperature_self;
  /// [k][l]: ⟨⟨ΔE_1 S_k(X1) T_l(X2)⟩⟩.
  std::vector<double> energy_temperature_partner;

  /// Returns the offset of [p][k][l]: (p·(K+1) + k)·(K+1) + l.
  [[nodiscard]] std::size_t index(int p, int k, int l) const {
    const auto w = static_cast<std::size_t>(k_max) + 1;
    return (static_cast<std::size_t>(p) * w + static_cast<std::size_t>(k)) * w + static_cast<std::size_t>(l);
  }
  /// Returns the offset of [q][k] (or [k][l]): q·(K+1) + k.
  [[nodiscard]] std::size_t index(int q, int k) const {
    return static_cast<std::size_t>(q) * (static_cast<std::size_t>(k_max) + 1) + static_cast<std::size_t>(k);
  }
};

/// Returns the weighted averages of the pair (i, j) for d = 2, 3 with the arguments of
/// pair_transfer_moments and the largest weight index k_max ≥ 0 (exact for the rational mass
/// ratio and width root, rounded to double once). Throws std::invalid_argument on bad input.
WeightedPairTransferMoments weighted_pair_transfer_moments(int dimension, const Rational& mass_ratio,
                                                           const Rational& width_root, const Rational& alpha, int n_max,
                                                           int k_max, double mass_i, double theta_j);

/// Returns the pair's averages about f_i^(0) = f_M,i Σ_k a_i[k] S_k(X1) and f_j^(0) = f_M,j Σ_l a_j[l] S_l(X2)
/// in the layout of PairTransferMoments (the Maxwellian factors X − d/2 and 2θv of its gradient entries become
/// Σ a T and Σ a G; energy_self and energy_partner are the contracted T entries plus (d/2) energy), so that a
/// solver written for the Maxwellian pair carries the cumulants (theory.md (17.23)). a_i, a_j: k_max + 1
/// entries each; throws std::invalid_argument otherwise.
PairTransferMoments contracted_pair_transfer(const WeightedPairTransferMoments& moments, std::span<const double> a_i,
                                             std::span<const double> a_j);

}  // namespace gkt
