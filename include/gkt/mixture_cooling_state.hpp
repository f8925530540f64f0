// The homogeneous cooling state of a granular mixture in the Maxwellian approximation: partial
// temperatures T_i/T from equal cooling rates ζ_1 = … = ζ_s (docs/theory.md §16.2).
#pragma once

#include <span>
#include <vector>

#include "gkt/mixture.hpp"

namespace gkt {

/// Returns ⟨X1' − X1⟩ of a collision of species i with j over Maxwellians, per collision and
/// normalised by the collision integral J0 (X = θ_i v², θ = m/(2T)):
/// −2μ_ji(1+α)[1 − ½μ_ji(1+α)(1 + θ_i/θ_j)], μ_ji = m_j/(m_i + m_j) (theory.md (16.3)).
double pair_energy_change(double mu_ji, double alpha, double theta_ratio);

/// Returns ζ_i* = ζ_i/ν0 of every species at temperature ratios γ_i = T_i/T (Σ x_i γ_i = 1) with
/// contact values χ_ij (i·s + j); ν0 = nT/η0 with η0 the elastic first-Sonine viscosity of a
/// one-component gas of mass m̄ and diameter σ̄ (theory.md (16.4)). Writes into `rates` (size s).
void species_cooling_rates(const Mixture& mixture, std::span<const double> temperature_ratio,
                           std::span<const double> chi, std::span<double> rates);

/// The mixture HCS.
struct MixtureCoolingState {
  std::vector<double> temperature_ratio;  ///< γ_i = T_i/T
  double cooling_rate = 0;                ///< the common ζ* = ζ/ν0
  std::vector<double> chi;                ///< χ_ij at i·s + j
  int iterations = 0;                     ///< Gauss–Seidel sweeps
  bool solved = false;                    ///< max_i |ζ_i* − ζ*| ≤ 1e-12 max(1, |ζ*|) reached
};

/// Returns the HCS of the mixture (validated first; throws std::invalid_argument on bad input):
/// ζ_i* = ζ_s* for the ratios γ_i/γ_s (bracketed 1D roots, swept until fixed), then Σ x_i γ_i = 1.
MixtureCoolingState mixture_cooling_state(const Mixture& mixture);

}  // namespace gkt
