// Dense-gas first-Sonine closed forms (theory.md §15.7): exact equality with the dilute closed
// forms at φ → 0, with Garzó & Dufty's published forms and with Chapman & Cowling's elastic ones
// (as exact functions of α, φ, χ), and agreement with the numerical Enskog solver.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "gkt/operators/collisional_transfer.hpp"
#include "gkt/transport/closed_forms/enskog_closed_form.hpp"
#include "gkt/transport/closed_forms/first_sonine_formulas.hpp"
#include "gkt/transport/common/pair_correlation.hpp"
#include "gkt/transport/monodisperse/homogeneous_cooling_state.hpp"
#include "gkt/transport/monodisperse/navier_stokes.hpp"

using gkt::EnskogClosedForm;
using gkt::EnskogMonomial;
using gkt::Rational;
using gkt::RationalFunction;
using gkt::RationalPolynomial;

namespace {

RationalFunction of(const RationalPolynomial& p) { return RationalFunction{p, RationalPolynomial(1L)}; }
EnskogClosedForm c(const RationalFunction& r, const EnskogMonomial& m = {}) { return EnskogClosedForm::term(r, m); }
EnskogClosedForm c(const Rational& q, const EnskogMonomial& m = {}) { return c(of(RationalPolynomial(q)), m); }

const EnskogMonomial kPhiChi{1, 1, 0, 0}, kChi{0, 1, 0, 0}, kPhi2ChiOverPi{2, 1, 0, 1};

/// Garzó & Dufty, PRE 59, 5895 (1999), first Sonine, standard scheme, in d dimensions with
/// c* = 2 a2 written as a2 (Garzó, Santos & Montanero, Physica A 376, 94 (2007)): η*, bulk
/// viscosity, κ* as exact functions of α, φ, χ; ν and ζ are the dilute first-Sonine ones times χ.
struct GarzoDuftyForms {
  EnskogClosedForm eta, bulk, kappa;
};
GarzoDuftyForms garzo_dufty_forms(int d) {
  const auto fs = gkt::first_sonine_navier_stokes(d);
  const RationalFunction a2 = gkt::first_sonine_hcs(d).a2;
  const RationalPolynomial alpha = RationalPolynomial::variable(), one(1L);
  const RationalFunction nue = of(fs.nu_eta_0) + a2 * of(fs.nu_eta_a2);
  const RationalFunction nuk = of(fs.nu_kappa_0) + a2 * of(fs.nu_kappa_a2);
  const RationalFunction z = of(fs.zeta_0) + a2 * of(fs.zeta_a2);
  const RationalFunction half{RationalPolynomial(Rational(1, 2)), one}, two{RationalPolynomial(2L), one};
  const Rational p2(1L << (d - 2)), p1(1L << (d - 1)), p3(1L << (d - 3 + 3)), dd(d), d2(d + 2);
  const RationalFunction opa = of(one + alpha);
  const EnskogClosedForm unit = c(Rational(1));
  const EnskogClosedForm eta_k =
      (unit - c(of(RationalPolynomial(p2 / d2)) * opa * of(one - RationalPolynomial(3L) * alpha), kPhiChi)) /
      c(nue - half * z, kChi);
  const Rational bulk_factor = Rational(1L << (2 * d + 1)) / d2;
  const EnskogClosedForm bulk =
      c(of(RationalPolynomial(bulk_factor)) * opa * (of(one) - a2 * of(RationalPolynomial(Rational(1, 16)))),
        kPhi2ChiOverPi);
  const EnskogClosedForm eta = eta_k * (unit + c(of(RationalPolynomial(p1 / d2)) * opa, kPhiChi)) + c(dd / d2) * bulk;
  const Rational dm1_d = Rational(d - 1) / dd;
  const RationalFunction kappa_source = of(RationalPolynomial(Rational(3) * p3 / Rational(8) / d2)) * opa * opa *
                                        (of(RationalPolynomial(2L) * alpha - one) + a2 * opa);
  const EnskogClosedForm kappa_k =
      c(dm1_d) * (c(of(one) + two * a2) + c(kappa_source, kPhiChi)) / c(nuk - two * z, kChi);
  const EnskogClosedForm kappa = kappa_k * (unit + c(of(RationalPolynomial(Rational(3) * p2 / d2)) * opa, kPhiChi)) +
                                 c(of(RationalPolynomial(Rational(1L << (2 * d + 1)) * Rational(d - 1) / (d2 * d2))) *
                                       opa * (of(one) + a2 * of(RationalPolynomial(Rational(7, 16)))),
                                   kPhi2ChiOverPi);
  return {eta, bulk, kappa};
}

gkt::EnskogState enskog(int d, const Rational& phi) {
  const auto& pc = gkt::pair_correlation("carnahan-starling");
  return {phi.to_double(), pc.contact_value(d, phi).to_double(), pc.packing_derivative(d, phi).to_double()};
}

}  // namespace

// φ → 0: the dense forms reduce to the dilute closed forms exactly (as rational functions of α);
// the purely collisional ones vanish and p* → 1.
TEST(EnskogClosedForm, DiluteLimitIsTheDiluteClosedForm) {
  for (int d : {2, 3}) {
    for (const auto& name : gkt::kFirstSonineCoefficients)
      EXPECT_TRUE(
          gkt::enskog_first_sonine_closed_form(d, name).dilute_limit().equals(gkt::first_sonine_closed_form(d, name)))
          << d << " " << name;
    EXPECT_TRUE(gkt::enskog_first_sonine_closed_form(d, "bulk_viscosity").dilute_limit().numerator.is_zero());
    EXPECT_TRUE(gkt::enskog_first_sonine_closed_form(d, "cooling_rate_first_order").dilute_limit().numerator.is_zero());
    EXPECT_TRUE(gkt::enskog_first_sonine_closed_form(d, "pressure").dilute_limit().equals(of(RationalPolynomial(1L))));
  }
}

// The engine's η*, bulk viscosity and κ* equal Garzó & Dufty's published first-Sonine forms
// (with a2, linear in a2 in every Sonine sum) as exact functions of α, φ and χ, d = 2 and 3.
TEST(EnskogClosedForm, EqualsGarzoDuftyExactly) {
  for (int d : {2, 3}) {
    const auto gd = garzo_dufty_forms(d);
    EXPECT_TRUE(gkt::enskog_first_sonine_closed_form(d, "shear_viscosity").equals(gd.eta)) << d;
    EXPECT_TRUE(gkt::enskog_first_sonine_closed_form(d, "bulk_viscosity").equals(gd.bulk)) << d;
    EXPECT_TRUE(gkt::enskog_first_sonine_closed_form(d, "thermal_conductivity").equals(gd.kappa)) << d;
  }
}

// With f0 Maxwellian (a2 = 0) the closed forms and the numerical solver at order 1 solve the same
// equations by two routes (exact symbolic assembly vs long-double tables and LU): every
// coefficient, μ* and ζ_U included, agrees to 1e-12 (relative) for d = 2, 3, three α, three φ.
TEST(EnskogClosedForm, AgreesWithNumericalSolverMaxwellian) {
  const RationalFunction zero{RationalPolynomial(0L), RationalPolynomial(1L)};
  for (int d : {2, 3}) {
    gkt::NavierStokesSolver ns(d);
    std::map<std::string, EnskogClosedForm> f;
    for (const auto& name : gkt::enskog_closed_form_coefficients())
      f[name] = gkt::enskog_first_sonine_closed_form(d, name, zero);
    for (const Rational& alpha : {Rational(9, 10), Rational(1, 2), Rational(1, 5)})
      for (const Rational& phi : {Rational(1, 10), Rational(3, 10), Rational(9, 20)}) {
        const auto st = enskog(d, phi);
        const auto v = ns.solve(alpha, 1, {1.0, 0.0}, gkt::SonineScheme::standard, st);
        auto at = [&](const std::string& name) {
          return f[name].evaluate(alpha, st.packing_fraction, st.chi, st.phi_dchi);
        };
        EXPECT_NEAR(at("shear_viscosity") / v.shear_viscosity, 1, 1e-12) << d << " " << alpha << " " << phi;
        EXPECT_NEAR(at("bulk_viscosity") / v.bulk_viscosity, 1, 1e-12) << d << " " << alpha << " " << phi;
        EXPECT_NEAR(at("thermal_conductivity") / v.thermal_conductivity, 1, 1e-12) << d << " " << alpha;
        EXPECT_NEAR(at("density_heat_coefficient") / v.density_heat_coefficient, 1, 1e-12) << d << " " << alpha;
        EXPECT_NEAR(at("cooling_rate_first_order") / v.cooling_rate_first_order, 1, 1e-12) << d << " " << alpha;
        EXPECT_NEAR(at("pressure") / st.pressure(d, alpha.to_double()), 1, 1e-15);
      }
  }
}

// With the van Noije–Ernst a2 the solver keeps the a2² products of its Sonine sums that the
// closed forms (like the published ones) drop: they differ by O(a2²), at most 0.061 a2² here.
TEST(EnskogClosedForm, DiffersFromSolverOnlyAtSecondOrderInA2) {
  for (int d : {2, 3}) {
    gkt::NavierStokesSolver ns(d);
    const auto hcs = gkt::first_sonine_hcs(d);
    std::map<std::string, EnskogClosedForm> f;
    for (const auto& name : gkt::enskog_closed_form_coefficients())
      f[name] = gkt::enskog_first_sonine_closed_form(d, name);
    for (const Rational& alpha : {Rational(9, 10), Rational(1, 2), Rational(1, 5)})
      for (const Rational& phi : {Rational(1, 10), Rational(2, 5)}) {
        const double a2 = hcs.a2.evaluate(alpha).to_double();
        const auto st = enskog(d, phi);
        const auto v = ns.solve(alpha, 1, {1.0, 0.0, a2}, gkt::SonineScheme::standard, st);
        auto rel = [&](const std::string& name, double value) {
          return std::abs(f[name].evaluate(alpha, st.packing_fraction, st.chi, st.phi_dchi) / value - 1);
        };
        const double tol = 0.1 * a2 * a2;  // measured ≤ 0.061 a2² (μ*, d = 2, α = 0.2)
        EXPECT_LE(rel("shear_viscosity", v.shear_viscosity), tol) << d << " " << alpha << " " << phi;
        EXPECT_LE(rel("thermal_conductivity", v.thermal_conductivity), tol) << d << " " << alpha << " " << phi;
        EXPECT_LE(rel("density_heat_coefficient", v.density_heat_coefficient), tol) << d << " " << alpha;
        EXPECT_LE(rel("cooling_rate_first_order", v.cooling_rate_first_order), tol) << d << " " << alpha;
        std::cout << "[ a2 ] d=" << d << " alpha=" << alpha << " phi=" << phi << " a2^2=" << a2 * a2 << " eta "
                  << rel("shear_viscosity", v.shear_viscosity) << " kappa "
                  << rel("thermal_conductivity", v.thermal_conductivity) << " mu "
                  << rel("density_heat_coefficient", v.density_heat_coefficient) << " zetaU "
                  << rel("cooling_rate_first_order", v.cooling_rate_first_order) << "\n";
      }
  }
}

// α = 1, 3D: Chapman & Cowling (1970) §16.41–16.42 first approximation, exactly:
// η* = (1/χ)(1 + 8φχ/5)² + (768/25π) φ²χ, κ* = (1/χ)(1 + 12φχ/5)² + (512/25π) φ²χ, μ* = ζ_U = 0.
TEST(EnskogClosedForm, ElasticLimitIsChapmanCowling) {
  auto at_one = [](const EnskogClosedForm& f) {
    EnskogClosedForm g;
    for (const auto& [m, r] : f.terms()) g = g + c(r.evaluate(Rational(1)), m);
    return g;
  };
  const EnskogMonomial inv_chi{0, -1, 0, 0}, phi{1, 0, 0, 0}, phi2_chi{2, 1, 0, 0};
  const auto eta = c(Rational(1), inv_chi) + c(Rational(16, 5), phi) + c(Rational(64, 25), phi2_chi) +
                   c(Rational(768, 25), kPhi2ChiOverPi);
  const auto kappa = c(Rational(1), inv_chi) + c(Rational(24, 5), phi) + c(Rational(144, 25), phi2_chi) +
                     c(Rational(512, 25), kPhi2ChiOverPi);
  EXPECT_TRUE(at_one(gkt::enskog_first_sonine_closed_form(3, "shear_viscosity")).equals(eta));
  EXPECT_TRUE(at_one(gkt::enskog_first_sonine_closed_form(3, "thermal_conductivity")).equals(kappa));
  EXPECT_TRUE(at_one(gkt::enskog_first_sonine_closed_form(3, "density_heat_coefficient")).terms().empty());
  EXPECT_TRUE(at_one(gkt::enskog_first_sonine_closed_form(3, "cooling_rate_first_order")).terms().empty());
}

// π g_d = 2^{2d−1} d/(d+2)², the exact rational the closed forms use for the φ²χ/π terms.
TEST(EnskogClosedForm, GradientFactorTimesPiIsRational) {
  EXPECT_NEAR(gkt::collisional_gradient_factor(3) * std::numbers::pi, 96.0 / 25, 1e-14);
  EXPECT_NEAR(gkt::collisional_gradient_factor(2) * std::numbers::pi, 1.0, 1e-14);
}

TEST(EnskogClosedForm, UnknownCoefficientNamesTheValidOnes) {
  try {
    gkt::enskog_first_sonine_closed_form(3, "viscosity");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("shear_viscosity"), std::string::npos);
  }
}

// The generated per-cell evaluator (`gkt formula --format cpp`, coefficients rounded to double)
// equals the exact closed forms to 1e-13 (relative), d = 2, 3, over α and φ.
TEST(EnskogClosedForm, GeneratedEvaluatorMatchesExactForms) {
  for (int d : {2, 3}) {
    std::map<std::string, EnskogClosedForm> f;
    for (const auto& name : gkt::enskog_closed_form_coefficients())
      f[name] = gkt::enskog_first_sonine_closed_form(d, name);
    for (const Rational& alpha : {Rational(1), Rational(7, 10), Rational(3, 10)})
      for (const Rational& phi : {Rational(1, 20), Rational(2, 5)}) {
        const auto st = enskog(d, phi);
        const auto v = gkt::enskog_first_sonine_values(d, alpha.to_double(), st);
        const double values[] = {v.a2,
                                 v.cooling_rate,
                                 v.pressure,
                                 v.shear_viscosity,
                                 v.bulk_viscosity,
                                 v.thermal_conductivity,
                                 v.density_heat_coefficient,
                                 v.cooling_rate_first_order};
        std::size_t i = 0;
        for (const auto& name : gkt::enskog_closed_form_coefficients()) {
          const double exact = f[name].evaluate(alpha, st.packing_fraction, st.chi, st.phi_dchi);
          EXPECT_NEAR(values[i++], exact, 1e-13 * std::max(1.0, std::abs(exact))) << d << " " << name << " " << alpha;
        }
      }
  }
}
