// The binary collision rule of rough inelastic hard spheres (d = 3) or disks (d = 2) of two
// species (docs/theory.md §19.17): particle 1 of species i (mass m_i, diameter σ_i, reduced moment
// of inertia κ_i = 4I_i/(m_iσ_i²)) meets particle 2 of species j at the contact distance
// σ_ij = (σ_i + σ_j)/2. Conventions as for one species (rough_collision_rule.hpp): σ̂ from 1 to 2,
// u = σ̂·(v1 − v2), spin velocities w_k = (σ_k/2) ω_k, so that the contact points move apart with
//     g_c = v1 − v2 + (w1 + w2) × σ̂          (disks: (w1 + w2) ẑ × σ̂),
// and the pair restitutions α_ij, β_ij send σ̂·g_c → −α σ̂·g_c, g_c,t → −β g_c,t. With the reduced
// mass μ_ij = m_i m_j/(m_i + m_j) and the tangential (effective) mass
//     1/M_ij = (1 + κ_i)/(κ_i m_i) + (1 + κ_j)/(κ_j m_j),                         (theory.md (19.50))
// the impulse on 1 is J = −(1+α) μ_ij u σ̂ − (1+β) M_ij g_c,t (−J on 2) and
//     v1' = v1 + J/m_i,  v2' = v2 − J/m_j,  w1' = w1 + σ̂ × J/(κ_i m_i),  w2' = w2 + σ̂ × J/(κ_j m_j).
// The diameters drop out of every average normalised by the collision rate (they only set w ↔ ω
// and the rate ∝ σ_ij^{d−1}); equal species give back (19.2) (M = κm/(2(1+κ))).
#pragma once

#include "gkt/algebra/rational.hpp"
#include "gkt/algebra/rational_polynomial.hpp"
#include "gkt/collision/rough_collision_map.hpp"

namespace gkt {

/// One species of a rough mixture: mass, reduced moment of inertia and the temperatures of its
/// reference Maxwellians (k_B = 1; any consistent units, velocities then in √(T/m)).
struct RoughSpecies {
  /// Mass m (> 0).
  Rational mass{1};
  /// Reduced moment of inertia κ = 4I/(mσ²), in (0, 1].
  Rational kappa{2, 5};
  /// Translational temperature T_t (> 0): v ~ exp(−m v²/(2T_t)).
  Rational translational_temperature{1, 2};
  /// Rotational temperature T_r (> 0): w = (σ/2)ω ~ exp(−κ m w²/(2T_r)).
  Rational rotational_temperature{1, 2};
};

/// Parameters of a collision between species i (slots v1, w1) and j (slots v2, w2) and of the two
/// species' reference Maxwellians; α, β and the spin scales exact in Ring (one of them may be the
/// polynomial variable).
///
/// Pre-collisional coordinates: v_k ~ exp(−a_k v_k²), a_k = m_k/(2T_t,k), and w_k = λ_k ŵ_k with
/// ŵ_k ~ exp(−b_k ŵ_k²). Numeric temperatures: λ_k = 1, b_k = κ_k m_k/(2T_r,k); symbolic
/// (rough_mixture_parameters_symbolic_spin): λ_k = x, b_k = κ_k m_k/(2T_r,k), so that the rotational
/// temperatures are x² T_r,k.
template <class Ring>
struct RoughMixtureParameters {
  /// Spatial dimension d (2 or 3).
  int dimension = 3;
  /// Normal restitution α_ij.
  Ring alpha{1L};
  /// Tangential restitution β_ij.
  Ring beta{-1L};
  /// Masses m_i, m_j.
  /// @{
  Rational mass_i{1}, mass_j{1};
  /// @}
  /// Reduced moments of inertia κ_i, κ_j.
  /// @{
  Rational kappa_i{2, 5}, kappa_j{2, 5};
  /// @}
  /// Translational Gaussian widths a_i, a_j.
  /// @{
  Rational velocity_width_i{1}, velocity_width_j{1};
  /// @}
  /// Spin scales λ_i, λ_j: w = λ ŵ.
  /// @{
  Ring spin_scale_i{1L}, spin_scale_j{1L};
  /// @}
  /// Spin Gaussian widths b_i, b_j of ŵ.
  /// @{
  Rational spin_width_i{5, 2}, spin_width_j{5, 2};
  /// @}

  /// Returns the tangential mass M_ij of (19.50), in the unit of the masses.
  [[nodiscard]] Rational tangential_mass() const;
  /// Returns the collision as a linear map at fixed σ̂ (theory.md (19.52)) with the widths (a_i, a_j, b_i, b_j).
  [[nodiscard]] RoughCollisionMap<Ring> collision_map() const;
};

/// Returns the parameters of an i–j collision for numeric α, β and numeric temperatures
/// (λ = 1). Throws std::invalid_argument naming the field for d ∉ {2, 3}, α ∉ (0, 1],
/// β ∉ [−1, 1], κ ∉ (0, 1], a mass or temperature ≤ 0.
RoughMixtureParameters<Rational> rough_mixture_parameters(int dimension, const Rational& alpha, const Rational& beta,
                                                          const RoughSpecies& species_i, const RoughSpecies& species_j);

/// Returns the parameters with the rotational temperatures symbolic: the ring variable x scales
/// both spins (λ_i = λ_j = x), so the species' rotational temperatures are x² T_r,i, x² T_r,j and
/// every moment is an even polynomial in x. At x = 1 it equals rough_mixture_parameters. Same checks.
RoughMixtureParameters<RationalPolynomial> rough_mixture_parameters_symbolic_spin(int dimension, const Rational& alpha,
                                                                                  const Rational& beta,
                                                                                  const RoughSpecies& species_i,
                                                                                  const RoughSpecies& species_j);

extern template struct RoughMixtureParameters<Rational>;
extern template struct RoughMixtureParameters<RationalPolynomial>;

}  // namespace gkt
