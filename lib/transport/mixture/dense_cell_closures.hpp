// The dense (Enskog) mixture's contact values, their density derivatives and the revised-Enskog
// functionals I_ℓij for one state of at most 4 species, in fixed-size arrays (no allocation): the
// same closures as Mixture::contact_values, Mixture::contact_value_derivatives and
// revised_enskog_functionals (lens-centroid closure), for the published first-Sonine closed form
// (docs/theory.md §17.10, §18.1, §18.12).
#pragma once

#include <array>

namespace gkt::detail {

/// One dense state: diameters in units of σ̄ = Σ x_i σ_i, mole fractions, φ.
struct DenseCellGeometry {
  int d = 3, s = 2;
  std::array<double, 4> sigma{}, fraction{};
  double packing_fraction = 0;
};

/// Contact values and derivatives at the state (pairs i·4 + j, derivative triples (i·4 + j)·4 + ℓ).
struct DenseCellClosures {
  std::array<double, 16> chi{};                 ///< χ_ij (theory.md (16.1))
  std::array<double, 64> log_chi_derivative{};  ///< n ∂ln χ_ij/∂n_ℓ at fixed T, n_k (k ≠ ℓ) (18.1)
  std::array<double, 64> functionals{};         ///< I_ℓij (18.18)–(18.20); zero for equal diameters
  double density = 0;                           ///< n σ̄^d = φ/(v_d Σ x_k σ_k^d)
  bool unequal = false;                         ///< whether any I_ℓij may be non-zero
};

/// Returns the closures of `g` (φ > 0; σ_k > 0; x_k summing to 1). I_ℓij by the binary's exact (18.20)
/// or, for s ≥ 3, the lens-centroid closure of §18.12 — equal to revised_enskog_functionals to rounding
/// (the λ integral of (18.17) by Gauss–Legendre rules of 6 to 24 points chosen by φ, the library's 24 at most).
DenseCellClosures dense_cell_closures(const DenseCellGeometry& g);
/// The same written into `out`, which must be value-initialised (zero I_ℓij stay zero): no copy of the arrays.
void dense_cell_closures(const DenseCellGeometry& g, DenseCellClosures& out);

}  // namespace gkt::detail
