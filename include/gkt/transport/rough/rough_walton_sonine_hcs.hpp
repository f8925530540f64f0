// The homogeneous cooling state of the Walton gas (rough spheres or disks with Coulomb friction,
// rough_walton.hpp) in the linear scheme at Sonine orders 1 … 3 (docs/theory.md §19.25): the scaled
// distribution φ_M(c) φ_M(ŵ)[1 + Σ a_pq S_p(c²) S_q(ŵ²)], 2 ≤ p + q ≤ N + 1 (the isotropic ansatz (19.26)), with
// the balances (19.10) for every test c^{2k} ŵ^{2l} and ζ_t = ζ_r, linearised in the a_pq. The collision averages
// are products of up to 2N + 2 quadratic forms of the Gaussian conditioned on the normal and tangential contact
// velocities (which fix η_t), by the joint cumulants (19.81) and a (u, |g_c,t|) Gauss–Legendre rule (§19.20).
// The oriented ansatz (spheres) adds Σ b_pq P S_p^(5/2)(c²) S_q^(5/2)(ŵ²), P = (c·ŵ)² − c²ŵ²/3, p + q ≤ N − 1, with
// the tests P c^{2k} ŵ^{2l} (theory.md (19.26a) and §19.29): the forms c·ŵ of both partners and of 1' join the six.
#pragma once

#include <array>
#include <vector>

#include "gkt/transport/rough/rough_sonine_cooling_state.hpp"

namespace gkt {

/// Highest Sonine order of the Walton HCS (products of up to 2N + 2 forms; order 4 would cost ~15× order 3,
/// docs/performance.md).
inline constexpr int kWaltonHcsHighestOrder = 3;

/// The linear-scheme Walton HCS at one Sonine order.
struct RoughWaltonSonineState {
  int order = 1;                            ///< Sonine order N (cumulants to p + q = N + 1)
  double temperature_ratio = 0;             ///< θ = T_r/T_t (+inf where the spin decouples; NaN where not solved)
  double cooling_rate = 0;                  ///< ζ* = ζ/ν0(T_t), ν0 = nT_t/η0(T_t) (NaN where not solved)
  std::vector<std::array<int, 2>> indices;  ///< (p, q) of the cumulants, 2 ≤ p + q ≤ N + 1
  std::vector<double> cumulants;            ///< a_pq in the order of `indices` (theory.md (19.26))
  /// (p, q) of the orientation coefficients b_pq, p + q ≤ N − 1 (oriented ansatz, spheres, spin coupled; else empty).
  std::vector<std::array<int, 2>> orientation_indices;
  std::vector<double> orientation_coefficients;  ///< b_pq in the order of `orientation_indices` (theory.md (19.26a))
  /// C = ⟨(c·ŵ)²/(c²ŵ²)⟩ = 1/3 + Σ b_pq (4/45)⟨x S_p⟩_M⟨y S_q⟩_M (theory.md (19.28)); 1/3 for the isotropic
  /// ansatz, NaN for disks (no orientation variable) or where not solved.
  double orientation_correlation = 1.0 / 3;
  double maxwellian_temperature_ratio = 0;  ///< θ of the Maxwellian approximation (rough_walton.hpp), the order-0 value
  double maxwellian_cooling_rate = 0;       ///< ζ* of the Maxwellian approximation
  /// True where the Maxwellian ζ_t = ζ_r has no finite root (μ_f = 0, β0 = −1, or friction too weak).
  bool spin_decoupled = false;
  /// False where the linear scheme of this order has no root with realizable a20, a02, a11 near the root of the
  /// order below (theory.md §19.25): θ, ζ* and the cumulants are then NaN.
  bool solved = true;
  /// Returns a_pq (dimensionless; 0 for indices outside the ansatz, NaN where not solved).
  [[nodiscard]] double cumulant(int p, int q) const;
  /// Returns b_pq (dimensionless; 0 outside the ansatz or for the isotropic one, NaN for disks or where not solved).
  [[nodiscard]] double orientation_coefficient(int p, int q) const;
};

/// Returns the linear-scheme Walton HCS at orders 1 … highest_order (≤ kWaltonHcsHighestOrder) for d ∈ {2, 3},
/// α ∈ (0, 1], β0 ∈ [−1, 1], κ ∈ (0, 1], μ_f ≥ 0 (+inf: constant β = β0), `panels` Gauss–Legendre panels per piece:
/// order N's τ by the secant method in ln τ from order N − 1's root (order 1 from rough_walton_linear_cooling_state's)
/// to 1e-12 (theory.md §19.25). `ansatz` = oriented adds the b_pq and their balances (spheres; theory.md §19.29;
/// for disks it is the isotropic ansatz, C NaN). Throws std::invalid_argument naming the field.
std::vector<RoughWaltonSonineState> rough_walton_sonine_cooling_states(
    int dimension, double alpha, double beta0, double kappa, double friction, int highest_order, int panels = 8,
    RoughSonineAnsatz ansatz = RoughSonineAnsatz::isotropic);

}  // namespace gkt
