// The collisional rates of the rough gas's moments at Sonine order N in the linear or the nonlinear scheme
// (docs/theory.md §19.13, (19.25b)–(19.25c), §19.24; the balances of §19.14): for the distribution
//   φ = φ_M(c) φ_M(ŵ) [1 + Σ_{2 ≤ p+q ≤ N+1} a_pq S_p(x) S_q(y) (+ Σ_{p+q ≤ N−1} b_pq P S_p^(5/2)(x) S_q^(5/2)(y))],
// the cooling rates z_t, z_r and the steady balances G_t = (k + l) z_t⟨ψ_t⟩ + R[ψ_t] of the tests ψ_t = x^k y^l
// (and P x^k y^l), products of the unknowns dropped (linear) or all kept (nonlinear: R quadratic, z⟨ψ⟩ cubic,
// (19.27)), as functions of τ = θ/κ and the unknowns. The steady solution is rough_sonine_cooling_state(d, α, β, κ,
// N, scheme, ansatz); the time evolution (rough_cooling_evolution.hpp) integrates the same balances away from it.
#pragma once

#include <array>
#include <memory>
#include <span>
#include <vector>

#include "gkt/algebra/rational.hpp"
#include "gkt/transport/rough/rough_sonine_cooling_state.hpp"

namespace gkt {

/// The rates and balances at one (τ, unknowns); reduced by nσ^{d−1}v_t ν (theory.md (5.3)).
struct RoughSonineRates {
  double translational_rate = 0;  ///< z_t = ζ_t/(nσ^{d−1}v_t ν) = −(2/d) R[x], linear in the unknowns
  double rotational_rate = 0;     ///< z_r = ζ_r/(nσ^{d−1}v_t ν) = −(2/d_r) R[y] (0 at β = −1: no torque)
  /// G_t = (k + l) z_t⟨ψ_t⟩ + R[ψ_t] of each unknown's test, in the order of the unknowns (linear scheme: products
  /// dropped).
  std::vector<double> residual;
};

/// The rates of rough spheres or disks at Sonine order N, linear or nonlinear scheme, isotropic or (3D, β > −1)
/// oriented ansatz.
class RoughSonineCoolingRates {
 public:
  /// Builds the exact tables (those of the Sonine HCS solver of the same order, scheme and ansatz, plus the collision
  /// averages ⟨x1^i⟩ — nonlinear: ⟨x1^i x2^j⟩ — of the collision count). Throws std::invalid_argument naming the field
  /// for d ∉ {2, 3}, α ∉ (0, 1], β ∉ [−1, 1], κ ∉ (0, 1] or order < 1.
  RoughSonineCoolingRates(int dimension, const Rational& alpha, const Rational& beta, const Rational& kappa, int order,
                          RoughSonineAnsatz ansatz, RoughSonineScheme scheme = RoughSonineScheme::linear);
  ~RoughSonineCoolingRates();
  /// Takes the tables (copying is deleted).
  RoughSonineCoolingRates(RoughSonineCoolingRates&&) noexcept;
  /// Takes the tables (copying is deleted).
  RoughSonineCoolingRates& operator=(RoughSonineCoolingRates&&) noexcept;
  RoughSonineCoolingRates(const RoughSonineCoolingRates&) = delete;
  RoughSonineCoolingRates& operator=(const RoughSonineCoolingRates&) = delete;

  /// Returns the rates and balances at τ = θ/κ > 0 (any τ at β = −1) and the unknowns (a_pq, then b_pq).
  [[nodiscard]] RoughSonineRates at(double tau, std::span<const double> unknowns) const;
  /// Returns the indices (p, q) of the a_pq, the first unknowns (ordered by p + q, then q; q = 0 only at β = −1).
  [[nodiscard]] const std::vector<std::array<int, 2>>& cumulant_indices() const;
  /// Returns the indices (p, q) of the b_pq, the unknowns after the a_pq (empty for the isotropic ansatz, disks, β =
  /// −1).
  [[nodiscard]] const std::vector<std::array<int, 2>>& orientation_indices() const;
  /// Returns the number of unknowns.
  [[nodiscard]] std::size_t unknowns() const;
  /// Returns ⟨ψ_t⟩_M of each unknown's test (x^k y^l for a_kl, P x^k y^l for b_kl).
  [[nodiscard]] const std::vector<double>& maxwellian_moments() const;
  /// Returns ⟨ψ_t Φ_w⟩_M, [t][w], t the unknowns' tests, w the unknowns: ⟨ψ_t⟩ = ⟨ψ_t⟩_M + Σ_w u_w ⟨ψ_t Φ_w⟩_M
  /// (triangular in the total degree).
  [[nodiscard]] const std::vector<std::vector<double>>& projections() const;
  /// Returns the power of T_r in each unknown's test (l for x^k y^l, l + 1 for P x^k y^l): its moment changes by
  /// (k z_t + l z_r)⟨ψ⟩ from the scaling alone.
  [[nodiscard]] const std::vector<int>& spin_degrees() const;
  /// Returns the collision frequency over the Maxwellian one at the same T_t, 1 + 2 Σ_p a_p0 ⟨S_p(x1)⟩ over
  /// collisions, nonlinear scheme + Σ_pq a_p0 a_q0 ⟨S_p(x1) S_q(x2)⟩ (the spin and orientation terms average out of
  /// |c12·σ̂|; theory.md (19.25c), (19.110)).
  [[nodiscard]] double collision_frequency_factor(std::span<const double> unknowns) const;
  /// Returns C − 1/3 per unit b_pq, in the order of orientation_indices() (theory.md (19.28)).
  [[nodiscard]] const std::vector<double>& correlation_weights() const;
  /// Returns true at β = −1 (no spin balance; z_r = 0).
  [[nodiscard]] bool spin_decoupled() const;
  /// Returns d.
  [[nodiscard]] int dimension() const;
  /// Returns κ as a double.
  [[nodiscard]] double kappa() const;
  /// Returns the Sonine order N.
  [[nodiscard]] int order() const;
  /// Returns the scheme (products of unknowns dropped or kept).
  [[nodiscard]] RoughSonineScheme scheme() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gkt
