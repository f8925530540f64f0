// The collisional rates of rough spheres' second- and fourth-degree moments with the velocity–spin orientation term
// (docs/theory.md §19.14, (19.26a) at order 1, linear scheme): the first-Sonine distribution
//   φ = φ_M(c) φ_M(ŵ) [1 + a20 S_2(x) + a02 S_2(y) + a11 S_1(x) S_1(y) + b00 P],   P = (c·ŵ)² − xy/3,
// and the balances of x, y, x², y², xy and P as functions of τ = θ/κ and (a20, a02, a11, b00). The steady solution is
// rough_sonine_cooling_state(3, α, β, κ, 1, linear, oriented); the time evolution (rough_cooling_evolution.hpp)
// integrates the same balances (theory.md §19.13).
#pragma once

#include <array>
#include <memory>

#include "gkt/algebra/rational.hpp"

namespace gkt {

/// The rates and balances at one (τ, a20, a02, a11, b00); reduced by nσ^{d−1}v_t ν (theory.md (5.3)).
struct RoughOrientedBalances {
  double translational_rate = 0;  ///< z_t = ζ_t/(nσ^{d−1}v_t ν) = −(2/d) R[x], linearised in the cumulants
  double rotational_rate = 0;     ///< z_r = ζ_r/(nσ^{d−1}v_t ν) = −(2/d_r) R[y], linearised in the cumulants
  /// For ψ = x², y², xy, P: the steady balances (k + l) z_t⟨ψ⟩ + R[ψ] (theory.md (19.10); products of cumulants
  /// dropped, as in the linear scheme).
  std::array<double, 4> residual{};
};

/// The oriented first-Sonine rates of rough spheres (d = 3), α ∈ (0, 1], β ∈ (−1, 1], κ ∈ (0, 1].
class RoughOrientedCoolingRates {
 public:
  /// Builds the exact tables (three engine tables with c·w forms, ~30 ms); throws std::invalid_argument naming the
  /// field on bad input (β = −1 included: the spin decouples and carries no orientation).
  RoughOrientedCoolingRates(const Rational& alpha, const Rational& beta, const Rational& kappa);
  ~RoughOrientedCoolingRates();
  /// Takes the tables (copying is deleted).
  RoughOrientedCoolingRates(RoughOrientedCoolingRates&&) noexcept;
  /// Takes the tables (copying is deleted).
  RoughOrientedCoolingRates& operator=(RoughOrientedCoolingRates&&) noexcept;
  RoughOrientedCoolingRates(const RoughOrientedCoolingRates&) = delete;
  RoughOrientedCoolingRates& operator=(const RoughOrientedCoolingRates&) = delete;

  /// Returns the rates and balances at τ = θ/κ > 0 and a = (a20, a02, a11, b00).
  [[nodiscard]] RoughOrientedBalances at(double tau, const std::array<double, 4>& a) const;
  /// Returns the Maxwellian moments per unit cumulant, (⟨x²⟩_M, ⟨y²⟩_M, ⟨xy⟩_M, ⟨P²⟩_M) = (15/4, 15/4, 9/4, 5/4)
  /// (⟨P²⟩_M = ⟨x²⟩⟨y²⟩⟨(cos²Θ − 1/3)²⟩ = (225/16)(4/45), theory.md §19.8):
  /// ⟨ψ⟩ = base (1 + a) for the first three, ⟨P⟩ = b00 ⟨P²⟩_M.
  [[nodiscard]] std::array<double, 4> base_moments() const;
  /// Returns C − 1/3 = ⟨(c·ŵ)²/(c²ŵ²)⟩ − 1/3 per unit b00 (1/5, theory.md (19.28)).
  [[nodiscard]] double correlation_weight() const;
  /// Returns κ as a double.
  [[nodiscard]] double kappa() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gkt
