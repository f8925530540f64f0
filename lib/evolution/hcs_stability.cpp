#include "gkt/hcs_stability.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gkt {

std::array<std::array<std::complex<double>, 3>, 3> longitudinal_matrix(int dimension, double cooling_rate,
                                                                       double shear_viscosity,
                                                                       double thermal_conductivity,
                                                                       double density_heat_coefficient, double k,
                                                                       const StabilityDensity& dense) {
  const double d = dimension, a = cooling_rate, p = dense.pressure;
  const double kappa = (d + 2) / (2 * (d - 1)) * thermal_conductivity;  // theory.md (14.2)
  const double mu = (d + 2) / (2 * (d - 1)) * density_heat_coefficient;
  const double eta = (d - 1) / d * shear_viscosity + dense.bulk_viscosity / 2;
  const std::complex<double> i(0, 1);
  return {{{0.0, 0.0, -i * k},
           {-(a * (1 + dense.log_chi_derivative) + mu * k * k), -(a / 2 + kappa * k * k),
            -(2 / d * p + dense.cooling_rate_first_order) * i * k},
           {-i * k / 2.0 * (p + dense.pressure_derivative), -i * k / 2.0 * p, a / 2 - eta * k * k}}};
}

double shear_critical_wavenumber(double cooling_rate, double shear_viscosity) {
  return std::sqrt(std::max(cooling_rate, 0.0) / shear_viscosity);
}

double critical_length(double largest_wavenumber) {
  return largest_wavenumber > 0 ? 2 * std::numbers::pi / largest_wavenumber : INFINITY;
}

HcsStability hcs_stability(int dimension, double cooling_rate, double shear_viscosity, double thermal_conductivity,
                           double density_heat_coefficient, const StabilityDensity& dense) {
  if (dimension != 2 && dimension != 3) throw std::invalid_argument("dimension: must be 2 or 3");
  if (!(shear_viscosity > 0) || !(thermal_conductivity > 0))
    throw std::invalid_argument("hcs_stability: transport coefficients must be positive");
  const double d = dimension, zeta = std::max(cooling_rate, 0.0), p = dense.pressure;
  HcsStability s;
  s.shear_wavenumber = shear_critical_wavenumber(cooling_rate, shear_viscosity);
  // det M = (k²/2)[(ζ*(1+λ) + U k²) p* − (ζ*/2 + K k²)(p* + φ∂p*)] vanishes at (14.5).
  const double kappa = (d + 2) / (2 * (d - 1)) * thermal_conductivity;
  const double mu = (d + 2) / (2 * (d - 1)) * density_heat_coefficient;
  const double longitudinal = p + dense.pressure_derivative;
  const double numerator = zeta * ((1 + dense.log_chi_derivative) * p - 0.5 * longitudinal);
  const double denominator = kappa * longitudinal - mu * p;
  s.heat_wavenumber = numerator > 0 && denominator > 0 ? std::sqrt(numerator / denominator) : 0.0;
  s.critical_length = critical_length(std::max(s.shear_wavenumber, s.heat_wavenumber));
  return s;
}

}  // namespace gkt
