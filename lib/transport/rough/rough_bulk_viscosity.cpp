#include "gkt/transport/rough/rough_bulk_viscosity.hpp"

#include <limits>
#include <stdexcept>

#include "gkt/collision/rough_collision_rule.hpp"
#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"

namespace gkt {

namespace {

/// Maxwellian ζ* = ζ/ν0 at θ: ζ* = −((d+2)/(2d))⟨Δc1²⟩ with ⟨Δc1²⟩ of theory.md (19.7).
double maxwellian_cooling_rate(int d, double alpha, double eta_t, double kappa, double theta) {
  const double energy =
      -(1 - alpha * alpha) / 2 - (d - 1) * eta_t * (1 - eta_t) + (d - 1) * eta_t * eta_t * theta / kappa;
  return -(d + 2.0) / (2.0 * d) * energy;
}

RoughScalarResponse respond(int d, double eta_t, double kappa, double theta, double zeta_star) {
  // θ∂ζ_t*/∂θ and θ∂ζ_r*/∂θ at fixed T_t from (19.12), in units of ν0 (g = (d+2)/4 converts ν of (5.3)).
  const double dr = d == 3 ? 3.0 : 1.0, g = (d + 2.0) / 4.0;
  const double coupling = 2.0 * (d - 1) * eta_t * eta_t / kappa;
  return rough_scalar_response(d, theta, zeta_star, -g * coupling * theta / d, g * coupling / (dr * theta));
}

RoughScalarResponse undefined() {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return {nan, nan, nan};
}

}  // namespace

RoughScalarResponse rough_scalar_response(int dimension, double theta, double zeta_star, double translational_slope,
                                          double rotational_slope) {
  if (dimension != 2 && dimension != 3) throw std::invalid_argument("dimension: must be 2 or 3");
  const double d = dimension, dr = dimension == 3 ? 3.0 : 1.0;
  RoughScalarResponse out;
  out.relaxation_rate = rotational_slope - translational_slope;  // Γ* (19.17)
  // δ = ln(T_r/(θT_t)) = Δ ∇·u/ν0 with (ζ*/2 + Γ*)Δ = 2/d (19.18); the ζ*/2 is ∂_t⁽⁰⁾ of 1/ν0.
  const double split = (2.0 / d) / (zeta_star / 2 + out.relaxation_rate);
  const double weight = d + dr * theta;  // (d + d_rθ) = (d + d_r)T/T_t
  out.bulk_viscosity = dr * theta / weight * split;
  // ζ of T = ν0(T_t)G(T_r/T_t), G = (dζ_t + d_rθζ_r)/(d + d_rθ): θG' at the HCS, minus the ν0 shift (19.19).
  const double slope = (d * translational_slope + dr * theta * rotational_slope) / weight;
  out.cooling_rate_first_order = split * (slope - zeta_star / 2 * dr * theta / weight);
  return out;
}

RoughScalarResponse rough_bulk_viscosity_at(int dimension, const Rational& alpha, const Rational& beta,
                                            const Rational& kappa, double temperature_ratio) {
  (void)rough_parameters_symbolic_temperature(dimension, alpha, beta, kappa);  // range checks
  if (!(temperature_ratio > 0)) throw std::invalid_argument("temperature_ratio: must be > 0");
  if (beta == Rational(-1)) return undefined();
  const double eta_t = ((Rational(1) + beta) * kappa / (Rational(2) * (Rational(1) + kappa))).to_double();
  const double k = kappa.to_double();
  return respond(dimension, eta_t, k, temperature_ratio,
                 maxwellian_cooling_rate(dimension, alpha.to_double(), eta_t, k, temperature_ratio));
}

RoughScalarResponse rough_bulk_viscosity(int dimension, const Rational& alpha, const Rational& beta,
                                         const Rational& kappa) {
  const RoughCoolingState hcs =
      rough_homogeneous_cooling_state(dimension, alpha, beta, kappa, RoughHcsScheme::maxwellian);
  if (hcs.spin_decoupled) return undefined();
  const double eta_t = ((Rational(1) + beta) * kappa / (Rational(2) * (Rational(1) + kappa))).to_double();
  return respond(dimension, eta_t, kappa.to_double(), hcs.temperature_ratio, hcs.cooling_rate);
}

}  // namespace gkt
