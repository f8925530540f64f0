// Fast per-cell evaluation of the first-Sonine closed forms (dilute and dense) through generated code.
#include <stdexcept>
#include <string>

#include "gkt/transport/closed_forms/enskog_closed_form.hpp"
#include "gkt/transport/closed_forms/first_sonine_formulas.hpp"
#include "transport/common/alpha_polynomial.hpp"

namespace gkt {

namespace {
#include "transport/closed_forms/generated/enskog_first_sonine_closed_forms.inc"
#include "transport/closed_forms/generated/first_sonine_closed_forms.inc"
}  // namespace

FirstSonineValues first_sonine_values(int dimension, double alpha) {
  detail::require_restitution(alpha);
  if (dimension == 3)
    return {first_sonine_a2_d3(alpha), first_sonine_cooling_rate_d3(alpha), first_sonine_shear_viscosity_d3(alpha),
            first_sonine_thermal_conductivity_d3(alpha), first_sonine_density_heat_coefficient_d3(alpha)};
  if (dimension == 2)
    return {first_sonine_a2_d2(alpha), first_sonine_cooling_rate_d2(alpha), first_sonine_shear_viscosity_d2(alpha),
            first_sonine_thermal_conductivity_d2(alpha), first_sonine_density_heat_coefficient_d2(alpha)};
  throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
}

EnskogFirstSonineValues enskog_first_sonine_values(int dimension, double alpha, const EnskogState& state) {
  detail::require_restitution(alpha);
  const double phi = state.packing_fraction, chi = state.chi, dchi = state.phi_dchi;
  if (dimension == 3)
    return {enskog_first_sonine_a2_d3(alpha, phi, chi, dchi),
            enskog_first_sonine_cooling_rate_d3(alpha, phi, chi, dchi),
            enskog_first_sonine_pressure_d3(alpha, phi, chi, dchi),
            enskog_first_sonine_shear_viscosity_d3(alpha, phi, chi, dchi),
            enskog_first_sonine_bulk_viscosity_d3(alpha, phi, chi, dchi),
            enskog_first_sonine_thermal_conductivity_d3(alpha, phi, chi, dchi),
            enskog_first_sonine_density_heat_coefficient_d3(alpha, phi, chi, dchi),
            enskog_first_sonine_cooling_rate_first_order_d3(alpha, phi, chi, dchi)};
  if (dimension == 2)
    return {enskog_first_sonine_a2_d2(alpha, phi, chi, dchi),
            enskog_first_sonine_cooling_rate_d2(alpha, phi, chi, dchi),
            enskog_first_sonine_pressure_d2(alpha, phi, chi, dchi),
            enskog_first_sonine_shear_viscosity_d2(alpha, phi, chi, dchi),
            enskog_first_sonine_bulk_viscosity_d2(alpha, phi, chi, dchi),
            enskog_first_sonine_thermal_conductivity_d2(alpha, phi, chi, dchi),
            enskog_first_sonine_density_heat_coefficient_d2(alpha, phi, chi, dchi),
            enskog_first_sonine_cooling_rate_first_order_d2(alpha, phi, chi, dchi)};
  throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
}

}  // namespace gkt
