// Matrix elements of the linearized Boltzmann collision operator of one component of smooth
// hard spheres/disks in a Sonine basis, with the Maxwellian reference f_M (docs/theory.md §5).
//
//   ⟨ψ, 𝓛φ⟩ = −(σ^{d−1}/n) ∫dv1 dv2 dσ̂ Θ(σ̂·g)(σ̂·g) f_M(v1) f_M(v2) [φ(v1) + φ(v2)] [ψ(v1') − ψ(v1)]
//   (weak form of −(J[f_M, f_Mφ] + J[f_Mφ, f_M]); [brilliantov2004] eq. 3.8, [garzo2019] eq. 2.19),
//   tracer (Lorentz) operator: the φ(v1) part only.
//
// Returned as an exact matrix L and a positive prefactor ν such that
//   ⟨ψ_p, 𝓛ψ_q⟩ / (n σ^{d−1} v0) = ν · L(p, q),   v0 = √(2T/m),   ν = √(2π) π^{d/2−1}/Γ(d/2).
#pragma once

#include <vector>

#include "gkt/algebra/dense_matrix.hpp"
#include "gkt/algebra/rational.hpp"
#include "gkt/algebra/rational_polynomial.hpp"
#include "gkt/collision/collision_rule.hpp"

namespace gkt {

/// Which part of the collision operator a matrix represents.
enum class OperatorPart {
  full,    ///< both collision partners perturbed (viscosity, heat conduction)
  tracer,  ///< only the test particle perturbed (self-diffusion)
};

/// Returns the exact matrix L(p, q), p, q = 0..n_max, of the one-component operator for basis
/// functions S_m^(n)(c²) Y_rank(c); Ring = Rational (α numeric) or RationalPolynomial (α symbolic).
template <class Ring>
DenseMatrix<Ring> linearized_operator_matrix(int dimension, const Ring& alpha, OperatorPart part, int rank, int n_max);

/// Returns L^(k)(p, q), k = 0..k_max, p, q = 0..n_max: the operator −(J[φ_k, ·] + J[·, φ_k]) with the
/// reference φ_k = f_M S_{d/2−1}^(k)(c²) in place of f_M, in the basis S_m^(n)(c²) Y_rank(c). The
/// operator about the homogeneous cooling state f0 = f_M Σ_k a_k S_k is Σ_k a_k L^(k) (theory.md
/// §10); L^(0) is linearized_operator_matrix(…, OperatorPart::full, …). Same prefactor ν.
/// With power = s the collision rate carries the extra factor (σ̂·g)^s (moments normalised by
/// J_s0; theory.md (2.9)) — used for velocity-dependent restitution.
template <class Ring>
std::vector<DenseMatrix<Ring>> hcs_linearized_operator_matrices(int dimension, const Ring& alpha, int rank, int n_max,
                                                                int k_max, const Rational& power = Rational(0));

/// The weighted gain − loss moments of one collision pair (species i at v1, j at v2) for a
/// reference f_i, f_j carrying Sonine cumulants (docs/theory.md §17.11), k = 0..k_max, p, q = 0..n_max:
///   self[k](p, q)  = ⟨S_k(X2) ψ_q(c1) · [ψ_p(c1') − ψ_p(c1)]⟩/J0  (the unknown at v1, the partner weighted),
///   cross[k](p, q) = ⟨S_k(X1) ψ_q(c2) · [ψ_p(c1') − ψ_p(c1)]⟩/J0  (the unknown at v2, the test's own species
///   weighted),
/// ψ_n = S_m^(n)(X) Y_rank(c) at each slot's width (X = θu², c = √θ u), S_k = S_{d/2−1}^(k), J0 the
/// pair's reference_collision_integral. One species: L^(k) = −(self[k] + cross[k]).
template <class Ring>
struct WeightedPairOperator {
  /// Per weight index k: the unknown at v1 with the partner weighted by S_k(X2).
  std::vector<DenseMatrix<Ring>> self;
  /// Per weight index k: the unknown at v2 with particle 1 weighted by S_k(X1).
  std::vector<DenseMatrix<Ring>> cross;
};

/// Returns the weighted pair moments above, exact (Ring = Rational or RationalPolynomial in α). The
/// contractions of odd rank need √(θ_iθ_j) rational, as in sonine_collision_moments. Throws
/// std::invalid_argument on a bad rank, n_max or k_max.
template <class Ring>
WeightedPairOperator<Ring> weighted_pair_operator_matrices(const CollisionPair& pair, const Ring& alpha, int rank,
                                                           int n_max, int k_max, const Rational& power = Rational(0));

/// Returns ν = √(2π) π^{d/2−1}/Γ(d/2), the factor between L and ⟨ψ_p, 𝓛ψ_q⟩/(nσ^{d−1}v0).
double linearized_operator_prefactor(int dimension);

/// Explicit instantiation for a numeric α (compiled once in the library).
extern template WeightedPairOperator<Rational> weighted_pair_operator_matrices<Rational>(const CollisionPair&,
                                                                                         const Rational&, int, int, int,
                                                                                         const Rational&);
/// Explicit instantiation for a symbolic α (compiled once in the library).
extern template WeightedPairOperator<RationalPolynomial> weighted_pair_operator_matrices<RationalPolynomial>(
    const CollisionPair&, const RationalPolynomial&, int, int, int, const Rational&);
/// Explicit instantiation for a numeric α (compiled once in the library).
extern template std::vector<DenseMatrix<Rational>> hcs_linearized_operator_matrices<Rational>(int, const Rational&, int,
                                                                                              int, int,
                                                                                              const Rational&);
/// Explicit instantiation for a symbolic α (compiled once in the library).
extern template std::vector<DenseMatrix<RationalPolynomial>> hcs_linearized_operator_matrices<RationalPolynomial>(
    int, const RationalPolynomial&, int, int, int, const Rational&);
/// Explicit instantiation for a numeric α (compiled once in the library).
extern template DenseMatrix<Rational> linearized_operator_matrix<Rational>(int, const Rational&, OperatorPart, int,
                                                                           int);
/// Explicit instantiation for a symbolic α (compiled once in the library).
extern template DenseMatrix<RationalPolynomial> linearized_operator_matrix<RationalPolynomial>(
    int, const RationalPolynomial&, OperatorPart, int, int);

}  // namespace gkt
