// The first-Sonine (linear scheme) HCS of a binary mixture of rough spheres and disks (docs/theory.md §19.30):
// identical species against the one-gas linear HCS (§19.6); β = −1 on every pair against the smooth mixture's
// first-Sonine HCS (§16.3); the tracer limit x_2 → 0; the balances at the solution; a DSMC with cumulants.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "gkt/transport/mixture/mixture_cooling_state.hpp"
#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"
#include "gkt/transport/rough/rough_mixture_sonine_cooling_state.hpp"
#include "rough_binary_fixture.hpp"
#include "rough_mixture_dsmc.hpp"

using gkt::Rational;
using gkt::RoughBinaryMixture;
using gkt::RoughMixtureComponent;
using gkt::test::binary;
using gkt::test::kHeavy;
using gkt::test::kLight;

// (a) Two identical components (x = 0.3, 0.7) are one gas: γ_i = 1 and θ, ζ*, a20, a02, a11 of the one-gas
// linear first-Sonine HCS (a different code path: one-species engine tables with θ symbolic, a scan in τ) to
// 1e-10, d = 2, 3.
TEST(RoughMixtureSonineCoolingState, IdenticalSpeciesAreTheOneGasLinearHcs) {
  struct State {
    int d;
    Rational alpha, beta, kappa;
  };
  for (const State& s : {State{3, Rational(9, 10), Rational(1, 2), Rational(2, 5)},
                         State{3, Rational(7, 10), Rational(1), Rational(2, 5)},
                         State{2, Rational(9, 10), Rational(1, 2), Rational(1, 2)}}) {
    const RoughMixtureComponent a{Rational(1), s.kappa, 1.0, 0.3}, b{Rational(1), s.kappa, 1.0, 0.7};
    const auto mix = gkt::rough_mixture_sonine_cooling_state(
        binary(s.d, a, b, {s.alpha, s.alpha, s.alpha}, {s.beta, s.beta, s.beta}));
    const auto one = gkt::rough_homogeneous_cooling_state(s.d, s.alpha, s.beta, s.kappa, gkt::RoughHcsScheme::linear);
    ASSERT_TRUE(mix.solved && one.linear_scheme_solved);
    std::printf("identical d=%d: theta %.12f / %.12f, a20 %.12f / %.12f, zeta %.12f / %.12f (%d Newton steps)\n", s.d,
                mix.rotational_ratio[0], one.temperature_ratio, mix.a20[0], one.a20, mix.cooling_rate, one.cooling_rate,
                mix.iterations);
    for (std::size_t k = 0; k < 2; ++k) {
      EXPECT_NEAR(mix.temperature_ratio[k], 1.0, 1e-10);
      EXPECT_NEAR(mix.rotational_ratio[k], one.temperature_ratio, 1e-10);
      EXPECT_NEAR(mix.a20[k], one.a20, 1e-10);
      EXPECT_NEAR(mix.a02[k], one.a02, 1e-10);
      EXPECT_NEAR(mix.a11[k], one.a11, 1e-10);
    }
    EXPECT_NEAR(mix.cooling_rate, one.cooling_rate, 1e-10);
  }
}

// (b) β = −1 on every pair: both spins decoupled (θ_i = +∞, a02_i, a11_i NaN); γ_i, a20_i and ζ* are the smooth
// mixture's first-Sonine linear HCS (K = 2, (16.6)–(16.7), its own engine and iteration) to 1e-10, d = 2, 3.
TEST(RoughMixtureSonineCoolingState, SmoothLimitIsTheSmoothMixtureFirstSonine) {
  for (int d : {2, 3}) {
    const std::array<Rational, 3> alpha{Rational(3, 4), Rational(9, 10), Rational(1, 2)};
    const Rational m1(-1);
    const auto rough = gkt::rough_mixture_sonine_cooling_state(binary(d, kLight, kHeavy, alpha, {m1, m1, m1}));
    gkt::Species s1, s2;
    s1.mass = gkt::ExactValue(kLight.mass);
    s1.diameter = kLight.diameter;
    s1.fraction = kLight.fraction;
    s2.mass = gkt::ExactValue(kHeavy.mass);
    s2.diameter = kHeavy.diameter;
    s2.fraction = kHeavy.fraction;
    gkt::Mixture smooth = gkt::make_mixture(d, {s1, s2}, 0.75);
    smooth.alpha = {0.75, 0.9, 0.9, 0.5};
    const auto hcs = gkt::mixture_cooling_state(smooth, gkt::MixtureHcsScheme::linear, 2);
    ASSERT_TRUE(rough.solved && hcs.solved);
    std::printf("smooth limit d=%d: a20 %.12f, %.12f / %.12f, %.12f; zeta %.12f / %.12f\n", d, rough.a20[0],
                rough.a20[1], hcs.a2[0], hcs.a2[1], rough.cooling_rate, hcs.cooling_rate);
    for (std::size_t k = 0; k < 2; ++k) {
      EXPECT_TRUE(rough.spin_decoupled[k] && std::isinf(rough.rotational_ratio[k]));
      EXPECT_TRUE(std::isnan(rough.a02[k]) && std::isnan(rough.a11[k]));
      EXPECT_NEAR(rough.temperature_ratio[k], hcs.temperature_ratio[k], 1e-10) << "d=" << d;
      EXPECT_NEAR(rough.a20[k], hcs.a2[k], 1e-10) << "d=" << d;
    }
    EXPECT_NEAR(rough.cooling_rate, hcs.cooling_rate, 1e-10) << "d=" << d;
  }
}

// (c) x_2 → 0: at x_2 = 0 species 1 is the one gas (its linear HCS, (19.176)); the state is smooth in x_2, so the
// difference quotients at x_2 = 1e-4 and 1e-6 agree (to 2 %, or 1e-6 absolute where the slope vanishes) for all
// nine values.
TEST(RoughMixtureSonineCoolingState, TracerLimitIsContinuous) {
  const Rational alpha(9, 10), beta(1, 2);
  const auto at = [&](double x2) {
    RoughMixtureComponent a = kLight, b = kHeavy;
    a.fraction = 1 - x2;
    b.fraction = x2;
    const auto s = gkt::rough_mixture_sonine_cooling_state(binary(3, a, b, {alpha, alpha, alpha}, {beta, beta, beta}));
    EXPECT_TRUE(s.solved) << "x2=" << x2;
    return std::array<double, 9>{s.temperature_ratio[0],
                                 s.temperature_ratio[1],
                                 s.rotational_ratio[0],
                                 s.rotational_ratio[1],
                                 s.cooling_rate,
                                 s.a20[0],
                                 s.a02[0],
                                 s.a20[1],
                                 s.a02[1]};
  };
  const auto v0 = at(0), v4 = at(1e-4), v6 = at(1e-6);
  const auto one = gkt::rough_homogeneous_cooling_state(3, alpha, beta, kLight.kappa, gkt::RoughHcsScheme::linear);
  EXPECT_NEAR(v0[0], 1.0, 1e-12);
  EXPECT_NEAR(v0[2], one.temperature_ratio, 1e-10);
  EXPECT_NEAR(v0[4], one.cooling_rate, 1e-10);
  EXPECT_NEAR(v0[5], one.a20, 1e-10);
  EXPECT_NEAR(v0[6], one.a02, 1e-10);
  std::printf("tracer (x2 = 0): gamma_2 %.6f theta_2 %.6f a20_2 %.6f a02_2 %.6f\n", v0[1], v0[3], v0[7], v0[8]);
  for (std::size_t k = 0; k < 9; ++k) {
    const double s4 = (v4[k] - v0[k]) / 1e-4, s6 = (v6[k] - v0[k]) / 1e-6;
    EXPECT_NEAR(s4, s6, std::max(0.02 * std::abs(s6), 1e-6 / 1e-4)) << "value " << k;
  }
}

// At the solution the four rates of the linear scheme equal ζ* and the six fourth-degree balances vanish
// ((19.172)–(19.174)), re-evaluated through rough_mixture_linear_balances at the printed state; d = 2, 3.
TEST(RoughMixtureSonineCoolingState, BalancesVanishAtTheSolution) {
  for (int d : {2, 3}) {
    const auto m = binary(d, kLight, kHeavy, {Rational(9, 10), Rational(4, 5), Rational(7, 10)},
                          {Rational(1, 2), Rational(0), Rational(1, 2)});
    const auto s = gkt::rough_mixture_sonine_cooling_state(m);
    std::printf("d=%d: gamma %.6f %.6f theta %.6f %.6f zeta %.6f a20 %.5f %.5f a02 %.5f %.5f a11 %.5f %.5f\n", d,
                s.temperature_ratio[0], s.temperature_ratio[1], s.rotational_ratio[0], s.rotational_ratio[1],
                s.cooling_rate, s.a20[0], s.a20[1], s.a02[0], s.a02[1], s.a11[0], s.a11[1]);
    ASSERT_TRUE(s.solved);
    const std::array<double, 4> t{s.temperature_ratio[0], s.temperature_ratio[1],
                                  s.temperature_ratio[0] * s.rotational_ratio[0],
                                  s.temperature_ratio[1] * s.rotational_ratio[1]};
    const auto b =
        gkt::rough_mixture_linear_balances(m, t, {s.a20[0], s.a02[0], s.a11[0], s.a20[1], s.a02[1], s.a11[1]});
    for (double r : b.cooling_rate) EXPECT_NEAR(r, s.cooling_rate, 1e-10);
    for (double g : b.balance) EXPECT_NEAR(g, 0.0, 1e-10);
  }
}

// (d) Against the test-side DSMC (tests/rough_mixture_dsmc.hpp: rigid-body rule, no engine), 3D, 3000 spheres,
// 40 collisions per particle of relaxation, 40 batches of 5, cumulants measured per batch; three states, one at
// mass ratio 10. Every γ_i, θ_i, a20_i, a02_i, a11_i within 4σ of the batch error (the batches are correlated,
// so σ is somewhat small; measured at most 2.4σ, theory.md §19.30); the DSMC must see the cumulants (a02_2 of
// the third state > 10σ from 0) and, in the first state, exclude the Maxwellian θ_1 (0.8279, > 4σ) that the
// linear scheme's correction approaches.
TEST(RoughMixtureSonineCoolingState, AgainstDsmc) {
  struct Case {
    RoughMixtureComponent a, b;
    gkt::test::McRoughSpecies ma, mb;
    Rational alpha, beta;
    std::array<int, 2> count;
  };
  const std::vector<Case> cases{
      {kLight,
       kHeavy,
       {1.0, 1.0, 0.4, 1.0, 1.0},
       {4.0, 2.0, 0.5, 1.0, 1.0},
       Rational(9, 10),
       Rational(1, 2),
       {900, 2100}},
      {kLight, kHeavy, {1.0, 1.0, 0.4, 1.0, 1.0}, {4.0, 2.0, 0.5, 1.0, 1.0}, Rational(7, 10), Rational(1), {900, 2100}},
      {RoughMixtureComponent{Rational(1), Rational(2, 5), 1.0, 0.5},
       RoughMixtureComponent{Rational(10), Rational(2, 5), 1.0, 0.5},
       {1.0, 1.0, 0.4, 1.0, 1.0},
       {10.0, 1.0, 0.4, 1.0, 1.0},
       Rational(9, 10),
       Rational(1, 2),
       {1500, 1500}}};
  for (const Case& c : cases) {
    const auto state = gkt::rough_mixture_sonine_cooling_state(
        binary(3, c.a, c.b, {c.alpha, c.alpha, c.alpha}, {c.beta, c.beta, c.beta}));
    ASSERT_TRUE(state.solved);
    const double al = c.alpha.to_double(), be = c.beta.to_double();
    const auto dsmc =
        gkt::test::run_rough_mixture_dsmc({c.ma, c.mb}, c.count, {al, al, al}, {be, be, be}, 40, 40, 5, 20261203);
    const std::array<double, 4> t{state.temperature_ratio[0], state.temperature_ratio[1], state.rotational_ratio[0],
                                  state.rotational_ratio[1]};
    const std::array<double, 6> a{state.a20[0], state.a02[0], state.a11[0], state.a20[1], state.a02[1], state.a11[1]};
    const char* tn[] = {"gamma_1", "gamma_2", "theta_1", "theta_2"};
    const char* an[] = {"a20_1", "a02_1", "a11_1", "a20_2", "a02_2", "a11_2"};
    std::printf("m2/m1 = %.0f alpha %.1f beta %.1f\n", c.mb.mass, al, be);
    for (std::size_t k = 0; k < 4; ++k)
      std::printf("  %s linear %.4f DSMC %.4f +- %.4f (%.1f sigma)\n", tn[k], t[k], dsmc.mean[k], dsmc.error[k],
                  (t[k] - dsmc.mean[k]) / dsmc.error[k]);
    for (std::size_t k = 0; k < 6; ++k)
      std::printf("  %s linear %.4f DSMC %.4f +- %.4f (%.1f sigma)\n", an[k], a[k], dsmc.cumulant_mean[k],
                  dsmc.cumulant_error[k], (a[k] - dsmc.cumulant_mean[k]) / dsmc.cumulant_error[k]);
    for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(t[k], dsmc.mean[k], 4 * dsmc.error[k]) << tn[k];
    for (std::size_t k = 0; k < 6; ++k) EXPECT_NEAR(a[k], dsmc.cumulant_mean[k], 4 * dsmc.cumulant_error[k]) << an[k];
    if (&c == &cases[0]) {
      const auto maxwellian =
          gkt::rough_mixture_cooling_state(binary(3, c.a, c.b, {c.alpha, c.alpha, c.alpha}, {c.beta, c.beta, c.beta}));
      EXPECT_GT(std::abs(maxwellian.rotational_ratio[0] - dsmc.mean[2]), 4 * dsmc.error[2]);
    }
    if (&c == &cases[2]) {
      EXPECT_GT(dsmc.cumulant_mean[4], 10 * dsmc.cumulant_error[4]);
    }
  }
}
