// The high-energy tails of a granular mixture's HCS and first-order distributions: for each species
// the rate A_i of φ_i ~ exp(−A_i c_i) in its own scaled speed c_i = √(m_i/(2T_i)) V (docs/theory.md
// §17.12), the mixture form of van Noije and Ernst's A = 2β/ζ_r.
#pragma once

#include <vector>

#include "gkt/transport/mixture/mixture.hpp"
#include "gkt/transport/mixture/mixture_cooling_state.hpp"

namespace gkt {

/// Returns A_i (dimensionless, per unit of c_i = √(m_i/(2T_i)) V) of every species:
/// A_i = 2β Σ_j x_j (σ_ij/σ̄)^{d−1} / (ζ √θ_i), β = π^{(d−1)/2}/Γ((d+1)/2), θ_i = (m_i/m̄)/γ_i and ζ = ζ* ν0
/// in the units n = m̄ = σ̄ = √(2T/m̄) = 1 ([vannoije1998] for one component; theory.md (17.28)), with γ_i
/// and ζ* of `state` (the HCS of `mixture`). A particle of species i much faster than every partner loses
/// at the rate β Σ_j n_j σ_ij^{d−1} V, and the scaling term (ζ/2) ∂_V·(V ·) of the HCS and of the
/// Chapman–Enskog equations balances it. Valid as an asymptote where species i is the faster one
/// (θ_i ≤ θ_j); a heavy species meets it only far beyond its partners' thermal speed. The Sonine series
/// of species i turns (its coefficients stop decaying) near order A_i²/4 (theory.md §10.6). Infinite at
/// α = 1 (ζ = 0). Throws std::invalid_argument if the state does not belong to the mixture.
std::vector<double> mixture_tail_exponents(const Mixture& mixture, const MixtureCoolingState& state);

}  // namespace gkt
