// The one place the stability input of a one-component gas is assembled (theory.md §14).
#include "gkt/evolution/hcs_stability.hpp"
#include "models/models.hpp"

namespace gkt::detail {

HcsStability monodisperse_stability(int dimension, double cooling_rate, const NavierStokesValues& values,
                                    const EnskogState& dense, double alpha, double cooling_temperature_exponent) {
  StabilityDensity density;
  density.pressure = dense.pressure(dimension, alpha);
  density.pressure_derivative =  // φ ∂p*/∂φ of (15.5)
      (dimension == 3 ? 2.0 : 1.0) * (1 + alpha) * dense.packing_fraction * (dense.chi + dense.phi_dchi);
  density.log_chi_derivative = dense.phi_dchi / dense.chi;
  density.bulk_viscosity = values.bulk_viscosity;
  density.cooling_rate_first_order = values.cooling_rate_first_order;
  density.cooling_temperature_exponent = cooling_temperature_exponent;
  return hcs_stability(dimension, cooling_rate, values.shear_viscosity, values.thermal_conductivity,
                       values.density_heat_coefficient, density);
}

}  // namespace gkt::detail
