// The steady uniform shear flow (USF) of smooth inelastic hard disks (d = 2) or spheres (d = 3)
// in Grad's moment approximation f = f_M (1 + (m/(2nT²)) Π_ij V_i V_j), whose collisional moments
// of m V_i V_j are −p ζ_M δ_ij − ν_η Π_ij with the Maxwellian cooling rate ζ_M and the first-Sonine
// shear-mode collision frequency ν_η derived by the engine (docs/theory.md §22, (22.3)–(22.7)).
//
// Units (seed 001 §3.3.1, [goldhirsch2005]; docs/conventions.md "uniform-shear"): reduced shear
// rate γ = a ℓ/√(2T/m), ℓ = 1/(2nσ) (d = 2) or 1/(πnσ²) (d = 3); stresses P_ij/(2nT) (1/2 on the
// diagonal at equilibrium in both dimensions).
#pragma once

namespace gkt {

/// The steady USF at one α in Grad's approximation (docs/theory.md (22.6), (22.7)).
struct UniformShearFlow {
  double cooling_rate = 0;               ///< ζ_M/ν0 (Maxwellian, no a2: Grad's f has none)
  double shear_collision_frequency = 0;  ///< ν_η/ν0 at f_M (1 at α = 1)
  double shear_rate = 0;                 ///< a/ν0(T), ν0 = nT/η0 (docs/conventions.md)
  double reduced_shear_rate = 0;         ///< γ = a ℓ/√(2T/m) (GNB's units)
  /// P_xx/(2nT) and P_yy/(2nT).
  /// @{
  double stress_xx = 0, stress_yy = 0;  ///< P_xx/(2nT), P_yy/(2nT)
  /// @}
  double stress_zz = 0;  ///< P_zz/(2nT) (d = 3; equals stress_yy; 0 in d = 2)
  double stress_xy = 0;  ///< P_xy/(2nT) (< 0 for a > 0)
};

/// Returns the steady USF of Grad's approximation at restitution α for d = 2 or 3 (theory.md
/// (22.6), (22.7)): ζ_M and ν_η are the engine's exact first-Sonine polynomials in α at a2 = 0.
/// Throws std::invalid_argument naming the argument for d ∉ {2, 3} or α outside (0, 1].
UniformShearFlow uniform_shear_flow_grad(int dimension, double alpha);

/// Returns ν0 ℓ/√(2T/m), the factor that turns a/ν0 into GNB's γ = a ℓ/√(2T/m) (theory.md (22.8)):
/// √(π/2) (d = 2), 16/(5√(2π)) (d = 3). Throws std::invalid_argument for d ∉ {2, 3}.
double uniform_shear_length_factor(int dimension);

/// Leading small-ε coefficients of the USF (γ = γ1 √ε + …, P_xy/(2nT) = τ̃_xy √ε + …, ε = 1 − α²).
struct UniformShearLeadingOrder {
  double gamma1 = 0;  ///< γ1
  double tau_xy = 0;  ///< τ̃_xy
};

/// Returns γ1 and τ̃_xy of Chapman–Enskog at Navier–Stokes order (theory.md (22.10)): the exact
/// O(ε) cooling rate ζ*/ε → (d+2)/(4d) and the elastic reduced viscosity η*(α = 1) given by the
/// caller (1 at first Sonine; the converged value reproduces GNB). Throws std::invalid_argument
/// for d ∉ {2, 3} or elastic_viscosity not finite and > 0.
UniformShearLeadingOrder uniform_shear_navier_stokes_limit(int dimension, double elastic_viscosity);

}  // namespace gkt
