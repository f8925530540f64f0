// Private: the interface of the trial families appended after the products in the rough Navier–Stokes systems
// (docs/theory.md (19.49)): their collision elements with the products T_r S_p L_q and with each other, and their
// Maxwellian products. Implemented by the aligned families alone (rough_aligned_families.hpp) and by the aligned
// plus chiral ones (rough_chiral_families.hpp, RoughTrialSpace::full).
#pragma once

namespace gkt::detail {

/// The families beyond the products of one (d, α, β, κ), θ symbolic.
class RoughFamilyElements {
 public:
  virtual ~RoughFamilyElements() = default;
  /// Returns the number of appended functions of rank r.
  [[nodiscard]] virtual int count(int rank) const = 0;
  /// Returns the number of appended functions of rank r up to member level `members` (they come first; every one
  /// where the families have no levels).
  [[nodiscard]] virtual int count_up_to(int rank, int members) const {
    static_cast<void>(members);
    return count(rank);
  }
  /// Returns ⟨φ, 𝓛ψ⟩ at τ = θ/κ for test φ and trial ψ of rank r, each a product (p, q) or, when p < 0, the appended
  /// function number q (1 … count; normalisation of theory.md (5.2)).
  [[nodiscard]] virtual double element(int rank, int p_test, int q_test, int p_trial, int q_trial,
                                       double tau) const = 0;
  /// Returns N = ⟨φ_i · φ_j⟩ of appended functions i, j (1 … count; 0 with every product).
  [[nodiscard]] virtual double maxwell_product(int rank, int i, int j) const = 0;
  /// Returns G = ⟨φ_j C·∂_C φ_i⟩ of appended functions i, j (1 … count).
  [[nodiscard]] virtual double maxwell_scaling_product(int rank, int i, int j) const = 0;
};

}  // namespace gkt::detail
