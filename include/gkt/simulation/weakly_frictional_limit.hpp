// The weakly frictional, weakly inelastic rough gas in the ordering of Goldhirsch, Noskowicz and
// Bar-Lev (docs/theory.md §19.32): 1 − α² = r η_t with r fixed and η_t = (1+β)κ/(2(1+κ)) → 0.
// The homogeneous cooling state has two branches: for r < r_c the spins are cold (θ = T_r/T_t ~ η_t,
// Maxwellian), for r > r_c hot (θ ~ 1/η_t), and the scaled spin y = w²/⟨w²⟩ then obeys a Fokker–Planck
// equation whose stationary density is y^{d_r/2−1} (b y + c)^μ e^{−λy}: a power-law tail y^{−2−2c0/b}
// cut off at y ~ 1/λ, λ ∝ the hot branch's η_t θ/κ (19.200)–(19.209).
#pragma once

namespace gkt {

/// Leading-order homogeneous cooling state of the GNB ordering (docs/theory.md §19.32, (19.201)–(19.203)).
struct WeaklyFrictionalHcs {
  double critical_ratio = 0;  ///< r_c = 2(d−1)(d/(d_r κ) − 1) of (19.203), the branch boundary in r
  bool hot_spins = false;     ///< r > r_c: θ ~ 1/η_t; otherwise θ ~ η_t
  /// θ/η_t for r < r_c ((19.201), dimensionless), η_t θ/κ = (r − r_c)/(2(d−1)) for r > r_c ((19.202)).
  double scaled_temperature_ratio = 0;
};

/// Returns the leading-order HCS of the GNB ordering 1 − α² = r η_t, η_t → 0, for spheres (d = 3)
/// or disks (d = 2) of reduced moment of inertia κ = 4I/(mσ²) (docs/theory.md §19.32, (19.201)–(19.203));
/// at r = r_c (to 1e−12) neither scaling holds and the function throws; throws std::invalid_argument
/// naming the field on bad input (d ∉ {2, 3}, r < 0 or not finite, κ ∉ (0, 1]).
WeaklyFrictionalHcs weakly_frictional_hcs(int d, double r, double kappa);

/// Moments of the stationary scaled spin y = w²/⟨w²⟩ of the hot branch (docs/theory.md §19.32).
struct WeaklyFrictionalSpinMoments {
  /// ⟨y²⟩ and ⟨y³⟩ (⟨y⟩ = 1; +∞ where the tail makes them diverge).
  /// @{
  double y2 = 0, y3 = 0;
  /// @}
  double drift_slope = 0;  ///< a1 of (19.205) in units of η_t²/κ² per collision, fixed by ⟨y⟩ = 1
};

/// Returns ⟨y²⟩, ⟨y³⟩ of the stationary density (19.207) of the hot branch's Fokker–Planck equation
/// (19.205)–(19.206) for d = 3 or 2 and the cutoff λ ≥ 0 (dimensionless, the rate of e^{−λy}); λ = 0 is
/// the pure power law (19.208), whose ⟨y²⟩ and ⟨y³⟩ are +∞. Quadrature in ln y, relative error below
/// 1e−6 for λ ≥ 0.01; throws std::invalid_argument naming the field on bad input (d, λ < 0 or not finite).
WeaklyFrictionalSpinMoments weakly_frictional_spin_moments(int d, double cutoff);

/// Returns the exponent p of the power-law tail y^{−p} of the scaled spin density at λ = 0 (r → r_c⁺),
/// p = 2 + 2c0/b of (19.208): 21/8 for spheres, 5/2 for disks; throws std::invalid_argument unless d ∈ {2, 3}.
double weakly_frictional_spin_tail_exponent(int d);

}  // namespace gkt
