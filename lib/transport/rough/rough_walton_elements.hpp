// Internal: the Walton gas's collision elements ⟨T_r S_p' L_q', 𝓛 T_r S_p L_q⟩ at one τ by quadrature over
// (u, |g_c,t|) of the conditioned Gaussian's moments (docs/theory.md §19.20), in the layout of the constant-β
// engine (rough_sonine_systems.hpp), so that its Galerkin systems solve the Walton gas unchanged.
#pragma once

#include <vector>

#include "transport/rough/rough_sonine_systems.hpp"

namespace gkt::detail {

/// Highest Sonine order of the Walton elements (products of up to 2K + 2 quadratic forms; K = 4 costs ~10–25 s,
/// K = 5 would cost minutes: theory.md §19.20, docs/performance.md).
inline constexpr int kWaltonHighestOrder = 4;

/// One monomial c x^x y^y (x = c², y = ŵ²) of a reference partner's weight Φ (theory.md (19.127)).
struct WaltonWeightTerm {
  int x = 0, y = 0;
  double c = 0;
};

/// Returns the collision elements of the Walton gas at τ = θ/κ for orders 1 … highest_order (≤ kWaltonHighestOrder),
/// `panels` 8-point Gauss–Legendre panels per piece in u and |g_c,t| (as rough_walton_productions). Ranges as
/// rough_walton_rates; throws std::invalid_argument naming the field. With `weight` the elements are instead
/// Σ_w a_w W^(w) of theory.md (19.44) for Φ = Σ_w a_w Φ_w given as monomials (the partner weight of the cumulant
/// reference, §19.25).
RoughCollisionElements rough_walton_collision_elements(int dimension, double alpha, double beta0, double kappa,
                                                       double friction, double tau, int highest_order, int panels = 8,
                                                       const std::vector<WaltonWeightTerm>* weight = nullptr);

}  // namespace gkt::detail
