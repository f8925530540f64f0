// Exact Enskog collisional-transfer moments of one component of smooth inelastic hard spheres
// or disks (docs/theory.md §15): the projections of the gradient part of the Enskog collision
// operator on the Sonine test functions, and the collisional parts of the momentum and heat
// fluxes, all about the homogeneous cooling state f0 = f_M Σ_k a_k S_k (velocities in units of
// v0 = √(2T/m)).
//
// Every entry is an exact moment of H = g − g' = (1+α)(σ̂·g)σ̂ (quadratic_form_moments.hpp),
// stored without the powers of 1/(1+α) that turn H into (σ̂·g)σ̂: the solver applies
// 1/(1+α)^{n_H} (listed per entry) in floating point, where α ∈ (0, 1] keeps it finite.
#pragma once

#include <vector>

#include "gkt/algebra/rational.hpp"
#include "gkt/algebra/rational_polynomial.hpp"

namespace gkt {

/// The collisional-transfer tensors up to Sonine index n_max (vector: S_{d/2}^(p), tensor:
/// S_{d/2+1}^(p)) and HCS weight index k_max. Index order is given per member; D_l(x) =
/// 2(S_l'(x) − S_l(x)), T_l(x) = x S_l − x S_l' − (d/2) S_l are the partner factors of ∂_c φ and
/// −½∂_c·(cφ) (S_l = S_{d/2−1}^(l)); ⟨·⟩_s is the collision average with the extra (σ̂·g)^s,
/// normalised by ⟨(σ̂·g)^s⟩.
template <class Ring>
struct CollisionalTransferMoments {
  /// Spatial dimension d (2 or 3).
  int dimension = 3;
  int n_max = 0;   ///< largest basis index of the flux tables
  int n_test = 0;  ///< largest test index of the source tables (≤ n_max)
  /// HCS weight index K: k, l = 0..K in the tables.
  int k_max = 0;
  /// [p][k][l]: ⟨S_k(X1) D_l(X2) [Y(c1'):(H c2) S_p(X1') − Y(c1):(H c2) S_p(X1)]⟩_{−1}, Y = Y_2, n_H = 1.
  std::vector<Ring> shear_source;
  /// [q][k]: ⟨S_k(X1) S_q(X2) ((H·c2)² − H² X2/d)⟩_{−1} (tensor S_q), n_H = 2.
  std::vector<Ring> shear_flux;
  /// [k][l]: ⟨S_k(X1) D_l(X2) (H·c2)⟩_0, n_H = 1.
  std::vector<Ring> shear_gradient;
  /// [p][k][l]: ⟨S_k(X1) T_l(X2) [(H·c1') S_p(X1') − (H·c1) S_p(X1)]⟩_{−1} (vector S_p), n_H = 1.
  std::vector<Ring> heat_source_temperature;
  /// [p][k][l]: the same with S_l(X2) in place of T_l(X2), n_H = 1.
  std::vector<Ring> heat_source_density;
  /// [q][k]: ⟨S_k(X1) S_q(X2) (H·G)(H·c2)⟩_{−1}, G = (c1 + c2)/2 (vector S_q), n_H = 2.
  std::vector<Ring> heat_flux;
  /// [k][l]: ⟨S_k(X1) T_l(X2) (H·G)⟩_0, n_H = 1.
  std::vector<Ring> heat_gradient_temperature;
  /// [k][l]: ⟨S_k(X1) S_l(X2) (H·G)⟩_0, n_H = 1.
  std::vector<Ring> heat_gradient_density;
  /// [p][k][l]: ⟨S_k(X1) D_l(X2) (H·c2) [S_p(X1') − S_p(X1)]⟩_{−1} (scalar S_p), n_H = 1: the
  /// trace of the ∇u source, which drives the scalar part of f^(1).
  std::vector<Ring> scalar_source;
  /// [k][l]: ⟨S_k(X1) D_l(X2) (H·c2)⟩_{+1}, n_H = 1: the f0 ∂f0 part of the cooling rate.
  std::vector<Ring> cooling_gradient;
  /// [q][k]: ⟨S_k(X1) S_q(X2)⟩_{+2} (scalar S_q): the f0 f^(1) part of the cooling rate.
  std::vector<Ring> cooling_scalar;

  /// Returns the offset of [p][k][l] in a three-index table: (p·(K+1) + k)·(K+1) + l.
  [[nodiscard]] std::size_t index(int p, int k, int l) const {
    return (static_cast<std::size_t>(p) * (k_max + 1) + k) * (k_max + 1) + l;
  }
  /// Returns the offset of [k][l] in a two-index table: k·(K+1) + l.
  [[nodiscard]] std::size_t index(int k, int l) const { return static_cast<std::size_t>(k) * (k_max + 1) + l; }
};

/// Returns the collisional-transfer moments for d = 2, 3 (exact; Ring = Rational for a numeric
/// α, RationalPolynomial for α symbolic): flux tables to basis index n_max, source tables to
/// test index n_test (default, or out of [0, n_max]: n_max).
template <class Ring>
CollisionalTransferMoments<Ring> collisional_transfer_moments(int dimension, const Ring& alpha, int n_max, int k_max,
                                                              int n_test = -1);

/// Returns e_d = n σ^d π^{−d} J_{−1,0}/(n σ^{d−1} v0 ν φ) — the factor that turns a (σ̂·g)^{−1}
/// collision average into a source term of the Galerkin equations per unit packing fraction:
/// 2^{d−1} d (12 in 3D, 4 in 2D; theory.md (15.3)).
double collisional_transfer_factor(int dimension);

/// Returns g_d = c_d² ν √2 π^{(d−1)/2}/(d (d+2)² Γ(d/2)), n σ^d = c_d φ: the factor of the φ²χ
/// (f0 ∂f0) terms of η*, bulk viscosity, κ*, μ* (theory.md (15.8), (15.11)).
double collisional_gradient_factor(int dimension);

/// Explicit instantiation for a numeric α (compiled once in the library).
extern template CollisionalTransferMoments<Rational> collisional_transfer_moments<Rational>(int, const Rational&, int,
                                                                                            int, int);
/// Explicit instantiation for a symbolic α (compiled once in the library).
extern template CollisionalTransferMoments<RationalPolynomial> collisional_transfer_moments<RationalPolynomial>(
    int, const RationalPolynomial&, int, int, int);

}  // namespace gkt
