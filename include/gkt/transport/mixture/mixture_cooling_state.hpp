// The homogeneous cooling state of a granular mixture: partial temperatures T_i/T from equal
// cooling rates ζ_1 = … = ζ_s, in the Maxwellian approximation or in the first Sonine
// approximation with the cumulants a2,i, linear or nonlinear in them (docs/theory.md §16).
#pragma once

#include <memory>
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

/// The species distributions f_i^(0) a Chapman–Enskog solution is built about (theory.md §17.11):
/// MixtureNavierStokes and TracerDiffusion.
struct MixtureReference {
  /// maxwellian: every f_i^(0) Maxwellian at T_i, as [garzo2002mixture] and [garzo2007mixture] (the
  /// default); linear or nonlinear: f_i^(0) = f_M,i (1 + Σ_{k=2}^K a_k,i S_k(X_i)) with the a_k,i, T_i and ζ
  /// of mixture_cooling_state(mixture, scheme, hcs_order) in the operator, the sources and ζ.
  MixtureHcsScheme scheme = MixtureHcsScheme::maxwellian;
  /// K: the cumulants a_2 … a_K (an integer in [2, 6]); ignored by the Maxwellian reference.
  int hcs_order = 2;
  /// Per species w_i = T_basis,i/T_i ∈ [0.6, 16]: the vector trial functions of species i are
  /// c' S_q(c'²) over the Maxwellian at w_i T_i, c' = c_i/√w_i (theory.md §17.12, "wide basis"); empty
  /// (the default) or all 1 is the standard basis. MixtureNavierStokes only, dilute gas with the
  /// Maxwellian reference only (anything else is refused).
  std::vector<double> basis_width = {};
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
/// (16.7a)); ignored by the Maxwellian scheme.
MixtureCoolingState mixture_cooling_state(const Mixture& mixture,
                                          MixtureHcsScheme scheme = MixtureHcsScheme::maxwellian, int sonine_order = 2);

/// The rates of change of a freely cooling mixture away from its HCS, per ν0(T) (theory.md §16.7).
struct MixtureCoolingRates {
  std::vector<double> cooling_rate;                ///< ζ_i* = −(d ln T_i/dt)/ν0(T) of every species
  double mixture_cooling_rate = 0;                 ///< ζ* = −(d ln T/dt)/ν0(T) = Σ_i x_i γ_i ζ_i*
  std::vector<std::vector<double>> cumulant_rate;  ///< (d a_k,i/dt)/ν0(T) at [i][k], k = 0 … K (0 for k < 2)
};

/// Returns the rates of a homogeneous mixture at temperature ratios γ_i = T_i/T (Σ x_i γ_i = 1) with
/// cumulants a_k,i (`cumulants[i][k]`, k = 0 … K, K ∈ [2, 6]; ignored by the Maxwellian scheme):
/// the X^p balances (16.7a) without the HCS condition, ⟨X^p⟩_i(a) changing as p ζ_i⟨X^p⟩_i + Λ B^p_i
/// (the scheme's products kept or dropped as in mixture_cooling_state, so that its HCS is the rest
/// point), and ζ_i* of (16.6). Throws std::invalid_argument naming the field on bad input.
MixtureCoolingRates mixture_cooling_rates(const Mixture& mixture, std::span<const double> temperature_ratio,
                                          const std::vector<std::vector<double>>& cumulants, MixtureHcsScheme scheme);

/// mixture_cooling_rates for one mixture, scheme and K along a trajectory: the pair moments are
/// computed exactly once at Chebyshev nodes in u = ln(θ_i/θ_j) and interpolated (to round-off), on
/// the range the trajectory is expected to visit — ln(γ_i/γ_j) between log_ratio_low[i·s + j] and
/// log_ratio_high[i·s + j], with a margin; outside it the exact moments are computed (theory.md §16.7).
class MixtureCoolingDynamics {
 public:
  /// Prepares the interpolated pair moments of `mixture` in `scheme` carrying a_2 … a_K (K = hcs_order) for ln(γ_i/γ_j)
  /// between log_ratio_low[i·s + j] and log_ratio_high[i·s + j]; throws std::invalid_argument naming the field on bad
  /// input.
  MixtureCoolingDynamics(const Mixture& mixture, MixtureHcsScheme scheme, int hcs_order,
                         std::span<const double> log_ratio_low, std::span<const double> log_ratio_high);
  /// Returns mixture_cooling_rates(mixture, temperature_ratio, cumulants, scheme) (a_0 … a_K per species).
  [[nodiscard]] MixtureCoolingRates rates(std::span<const double> temperature_ratio,
                                          const std::vector<std::vector<double>>& cumulants) const;

 private:
  struct Tables;  // the interpolants (mixture_cooling_state.cpp)
  Mixture mixture_;
  MixtureHcsScheme scheme_;
  int k_max_;
  std::shared_ptr<const Tables> tables_;
};

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

/// Returns the derivatives of the mixture's HCS (dilute or dense) in the `reference` scheme (K = hcs_order) with
/// respect to the partial densities at fixed T — n ∂ln γ_i/∂n_j and n (∂ζ/∂n_j)/ν0 as above — and, if
/// `cumulant_derivatives` is given, n ∂a_k,i/∂n_j at [i·s + j][k] (k = 0 … K), by a central stencil in n_j
/// of the solved HCS (step 10⁻³ n; five points dilute, seven dense, where φ moves with n_j; one-sided five
/// points when x_j < 2·10⁻³, dense 3·10⁻³; theory.md §17.11). Throws
/// std::invalid_argument naming the field on bad input, or if a stencil state does not converge.
MixtureCoolingSensitivity mixture_cooling_sensitivity(const Mixture& mixture, const MixtureReference& reference,
                                                      std::vector<std::vector<double>>* cumulant_derivatives = nullptr);

}  // namespace gkt
