// Navier–Stokes transport coefficients of a granular mixture of s smooth inelastic hard spheres
// (d = 3) or disks (d = 2) about its (Maxwellian) homogeneous cooling state, at any Sonine order:
// the dilute (Boltzmann) gas (docs/theory.md §17; [garzo2002mixture]) and the dense (revised
// Enskog) gas (theory.md §18; [garzo2007mixture]).
//
// Reduced as in docs/conventions.md "Mixtures": D_ij* = D_ij/(n D0), D^T_i* = D^T_i/D0,
// D^p_i* = D^p_i/D0, η* = η/η0, λ* = λ/κ0, D''_j* = T D''_j/κ0, with D0, η0, κ0 the elastic
// first-approximation self-diffusion, viscosity and conductivity of a one-component gas of mass
// m̄ = Σ x_i m_i and diameter σ̄ = Σ x_i σ_i at the same n and T.
#pragma once

#include <memory>
#include <vector>

#include "gkt/operators/mixture_collisional_transfer.hpp"
#include "gkt/transport/mixture/mixture.hpp"
#include "gkt/transport/mixture/mixture_cooling_state.hpp"

namespace gkt {

/// The Navier–Stokes coefficients of one Sonine order (species indices from 0).
struct MixtureTransportValues {
  /// D_ij* at i·s + j: j_i = −Σ_j (m_i m_j n_j/ρ) D_ij ∇ln n_j − ρ D^T_i ∇ln T (theory.md (17.1)).
  std::vector<double> mutual_diffusion;
  std::vector<double> thermal_diffusion;  ///< D^T_i*
  /// D^F_ij* = D^F_ij T/(m̄ n D0) at i·s + j: j_i ∋ −Σ_j D^F_ij F_j for external forces F_j on the
  /// particles of species j (GDH's D^F_ij, [garzo2007mixture]; theory.md (18.14)).
  std::vector<double> mobility;
  /// L_j* = L_j/κ0 (species from 0): q ∋ −Σ_j L_j F_j, the heat flux per external force on species j, GDH's
  /// Σ_i L_ij ([garzo2007mixture]; theory.md (18.15)); −D''_j* in the dilute elastic gas.
  std::vector<double> heat_mobility;
  std::vector<double> pressure_diffusion;  ///< D^p_i* = Σ_j m_i m_j n_j D_ij/ρ² (j_i ∋ −ρ D^p_i ∇ln p; (17.8))
  std::vector<double> dufour;              ///< D''_j*: q = −λ∇T − T² Σ_j D''_j ∇ln n_j
  /// Per-particle drift of species i relative to u, w_i = j_i/(m_i n_i) = D0 Σ_j drift[i·s + j] ∇ln n_j +
  /// D0 thermal_drift[i] ∇ln T, finite also for a tracer i (theory.md (17.13)).
  /// @{
  std::vector<double> drift, thermal_drift;
  /// @}
  /// Λ_i = segregation[i] + g* segregation_gravity[i] (binaries only, else empty): the thermal
  /// diffusion factor of species i, ∂ln(n_i/n) = −Λ_i ∂ln T in a steady state with j_i = 0 and
  /// ∂p = −ρg, g* = ρg/(n ∂T) (theory.md (17.13)); nan if the other species is absent.
  /// @{
  std::vector<double> segregation, segregation_gravity;
  /// @}
  double shear_viscosity = 0;  ///< η*
  /// η_i^k* of [garzo2007mixture]: species i's kinetic part of η* (their sum is η* of the dilute gas)
  std::vector<double> shear_viscosity_kinetic;
  double thermal_conductivity = 0;          ///< λ*
  double bulk_viscosity = 0;                ///< κ/η0 (zero in the dilute gas)
  double cooling_rate_first_order = 0;      ///< ζ_U of ζ = ζ0 + ζ_U ∇·u (dimensionless; zero in the dilute gas)
  double pressure = 1;                      ///< p* = p/(nT)
  std::vector<double> pressure_derivative;  ///< P_j = (∂p/∂n_j)/T at fixed T and n_k (1 in the dilute gas; (18.2))
  /// ϖ_i of the first-order partial temperatures T_i = γ_i T + T ϖ_i ∇·u/ν0 (theory.md (18.7); empty in
  /// the dilute gas, nan for an absent species).
  std::vector<double> temperature_first_order;
};

/// How the first-order Chapman–Enskog equations are truncated (docs/theory.md §17.10).
enum class MixtureTruncation {
  /// gkt's Galerkin method: every vector trial function c S_0 … c S_N coupled in one system, the
  /// first-order partial temperatures ϖ_i solved in the dense gas (the default).
  complete,
  /// Garzó–Hrenya–Dufty's published first Sonine ([garzo2007mixture]; [garzo2002mixture] dilute):
  /// order 1 only; each flux keeps its leading polynomial — the mass-flux rows (c S_0) are solved
  /// alone and fed into the heat-flux rows (c S_1) — and ϖ_i = 0 (ζ_U and κ without them).
  published,
};

/// The linearised Boltzmann operator of a dilute mixture in Sonine polynomials, built once (exact
/// engine moments rounded to double) and solved at any order up to max_order.
class MixtureNavierStokes {
 public:
  /// Builds the operator for `mixture` (validated) about its HCS in the `reference` (Maxwellian by
  /// default), with vector trial functions c S_0 … c S_max_order, tensor ones Y_2 S_0 … Y_2 S_{max_order−1}
  /// and, for φ > 0, scalar ones S_1 … S_{max_order+1} per species; a cumulant reference carries the a_k,i
  /// into the operator, the sources, ζ and, for φ > 0, the collisional transfer (theory.md §17.11). Throws
  /// std::invalid_argument naming the field on bad input.
  MixtureNavierStokes(const Mixture& mixture, int max_order, MixtureReference reference = {});
  /// Copies carry the built operator (deep copy); a moved-from solver may only be assigned to or destroyed.
  ~MixtureNavierStokes();
  /// Deep copy, including the built operator.
  MixtureNavierStokes(const MixtureNavierStokes& other);
  /// Deep copy, including the built operator.
  MixtureNavierStokes& operator=(const MixtureNavierStokes& other);
  /// Takes the operator; the moved-from solver may only be assigned to or destroyed.
  MixtureNavierStokes(MixtureNavierStokes&&) noexcept;
  /// Takes the operator; the moved-from solver may only be assigned to or destroyed.
  MixtureNavierStokes& operator=(MixtureNavierStokes&&) noexcept;

  /// Returns the coefficients at Sonine order N (vector modes c S_0 … c S_N, shear Y_2 S_0 …
  /// Y_2 S_{N−1}, scalar S_1 … S_{N+1}), 1 ≤ N ≤ max_order.
  [[nodiscard]] MixtureTransportValues coefficients(int order) const;
  /// Returns the coefficients at order N truncated as `truncation` says: `complete` is
  /// coefficients(order); `published` (GDH's first Sonine, theory.md §17.10) needs order = 1 and throws
  /// std::invalid_argument naming `order` otherwise.
  [[nodiscard]] MixtureTransportValues coefficients(int order, MixtureTruncation truncation) const;
  /// Returns the largest Sonine order N the operator was built for (the constructor's max_order).
  [[nodiscard]] int max_order() const;
  /// Returns the HCS the coefficients are built about (its cumulants are those in f^(0)).
  [[nodiscard]] const MixtureCoolingState& cooling_state() const;
  /// Returns the HCS density derivatives used in the sources (theory.md §16.6; §17.11 for a cumulant reference).
  [[nodiscard]] const MixtureCoolingSensitivity& cooling_sensitivity() const;
  /// Returns n ∂a_k,i/∂n_j at [i·s + j][k] (k = 0 … K; empty for the Maxwellian reference): the
  /// cumulants' density derivatives in the ∇n_j sources (theory.md §17.11).
  [[nodiscard]] const std::vector<std::vector<double>>& cumulant_sensitivity() const;

 private:
  struct Impl;  // the operator blocks (Eigen) and the dense gas's pair tables (mixture_navier_stokes.cpp)
  std::unique_ptr<Impl> impl_;
};

}  // namespace gkt
