// Elastic hard spheres (d = 3) and hard disks (d = 2), dilute: shear viscosity, thermal
// conductivity and self-diffusion at any Sonine order, exact (docs/theory.md §5–6).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "gkt/algebra/dense_matrix.hpp"
#include "gkt/algebra/rational.hpp"
#include "gkt/transport/common/sonine_solution.hpp"

namespace gkt {

/// The transport coefficients of the elastic hard-sphere gas.
enum class HardSphereCoefficient { shear_viscosity = 0, thermal_conductivity = 1, self_diffusion = 2 };

/// Highest Sonine order the hard-sphere solver accepts (the error estimate uses two more, three where the
/// changes change sign: docs/theory.md (6.3)).
inline constexpr int kHardSphereMaxOrder = 40;

/// Sonine matrices of the elastic hard-sphere operator for one dimension, built once to the
/// highest order asked for and reused (orders are nested: order N uses the leading block).
class HardSphereSonineSystem {
 public:
  /// Throws std::invalid_argument unless dimension is 2 or 3.
  explicit HardSphereSonineSystem(int dimension);

  /// Returns the reduced coefficient (η/η0, κ/κ0 or D/D0, PHYSICS conventions) at Sonine
  /// order `order` (number of Sonine polynomials, 1 = first approximation), exact.
  Rational reduced_coefficient(HardSphereCoefficient c, int order);

  /// Returns the value at `order` with its estimated truncation error (6.3) of docs/theory.md §6 (uses orders
  /// +1, +2, and +3 where the changes change sign).
  TruncationEstimate estimate(HardSphereCoefficient c, int order);

  /// Returns the spatial dimension d.
  [[nodiscard]] int dimension() const { return dimension_; }

 private:
  void ensure_built(std::size_t coefficient, int n_max);
  int dimension_;
  std::array<int, 3> built_{-1, -1, -1};  // largest Sonine index in each matrix
  std::array<DenseMatrix<Rational>, 3> matrices_;
  std::array<std::vector<Rational>, 3> values_;                              // values_[c][N-1], filled lazily
  std::array<std::vector<std::optional<TruncationEstimate>>, 3> estimates_;  // estimates_[c][N-1]
};

/// Returns η0 = ((d+2)Γ(d/2)/(8π^{(d−1)/2})) σ^{1−d} √(mT), the elastic first-Sonine viscosity.
double reference_shear_viscosity(int dimension, double mass, double temperature, double diameter);
/// Returns κ0 = (d(d+2)/(2(d−1))) η0/m (k_B = 1), the elastic first-Sonine thermal conductivity.
double reference_thermal_conductivity(int dimension, double mass, double temperature, double diameter);
/// Returns D0 = (dΓ(d/2)/(4π^{(d−1)/2})) √(T/m)/(n σ^{d−1}), the elastic first-Sonine self-diffusion.
double reference_self_diffusion(int dimension, double mass, double temperature, double diameter, double density);

}  // namespace gkt
