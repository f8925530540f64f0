// Garzó–Hrenya–Dufty's published first Sonine approximation for a dilute or dense (revised Enskog)
// granular mixture of s ≤ 4 smooth inelastic species, in closed form and double precision: one call
// per state, no allocation (docs/theory.md §17.10; [garzo2002mixture], [garzo2007mixture] and
// [garzo2007mixtureII]).
//
// The truncation is GDH's, not gkt's default (MixtureTruncation::published of MixtureNavierStokes):
// each flux keeps its leading Sonine polynomial, the mass-flux equations (trial c S_0) are solved
// alone and their solution is fed into the heat-flux equations (trial c S_1), and f^(0) is the
// Maxwellian at the HCS temperatures T_i = γ_i T; dense, the first-order partial temperatures ϖ_i are
// dropped as GDH do. Reduced as MixtureTransportValues
// (docs/conventions.md "Mixtures").
#pragma once

#include <array>

#include "gkt/transport/mixture/mixture.hpp"

namespace gkt {

/// One state of a mixture at the per-cell boundary: fixed size, species from 0.
struct MixtureCell {
  int dimension = 3;  ///< d = 2 or 3
  int species = 2;    ///< s = 2 … 4
  /// m_i, σ_i (any units, > 0) and x_i (≥ 0, summing to 1 within 1e-12) of species i < s.
  /// @{
  std::array<double, 4> mass{}, diameter{}, fraction{};
  /// @}
  std::array<double, 16> restitution{};  ///< α_ij at i·4 + j, symmetric, in (0, 1]
  double packing_fraction = 0;           ///< φ in [0, φ_max(d)); 0 is the dilute gas
};

/// Returns the cell of a validated Mixture (throws std::invalid_argument naming the field for more
/// than 4 species).
MixtureCell mixture_cell(const Mixture& mixture);

/// The published first-Sonine coefficients of one state (species from 0; entries i·4 + j for pairs).
struct PublishedFirstSonine {
  std::array<double, 4> temperature_ratio{};   ///< γ_i = T_i/T of the Maxwellian HCS (theory.md §16.2)
  double cooling_rate = 0;                     ///< ζ* = ζ/ν0
  std::array<double, 16> mutual_diffusion{};   ///< D_ij* = D_ij/(n D0)
  std::array<double, 4> thermal_diffusion{};   ///< D^T_i* = D^T_i/D0
  std::array<double, 4> pressure_diffusion{};  ///< D^p_i* = Σ_j m_i m_j n_j D_ij/(ρ² D0)
  std::array<double, 16> mobility{};           ///< D^F_ij* = D^F_ij T/(m̄ n D0)
  double thermal_conductivity = 0;             ///< λ* = λ/κ0
  /// λ_i* (GDH's λ_i^k): species i's kinetic part; Σ_i λ_i* = λ* when dilute, dense λ* adds the collisional transfer
  std::array<double, 4> thermal_conductivity_species{};
  std::array<double, 4> dufour{};  ///< D''_j* (kinetic and, dense, collisional)
  std::array<double, 16>
      dufour_species{};  ///< D_q,ij* = T D_q,ij/κ0, kinetic parts (GDH's split; Σ_i = D''_j* when dilute)
  std::array<double, 4> heat_mobility{};            ///< L_j* (kinetic and, dense, collisional)
  std::array<double, 16> heat_mobility_species{};   ///< L_ij* = L_ij/κ0, kinetic parts (Σ_i = L_j* when dilute)
  double shear_viscosity = 0;                       ///< η* = η/η0 (kinetic and, dense, collisional)
  std::array<double, 4> shear_viscosity_species{};  ///< η_i* (GDH's η_i^k), kinetic parts (Σ_i = η* when dilute)
  double bulk_viscosity = 0;                        ///< κ/η0 (0 when dilute)
  double cooling_rate_first_order = 0;              ///< ζ_U of ζ = ζ0 + ζ_U ∇·u (0 when dilute)
  double pressure = 1;                              ///< p* = p/(nT) (18.2)
  std::array<double, 4> pressure_derivative{};      ///< P_j = (∂p/∂n_j)/T at fixed T and n_k (1 when dilute)
};

/// Returns GDH's first-Sonine coefficients of the state `cell`, dilute or dense (the engine's
/// MixtureTruncation::published at order 1), reduced by the reference gas of m̄ = Σ x_i m_i,
/// σ̄ = Σ x_i σ_i at the same n and T (theory.md §17.10).
/// Throws std::invalid_argument naming the field on bad input, or if the HCS does not converge.
PublishedFirstSonine published_first_sonine(const MixtureCell& cell);

}  // namespace gkt
