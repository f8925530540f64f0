// The Enskog collisional-transfer integrals of the tail scheme (docs/theory.md §15.8; [garzo1999] for the
// revised Enskog equation): the σ̂- and angle-integrated kernels at each radial node (c1, c2) of the tail scheme's 2-D
// rule, so that every collisional-transfer table of collisional_transfer.hpp becomes a sum over nodes of φ(c1) × (a
// partner function of c2) × kernel — for any isotropic HCS φ, not only a finite Sonine sum.
#pragma once

#include <cstddef>
#include <vector>

namespace gkt::detail {

/// A node (c1, c2) of the tail scheme's radial rule (speeds in units of v0) and its weight in dc1 dc2.
struct TransferNode {
  double c1 = 0, c2 = 0, weight = 0;
};

/// The per-node families with a test index p = 0 … p_max (test functions of particle 1).
enum TransferFamily {
  kTransferShearSource = 0,   ///< [Y(c1'):(H c2) S_p(X1') − Y(c1):(H c2) S_p(X1)], S_p = S^{(d/2+1)}_p, s = −1
  kTransferHeatSource = 1,    ///< [(H·c1') S_p(X1') − (H·c1) S_p(X1)], S_p = S^{(d/2)}_p, s = −1
  kTransferScalarSource = 2,  ///< (H·c2)[S_p(X1') − S_p(X1)], S_p = S^{(d/2−1)}_p, s = −1
};

/// The per-node values without a test index.
enum TransferValue {
  kTransferShearFlux = 0,    ///< (H·c2)² − H² X2/d, s = −1
  kTransferHeatFlux,         ///< (H·G)(H·c2), G = (c1 + c2)/2, s = −1
  kTransferShearGradient,    ///< H·c2, s = 0
  kTransferHeatGradient,     ///< H·G, s = 0
  kTransferCoolingGradient,  ///< H·c2, s = +1
  kTransferCoolingScalar,    ///< 1, s = +2
  kTransferValues
};

/// The kernels at every node. An entry is ∫ d(angle between c1 and c2) dσ̂ Θ(σ̂·g)(σ̂·g)^{1+s} X times the
/// node's measure (∫d^d c1 d^d c2 = Σ_nodes of isotropic functions), divided by the Maxwellian normalisation
/// N_s = ∫∫ f_M f_M ∫dσ̂ Θ(σ̂·g)^{1+s}: Σ_nodes f_M(c1) f_M(c2) K = the exact ⟨X⟩_s of collisional_transfer.hpp.
/// H = (1+α)(σ̂·g)σ̂, c1' = c1 − ((1+α)/2)(σ̂·g)σ̂, X = c², f_M = π^{−d/2} exp(−c²).
struct TransferKernel {
  int p_max = 0;
  std::vector<double> values;  ///< [node][3 (p_max + 1) + kTransferValues]
  /// Returns the number of doubles per node.
  [[nodiscard]] std::size_t stride() const { return 3 * static_cast<std::size_t>(p_max + 1) + kTransferValues; }
  /// Returns the p_max + 1 values of `family` at `node`.
  [[nodiscard]] const double* family(std::size_t node, TransferFamily f) const {
    return &values[node * stride() + static_cast<std::size_t>(f) * static_cast<std::size_t>(p_max + 1)];
  }
  /// Returns the kTransferValues values at `node`.
  [[nodiscard]] const double* scalars(std::size_t node) const {
    return &values[node * stride() + 3 * static_cast<std::size_t>(p_max + 1)];
  }
};

/// Returns the collisional-transfer kernels for d = 2, 3, α ∈ (0, 1] and tests p ≤ p_max at `nodes`
/// (dimensionless, per unit of the exact Maxwellian averages). 3D: exact Gauss rules in the relative speed
/// g (dμ = g dg/(c1 c2)), in s = ĝ·σ̂ and Gauss–Chebyshev in the azimuth; 2D: the angle between c1 and c2
/// as the tail kernel (θ = η sinh v) and Gauss–Legendre in the angle of σ̂ (the integrands carry odd powers
/// of cos, which a rule in sin cannot integrate exactly). Uses every core for large node sets.
TransferKernel collisional_transfer_kernel(int dimension, double alpha, int p_max,
                                           const std::vector<TransferNode>& nodes);

/// Returns N_s = ∫∫ f_M f_M ∫dσ̂ Θ(σ̂·g)(σ̂·g)^s = B_{1+s} 2^{(1+s)/2} Γ((d+1+s)/2)/Γ(d/2), B_n = ∫dσ̂ Θ(ĝ·σ̂)^n
/// (3D: 2π/(n+1); 2D: √π Γ((n+1)/2)/Γ(n/2 + 1)); dimensionless (velocities in v0).
double transfer_normalisation(int dimension, int power);

}  // namespace gkt::detail
