// Linear stability of the HCS (theory.md §14): the closed-form critical wave numbers against the
// eigenvalues of the linearised hydrodynamic matrix computed numerically (Eigen).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>

#include "gkt/evolution/hcs_stability.hpp"
#include "gkt/models/transport_model.hpp"
#include "gkt/transport/common/pair_correlation.hpp"
#include "gkt/transport/monodisperse/homogeneous_cooling_state.hpp"
#include "gkt/transport/monodisperse/navier_stokes.hpp"
#include "gkt/transport/viscoelastic/viscoelastic_transport.hpp"

namespace {

Eigen::Vector3cd eigenvalues(int d, double zeta, double eta, double kappa, double mu, double k,
                             const gkt::StabilityDensity& dense = {}) {
  const auto m = gkt::longitudinal_matrix(d, zeta, eta, kappa, mu, k, dense);
  Eigen::Matrix3cd e;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) e(r, c) = m[r][c];
  return Eigen::ComplexEigenSolver<Eigen::Matrix3cd>(e).eigenvalues();
}

/// The heat mode: the eigenvalue with the smallest imaginary part.
std::complex<double> heat_mode(const Eigen::Vector3cd& values) {
  int best = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(values(i).imag()) < std::abs(values(best).imag())) best = i;
  return values(best);
}

}  // namespace

// With the solver's ζ*, η*, κ*, μ* (α = 0.8 and 0.6, order 4, d = 2, 3): the heat-mode eigenvalue
// of the 3×3 longitudinal matrix is real and changes sign exactly at k∥c (closed form (14.3)), and
// the numerical determinant equals (k²/2)(ζ/2 − ((d+2)/(2(d−1)))(κ − μ) k²).
TEST(HcsStability, HeatModeCrossesZeroAtTheClosedFormWavenumber) {
  for (int d : {2, 3}) {
    gkt::NavierStokesSolver ns(d);
    gkt::HomogeneousCoolingState hcs(d);
    for (const gkt::Rational& alpha : {gkt::Rational(4, 5), gkt::Rational(3, 5)}) {
      const auto state = hcs.solve(alpha, 5, gkt::HcsScheme::nonlinear);
      const auto v = ns.solve(alpha, 4, state.a);
      const double zeta = state.cooling_rate;
      const auto s = gkt::hcs_stability(d, zeta, v.shear_viscosity, v.thermal_conductivity, v.density_heat_coefficient);
      ASSERT_GT(s.heat_wavenumber, 0);
      const auto below = heat_mode(eigenvalues(d, zeta, v.shear_viscosity, v.thermal_conductivity,
                                               v.density_heat_coefficient, 0.999 * s.heat_wavenumber));
      const auto above = heat_mode(eigenvalues(d, zeta, v.shear_viscosity, v.thermal_conductivity,
                                               v.density_heat_coefficient, 1.001 * s.heat_wavenumber));
      EXPECT_GT(below.real(), 0) << d << " " << alpha;
      EXPECT_LT(above.real(), 0) << d << " " << alpha;
      EXPECT_LT(std::abs(below.imag()), 1e-12);
      for (double k : {0.3, 0.7, 1.3}) {
        const auto ev = eigenvalues(d, zeta, v.shear_viscosity, v.thermal_conductivity, v.density_heat_coefficient, k);
        const std::complex<double> det = ev(0) * ev(1) * ev(2);
        const double closed =
            k * k / 2 *
            (zeta / 2 - (d + 2.0) / (2 * (d - 1)) * (v.thermal_conductivity - v.density_heat_coefficient) * k * k);
        EXPECT_NEAR(det.real(), closed, 1e-12 * (1 + std::abs(closed)));
        EXPECT_NEAR(det.imag(), 0.0, 1e-12);
      }
      // Shear modes: growth rate (ζ* − η* k*²)/2 vanishes at k⊥c; vortices come first (seed 003).
      EXPECT_NEAR(zeta - v.shear_viscosity * s.shear_wavenumber * s.shear_wavenumber, 0.0, 1e-14);
      EXPECT_GT(s.shear_wavenumber, s.heat_wavenumber);
      EXPECT_NEAR(s.critical_length, 2 * M_PI / s.shear_wavenumber, 1e-12);
    }
  }
}

// Viscoelastic spheres (theory.md (14.6)): ζ ∝ n T^{λ_T} with λ_T(δ') from the transport series
// (3/5 as δ' → 0). With the series' ζ*, η*, κ*, μ*, λ_T at δ' = 0.05, 0.2 (order 3), the heat-mode
// eigenvalue changes sign at k∥c, the determinant is (k²/2)((1 − λ_T)ζ* − K_U k²), and λ_T = ½ would
// put k∥c 9–11 % higher.
TEST(HcsStability, ViscoelasticHeatModeUsesTheCoolingTemperatureExponent) {
  const auto series = gkt::viscoelastic_transport_series(3);
  for (const double x : {0.05, 0.2}) {
    const auto v = gkt::viscoelastic_state(series, x);
    const double zeta = v.cooling_rate, eta = v.shear_viscosity, kappa = v.thermal_conductivity,
                 mu = v.density_heat_coefficient;
    gkt::StabilityDensity dilute;
    dilute.cooling_temperature_exponent = v.cooling_temperature_exponent;
    EXPECT_NEAR(dilute.cooling_temperature_exponent, 0.6, 0.05) << x;
    const auto s = gkt::hcs_stability(3, zeta, eta, kappa, mu, dilute);
    const auto below = heat_mode(eigenvalues(3, zeta, eta, kappa, mu, 0.999 * s.heat_wavenumber, dilute));
    const auto above = heat_mode(eigenvalues(3, zeta, eta, kappa, mu, 1.001 * s.heat_wavenumber, dilute));
    EXPECT_GT(below.real(), 0) << x;
    EXPECT_LT(above.real(), 0) << x;
    for (double k : {0.1, 0.4}) {
      const auto ev = eigenvalues(3, zeta, eta, kappa, mu, k, dilute);
      const double closed =
          k * k / 2 * ((1 - dilute.cooling_temperature_exponent) * zeta - 5.0 / 4 * (kappa - mu) * k * k);
      EXPECT_NEAR((ev(0) * ev(1) * ev(2)).real(), closed, 1e-12 * (1 + std::abs(closed)));
    }
    const auto constant_alpha = gkt::hcs_stability(3, zeta, eta, kappa, mu);
    EXPECT_GT(constant_alpha.heat_wavenumber / s.heat_wavenumber, 1.08) << x;
  }
}

// Elastic gas: no cooling, no instability (infinite critical size).
TEST(HcsStability, ElasticGasIsStable) {
  const auto s = gkt::hcs_stability(3, 0.0, 1.016, 1.025, 0.0);
  EXPECT_EQ(s.shear_wavenumber, 0.0);
  EXPECT_EQ(s.heat_wavenumber, 0.0);
  EXPECT_TRUE(std::isinf(s.critical_length));
}

// Dense gas (Enskog, theory.md (14.4)–(14.5)), with the solver's order-4 coefficients at φ = 0.3
// (α = 0.8, 0.6; d = 2, 3; ζ* = χ ζ*_dilute): the heat-mode eigenvalue of the dense longitudinal
// matrix — which also carries the bulk viscosity and ζ_U — changes sign at the closed-form k∥c,
// whose determinant leaves both out; the shear mode at √(ζ*/η*). At φ → 0 the dense input gives
// the dilute values.
TEST(HcsStability, DenseHeatModeCrossesZeroAtTheClosedFormWavenumber) {
  for (int d : {2, 3}) {
    gkt::NavierStokesSolver ns(d);
    gkt::HomogeneousCoolingState hcs(d);
    const auto& pc = gkt::pair_correlation("carnahan-starling");
    for (const gkt::Rational& alpha : {gkt::Rational(4, 5), gkt::Rational(3, 5)}) {
      const gkt::Rational phi(3, 10);
      const double chi = pc.contact_value(d, phi).to_double(), dchi = pc.packing_derivative(d, phi).to_double();
      const gkt::EnskogState st{0.3, chi, dchi};
      const auto state = hcs.solve(alpha, 5, gkt::HcsScheme::nonlinear);
      const auto v = ns.solve(alpha, 4, state.a, gkt::SonineScheme::standard, st);
      const double a = alpha.to_double(), zeta = chi * state.cooling_rate;
      gkt::StabilityDensity density;
      density.pressure = st.pressure(d, a);
      density.pressure_derivative = (d == 3 ? 2.0 : 1.0) * (1 + a) * 0.3 * (chi + dchi);
      density.log_chi_derivative = dchi / chi;
      density.bulk_viscosity = v.bulk_viscosity;
      density.cooling_rate_first_order = v.cooling_rate_first_order;
      const auto s =
          gkt::hcs_stability(d, zeta, v.shear_viscosity, v.thermal_conductivity, v.density_heat_coefficient, density);
      ASSERT_GT(s.heat_wavenumber, 0) << d << " " << alpha;
      auto heat = [&](double k) {
        return heat_mode(
            eigenvalues(d, zeta, v.shear_viscosity, v.thermal_conductivity, v.density_heat_coefficient, k, density));
      };
      EXPECT_GT(heat(0.999 * s.heat_wavenumber).real(), 0) << d << " " << alpha;
      EXPECT_LT(heat(1.001 * s.heat_wavenumber).real(), 0) << d << " " << alpha;
      EXPECT_NEAR(zeta - v.shear_viscosity * s.shear_wavenumber * s.shear_wavenumber, 0.0, 1e-14);
      std::cout << "[ dense ] d=" << d << " alpha=" << alpha << " phi=0.3: k_shear=" << s.shear_wavenumber
                << " k_heat=" << s.heat_wavenumber << "\n";
    }
  }
  gkt::StabilityDensity dilute;
  const auto a = gkt::hcs_stability(3, 0.2, 1.1, 1.2, 0.3, dilute);
  const auto b = gkt::hcs_stability(3, 0.2, 1.1, 1.2, 0.3);
  EXPECT_EQ(a.heat_wavenumber, b.heat_wavenumber);
  EXPECT_NEAR(b.heat_wavenumber, std::sqrt(2 * 0.2 / (5 * (1.2 - 0.3))), 1e-15);
}

namespace {

/// k⊥c*, k∥c*, L_c* of `model` at `point`, order `order`, through the model interface.
std::vector<gkt::CoefficientValue> critical_values(const std::string& model, const gkt::ParameterPoint& point,
                                                   int order) {
  gkt::OrderRequest request;
  request.order = order;
  return gkt::make_transport_model(model)->evaluate(
      point, {"critical_wavenumber_shear", "critical_wavenumber_heat", "critical_length"}, request);
}

/// The elastic end (docs/conventions.md): both wave numbers exactly 0, L_c* = +∞, errors 0; and the
/// approach to it is continuous: k* ∝ √ζ* ∝ √ε and L_c* ∝ 1/√ε as the inelasticity ε → 0, so
/// k*/√ε and L_c*·√ε settle to the same limits at ε = 10⁻⁴ and 10⁻⁶ (to 1 %).
void expect_continuous_elastic_limit(const std::string& model,
                                     const std::function<gkt::ParameterPoint(const gkt::Rational&)>& at, int order) {
  const auto elastic = critical_values(model, at(gkt::Rational(0)), order);
  for (int c = 0; c < 2; ++c) {
    EXPECT_TRUE(elastic[c].defined && !elastic[c].infinite) << model << " " << c;
    EXPECT_EQ(elastic[c].value, gkt::Rational(0)) << model << " " << c;
    EXPECT_EQ(elastic[c].error, gkt::Rational(0)) << model << " " << c;
  }
  EXPECT_TRUE(elastic[2].defined && elastic[2].infinite && elastic[2].converged) << model;
  EXPECT_EQ(elastic[2].error, gkt::Rational(0)) << model;
  const auto near = critical_values(model, at(gkt::Rational(1, 10000)), order),
             nearer = critical_values(model, at(gkt::Rational(1, 1000000)), order);
  for (int c = 0; c < 3; ++c) {
    ASSERT_TRUE(near[c].defined && !near[c].infinite && nearer[c].defined && !nearer[c].infinite) << model;
    const double power = c < 2 ? -0.5 : 0.5;  // k/√ε, L·√ε
    const double a = near[c].value.to_double() * std::pow(1e-4, power),
                 b = nearer[c].value.to_double() * std::pow(1e-6, power);
    EXPECT_GT(a, 0) << model << " " << c;
    EXPECT_NEAR(b / a, 1, 1e-2) << model << " " << c;
  }
}

}  // namespace

// α = 1 (or δ' = 0) is a valid state: the elastic gas never clusters. Every model answers k⊥c* =
// k∥c* = 0 and L_c* = +∞ (printed inf), continuously with α → 1 — before, converting L_c* = ∞ to a
// rational threw "Rational: non-finite double" and a sweep through α = 1 lost every row.
TEST(HcsStability, ElasticLimitIsContinuousInEveryModel) {
  for (const char* hcs : {"nonlinear", "linear"})
    for (const double phi : {0.0, 0.3}) {
      expect_continuous_elastic_limit(
          "smooth-inelastic",
          [&](const gkt::Rational& e) {
            gkt::ParameterPoint p;
            p.numbers["alpha"] = gkt::Rational(1) - e;
            p.numbers["packing_fraction"] = gkt::Rational::from_double(phi);
            p.choices["hcs"] = hcs;
            return p;
          },
          hcs == std::string("linear") ? 1 : 2);
    }
  expect_continuous_elastic_limit(
      "mixture",
      [](const gkt::Rational& e) {
        gkt::ParameterPoint p;
        const gkt::Rational alpha = gkt::Rational(1) - e;
        p.numbers = {{"species", gkt::Rational(2)},         {"mass_1", gkt::Rational(1)},
                     {"mass_2", gkt::Rational(2)},          {"diameter_1", gkt::Rational(1)},
                     {"diameter_2", gkt::Rational(3, 2)},   {"fraction_1", gkt::Rational(1, 2)},
                     {"fraction_2", gkt::Rational(1, 2)},   {"alpha", alpha},
                     {"packing_fraction", gkt::Rational(0)}};
        return p;
      },
      1);
  expect_continuous_elastic_limit(
      "viscoelastic",
      [](const gkt::Rational& e) {
        gkt::ParameterPoint p;
        // ζ* ∝ δ' (theory.md (13.3)): δ' = ε plays the role of the inelasticity.
        p.numbers["delta_prime"] = e;
        return p;
      },
      1);
}
