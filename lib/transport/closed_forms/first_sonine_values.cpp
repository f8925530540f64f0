// Fast per-cell evaluation of the first-Sonine closed forms (dilute and dense) through generated code.
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>

#include "gkt/transport/closed_forms/enskog_closed_form.hpp"
#include "gkt/transport/closed_forms/first_sonine_formulas.hpp"

namespace gkt {

namespace {
#include "transport/closed_forms/generated/enskog_first_sonine_closed_forms.inc"
#include "transport/closed_forms/generated/first_sonine_closed_forms.inc"

/// Returns x in its shortest round-trip decimal (the value echoed in an error message).
std::string shortest(double x) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, x).ptr;
  return {buffer, end};
}

/// Throws "<name>: must be <range>, got <value>": out of line and cold, so that the checks on the
/// valid path stay a few compares (docs/performance.md).
[[noreturn, gnu::cold, gnu::noinline]] void refuse(const char* name, const char* range, double value) {
  throw std::invalid_argument(std::string(name) + ": must be " + range + ", got " + shortest(value));
}

/// Throws unless 0 < α ≤ 1 (nan fails) and d ∈ {2, 3}.
inline void require_alpha_dimension(double alpha, int dimension) {
  if (!(alpha > 0 && alpha <= 1)) refuse("alpha", "a number in (0, 1]", alpha);
  if (dimension != 2 && dimension != 3) refuse("dimension", "2 or 3", dimension);
}
}  // namespace

FirstSonineValues first_sonine_values(int dimension, double alpha) {
  require_alpha_dimension(alpha, dimension);
  if (dimension == 3)
    return {first_sonine_a2_d3(alpha), first_sonine_cooling_rate_d3(alpha), first_sonine_shear_viscosity_d3(alpha),
            first_sonine_thermal_conductivity_d3(alpha), first_sonine_density_heat_coefficient_d3(alpha)};
  return {first_sonine_a2_d2(alpha), first_sonine_cooling_rate_d2(alpha), first_sonine_shear_viscosity_d2(alpha),
          first_sonine_thermal_conductivity_d2(alpha), first_sonine_density_heat_coefficient_d2(alpha)};
}

EnskogFirstSonineValues enskog_first_sonine_values(int dimension, double alpha, const EnskogState& state) {
  require_alpha_dimension(alpha, dimension);
  const double phi = state.packing_fraction, chi = state.chi, dchi = state.phi_dchi;
  // The ranges gkt table accepts (max_packing_fraction: 1/2 in 3D, 7/10 in 2D; a contact value of
  // hard spheres is ≥ 1 and grows with φ), compared in double: no allocation on the valid path.
  if (!(phi >= 0 && phi <= (dimension == 3 ? 0.5 : 0.7)))
    refuse("packing_fraction",
           dimension == 3 ? "a number in [0, 0.5] for dimension = 3" : "a number in [0, 0.7] for dimension = 2", phi);
  if (!(chi >= 1 && chi < INFINITY)) refuse("chi", "a finite number >= 1", chi);
  if (!(dchi >= 0 && dchi < INFINITY)) refuse("phi_dchi", "a finite number >= 0", dchi);
  const EnskogFirstSonineValues v =
      dimension == 3 ? EnskogFirstSonineValues{enskog_first_sonine_a2_d3(alpha, phi, chi, dchi),
                                               enskog_first_sonine_cooling_rate_d3(alpha, phi, chi, dchi),
                                               enskog_first_sonine_pressure_d3(alpha, phi, chi, dchi),
                                               enskog_first_sonine_shear_viscosity_d3(alpha, phi, chi, dchi),
                                               enskog_first_sonine_bulk_viscosity_d3(alpha, phi, chi, dchi),
                                               enskog_first_sonine_thermal_conductivity_d3(alpha, phi, chi, dchi),
                                               enskog_first_sonine_density_heat_coefficient_d3(alpha, phi, chi, dchi),
                                               enskog_first_sonine_cooling_rate_first_order_d3(alpha, phi, chi, dchi)}
                     : EnskogFirstSonineValues{enskog_first_sonine_a2_d2(alpha, phi, chi, dchi),
                                               enskog_first_sonine_cooling_rate_d2(alpha, phi, chi, dchi),
                                               enskog_first_sonine_pressure_d2(alpha, phi, chi, dchi),
                                               enskog_first_sonine_shear_viscosity_d2(alpha, phi, chi, dchi),
                                               enskog_first_sonine_bulk_viscosity_d2(alpha, phi, chi, dchi),
                                               enskog_first_sonine_thermal_conductivity_d2(alpha, phi, chi, dchi),
                                               enskog_first_sonine_density_heat_coefficient_d2(alpha, phi, chi, dchi),
                                               enskog_first_sonine_cooling_rate_first_order_d2(alpha, phi, chi, dchi)};
  // χ and φ dχ/dφ have no upper bound of their own; the closed forms are polynomials of low degree
  // in them (theory.md §15.7), finite below 1e50 (the fuzz target checks it), and beyond it the set
  // is refused if it overflows: a sum is finite iff every term is.
  if ((chi > 1e50 || dchi > 1e50) &&
      !std::isfinite(v.a2 + v.cooling_rate + v.pressure + v.shear_viscosity + v.bulk_viscosity +
                     v.thermal_conductivity + v.density_heat_coefficient + v.cooling_rate_first_order))
    refuse("chi, phi_dchi", "small enough for finite coefficients", chi);
  return v;
}

}  // namespace gkt
