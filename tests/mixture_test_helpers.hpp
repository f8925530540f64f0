// Small helpers shared by the mixture tests.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Dense>

#include "evolution/mixture_longitudinal_matrix.hpp"
#include "gkt/transport/mixture/mixture_navier_stokes.hpp"

namespace gkt::test {

/// Returns |a − b| / max(1, |b|).
inline double relative(double a, double b) { return std::abs(a - b) / std::max(1.0, std::abs(b)); }

/// Returns the number of eigenvalues of m with a positive real part (growing modes).
inline int growing_modes(const Eigen::MatrixXcd& m) {
  int n = 0;
  for (const auto& e : m.eigenvalues()) n += e.real() > 0;
  return n;
}

/// Returns the reduced values a per-cell table interpolates, from the direct solve `ns` at Sonine order `order`, in
/// the order the table tests walk them: ζ*, η*, λ*, the γ_i, then D_ij*, D^T_i*, D^p_i*, D''_j*.
inline std::vector<double> table_values(const MixtureNavierStokes& ns, int order) {
  const auto v = ns.coefficients(order);
  const auto& hcs = ns.cooling_state();
  std::vector<double> out{hcs.cooling_rate, v.shear_viscosity, v.thermal_conductivity};
  out.insert(out.end(), hcs.temperature_ratio.begin(), hcs.temperature_ratio.end());
  out.insert(out.end(), v.mutual_diffusion.begin(), v.mutual_diffusion.end());
  out.insert(out.end(), v.thermal_diffusion.begin(), v.thermal_diffusion.end());
  out.insert(out.end(), v.pressure_diffusion.begin(), v.pressure_diffusion.end());
  out.insert(out.end(), v.dufour.begin(), v.dufour.end());
  return out;
}

}  // namespace gkt::test
