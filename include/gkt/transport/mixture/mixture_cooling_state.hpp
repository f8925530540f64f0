// The homogeneous cooling state of a granular mixture: partial temperatures T_i/T from equal
// cooling rates ζ_1 = … = ζ_s, in the Maxwellian approximation or in the first Sonine
// approximation with the cumulants a2,i, linear or nonlinear in them (docs/theory.md §16).
#pragma once

#include <span>
#include <vector>

#include "gkt/transport/mixture/mixture.hpp"

namespace gkt {

/// Returns ⟨X1' − X1⟩ of a collision of species i with j over Maxwellians, per collision and
/// normalised by the collision integral J0 (X = θ_i v², θ = m/(2T)):
/// −2μ_ji(1+α)[1 − ½μ_ji(1+α)(1 + θ_i/θ_j)], μ_ji = m_j/(m_i + m_j) (theory.md (16.3)).
double pair_energy_change(double mu_ji, double alpha, double theta_ratio);

/// Returns ζ_i* = ζ_i/ν0 of every species at temperature ratios γ_i = T_i/T with contact values
/// χ_ij (i·s + j); ν0 = nT/η0 with η0 the elastic first-Sonine viscosity of a one-component gas
/// of mass m̄ and diameter σ̄ (theory.md (16.4)). `correction` (i·s + j, optional) is added to
/// the pair's ⟨X1' − X1⟩: the a2 terms of (16.6). Writes into `rates` (size s).
void species_cooling_rates(const Mixture& mixture, std::span<const double> temperature_ratio,
                           std::span<const double> chi, std::span<double> rates,
                           std::span<const double> correction = {});

/// How the species distributions of the HCS are represented.
enum class MixtureHcsScheme {
  maxwellian,  ///< f_i Maxwellian at T_i (every a_k,i = 0)
  linear,      ///< f_i = f_M,i (1 + Σ_{k=2}^K a_k,i S_k), every collision moment linear in the a's
  nonlinear,   ///< the same f_i with the products a_k,i a_l,j (and ζ_i a_k,i) kept
};

/// The mixture HCS.
struct MixtureCoolingState {
  std::vector<double> temperature_ratio;       ///< γ_i = T_i/T
  std::vector<double> a2;                      ///< a2,i (zero in the Maxwellian scheme)
  std::vector<std::vector<double>> cumulants;  ///< a_k,i at [i][k], k = 0 … K (a_0 = 1, a_1 = 0)
  double cooling_rate = 0;                     ///< the common ζ* = ζ/ν0
  std::vector<double> chi;                     ///< χ_ij at i·s + j
  int iterations = 0;                          ///< outer iterations (linear scheme) or Gauss–Seidel sweeps
  bool solved = false;                         ///< equal rates to 1e-12 (and, linear, a fixed point to 1e-12)
};

/// Returns the HCS of the mixture (validated first; throws std::invalid_argument on bad input),
/// carrying the cumulants a_2 … a_K of every species, K = sonine_order ∈ [2, 6] (theory.md §16.3,
/// (16.8)); ignored by the Maxwellian scheme.
MixtureCoolingState mixture_cooling_state(const Mixture& mixture,
                                          MixtureHcsScheme scheme = MixtureHcsScheme::maxwellian, int sonine_order = 2);

/// How the Maxwellian HCS of a mixture responds to the partial densities at fixed T.
struct MixtureCoolingSensitivity {
  std::vector<double> temperature_ratio;  ///< n ∂ln γ_i/∂n_j at i·s + j
  std::vector<double> cooling_rate;       ///< n (∂ζ/∂n_j)/ν0, ν0 of (16.4) held at the state
};

/// Returns the derivatives of the Maxwellian HCS `state` of the `mixture` with respect to
/// the partial densities n_j at fixed T and fixed n_k (k ≠ j), by implicit differentiation of
/// ζ_1 = … = ζ_s, Σ_k n_k γ_k = n (theory.md (16.11)), with the contact values' own density
/// dependence in the dense gas (theory.md (18.1)); exact up to rounding.
MixtureCoolingSensitivity mixture_cooling_sensitivity(const Mixture& mixture, const MixtureCoolingState& state);

}  // namespace gkt
