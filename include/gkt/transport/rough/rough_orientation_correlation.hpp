// The translation–rotation orientational correlation of the rough-sphere HCS (3D; seed 000,
// [brilliantov2007rough]): C = ⟨(v·ω)²/(v²ω²)⟩ = ⟨cos²Θ⟩, 1/3 without correlation
// (docs/theory.md §19.8). First approximation: Maxwellians at the Maxwellian HCS θ times
// [1 + b P], P = (c·ŵ)² − c²ŵ²/3, with b from the balance of ⟨P⟩; then C = 1/3 + b/5.
#pragma once

#include "gkt/algebra/rational.hpp"

namespace gkt {

/// The correlation and its pieces.
struct RoughOrientationCorrelation {
  double correlation = 1.0 / 3;  ///< C = ⟨cos²Θ⟩
  double b = 0;                  ///< coefficient of P in the distribution
  double temperature_ratio = 1;  ///< the Maxwellian HCS θ used
};

/// Returns C for spheres (d = 3) with α ∈ (0, 1], β ∈ [−1, 1], κ ∈ (0, 1] (std::invalid_argument
/// naming the field otherwise). At β = −1 no correlation is generated: C = 1/3, b = 0, θ = inf.
RoughOrientationCorrelation rough_orientation_correlation(const Rational& alpha, const Rational& beta,
                                                          const Rational& kappa);

}  // namespace gkt
