// The rough HCS at any Sonine order (docs/theory.md §19.14) against
//  (1) the first-Sonine linear solver (order 1, linear scheme: the same equations);
//  (2) equilibrium at α = β = 1 (θ = 1, every cumulant 0, every order and scheme);
//  (3) the smooth gas at β = −1 (the spin decouples): a_p0 and ζ* equal the smooth-inelastic HCS
//      solver's a_p and ζ* at the same order (nonlinear and, at order 1, linear);
//  (4) convergence with order at two 3D states.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "gkt/transport/monodisperse/homogeneous_cooling_state.hpp"
#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"
#include "gkt/transport/rough/rough_sonine_cooling_state.hpp"

using gkt::Rational;
using gkt::RoughSonineScheme;

TEST(RoughSonineCoolingState, OrderOneLinearIsTheFirstSonineSolver) {
  struct Case {
    int d;
    Rational alpha, beta, kappa;
  };
  for (const Case& c :
       {Case{3, Rational(9, 10), Rational(1, 2), Rational(2, 5)}, Case{3, Rational(7, 10), Rational(1), Rational(2, 5)},
        Case{3, Rational(1, 2), Rational(1, 2), Rational(2, 5)},
        Case{2, Rational(9, 10), Rational(1, 2), Rational(1, 2)},
        Case{2, Rational(9, 10), Rational(3, 10), Rational(1)}}) {
    const auto first = gkt::rough_homogeneous_cooling_state(c.d, c.alpha, c.beta, c.kappa, gkt::RoughHcsScheme::linear);
    const auto s = gkt::rough_sonine_cooling_state(c.d, c.alpha, c.beta, c.kappa, 1, RoughSonineScheme::linear);
    ASSERT_TRUE(first.linear_scheme_solved);
    ASSERT_TRUE(s.solved);
    EXPECT_EQ(s.indices.size(), 3u);
    EXPECT_NEAR(s.temperature_ratio, first.temperature_ratio, 1e-12 * first.temperature_ratio) << c.d << c.alpha;
    EXPECT_NEAR(s.cooling_rate, first.cooling_rate, 1e-12);
    EXPECT_NEAR(s.cumulant(2, 0), first.a20, 1e-12);
    EXPECT_NEAR(s.cumulant(0, 2), first.a02, 1e-12);
    EXPECT_NEAR(s.cumulant(1, 1), first.a11, 1e-12);
    EXPECT_EQ(s.cumulant(3, 0), 0.0);  // beyond the order: truncated
  }
}

TEST(RoughSonineCoolingState, ElasticPerfectlyRoughIsEquilibrium) {
  for (int d : {2, 3})
    for (int order : {1, 2, 3})
      for (auto scheme : {RoughSonineScheme::linear, RoughSonineScheme::nonlinear}) {
        const auto s =
            gkt::rough_sonine_cooling_state(d, Rational(1), Rational(1), Rational(d == 3 ? 2 : 1, 5), order, scheme);
        ASSERT_TRUE(s.solved);
        EXPECT_NEAR(s.temperature_ratio, 1, 1e-12) << d << order;
        EXPECT_NEAR(s.cooling_rate, 0, 1e-13);
        EXPECT_EQ(s.indices.size(), static_cast<std::size_t>((order + 2) * (order + 3) / 2 - 3));
        for (const double a : s.cumulants) EXPECT_NEAR(a, 0, 1e-12) << d << order;
      }
}

TEST(RoughSonineCoolingState, SmoothLimitIsTheSmoothGasAtEveryOrder) {
  for (int d : {2, 3}) {
    gkt::HomogeneousCoolingState smooth(d);
    for (const Rational& alpha : {Rational(9, 10), Rational(3, 5)}) {
      for (int order = 1; order <= 3; ++order) {
        const auto s = gkt::rough_sonine_cooling_state(d, alpha, Rational(-1), Rational(2, 5), order,
                                                       RoughSonineScheme::nonlinear);
        const auto ref = smooth.solve(alpha, order + 1, gkt::HcsScheme::nonlinear);
        ASSERT_TRUE(s.solved && ref.solved);
        EXPECT_TRUE(s.spin_decoupled);
        EXPECT_TRUE(std::isinf(s.temperature_ratio));
        EXPECT_EQ(s.indices.size(), static_cast<std::size_t>(order));
        EXPECT_NEAR(s.cooling_rate, ref.cooling_rate, 1e-12) << d << " " << alpha << " " << order;
        for (int p = 2; p <= order + 1; ++p)
          EXPECT_NEAR(s.cumulant(p, 0), ref.a[static_cast<std::size_t>(p)], 1e-12) << d << alpha << order << p;
        EXPECT_TRUE(std::isnan(s.cumulant(0, 2)));
      }
      const auto lin =
          gkt::rough_sonine_cooling_state(d, alpha, Rational(-1), Rational(2, 5), 1, RoughSonineScheme::linear);
      const auto ref = smooth.solve(alpha, 2, gkt::HcsScheme::linear);
      EXPECT_NEAR(lin.cumulant(2, 0), ref.a[2], 1e-13);
      EXPECT_NEAR(lin.cooling_rate, ref.cooling_rate, 1e-13);
    }
  }
}

// 3D, κ = 2/5, (α, β) = (0.9, 0.5): θ converges with the order (successive differences shrink) in
// both schemes, to 0.8550 (theory.md §19.14), while the first-Sonine θ is 0.8554.
TEST(RoughSonineCoolingState, TemperatureRatioConvergesWithOrder) {
  for (auto scheme : {RoughSonineScheme::linear, RoughSonineScheme::nonlinear}) {
    std::vector<double> theta;
    for (int order = 1; order <= 3; ++order) {
      const auto s = gkt::rough_sonine_cooling_state(3, Rational(9, 10), Rational(1, 2), Rational(2, 5), order, scheme);
      ASSERT_TRUE(s.solved) << order;
      theta.push_back(s.temperature_ratio);
    }
    EXPECT_LT(std::abs(theta[2] - theta[1]), std::abs(theta[1] - theta[0]));
    EXPECT_GT(std::abs(theta[1] - theta[0]), 1e-4);  // the higher orders do move θ
    EXPECT_NEAR(theta[2], 0.8550, 2e-4);
  }
}
