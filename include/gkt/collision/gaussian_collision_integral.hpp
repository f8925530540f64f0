// The Gaussian collision integral: the closed form from which every matrix element of the
// linearized collision operator follows by Taylor expansion (generating-function method of
// [goldhirsch2005] appendix A, generalised; derivation in docs/theory.md §2).
//
//   J(Q) = ∫ dv1 dv2 dσ̂ Θ(σ̂·g)(σ̂·g) exp(−Σ_ab Q_ab W_a·W_b),   W = (v1, v2, v1', v2'),
//
// with (v1, v2, v1', v2') = T (G, g, g') (collision_rule.hpp) and M = TᵀQT =
// [[A, D, E], [D, B, H], [E, H, C]]:
//
//   J = K_d √A / (N1^{(d−1)/2} N2),   K_d = S_d π^{d−1/2} / 2,   S_d = 2π^{d/2}/Γ(d/2),
//   N1 = A(B + C + 2H) − (D + E)²,    N2 = A(B + α²C − 2αH) − (D − αE)².       (theory.md eq. 2.7)
#pragma once

#include <array>

#include "gkt/collision/collision_rule.hpp"

namespace gkt {

/// 4×4 symmetric coefficient matrix of a quadratic form in (v1, v2, v1', v2').
using QuadraticForm = std::array<std::array<double, 4>, 4>;

/// Returns K_d = S_d π^{d−1/2}/2, the dimension constant of the closed form (d = 2: π^{5/2}; d = 3: 2π^{7/2}).
double gaussian_integral_constant(int dimension);

/// Returns J(Q) in closed form (double precision); requires the form to be integrable
/// (A > 0, N1 > 0, N2 > 0), else throws std::domain_error. Masses enter only as m_i/(m_i+m_j).
double gaussian_collision_integral(int dimension, double mass_i, double mass_j, double alpha, const QuadraticForm& q);

}  // namespace gkt
