// Homogeneous cooling state: published closed forms (exact, as rational functions of α),
// limits, the convergence pattern of the Sonine series, and a DSMC simulation with error bars.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

#include "dsmc.hpp"
#include "gkt/algebra/sonine.hpp"
#include "gkt/transport/monodisperse/homogeneous_cooling_state.hpp"

using gkt::HcsScheme;
using gkt::Rational;
using gkt::RationalFunction;
using gkt::RationalPolynomial;

namespace {
RationalPolynomial c(long v) { return RationalPolynomial(v); }
}  // namespace

// van Noije & Ernst, Granular Matter 1, 57 (1998), first Sonine approximation, any d:
// a2 = 16(1−α)(1−2α²) / (9 + 24d − α(41 − 8d) + 30α²(1−α)). Compared as rational functions.
TEST(HcsFirstSonine, VanNoijeErnstExactly) {
  const auto a = RationalPolynomial::variable();
  for (int d : {2, 3}) {
    const auto fs = gkt::first_sonine_hcs(d);
    const RationalFunction vne{c(16) * (c(1) - a) * (c(1) - c(2) * a * a),
                               c(9 + 24 * d) - a * c(41 - 8 * d) + c(30) * a * a * (c(1) - a)};
    EXPECT_TRUE(fs.a2.equals(vne)) << "d=" << d << ": " << fs.a2.numerator.to_string() << " / "
                                   << fs.a2.denominator.to_string();
    // PHYSICS.md: a2(α = 1/2, 3D) = 4/76.25
    if (d == 3) {
      EXPECT_EQ(fs.a2.evaluate(Rational(1, 2)), Rational(16, 305));
    }
    // a2 vanishes at α = 1 and changes sign at α = 1/√2 (a root of 1 − 2α²).
    EXPECT_TRUE(fs.a2.evaluate(Rational(1)).is_zero());
    EXPECT_LT(fs.a2.evaluate(Rational(7, 10)) * fs.a2.evaluate(Rational(71, 100)), Rational(0));
  }
}

// Cooling rate, first Sonine, linear in a2 ([vannoije1998]; [brilliantov2004] eq. 6.25 for d = 3):
// ζ* = ((d+2)/(4d)) (1 − α²) (1 + 3a2/16), exactly.
TEST(HcsFirstSonine, CoolingRateExactly) {
  const auto a = RationalPolynomial::variable();
  for (int d : {2, 3}) {
    const auto fs = gkt::first_sonine_hcs(d);
    const RationalPolynomial zeta0 = RationalPolynomial(Rational(d + 2, 4 * d)) * (c(1) - a * a);
    EXPECT_EQ(fs.cooling_rate_0, zeta0) << d;
    EXPECT_EQ(fs.cooling_rate_a2, zeta0 * RationalPolynomial(Rational(3, 16))) << d;
  }
}

// The elastic limit: the Maxwellian is the HCS; every cumulant and ζ* vanish, at every order.
TEST(Hcs, ElasticLimitIsMaxwellian) {
  for (int d : {2, 3}) {
    gkt::HomogeneousCoolingState h(d);
    for (int k = 2; k <= 8; ++k) {
      const auto s = h.solve(Rational(1), k, HcsScheme::nonlinear);
      ASSERT_TRUE(s.solved);
      for (int j = 2; j <= k; ++j) EXPECT_EQ(s.a[j], 0.0);
      EXPECT_EQ(s.cooling_rate, 0.0);
    }
  }
}

// Continuity at α → 1 (no 0/0): a2 is linear in (1−α) with the van Noije–Ernst slope
// −16/(32d − 32) for the first Sonine approximation; the nonlinear K = 2 scheme agrees with it to
// O((1−α)²); the converged (K = 8) a2/(1−α) has a finite limit (values at 1−α = 1e-4 and 1e-5
// agree to 1e-3) — a different slope from first Sonine, as the two differ by ~8 % at α = 0.9.
TEST(Hcs, ContinuousAtAlphaOne) {
  for (int d : {2, 3}) {
    gkt::HomogeneousCoolingState h(d);
    const double slope = -16.0 / (32.0 * d - 32.0);
    double previous_ratio = 0;
    for (const Rational& eps : {Rational(1, 10000), Rational(1, 100000)}) {
      const double e = eps.to_double();
      const auto lin = h.solve(Rational(1) - eps, 2, HcsScheme::linear);
      const auto k2 = h.solve(Rational(1) - eps, 2, HcsScheme::nonlinear);
      const auto k8 = h.solve(Rational(1) - eps, 8, HcsScheme::nonlinear);
      ASSERT_TRUE(k2.solved && k8.solved);
      EXPECT_NEAR(lin.a[2] / e, slope, 1e-3);
      EXPECT_NEAR(k2.a[2], lin.a[2], 10 * e * e);
      EXPECT_NEAR(k8.cooling_rate / (1 - (1 - e) * (1 - e)), (d + 2) / (4.0 * d), 1e-3);
      const double ratio = k8.a[2] / e;
      if (previous_ratio != 0) {
        EXPECT_NEAR(ratio / previous_ratio, 1.0, 1e-3);
      }
      previous_ratio = ratio;
    }
  }
}

// Convergence in Sonine order (PHYSICS.md, verified there by an independent solver and DSMC):
// geometric for α ≥ 0.8; even/odd oscillation around α = 0.7; at α ≤ 0.3 the nonlinear
// truncations stop having a solution or swing by O(1) — the series is only asymptotic.
TEST(Hcs, ConvergencePatternInSonineOrder) {
  gkt::HomogeneousCoolingState h(3);
  // α = 0.9: corrections shrink geometrically; K = 10 and 12 agree to 1e-8.
  const auto k10 = h.solve(Rational(9, 10), 10, HcsScheme::nonlinear);
  const auto k12 = h.solve(Rational(9, 10), 12, HcsScheme::nonlinear);
  EXPECT_NEAR(k10.a[2], k12.a[2], 1e-8);
  double previous = 1;
  for (int k = 3; k <= 9; ++k) {
    const double delta = std::abs(h.solve(Rational(9, 10), k + 1, HcsScheme::nonlinear).a[2] -
                                  h.solve(Rational(9, 10), k, HcsScheme::nonlinear).a[2]);
    EXPECT_LT(delta, previous);
    previous = delta;
  }
  // α = 0.7: successive corrections alternate in sign.
  int sign_changes = 0;
  double last = 0;
  for (int k = 4; k <= 11; ++k) {
    const double delta = h.solve(Rational(7, 10), k + 1, HcsScheme::nonlinear).a[2] -
                         h.solve(Rational(7, 10), k, HcsScheme::nonlinear).a[2];
    if (last * delta < 0) ++sign_changes;
    last = delta;
  }
  EXPECT_GE(sign_changes, 5);
  // α = 0.2: some truncation K ≤ 12 has no real solution or a2 changes by more than 0.1.
  bool breaks_down = false;
  double a2_previous = h.solve(Rational(1, 5), 2, HcsScheme::nonlinear).a[2];
  for (int k = 3; k <= 12 && !breaks_down; ++k) {
    const auto s = h.solve(Rational(1, 5), k, HcsScheme::nonlinear);
    breaks_down = !s.solved || std::abs(s.a[2] - a2_previous) > 0.1;
    a2_previous = s.a[2];
  }
  EXPECT_TRUE(breaks_down);
}

// Why the Sonine series is asymptotic at every α < 1 (theory.md §10.6, §6): the HCS has the tail
// exp(−A c), A = 2β/ζ_r [vannoije1998], and the Maxwellian moment of order k peaks at c ≈ √k, which reaches the
// tail at c ≈ A/2: the cumulants decay only up to k ≈ A²/4 and grow beyond. 2D, K = 16: at α = 0.7
// (A²/4 ≈ 9.8) the even cumulants turn between A²/8 and A²/4 + 2 and |a_16| exceeds |a_8|; at
// α = 0.9 (A²/4 ≈ 71) they still decay. The same turn near k ≈ 20 (A²/4 = 19.8) stops κ*, μ* at
// ≈ 2e-8 in 2D at α = 0.8 (docs/performance.md).
TEST(Hcs, SonineCumulantsTurnWhereTheTailBegins) {
  const int d = 2;
  gkt::HomogeneousCoolingState h(d);
  const double beta = std::pow(std::numbers::pi, (d - 1) / 2.0) / std::tgamma((d + 1) / 2.0);
  const double nu = std::sqrt(2.0) * std::pow(std::numbers::pi, (d - 1) / 2.0) / std::tgamma(d / 2.0);
  auto onset = [&](const gkt::HcsState& s) {  // A²/4 with ζ_r = 4ν ζ*/(d + 2)
    const double a = 2 * beta / (4 * nu * s.cooling_rate / (d + 2));
    return a * a / 4;
  };
  const auto strong = h.solve(Rational(7, 10), 16, HcsScheme::nonlinear);
  ASSERT_TRUE(strong.solved);
  const double k_star = onset(strong);
  ASSERT_LT(k_star, 16.0);
  int k_min = 2;
  for (int k = 4; k <= 16; k += 2)
    if (std::abs(strong.a[k]) < std::abs(strong.a[k_min])) k_min = k;
  EXPECT_GE(k_min, k_star / 2);
  EXPECT_LE(k_min, k_star + 2);
  EXPECT_GT(std::abs(strong.a[16]), 3 * std::abs(strong.a[8]));

  const auto mild = h.solve(Rational(9, 10), 16, HcsScheme::nonlinear);
  ASSERT_TRUE(mild.solved);
  EXPECT_GT(onset(mild), 16.0);
  EXPECT_LT(std::abs(mild.a[16]), 0.05 * std::abs(mild.a[8]));
}

namespace {
/// ⟨x^p S_k(x)⟩ under the Maxwellian (x = c², S_k = S_{d/2−1}^(k)).
double maxwell_moment(int d, int p, int k) {
  std::vector<Rational> poly(static_cast<std::size_t>(p), Rational(0));
  const auto s = gkt::sonine_coefficients(gkt::sonine_twice_m(d, 0), k);
  poly.insert(poly.end(), s.begin(), s.end());
  return gkt::maxwell_average(d, poly).to_double();
}
}  // namespace

// DSMC (independent: simulates collisions, no Sonine expansion). a2 and a3 follow exactly from
// ⟨c⁴⟩ and ⟨c⁶⟩ (S_k is orthogonal to x^p for k > p). Tolerance: 4 standard errors (means of 180
// batches of five collisions per particle: batches of one were correlated, theory.md §21.4).
// At α = 0.8, 3D the converged Sonine a2 (−0.01431) and the first-Sonine a2 (−0.01258) differ by
// more than 4σ, so the test tells them apart.
TEST(HcsDsmc, CumulantsAgreeWithConvergedSonine) {
  struct Case {
    int d;
    Rational alpha;
  };
  for (const Case& k : {Case{3, Rational(4, 5)}, Case{2, Rational(4, 5)}}) {
    const double alpha = k.alpha.to_double();
    const auto m = gkt::test::run_hcs_dsmc(k.d, alpha, 20000, 8, 180, 5.0, 42);
    const double x2 = maxwell_moment(k.d, 2, 0), x3 = maxwell_moment(k.d, 3, 0);
    const double a2 = m.c4 / x2 - 1, a2_error = m.c4_error / x2;
    const double a3 = (m.c6 - x3 - a2 * maxwell_moment(k.d, 3, 2)) / maxwell_moment(k.d, 3, 3);
    const double a3_error =
        std::hypot(m.c6_error, a2_error * std::abs(maxwell_moment(k.d, 3, 2))) / std::abs(maxwell_moment(k.d, 3, 3));
    gkt::HomogeneousCoolingState h(k.d);
    const auto converged = h.solve(k.alpha, 10, HcsScheme::nonlinear);
    const auto first = h.solve(k.alpha, 2, HcsScheme::linear);
    EXPECT_NEAR(a2, converged.a[2], 4 * a2_error) << "d=" << k.d << " DSMC a2 = " << a2 << " ± " << a2_error;
    EXPECT_NEAR(a3, converged.a[3], 4 * a3_error) << "d=" << k.d << " DSMC a3 = " << a3 << " ± " << a3_error;
    if (k.d == 3) {
      EXPECT_GT(std::abs(a2 - first.a[2]), 4 * a2_error) << "DSMC cannot resolve the first-Sonine error";
    }
    std::cout << "[ DSMC ] d=" << k.d << " alpha=" << alpha << ": a2 = " << a2 << " ± " << a2_error
              << " (Sonine K=10: " << converged.a[2] << ", first Sonine: " << first.a[2] << "), a3 = " << a3 << " ± "
              << a3_error << " (Sonine K=10: " << converged.a[3] << ")\n";
  }
}
