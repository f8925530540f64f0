// Uniform shear flow: Grad's steady state (docs/theory.md §22), its small-ε expansion against
// Goldhirsch–Noskowicz–Bar-Lev's printed numbers (seed 001 §3.3.1, [goldhirsch2005]) and the DSMC.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "gkt/algebra/rational.hpp"
#include "gkt/models/transport_model.hpp"
#include "gkt/simulation/random_stream.hpp"
#include "gkt/simulation/uniform_shear_dsmc.hpp"
#include "gkt/transport/closed_forms/uniform_shear_flow.hpp"
#include "gkt/transport/common/pair_correlation.hpp"
#include "gkt/transport/monodisperse/navier_stokes.hpp"

namespace {

using gkt::uniform_shear_flow_grad;

// GNB's printed 2D numbers (seed 001 §3.3.1, eq. (16)).
constexpr double kGnbGamma1 = 0.8771, kGnbTauXX = 0.2612, kGnbTauXY = -0.3572, kGnbRatio = 0.5224;

TEST(UniformShearGrad, CollisionFrequenciesAreTheKnownMaxwellianOnes) {
  // ζ_M = (d+2)(1−α²)/(4d); ν_η = (3/(4d))(1 − α + 2d/3)(1 + α) ([garzo2019] ch. 3 at a2 = 0).
  for (int d : {2, 3})
    for (double alpha : {1.0, 0.9, 0.7, 0.3}) {
      const auto u = uniform_shear_flow_grad(d, alpha);
      EXPECT_NEAR(u.cooling_rate, (d + 2) * (1 - alpha * alpha) / (4.0 * d), 1e-14) << d << " " << alpha;
      EXPECT_NEAR(u.shear_collision_frequency, 3.0 / (4 * d) * (1 - alpha + 2.0 * d / 3) * (1 + alpha), 1e-14)
          << d << " " << alpha;
    }
}

TEST(UniformShearGrad, BalancesHold) {
  for (int d : {2, 3})
    for (double alpha : {0.95, 0.7, 0.2}) {
      const auto u = uniform_shear_flow_grad(d, alpha);
      // energy (22.4): a P_xy = −(d/2) p ζ, i.e. a* · 2 stress_xy = −(d/2) ζ*
      EXPECT_NEAR(2 * u.shear_rate * u.stress_xy, -0.5 * d * u.cooling_rate, 1e-13);
      // trace: Σ P_ii = d p
      EXPECT_NEAR(u.stress_xx + u.stress_yy + u.stress_zz, 0.5 * d, 1e-13);
      // xy (22.5): a P_yy = −ν_η P_xy
      EXPECT_NEAR(u.shear_rate * u.stress_yy, -u.shear_collision_frequency * u.stress_xy, 1e-13);
      EXPECT_NEAR(u.reduced_shear_rate, u.shear_rate * gkt::uniform_shear_length_factor(d), 1e-14);
      if (d == 3) {
        EXPECT_EQ(u.stress_zz, u.stress_yy);
      }
    }
  const auto elastic = uniform_shear_flow_grad(2, 1.0);
  EXPECT_EQ(elastic.shear_rate, 0.0);
  EXPECT_EQ(elastic.stress_xx, 0.5);
  EXPECT_EQ(elastic.stress_xy, 0.0);
}

TEST(UniformShearGrad, RejectsBadInput) {
  EXPECT_THROW(uniform_shear_flow_grad(4, 0.9), std::invalid_argument);
  EXPECT_THROW(uniform_shear_flow_grad(2, 0.0), std::invalid_argument);
  EXPECT_THROW(uniform_shear_flow_grad(2, 1.1), std::invalid_argument);
  EXPECT_THROW(uniform_shear_flow_grad(2, std::nan("")), std::invalid_argument);
  EXPECT_THROW(gkt::uniform_shear_navier_stokes_limit(2, 0.0), std::invalid_argument);
}

/// Coefficients c0, c1, c2 of g(s) = c0 + c1 s + c2 s² through three points (Lagrange).
std::array<double, 3> quadratic_through(const std::array<double, 3>& s, const std::array<double, 3>& g) {
  std::array<double, 3> c{};
  for (int i = 0; i < 3; ++i) {
    const double a = s[(i + 1) % 3], b = s[(i + 2) % 3], w = g[i] / ((s[i] - a) * (s[i] - b));
    c[0] += w * a * b;
    c[1] -= w * (a + b);
    c[2] += w;
  }
  return c;
}

// Theory.md §22.3: in 2D Grad gives γ = (√π/2)√ε (1 + 5ε/16 + …), γ2 = 0, τ̃_xy = −1/(2√2),
// τ̃_xx = −τ̃_yy = 1/4; fitted here from the solution at small ε = s².
TEST(UniformShearGrad, SmallInelasticityExpansionIn2D) {
  const std::array<double, 3> s{0.01, 0.02, 0.03};
  std::array<double, 3> gamma{}, tau_xy{}, tau_xx{}, tau_yy{};
  for (int k = 0; k < 3; ++k) {
    const double eps = s[k] * s[k];
    const auto u = uniform_shear_flow_grad(2, std::sqrt(1 - eps));
    gamma[k] = u.reduced_shear_rate / s[k];
    tau_xy[k] = u.stress_xy / s[k];
    tau_xx[k] = (u.stress_xx - 0.5) / eps;
    tau_yy[k] = (u.stress_yy - 0.5) / eps;
  }
  const auto g = quadratic_through(s, gamma);
  EXPECT_NEAR(g[0], std::sqrt(std::numbers::pi) / 2, 1e-7);       // γ1
  EXPECT_NEAR(g[1], 0.0, 1e-5);                                   // γ2 = 0, as GNB
  EXPECT_NEAR(g[2], 5 * std::sqrt(std::numbers::pi) / 32, 1e-3);  // γ3
  EXPECT_NEAR(quadratic_through(s, tau_xy)[0], -1 / (2 * std::sqrt(2.0)), 1e-7);
  const double txx = quadratic_through(s, tau_xx)[0], tyy = quadratic_through(s, tau_yy)[0];
  EXPECT_NEAR(txx, 0.25, 1e-6);
  EXPECT_NEAR(tyy, -0.25, 1e-6);
  // What agrees with GNB exactly: γ2 = 0 and τ̃_xx = −τ̃_yy (so the ratio has their form (1+cε)/(1−cε)).
  EXPECT_NEAR(txx + tyy, 0.0, 1e-6);
  // The documented differences (theory.md §22.4): Grad's first-Sonine viscosity puts γ1 1.0 % high
  // and |τ̃_xy| 1.0 % low; the normal stresses are a Burnett effect, 4.3 % low in Grad.
  EXPECT_NEAR(g[0] / kGnbGamma1 - 1, 0.0104, 5e-4);
  EXPECT_NEAR(quadratic_through(s, tau_xy)[0] / kGnbTauXY - 1, -0.0102, 5e-4);
  EXPECT_NEAR(txx / kGnbTauXX - 1, -0.0429, 5e-4);
  EXPECT_NEAR(2 * txx / kGnbRatio - 1, -0.0429, 5e-4);
}

// Theory.md §22.4: Chapman–Enskog at Navier–Stokes order with the engine's elastic viscosity.
// GNB's γ1 and τ̃_xy both imply η* = 1.0209, between the engine's second (51/50) and third Sonine
// values and 0.1 % below the converged 1.02197, which moves them in the fourth digit (0.87665,
// −0.35742); their product, fixed by the energy balance alone, agrees to the printed digits.
TEST(UniformShearChapmanEnskog, ConvergedViscosityAgainstGnb) {
  gkt::NavierStokesSolver solver(2);
  const double second = solver.solve(gkt::Rational(1), 2, {1, 0, 0}).shear_viscosity;
  const double third = solver.solve(gkt::Rational(1), 3, {1, 0, 0}).shear_viscosity;
  const double converged = solver.solve(gkt::Rational(1), 8, {1, 0, 0}).shear_viscosity;
  EXPECT_NEAR(second, 1.02, 1e-14);
  EXPECT_NEAR(converged, 1.02197, 1e-5);
  const double implied_by_gamma1 = std::numbers::pi / (4 * kGnbGamma1 * kGnbGamma1);  // (22.10) inverted
  const double implied_by_tau_xy = 8 * kGnbTauXY * kGnbTauXY;
  EXPECT_NEAR(implied_by_gamma1, implied_by_tau_xy, 3e-4);  // one viscosity behind both numbers
  for (double implied : {implied_by_gamma1, implied_by_tau_xy}) {
    EXPECT_GT(implied, second);
    EXPECT_LT(implied, third);
  }
  const auto limit = gkt::uniform_shear_navier_stokes_limit(2, converged);
  EXPECT_NEAR(limit.gamma1, 0.87665, 1e-5);
  EXPECT_NEAR(limit.tau_xy, -0.35742, 1e-5);
  EXPECT_GT(std::abs(limit.gamma1 - kGnbGamma1), 4e-4);  // outside GNB's printed rounding (5e-5)
  EXPECT_GT(std::abs(limit.tau_xy - kGnbTauXY), 2e-4);
  // γ1 τ̃_xy = −(1/4)√(π/2) for every η* (energy balance): GNB's product within its rounding.
  EXPECT_NEAR(limit.gamma1 * limit.tau_xy, -std::sqrt(std::numbers::pi / 2) / 4, 1e-12);
  EXPECT_NEAR(kGnbGamma1 * kGnbTauXY, -std::sqrt(std::numbers::pi / 2) / 4, 6e-5);
  // at first Sonine (η* = 1) it is Grad's leading order
  const auto first = gkt::uniform_shear_navier_stokes_limit(2, 1.0);
  EXPECT_NEAR(first.gamma1, std::sqrt(std::numbers::pi) / 2, 1e-15);
  EXPECT_NEAR(first.tau_xy, -1 / (2 * std::sqrt(2.0)), 1e-15);
}

/// Run averages (one value per independent run) of a small USF DSMC started at Grad's shear rate.
struct ShearSample {
  gkt::DsmcEstimate gamma, xx, yy, zz, xy;
};

ShearSample shear_dsmc(int d, double alpha, int runs, double start = 1, double relaxation = 20, double phi = 0,
                       double chi = 1) {
  const auto grad = uniform_shear_flow_grad(d, alpha);
  std::vector<double> g, xx, yy, zz, xy;
  auto mean = [](const std::vector<double>& x) { return gkt::mean_and_error(x).mean; };
  for (int r = 0; r < runs; ++r) {
    gkt::DsmcSchedule s;
    s.particles = 2000;
    s.relaxation = relaxation;
    s.batches = 20;
    s.per_batch = 2;
    s.seed = gkt::dsmc_run_seed(23, static_cast<std::uint64_t>(r));
    const auto run = gkt::run_uniform_shear_dsmc(d, {alpha, start * grad.shear_rate, phi, chi}, s);
    g.push_back(mean(run.reduced_shear_rate));
    xx.push_back(mean(run.stress_xx));
    yy.push_back(mean(run.stress_yy));
    zz.push_back(mean(run.stress_zz));
    xy.push_back(mean(run.stress_xy));
  }
  return {gkt::mean_and_error(g), gkt::mean_and_error(xx), gkt::mean_and_error(yy), gkt::mean_and_error(zz),
          gkt::mean_and_error(xy)};
}

// Theory.md §22.5: at α = 0.7 the DSMC lies within the documented few per cent of Grad (γ 5–6 %
// above, stresses within 3.5 %), and shows what Grad cannot: P_zz ≠ P_yy in 3D.
TEST(UniformShearDsmc, AgreesWithGradWithinItsDocumentedAccuracy) {
  for (int d : {2, 3}) {
    const auto grad = uniform_shear_flow_grad(d, 0.7);
    const auto dsmc = shear_dsmc(d, 0.7, 6);
    const double relative = dsmc.gamma.mean / grad.reduced_shear_rate - 1;
    EXPECT_GT(relative, 0.03) << d;  // measured +5.0 % (2D), +5.9 % (3D), errors ~0.1 %
    EXPECT_LT(relative, 0.08) << d;
    EXPECT_LT(dsmc.gamma.error, 0.01 * dsmc.gamma.mean);  // a sample that can tell 3 % from 5 %
    EXPECT_NEAR(dsmc.xx.mean / grad.stress_xx, 1, 0.025) << d;
    EXPECT_NEAR(dsmc.yy.mean / grad.stress_yy, 1, 0.035) << d;
    EXPECT_NEAR(dsmc.xy.mean / grad.stress_xy, 1, 0.035) << d;
    if (d == 3) {
      EXPECT_GT(dsmc.zz.mean - dsmc.yy.mean, 5 * std::hypot(dsmc.zz.error, dsmc.yy.error));
    } else {
      EXPECT_EQ(dsmc.zz.mean, 0.0);
    }
  }
}

// The shear rate a is fixed in a run and T relaxes to the steady state: starting 1.5 times above
// Grad's a* (T/T_initial → 2.1 instead of 0.9) gives the same γ and stresses.
TEST(UniformShearDsmc, SteadyStateDoesNotDependOnTheInitialShearRate) {
  const auto near = shear_dsmc(2, 0.7, 6, 1.0, 60), far = shear_dsmc(2, 0.7, 6, 1.5, 60);
  EXPECT_NEAR(far.gamma.mean, near.gamma.mean, 4 * std::hypot(far.gamma.error, near.gamma.error));
  EXPECT_NEAR(far.xy.mean, near.xy.mean, 4 * std::hypot(far.xy.error, near.xy.error));
  EXPECT_NEAR(far.xx.mean, near.xx.mean, 4 * std::hypot(far.xx.error, near.xx.error));
}

// The Enskog scheme (theory.md §22.8) at φ → 0 (φ = 10⁻⁹, χ = 1: σ̂ drawn uniformly and accepted
// against g_max instead of the dilute scheme's weighted σ̂) is today's dilute USF DSMC: γ and the
// stresses at α = 0.7 (2D) within 4 combined standard errors, no collisional stress to see.
TEST(UniformShearDsmc, EnskogSchemeAtVanishingDensityIsTheDiluteOne) {
  const auto dilute = shear_dsmc(2, 0.7, 6), enskog = shear_dsmc(2, 0.7, 6, 1, 20, 1e-9, 1);
  EXPECT_NEAR(enskog.gamma.mean, dilute.gamma.mean, 4 * std::hypot(enskog.gamma.error, dilute.gamma.error));
  EXPECT_NEAR(enskog.xx.mean, dilute.xx.mean, 4 * std::hypot(enskog.xx.error, dilute.xx.error));
  EXPECT_NEAR(enskog.yy.mean, dilute.yy.mean, 4 * std::hypot(enskog.yy.error, dilute.yy.error));
  EXPECT_NEAR(enskog.xy.mean, dilute.xy.mean, 4 * std::hypot(enskog.xy.error, dilute.xy.error));
  EXPECT_GT(enskog.gamma.error, 0);
}

// The collisional transfer of the Enskog DSMC against the one exact dense number: with a vanishing
// shear rate (10⁻⁹) the gas is in its homogeneous cooling state, where the collisional pressure is
// p^c/(nT) = 2^{d−2}(1+α)φχ for any cumulants (theory.md (15.5)). α = 0.8, φ = 0.3 (χ of the default
// closure), 4 runs × 2000 particles × 10 collisions per particle in batches of 0.5: within 4σ
// (measured −0.4σ in 3D, −0.2σ in 2D; σ ≈ 0.4 %), and no shear stress.
TEST(UniformShearDsmc, EnskogCollisionalPressureOfTheCoolingState) {
  const double alpha = 0.8, phi = 0.3;
  for (int d : {3, 2}) {
    const double chi = gkt::pair_correlations().front().contact_value_double(d, phi);
    std::vector<double> pressure, shear;
    for (int r = 0; r < 4; ++r) {
      gkt::DsmcSchedule s;
      s.particles = 2000;
      s.relaxation = 5;
      s.batches = 20;
      s.per_batch = 0.5;
      s.seed = gkt::dsmc_run_seed(23, static_cast<std::uint64_t>(r));
      const auto run = gkt::run_uniform_shear_dsmc(d, {alpha, 1e-9, phi, chi}, s);
      auto mean = [](const std::vector<double>& x) { return gkt::mean_and_error(x).mean; };
      pressure.push_back((2.0 / d) * (mean(run.collisional_xx) + mean(run.collisional_yy) + mean(run.collisional_zz)));
      shear.push_back(mean(run.collisional_xy));
      EXPECT_EQ(run.stress_xy.size(), run.collisional_xy.size());
    }
    const auto p = gkt::mean_and_error(pressure), xy = gkt::mean_and_error(shear);
    EXPECT_NEAR(p.mean, std::pow(2.0, d - 2) * (1 + alpha) * phi * chi, 4 * p.error) << d;
    EXPECT_LT(p.error, 0.01 * p.mean) << d;
    EXPECT_NEAR(xy.mean, 0, 4 * xy.error) << d;
  }
}

TEST(UniformShearDsmc, RejectsBadInput) {
  gkt::DsmcSchedule s;
  s.particles = 100;
  s.batches = 1;
  s.per_batch = 1;
  EXPECT_THROW(gkt::run_uniform_shear_dsmc(2, {1.0, 0.3}, s), std::invalid_argument);
  EXPECT_THROW(gkt::run_uniform_shear_dsmc(2, {0.9, 0.0}, s), std::invalid_argument);
  EXPECT_THROW(gkt::run_uniform_shear_dsmc(2, {0.9, std::nan("")}, s), std::invalid_argument);
  EXPECT_THROW(gkt::run_uniform_shear_dsmc(4, {0.9, 0.3}, s), std::invalid_argument);
  EXPECT_THROW(gkt::run_uniform_shear_dsmc(3, {0.9, 0.3, 0.6, 2}, s), std::invalid_argument);
  EXPECT_THROW(gkt::run_uniform_shear_dsmc(3, {0.9, 0.3, -0.1, 2}, s), std::invalid_argument);
  EXPECT_THROW(gkt::run_uniform_shear_dsmc(3, {0.9, 0.3, 0.2, 0.5}, s), std::invalid_argument);
  s.particles = 1;
  EXPECT_THROW(gkt::run_uniform_shear_dsmc(2, {0.9, 0.3}, s), std::invalid_argument);
}

// `gkt table` with model = "uniform-shear" answers Grad's solution; stress_zz only in 3D.
TEST(UniformShearModel, TableValuesAreGradsSolution) {
  auto model = gkt::make_transport_model("uniform-shear");
  for (int d : {2, 3}) {
    gkt::ParameterPoint p;
    p.numbers["dimension"] = gkt::Rational(d);
    p.numbers["alpha"] = gkt::Rational(7, 10);
    std::vector<std::string> names{"reduced_shear_rate", "stress_xx", "stress_yy", "stress_xy"};
    if (d == 3) names.emplace_back("stress_zz");
    EXPECT_EQ(model->scene_coefficient_names(p).size(), d == 3 ? 5U : 4U);
    const auto values = model->evaluate(p, names, {1, {}});
    const auto grad = uniform_shear_flow_grad(d, 0.7);
    const std::vector<double> expected{grad.reduced_shear_rate, grad.stress_xx, grad.stress_yy, grad.stress_xy,
                                       grad.stress_zz};
    for (std::size_t k = 0; k < names.size(); ++k) {
      EXPECT_EQ(values[k].value.to_double(), expected[k]) << d << " " << names[k];
      EXPECT_FALSE(values[k].error_estimated);
    }
    if (d == 2) {
      EXPECT_THROW((void)model->evaluate(p, {"stress_zz"}, {1, {}}), std::invalid_argument);
    }
  }
}

}  // namespace
