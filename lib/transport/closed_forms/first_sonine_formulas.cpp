#include "gkt/transport/closed_forms/first_sonine_formulas.hpp"

#include <stdexcept>

#include "gkt/transport/monodisperse/homogeneous_cooling_state.hpp"
#include "gkt/transport/monodisperse/navier_stokes.hpp"
#include "support/strings.hpp"

namespace gkt {

namespace {
RationalFunction constant(const Rational& c) { return RationalFunction{RationalPolynomial(c), RationalPolynomial(1L)}; }
RationalFunction of(const RationalPolynomial& p) { return RationalFunction{p, RationalPolynomial(1L)}; }
}  // namespace

RationalFunction first_sonine_closed_form(int dimension, const std::string& coefficient, SonineScheme scheme) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
  const auto hcs = first_sonine_hcs(dimension);
  if (coefficient == "a2") return hcs.a2;
  if (coefficient == "cooling_rate") return hcs.cooling_rate;
  const auto ns = first_sonine_navier_stokes(dimension);
  const RationalFunction& a2 = hcs.a2;
  // theory.md (10.8) with ν = ν0 + a2 ν2, ζ = ζ0 + a2 ζ2 (all polynomials in α).
  const bool modified = scheme == SonineScheme::modified;
  const RationalFunction nu_eta = of(ns.nu_eta_0) + a2 * of(modified ? ns.modified_nu_eta_a2 : ns.nu_eta_a2);
  const RationalFunction nu_kappa = of(ns.nu_kappa_0) + a2 * of(modified ? ns.modified_nu_kappa_a2 : ns.nu_kappa_a2);
  const RationalFunction zeta = of(ns.zeta_0) + a2 * of(ns.zeta_a2);
  const Rational d_ratio(dimension - 1, static_cast<unsigned long>(dimension));
  if (coefficient == "shear_viscosity") return constant(Rational(1)) / (nu_eta - constant(Rational(1, 2)) * zeta);
  const RationalFunction kappa = constant(d_ratio) * (constant(Rational(1)) + constant(Rational(2)) * a2) /
                                 (nu_kappa - constant(Rational(2)) * zeta);
  if (coefficient == "thermal_conductivity") return kappa;
  if (coefficient == "density_heat_coefficient")
    return (constant(Rational(2)) * zeta * kappa + constant(Rational(2) * d_ratio) * a2) /
           (constant(Rational(2)) * nu_kappa - constant(Rational(3)) * zeta);
  throw std::invalid_argument("coefficient: no first-Sonine closed form for '" + coefficient +
                              "'; valid: " + detail::join(kFirstSonineCoefficients));
}

}  // namespace gkt
