// The quasi-smooth limit β → −1⁺ of rough spheres and disks at fixed α < 1 (docs/theory.md §19.18).
// With W = η_t w (η_t = (1+β)κ/(2(1+κ)), w = (σ/2)ω) the collision rule (19.2) becomes, as η_t → 0,
//   v1' = v1 − η_n u σ̂ − (W1 + W2) × σ̂,   v2' = v2 + η_n u σ̂ + (W1 + W2) × σ̂,   W' = W + O(η_t),   (19.60)
// so the translation relaxes in O(1) collisions with the spins frozen, while the spins move over
// O(1/η_t) collisions. The slow dynamics contracts every spin at a rate that grows with |W| (a particle
// with a larger spin is kicked harder, so it is hotter and collides more often), and the stationary spin
// distribution is a shell, |W| the same for every particle, directions uniform (§19.18). This file runs
// the fast dynamics (19.60) with every |W| = 1 by DSMC and returns the limit values θη_t², ζ*/η_t, a20
// and the orientation correlation C.
#pragma once

#include <vector>

#include "gkt/simulation/homogeneous_dsmc.hpp"

namespace gkt {

/// Normal restitution α ∈ (0, 1) and reduced moment of inertia κ = 4I/(mσ²) ∈ (0, 1] of the
/// quasi-smooth limit (β → −1⁺; β itself has dropped out of (19.60)).
struct QuasiSmoothLimitParameters {
  /// α ∈ (0, 1) (at α = 1 the kicks heat the translation without loss: no stationary state) and κ.
  /// @{
  double alpha = 0.5, kappa = 0.4;
  /// @}
};

/// One run of the limit dynamics (19.60), per batch: θη_t² = T_r η_t²/T_t (dimensionless), ζ*/η_t with
/// ζ* = ζ/ν0(T_t) (docs/conventions.md) the common cooling rate of both temperatures, the translational
/// cumulant a20, and the orientation correlation C = ⟨(v·W)²/(v²W²)⟩ (d = 3; empty for disks, whose
/// spin is normal to the plane of v).
struct QuasiSmoothLimitRun {
  /// Per batch: θη_t², ζ*/η_t, a20 and C (C for d = 3 only).
  /// @{
  std::vector<double> temperature_ratio_eta_squared, cooling_rate_over_eta, a20, orientation;
  /// @}
};

/// Runs the DSMC of the quasi-smooth limit (19.60) for d = 3 (spheres) or 2 (disks), every particle's
/// spin of the same magnitude and a uniform direction (d = 2: sign); returns the per-batch values of
/// QuasiSmoothLimitRun; throws std::invalid_argument naming the field on bad input (α ∉ (0, 1),
/// κ ∉ (0, 1], d ∉ {2, 3}, a bad schedule).
QuasiSmoothLimitRun run_quasi_smooth_limit_dsmc(int d, const QuasiSmoothLimitParameters& parameters,
                                                const DsmcSchedule& schedule);

/// Returns the spin cumulant a02 = ⟨y²⟩/⟨y²⟩_M − 1 (y = ŵ²) of the quasi-smooth limit, where every
/// spin has the same magnitude: −2/(d_r + 2) with d_r = 3 (d = 3) or 1 (d = 2), i.e. −2/5 and −2/3
/// (docs/theory.md §19.18); throws std::invalid_argument unless d ∈ {2, 3}.
double quasi_smooth_limit_spin_cumulant(int d);

}  // namespace gkt
