// The homogeneous cooling state of a binary mixture of rough spheres (d = 3) or disks (d = 2) in the first
// Sonine approximation, linear scheme (docs/theory.md §19.30): every species i carries its own cumulants
//   a20_i = ⟨X_i²⟩/⟨X_i²⟩_M − 1,  a02_i = ⟨Y_i²⟩/⟨Y_i²⟩_M − 1,  a11_i = ⟨X_iY_i⟩/(⟨X_i⟩⟨Y_i⟩) − 1,
// X_i = m_i v²/(2T_t,i), Y_i = κ_i m_i w²/(2T_r,i) (w = (σ_i/2)ω; the species' own temperatures), i.e.
//   f_i = f_M(X_i) f_M(Y_i) [1 + a20_i S_2(X_i) + a02_i S_2(Y_i) + a11_i S_1(X_i) S_1(Y_i)],
// with the translational ratios γ_i, the spin ratios θ_i and ζ* solved self-consistently; every collision
// average of a product of the two species' Sonine polynomials comes exactly from the two-species rough
// engine (rough_mixture_collision_moments.hpp) at the current (rationalised) temperatures.
#pragma once

#include <array>

#include "gkt/transport/rough/rough_mixture_cooling_state.hpp"

namespace gkt {

/// The collisional rates and the linear-scheme balances of a homogeneous rough binary mixture at given
/// temperatures and cumulants (theory.md (19.171)–(19.173)); time in 1/ν0(T), T = Σx_i T_t,i.
struct RoughMixtureLinearBalances {
  /// ζ*_k(a) = −(d ln T_k/dt)/ν0(T) for k = (translational 1, translational 2, rotational 1, rotational 2),
  /// linear in the cumulants ((19.172)).
  std::array<double, 4> cooling_rate{};
  /// The steady fourth-degree balances G_{p,i} at [3i + p], p = 0 (X²), 1 (Y²), 2 (XY), ζ⟨ψ⟩ linearised
  /// ((19.173)): zero at the linear HCS.
  std::array<double, 6> balance{};
};

/// Returns the rates and balances at the temperatures (T_t,1, T_t,2, T_r,1, T_r,2) (> 0, any unit) and the
/// cumulants (a20_1, a02_1, a11_1, a20_2, a02_2, a11_2), from the exact two-species engine tables
/// (temperature ratios rationalised to within 1e-12). Throws std::invalid_argument on bad input.
RoughMixtureLinearBalances rough_mixture_linear_balances(const RoughBinaryMixture& mixture,
                                                         const std::array<double, 4>& temperatures,
                                                         const std::array<double, 6>& cumulants);

/// The first-Sonine (linear scheme) HCS of a rough binary mixture.
struct RoughMixtureSonineCoolingState {
  std::array<double, 2> temperature_ratio{};  ///< γ_i = T_t,i/T, T = Σx_i T_t,i
  std::array<double, 2> rotational_ratio{};   ///< θ_i = T_r,i/T_t,i (+∞ for a decoupled spin)
  double cooling_rate = 0;                    ///< the common ζ* = ζ/ν0(T) (reduction of theory.md (16.4))
  /// The cumulants of species i (theory.md (19.170)); a02_i = a11_i = NaN for a decoupled spin.
  /// @{
  std::array<double, 2> a20{}, a02{}, a11{};
  /// @}
  std::array<bool, 2> spin_decoupled{};  ///< β = −1 on every pair the species meets with weight (theory.md (19.130))
  bool solved =
      false;  ///< Newton converged (a full step < 1e-10 in the logs) to cumulants every species can have ((19.24a))
  int iterations = 0;  ///< Newton iterations from the Maxwellian HCS
};

/// Returns the linear first-Sonine HCS by Newton's method in (ln T_t,2/T_t,1, ln θ_1, ln θ_2) from the
/// Maxwellian HCS, the six cumulants solved exactly at each step from their linear balances (theory.md
/// §19.30); `solved = false` (values of the last iterate) where Newton does not converge or the cumulants are
/// not realizable. Throws std::invalid_argument on bad input (as rough_mixture_cooling_state).
RoughMixtureSonineCoolingState rough_mixture_sonine_cooling_state(const RoughBinaryMixture& mixture);

}  // namespace gkt
