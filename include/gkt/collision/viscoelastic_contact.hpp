// The dissipative Hertz contact of two viscoelastic spheres and its coefficient of restitution
// ([brilliantov1996]; [schwager1998]; [brilliantov2002] §2): in reduced units the compression x(t)
// obeys
//     x'' + x^{3/2} + β x^{1/2} x' = 0,   x(0) = 0, x'(0) = 1,
// the collision ends when x returns to 0, and ε(β) = −x'(end). β = A κ^{2/5} g^{1/5} is the
// expansion variable of [brilliantov2002] eq. 2.2, ε = 1 − C1 β + C2 β² − C3 β³ + … (docs/theory.md §13).
#pragma once

#include <vector>

namespace gkt {

/// Returns ε(β) for β ≥ 0 (double; the ODE is integrated in the phase plane, rk8pd, relative
/// accuracy ~1e-14). Throws std::invalid_argument for β < 0 or β > 1.
double viscoelastic_contact_restitution(double beta);

/// Returns C1 = Γ(3/5)√π / (2^{1/5} 5^{2/5} Γ(21/10)) = 1.1534489, the first-order coefficient in closed
/// form ([schwager1998]).
double viscoelastic_restitution_c1();

/// Returns c_1 … c_J (J ≤ 4) of ε(β) = 1 + Σ_j c_j β^j: c_1 = −C1 exactly, c_2 … c_J fitted to ε(β)
/// on 24 Chebyshev nodes of β ∈ [0.05, 0.3] (degree 10). Measured accuracy (stability under changes
/// of the switch points, range and degree): c_2 1e-9, c_3 1e-7, c_4 1e-5 relative.
std::vector<double> viscoelastic_restitution_series(int orders);

/// Returns h_1 … h_J (J ≤ 4) of ε = 1 + Σ_j h_j β^j for a given C1: h_1 = −C1, h_2 = (3/5) C1²
/// ([brilliantov2002]; the fit reproduces it to 4e-10), h_j = c_j (C1/C1_exact)^j for j ≥ 3 (the
/// fitted c_j, computed once per process).
std::vector<double> hertz_restitution_coefficients(double c1, int orders);

}  // namespace gkt
