// The amplitude of the high-energy tail of the homogeneous cooling state of dilute smooth inelastic
// hard spheres (d = 3) and disks (d = 2): φ(c) ~ 𝒜 c^γ exp(−A c) for c → ∞, with φ the scaled
// distribution of docs/conventions.md (∫ φ d^d c = 1, ∫ c² φ d^d c = d/2, c = v/v0, v0 = √(2T/m)),
// A = 2β/ζ_r ([vannoije1998]) and γ of theory.md (10.15). 𝒜 follows from the tail scheme's φ_N
// (tail_galerkin.hpp), where it is converged in N, carried to c = ∞ by the exact Boltzmann equation
// written as a first-order equation for R = φ/(c^γ e^{−A c}) (docs/theory.md §10.7, (10.16)–(10.17)).
#pragma once

#include <functional>
#include <vector>

namespace gkt {

/// The restitutions where hcs_tail_amplitude was measured to work (theory.md §10.7): α ∈ [0.05, 0.7] in 2D and 3D
/// at resolution 12 (relative errors 0.1–0.4 %). Above, φ_N is converged only inside the Gaussian core (which
/// reaches c ≈ A/2) and the continuation does not settle (2D α = 0.8 and 0.9 at N = 12); below 0.05 it was not
/// measured.
inline constexpr double kHcsTailAmplitudeMinAlpha = 0.05;
/// The highest restitution where hcs_tail_amplitude was measured to work (2D and 3D, N = 12; see above).
inline constexpr double kHcsTailAmplitudeMaxAlpha = 0.7;

/// The tail amplitude at one resolution and matching speed.
struct HcsTailMatch {
  double matching_speed = 0;  ///< c_m (units v0): φ_N is used for c ≤ c_m
  double amplitude = 0;       ///< 𝒜 from this c_m (units of φ: v0^{−d} per unit density, times c^{−γ})
  double ratio_at_match = 0;  ///< R_N(c_m) = φ_N(c_m) c_m^{−γ} e^{A c_m}
  bool settled = false;       ///< the fixed point of the continuation met its tolerance (finite)
};

/// The tail amplitude 𝒜 of the HCS with its error estimate (theory.md §10.7).
struct HcsTailAmplitude {
  int order = 0;                      ///< resolution N of the tail scheme used
  double amplitude = 0;               ///< 𝒜 of φ ~ 𝒜 c^γ e^{−A c} (φ normalised as in docs/conventions.md)
  double error = 0;                   ///< estimate: spread over matching speeds plus the change from resolution N − 1
  double exponent = 0;                ///< A = 2β/ζ_r from the resolution-N solution (units 1/v0)
  double power = 0;                   ///< γ of (10.15)
  double first_correction = 0;        ///< b_1 of φ = 𝒜 c^γ e^{−A c}(1 + b_1/c + O(c^{−2})) (units v0)
  std::vector<HcsTailMatch> matches;  ///< resolution N, each matching speed
  std::vector<HcsTailMatch> previous_matches;  ///< resolution N − 1, the same matching speeds
};

/// Returns 𝒜 of φ ~ 𝒜 c^γ exp(−A c) (theory.md §10.7) for dimension d = 2 or 3, restitution α ∈
/// [kHcsTailAmplitudeMinAlpha, kHcsTailAmplitudeMaxAlpha] and tail-scheme resolution N ∈ [3,
/// kTailGalerkinMaxOrder], with the error estimate of HcsTailAmplitude. Throws std::invalid_argument naming the
/// field for d ∉ {2, 3}, α outside that measured range (α = 1: the Maxwellian has no exponential tail at all) or
/// N out of range, and std::runtime_error if the continuation does not settle at a matching speed (measured: 2D
/// α = 0.8 and 0.9 at N = 12, where φ_N is converged only to c ≈ 3–4, inside the Gaussian core that reaches to
/// A/2 = 4.5 and 8.4).
HcsTailAmplitude hcs_tail_amplitude(int dimension, double alpha, int order);

/// The gain and loss of J*[φ, φ] = G − ν φ at one speed (units of theory.md (9.1): dσ̂ Θ(g·σ̂)(g·σ̂),
/// velocities in v0).
struct BoltzmannGainLoss {
  double gain_ratio = 0;    ///< G(c)/φ(c) (theory.md (10.18))
  double loss = 0;          ///< ν(c) = β ∫ φ(v2) |v − v2| d^d v2 over |v2| ≤ 6
  double partner_mass = 0;  ///< ∫ φ(v2) d^d v2 over |v2| ≤ 6 on the same rule (1 for a normalised φ)
};

/// Returns G(c)/φ(c) and ν(c) of the Boltzmann operator for an isotropic φ given by its logarithm
/// `log_phi` (theory.md §10.7), dimension d = 2 or 3, α ∈ (0, 1), c > 0. The gain is written over the
/// pre-collision partner and σ̂ ((10.18)), partners to speed 6 and, for a fast partner that stops on a
/// slow particle, beyond while φ(u)/φ(c) > e^{−37}; σ̂ panels graded toward the grazing ends. Throws
/// std::invalid_argument naming the field for d, α or c out of range.
BoltzmannGainLoss boltzmann_gain_loss(int dimension, double alpha, double c,
                                      const std::function<double(double)>& log_phi);

}  // namespace gkt
