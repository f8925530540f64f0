// The reference values that reduce every coefficient (docs/conventions.md "Reference values"): a
// one-component elastic gas of mass m and diameter σ at n and T, first approximation of Chapman &
// Cowling. Front ends use them to turn reduced coefficients into physical ones.
#pragma once

#include <cmath>
#include <numbers>

namespace gkt {

/// Returns c_d = π^{(d−1)/2}/Γ(d/2) = K_d/π^d, the geometric factor of every collision rate:
/// (θ_iθ_j)^{d/2} J0_ij π^{−d} = c_d √(1/θ_i + 1/θ_j) (theory.md (16.4)).
inline double geometric_factor(int d) { return std::pow(std::numbers::pi, (d - 1) / 2.0) / std::tgamma(d / 2.0); }

/// Returns v_d = π^{d/2}/(2^d Γ(d/2 + 1)), the volume of a sphere (area of a disk) of unit
/// diameter: φ = n v_d Σ_i x_i σ_i^d.
inline double unit_sphere_volume(int d) {
  return std::pow(std::numbers::pi, d / 2.0) / (std::pow(2.0, d) * std::tgamma(d / 2.0 + 1));
}

/// η0, κ0, D0 and ν0 = nT/η0 of the reference gas, in the caller's units.
struct ReferenceGas {
  double viscosity;            ///< η0 = ((d+2)/(8c_d)) √(mT)/σ^{d−1}
  double conductivity;         ///< κ0 = (d(d+2)/(2(d−1))) η0/m
  double self_diffusion;       ///< D0 = (d/(4c_d)) √(T/m)/(nσ^{d−1})
  double collision_frequency;  ///< ν0 = nT/η0
};

/// Returns the reference values of a gas of mass m and diameter σ at density n and temperature T.
inline ReferenceGas reference_gas(int d, double mass, double diameter, double n, double temperature) {
  const double c = geometric_factor(d), area = std::pow(diameter, d - 1);
  const double eta0 = (d + 2) / (8 * c) * std::sqrt(mass * temperature) / area;
  return {eta0, d * (d + 2) / (2.0 * (d - 1)) * eta0 / mass, d / (4 * c) * std::sqrt(temperature / mass) / (n * area),
          n * temperature / eta0};
}

/// Returns the reference values in the units of theory.md (16.11), n = m = σ = √(2T/m) = 1 and
/// T = 1/2: reference_gas(d, 1, 1, 1, 1/2) with √(mT) = 1/√2 taken exactly.
inline ReferenceGas unit_reference_gas(int d) {
  const double c = geometric_factor(d), root2 = std::sqrt(2.0);
  const double eta0 = (d + 2) / (8 * root2 * c);
  return {eta0, d * (d + 2) / (2.0 * (d - 1)) * eta0, d / (4 * root2 * c), 4 * root2 * c / (d + 2)};
}

}  // namespace gkt
