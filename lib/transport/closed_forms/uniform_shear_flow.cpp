// Grad's steady uniform shear flow and its Navier–Stokes limit (uniform_shear_flow.hpp;
// docs/theory.md §22).
#include "gkt/transport/closed_forms/uniform_shear_flow.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "gkt/algebra/rational.hpp"
#include "gkt/transport/monodisperse/navier_stokes.hpp"

namespace gkt {

namespace {

void check_dimension(int d) {
  if (d != 2 && d != 3) throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(d));
}

/// The engine's first-Sonine polynomials of dimension d, derived once (thread-safe static init).
const FirstSonineNavierStokes& first_sonine(int d) {
  static const FirstSonineNavierStokes two = first_sonine_navier_stokes(2), three = first_sonine_navier_stokes(3);
  return d == 2 ? two : three;
}

}  // namespace

double uniform_shear_length_factor(int dimension) {
  check_dimension(dimension);
  // ν0 = nT/η0: 2nσ√(πT/m) (d = 2), (16/5)nσ²√(πT/m) (d = 3); ℓ = 1/(2nσ), 1/(πnσ²).
  return dimension == 2 ? std::sqrt(std::numbers::pi / 2) : 16 / (5 * std::sqrt(2 * std::numbers::pi));
}

UniformShearFlow uniform_shear_flow_grad(int dimension, double alpha) {
  check_dimension(dimension);
  if (!(alpha > 0 && alpha <= 1))
    throw std::invalid_argument("alpha: must be a number in (0, 1], got " + std::to_string(alpha));
  const auto& fs = first_sonine(dimension);
  const Rational a = Rational::from_double(alpha);
  UniformShearFlow out;
  out.cooling_rate = fs.zeta_0.evaluate(a).to_double();
  out.shear_collision_frequency = fs.nu_eta_0.evaluate(a).to_double();
  const double d = dimension, zeta = out.cooling_rate, nu = out.shear_collision_frequency;
  // theory.md (22.6): a*² = d ζ ν²/(2(ν − ζ)); (22.7): P_yy/p = 1 − ζ/ν, P_xx/p = 1 + (d−1)ζ/ν,
  // P_xy/p = −a*(1 − ζ/ν)/ν.
  out.shear_rate = std::sqrt(d * zeta * nu * nu / (2 * (nu - zeta)));
  out.reduced_shear_rate = out.shear_rate * uniform_shear_length_factor(dimension);
  out.stress_yy = 0.5 * (1 - zeta / nu);
  out.stress_xx = 0.5 * (1 + (d - 1) * zeta / nu);
  out.stress_zz = dimension == 3 ? out.stress_yy : 0.0;
  out.stress_xy = -0.5 * out.shear_rate * (1 - zeta / nu) / nu;
  return out;
}

UniformShearLeadingOrder uniform_shear_navier_stokes_limit(int dimension, double elastic_viscosity) {
  check_dimension(dimension);
  if (!(elastic_viscosity > 0 && std::isfinite(elastic_viscosity)))
    throw std::invalid_argument("elastic_viscosity: must be a finite number > 0, got " +
                                std::to_string(elastic_viscosity));
  const double d = dimension, zeta1 = (d + 2) / (4 * d);                 // ζ*/ε at ε → 0 (theory.md (22.9))
  const double shear1 = std::sqrt(0.5 * d * zeta1 / elastic_viscosity);  // a*/√ε, from η a² = (d/2) p ζ
  return {shear1 * uniform_shear_length_factor(dimension), -0.5 * elastic_viscosity * shear1};
}

}  // namespace gkt
