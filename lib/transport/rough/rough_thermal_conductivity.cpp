#include "gkt/transport/rough/rough_thermal_conductivity.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "gkt/algebra/rational_polynomial.hpp"
#include "gkt/collision/rough_collision_moments.hpp"
#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"

namespace gkt {

namespace {

using S = RoughSlot;

/// Converts an even polynomial in λ to its values at τ = λ² divided by τ^{spin_power}.
double at_tau(const RationalPolynomial& m, int spin_power, double tau) {
  double value = 0, power = 1;
  for (long j = 0; j <= m.degree(); j += 2, power *= tau) value += m.coefficient(j).to_double() * power;
  return value * std::pow(tau, -spin_power);
}

/// ⟨ψ_i(A)·ψ_j(B)⟩/⟨1⟩ (ψ1 = v(v² − (d+2)/2), ψ2 = v(ŵ² − d_r/2)) for the slot pairs A = (va, wa),
/// B = (vb, wb), θ symbolic, at τ.
double pair(const RoughCollisionParameters<RationalPolynomial>& p, S va, S wa, S vb, S wb, int i, int j, double tau,
            int d) {
  const RoughForm c = rough_dot_form(va, vb);
  const RoughForm sa = i == 1 ? rough_dot_form(va, va) : rough_dot_form(wa, wa);
  const RoughForm sb = j == 1 ? rough_dot_form(vb, vb) : rough_dot_form(wb, wb);
  const RoughCollisionMoments<RationalPolynomial> m(p, {c, sa, sb}, {1, 1, 1});
  // ŵ² = w²/τ: the spin factors carry τ^{−1} each.
  const int pa = i == 2 ? 1 : 0, pb = j == 2 ? 1 : 0;
  const double c1 = (d + 2) / 2.0, c2 = d == 3 ? 1.5 : 0.5;
  const double ca = i == 1 ? c1 : c2, cb = j == 1 ? c1 : c2;
  return at_tau(m.moment({1, 1, 1, 0}), pa + pb, tau) - cb * at_tau(m.moment({1, 1, 0, 0}), pa, tau) -
         ca * at_tau(m.moment({1, 0, 1, 0}), pb, tau) + ca * cb * at_tau(m.moment({1, 0, 0, 0}), 0, tau);
}

/// ⟨ψ_i, 𝓛ψ_j⟩ in the normalisation of theory.md (5.2).
double operator_element(const RoughCollisionParameters<RationalPolynomial>& p, int i, int j, double tau, int d) {
  return pair(p, S::v1, S::w1, S::v1, S::w1, j, i, tau, d) -
         pair(p, S::v1, S::w1, S::v1_post, S::w1_post, j, i, tau, d) +
         pair(p, S::v2, S::w2, S::v1, S::w1, j, i, tau, d) -
         pair(p, S::v2, S::w2, S::v1_post, S::w1_post, j, i, tau, d);
}

RoughThermalConductivity solve(int d, const Rational& alpha, const Rational& beta, const Rational& kappa, double theta,
                               double zeta_star, bool spin_decoupled) {
  const auto p = rough_parameters_symbolic_temperature(d, alpha, beta, kappa);
  const double tau = spin_decoupled ? 1.0 : theta / kappa.to_double();
  const RoughHeatOperator l{{{operator_element(p, 1, 1, tau, d), operator_element(p, 1, 2, tau, d)},
                             {operator_element(p, 2, 1, tau, d), operator_element(p, 2, 2, tau, d)}}};
  return rough_heat_flux_response(d, l, spin_decoupled ? std::numeric_limits<double>::infinity() : theta, zeta_star);
}

}  // namespace

RoughThermalConductivity rough_heat_flux_response(int d, const RoughHeatOperator& l, double theta, double zeta_star) {
  if (d != 2 && d != 3) throw std::invalid_argument("dimension: must be 2 or 3");
  // (𝓛 − 2ζ)𝔄 = ψ1 + ψ2 (theory.md (19.15)): M = L − 2z diag(⟨ψ1²⟩, ⟨ψ2²⟩), z = (4/(d+2))ζ*,
  // ⟨ψ1²⟩ = d(d+2)/4, ⟨ψ2²⟩ = d d_r/4 (15/4, 9/4 for spheres; 2, 1/2 for disks).
  const double dr = d == 3 ? 3.0 : 1.0;
  const double z = 4.0 / (d + 2) * zeta_star, n1 = d * (d + 2) / 4.0, n2 = d * dr / 4.0;
  const double m11 = l[0][0] - 2 * z * n1, m12 = l[0][1], m21 = l[1][0], m22 = l[1][1] - 2 * z * n2;
  RoughThermalConductivity out;
  const double reference = n1 * n1 / (d - 1);  // the smooth elastic flux n1²/L11, L11 = d − 1
  if (std::isinf(theta)) {                     // β = −1: m12 = m21 = 0, the translational channel alone
    const double x1 = n1 / m11;
    out.translational = n1 * x1 / reference;
    out.density_heat_translational = n1 * (z * n1 * x1 / (m11 + 0.5 * z * n1)) / reference;
    out.total = out.density_heat_total = std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  const auto solve2 = [](double a11, double a12, double a21, double a22, double r1, double r2) {
    const double det = a11 * a22 - a12 * a21;
    return std::array<double, 2>{(a22 * r1 - a12 * r2) / det, (a11 * r2 - a21 * r1) / det};
  };
  const auto x = solve2(m11, m12, m21, m22, n1, n2);  // 𝔄 = x1 ψ1 + x2 ψ2
  // Flux ⟨c(c² + θŵ²)·𝔄⟩ = n1 x1 + θ n2 x2, against the smooth elastic n1²/(d − 1).
  out.translational = n1 * x[0] / reference;
  out.total = (n1 * x[0] + theta * n2 * x[1]) / reference;
  // (𝓛 − (3/2)ζ)𝔅 = ζ𝔄: M + (1/2)z diag(n1, n2) on the left, z diag(n1, n2) x on the right.
  const auto y = solve2(m11 + 0.5 * z * n1, m12, m21, m22 + 0.5 * z * n2, z * n1 * x[0], z * n2 * x[1]);
  out.density_heat_translational = n1 * y[0] / reference;
  out.density_heat_total = (n1 * y[0] + theta * n2 * y[1]) / reference;
  return out;
}

RoughThermalConductivity rough_thermal_conductivity_at(int dimension, const Rational& alpha, const Rational& beta,
                                                       const Rational& kappa, double temperature_ratio) {
  (void)rough_parameters_symbolic_temperature(dimension, alpha, beta, kappa);  // range checks
  if (!(temperature_ratio > 0)) throw std::invalid_argument("temperature_ratio: must be > 0");
  // Maxwellian ζ* at this θ: ζ* = −((d+2)/(2d))⟨Δc1²⟩ with (19.7).
  const int d = dimension;
  const double eta = ((Rational(1) + beta) * kappa / (Rational(2) * (Rational(1) + kappa))).to_double();
  const double a = alpha.to_double(), tau = temperature_ratio / kappa.to_double();
  const double energy = -(1 - a * a) / 2 - (d - 1) * eta * (1 - eta) + (d - 1) * eta * eta * tau;
  return solve(d, alpha, beta, kappa, temperature_ratio, -(d + 2.0) / (2.0 * d) * energy, beta == Rational(-1));
}

RoughThermalConductivity rough_thermal_conductivity(int dimension, const Rational& alpha, const Rational& beta,
                                                    const Rational& kappa) {
  const RoughCoolingState hcs =
      rough_homogeneous_cooling_state(dimension, alpha, beta, kappa, RoughHcsScheme::maxwellian);
  return solve(dimension, alpha, beta, kappa, hcs.temperature_ratio, hcs.cooling_rate, hcs.spin_decoupled);
}

RoughThermalConductivity rough_thermal_conductivity_at(const Rational& alpha, const Rational& beta,
                                                       const Rational& kappa, double temperature_ratio) {
  return rough_thermal_conductivity_at(3, alpha, beta, kappa, temperature_ratio);
}

RoughThermalConductivity rough_thermal_conductivity(const Rational& alpha, const Rational& beta,
                                                    const Rational& kappa) {
  return rough_thermal_conductivity(3, alpha, beta, kappa);
}

}  // namespace gkt
