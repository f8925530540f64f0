// Navier–Stokes transport of a dilute gas of viscoelastic spheres (3D) as power series in δ':
// the Chapman–Enskog equations of docs/theory.md §10 about the adiabatic homogeneous cooling state,
// with ζ ∝ n T^{1/2 + s/2} and f^(0) depending on T also through δ' ∝ T^{s/2} (theory.md §13.2).
#pragma once

#include <vector>

#include "gkt/operators/viscoelastic_hierarchy.hpp"

namespace gkt {

/// Coefficients of δ'^j, j = 0 … J (J = number of restitution coefficients), of the HCS and the
/// Navier–Stokes coefficients at one Sonine order.
struct ViscoelasticTransportSeries {
  int sonine_order = 0;                        ///< N trial polynomials per mode; the HCS keeps a_2 … a_{N+1}
  std::vector<std::vector<double>> cumulants;  ///< a_k = Σ_j cumulants[k][j] δ'^j, k = 0 … N + 1
  std::vector<double> cooling_rate;            ///< ζ* = ζ/ν0, ν0 = nT/η0 (elastic η0 at the current T)
  /// λ_T = ∂ln ζ/∂ln T = ½ + γ δ'ζ'/ζ (theory.md §13.2); its last coefficient (δ'^J) is not known
  /// and set to 0.
  std::vector<double> cooling_temperature_exponent;
  std::vector<double> shear_viscosity;           ///< η* = η/η0
  std::vector<double> thermal_conductivity;      ///< κ* = κ/κ0
  std::vector<double> density_heat_coefficient;  ///< μ* = nμ/(Tκ0)
};

/// Returns the δ'-series of a_k, ζ*, η*, κ*, μ* at Sonine order N ≥ 1 (N = 1: the first Sonine
/// approximation of [brilliantov2002], HCS truncated at a_2 and kept nonlinear); theory.md (13.8)–(13.11).
/// Throws std::invalid_argument unless 1 ≤ N ≤ 8.
ViscoelasticTransportSeries viscoelastic_transport_series(int sonine_order,
                                                          const ViscoelasticRestitution& restitution = {});

/// a2, ζ*, η*, κ*, μ* and λ_T of the state at one δ', summed from the series.
struct ViscoelasticState {
  /// a2, ζ* = ζ/ν0, η* = η/η0, κ* = κ/κ0 and μ* = nμ/(Tκ0) at the given δ'.
  /// @{
  double a2, cooling_rate, shear_viscosity, thermal_conductivity, density_heat_coefficient;
  /// @}
  double cooling_temperature_exponent;  ///< λ_T, always without its unknown δ'^J term
};

/// Returns the series summed at δ' through δ'^orders (orders < 0: every term).
ViscoelasticState viscoelastic_state(const ViscoelasticTransportSeries& series, double delta_prime, int orders = -1);

/// BP's constants derived from the engine ([brilliantov2002] §3; theory.md (13.3)–(13.7)): ω0 = −ν E^(1)(0,0),
/// ω1 = ν E^(2)(0,0) (μ2 = ω0 δ' − ω1 δ'² + … at a2 = 0), q0 = ω0 2^{1/10}/(16√(2π)) (the T ∝ t^{−5/3}
/// time scale), and the first Sonine series (N = 1, HCS a2 only): a2 = a21 δ' + a22 δ'²,
/// η* = 1 + η̃1 δ' + η̃2 δ'², κ* = 1 + κ̃1 δ' + κ̃2 δ'², μ* = μ̃1 δ' + μ̃2 δ'².
struct ViscoelasticConstants {
  /// ω0 = −ν E^(1)(0,0), ω1 = ν E^(2)(0,0) and q0 = ω0 2^{1/10}/(16√(2π)).
  /// @{
  double omega0, omega1, q0;
  /// @}
  /// a21, a22: the first-Sonine HCS a2 = a21 δ' + a22 δ'².
  /// @{
  double a2_1, a2_2;
  /// @}
  /// η̃1, η̃2: η* = 1 + η̃1 δ' + η̃2 δ'².
  /// @{
  double shear_viscosity_1, shear_viscosity_2;  ///< η̃1 equals BP's printed rational; η̃2 does not (theory.md §13.2)
  /// @}
  /// κ̃1, κ̃2: κ* = 1 + κ̃1 δ' + κ̃2 δ'².
  /// @{
  double thermal_conductivity_1, thermal_conductivity_2;  ///< neither equals BP's printed value (theory.md §13.2)
  /// @}
  /// μ̃1, μ̃2: μ* = μ̃1 δ' + μ̃2 δ'².
  /// @{
  double density_heat_coefficient_1, density_heat_coefficient_2;  ///< μ̃1 equals BP's rational; μ̃2 does not
  /// @}
};

/// Returns the constants for the given restitution series (h_1, h_2 at least).
ViscoelasticConstants viscoelastic_constants(const ViscoelasticRestitution& restitution = {});

}  // namespace gkt
