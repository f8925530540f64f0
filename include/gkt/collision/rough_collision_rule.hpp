// The binary collision rule of rough inelastic hard spheres (d = 3) or disks (d = 2) of one
// species: mass m, diameter σ, moment of inertia I, reduced moment of inertia κ = 4I/(mσ²).
// Convention (docs/theory.md §19.1): σ̂ is the unit vector from the centre of particle 1 to that
// of particle 2, u = σ̂·(v1 − v2) > 0 for approaching particles, and the spin enters as the
// velocity w = (σ/2) ω (disks: ω and w are scalars about the normal of the plane). The relative
// velocity of the contact points is
//     g_c = v1 − v2 + (w1 + w2) × σ̂          (disks: (w1 + w2) ẑ × σ̂),
// and a collision maps σ̂·g_c → −α σ̂·g_c and the tangential part g_c,t → −β g_c,t, with
// β = −1 smooth and β = +1 perfectly rough ([huthmann1997]; [luding1998] eq. 1–3; the usual
// convention of [kremer2014] eq. 2.2; seed 000 writes the tangential law with −β). With
// η_n = (1+α)/2 and η_t = (1+β)κ/(2(1+κ)), momentum and angular momentum conservation give
//     v1' = v1 − η_n u σ̂ − η_t g_c,t,   v2' = v2 + η_n u σ̂ + η_t g_c,t,
//     w1' = w1 − (η_t/κ) σ̂ × g_c,t,     w2' = w2 − (η_t/κ) σ̂ × g_c,t.
#pragma once

#include <array>

#include "gkt/algebra/rational.hpp"
#include "gkt/algebra/rational_polynomial.hpp"
#include "gkt/collision/rough_collision_map.hpp"

namespace gkt {

/// The eight vectors a rough-sphere collision integrand can depend on: translational velocities
/// v and spin velocities w = (σ/2)ω of both partners, before and after the collision.
enum class RoughSlot { v1 = 0, v2 = 1, w1 = 2, w2 = 3, v1_post = 4, v2_post = 5, w1_post = 6, w2_post = 7 };

/// Returns true for the spin slots w1, w2, w1', w2'.
constexpr bool is_spin_slot(RoughSlot s) { return (static_cast<int>(s) % 4) >= 2; }

/// Parameters of the rough collision and of the two reference Maxwellians, exact in Ring (α or
/// β may be a polynomial variable, or the spin scale λ below).
///
/// Pre-collisional coordinates: v ~ exp(−v²) (velocities in units of √(2T_t/m)) and w = λ ŵ with
/// ŵ ~ exp(−spin_width ŵ²). For a spin temperature ratio θ = T_r/T_t the spin w (in the same
/// unit) has the Gaussian width κ/θ: either λ = 1, spin_width = κ/θ (θ a number) or
/// λ = √(θ/κ), spin_width = 1 (θ symbolic through λ, see rough_parameters_symbolic_temperature).
template <class Ring>
struct RoughCollisionParameters {
  /// Spatial dimension d (2 or 3).
  int dimension = 3;
  /// Normal restitution α.
  Ring alpha{1L};
  /// Tangential restitution β.
  Ring beta{-1L};
  /// Reduced moment of inertia κ = 4I/(mσ²).
  Rational kappa{2, 5};
  /// Spin scale λ: w = λ ŵ.
  Ring spin_scale{1L};
  /// Gaussian width of ŵ: ŵ ~ exp(−spin_width ŵ²).
  Rational spin_width{5, 2};

  /// Returns η_n = (1+α)/2.
  [[nodiscard]] Ring normal_factor() const;
  /// Returns η_t = (1+β)κ/(2(1+κ)).
  [[nodiscard]] Ring tangential_factor() const;
  /// Returns the collision (19.4) as a linear map at fixed σ̂ with the widths (1, 1, s, s).
  [[nodiscard]] RoughCollisionMap<Ring> collision_map() const;
};

/// Returns the parameters for numeric α, β, κ and θ = T_r/T_t (λ = 1, spin_width = κ/θ). Throws
/// std::invalid_argument naming the field for d ∉ {2, 3}, α ∉ (0, 1], β ∉ [−1, 1], κ ∉ (0, 1], θ ≤ 0.
RoughCollisionParameters<Rational> rough_parameters(int dimension, const Rational& alpha, const Rational& beta,
                                                    const Rational& kappa, const Rational& temperature_ratio);

/// Returns the parameters with θ symbolic: the ring variable is λ = √(θ/κ) (spin_width = 1), so
/// every moment is a polynomial in λ (even, i.e. a polynomial in θ/κ). Same checks as above.
RoughCollisionParameters<RationalPolynomial> rough_parameters_symbolic_temperature(int dimension, const Rational& alpha,
                                                                                   const Rational& beta,
                                                                                   const Rational& kappa);

extern template struct RoughCollisionParameters<Rational>;
extern template struct RoughCollisionParameters<RationalPolynomial>;

}  // namespace gkt
