// Bilinear collision moments of anisotropic (Cartesian Hermite) basis functions of one component
// of smooth inelastic hard disks (d = 2) or spheres (d = 3) (docs/theory.md §22.7):
//
//   B(k; i, j) = ∫dc1 dc2 dσ̂ Θ(σ̂·g)(σ̂·g) w(c1) w(c2) ψ_i(c1) ψ_j(c2) [ψ_k(c1') − ψ_k(c1)],
//
// symmetrised in i ↔ j, with w(c) = π^{−d/2} e^{−c²}, c = V/√(2T/m), g = c1 − c2,
// c1' = c1 − ((1+α)/2)(σ̂·g)σ̂ and ψ_n(c) = Π_a h_{n_a}(c_a), h_n = H_n/√(2ⁿ n!) (orthonormal with
// the weight π^{−1/2}e^{−c²}). With f = n (m/2T)^{d/2} w(c) Σ_i x_i ψ_i(c),
// ∫ψ_k J[f, f] dV = n² σ^{d−1} √(2T/m) Σ_ij B(k; i, j) x_i x_j.
//
// The engine's exact Gaussian integrals (collision_moments.hpp, quadratic_form_moments.hpp) give
// rotation-invariant integrands (products of up to four scalar products) only; the component-wise
// moments here are computed in double precision by a product quadrature that is exact for the
// polynomial integrand (theory.md §22.7): Gauss–Hermite in the centre-of-mass velocity,
// generalised Gauss–Laguerre in |g|²/2, exact rules on the sphere for ĝ and for σ̂ about ĝ.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace gkt {

/// The degrees (n_x, n_y, n_z) of one Cartesian Hermite polynomial ψ = h_{n_x}(c_x) h_{n_y}(c_y) h_{n_z}(c_z).
using HermiteIndex = std::array<int, 3>;

/// Returns the Hermite indices of total degree ≤ max_degree (even, ≥ 0) in dimension d (2 or 3;
/// n_z = 0 in 2D) with the symmetry of uniform shear flow u = a y x̂: even under c → −c and under
/// c_z → −c_z (n_x + n_y and n_z even), ordered by degree, then lexicographically; the first is
/// ψ = 1. Throws std::invalid_argument naming the argument otherwise.
std::vector<HermiteIndex> shear_symmetric_hermite_basis(int dimension, int max_degree);

/// Returns h_0(x) … h_n(x) (orthonormal Hermite functions' polynomials) into out[0..n].
void orthonormal_hermite_values(double x, int n, double* out);

/// The tensor B(k; i, j) of one basis at one α (reduced as in the file comment; double precision).
struct CartesianCollisionMoments {
  int dimension = 2;                ///< d (2 or 3)
  double alpha = 1;                 ///< coefficient of normal restitution
  std::vector<HermiteIndex> basis;  ///< ψ_0 … ψ_{K−1}
  std::vector<double> values;       ///< B(k; i, j) at (k·K + i)·K + j (symmetric in i, j)
  /// Returns B(k; i, j).
  [[nodiscard]] double operator()(std::size_t k, std::size_t i, std::size_t j) const {
    const std::size_t n = basis.size();
    return values[(k * n + i) * n + j];
  }
};

/// Returns B(k; i, j) for every k, i, j of `basis` (any Hermite indices of dimension d, n_z = 0 in
/// 2D) at restitution α ∈ (0, 1]; exact up to rounding (the quadrature integrates the polynomial
/// integrand exactly). Cost ∝ K³ × (3p/2 + 1)^d (3p/2)^{d−1} p with p the largest degree.
/// Throws std::invalid_argument naming the argument for d ∉ {2, 3}, α outside (0, 1] or an index
/// outside the dimension.
CartesianCollisionMoments cartesian_collision_moments(int dimension, double alpha,
                                                      const std::vector<HermiteIndex>& basis);

}  // namespace gkt
