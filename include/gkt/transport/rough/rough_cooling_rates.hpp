// The collisional rates of the rough gas's second- and fourth-degree moments in the first Sonine
// (linear) approximation (docs/theory.md §19.4, (19.10)–(19.12)): the translational and rotational
// cooling rates and the fourth-degree balances, as functions of τ = θ/κ and of the cumulants
// a = (a20, a02, a11). The collision averages are exact Laurent polynomials in τ from three engine
// tables (rough_collision_moments.hpp); evaluating them is a few dozen multiply-adds, so both the
// steady HCS solver (rough_homogeneous_cooling_state.hpp) and the time evolution
// (rough_cooling_evolution.hpp) call them.
#pragma once

#include <array>
#include <memory>

#include "gkt/algebra/rational.hpp"

namespace gkt {

/// The rates and balances at one (τ, a); reduced by nσ^{d−1}v_t ν (v_t = √(2T_t/m), ν of
/// theory.md (5.3)).
struct RoughBalances {
  double translational_rate = 0;  ///< z_t(a) = ζ_t/(nσ^{d−1}v_t ν) = −(2/d) R[x](a)
  double rotational_rate = 0;     ///< z_r(a) = ζ_r/(nσ^{d−1}v_t ν) = −(2/d_r) R[y](a)
  /// G_0 = R[x]/d − R[y]/d_r (= (z_r − z_t)/2) and, for ψ = x², y², xy, the steady fourth-degree
  /// balances G_p = 2z_t(a)⟨ψ⟩_a + R[ψ](a), z_t⟨ψ⟩ linearised in a (theory.md (19.10)).
  std::array<double, 4> residual{};
  std::array<std::array<double, 3>, 4> jacobian{};  ///< ∂G/∂a (exact: G is linear in a)
};

/// The collision averages of the linear scheme at one τ: productions[X][t] = R_X[ψ_t] (weights X ∈ {1, S2(x),
/// S2(y), S1(x)S1(y)}, tests t ∈ {x, y, x², y², xy}; RoughCoolingRates::production, theory.md (19.10)).
using RoughProductionTable = std::array<std::array<double, 5>, 4>;

/// Returns the rates and the linear-scheme balances at cumulants a = (a20, a02, a11) from the collision
/// averages at one τ, for dimension d ∈ {2, 3} (theory.md (19.10)–(19.11); the algebra of
/// RoughCoolingRates::at, shared with the Walton gas's quadrature, rough_walton_cumulants.hpp).
RoughBalances rough_linear_balances(int dimension, const RoughProductionTable& productions,
                                    const std::array<double, 3>& a);

/// The rough gas's collisional rates for d ∈ {2, 3}, α ∈ (0, 1], β ∈ [−1, 1], κ ∈ (0, 1].
class RoughCoolingRates {
 public:
  /// Builds the exact tables (~40–60 ms); throws std::invalid_argument naming the field on bad input.
  RoughCoolingRates(int dimension, const Rational& alpha, const Rational& beta, const Rational& kappa);
  ~RoughCoolingRates();
  /// Takes the tables (copying is deleted).
  RoughCoolingRates(RoughCoolingRates&&) noexcept;
  /// Takes the tables (copying is deleted).
  RoughCoolingRates& operator=(RoughCoolingRates&&) noexcept;
  RoughCoolingRates(const RoughCoolingRates&) = delete;
  RoughCoolingRates& operator=(const RoughCoolingRates&) = delete;

  /// Returns the rates and balances at τ = θ/κ > 0 and cumulants a = (a20, a02, a11).
  [[nodiscard]] RoughBalances at(double tau, const std::array<double, 3>& a) const;
  /// Returns the Maxwellian fourth moments (⟨x²⟩_M, ⟨y²⟩_M, ⟨xy⟩_M) = (d(d+2)/4, d_r(d_r+2)/4, d d_r/4).
  [[nodiscard]] std::array<double, 3> maxwellian_fourth_moments() const;
  /// Returns the collision frequency over the Maxwellian one at the same T_t, 1 + c a20 with
  /// c = 2⟨S_2(x1)⟩ over collisions (the spin cumulants do not change it; linear in a20).
  [[nodiscard]] double collision_frequency_factor(double a20) const;
  /// Returns the collision average R_X[ψ_t] = ⟨(Φ_X(1) + Φ_X(2))(ψ_t(1') − ψ_t(1))⟩/⟨1⟩ at τ (Φ_0 = 1
  /// counted once) for the weights X ∈ {0: 1, 1: S2(x), 2: S2(y), 3: S1(x)S1(y)} and the tests
  /// t ∈ {x, y, x², y², xy} (theory.md (19.10)).
  [[nodiscard]] double production(std::size_t weight, std::size_t test, double tau) const;
  /// Returns (c0, c1, c2) of τ·G_0(τ, 0) = c0 + c1 τ + c2 τ², exact (the Maxwellian θ equation).
  [[nodiscard]] std::array<Rational, 3> maxwellian_temperature_equation() const;
  /// Returns the spatial dimension d.
  [[nodiscard]] int dimension() const;
  /// Returns κ as a double.
  [[nodiscard]] double kappa() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gkt
