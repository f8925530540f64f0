// Sonine moments of the nonlinear (bilinear) Boltzmann collision operator of one component of
// smooth inelastic hard spheres/disks (docs/theory.md §9):
//
//   T(p; k, l) = ⟨S_k(X1) S_l(X2) [S_p(X1') − S_p(X1)]⟩ / J0,
//   E(k, l)    = ⟨S_k(X1) S_l(X2) [X1' − X1]⟩ / J0            (energy moment),
//
// X = c², S_n = S_{d/2−1}^(n), ⟨·⟩ as in collision_moments.hpp with θ = 1 (velocities in units
// of v0 = √(2T/m)). With f = f_M Σ_k a_k S_k, ∫ψ J[f, f] = ν Σ a_k a_l (moment) (theory.md (5.3)).
#pragma once

#include <vector>

#include "gkt/algebra/rational.hpp"
#include "gkt/algebra/rational_polynomial.hpp"

namespace gkt {

/// The tensors T(p; k, l), p, k, l = 0..K, and E(k, l), exact in Ring.
template <class Ring>
struct BilinearCollisionMoments {
  /// Spatial dimension d (2 or 3).
  int dimension = 3;
  /// The largest Sonine index K.
  int k_max = 0;
  std::vector<Ring> sonine;     ///< T(p; k, l) at (p·(K+1) + k)·(K+1) + l
  std::vector<Ring> energy;     ///< E(k, l) at k·(K+1) + l
  std::vector<Ring> frequency;  ///< C(k, l) = ⟨S_k(X1) S_l(X2)⟩/J0 (collision rate) at k·(K+1) + l
  /// Returns T(p; k, l) (exact).
  [[nodiscard]] const Ring& t(int p, int k, int l) const {
    return sonine[(static_cast<std::size_t>(p) * (k_max + 1) + k) * (k_max + 1) + l];
  }
  /// Returns E(k, l) (exact).
  [[nodiscard]] const Ring& e(int k, int l) const { return energy[static_cast<std::size_t>(k) * (k_max + 1) + l]; }
};

/// Returns the bilinear collision moments up to Sonine index k_max; Ring = Rational (α a
/// number) or RationalPolynomial (α symbolic).
template <class Ring>
BilinearCollisionMoments<Ring> bilinear_collision_moments(int dimension, const Ring& alpha, int k_max);

/// Explicit instantiation for a numeric α (compiled once in the library).
extern template BilinearCollisionMoments<Rational> bilinear_collision_moments<Rational>(int, const Rational&, int);
/// Explicit instantiation for a symbolic α (compiled once in the library).
extern template BilinearCollisionMoments<RationalPolynomial> bilinear_collision_moments<RationalPolynomial>(
    int, const RationalPolynomial&, int);

}  // namespace gkt
