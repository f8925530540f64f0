// The automatic width of the vector Sonine basis of a dilute granular mixture (docs/theory.md §17.12,
// (17.30)): one Gaussian width w for every species, chosen from the species' tail exponents (17.28) so
// that no species' series turns before a target order, capped where the Maxwellian core itself would
// converge too slowly in the wider basis.
#pragma once

#include <vector>

#include "gkt/transport/mixture/mixture.hpp"
#include "gkt/transport/mixture/mixture_cooling_state.hpp"

namespace gkt {

/// Returns the automatic basis widths w_i = T_basis,i/T_i (dimensionless, one per species, all equal) of
/// theory.md (17.30): w = clamp(4 N*/A*², 1, 2) with A* = min_i s_i A_i, A_i the tail exponents (17.28) of
/// `state` (the HCS of `mixture`) and s_i = Σ_j x_j σ_ij^{d−1} min(1, 2μ_ji) / Σ_j x_j σ_ij^{d−1}, μ_ji =
/// m_j/(m_i + m_j): the share of a fast particle's collisions that remove it from the tail (a much lighter
/// partner's kicks are a drag, weighted by 2μ_ji). A species with s_i < 1/2 whose thermal speed² 2T_i/m_i is
/// below half that of its dragging partners (Fokker–Planck regime: Gaussian tail) does not count. All 1
/// (the standard basis) when no species counts or α = 1.
/// `target_order` N* ∈ [1, 100] is the highest Sonine order the widths are chosen for (12, the model's
/// highest). Throws std::invalid_argument naming the field on bad input.
std::vector<double> mixture_basis_width(const Mixture& mixture, const MixtureCoolingState& state,
                                        int target_order = 12);

}  // namespace gkt
