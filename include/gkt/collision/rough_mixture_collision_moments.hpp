// Collision moments of a binary mixture of rough spheres or disks (docs/theory.md §19.17): the
// averages over i–j collisions, weighted by the two species' Maxwellians (each at its own T_t, T_r),
//
//   ⟨X⟩ = ∫dv1 dv2 dŵ1 dŵ2 dσ̂ Θ(u) u e^{−a_i v1² − a_j v2² − b_i ŵ1² − b_j ŵ2²} X,   u = σ̂·(v1 − v2),
//
// of products of quadratic forms in (v1, v2, w1, w2, v1', v2', w1', w2') (RoughSlot; slot 1 is
// species i, slot 2 species j), exact in Ring. Same closed form (19.5)/(19.5a) and Euler recurrence
// as one species (rough_collision_moments.hpp); only the collision map (19.52) and the widths differ.
#pragma once

#include <functional>
#include <vector>

#include "gkt/collision/rough_collision_moments.hpp"
#include "gkt/collision/rough_mixture_collision_rule.hpp"

namespace gkt {

/// Returns the table of ⟨Π_v F_v^{k_v}⟩/⟨1⟩, 0 ≤ k_v ≤ degrees[v] (and accepted by `keep`, a
/// down-closed set), for up to nine forms F_v over the slots of an i–j collision; velocities in the
/// unit of the species' masses and temperatures (rough_mixture_collision_rule.hpp). Exact in Ring
/// (Rational, or RationalPolynomial with α, β or the spin scale x symbolic). Throws
/// std::invalid_argument as RoughCollisionMoments does.
template <class Ring>
RoughCollisionMoments<Ring> rough_mixture_collision_moments(const RoughMixtureParameters<Ring>& parameters,
                                                            const std::vector<RoughForm>& forms,
                                                            const std::vector<int>& degrees,
                                                            std::function<bool(const RoughExponents&)> keep = {});

/// Returns the form c² of a slot in the species' reduced velocity: a_k v² at a translational slot,
/// b_k ŵ² = b_k w² at a spin slot (numeric temperatures, λ = 1), k the slot's species
/// (1, 1' → i; 2, 2' → j). Sonine polynomials in c², ŵ² and the products c_a·c_b of
/// rough_mixture_reduced_dot build every matrix element. Throws std::invalid_argument if a spin scale is not 1.
RoughForm rough_mixture_reduced_square(const RoughMixtureParameters<Rational>& parameters, RoughSlot slot);

/// Returns the form c_a·c_b of two slots in their reduced velocities, √(width_a width_b) W_a·W_b (widths as
/// in rough_mixture_reduced_square; λ = 1); the rank-one and rank-two (c c − c²I/d) spherical-harmonic
/// contractions are built from it. Throws std::invalid_argument if width_a width_b is not the square of a
/// rational (the moment would not be rational) or a spin scale is not 1.
RoughForm rough_mixture_reduced_dot(const RoughMixtureParameters<Rational>& parameters, RoughSlot a, RoughSlot b);

/// Explicit instantiation for numeric parameters (compiled once in the library).
extern template RoughCollisionMoments<Rational> rough_mixture_collision_moments<Rational>(
    const RoughMixtureParameters<Rational>&, const std::vector<RoughForm>&, const std::vector<int>&,
    std::function<bool(const RoughExponents&)>);
/// Explicit instantiation for one symbolic parameter (compiled once in the library).
extern template RoughCollisionMoments<RationalPolynomial> rough_mixture_collision_moments<RationalPolynomial>(
    const RoughMixtureParameters<RationalPolynomial>&, const std::vector<RoughForm>&, const std::vector<int>&,
    std::function<bool(const RoughExponents&)>);

}  // namespace gkt
