#include "gkt/evolution/rough_hcs_stability.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gkt {

namespace {

void check(const RoughStabilityInput& in) {
  if (in.dimension != 2 && in.dimension != 3) throw std::invalid_argument("dimension: must be 2 or 3");
  if (!(in.temperature_ratio > 0))
    throw std::invalid_argument("temperature_ratio: must be > 0 (+inf: the spin decoupled)");
  if (!(in.shear_viscosity > 0) || !std::isfinite(in.shear_viscosity))
    throw std::invalid_argument("shear_viscosity: must be a finite number > 0");
  if (!(in.thermal_conductivity > 0) || !std::isfinite(in.thermal_conductivity))
    throw std::invalid_argument("thermal_conductivity: must be a finite number > 0");
}

/// True when the spin is decoupled (θ = +∞, β = −1): T_t is the hydrodynamic temperature.
bool spin_decoupled(const RoughStabilityInput& in) { return std::isinf(in.temperature_ratio); }

}  // namespace

double rough_translational_share(int dimension, double temperature_ratio) {
  if (std::isinf(temperature_ratio)) return 1.0;
  const double d = dimension, d_r = dimension == 3 ? 3.0 : 1.0;
  return d / (d + d_r * temperature_ratio);
}

std::array<std::array<std::complex<double>, 3>, 3> rough_longitudinal_matrix(const RoughStabilityInput& in, double k) {
  check(in);
  const double d = in.dimension, a = in.cooling_rate;
  const double s = rough_translational_share(in.dimension, in.temperature_ratio);
  const bool decoupled = spin_decoupled(in);
  const double bulk = decoupled ? 0.0 : in.bulk_viscosity;
  const double zeta_u = decoupled ? 0.0 : in.cooling_rate_first_order;
  // theory.md (19.31): K, U carry the share s (∇T_t = τ_t∇T, heat capacity (d + d_r)/2), the work
  // term 2τ_t/(d + d_r) = 2s/d, the longitudinal viscosity the bulk viscosity.
  const double heat = s * (d + 2) / (2 * (d - 1));
  const double kappa = heat * in.thermal_conductivity, mu = heat * in.density_heat_coefficient;
  const double eta = (d - 1) / d * in.shear_viscosity + bulk / 2;
  const std::complex<double> i(0, 1);
  return {{{0.0, 0.0, -i * k},
           {-(a + mu * k * k), -(a / 2 + kappa * k * k), -(2 * s / d + zeta_u) * i * k},
           {-i * k / 2.0, -i * k / 2.0, a / 2 - eta * k * k}}};
}

HcsStability rough_hcs_stability(const RoughStabilityInput& in) {
  check(in);
  const double d = in.dimension, zeta = std::max(in.cooling_rate, 0.0);
  const double s = rough_translational_share(in.dimension, in.temperature_ratio);
  HcsStability out;
  out.shear_wavenumber = shear_critical_wavenumber(in.cooling_rate, in.shear_viscosity);
  // det M = (k²/2)[ζ*/2 − s((d+2)/(2(d−1)))(κ* − μ*)k²] vanishes at (19.32).
  const double denominator = s * (d + 2) * (in.thermal_conductivity - in.density_heat_coefficient);
  const double numerator = (d - 1) * zeta;
  out.heat_wavenumber = numerator > 0 && denominator > 0 ? std::sqrt(numerator / denominator) : 0.0;
  out.critical_length = critical_length(std::max(out.shear_wavenumber, out.heat_wavenumber));
  return out;
}

}  // namespace gkt
