#include "gkt/hcs_stability.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gkt {

std::array<std::array<std::complex<double>, 3>, 3> longitudinal_matrix(int dimension, double cooling_rate,
                                                                       double shear_viscosity,
                                                                       double thermal_conductivity,
                                                                       double density_heat_coefficient, double k) {
  const double d = dimension, a = cooling_rate;
  const double kappa = (d + 2) / (2 * (d - 1)) * thermal_conductivity;  // theory.md (14.2)
  const double mu = (d + 2) / (2 * (d - 1)) * density_heat_coefficient;
  const double eta = (d - 1) / d * shear_viscosity;
  const std::complex<double> i(0, 1);
  return {{{0.0, 0.0, -i * k},
           {-(a + mu * k * k), -(a / 2 + kappa * k * k), -(2 / d) * i * k},
           {-i * k / 2.0, -i * k / 2.0, a / 2 - eta * k * k}}};
}

HcsStability hcs_stability(int dimension, double cooling_rate, double shear_viscosity, double thermal_conductivity,
                           double density_heat_coefficient) {
  if (dimension != 2 && dimension != 3) throw std::invalid_argument("dimension: must be 2 or 3");
  if (!(shear_viscosity > 0) || !(thermal_conductivity > 0))
    throw std::invalid_argument("hcs_stability: transport coefficients must be positive");
  const double d = dimension;
  HcsStability s;
  s.shear_wavenumber = std::sqrt(std::max(cooling_rate, 0.0) / shear_viscosity);
  const double difference = thermal_conductivity - density_heat_coefficient;
  s.heat_wavenumber = difference > 0 ? std::sqrt((d - 1) * std::max(cooling_rate, 0.0) / ((d + 2) * difference)) : 0.0;
  const double k = std::max(s.shear_wavenumber, s.heat_wavenumber);
  s.critical_length = k > 0 ? 2 * std::numbers::pi / k : INFINITY;
  return s;
}

}  // namespace gkt
