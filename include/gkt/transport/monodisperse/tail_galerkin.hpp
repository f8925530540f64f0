// Homogeneous cooling state and Navier–Stokes coefficients of dilute smooth inelastic hard
// spheres (d = 3) and disks (d = 2) in a representation that carries the exponential high-energy tail of the HCS:
// Petrov–Galerkin with Sonine test functions and trial functions w(c) × polynomial in c², where
// w is Gaussian in the core and decays as exp(−A c) with the HCS tail exponent A
// (docs/theory.md §10.6; [vannoije1998] for the tail). It converges at strong dissipation,
// where the Maxwellian-weighted Sonine series of §9–10 is asymptotic.
//
// Reduced as the Sonine solvers: a_k the Sonine cumulants of φ, ζ* = ζ/ν0, η* = η/η0,
// κ* = κ/κ0, μ* = nμ/(Tκ0) (docs/conventions.md), A in units of 1/v0, v0 = √(2T/m).
#pragma once

#include <vector>

#include "gkt/transport/common/enskog_state.hpp"

namespace gkt {

/// Highest resolution (polynomial degree N of the transport modes) the tail scheme accepts; a cost cap
/// (docs/performance.md "Tail scheme"): `tolerance = 1e-4` stops by N ≈ 20 for every α ≥ 0.2, and the row
/// scaling of the linear solves keeps 2D α = 0.2 stable to N = 24 (theory.md §10.6).
inline constexpr int kTailGalerkinMaxOrder = 24;

/// The tail-scheme quantities at one resolution N (dilute, or the Enskog gas of theory.md §15.8).
struct TailGalerkinValues {
  int order = 0;                        ///< N: CE trial/test degree N, HCS degree N + 1 in c²
  bool solved = false;                  ///< false if Newton's method found no HCS at this N
  double a2 = 0;                        ///< Sonine cumulant a2 of the HCS
  double a3 = 0;                        ///< Sonine cumulant a3 of the HCS
  double cooling_rate = 0;              ///< ζ* = ζ/ν0 (dense: χ times the dilute, theory.md (15.1))
  double tail_exponent = 0;             ///< A of φ ~ exp(−A c): 2β/ζ_r, β = π^{(d−1)/2}/Γ((d+1)/2)
  double shear_viscosity = 0;           ///< η* = η/η0
  double thermal_conductivity = 0;      ///< κ* = κ/κ0
  double density_heat_coefficient = 0;  ///< μ* = nμ/(Tκ0)
  double bulk_viscosity = 0;            ///< /η0; zero in the dilute gas (theory.md (15.9))
  double cooling_rate_first_order = 0;  ///< ζ_U of ζ = ζ0 + ζ_U ∇·u (theory.md (15.13)); zero in the dilute gas
};

/// The trial functions of the tail scheme (docs/theory.md §10.6).
enum class TailTrialSpace {
  even,       ///< w(c) × polynomials in c² (10.11): the first tail space (library only; converges slowly)
  power_law,  ///< α < 1: w(c)(1 + c²)^{γ/2} × polynomials in √(4 + c²) − 2, γ the power of the HCS
              ///< tail (10.15), γ − 2 for the vector modes; α = 1: as `even`. Much closer at a given N
              ///< for α ≤ 0.5; `scheme = "tail"` and the shipped tail table.
};

/// Returns the tail-scheme values at resolutions N = 1 … max_order for dimension d = 2 or 3 and
/// restitution α ∈ (0, 1] (element N − 1 is resolution N) with the trial functions `trial`. The
/// collision kernel on the quadrature grid is computed once for max_order (on every core) and shared by
/// all resolutions (each resolution uses the leading Sonine test functions). Throws
/// std::invalid_argument naming the field for d ∉ {2, 3}, α outside (0, 1] or max_order outside
/// [1, kTailGalerkinMaxOrder]. With `dense.packing_fraction` > 0 the values are those of the (revised)
/// Enskog gas at that density (theory.md §15.8): χ-scaled operator and ζ*, the kinetic sources of §15.3 and
/// the collisional transfer of §15.2–15.5 by quadrature over the tail-basis φ; the collisional-transfer
/// kernel is computed once per sequence as the collision kernel.
std::vector<TailGalerkinValues> tail_galerkin_sequence(int dimension, double alpha, int max_order,
                                                       TailTrialSpace trial = TailTrialSpace::even,
                                                       const EnskogState& dense = {});

/// The HCS of the tail scheme at one resolution as a function of the speed, for the tail amplitude
/// (hcs_tail_amplitude.hpp, theory.md §10.7).
struct TailHcsProfile {
  TailGalerkinValues values;         ///< the resolution's values (values.order = N)
  double weight_exponent = 0;        ///< A of the trial weight of the last pass (units 1/v0; ∞ at α = 1)
  std::vector<double> speed;         ///< c (units v0) at the radial quadrature nodes, increasing
  std::vector<double> distribution;  ///< φ_N(c) at those nodes (∫ φ d^d c = 1, ∫ c² φ d^d c = d/2)
};

/// Returns, as tail_galerkin_sequence, the resolutions N = 1 … max_order, each with its HCS φ_N on the
/// radial quadrature nodes of the scheme (the same computation; the vector holds one profile per N).
/// Throws as tail_galerkin_sequence.
std::vector<TailHcsProfile> tail_galerkin_hcs_profiles(int dimension, double alpha, int max_order,
                                                       TailTrialSpace trial = TailTrialSpace::power_law);

/// Returns γ of the HCS tail φ ~ c^γ exp(−A c) (dimensionless; theory.md (10.15)): −d + 2/k in 3D,
/// −d + 1/k in 2D, k = (1 + α)(3 − α)/4. Throws std::invalid_argument for d ∉ {2, 3} or α ∉ (0, 1].
double hcs_tail_power(int dimension, double alpha);

}  // namespace gkt
