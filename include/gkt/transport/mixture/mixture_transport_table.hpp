// The Navier–Stokes set of a granular binary for hydrodynamic solvers: built once per pair of
// species and restitution matrix, then evaluated at any state (x_1, n, T) in physical units
// without allocation (docs/theory.md §17.8, dense §18.10).
//
// At fixed species and α the reduced coefficients depend on the composition x_1 and, in the dense
// gas, on the packing fraction φ only; they are solved at Chebyshev–Lobatto points of x_1 ∈ [0, 1]
// (both ends tracer limits) and, for a dense table, of φ ∈ [0, φ_max], and interpolated
// barycentrically (tensor product); n and T enter through φ = n v_d Σ x_i σ_i^d and the reference
// values η0, κ0, D0, ν0 of the gas (m̄, σ̄).
#pragma once

#include <array>
#include <vector>

#include "gkt/transport/common/chebyshev_axis.hpp"
#include "gkt/transport/mixture/mixture.hpp"
#include "gkt/transport/mixture/mixture_cooling_state.hpp"

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
  double pressure = 0;                         ///< p (energy/volume; nT when dilute)
  double bulk_viscosity = 0;                   ///< κ (P ∋ −κ I ∇·u; 0 when dilute)
  double cooling_rate_first_order = 0;         ///< ζ_U (ζ = ζ0 + ζ_U ∇·u; dimensionless)
};

/// Interpolation table of a binary's transport coefficients in the mole fraction x_1 (and φ):
/// piecewise Chebyshev–Lobatto interpolation on subintervals of x_1 ∈ [0, 1], adapted at build
/// until a requested accuracy holds at every point checked (docs/theory.md §17.8).
class BinaryTransportTable {
 public:
  /// Solves the mixture (species masses and diameters as given, fractions and φ ignored; α of
  /// `mixture`) at Sonine order `order` on `nodes` Chebyshev–Lobatto points x_1 ∈ [0, 1] — and, if
  /// max_packing_fraction > 0, on packing_nodes points φ ∈ [0, max_packing_fraction] — and measures
  /// the interpolation error at the angular midpoints between the nodes. While that error exceeds
  /// `tolerance` every axis is refined, K → 2K − 1 nodes (the points where the error was measured
  /// become nodes), up to 64 nodes per axis; past 64 the x_1 interval is bisected, each half with
  /// `nodes` points in x_1 (and the φ nodes reached), recursively. A piece that meets the tolerance
  /// is then checked against direct solves at an independent set of off-node points (angles a third
  /// of the way between nodes) and bisected too if it misses there. Throws std::invalid_argument on
  /// bad input (nodes or packing_nodes outside [3, 64], order outside [1, 12], max_packing_fraction
  /// outside [0, φ limit), tolerance outside (0, 1]), on a mixture that fails Mixture::validate, and
  /// when bisection no longer helps (a piece narrower than 2^-10 or whose error three successive
  /// bisections did not halve): the one-line message names the error reached, where, and the x_1
  /// interval (e.g. around a pole of the order-N solution). `fraction_range` [x_low, x_high] ⊆ [0, 1]
  /// (x_low < x_high) limits the table to those compositions (a table below a pole; evaluate then
  /// refuses x_1 outside it); bad ranges are refused naming fraction_range. `reference` is the f^(0) every
  /// node is solved about (theory.md §17.11; §17.14 "Tables about the cumulant HCS"): the Maxwellian (the
  /// default, GDH's) or the HCS of reference.scheme with a_2 … a_K, K = reference.hcs_order; the tolerance
  /// is enforced the same way, against direct solves about that reference.
  BinaryTransportTable(const Mixture& mixture, int order, int nodes = 24, double max_packing_fraction = 0,
                       int packing_nodes = 12, double tolerance = 1e-3,
                       std::array<double, 2> fraction_range = {0.0, 1.0}, MixtureReference reference = {});

  /// Returns the coefficients at x_1 ∈ fraction_range ([0, 1] by default), density n > 0 and temperature T > 0 (no
  /// allocation); every value is nan if φ = n v_d Σ x_i σ_i^d exceeds the table's φ_max (0 for a dilute table, which
  /// treats any n as dilute). Throws std::invalid_argument naming the argument when x_1, n or T is outside its range or
  /// not finite, or when the coefficients at (n, T) over- or underflow a double.
  [[nodiscard]] BinaryTransport evaluate(double fraction_1, double number_density, double temperature) const;

  /// Returns the largest |interpolated − solved| of the reduced coefficients, relative to
  /// max(1, |value|), over every point checked at build time: the angular midpoints between nodes
  /// (dense: every pair of midpoints in x_1 and φ) and the independent validation points (at most
  /// the constructor's tolerance).
  [[nodiscard]] double interpolation_error() const { return interpolation_error_; }
  /// Returns the same error measured at the independent validation points alone (never used to
  /// place nodes).
  [[nodiscard]] double validation_error() const { return validation_error_; }

  /// Returns the number of distinct nodes in x_1 over all pieces after refinement.
  [[nodiscard]] int fraction_nodes() const;
  /// Returns the largest number of nodes in φ of a piece after refinement (1 for a dilute table).
  [[nodiscard]] int packing_nodes() const;
  /// Returns the compositions [x_low, x_high] the table covers.
  [[nodiscard]] std::array<double, 2> fraction_range() const { return fraction_range_; }
  /// Returns the number of x_1 subintervals (pieces) the build settled on (1 without bisection).
  [[nodiscard]] int intervals() const { return static_cast<int>(pieces_.size()); }
  /// Returns the number of direct mixture solves the build made (nodes, midpoints, validation).
  [[nodiscard]] int build_solves() const { return build_solves_; }
  /// Returns the wall-clock time of the build in seconds.
  [[nodiscard]] double build_seconds() const { return build_seconds_; }
  /// Returns the f^(0) the nodes were solved about (the constructor's reference).
  [[nodiscard]] const MixtureReference& reference() const { return reference_; }

 private:
  // ζ*, γ_1, γ_2, η*, λ*, D_ij* (4), D^T_i* (2), D^p_i* (2), D''_j* (2), p*, κ*, ζ_U
  static constexpr int kReduced = 18;
  static constexpr int kMaxNodes = 64;  // per axis: evaluate() keeps its factors on the stack
  using Reduced = std::array<double, kReduced>;
  using Axis = ChebyshevAxis;
  /// One x_1 subinterval: its axes and values (at packing node a, fraction node b: a · nodes + b).
  struct Piece {
    Axis fraction_axis, packing_axis;
    std::vector<Reduced> values;
    [[nodiscard]] Reduced reduced_at(double fraction_1, double packing) const;
  };
  int dimension_;
  std::array<double, 2> mass_{}, diameter_{}, species_volume_{};  // species_volume_: v_d σ_i^d
  double max_packing_ = 0;
  std::array<double, 2> fraction_range_{0.0, 1.0};
  std::vector<Piece> pieces_;   // ordered in x_1
  std::vector<double> breaks_;  // the pieces' upper ends but the last (evaluate's search)
  double interpolation_error_ = 0, validation_error_ = 0;
  double reduced_bound_ = 0;  // bounds every interpolated |reduced value| (evaluate's overflow check)
  int build_solves_ = 0;
  double build_seconds_ = 0;
  MixtureReference reference_;

  static Reduced solve(const Mixture& mixture, int order, const MixtureReference& reference);
};

}  // namespace gkt
