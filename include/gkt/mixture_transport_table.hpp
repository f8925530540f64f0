// The Navier–Stokes set of a dilute granular binary for hydrodynamic solvers: built once per pair
// of species and restitution matrix, then evaluated at any state (x_1, n, T) in physical units
// without allocation (docs/theory.md §17.8).
//
// At fixed species and α the reduced coefficients depend on the composition x_1 only; they are
// solved at Chebyshev–Lobatto points of x_1 ∈ [0, 1] (both ends tracer limits) and interpolated
// barycentrically; n and T enter through the reference values η0, κ0, D0, ν0 of the gas (m̄, σ̄).
#pragma once

#include <array>
#include <vector>

#include "gkt/mixture.hpp"

namespace gkt {

/// The Navier–Stokes set of a binary at one state, in the caller's units (mass, length, energy
/// for T, so that velocities are √(T/m)); species indices 0, 1.
struct BinaryTransport {
  double cooling_rate = 0;                    ///< ζ (1/time)
  std::array<double, 2> temperature_ratio{};  ///< T_i/T
  double shear_viscosity = 0;                 ///< η
  double thermal_conductivity = 0;            ///< λ (q = −λ∇T − …)
  std::array<double, 4> mutual_diffusion{};  ///< D_ij at 2i + j (j_i = −Σ_j (m_i m_j n_j/ρ) D_ij ∇ln n_j − …)
  std::array<double, 2> thermal_diffusion{};   ///< D^T_i (j_i ∋ −ρ D^T_i ∇ln T)
  std::array<double, 2> pressure_diffusion{};  ///< D^p_i (j_i ∋ −ρ D^p_i ∇ln p at fixed x, T)
  std::array<double, 2> dufour{};              ///< D''_j (q ∋ −T² D''_j ∇ln n_j)
};

/// Interpolation table of a dilute binary's transport coefficients in the mole fraction x_1.
class BinaryTransportTable {
 public:
  /// Solves the mixture (species masses and diameters as given, fractions ignored; α of `mixture`;
  /// φ must be 0) at `nodes` Chebyshev–Lobatto points x_1 ∈ [0, 1] at Sonine order `order`, and
  /// measures the interpolation error at the midpoints between nodes. Throws std::invalid_argument
  /// on bad input (nodes < 3, order outside [1, 12]).
  BinaryTransportTable(const Mixture& mixture, int order, int nodes = 24);

  /// Returns the coefficients at x_1 ∈ [0, 1], density n > 0 and temperature T > 0 (no allocation).
  [[nodiscard]] BinaryTransport evaluate(double fraction_1, double number_density, double temperature) const;

  /// Returns the largest |interpolated − solved| of the reduced coefficients at the midpoints
  /// between nodes, relative to max(1, |value|): the interpolation error measured at build time.
  [[nodiscard]] double interpolation_error() const { return interpolation_error_; }

 private:
  static constexpr int kReduced = 15;  // ζ*, γ_1, γ_2, η*, λ*, D_ij* (4), D^T_i* (2), D^p_i* (2), D''_j* (2)
  int dimension_;
  std::array<double, 2> mass_{}, diameter_{};
  std::vector<double> nodes_, weights_;               // x_1 at the nodes, barycentric weights
  std::vector<std::array<double, kReduced>> values_;  // reduced set at each node
  double interpolation_error_ = 0;

  [[nodiscard]] std::array<double, kReduced> reduced_at(double fraction_1) const;
  static std::array<double, kReduced> solve(const Mixture& mixture, int order);
};

}  // namespace gkt
