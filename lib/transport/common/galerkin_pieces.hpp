// Private: the α-independent pieces of the Navier–Stokes Galerkin systems (docs/theory.md
// (10.4)–(10.7), (15.13)), exact; the solver rounds them once, the closed forms keep them exact.
#pragma once

#include <vector>

#include "gkt/algebra/rational.hpp"

namespace gkt::detail {

/// The α-independent pieces of one mode's Galerkin system (theory.md (10.4)–(10.7)): exact
/// (T = Rational, for the closed forms) or rounded to double (the solver).
template <class T>
struct GalerkinPieces {
  std::vector<std::vector<T>> d, m;        ///< D(p, q), M(p, q)
  std::vector<std::vector<T>> u, u2;       ///< source projections per HCS weight S_k (u2: density)
  std::vector<std::vector<T>> u_pressure;  ///< ⟨((d/2)S_p + xS_p') S_k⟩: the part ∝ p* (vector)
  std::vector<T> flux;                     ///< ⟨x² S_q⟩
  /// product[k](q, r) = ⟨w S_k S_q S_r⟩/⟨w S_r²⟩ (w the mode's weight; S_k scalar index), the
  /// expansion of S_k S_q in the mode's basis (modified scheme, theory.md (10.9)).
  std::vector<std::vector<std::vector<T>>> product;
};

/// Returns product[k][q][r] = ⟨x^rank S_k S_q S_r⟩/⟨x^rank S_r²⟩ (S_k of index d/2 − 1, S_q, S_r of
/// the mode's index): S_k S_q = Σ_r product[k][q][r] S_r (theory.md (10.9)), exact.
std::vector<std::vector<std::vector<Rational>>> exact_product_table(int d, int rank, int n_max, int k_max);

/// Returns the heat and density modes' pieces (basis c S_p, p = 0 … n_max; HCS weights to k_max).
GalerkinPieces<Rational> vector_pieces(int d, int n_max, int k_max);
/// Returns the shear mode's pieces (basis Y_2(c) S_p).
GalerkinPieces<Rational> tensor_pieces(int d, int n_max, int k_max);
/// Returns the ∇·u (scalar) mode's pieces of the dense gas: d = D⁰(p, q) = −½⟨S_q(2xS_p' − S_p)⟩,
/// u = ⟨x S_p' S_k⟩ (the source per unit of ζ_U − (2/d)(1 − p*); theory.md (15.13)).
GalerkinPieces<Rational> scalar_pieces(int d, int n_max, int k_max);

/// Returns the pieces rounded to double.
GalerkinPieces<double> rounded(const GalerkinPieces<Rational>& exact);

}  // namespace gkt::detail
