// The steady uniform shear flow beyond Grad: a moment (Hermite–Sonine) solution of
// −a V_y ∂f/∂V_x = J[f, f] (docs/theory.md (22.1), §22.7) with
//
//   f = n (m/2T)^{d/2} π^{−d/2} e^{−c²} Σ_i x_i ψ_i(c),   c = V/√(2T/m),
//
// ψ_i the Cartesian Hermite polynomials of total degree ≤ 2N with the symmetry of the flow
// (cartesian_collision_moments.hpp), Galerkin projection on the same ψ_k, and the full bilinear
// collision moments (the products x_i x_j Grad drops are kept). Unknowns: x_i (x_0 = 1) and the
// shear rate a*, fixed by the temperature ⟨c²⟩ = d/2. Units as uniform_shear_flow.hpp.
#pragma once

#include <vector>

namespace gkt {

/// Which collision terms the moment equations keep.
enum class UniformShearCollisionTerms {
  linear,    ///< terms linear in the x_i only (at order 1 exactly Grad's (22.3))
  bilinear,  ///< every product x_i x_j (the exact moments of J[f, f] in the basis)
};

/// One moment solution of the steady USF (theory.md §22.7).
struct UniformShearMoments {
  int order = 1;                  ///< N: Hermite polynomials of total degree ≤ 2N
  int basis_size = 0;             ///< number of basis polynomials (ψ = 1 included)
  double shear_rate = 0;          ///< a/ν0(T), ν0 = nT/η0
  double reduced_shear_rate = 0;  ///< γ = a ℓ/√(2T/m) (theory.md (22.8))
  double stress_xx = 0;           ///< P_xx/(2nT)
  double stress_yy = 0;           ///< P_yy/(2nT)
  double stress_zz = 0;           ///< P_zz/(2nT) (d = 3; 0 in d = 2)
  double stress_xy = 0;           ///< P_xy/(2nT)
  double cooling_rate = 0;        ///< ζ/ν0 = −(1/(d p ν0)) m∫V² J[f, f] (from the collision moments)
  double kurtosis = 0;            ///< a2 = ⟨c⁴⟩/(d(d+2)/4) − 1 (the isotropic fourth cumulant)
  double energy_balance = 0;      ///< 2a*P_xy/p + d ζ* (theory.md (22.4); zero up to rounding)
  int newton_iterations = 0;      ///< Newton steps taken from the previous order's solution
};

/// Returns the moment solutions at orders 1 … max_order (element N − 1 is order N), each
/// started from the previous one (order 1 from Grad's (22.7)) and solved by Newton's method to
/// rounding. With `linear` terms, order 1 is Grad's solution (22.6)–(22.7) recomputed from the
/// quadrature. Cost: see docs/performance.md (d = 3, N = 3: ~25 s of CPU). Throws std::invalid_argument
/// naming the argument for d ∉ {2, 3}, α outside (0, 1) or max_order outside [1, 6] (d = 2) /
/// [1, 3] (d = 3); std::runtime_error if Newton's method does not converge.
std::vector<UniformShearMoments> uniform_shear_flow_moments(
    int dimension, double alpha, int max_order,
    UniformShearCollisionTerms terms = UniformShearCollisionTerms::bilinear);

/// Returns the largest order uniform_shear_flow_moments accepts in dimension d (6 in 2D, 3 in 3D).
int uniform_shear_max_moment_order(int dimension);

}  // namespace gkt
