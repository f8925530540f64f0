// Navier–Stokes coefficients of the Walton gas (rough spheres or disks with Coulomb friction,
// rough_walton.hpp) at Sonine orders beyond the first (docs/theory.md §19.20): the translation × spin Sonine
// product families of the constant-β solver (rough_sonine_transport.hpp, (19.40)–(19.43)) with the collision
// elements computed by quadrature over the normal relative velocity u and |g_c,t| (which fix η_t) of the
// conditioned Gaussian's moments, products of up to 2N + 2 quadratic forms, their joint cumulants (19.71).
// Reference state: Maxwellians at T_t and θT_t (the Maxwellian Walton HCS when θ is its root).
#pragma once

#include <vector>

#include "gkt/transport/rough/rough_sonine_transport.hpp"
#include "gkt/transport/rough/rough_walton_sonine_hcs.hpp"

namespace gkt {

/// Returns η*, κ*, μ*, η_b*, ζ_U (reductions of RoughTransportValues) of the Walton gas about Maxwellians at
/// θ = T_r/T_t for the Sonine orders 1 … highest_order (element k − 1 is order k), highest_order ∈ [1, 4]; ζ* is the
/// Maxwellian Walton rate at θ. μ_f = 0 or β0 = −1 (no torque): the spin decouples, the translational values are the
/// smooth gas's and the totals NaN (θ is then ignored). Order 1 is rough_walton.hpp's first approximation. `panels`
/// as rough_walton_productions. Throws std::invalid_argument naming the field (ranges as rough_walton_rates, θ > 0
/// finite, `order` outside [1, 4]).
std::vector<RoughTransportValues> rough_walton_sonine_transport(int dimension, double alpha, double beta0, double kappa,
                                                                double friction, double temperature_ratio,
                                                                int highest_order, int panels = 8);

/// Returns η*, κ*, μ*, η_b*, ζ_U at Sonine orders 1 … highest_order (≤ 4, element k − 1 is order k) about the Walton
/// HCS `hcs` (theory.md §19.25, (19.127)): f0 = f_M(c) f_M(ŵ)[1 + Σ a_pq S_p(c²) S_q(ŵ²)] at its θ with its ζ*; the
/// collision matrix gains Σ a_pq W^(pq) of (19.44), by the same quadrature, and the sources are averages over f0
/// (19.45). Throws std::invalid_argument naming `hcs` when it is not solved, and the fields as above.
std::vector<RoughTransportValues> rough_walton_sonine_transport_about_hcs(int dimension, double alpha, double beta0,
                                                                          double kappa, double friction,
                                                                          const RoughWaltonSonineState& hcs,
                                                                          int highest_order, int panels = 8);

}  // namespace gkt
