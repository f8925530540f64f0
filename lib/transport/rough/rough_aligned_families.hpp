// The lowest trial families of the rough gas's Navier–Stokes modes beyond the translation × spin Sonine products
// (docs/theory.md §19.21): the spin-alignment families built with (ŵŵ)° and c·ŵ (3D; ŵ axial, c·ŵ a pseudoscalar),
//   tensor: T1 = (ŵŵ)°,  T2 = (c·ŵ)(cŵ)°_sym − (ŵ²/3)(cc)°;   vector: F = (ŵŵ)°·c;   scalar: P = (c·ŵ)² − c²ŵ²/3,
// each orthogonal (Maxwellian weights) to every product T_r S_p(c²) L_q(ŵ²), and their exact collision elements with
// the products of order N and with each other. Each element is a polynomial in the ten invariants X_a, Y_a, c_a·ŵ_a,
// X_b, Y_b, c_b·ŵ_b, c_a·c_b, c_a·ŵ_b, ŵ_a·c_b, ŵ_a·ŵ_b of the slot pair (a trial, b test), averaged in the engine with
// the forms coupling v and w ((19.5a)) and θ symbolic. The chiral families (built with c × ŵ) are not here: their
// couplings to the products are single triple products, which no product of the engine's quadratic forms gives.
#pragma once

#include <array>
#include <vector>

#include "gkt/algebra/rational.hpp"
#include "gkt/algebra/rational_polynomial.hpp"
#include "gkt/collision/rough_collision_rule.hpp"
#include "transport/rough/rough_family_elements.hpp"

namespace gkt::detail {

/// The exact collision elements between the aligned-spin families and the products T_r S_p L_q (3D).
class RoughAlignedFamilyElements : public RoughFamilyElements {
 public:
  /// Builds the elements with the products of p + q ≤ K (K − 1 for rank 2), K = highest_order, for the aligned
  /// families times S_p(x) L_q(y), p + q ≤ aligned_order − 1 (1: the four families of (19.48) alone). Throws
  /// std::invalid_argument naming `dimension` for d ≠ 3 (c·ŵ vanishes for disks), `order` for K < 1 and
  /// `aligned_order` below 1.
  RoughAlignedFamilyElements(const RoughCollisionParameters<RationalPolynomial>& parameters, int highest_order,
                             int aligned_order = 1);
  /// Returns the number of aligned functions of rank r: (2 tensor families, 1 vector, 1 scalar) × the members.
  [[nodiscard]] int count(int rank) const override;
  /// Returns ⟨φ, 𝓛ψ⟩ at τ = θ/κ for test φ and trial ψ of rank r, each a product (p, q) or, when p < 0, the aligned
  /// function number q (1 … count; normalisation of theory.md (5.2), as RoughCollisionElements::element).
  [[nodiscard]] double element(int rank, int p_test, int q_test, int p_trial, int q_trial, double tau) const override;
  /// Returns the Maxwellian product N = ⟨φ_i:φ_j⟩ of aligned functions i, j (1 … count) of rank r (exact; 0 with
  /// every product).
  [[nodiscard]] double maxwell_product(int rank, int i, int j) const override;
  /// Returns G = ⟨φ_j C·∂_C φ_i⟩ over the Maxwellians of aligned functions i, j of rank r (the cooling term's G).
  [[nodiscard]] double maxwell_scaling_product(int rank, int i, int j) const override;
  /// Returns K.
  [[nodiscard]] int highest_order() const { return k_; }

 private:
  [[nodiscard]] int index(int rank, int p, int q) const;
  int k_;
  int members_ = 1;  ///< number of (p, q) multipliers of each aligned family
  int shift_ = 0;    ///< every stored element is λ^shift × its value
  /// Per rank, index (test, trial) over [products (p, q), then the aligned functions]: coefficients of λ^j.
  std::array<std::vector<std::vector<long double>>, 3> elements_;
  std::array<std::vector<double>, 3> product_, scaling_;  ///< per rank, (i, j) over the aligned functions
  std::array<int, 3> size_{};
};

}  // namespace gkt::detail
