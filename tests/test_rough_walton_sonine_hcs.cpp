// The Walton gas's HCS in the linear scheme at Sonine orders 1–3 (docs/theory.md §19.25): against the constant-β
// solver of §19.14 at μ_f = ∞ (exact engine tables against the conditioned-Gaussian quadrature), against the
// first-Sonine Walton solver of §19.19 at order 1, its convergence with the order and the quadrature rule, and the
// test-side DSMC with the Walton rule.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <vector>

#include "dsmc_rough.hpp"
#include "gkt/transport/rough/rough_sonine_cooling_state.hpp"
#include "gkt/transport/rough/rough_sonine_transport.hpp"
#include "gkt/transport/rough/rough_walton_cumulants.hpp"
#include "gkt/transport/rough/rough_walton_sonine.hpp"
#include "gkt/transport/rough/rough_walton_sonine_hcs.hpp"

using gkt::Rational;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

// μ_f = ∞ (every contact sticks, β = β0): θ, ζ* and every a_pq of orders 1–3 equal the constant-β linear scheme with
// the isotropic ansatz (exact Laurent tables of the engine, rough_sonine_cooling_state) to 1e-8, d = 2, 3 — an
// independent test of the products of up to eight forms (19.81), the bookkeeping of (19.121) and the secant root.
TEST(RoughWaltonSonineHcs, InfiniteFrictionIsTheConstantBetaLinearScheme) {
  for (int d : {3, 2}) {
    const Rational alpha(9, 10), beta(1, 2), kappa = d == 3 ? Rational(2, 5) : Rational(1, 2);
    const auto w = gkt::rough_walton_sonine_cooling_states(d, 0.9, 0.5, kappa.to_double(), kInf, 3);
    ASSERT_EQ(w.size(), 3U);
    for (int n = 1; n <= 3; ++n) {
      const auto e = gkt::rough_sonine_cooling_state(d, alpha, beta, kappa, n, gkt::RoughSonineScheme::linear);
      const auto& s = w[static_cast<std::size_t>(n - 1)];
      ASSERT_TRUE(e.solved && s.solved) << d << " " << n;
      EXPECT_NEAR(s.temperature_ratio, e.temperature_ratio, 1e-8) << d << " " << n;
      EXPECT_NEAR(s.cooling_rate, e.cooling_rate, 1e-8) << d << " " << n;
      ASSERT_EQ(s.indices.size(), e.indices.size());
      for (std::size_t i = 0; i < s.indices.size(); ++i)
        EXPECT_NEAR(s.cumulant(s.indices[i][0], s.indices[i][1]), e.cumulant(s.indices[i][0], s.indices[i][1]), 1e-8)
            << d << " " << n << " a" << s.indices[i][0] << s.indices[i][1];
    }
  }
}

// With sliding (half the contacts at (0.9, 1, 0.5)): order 1 is the first-Sonine solver of §19.19 (its scan and
// regula falsi, the twenty-average table) to 1e-9; the steps |v_N − v_{N−1}| (v_0 the Maxwellian) of θ, ζ*, a20 and
// a02 shrink with the order in 2D and 3D (ζ*: from order 1 on); 8 against 16 panels per piece at order 2 agree to 1e-9.
TEST(RoughWaltonSonineHcs, OrderOneAndConvergence) {
  for (int d : {3, 2}) {
    const double kappa = d == 3 ? 0.4 : 0.5;
    const auto w = gkt::rough_walton_sonine_cooling_states(d, 0.9, 1.0, kappa, 0.5, 3);
    const auto f = gkt::rough_walton_linear_cooling_state(d, 0.9, 1.0, kappa, 0.5);
    ASSERT_TRUE(f.linear_scheme_solved);
    for (const auto& s : w) ASSERT_TRUE(s.solved) << d << " " << s.order;
    EXPECT_NEAR(w[0].temperature_ratio, f.temperature_ratio, 1e-9);
    EXPECT_NEAR(w[0].cooling_rate, f.cooling_rate, 1e-9);
    EXPECT_NEAR(w[0].cumulant(2, 0), f.a20, 1e-9);
    EXPECT_NEAR(w[0].cumulant(0, 2), f.a02, 1e-9);
    EXPECT_NEAR(w[0].cumulant(1, 1), f.a11, 1e-9);
    const auto steps = [&](auto value, double order_zero, bool from_maxwellian = true) {
      const double s1 = std::abs(value(w[0]) - order_zero), s2 = std::abs(value(w[1]) - value(w[0])),
                   s3 = std::abs(value(w[2]) - value(w[1]));
      std::printf("d=%d steps %.3g %.3g %.3g\n", d, s1, s2, s3);
      if (from_maxwellian) {
        EXPECT_LT(s2, s1);
      }
      EXPECT_LT(s3, s2);
    };
    steps([](const auto& s) { return s.temperature_ratio; }, f.maxwellian_temperature_ratio);
    // ζ*: the Maxwellian value is within 1e-4 of the linear ones (2D: 8e-5, nearer than order 2 is to order 1).
    steps([](const auto& s) { return s.cooling_rate; }, f.maxwellian_cooling_rate, false);
    steps([](const auto& s) { return s.cumulant(2, 0); }, 0.0);
    steps([](const auto& s) { return s.cumulant(0, 2); }, 0.0);
    const auto fine = gkt::rough_walton_sonine_cooling_states(d, 0.9, 1.0, kappa, 0.5, 2, 16);
    EXPECT_NEAR(fine[1].temperature_ratio, w[1].temperature_ratio, 1e-9);
    for (const auto& [p, q] : w[1].indices) EXPECT_NEAR(fine[1].cumulant(p, q), w[1].cumulant(p, q), 1e-9);
  }
}

// Disks at (0.9, 1, 0.5) (the isotropic ansatz is complete in 2D: c·ŵ ≡ 0), against the library DSMC with the Walton
// rule (8000 particles, 20 + 40 × 5 collisions per particle, batch errors): θ, a20, a02 of order 3 within the
// printed error |v_3 − v_2| plus 0.5 % (θ) or 0.002 (a20) or 15 % (a02: the spin tail still creeps, §19.19) plus
// 4σ; a20 nearer the DSMC at order 3 than at order 1 (theory.md §19.25).
TEST(RoughWaltonSonineHcs, DisksAgainstDsmc) {
  const auto w = gkt::rough_walton_sonine_cooling_states(2, 0.9, 1.0, 0.5, 0.5, 3);
  ASSERT_TRUE(w[2].solved);
  const auto s = gkt::test::run_rough_hcs_dsmc(2, 0.9, 1.0, 0.5, w[2].temperature_ratio, 8000, 20, 40, 5, 7, 0.5);
  const double theta = w[2].temperature_ratio, a20 = w[2].cumulant(2, 0), a02 = w[2].cumulant(0, 2);
  std::printf("walton order 3 d=2: theta %.5f DSMC %.5f +- %.5f; a20 %.5f / %.5f +- %.5f; a02 %.5f / %.5f +- %.5f\n",
              theta, s.theta, s.theta_error, a20, s.a20, s.a20_error, a02, s.a02, s.a02_error);
  EXPECT_NEAR(theta, s.theta, std::abs(theta - w[1].temperature_ratio) + 0.005 * s.theta + 4 * s.theta_error);
  EXPECT_NEAR(a20, s.a20, std::abs(a20 - w[1].cumulant(2, 0)) + 0.002 + 4 * s.a20_error);
  EXPECT_NEAR(a02, s.a02, std::abs(a02 - w[1].cumulant(0, 2)) + 0.15 * std::abs(s.a02) + 4 * s.a02_error);
  EXPECT_LT(std::abs(a20 - s.a20), std::abs(w[0].cumulant(2, 0) - s.a20) + s.a20_error);
}

// No torque (μ_f = 0) or β0 = −1: the spin decouples at every order (θ = inf, the rest NaN); bad input names the
// field; orders beyond 3 are refused.
TEST(RoughWaltonSonineHcs, DecoupledSpinAndBadInput) {
  for (const auto& w : {gkt::rough_walton_sonine_cooling_states(3, 0.9, 1.0, 0.4, 0.0, 2),
                        gkt::rough_walton_sonine_cooling_states(2, 0.9, -1.0, 0.5, 0.5, 2)})
    for (const auto& s : w) {
      EXPECT_TRUE(s.spin_decoupled);
      EXPECT_FALSE(s.solved);
      EXPECT_TRUE(std::isinf(s.temperature_ratio));
      EXPECT_TRUE(std::isnan(s.cooling_rate));
      EXPECT_TRUE(std::isnan(s.cumulant(2, 0)));
    }
  EXPECT_THROW((void)gkt::rough_walton_sonine_cooling_states(3, 0.9, 1.0, 0.4, 0.5, 4), std::invalid_argument);
  EXPECT_THROW((void)gkt::rough_walton_sonine_cooling_states(3, 0.9, 1.0, 0.4, 0.5, 0), std::invalid_argument);
  EXPECT_THROW((void)gkt::rough_walton_sonine_cooling_states(3, 1.5, 1.0, 0.4, 0.5, 1), std::invalid_argument);
  EXPECT_THROW((void)gkt::rough_walton_sonine_cooling_states(3, 0.9, 1.0, 0.4, -1.0, 1), std::invalid_argument);
}

// Navier–Stokes about the cumulant HCS (theory.md §19.25, (19.127)): at μ_f = ∞ the Walton elements weighted by
// Φ = Σ a_pq S_p S_q (quadrature, products of up to 2K + 4 forms) and the sources over f0 give the constant-β
// solver's values about its first-Sonine linear HCS (exact weighted engine tables, RoughSonineTransport::
// at_cooling_state) to 1e-8 at orders 1, 2, d = 2, 3; with sliding (0.9, 1, 0.5) the cumulant reference moves every
// column away from the Maxwellian reference (by more than 1e-3 relative).
TEST(RoughWaltonSonineHcs, TransportAboutTheCumulantHcs) {
  for (int d : {3, 2}) {
    const Rational alpha(9, 10), beta(1, 2), kappa = d == 3 ? Rational(2, 5) : Rational(1, 2);
    const auto hcs = gkt::rough_walton_sonine_cooling_states(d, 0.9, 0.5, kappa.to_double(), kInf, 1);
    const auto w = gkt::rough_walton_sonine_transport_about_hcs(d, 0.9, 0.5, kappa.to_double(), kInf, hcs[0], 2);
    const gkt::RoughSonineTransport t(d, alpha, beta, kappa, 2, 2);
    const auto e = gkt::rough_sonine_cooling_state(d, alpha, beta, kappa, 1, gkt::RoughSonineScheme::linear);
    for (int n = 1; n <= 2; ++n) {
      const auto v = t.at_cooling_state(n, e);
      const auto& x = w[static_cast<std::size_t>(n - 1)];
      EXPECT_NEAR(x.shear_viscosity, v.shear_viscosity, 1e-8) << d << " " << n;
      EXPECT_NEAR(x.thermal_conductivity, v.thermal_conductivity, 1e-8) << d << " " << n;
      EXPECT_NEAR(x.density_heat_coefficient, v.density_heat_coefficient, 1e-8) << d << " " << n;
      EXPECT_NEAR(x.bulk_viscosity, v.bulk_viscosity, 1e-8) << d << " " << n;
      EXPECT_NEAR(x.cooling_rate_first_order, v.cooling_rate_first_order, 1e-8) << d << " " << n;
    }
  }
  const auto hcs = gkt::rough_walton_sonine_cooling_states(3, 0.9, 1.0, 0.4, 0.5, 1);
  const auto about = gkt::rough_walton_sonine_transport_about_hcs(3, 0.9, 1.0, 0.4, 0.5, hcs[0], 1);
  const auto maxwellian =
      gkt::rough_walton_sonine_transport(3, 0.9, 1.0, 0.4, 0.5, hcs[0].maxwellian_temperature_ratio, 1);
  for (const auto& [x, y] : {std::pair{about[0].shear_viscosity, maxwellian[0].shear_viscosity},
                             std::pair{about[0].thermal_conductivity, maxwellian[0].thermal_conductivity},
                             std::pair{about[0].bulk_viscosity, maxwellian[0].bulk_viscosity}})
    EXPECT_GT(std::abs(x - y), 1e-3 * std::abs(y));
  auto unsolved = hcs[0];
  unsolved.solved = false;
  EXPECT_THROW((void)gkt::rough_walton_sonine_transport_about_hcs(3, 0.9, 1.0, 0.4, 0.5, unsolved, 1),
               std::invalid_argument);
}

// The oriented ansatz (theory.md §19.29): at μ_f = ∞ θ, ζ*, every a_pq, every b_pq and C of orders 1–3 equal the
// constant-β oriented linear scheme (exact engine tables with the forms c·w, rough_sonine_cooling_state with
// RoughSonineAnsatz::oriented) to 1e-8 — the quadrature's c·ŵ forms and the P tests against the engine; disks: the
// oriented ansatz is the isotropic one (C NaN, no b).
TEST(RoughWaltonSonineHcs, OrientedInfiniteFrictionIsTheConstantBetaOrientedScheme) {
  const Rational alpha(9, 10), beta(1, 2), kappa(2, 5);
  const auto w =
      gkt::rough_walton_sonine_cooling_states(3, 0.9, 0.5, 0.4, kInf, 3, 8, gkt::RoughSonineAnsatz::oriented);
  ASSERT_EQ(w.size(), 3U);
  for (int n = 1; n <= 3; ++n) {
    const auto e = gkt::rough_sonine_cooling_state(3, alpha, beta, kappa, n, gkt::RoughSonineScheme::linear,
                                                   gkt::RoughSonineAnsatz::oriented);
    const auto& s = w[static_cast<std::size_t>(n - 1)];
    ASSERT_TRUE(e.solved && s.solved) << n;
    std::printf("order %d: theta %.9f / %.9f  C %.9f / %.9f\n", n, s.temperature_ratio, e.temperature_ratio,
                s.orientation_correlation, e.orientation_correlation);
    EXPECT_NEAR(s.temperature_ratio, e.temperature_ratio, 1e-8) << n;
    EXPECT_NEAR(s.cooling_rate, e.cooling_rate, 1e-8) << n;
    EXPECT_NEAR(s.orientation_correlation, e.orientation_correlation, 1e-8) << n;
    ASSERT_EQ(s.indices.size(), e.indices.size());
    for (const auto& [p, q] : s.indices) EXPECT_NEAR(s.cumulant(p, q), e.cumulant(p, q), 1e-8) << n << " a" << p << q;
    ASSERT_EQ(s.orientation_indices.size(), e.orientation_indices.size());
    ASSERT_EQ(s.orientation_indices.size(), static_cast<std::size_t>(n * (n + 1) / 2));
    for (const auto& [p, q] : s.orientation_indices)
      EXPECT_NEAR(s.orientation_coefficient(p, q), e.orientation_coefficient(p, q), 1e-8) << n << " b" << p << q;
  }
  const auto disks =
      gkt::rough_walton_sonine_cooling_states(2, 0.9, 1.0, 0.5, 0.5, 2, 8, gkt::RoughSonineAnsatz::oriented);
  const auto isotropic = gkt::rough_walton_sonine_cooling_states(2, 0.9, 1.0, 0.5, 0.5, 2);
  for (std::size_t n = 0; n < 2; ++n) {
    EXPECT_TRUE(disks[n].orientation_indices.empty());
    EXPECT_TRUE(std::isnan(disks[n].orientation_correlation));
    EXPECT_EQ(disks[n].temperature_ratio, isotropic[n].temperature_ratio);
  }
}

// 3D with half the contacts sliding, (0.9, 1, 0.5) (theory.md §19.29): against the library DSMC with the Walton rule
// (four runs of 16000 particles, 30 + 10 × 10 collisions per particle, mean ± standard error of the run means), the
// oriented order-3 θ, a11 and C within the step from order 2 plus 3σ, while the isotropic order-3 θ and a11 (§19.25)
// lie more than their step plus 3σ away and C = 1/3 more than 10σ. The rule with 4 panels per piece (within 1.3e-7
// of 8, §19.19) halves the cost.
TEST(RoughWaltonSonineHcs, OrientedAgainstDsmcInThreeDimensions) {
  const auto o = gkt::rough_walton_sonine_cooling_states(3, 0.9, 1.0, 0.4, 0.5, 3, 4, gkt::RoughSonineAnsatz::oriented);
  const auto i = gkt::rough_walton_sonine_cooling_states(3, 0.9, 1.0, 0.4, 0.5, 3, 4);
  for (const auto& s : {o[1], o[2], i[1], i[2]}) ASSERT_TRUE(s.solved);
  std::vector<double> theta, a11, c;
  for (std::uint64_t seed : {1u, 2u, 3u, 4u}) {
    const auto s =
        gkt::test::run_rough_hcs_dsmc(3, 0.9, 1.0, 0.4, o[2].temperature_ratio, 16000, 30, 10, 10, seed, 0.5);
    theta.push_back(s.theta);
    a11.push_back(s.a11);
    c.push_back(s.orientation);
  }
  double t = 0, te = 0, a = 0, ae = 0, cc = 0, ce = 0;  // run means ± standard errors
  gkt::test::batch_mean(theta, t, te);
  gkt::test::batch_mean(a11, a, ae);
  gkt::test::batch_mean(c, cc, ce);
  std::printf("DSMC theta %.5f +- %.5f a11 %.5f +- %.5f C %.5f +- %.5f\n", t, te, a, ae, cc, ce);
  std::printf("oriented N=3 theta %.5f a11 %.5f C %.5f; isotropic theta %.5f a11 %.5f\n", o[2].temperature_ratio,
              o[2].cumulant(1, 1), o[2].orientation_correlation, i[2].temperature_ratio, i[2].cumulant(1, 1));
  EXPECT_LT(te, 0.003) << "DSMC too noisy";
  EXPECT_NEAR(o[2].temperature_ratio, t, std::abs(o[2].temperature_ratio - o[1].temperature_ratio) + 3 * te);
  EXPECT_NEAR(o[2].cumulant(1, 1), a, std::abs(o[2].cumulant(1, 1) - o[1].cumulant(1, 1)) + 3 * ae);
  EXPECT_NEAR(o[2].orientation_correlation, cc,
              std::abs(o[2].orientation_correlation - o[1].orientation_correlation) + 3 * ce);
  EXPECT_GT(std::abs(i[2].temperature_ratio - t), std::abs(i[2].temperature_ratio - i[1].temperature_ratio) + 3 * te);
  EXPECT_GT(std::abs(i[2].cumulant(1, 1) - a), std::abs(i[2].cumulant(1, 1) - i[1].cumulant(1, 1)) + 3 * ae);
  EXPECT_LT(cc, 1.0 / 3 - 10 * ce);
}
