// The first-Sonine Navier–Stokes systems of rough spheres and disks with the lowest aligned and chiral trial families
// (docs/theory.md §19.21, §19.22), every collision element exact (θ symbolic, λ = √(θ/κ)):
//   tensor: (cc)°, (ŵŵ)°, (c·ŵ)(cŵ)° − (ŵ²/3)(cc)°, (c(c × ŵ))_sym, (c·ŵ)(ŵ(c × ŵ))_sym   (3D);  (cc)°, ŵ(c c⊥)_sym
//   (2D); vector: c(x − (d+2)/2), c(y − d_r/2), (ŵŵ)°·c, c × ŵ   (3D);   c(x − 2), c(y − 1/2), ŵ c⊥   (2D); scalar: x −
//   d/2, y − d_r/2, (c·ŵ)² − xy/3 (3D),
// the families of gkt_rough_trial_families_mc in its order. Each element contracts to a polynomial in the ten dot
// products of the slot pair and at most one triple product (two reduce to dot products by the Gram determinant,
// (19.94)); the dot products average in RoughCollisionMoments, the triple products in RoughTripleProductMoments.
#pragma once

#include <array>
#include <vector>

#include "gkt/algebra/rational.hpp"
#include "gkt/algebra/rational_polynomial.hpp"
#include "transport/rough/rough_family_elements.hpp"

namespace gkt::detail {

/// Exact collision elements, Maxwellian products and scaling products of the first-Sonine families with the lowest
/// aligned and chiral members; or (second constructor) of the products of order N, the aligned members and the lowest
/// chiral families (RoughTrialSpace::full).
class RoughChiralFamilyElements : public RoughFamilyElements {
 public:
  /// Builds every element for d = 2 or 3 at restitutions α, β and κ. Throws std::invalid_argument naming
  /// `dimension` unless d ∈ {2, 3}, and `alpha`, `beta`, `kappa` outside (0, 1], [−1, 1], (0, ∞).
  RoughChiralFamilyElements(int dimension, const Rational& alpha, const Rational& beta, const Rational& kappa);
  /// Builds the functions of RoughTrialSpace::full: the products T_r S_p L_q of p + q ≤ K (K − 1 for rank 2), then,
  /// member level m = 1 … aligned_order in turn, (3D) the aligned families of (19.48) and the lowest chiral families
  /// each times S_p L_q of p + q = m − 1 (theory.md (19.150)) and (3D) (cc)° P, c P (P = (c·ŵ)² − xy/3) times S_p L_q
  /// of p + q = m − 2 ((19.152)); only the elements with an appended function are computed. Throws
  /// std::invalid_argument naming `dimension`, `order` (K < 1) or `aligned_order` (< 1).
  RoughChiralFamilyElements(int dimension, const Rational& alpha, const Rational& beta, const Rational& kappa,
                            int highest_order, int aligned_order);
  /// Returns the number of functions of rank r (0 scalar, 1 vector, 2 tensor), products included.
  [[nodiscard]] int size(int rank) const;
  /// Returns the number of appended (aligned and chiral) functions of rank r.
  [[nodiscard]] int count(int rank) const override;
  /// Returns element(rank, i, j, τ) with products (p, q) and appended functions (p < 0, q = 1 … count) as indices.
  [[nodiscard]] double element(int rank, int p_test, int q_test, int p_trial, int q_trial, double tau) const override;
  /// Returns maxwell_product of appended functions i, j (1 … count).
  [[nodiscard]] double maxwell_product(int rank, int i, int j) const override;
  /// Returns maxwell_scaling_product of appended functions i, j (1 … count).
  [[nodiscard]] double maxwell_scaling_product(int rank, int i, int j) const override;
  /// Returns the number of appended functions of rank r with member level m ≤ members (they come first).
  [[nodiscard]] int count_up_to(int rank, int members) const override;
  /// Returns true when family i of rank r is chiral (odd in ŵ: built with c × ŵ, resp. ŵ c⊥).
  [[nodiscard]] bool chiral(int rank, int i) const;
  /// Returns ⟨φ_test, 𝓛 φ_trial⟩ = ⟨(φ_trial(1) + φ_trial(2)) · (φ_test(1) − φ_test(1'))⟩/⟨1⟩ at τ = θ/κ
  /// (dimensionless, the normalisation of gkt_rough_trial_families_mc; indices 0 … count − 1).
  [[nodiscard]] double element(int rank, int test, int trial, double tau) const;
  /// Returns the Maxwellian product N_ij = ⟨φ_i · φ_j⟩ (exact; indices 0 … size − 1).
  [[nodiscard]] double maxwell_product_at(int rank, int i, int j) const;
  /// Returns G_ij = ⟨φ_j · C·∂_C φ_i⟩ over the Maxwellians (exact; indices 0 … size − 1).
  [[nodiscard]] double maxwell_scaling_product_at(int rank, int i, int j) const;

 private:
  [[nodiscard]] std::size_t at(int rank, int i, int j) const;
  [[nodiscard]] int function_index(int rank, int p, int q) const;
  int dimension_;
  int highest_order_ = 0;          ///< K of the products (0: the tool's list)
  std::array<int, 3> products_{};  ///< number of products per rank (0 for the tool's list)
  std::array<int, 3> count_{};
  std::array<std::vector<bool>, 3> chiral_;
  std::array<std::vector<int>, 3> level_;  ///< member level of each appended function (full space)
  int shift_ = 0;                          ///< every stored element is λ^shift × its value
  /// Per rank, (test, trial): the rational part and the part times √(π/2), polynomials in λ.
  std::array<std::vector<RationalPolynomial>, 3> even_, odd_;
  std::array<std::vector<double>, 3> product_, scaling_;
};

}  // namespace gkt::detail
