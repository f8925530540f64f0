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

/// ⟨ψ_i(A)·ψ_j(B)⟩/⟨1⟩ (ψ1 = v(v² − 5/2), ψ2 = v(ŵ² − 3/2)) for the slot pairs A = (va, wa),
/// B = (vb, wb), θ symbolic, at τ.
double pair(const RoughCollisionParameters<RationalPolynomial>& p, S va, S wa, S vb, S wb, int i, int j, double tau) {
  const RoughForm c = rough_dot_form(va, vb);
  const RoughForm sa = i == 1 ? rough_dot_form(va, va) : rough_dot_form(wa, wa);
  const RoughForm sb = j == 1 ? rough_dot_form(vb, vb) : rough_dot_form(wb, wb);
  const RoughCollisionMoments<RationalPolynomial> m(p, {c, sa, sb}, {1, 1, 1});
  // ŵ² = w²/τ: the spin factors carry τ^{−1} each.
  const int pa = i == 2 ? 1 : 0, pb = j == 2 ? 1 : 0;
  const double ca = i == 1 ? 2.5 : 1.5, cb = j == 1 ? 2.5 : 1.5;
  return at_tau(m.moment({1, 1, 1, 0}), pa + pb, tau) - cb * at_tau(m.moment({1, 1, 0, 0}), pa, tau) -
         ca * at_tau(m.moment({1, 0, 1, 0}), pb, tau) + ca * cb * at_tau(m.moment({1, 0, 0, 0}), 0, tau);
}

/// ⟨ψ_i, 𝓛ψ_j⟩ in the normalisation of theory.md (5.2).
double operator_element(const RoughCollisionParameters<RationalPolynomial>& p, int i, int j, double tau) {
  return pair(p, S::v1, S::w1, S::v1, S::w1, j, i, tau) - pair(p, S::v1, S::w1, S::v1_post, S::w1_post, j, i, tau) +
         pair(p, S::v2, S::w2, S::v1, S::w1, j, i, tau) - pair(p, S::v2, S::w2, S::v1_post, S::w1_post, j, i, tau);
}

RoughThermalConductivity solve(const Rational& alpha, const Rational& beta, const Rational& kappa, double theta,
                               double zeta_star, bool spin_decoupled) {
  const auto p = rough_parameters_symbolic_temperature(3, alpha, beta, kappa);
  const double tau = spin_decoupled ? 1.0 : theta / kappa.to_double();
  // (𝓛 − 2ζ)𝔄 = ψ1 + ψ2 (theory.md (19.15)): M = L − 2z diag(⟨ψ1²⟩, ⟨ψ2²⟩), z = (4/5)ζ*.
  const double z = 0.8 * zeta_star, n1 = 15.0 / 4, n2 = 9.0 / 4;
  const double m11 = operator_element(p, 1, 1, tau) - 2 * z * n1, m12 = operator_element(p, 1, 2, tau),
               m21 = operator_element(p, 2, 1, tau), m22 = operator_element(p, 2, 2, tau) - 2 * z * n2;
  RoughThermalConductivity out;
  if (spin_decoupled) {  // β = −1: m12 = m21 = 0, the translational channel alone
    out.translational = n1 * (n1 / m11) / (n1 * n1 / 2);
    out.total = std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  const double det = m11 * m22 - m12 * m21;
  const double x1 = (m22 * n1 - m12 * n2) / det, x2 = (m11 * n2 - m21 * n1) / det;  // 𝔄 = x1 ψ1 + x2 ψ2
  // Flux ⟨c(c² + θŵ²)·𝔄⟩ = n1 x1 + θ n2 x2, against the smooth elastic n1²/2 (L11 = d − 1 = 2).
  out.translational = n1 * x1 / (n1 * n1 / 2);
  out.total = (n1 * x1 + theta * n2 * x2) / (n1 * n1 / 2);
  return out;
}

}  // namespace

RoughThermalConductivity rough_thermal_conductivity_at(const Rational& alpha, const Rational& beta,
                                                       const Rational& kappa, double temperature_ratio) {
  (void)rough_parameters_symbolic_temperature(3, alpha, beta, kappa);  // range checks
  if (!(temperature_ratio > 0)) throw std::invalid_argument("temperature_ratio: must be > 0");
  // Maxwellian ζ* at this θ: ζ* = −(5/6)⟨Δc1²⟩ with (19.7).
  const double eta = ((Rational(1) + beta) * kappa / (Rational(2) * (Rational(1) + kappa))).to_double();
  const double a = alpha.to_double(), tau = temperature_ratio / kappa.to_double();
  const double energy = -(1 - a * a) / 2 - 2 * eta * (1 - eta) + 2 * eta * eta * tau;
  return solve(alpha, beta, kappa, temperature_ratio, -5.0 / 6 * energy, beta == Rational(-1));
}

RoughThermalConductivity rough_thermal_conductivity(const Rational& alpha, const Rational& beta,
                                                    const Rational& kappa) {
  const RoughCoolingState hcs = rough_homogeneous_cooling_state(3, alpha, beta, kappa, RoughHcsScheme::maxwellian);
  return solve(alpha, beta, kappa, hcs.temperature_ratio, hcs.cooling_rate, hcs.spin_decoupled);
}

}  // namespace gkt
