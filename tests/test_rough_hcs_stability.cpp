// Linear stability of the rough gas's HCS (docs/theory.md §19.15): the closed-form critical wave
// numbers (19.32) against the eigenvalues of the longitudinal matrix (19.31) computed numerically
// (Eigen), with the library's first-Sonine coefficients; the smooth limit β = −1 against the smooth
// gas's stability (hcs_stability, theory.md §14) with the smooth solver's first-Sonine coefficients
// at a2 = 0; the elastic perfectly rough gas; the shear mode against √(ζ*/η*) with ζ* from an
// independent solution of Huthmann & Zippelius's equations; sign and trend.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>

#include "gkt/evolution/hcs_stability.hpp"
#include "gkt/evolution/rough_hcs_stability.hpp"
#include "gkt/models/transport_model.hpp"
#include "gkt/transport/monodisperse/navier_stokes.hpp"
#include "gkt/transport/rough/rough_bulk_viscosity.hpp"
#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"
#include "gkt/transport/rough/rough_shear_viscosity.hpp"
#include "gkt/transport/rough/rough_thermal_conductivity.hpp"

using gkt::Rational;

namespace {

/// The library's first-Sonine input at the Maxwellian HCS of (d, α, β, κ).
gkt::RoughStabilityInput input(int d, const Rational& alpha, const Rational& beta, const Rational& kappa) {
  const auto m = gkt::rough_homogeneous_cooling_state(d, alpha, beta, kappa, gkt::RoughHcsScheme::maxwellian);
  const auto q = gkt::rough_thermal_conductivity(d, alpha, beta, kappa);
  const auto b = gkt::rough_bulk_viscosity(d, alpha, beta, kappa);
  gkt::RoughStabilityInput in;
  in.dimension = d;
  in.temperature_ratio = m.temperature_ratio;
  in.cooling_rate = m.cooling_rate;
  in.shear_viscosity = gkt::rough_shear_viscosity(d, alpha, beta, kappa);
  in.bulk_viscosity = b.bulk_viscosity;
  in.thermal_conductivity = q.total;
  in.density_heat_coefficient = q.density_heat_total;
  in.cooling_rate_first_order = b.cooling_rate_first_order;
  return in;
}

Eigen::Vector3cd eigenvalues(const gkt::RoughStabilityInput& in, double k) {
  const auto m = gkt::rough_longitudinal_matrix(in, k);
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

/// k⊥c*, k∥c*, L_c* of `model` at `point` through the model interface (order 1).
std::vector<gkt::CoefficientValue> critical_values(const std::string& model, const gkt::ParameterPoint& point) {
  return gkt::make_transport_model(model)->evaluate(
      point, {"critical_wavenumber_shear", "critical_wavenumber_heat", "critical_length"}, gkt::OrderRequest{});
}

gkt::ParameterPoint rough_point(int d, const Rational& alpha, const Rational& beta, const Rational& kappa) {
  gkt::ParameterPoint p;
  p.numbers = {{"dimension", Rational(d)}, {"alpha", alpha}, {"beta", beta}, {"moment_of_inertia", kappa}};
  p.choices["hcs"] = "maxwellian";
  return p;
}

/// ζ* of the Maxwellian HCS written out independently (theory.md (19.12)): ζ_t = ζ_r solved by
/// bisection in ln θ, ζ* = ((d+2)/4) z_t.
double maxwellian_cooling_rate(int d, double alpha, double beta, double kappa) {
  const double eta = (1 + beta) * kappa / (2 * (1 + kappa)), dr = d == 3 ? 3 : 1;
  auto zt = [&](double theta) {
    return 2.0 / d * ((1 - alpha * alpha) / 2 + (d - 1) * (eta * (1 - eta) - eta * eta * theta / kappa));
  };
  auto zr = [&](double theta) {
    return 2 * (d - 1) / dr * (eta / kappa) * (1 - eta / kappa - eta / theta);  // η/(κτ) = η/θ
  };
  double lo = -20, hi = 20;  // ln θ; ζ_t − ζ_r > 0 at small θ, < 0 at large θ
  for (int i = 0; i < 200; ++i) {
    const double mid = (lo + hi) / 2;
    (zt(std::exp(mid)) - zr(std::exp(mid)) > 0 ? lo : hi) = mid;
  }
  return (d + 2) / 4.0 * zt(std::exp(lo));
}

}  // namespace

// The heat-mode eigenvalue of (19.31) is real and changes sign exactly at k∥c* of (19.32), and the
// numerical determinant is (k²/2)(ζ*/2 − s((d+2)/(2(d−1)))(κ* − μ*)k²) whatever η_b, ζ_U (they drop
// out); the shear mode ½(ζ* − η*k²) vanishes at k⊥c*.
TEST(RoughHcsStability, HeatModeCrossesZeroAtTheClosedFormWavenumber) {
  struct Case {
    int d;
    Rational alpha, beta, kappa;
  };
  for (const Case& c :
       {Case{3, Rational(9, 10), Rational(1, 2), Rational(2, 5)}, Case{3, Rational(1, 2), Rational(0), Rational(2, 5)},
        Case{3, Rational(7, 10), Rational(-1, 2), Rational(1, 4)},
        Case{2, Rational(4, 5), Rational(1, 2), Rational(1, 2)},
        Case{2, Rational(1, 2), Rational(1), Rational(1, 2)}}) {
    const auto in = input(c.d, c.alpha, c.beta, c.kappa);
    ASSERT_NE(in.bulk_viscosity, 0);
    ASSERT_NE(in.cooling_rate_first_order, 0);
    const auto s = gkt::rough_hcs_stability(in);
    ASSERT_GT(s.heat_wavenumber, 0) << c.d << " " << c.alpha << " " << c.beta;
    const auto below = heat_mode(eigenvalues(in, 0.999 * s.heat_wavenumber));
    const auto above = heat_mode(eigenvalues(in, 1.001 * s.heat_wavenumber));
    EXPECT_GT(below.real(), 0) << c.d << " " << c.alpha << " " << c.beta;
    EXPECT_LT(above.real(), 0) << c.d << " " << c.alpha << " " << c.beta;
    EXPECT_LT(std::abs(below.imag()), 1e-12);
    const double share = c.d / (c.d + (c.d == 3 ? 3 : 1) * in.temperature_ratio);
    for (double k : {0.3, 0.7, 1.3}) {
      const auto ev = eigenvalues(in, k);
      const std::complex<double> det = ev(0) * ev(1) * ev(2);
      const double closed = k * k / 2 *
                            (in.cooling_rate / 2 - share * (c.d + 2.0) / (2 * (c.d - 1)) *
                                                       (in.thermal_conductivity - in.density_heat_coefficient) * k * k);
      EXPECT_NEAR(det.real(), closed, 1e-12 * (1 + std::abs(closed)));
      EXPECT_NEAR(det.imag(), 0.0, 1e-12);
    }
    EXPECT_NEAR(in.cooling_rate - in.shear_viscosity * s.shear_wavenumber * s.shear_wavenumber, 0.0, 1e-14);
    EXPECT_NEAR(s.critical_length, 2 * M_PI / std::max(s.shear_wavenumber, s.heat_wavenumber), 1e-12);
  }
}

// β = −1: the spin decouples and the hydrodynamics are the smooth gas's. The model's values equal
// the smooth gas's stability (hcs_stability, theory.md (14.1), (14.3)) with the smooth solver's
// first-Sonine η*, κ*, μ* about the Maxwellian (a2 = 0) and ζ* = ((d+2)/(4d))(1 − α²), to round-off.
TEST(RoughHcsStability, SmoothLimitIsTheSmoothGas) {
  for (int d : {2, 3}) {
    gkt::NavierStokesSolver ns(d);
    for (const Rational& alpha : {Rational(9, 10), Rational(7, 10), Rational(1, 2)}) {
      const auto v = ns.solve(alpha, 1, {1.0, 0.0, 0.0});
      const double a = alpha.to_double(), zeta = (d + 2) / (4.0 * d) * (1 - a * a);
      const auto smooth =
          gkt::hcs_stability(d, zeta, v.shear_viscosity, v.thermal_conductivity, v.density_heat_coefficient);
      for (const Rational& kappa : {Rational(2, 5), Rational(1, 10)}) {
        const auto rough = critical_values("rough", rough_point(d, alpha, Rational(-1), kappa));
        EXPECT_NEAR(rough[0].value.to_double(), smooth.shear_wavenumber, 1e-12 * smooth.shear_wavenumber) << d << alpha;
        EXPECT_NEAR(rough[1].value.to_double(), smooth.heat_wavenumber, 1e-12 * smooth.heat_wavenumber) << d << alpha;
        EXPECT_NEAR(rough[2].value.to_double(), smooth.critical_length, 1e-12 * smooth.critical_length) << d << alpha;
      }
    }
  }
}

// α = β = 1 (Pidduck's gas) does not cool: both wave numbers exactly 0 and L_c* = +∞ (docs/conventions.md
// "The elastic end"), d = 2, 3 (not the Walton gas: its sliding contacts dissipate even at α = β0 = 1);
// and the approach is continuous: k* ∝ √(1 − α), L_c* ∝ 1/√(1 − α) at β = 1.
TEST(RoughHcsStability, ElasticPerfectlyRoughGasIsStable) {
  for (int d : {2, 3}) {
    const Rational kappa = d == 3 ? Rational(2, 5) : Rational(1, 2);
    const auto v = critical_values("rough", rough_point(d, Rational(1), Rational(1), kappa));
    for (int c = 0; c < 2; ++c) {
      EXPECT_TRUE(v[c].defined && !v[c].infinite) << d << " " << c;
      EXPECT_EQ(v[c].value, Rational(0)) << d << " " << c;
    }
    EXPECT_TRUE(v[2].defined && v[2].infinite) << d;
    EXPECT_EQ(v[2].error, Rational(0));
    const auto near = critical_values("rough", rough_point(d, Rational(9999, 10000), Rational(1), kappa));
    const auto nearer = critical_values("rough", rough_point(d, Rational(999999, 1000000), Rational(1), kappa));
    for (int c = 0; c < 3; ++c) {
      const double power = c < 2 ? -0.5 : 0.5;
      const double x = near[c].value.to_double() * std::pow(1e-4, power),
                   y = nearer[c].value.to_double() * std::pow(1e-6, power);
      EXPECT_GT(x, 0) << d << " " << c;
      EXPECT_NEAR(y / x, 1, 1e-2) << d << " " << c;
    }
  }
}

// The shear mode: k⊥c* = √(ζ*/η*) with ζ* from Huthmann & Zippelius's balance solved here by bisection
// (not the library's quadratic) and η* the model's own column.
TEST(RoughHcsStability, ShearModeIsTheClosedForm) {
  struct Case {
    int d;
    double alpha, beta, kappa;
  };
  for (const Case& c : {Case{3, 0.9, 0.5, 0.4}, Case{3, 0.6, -0.5, 0.4}, Case{3, 0.8, 1, 0.25}, Case{2, 0.7, 0.2, 0.5},
                        Case{2, 0.95, -0.8, 1}}) {
    const auto point =
        rough_point(c.d, Rational::from_double(c.alpha), Rational::from_double(c.beta), Rational::from_double(c.kappa));
    const auto eta = gkt::make_transport_model("rough")->evaluate(point, {"shear_viscosity"}, gkt::OrderRequest{});
    const double zeta = maxwellian_cooling_rate(c.d, c.alpha, c.beta, c.kappa);
    const auto v = critical_values("rough", point);
    EXPECT_NEAR(v[0].value.to_double(), std::sqrt(zeta / eta[0].value.to_double()), 1e-10)
        << c.d << " " << c.alpha << " " << c.beta;
  }
}

// Sign and trend, without DSMC: for α < 1 both modes grow at long wavelengths (k⊥c*, k∥c* > 0), more
// so the more inelastic (k* grows, L_c* shrinks as α decreases at fixed β); near β = −1 the hot spin
// feeds the translation and ζ* → 0 (theory.md §19.5), so L_c* grows far above the smooth value —
// "small roughness makes the system less unstable" [garzo2018rough] (abstract); medium roughness
// (β = 0 at α = 0.9) is more unstable than the smooth gas, as the same abstract states.
TEST(RoughHcsStability, SignAndTrend) {
  for (int d : {2, 3}) {
    const Rational kappa = d == 3 ? Rational(2, 5) : Rational(1, 2);
    for (const Rational& beta : {Rational(1, 2), Rational(0)}) {
      double previous_length = INFINITY, previous_shear = 0, previous_heat = 0;
      for (const Rational& alpha : {Rational(95, 100), Rational(9, 10), Rational(7, 10)}) {
        const auto v = critical_values("rough", rough_point(d, alpha, beta, kappa));
        EXPECT_GT(v[0].value.to_double(), previous_shear) << d << " " << alpha << " " << beta;
        EXPECT_GT(v[1].value.to_double(), previous_heat) << d << " " << alpha << " " << beta;
        EXPECT_LT(v[2].value.to_double(), previous_length) << d << " " << alpha << " " << beta;
        previous_shear = v[0].value.to_double();
        previous_heat = v[1].value.to_double();
        previous_length = v[2].value.to_double();
      }
    }
    const double smooth =
        critical_values("rough", rough_point(d, Rational(9, 10), Rational(-1), kappa))[2].value.to_double();
    const double quasi_smooth =
        critical_values("rough", rough_point(d, Rational(9, 10), Rational(-99, 100), kappa))[2].value.to_double();
    const double medium =
        critical_values("rough", rough_point(d, Rational(9, 10), Rational(0), kappa))[2].value.to_double();
    EXPECT_GT(quasi_smooth, 2 * smooth) << d;
    EXPECT_LT(medium, smooth) << d;
  }
}

// Walton friction: μ_f = 10⁵ is the constant-β gas (1e-6), and where the spin decouples (μ_f = 0) the
// values are undefined (nan), not the smooth gas's: the Walton model has no decoupled branch.
TEST(RoughHcsStability, WaltonLargeFrictionIsConstantBeta) {
  for (int d : {2, 3}) {
    const Rational kappa = d == 3 ? Rational(2, 5) : Rational(1, 2);
    gkt::ParameterPoint walton;
    walton.numbers = {{"dimension", Rational(d)},
                      {"alpha", Rational(4, 5)},
                      {"beta0", Rational(1, 2)},
                      {"moment_of_inertia", kappa},
                      {"friction", Rational(100000)}};
    const auto w = critical_values("rough-walton", walton);
    const auto r = critical_values("rough", rough_point(d, Rational(4, 5), Rational(1, 2), kappa));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(w[c].value.to_double() / r[c].value.to_double(), 1, 1e-6) << d << " " << c;
    walton.numbers["friction"] = Rational(0);
    for (const auto& v : critical_values("rough-walton", walton)) EXPECT_FALSE(v.defined);
  }
}

// Bad input names the field.
TEST(RoughHcsStability, BadInputNamesTheField) {
  gkt::RoughStabilityInput in;
  in.dimension = 4;
  EXPECT_THROW(gkt::rough_hcs_stability(in), std::invalid_argument);
  in.dimension = 3;
  in.temperature_ratio = 0;
  try {
    gkt::rough_hcs_stability(in);
    ADD_FAILURE() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("temperature_ratio"), std::string::npos) << e.what();
  }
  in.temperature_ratio = 1;
  in.thermal_conductivity = std::nan("");
  EXPECT_THROW(gkt::rough_longitudinal_matrix(in, 0.1), std::invalid_argument);
}
