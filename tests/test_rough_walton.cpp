// Coulomb (Walton) friction, docs/theory.md §19.10: the constant-β limit μ_f → ∞, the angular
// quadrature against Monte Carlo averages over collisions (error bars), the Maxwellian θ against the
// in-suite DSMC with the Walton rule, and the scalar response through the rate slopes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "dsmc_rough.hpp"
#include "gkt/transport/rough/rough_bulk_viscosity.hpp"
#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"
#include "gkt/transport/rough/rough_shear_viscosity.hpp"
#include "gkt/transport/rough/rough_thermal_conductivity.hpp"
#include "gkt/transport/rough/rough_walton.hpp"
#include "rough_monte_carlo.hpp"

using gkt::Rational;

TEST(RoughWalton, ConstantBetaIsInfiniteFriction) {
  const double inf = std::numeric_limits<double>::infinity();
  for (int d : {3, 2}) {
    const double a = 0.8, b = 0.3, k = d == 3 ? 0.4 : 0.5, theta = 1.3, tau = theta / k;
    const double eta = (1 + b) * k / (2 * (1 + k)), g = (d + 2) / 4.0, dr = d == 3 ? 3 : 1;
    const auto r = gkt::rough_walton_rates(d, a, b, k, inf, theta);
    // theory.md (19.12) times (d+2)/4.
    EXPECT_NEAR(r.translational, g * 2 / d * ((1 - a * a) / 2 + (d - 1) * (eta * (1 - eta) - eta * eta * tau)), 1e-14);
    EXPECT_NEAR(r.rotational, g * 2 * (d - 1) / dr * (eta / k) * (1 - eta / k - eta / (k * tau)), 1e-14);
    // A large but finite μ_f: sliding only for cot γ < 2η0/(μ_f(1+α)), a fraction O(μ_f⁻²).
    const auto big = gkt::rough_walton_rates(d, a, b, k, 1e4, theta);
    EXPECT_NEAR(big.translational, r.translational, 1e-7);
    EXPECT_NEAR(big.rotational, r.rotational, 1e-7);
    const Rational alpha(4, 5), beta(3, 10), kappa = d == 3 ? Rational(2, 5) : Rational(1, 2);
    const auto w = gkt::rough_walton_cooling_state(d, alpha, beta, kappa, Rational(100000));
    const auto hcs = gkt::rough_homogeneous_cooling_state(d, alpha, beta, kappa, gkt::RoughHcsScheme::maxwellian);
    EXPECT_NEAR(w.temperature_ratio, hcs.temperature_ratio, 1e-8);
    EXPECT_NEAR(w.cooling_rate, hcs.cooling_rate, 1e-8);
    const auto bulk = gkt::rough_bulk_viscosity(d, alpha, beta, kappa);
    EXPECT_NEAR(w.bulk_viscosity, bulk.bulk_viscosity, 1e-6 * bulk.bulk_viscosity);
    EXPECT_NEAR(w.cooling_rate_first_order, bulk.cooling_rate_first_order, 1e-6);
  }
}

TEST(RoughWalton, QuadratureConverged) {
  for (const double mu : {0.05, 0.3, 2.0}) {
    const auto coarse = gkt::rough_walton_rates(3, 0.7, 0.6, 0.4, mu, 2.0, 4000);
    const auto fine = gkt::rough_walton_rates(3, 0.7, 0.6, 0.4, mu, 2.0, 16000);
    EXPECT_NEAR(coarse.translational, fine.translational, 1e-11 * std::abs(fine.translational)) << mu;
    EXPECT_NEAR(coarse.rotational, fine.rotational, 1e-11 * std::abs(fine.rotational)) << mu;
  }
}

// Monte Carlo over collisions (weights Θ(u)u, Maxwellians at T_t and T_r = θT_t) with the Walton rule
// of tests/rough_monte_carlo.hpp applied collision by collision: ζ_t* = −((d+2)/(2d))⟨Δc1²⟩,
// ζ_r* = −((d+2)/(2d_rτ))⟨Δw1²⟩ (units of (19.22)) within 5 standard errors.
TEST(RoughWalton, RatesAgainstMonteCarlo) {
  struct Case {
    int d;
    double alpha, beta0, kappa, friction, theta;
  };
  for (const Case c :
       {Case{3, 0.8, 0.5, 0.4, 0.1, 1.5}, Case{3, 0.6, 1.0, 0.4, 0.3, 0.7}, Case{2, 0.9, 0.4, 0.5, 0.15, 1.0}}) {
    gkt::test::RoughCollisionSampler sampler(c.d, c.alpha, c.beta0, c.kappa, c.theta, 11, c.friction);
    const int n = 400000;
    double w_sum = 0, v_sum = 0, v_sq = 0, s_sum = 0, s_sq = 0;
    for (int i = 0; i < n; ++i) {
      const auto x = sampler.draw();
      const double dv = gkt::test::dot3(x.w[4], x.w[4]) - gkt::test::dot3(x.w[0], x.w[0]);
      const double dw = gkt::test::dot3(x.w[6], x.w[6]) - gkt::test::dot3(x.w[2], x.w[2]);
      w_sum += x.weight;
      v_sum += x.weight * dv;
      v_sq += x.weight * dv * x.weight * dv;
      s_sum += x.weight * dw;
      s_sq += x.weight * dw * x.weight * dw;
    }
    // Ratio estimators ⟨uX⟩/⟨u⟩; the error of ⟨u⟩ is small against that of ⟨uX⟩ here.
    const double mean_w = w_sum / n, dv = v_sum / w_sum, ds = s_sum / w_sum;
    const double dv_err = std::sqrt((v_sq / n - (v_sum / n) * (v_sum / n)) / n) / mean_w;
    const double ds_err = std::sqrt((s_sq / n - (s_sum / n) * (s_sum / n)) / n) / mean_w;
    const double tau = c.theta / c.kappa, dr = c.d == 3 ? 3 : 1, g = (c.d + 2) / 4.0;
    const auto r = gkt::rough_walton_rates(c.d, c.alpha, c.beta0, c.kappa, c.friction, c.theta);
    const double scale_t = -g * 2 / c.d, scale_r = -g * 2 / (dr * tau);
    std::printf("walton d=%d: zeta_t %.5f MC %.5f +- %.5f, zeta_r %.5f MC %.5f +- %.5f\n", c.d, r.translational,
                scale_t * dv, std::abs(scale_t) * dv_err, r.rotational, scale_r * ds, std::abs(scale_r) * ds_err);
    EXPECT_NEAR(r.translational, scale_t * dv, 5 * std::abs(scale_t) * dv_err);
    EXPECT_NEAR(r.rotational, scale_r * ds, 5 * std::abs(scale_r) * ds_err);
    // The friction matters at these points: the constant-β0 rates lie outside the error bars.
    const auto sticking =
        gkt::rough_walton_rates(c.d, c.alpha, c.beta0, c.kappa, std::numeric_limits<double>::infinity(), c.theta);
    EXPECT_GT(std::abs(sticking.rotational - scale_r * ds), 8 * std::abs(scale_r) * ds_err);
  }
}

// DSMC of the HCS with the Walton rule (4000 particles, 20 + 20 × 5 collisions per particle): the
// Maxwellian θ is a first approximation, off by 2–6 % here (cumulants left out, as for constant β,
// theory.md §19.6); the friction moves θ far from the constant-β0 value, and the DSMC sees that.
TEST(RoughWalton, TemperatureRatioAgainstDsmc) {
  struct Case {
    int d;
    long a10, b10, mu100;
  };
  for (const Case c : {Case{3, 9, 10, 50}, Case{3, 8, 0, 100}, Case{2, 9, 10, 50}}) {
    const double k = c.d == 3 ? 0.4 : 0.5;
    const Rational kappa = c.d == 3 ? Rational(2, 5) : Rational(1, 2);
    const auto w =
        gkt::rough_walton_cooling_state(c.d, Rational(c.a10, 10), Rational(c.b10, 10), kappa, Rational(c.mu100, 100));
    ASSERT_FALSE(w.spin_decoupled);
    const auto s = gkt::test::run_rough_hcs_dsmc(c.d, c.a10 / 10.0, c.b10 / 10.0, k, w.temperature_ratio, 4000, 20, 20,
                                                 5, 5, c.mu100 / 100.0);
    const auto fixed = gkt::rough_homogeneous_cooling_state(c.d, Rational(c.a10, 10), Rational(c.b10, 10), kappa,
                                                            gkt::RoughHcsScheme::maxwellian);
    std::printf("walton HCS d=%d alpha=%.1f beta0=%.1f mu=%.2f: theta %.4f DSMC %.4f +- %.4f (constant beta0: %.4f)\n",
                c.d, c.a10 / 10.0, c.b10 / 10.0, c.mu100 / 100.0, w.temperature_ratio, s.theta, s.theta_error,
                fixed.temperature_ratio);
    EXPECT_NEAR(w.temperature_ratio, s.theta, 0.07 * s.theta + 4 * s.theta_error);
    if (c.b10 == 10) {
      EXPECT_GT(std::abs(fixed.temperature_ratio - s.theta), 0.2 * s.theta);
    }
  }
}

// Sliding contacts take at most μ_f times the normal impulse, so a fast spin loses a bounded amount per
// collision while the translation cools: the spin tail freezes and θ runs away (theory.md §19.10). At
// (α, β0, μ_f) = (0.7, 0.5, 0.5) the Maxwellian approximation has a finite root (θ = 1.48) but the
// DSMC's θ and a02 grow without bound — the Maxwellian HCS of the Walton gas is not always reached.
TEST(RoughWalton, FrozenSpinTailInDsmc) {
  const auto w = gkt::rough_walton_cooling_state(3, Rational(7, 10), Rational(1, 2), Rational(2, 5), Rational(1, 2));
  ASSERT_FALSE(w.spin_decoupled);
  EXPECT_LT(w.temperature_ratio, 2);
  const auto early = gkt::test::run_rough_hcs_dsmc(3, 0.7, 0.5, 0.4, w.temperature_ratio, 4000, 5, 20, 1, 5, 0.5);
  const auto late = gkt::test::run_rough_hcs_dsmc(3, 0.7, 0.5, 0.4, w.temperature_ratio, 4000, 80, 20, 1, 5, 0.5);
  std::printf(
      "walton runaway: theta %.4f; DSMC after 5 collisions/particle %.3f (a02 %.2f), after 80 %.1f (a02 %.1f)\n",
      w.temperature_ratio, early.theta, early.a02, late.theta, late.a02);
  EXPECT_LT(early.theta, 2);
  EXPECT_GT(late.theta, 100);
  EXPECT_GT(late.a02, 100);
  // The same point with constant β = β0 has a stationary DSMC θ (no sliding cap).
  const auto fixed = gkt::test::run_rough_hcs_dsmc(3, 0.7, 0.5, 0.4, 1.2, 4000, 80, 20, 1, 5);
  EXPECT_LT(fixed.theta, 2);
}

TEST(RoughWalton, BadInputAndDecoupledSpin) {
  EXPECT_THROW(gkt::rough_walton_rates(3, 0.9, 0.5, 0.4, -0.1, 1.0), std::invalid_argument);
  EXPECT_THROW(gkt::rough_walton_rates(3, 0.9, 1.5, 0.4, 0.1, 1.0), std::invalid_argument);
  EXPECT_THROW(gkt::rough_walton_rates(4, 0.9, 0.5, 0.4, 0.1, 1.0), std::invalid_argument);
  const auto smooth = gkt::rough_walton_cooling_state(3, Rational(9, 10), Rational(1, 2), Rational(2, 5), Rational(0));
  EXPECT_TRUE(smooth.spin_decoupled);
  EXPECT_TRUE(std::isinf(smooth.temperature_ratio));
  EXPECT_TRUE(std::isnan(smooth.bulk_viscosity));
}

// η* of the Walton gas (theory.md (19.23)): with μ_f = ∞ the conditioned-Gaussian quadrature must give
// the engine's exact first-Sonine η* (rough_shear_viscosity_at) — a check of the conditioning and of
// Isserlis' theorem — and with finite μ_f L_η must agree with Monte Carlo over collisions.
TEST(RoughWalton, ShearViscosity) {
  const double inf = std::numeric_limits<double>::infinity();
  for (int d : {3, 2}) {
    const double k = d == 3 ? 0.4 : 0.5;
    const Rational kappa = d == 3 ? Rational(2, 5) : Rational(1, 2);
    const double exact =
        gkt::rough_shear_viscosity_at(d, Rational(4, 5), Rational(3, 10), kappa, Rational(13, 10)).to_double();
    // Simpson's h⁴: 2e-7 with 200 panels, 1e-8 with the default 400.
    EXPECT_NEAR(gkt::rough_walton_shear_viscosity(d, 0.8, 0.3, k, inf, 1.3), exact, 5e-8) << d;
    EXPECT_NEAR(gkt::rough_walton_shear_viscosity(d, 0.8, 0.3, k, 1e5, 1.3), exact, 5e-8) << d;
    // Quadrature converged at the default (against twice the panels).
    const double coarse = gkt::rough_walton_shear_viscosity(d, 0.7, 1.0, k, 0.3, 1.2);
    const double fine = gkt::rough_walton_shear_viscosity(d, 0.7, 1.0, k, 0.3, 1.2, 800);
    EXPECT_NEAR(coarse, fine, 5e-8 * fine) << d;
  }
  struct Case {
    int d;
    double alpha, beta0, kappa, friction, theta;
  };
  for (const Case c : {Case{3, 0.8, 1.0, 0.4, 0.1, 1.5}, Case{2, 0.7, 0.6, 0.5, 0.2, 0.8}}) {
    gkt::test::RoughCollisionSampler sampler(c.d, c.alpha, c.beta0, c.kappa, c.theta, 17, c.friction);
    const auto y2 = [&](const gkt::test::Vec3& a, const gkt::test::Vec3& b) {
      const double ab = gkt::test::dot3(a, b);
      return ab * ab - gkt::test::dot3(a, a) * gkt::test::dot3(b, b) / c.d;
    };
    const int n = 400000;
    double w_sum = 0, x_sum = 0, x_sq = 0;
    for (int i = 0; i < n; ++i) {
      const auto x = sampler.draw();
      const double l = y2(x.w[0], x.w[0]) + y2(x.w[1], x.w[0]) - y2(x.w[0], x.w[4]) - y2(x.w[1], x.w[4]);
      w_sum += x.weight;
      x_sum += x.weight * l;
      x_sq += x.weight * l * x.weight * l;
    }
    const double l_mc = x_sum / w_sum, err = std::sqrt((x_sq / n - (x_sum / n) * (x_sum / n)) / n) / (w_sum / n);
    const double zeta = gkt::rough_walton_rates(c.d, c.alpha, c.beta0, c.kappa, c.friction, c.theta).translational;
    const double eta = gkt::rough_walton_shear_viscosity(c.d, c.alpha, c.beta0, c.kappa, c.friction, c.theta);
    const double l_quadrature = (c.d - 1) * (1 / eta + zeta / 2);
    std::printf("walton L_eta d=%d: quadrature %.5f MC %.5f +- %.5f (eta* %.5f)\n", c.d, l_quadrature, l_mc, err, eta);
    EXPECT_NEAR(l_quadrature, l_mc, 5 * err);
  }
}

// κ*, μ* of the Walton gas: at μ_f = ∞ the conditioned-Gaussian quadrature of the sextic forms must give
// the engine's exact first-Sonine κ*, μ* at the same θ (rough_thermal_conductivity_at).
TEST(RoughWalton, ThermalConductivityConstantBetaLimit) {
  const double inf = std::numeric_limits<double>::infinity();
  for (int d : {3, 2}) {
    const double k = d == 3 ? 0.4 : 0.5;
    const Rational kappa = d == 3 ? Rational(2, 5) : Rational(1, 2);
    const auto exact = gkt::rough_thermal_conductivity_at(d, Rational(4, 5), Rational(3, 10), kappa, 1.3);
    const auto w = gkt::rough_walton_thermal_conductivity(d, 0.8, 0.3, k, inf, 1.3);
    EXPECT_NEAR(w.total, exact.total, 1e-9 * exact.total) << d;
    EXPECT_NEAR(w.density_heat_total, exact.density_heat_total, 1e-9 * exact.density_heat_total) << d;
  }
  // Converged with finite friction (the kink as a panel edge): 8 against 16 panels.
  const auto coarse = gkt::rough_walton_thermal_conductivity(3, 0.7, 1.0, 0.4, 0.3, 1.2);
  const auto fine = gkt::rough_walton_thermal_conductivity(3, 0.7, 1.0, 0.4, 0.3, 1.2, 16);
  EXPECT_NEAR(coarse.total, fine.total, 1e-9 * fine.total);
  EXPECT_NEAR(coarse.density_heat_total, fine.density_heat_total, 1e-9 * fine.density_heat_total);
}

// The heat operator with sliding contacts against Monte Carlo over collisions (the spin enters through
// ψ2 = c(ŵ² − 3/2), ŵ² = w²/τ): L_ij = ⟨ψ_j(1)·(ψ_i(1) − ψ_i(1'))⟩ + ⟨ψ_j(2)·(ψ_i(1) − ψ_i(1'))⟩.
TEST(RoughWalton, HeatOperatorAgainstMonteCarlo) {
  const double alpha = 0.8, beta0 = 1.0, kappa = 0.4, friction = 0.15, theta = 1.4, tau = theta / kappa;
  gkt::test::RoughCollisionSampler sampler(3, alpha, beta0, kappa, theta, 23, friction);
  const auto psi = [&](int i, const gkt::test::Vec3& v, const gkt::test::Vec3& w) {
    const double f = i == 1 ? gkt::test::dot3(v, v) - 2.5 : gkt::test::dot3(w, w) / tau - 1.5;
    return gkt::test::Vec3{v[0] * f, v[1] * f, v[2] * f};
  };
  const int n = 400000;
  double w_sum = 0;
  std::array<double, 4> sum{}, sq{};
  for (int s = 0; s < n; ++s) {
    const auto x = sampler.draw();
    w_sum += x.weight;
    for (int i = 1; i <= 2; ++i)
      for (int j = 1; j <= 2; ++j) {
        const auto a1 = psi(j, x.w[0], x.w[2]), a2 = psi(j, x.w[1], x.w[3]);
        const auto b = psi(i, x.w[0], x.w[2]), bp = psi(i, x.w[4], x.w[6]);
        const gkt::test::Vec3 diff{b[0] - bp[0], b[1] - bp[1], b[2] - bp[2]};
        const double value = x.weight * (gkt::test::dot3(a1, diff) + gkt::test::dot3(a2, diff));
        const auto e = static_cast<std::size_t>(2 * (i - 1) + (j - 1));
        sum[e] += value;
        sq[e] += value * value;
      }
  }
  const auto l = gkt::rough_walton_heat_operator(3, alpha, beta0, kappa, friction, theta);
  for (std::size_t e = 0; e < 4; ++e) {
    const double mc = sum[e] / w_sum, err = std::sqrt((sq[e] / n - (sum[e] / n) * (sum[e] / n)) / n) / (w_sum / n);
    const double q = l[e / 2][e % 2];
    std::printf("walton heat L%zu%zu: quadrature %.5f MC %.5f +- %.5f\n", e / 2 + 1, e % 2 + 1, q, mc, err);
    EXPECT_NEAR(q, mc, 5 * err);
  }
}
