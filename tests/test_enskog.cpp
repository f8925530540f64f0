// Dense (Enskog) smooth inelastic gas: the collisional-transfer integrals against Monte Carlo,
// the published first-Sonine Navier–Stokes coefficients (Garzó & Dufty 1999 in d dimensions),
// Chapman–Cowling's elastic Enskog values, exact invariants and the dilute limit.
#include <gtest/gtest.h>

#include <cmath>

#include "gkt/collision/quadratic_form_moments.hpp"
#include "gkt/operators/collisional_transfer.hpp"
#include "gkt/operators/linearized_operator.hpp"
#include "gkt/transport/common/pair_correlation.hpp"
#include "gkt/transport/monodisperse/homogeneous_cooling_state.hpp"
#include "gkt/transport/monodisperse/navier_stokes.hpp"
#include "monte_carlo.hpp"

using gkt::Rational;
using gkt::RationalPolynomial;
using gkt::Slot;
using gkt::test::Collision;
using gkt::test::Vec;

namespace {

gkt::EnskogState enskog(int d, const Rational& phi) {
  const auto& pc = gkt::pair_correlation("carnahan-starling");
  return {phi.to_double(), pc.contact_value(d, phi).to_double(), pc.packing_derivative(d, phi).to_double()};
}

/// Garzó & Dufty, PRE 59, 5895 (1999), first Sonine, standard scheme, written in d dimensions
/// with a2 (Garzó, Santos & Montanero, Physica A 376, 94 (2007); Garzó, Granular Gaseous Flows
/// (2019) ch. 5): η*, bulk viscosity, κ*; ν, ζ the dilute first-Sonine values times χ.
struct GarzoDufty {
  double eta, bulk, kappa;
};
GarzoDufty garzo_dufty(int d, double a, double a2, double phi, double chi, const gkt::FirstSonineNavierStokes& fs) {
  const Rational al = Rational::from_double(a);
  const double nue = fs.nu_eta_0.evaluate(al).to_double() + a2 * fs.nu_eta_a2.evaluate(al).to_double();
  const double nuk = fs.nu_kappa_0.evaluate(al).to_double() + a2 * fs.nu_kappa_a2.evaluate(al).to_double();
  const double z = fs.zeta_0.evaluate(al).to_double() + a2 * fs.zeta_a2.evaluate(al).to_double();
  const double pc = phi * chi, dd = d;
  const double eta_k = (1 - std::pow(2.0, d - 2) / (dd + 2) * (1 + a) * (1 - 3 * a) * pc) / (chi * (nue - z / 2));
  const double bulk = std::pow(2.0, 2 * d + 1) / (M_PI * (dd + 2)) * phi * phi * chi * (1 + a) * (1 - a2 / 16);
  const double eta = eta_k * (1 + std::pow(2.0, d - 1) / (dd + 2) * pc * (1 + a)) + dd / (dd + 2) * bulk;
  const double kappa_k =
      (dd - 1) / dd *
      (1 + 2 * a2 + 3 * std::pow(2.0, d - 3) / (dd + 2) * pc * (1 + a) * (1 + a) * (2 * a - 1 + a2 * (1 + a))) /
      (chi * (nuk - 2 * z));
  const double kappa = kappa_k * (1 + 3 * std::pow(2.0, d - 2) / (dd + 2) * pc * (1 + a)) +
                       std::pow(2.0, 2 * d + 1) * (dd - 1) / ((dd + 2) * (dd + 2) * M_PI) * phi * phi * chi * (1 + a) *
                           (1 + 7 * a2 / 16);
  return {eta, bulk, kappa};
}

}  // namespace

// The moments of H = (1+α)(σ̂·g)σ̂ with the weights (σ̂·g)^{−1} and (σ̂·g)^0 — the new integrand
// shapes of the collisional transfer — against Monte Carlo (GSL, 400k samples, 5σ).
TEST(QuadraticFormMoments, AgreeWithMonteCarlo) {
  for (int d : {2, 3}) {
    const Rational alpha(3, 5);
    const gkt::CollisionPair pair{d, Rational(1), Rational(1), Rational(1), Rational(1)};
    const auto c1 = gkt::slot_vector(Slot::v1), c2 = gkt::slot_vector(Slot::v2), c1p = gkt::slot_vector(Slot::v1_post);
    const auto h = gkt::collision_vector();
    const auto g2 = gkt::combine(c1, c2, Rational(1));  // c1 + c2 = 2G
    const gkt::QuadraticFormMoments<Rational> m1(
        pair, alpha, {gkt::dot_form(c1p, h), gkt::dot_form(c1p, c2), gkt::dot_form(c1p, c1p), gkt::dot_form(h, h)},
        {1, 1, 1, 1}, Rational(-1));
    const gkt::QuadraticFormMoments<Rational> m2(
        pair, alpha, {gkt::dot_form(h, g2), gkt::dot_form(h, c2), gkt::dot_form(c2, c2), gkt::dot_form(c1, c1)},
        {1, 2, 1, 1}, Rational(-1));
    const gkt::QuadraticFormMoments<Rational> m0(pair, alpha, {gkt::dot_form(h, c2), gkt::dot_form(c1, c1)}, {1, 1},
                                                 Rational(0));
    const double exact[] = {m1.moment({1, 1, 1, 0}).to_double(), m1.moment({0, 0, 0, 1}).to_double(),
                            m2.moment({1, 1, 1, 0}).to_double(), m2.moment({0, 2, 0, 1}).to_double(),
                            m0.moment({1, 1, 0, 0}).to_double()};
    const double a = alpha.to_double();
    auto vec_h = [&](const Collision& c) {
      Vec r{};
      for (int k = 0; k < d; ++k) r[k] = c.v1[k] - c.v2[k] - c.v1p[k] + c.v2p[k];
      return r;
    };
    auto dot = [&](const Vec& x, const Vec& y) { return gkt::test::dot(x, y, d); };
    auto inv_u = [&](const Collision& c) { return (1 + a) / std::sqrt(dot(vec_h(c), vec_h(c))); };  // 1/(σ̂·g)
    auto plus = [&](const Vec& x, const Vec& y) {
      Vec r{};
      for (int k = 0; k < d; ++k) r[k] = x[k] + y[k];
      return r;
    };
    std::vector<std::function<double(const Collision&)>> f{
        [&](const Collision& c) { return inv_u(c); },
        [&](const Collision& c) { return inv_u(c) * dot(c.v1p, vec_h(c)) * dot(c.v1p, c.v2) * dot(c.v1p, c.v1p); },
        [&](const Collision& c) { return inv_u(c) * dot(vec_h(c), vec_h(c)); },
        [&](const Collision& c) {
          return inv_u(c) * dot(vec_h(c), plus(c.v1, c.v2)) * dot(vec_h(c), c.v2) * dot(c.v2, c.v2);
        },
        [&](const Collision& c) { return inv_u(c) * std::pow(dot(vec_h(c), c.v2), 2) * dot(c.v1, c.v1); },
        [&](const Collision& c) { return dot(vec_h(c), c.v2) * dot(c.v1, c.v1); },
    };
    gkt::test::CollisionSampler sampler(d, 1, 1, 1, 1, a, 4242 + d);
    const auto mc = gkt::test::weighted_averages(sampler, 400000, f);
    for (int i = 0; i < 4; ++i) {  // s = −1: ratio of two weighted means
      const double r = mc[i + 1].mean / mc[0].mean;
      const double err = std::abs(r) * std::hypot(mc[i + 1].error / mc[i + 1].mean, mc[0].error / mc[0].mean);
      EXPECT_NEAR(exact[i], r, 5 * err + 1e-4) << "d=" << d << " integrand " << i;
    }
    EXPECT_NEAR(exact[4], mc[5].mean, 5 * mc[5].error) << "d=" << d;
  }
}

// p* = 1 + 2^{d−2}(1+α)φχ holds whatever the cumulants: ⟨H² S_k(X1) S_l(X2)⟩_{−1} = (1+α)² δ_k0 δ_l0
// as exact polynomials in α (k, l ≤ 3), and e_d = 2^{d−1} d.
TEST(Enskog, PressureIndependentOfCumulants) {
  const auto alpha = RationalPolynomial::variable();
  for (int d : {2, 3}) {
    const gkt::CollisionPair pair{d, Rational(1), Rational(1), Rational(1), Rational(1)};
    const auto h = gkt::collision_vector();
    const auto c1 = gkt::slot_vector(Slot::v1), c2 = gkt::slot_vector(Slot::v2);
    const gkt::QuadraticFormMoments<RationalPolynomial> m(
        pair, alpha, {gkt::dot_form(h, h), gkt::dot_form(c1, c1), gkt::dot_form(c2, c2)}, {1, 3, 3}, Rational(-1));
    const RationalPolynomial one_plus = RationalPolynomial(Rational(1)) + alpha;
    EXPECT_EQ(m.moment({1, 0, 0, 0}), one_plus * one_plus) << d;
    // ⟨H² X1^a X2^b⟩ depends on a, b only through ⟨X⟩-moments of degree ≤ 1 beyond the Maxwellian:
    // contracting with S_k (k ≥ 2) removes it — check k = 2 through its polynomial x² − (d+2)x + d(d+2)/4.
    const Rational half_d(d, 2);
    RationalPolynomial s2 = m.moment({1, 2, 0, 0}) * RationalPolynomial(Rational(1, 2)) -
                            m.moment({1, 1, 0, 0}) * RationalPolynomial(half_d + Rational(1)) +
                            m.moment({1, 0, 0, 0}) * RationalPolynomial(half_d * (half_d + Rational(1)) / Rational(2));
    EXPECT_TRUE(s2.is_zero()) << d << ": " << s2.to_string();
    EXPECT_NEAR(gkt::collisional_transfer_factor(d), std::pow(2.0, d - 1) * d, 1e-12);
  }
}

// First Sonine about the Maxwellian (a2 = 0): η*, bulk viscosity and κ* equal Garzó & Dufty's
// closed forms to round-off for d = 2, 3, α from 1 to 0.2, φ up to the largest allowed.
TEST(Enskog, FirstSonineEqualsGarzoDuftyMaxwellian) {
  for (int d : {2, 3}) {
    gkt::NavierStokesSolver ns(d);
    const auto fs = gkt::first_sonine_navier_stokes(d);
    for (const Rational& alpha : {Rational(1), Rational(7, 10), Rational(1, 2), Rational(1, 5)})
      for (const Rational& phi : {Rational(1, 10), Rational(3, 10), d == 3 ? Rational(1, 2) : Rational(7, 10)}) {
        const auto st = enskog(d, phi);
        const auto v = ns.solve(alpha, 1, {1.0, 0.0}, gkt::SonineScheme::standard, st);
        const auto gd = garzo_dufty(d, alpha.to_double(), 0.0, st.packing_fraction, st.chi, fs);
        EXPECT_NEAR(v.shear_viscosity / gd.eta, 1.0, 1e-12) << d << " " << alpha << " " << phi;
        EXPECT_NEAR(v.bulk_viscosity / gd.bulk, 1.0, 1e-12) << d << " " << alpha << " " << phi;
        EXPECT_NEAR(v.thermal_conductivity / gd.kappa, 1.0, 1e-12) << d << " " << alpha << " " << phi;
      }
  }
}

// With f0 = f_M(1 + a2 S2) (van Noije–Ernst a2) the engine keeps the a2² products of the
// collisional terms that the published forms drop: agreement within 0.1 a2² (relative).
TEST(Enskog, FirstSonineEqualsGarzoDuftyToOrderA2) {
  for (int d : {2, 3}) {
    gkt::NavierStokesSolver ns(d);
    gkt::HomogeneousCoolingState h(d);
    const auto fs = gkt::first_sonine_navier_stokes(d);
    for (const Rational& alpha : {Rational(9, 10), Rational(1, 2), Rational(1, 5)})
      for (const Rational& phi : {Rational(1, 5), Rational(2, 5)}) {
        const double a2 = h.solve(alpha, 2, gkt::HcsScheme::linear).exact_a2->to_double();
        const auto st = enskog(d, phi);
        const auto v = ns.solve(alpha, 1, {1.0, 0.0, a2}, gkt::SonineScheme::standard, st);
        const auto gd = garzo_dufty(d, alpha.to_double(), a2, st.packing_fraction, st.chi, fs);
        const double tol = 0.1 * a2 * a2;
        EXPECT_NEAR(v.shear_viscosity / gd.eta, 1.0, tol) << d << " " << alpha << " " << phi;
        EXPECT_NEAR(v.bulk_viscosity / gd.bulk, 1.0, tol) << d << " " << alpha << " " << phi;
        EXPECT_NEAR(v.thermal_conductivity / gd.kappa, 1.0, tol) << d << " " << alpha << " " << phi;
      }
  }
}

// Elastic hard spheres (Chapman & Cowling 1970 §16.41–16.42, first approximation, b n = 4φ):
//   η* = (1/χ)(1 + 8φχ/5)² + (768/(25π)) φ²χ,  κ* = (1/χ)(1 + 12φχ/5)² + (512/(25π)) φ²χ;
// and at α = 1 the collisional sources are pure first Sonine (projections on S_p, p ≥ 1 (shear)
// and p ≥ 2 (heat) vanish exactly), so the kinetic equations are the dilute ones rescaled.
TEST(Enskog, ElasticLimitChapmanCowling) {
  gkt::NavierStokesSolver ns(3);
  for (const Rational& phi : {Rational(1, 10), Rational(1, 4), Rational(1, 2)}) {
    const auto st = enskog(3, phi);
    const auto v = ns.solve(Rational(1), 1, {1.0, 0.0}, gkt::SonineScheme::standard, st);
    const double f = st.packing_fraction, chi = st.chi;
    EXPECT_NEAR(v.shear_viscosity, std::pow(1 + 1.6 * f * chi, 2) / chi + 768 / (25 * M_PI) * f * f * chi, 1e-12);
    EXPECT_NEAR(v.thermal_conductivity, std::pow(1 + 2.4 * f * chi, 2) / chi + 512 / (25 * M_PI) * f * f * chi, 1e-12);
    EXPECT_NEAR(v.density_heat_coefficient, 0.0, 1e-13);
  }
  for (int d : {2, 3}) {
    const auto m = gkt::collisional_transfer_moments<Rational>(d, Rational(1), 4, 0);
    for (int p = 1; p <= 4; ++p) EXPECT_TRUE(m.shear_source[m.index(p, 0, 0)].is_zero()) << d << " " << p;
    for (int p = 2; p <= 4; ++p) {
      EXPECT_TRUE(m.heat_source_temperature[m.index(p, 0, 0)].is_zero()) << d << " " << p;
      EXPECT_TRUE(m.heat_source_density[m.index(p, 0, 0)].is_zero()) << d << " " << p;
      EXPECT_TRUE(m.scalar_source[m.index(p, 0, 0)].is_zero()) << d << " " << p;
    }
  }
}

// φ → 0 is continuous (no separate dilute branch): φ = 1e-9 gives the dilute values to 1e-8 at
// order 4; and both schemes agree in the dense gas at α = 0.9 (φ = 0.3, order 4) within the
// truncation error.
TEST(Enskog, DiluteLimitAndSchemesAgree) {
  for (int d : {2, 3}) {
    gkt::NavierStokesSolver ns(d);
    gkt::HomogeneousCoolingState h(d);
    const Rational alpha(9, 10);
    const auto hcs = h.solve(alpha, 5, gkt::HcsScheme::nonlinear).a;
    const auto dilute = ns.solve(alpha, 4, hcs);
    const auto tiny = ns.solve(alpha, 4, hcs, gkt::SonineScheme::standard, enskog(d, Rational(1, 1000000000)));
    EXPECT_NEAR(tiny.shear_viscosity, dilute.shear_viscosity, 1e-8);
    EXPECT_NEAR(tiny.thermal_conductivity, dilute.thermal_conductivity, 1e-8);
    EXPECT_NEAR(tiny.density_heat_coefficient, dilute.density_heat_coefficient, 1e-8);
    EXPECT_LT(tiny.bulk_viscosity, 1e-16);
    const auto st = enskog(d, Rational(3, 10));
    const auto s = ns.solve(alpha, 4, hcs, gkt::SonineScheme::standard, st);
    const auto m = ns.solve(alpha, 4, hcs, gkt::SonineScheme::modified, st);
    // within the order-4 truncation errors (dilute: 4.5e-5 for η*, 2.2e-4 for κ*; docs/performance.md)
    EXPECT_NEAR(s.shear_viscosity / m.shear_viscosity, 1.0, 2e-4) << d;
    EXPECT_NEAR(s.thermal_conductivity / m.thermal_conductivity, 1.0, 1e-3) << d;
    EXPECT_NEAR(s.bulk_viscosity / m.bulk_viscosity, 1.0, 1e-12) << d;  // f0 f0 only: same in both schemes
  }
}

// First-order cooling rate ζ_U. Its f0 ∂f0 part is Garzó & Dufty's
// ζ10 = −(3·2^{d−2}/d) φχ(1 − α²) exactly ((15.12) needs ⟨(H·c2) D_0⟩_{+1} = 3(1+α) as a
// polynomial in α); the full ζ_U vanishes at α = 1 and as φ → 0, its f^(1) part ζ11 = ζ_U − ζ10
// is ∝ φχ(1 − α²) at first Sonine, and the two schemes agree at α = 0.9 within 1e-5 (order 4).
TEST(Enskog, FirstOrderCoolingRate) {
  const auto alpha = RationalPolynomial::variable();
  for (int d : {2, 3}) {
    const auto m = gkt::collisional_transfer_moments<RationalPolynomial>(d, alpha, 1, 0);
    EXPECT_EQ(m.cooling_gradient[m.index(0, 0)],
              RationalPolynomial(Rational(3)) * (RationalPolynomial(Rational(1)) + alpha))
        << d;
    gkt::NavierStokesSolver ns(d);
    EXPECT_EQ(ns.solve(Rational(1), 2, {1.0, 0.0}, gkt::SonineScheme::standard, enskog(d, Rational(3, 10)))
                  .cooling_rate_first_order,
              0.0);
    double ratio = 0;
    for (const Rational& phi : {Rational(1, 10), Rational(4, 10)}) {
      const auto st = enskog(d, phi);
      const double a = 0.5, f = st.packing_fraction * st.chi * (1 - a * a);
      const double zeta_u =
          ns.solve(Rational(1, 2), 1, {1.0, 0.0}, gkt::SonineScheme::standard, st).cooling_rate_first_order;
      const double zeta10 = -3 * std::pow(2.0, d - 2) / d * f;
      const double r = (zeta_u - zeta10) / f;
      if (ratio != 0) {
        EXPECT_NEAR(r, ratio, 1e-12) << d;
      }
      ratio = r;
      EXPECT_GT(std::abs(zeta_u - zeta10), 1e-3 * std::abs(zeta10)) << d;  // ζ11 is not negligible
    }
    gkt::HomogeneousCoolingState h(d);
    const auto hcs = h.solve(Rational(9, 10), 5, gkt::HcsScheme::nonlinear).a;
    const auto st = enskog(d, Rational(3, 10));
    EXPECT_NEAR(ns.solve(Rational(9, 10), 4, hcs, gkt::SonineScheme::standard, st).cooling_rate_first_order,
                ns.solve(Rational(9, 10), 4, hcs, gkt::SonineScheme::modified, st).cooling_rate_first_order, 1e-5)
        << d;
    EXPECT_EQ(ns.solve(Rational(9, 10), 4, hcs).cooling_rate_first_order, 0.0);  // dilute
  }
}

// Energy balance closes: the scalar equation is solved on S_2 … S_{N+1}; its S_1 (energy) row is
// not imposed, and must then hold by itself once ζ_U is the cooling rate computed from the
// collision integrals (15.12)–(15.13). At first Sonine about a Maxwellian, δ̃_2 = (ζ_U − ζ10)/c_2 and
//   χ L(1, 2) δ̃_2 = −(d/2) ζ_U + (1 − p*) − e φχ K(1)/(d(1+α)),
// which ties the energy moment of the gradient term (collisional work (p* − 1)∇·u and ζ10) and
// of the linearized operator (ζ11) together.
TEST(Enskog, EnergyRowClosesWithFirstOrderCoolingRate) {
  for (int d : {2, 3})
    for (const Rational& alpha : {Rational(9, 10), Rational(1, 2), Rational(1, 3)}) {
      const Rational phi(1, 4);
      const auto st = enskog(d, phi);
      const double a = alpha.to_double(), pc = st.packing_fraction * st.chi;
      gkt::NavierStokesSolver ns(d);
      const double zeta_u = ns.solve(alpha, 1, {1.0, 0.0}, gkt::SonineScheme::standard, st).cooling_rate_first_order;
      const double zeta10 = -3 * std::pow(2.0, d - 2) / d * pc * (1 - a * a);
      const auto m = gkt::collisional_transfer_moments<Rational>(d, alpha, 2, 0);
      const double c2 = 2 * (1 - a * a) * st.chi / d * m.cooling_scalar[m.index(2, 0)].to_double();
      const double l12 = gkt::hcs_linearized_operator_matrices<Rational>(d, alpha, 0, 2, 0)[0](1, 2).to_double();
      const double e = gkt::collisional_transfer_factor(d), p_star = st.pressure(d, a);
      const double lhs = st.chi * l12 * (zeta_u - zeta10) / c2;
      const double rhs =
          -0.5 * d * zeta_u + (1 - p_star) - e * pc / (d * (1 + a)) * m.scalar_source[m.index(1, 0, 0)].to_double();
      EXPECT_NEAR(lhs, rhs, 1e-12 * (1 + std::abs(rhs))) << d << " " << alpha;
    }
}

// The pair correlation registry: χ(0) = 1, the derivative against a central difference, and
// an unknown name listing the valid ones.
TEST(PairCorrelation, RegistryAndDerivative) {
  const auto& cs = gkt::pair_correlation("carnahan-starling");
  for (int d : {2, 3}) {
    EXPECT_EQ(cs.contact_value(d, Rational(0)), Rational(1));
    const Rational phi(3, 10), step(1, 1000000);
    const double numeric = phi.to_double() *
                           (cs.contact_value(d, phi + step) - cs.contact_value(d, phi - step)).to_double() /
                           (2 * step.to_double());
    EXPECT_NEAR(cs.packing_derivative(d, phi).to_double(), numeric, 1e-8) << d;
  }
  EXPECT_EQ(cs.contact_value(3, Rational(1, 2)), Rational(6));  // (1 − 1/4)/(1/8)
  try {
    (void)gkt::pair_correlation("percus-yevick");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("valid: \"carnahan-starling\""), std::string::npos) << e.what();
  }
}

// The double forms of every registered closure (the per-cell χ of enskog_state) against the exact
// rational ones at the same φ (the double's exact value), to 1e-14 relative, over [0, φ_max].
TEST(PairCorrelation, DoubleFormsMatchExact) {
  for (const auto& closure : gkt::pair_correlations())
    for (int d : {2, 3}) {
      const double top = gkt::max_packing_fraction(d).to_double();
      for (int k = 0; k <= 64; ++k) {
        const double phi = top * k / 64;
        const Rational exact_phi = Rational::from_double(phi);
        const double chi = closure.contact_value(d, exact_phi).to_double();
        const double dchi = closure.packing_derivative(d, exact_phi).to_double();
        EXPECT_NEAR(closure.contact_value_double(d, phi), chi, 1e-14 * std::abs(chi)) << closure.name << d << phi;
        EXPECT_NEAR(closure.packing_derivative_double(d, phi), dchi, 1e-14 * std::abs(dchi))
            << closure.name << d << phi;
        const gkt::EnskogState state = gkt::enskog_state(d, phi, closure);
        EXPECT_EQ(state.packing_fraction, phi);
        EXPECT_EQ(state.chi, closure.contact_value_double(d, phi));
        EXPECT_EQ(state.phi_dchi, closure.packing_derivative_double(d, phi));
      }
    }
  EXPECT_EQ(gkt::enskog_state(3, 0.25).chi, gkt::enskog_state(3, 0.25, gkt::pair_correlations().front()).chi);
}

// enskog_state refuses a dimension other than 2, 3 and φ outside [0, φ_max] (nan included),
// naming the field and the range.
TEST(PairCorrelation, EnskogStateRefusesBadInput) {
  auto message = [](int d, double phi) {
    try {
      (void)gkt::enskog_state(d, phi);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(3, 0.51), "packing_fraction: must be a number in [0, 0.5] for dimension = 3, got 0.51");
  EXPECT_EQ(message(2, 0.71), "packing_fraction: must be a number in [0, 0.7] for dimension = 2, got 0.71");
  EXPECT_EQ(message(3, -0.1), "packing_fraction: must be a number in [0, 0.5] for dimension = 3, got -0.1");
  EXPECT_NE(message(3, std::nan("")).find("packing_fraction: must be"), std::string::npos);
  EXPECT_EQ(message(4, 0.1), "dimension: must be 2 or 3, got 4");
  EXPECT_NO_THROW((void)gkt::enskog_state(3, 0.5));
  EXPECT_NO_THROW((void)gkt::enskog_state(2, 0.7));
}
