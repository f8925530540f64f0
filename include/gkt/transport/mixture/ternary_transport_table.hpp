// The Navier–Stokes set of a granular ternary for hydrodynamic solvers: built once per set of three
// species and restitution matrix, then evaluated at any state (x_1, x_2, n, T) in physical units
// without allocation (docs/theory.md §17.8, "Ternary tables"; dense, φ as a third axis, §18.10).
//
// At fixed species and α the reduced coefficients depend on the two independent fractions only
// (x_3 = 1 − x_1 − x_2). The triangle x_1, x_2 ≥ 0, x_1 + x_2 ≤ 1 is the image of the square
// (u, v) ∈ [0, 1]² under the collapsed (Duffy) map x_1 = u, x_2 = (1 − u) v, x_3 = (1 − u)(1 − v)
// ([duffy1982]); the coefficients are solved on a tensor grid of Chebyshev–Lobatto points in u and v
// and interpolated barycentrically ([berrut2004]), on rectangles of the square split until a requested
// accuracy holds at every point checked. A dense table adds Chebyshev–Lobatto points of φ ∈ [0, φ_max].
#pragma once

#include <array>
#include <vector>

#include "gkt/transport/common/chebyshev_axis.hpp"
#include "gkt/transport/mixture/mixture.hpp"
#include "gkt/transport/mixture/mixture_cooling_state.hpp"

namespace gkt {

/// The Navier–Stokes set of a ternary at one state, in the caller's units (mass, length, energy for
/// T); species indices 0, 1, 2; matrices row-major (i, j at 3i + j).
struct TernaryTransport {
  double cooling_rate = 0;                    ///< ζ (1/time)
  std::array<double, 3> temperature_ratio{};  ///< T_i/T
  double shear_viscosity = 0;                 ///< η
  double thermal_conductivity = 0;            ///< λ (q = −λ∇T − …)
  std::array<double, 9> mutual_diffusion{};  ///< D_ij at 3i + j (j_i = −Σ_j (m_i m_j n_j/ρ) D_ij ∇ln n_j − …)
  std::array<double, 3> thermal_diffusion{};   ///< D^T_i (j_i ∋ −ρ D^T_i ∇ln T)
  std::array<double, 3> pressure_diffusion{};  ///< D^p_i (j_i ∋ −ρ D^p_i ∇ln p at fixed x, T)
  std::array<double, 3> dufour{};              ///< D''_j (q ∋ −T² D''_j ∇ln n_j)
  double pressure = 0;                         ///< p (energy/volume; nT when dilute)
  double bulk_viscosity = 0;                   ///< κ (P ∋ −κ I ∇·u; 0 when dilute)
  double cooling_rate_first_order = 0;         ///< ζ_U (ζ = ζ0 + ζ_U ∇·u; dimensionless, 0 when dilute)
};

/// Interpolation table of a ternary's transport coefficients on the composition triangle (and, dense,
/// in φ) (docs/theory.md §17.8, §18.10): piecewise tensor Chebyshev–Lobatto interpolation in the Duffy
/// square (× φ), adapted at build until a requested accuracy holds at every point checked, or refused.
class TernaryTransportTable {
 public:
  /// Solves the ternary (species masses, diameters and the restitution matrix α_ij of `mixture`; its
  /// fractions are ignored) at Sonine order `order` on nodes × nodes Chebyshev–Lobatto points of the
  /// Duffy square — and, if max_packing_fraction > 0 (a dense table; the mixture's φ is then ignored),
  /// on packing_nodes points φ ∈ [0, max_packing_fraction] — and measures the interpolation error at
  /// every pair (triple) of angular midpoints. While that error exceeds `tolerance` every axis is
  /// refined, K → 2K − 1 (the midpoints become nodes), up to `max_nodes` per axis; past that the square
  /// is split into four, each quarter with `nodes` × `nodes` points (and the φ nodes reached), recursively. A piece
  /// that meets the tolerance is then checked against direct solves at independent off-node points (angles a third of
  /// the way between every other pair of nodes) and split too if it misses there. Throws std::invalid_argument on bad
  /// input (a mixture that is not 3 species, fails Mixture::validate or, for a dilute table, has packing_fraction ≠ 0;
  /// nodes or packing_nodes outside [3, 33], max_nodes outside [nodes, 33], order outside [1, 12], tolerance outside
  /// (0, 1], max_packing_fraction outside [0, φ limit)) and when splitting no longer helps (a piece narrower than 2^-8
  /// or whose error four successive splits did not halve): the one-line message names the error reached, the point
  /// (x_1, x_2) and the region of x_1 and x_2/(1 − x_1) (and φ, dense) (e.g. around a pole of the order-N solution).
  /// `reference` is the f^(0) every node is solved about, as BinaryTransportTable's (theory.md §17.14).
  TernaryTransportTable(const Mixture& mixture, int order, int nodes = 9, double tolerance = 1e-3, int max_nodes = 33,
                        double max_packing_fraction = 0, int packing_nodes = 5, MixtureReference reference = {});

  /// Returns the coefficients at x_1, x_2 ≥ 0 with x_1 + x_2 ≤ 1 (x_3 = 1 − x_1 − x_2), density
  /// n > 0 and temperature T > 0 (no allocation); every value is nan if φ = n v_d Σ x_i σ_i^d exceeds
  /// the table's φ_max (0 for a dilute table, which treats any n as dilute). Throws std::invalid_argument naming the
  /// argument when a fraction, n or T is outside its range or not finite, or when the coefficients at (n, T) over- or
  /// underflow a double.
  [[nodiscard]] TernaryTransport evaluate(double fraction_1, double fraction_2, double number_density,
                                          double temperature) const;

  /// Returns the coefficients at (x_1, x_2) and packing fraction φ (0 for a dilute table) reduced as
  /// docs/conventions.md (ζ*, T_i/T, η*, λ*, D_ij*, D^T_i*, D^p_i*, D''_j*, p*, κ/η0, ζ_U) by the reference
  /// gas of m̄ = Σ x_i m_i, σ̄ = Σ x_i σ_i; refuses fractions as evaluate does and φ outside [0, φ_max]
  /// naming packing_fraction (no allocation).
  [[nodiscard]] TernaryTransport evaluate_reduced(double fraction_1, double fraction_2,
                                                  double packing_fraction = 0) const;

  /// Returns the largest |interpolated − solved| of the reduced coefficients, relative to
  /// max(1, |value|), over every point checked at build time (midpoints and validation points; at
  /// most the constructor's tolerance).
  [[nodiscard]] double interpolation_error() const { return interpolation_error_; }
  /// Returns the same error measured at the independent validation points alone.
  [[nodiscard]] double validation_error() const { return validation_error_; }
  /// Returns the number of rectangles of the Duffy square (pieces) the build settled on.
  [[nodiscard]] int pieces() const { return static_cast<int>(pieces_.size()); }
  /// Returns the largest number of nodes per axis of a piece after refinement.
  [[nodiscard]] int nodes_per_axis() const;
  /// Returns the largest number of φ nodes of a piece after refinement (1 for a dilute table).
  [[nodiscard]] int packing_nodes() const;
  /// Returns the table's φ_max (0 for a dilute table).
  [[nodiscard]] double max_packing_fraction() const { return max_packing_; }
  /// Returns the number of direct mixture solves the build made (nodes, midpoints, validation).
  [[nodiscard]] int build_solves() const { return build_solves_; }
  /// Returns the wall-clock time of the build in seconds.
  [[nodiscard]] double build_seconds() const { return build_seconds_; }
  /// Returns the f^(0) the nodes were solved about (the constructor's reference).
  [[nodiscard]] const MixtureReference& reference() const { return reference_; }

 private:
  // ζ*, γ_i (3), η*, λ*, D_ij* (9), D^T_i* (3), D^p_i* (3), D''_j* (3), p*, κ/η0, ζ_U
  static constexpr int kReduced = 27;
  static constexpr int kMaxNodes = 33;  // per axis: evaluate() keeps its factors on the stack
  using Reduced = std::array<double, kReduced>;
  using Axis = ChebyshevAxis;
  /// One rectangle of the Duffy square (× [0, φ_max]): its axes and values (at φ node c, v node a, u node b:
  /// (c · K_v + a) · K_u + b).
  struct Piece {
    Axis u_axis, v_axis, packing_axis;
    std::vector<Reduced> values;
    [[nodiscard]] Reduced reduced_at(double u, double v, double phi) const;
  };
  /// A node of the quadtree over the square: a leaf holds a piece, an inner node four children
  /// (first child at `child`, ordered by (v half, u half)) split at (u_split, v_split).
  struct Cell {
    int piece = -1, child = -1;
    double u_split = 0, v_split = 0;
  };
  int dimension_;
  std::array<double, 3> mass_{}, diameter_{}, species_volume_{};  // species_volume_: v_d σ_i^d
  double max_packing_ = 0;
  std::vector<Piece> pieces_;
  std::vector<Cell> tree_;  // tree_[0] is the whole square
  double interpolation_error_ = 0, validation_error_ = 0;
  double reduced_bound_ = 0;  // bounds every interpolated |reduced value| (evaluate's overflow check)
  int build_solves_ = 0;
  double build_seconds_ = 0;
  MixtureReference reference_;

  /// Returns the interpolated reduced set at (x_1, x_2, φ), refusing fractions off the triangle.
  [[nodiscard]] Reduced reduced(double fraction_1, double fraction_2, double phi) const;
  static Reduced solve(const Mixture& mixture, int order, const MixtureReference& reference);
};

}  // namespace gkt
