// The dense gas's first-Sonine closed forms (docs/theory.md §15.7): the Galerkin systems of
// NavierStokesSolver::solve at order 1 in the standard scheme (one trial function per mode:
// c S_1, Y_2 S_0 and, for ζ_U, S_2), assembled in exact arithmetic with φ, χ and φ dχ/dφ kept as
// symbols. Every Sonine sum over the HCS weights f_M Σ a_k S_k is kept linear in a2.
#include <algorithm>
#include <stdexcept>

#include "gkt/operators/collisional_transfer.hpp"
#include "gkt/operators/linearized_operator.hpp"
#include "gkt/operators/nonlinear_collision_moments.hpp"
#include "gkt/transport/closed_forms/enskog_closed_form.hpp"
#include "gkt/transport/monodisperse/homogeneous_cooling_state.hpp"
#include "support/strings.hpp"
#include "transport/common/galerkin_pieces.hpp"

namespace gkt {

namespace {

using Form = EnskogClosedForm;

RationalFunction of(const RationalPolynomial& p) { return RationalFunction{p, RationalPolynomial(1L)}; }
RationalFunction of(const Rational& c) { return of(RationalPolynomial(c)); }
Form constant(const Rational& c) { return Form::term(of(c)); }
Form of_alpha(const RationalFunction& r) { return Form::term(r); }

/// The pieces of the three first-Sonine systems and the collisional-transfer tables, exact in α.
struct FirstSonineDense {
  int d;
  RationalFunction a2;
  RationalPolynomial alpha = RationalPolynomial::variable();
  std::vector<DenseMatrix<RationalPolynomial>> vec, ten, sca;  // operators by HCS weight
  BilinearCollisionMoments<RationalPolynomial> energy;
  detail::GalerkinPieces<Rational> vp, tp, sp;
  CollisionalTransferMoments<RationalPolynomial> ct;

  FirstSonineDense(int dimension, RationalFunction a2_of_alpha)
      : d(dimension),
        a2(std::move(a2_of_alpha)),
        vec(hcs_linearized_operator_matrices<RationalPolynomial>(d, alpha, 1, 1, 2)),
        ten(hcs_linearized_operator_matrices<RationalPolynomial>(d, alpha, 2, 0, 2)),
        sca(hcs_linearized_operator_matrices<RationalPolynomial>(d, alpha, 0, 2, 2)),
        energy(bilinear_collision_moments<RationalPolynomial>(d, alpha, 2)),
        vp(detail::vector_pieces(d, 1, 2)),
        tp(detail::tensor_pieces(d, 0, 2)),
        sp(detail::scalar_pieces(d, 2, 2)),
        ct(collisional_transfer_moments<RationalPolynomial>(d, alpha, 2, 2)) {}

  // Σ_k a_k t_k and Σ_kl a_k a_l t_kl with a = (1, 0, a2), linear in a2.
  [[nodiscard]] RationalFunction linear(const RationalFunction& t0, const RationalFunction& t2) const {
    return t0 + a2 * t2;
  }
  [[nodiscard]] RationalFunction weighted(const std::vector<RationalPolynomial>& t, int q) const {
    return linear(of(t[ct.index(q, 0)]), of(t[ct.index(q, 2)]));
  }
  [[nodiscard]] RationalFunction bilinear(const std::vector<RationalPolynomial>& t, int p) const {
    return linear(of(t[ct.index(p, 0, 0)]), of(t[ct.index(p, 0, 2)] + t[ct.index(p, 2, 0)]));
  }
  [[nodiscard]] RationalFunction bilinear(const std::vector<RationalPolynomial>& t) const {
    return linear(of(t[ct.index(0, 0)]), of(t[ct.index(0, 2)] + t[ct.index(2, 0)]));
  }
  [[nodiscard]] RationalFunction source(const std::vector<std::vector<Rational>>& u, int p) const {
    return linear(of(u[p][0]), of(u[p][2]));
  }
  [[nodiscard]] RationalFunction operator_entry(const std::vector<DenseMatrix<RationalPolynomial>>& m, int p) const {
    return linear(of(m[0](p, p)), of(m[2](p, p)));
  }
  /// ζ_r/ν = −(2/d) R_1, R_1 = Σ a_k a_l E(k, l) (theory.md (9.2)).
  [[nodiscard]] RationalFunction zeta_term() const {
    return of(Rational(-2, static_cast<unsigned long>(d))) *
           linear(of(energy.e(0, 0)), of(energy.e(0, 2) + energy.e(2, 0)));
  }
};

/// Returns the named coefficient (theory.md §15.2–15.5 at order 1; the equation numbers below).
Form assemble(const FirstSonineDense& s, const std::string& name) {
  const int d = s.d;
  const Rational rd(d);
  const RationalFunction one_plus_alpha = of(RationalPolynomial(1L) + s.alpha);
  const Form phi_chi = Form::term(of(Rational(1)), {1, 1, 0, 0});
  const Form chi = Form::term(of(Rational(1)), {0, 1, 0, 0});
  const Form dlnchi = Form::term(of(Rational(1)), {0, -1, 1, 0});           // φ ∂ln χ/∂φ
  const Form phi2_chi_over_pi = Form::term(of(Rational(1)), {2, 1, 0, 1});  // φ²χ/π
  const Form e_phi_chi = constant(Rational(d == 3 ? 12 : 4)) * phi_chi;     // e_d φχ (15.3)
  const Rational g_d_pi(d == 3 ? 96 : 16, d == 3 ? 25UL : 16UL);            // π g_d = 2^{2d−1}d/(d+2)²
  const Form pressure_excess = of_alpha(of(Rational(d == 3 ? 2 : 1)) * one_plus_alpha) * phi_chi;  // p* − 1 (15.5)
  const Form inv_1pa = of_alpha(of(Rational(1)) / one_plus_alpha);
  const RationalFunction zt = s.zeta_term();

  if (name == "a2") return of_alpha(s.a2);
  if (name == "pressure") return constant(Rational(1)) + pressure_excess;
  if (name == "cooling_rate") {  // (15.1)
    const auto hcs = first_sonine_hcs(d);
    return of_alpha(s.linear(of(hcs.cooling_rate_0), of(hcs.cooling_rate_a2))) * chi;
  }
  if (name == "thermal_conductivity" || name == "density_heat_coefficient") {  // c S_1
    const auto& v = s.vp;
    const RationalFunction l = s.operator_entry(s.vec, 1);
    const Form a_matrix = of_alpha(l + zt * (of(v.d[1][1]) - of(v.m[1][1] / Rational(2)))) * chi;
    const Form b_matrix = of_alpha(l + zt * of(v.d[1][1]));
    const Form u_pressure = of_alpha(s.source(v.u_pressure, 1));
    // φ ∂p*/∂φ = 2^{d−2}(1+α)(φχ + φ·φ dχ/dφ)
    const Form phi_dp =
        of_alpha(of(Rational(d == 3 ? 2 : 1)) * one_plus_alpha) * (phi_chi + Form::term(of(Rational(1)), {1, 0, 1, 0}));
    const Form sa = of_alpha(s.source(v.u, 1)) + pressure_excess * u_pressure +
                    e_phi_chi * inv_1pa * of_alpha(s.bilinear(s.ct.heat_source_temperature, 1));  // (15.6)
    const Form sb = of_alpha(s.source(v.u2, 1)) + (pressure_excess + phi_dp) * u_pressure +
                    e_phi_chi * (constant(Rational(1)) + constant(Rational(1, 2)) * dlnchi) * inv_1pa *
                        of_alpha(s.bilinear(s.ct.heat_source_density, 1));
    const Form flux = constant(v.flux[1]) + e_phi_chi * inv_1pa * of_alpha(s.weighted(s.ct.heat_flux, 1));  // (15.10)
    const Form alpha_t = sa / a_matrix;
    const Form reduce = constant(Rational(-16 * (d - 1)) / Rational(d * d * (d + 2) * (d + 2)));  // (10.6)
    const Form gradient = constant(Rational(-8 * (d - 1)) / rd * g_d_pi) * phi2_chi_over_pi;      // (15.11)
    if (name == "thermal_conductivity")
      return reduce * alpha_t * flux + gradient * of_alpha(s.bilinear(s.ct.heat_gradient_temperature));
    const Form beta_t =
        (sb / chi + of_alpha(zt * of(v.m[1][1])) * (constant(Rational(1)) + dlnchi) * alpha_t) / b_matrix;
    return reduce * beta_t * flux + gradient * of_alpha(s.bilinear(s.ct.heat_gradient_density));
  }
  const Form shear_gradient =
      constant(Rational(2) * g_d_pi) * phi2_chi_over_pi * of_alpha(s.bilinear(s.ct.shear_gradient));  // (15.8)
  if (name == "bulk_viscosity") return constant(Rational(d + 2) / rd) * shear_gradient;               // (15.9)
  if (name == "shear_viscosity") {                                                                    // Y_2 S_0
    const auto& t = s.tp;
    const Form c_matrix = of_alpha(s.operator_entry(s.ten, 0) + zt * of(t.d[0][0])) * chi;
    const Form sc = of_alpha(s.source(t.u, 0)) - e_phi_chi * inv_1pa * of_alpha(s.bilinear(s.ct.shear_source, 0));
    const Form flux = constant(t.flux[0]) + constant(Rational(d, static_cast<unsigned long>(2 * (d - 1)))) * e_phi_chi *
                                                inv_1pa * of_alpha(s.weighted(s.ct.shear_flux, 0));  // (15.7)
    return constant(Rational(-8) / Rational(d * (d + 2) * (d + 2))) * (sc / c_matrix) * flux + shear_gradient;
  }
  if (name == "cooling_rate_first_order") {  // S_2, (15.12)–(15.13)
    const auto& sc = s.sp;
    const Form s_matrix = of_alpha(s.operator_entry(s.sca, 2) + zt * of(sc.d[2][2])) * chi;
    const Form u_zeta = of_alpha(s.source(sc.u, 2));
    const Form u_fixed = constant(Rational(2) / rd) * pressure_excess * u_zeta -
                         e_phi_chi * inv_1pa * constant(Rational(1) / rd) * of_alpha(s.bilinear(s.ct.scalar_source, 2));
    const Form cooling = of_alpha(of(Rational(2) / rd) * of(RationalPolynomial(1L) - s.alpha * s.alpha)) * chi *
                         of_alpha(s.weighted(s.ct.cooling_scalar, 2));
    const Form zeta10 = of_alpha(of(Rational(-1) / Rational(2 * d * d)) * of(RationalPolynomial(1L) - s.alpha)) *
                        e_phi_chi * of_alpha(s.bilinear(s.ct.cooling_gradient));
    return (zeta10 + cooling * (u_fixed / s_matrix)) / (constant(Rational(1)) - cooling * (u_zeta / s_matrix));
  }
  throw std::invalid_argument("coefficient: no dense first-Sonine closed form for '" + name +
                              "'; valid: " + detail::join(enskog_closed_form_coefficients()));
}

}  // namespace

const std::vector<std::string>& enskog_closed_form_coefficients() {
  static const std::vector<std::string> names{"a2",
                                              "cooling_rate",
                                              "pressure",
                                              "shear_viscosity",
                                              "bulk_viscosity",
                                              "thermal_conductivity",
                                              "density_heat_coefficient",
                                              "cooling_rate_first_order"};
  return names;
}

EnskogClosedForm enskog_first_sonine_closed_form(int dimension, const std::string& coefficient,
                                                 const RationalFunction& a2) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
  const auto& names = enskog_closed_form_coefficients();
  if (std::find(names.begin(), names.end(), coefficient) == names.end())
    throw std::invalid_argument("coefficient: no dense first-Sonine closed form for '" + coefficient +
                                "'; valid: " + detail::join(names));
  return assemble(FirstSonineDense(dimension, a2), coefficient);
}

EnskogClosedForm enskog_first_sonine_closed_form(int dimension, const std::string& coefficient) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
  return enskog_first_sonine_closed_form(dimension, coefficient, first_sonine_hcs(dimension).a2);
}

}  // namespace gkt
