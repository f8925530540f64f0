// Private: the α-independent pieces of the Navier–Stokes Galerkin systems (docs/theory.md
// (10.4)–(10.7), (15.13)), exact; the solver rounds them once, the closed forms keep them exact.
#pragma once

#include <vector>

#include "gkt/algebra/rational.hpp"
#include "gkt/transport/monodisperse/navier_stokes.hpp"

namespace gkt::detail {

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
