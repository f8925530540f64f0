// The GNB ordering 1 − α² = r η_t, η_t → 0 (docs/theory.md §19.32; gkt/simulation/weakly_frictional_limit.hpp):
// the two branches of the homogeneous cooling state against the library's rough DSMC, and the hot
// branch's spin distribution (power law y^{−21/8} cut off by e^{−λy}) against the DSMC's ⟨y²⟩, ⟨y³⟩.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "dsmc_rough.hpp"
#include "gkt/simulation/weakly_frictional_limit.hpp"

namespace {

double eta_of_beta(double beta, double kappa) { return (1 + beta) * kappa / (2 * (1 + kappa)); }
double beta_of_eta(double eta, double kappa) { return 2 * (1 + kappa) * eta / kappa - 1; }

/// ⟨y²⟩ and ⟨y³⟩ (y = w²/⟨w²⟩) from the cumulants a02, a03 of d_r rotational degrees of freedom.
double spin_y2(double a02, int dr) { return (1 + a02) * (dr + 2) / dr; }
double spin_y3(double a03, int dr) { return (1 + a03) * (dr + 2) * (dr + 4) / (dr * dr); }

// (19.201)–(19.203): at η_t = 0.01 the DSMC's θ/η_t (r < r_c) and η_t θ/κ (r > r_c) within 4σ plus a
// relative 8η_t. The stand-alone survey of §19.32 measured the O(η_t) correction: 3D r = 2 gives
// θ/η_t = 2.77, 2.63, 2.59 at η_t = 0.02, 0.01, 0.005 (limit 2.5), i.e. at most 5.3 η_t relative; the
// hot branch is within 1 % at η_t = 0.01. The other branch's scaling, or r_c off by one, fails.
TEST(WeaklyFrictionalLimit, HcsBranchesAgreeWithTheRoughDsmc) {
  const double eta = 0.01;
  for (int d : {3, 2}) {
    const double kappa = d == 3 ? 0.4 : 0.5;
    for (double r : {2.0, 14.0}) {
      const gkt::WeaklyFrictionalHcs hcs = gkt::weakly_frictional_hcs(d, r, kappa);
      EXPECT_NEAR(hcs.critical_ratio, 6, 1e-12);  // 4(1/κ − 1) at κ = 2/5, 2(2/κ − 1) at κ = 1/2
      ASSERT_EQ(hcs.hot_spins, r > 6);
      const double theta =
          hcs.hot_spins ? hcs.scaled_temperature_ratio * kappa / eta : hcs.scaled_temperature_ratio * eta;
      const double alpha = std::sqrt(1 - r * eta), beta = beta_of_eta(eta, kappa);
      ASSERT_NEAR(eta_of_beta(beta, kappa), eta, 1e-15);
      const auto s = gkt::test::run_rough_hcs_dsmc(d, alpha, beta, kappa, theta, 500, 20 / eta, 20, 2 / eta, 17);
      EXPECT_NEAR(s.theta / theta, 1, 4 * s.theta_error / theta + 8 * eta) << "d = " << d << ", r = " << r;
      if (!hcs.hot_spins) {  // the cold branch's spin is Maxwellian: ⟨y²⟩ = (d_r + 2)/d_r
        EXPECT_NEAR(s.a02, 0, 4 * s.a02_error + 0.03) << "d = " << d;
      }
    }
  }
}

// (19.205)–(19.207): the hot branch's spin density is one-parameter family in λ. The DSMC's ⟨y²⟩ fixes
// λ; the family then predicts ⟨y³⟩, compared within 4σ (the DSMC's σ of ⟨y³⟩ and that of ⟨y²⟩ carried
// through λ) plus 6 % for the O(η_t) corrections at η_t = 0.02 (§19.32: the ⟨y³⟩ the survey finds at
// η_t = 0.02 and 0.01 differ by ≈ 5 % at r = 14). The Maxwellian spin (⟨y²⟩ = 5/3) and the shell of
// §19.18 (⟨y²⟩ = 1) are excluded, and λ/X lies near the value 0.35κ the fixed-α measurement of §19.18 gives.
TEST(WeaklyFrictionalLimit, SpinTailFollowsTheFokkerPlanckFamily) {
  const int d = 3, dr = 3;
  const double kappa = 0.4, eta = 0.02, r = 14;
  const gkt::WeaklyFrictionalHcs hcs = gkt::weakly_frictional_hcs(d, r, kappa);
  const double alpha = std::sqrt(1 - r * eta), beta = beta_of_eta(eta, kappa);
  const auto s = gkt::test::run_rough_hcs_dsmc(d, alpha, beta, kappa, hcs.scaled_temperature_ratio * kappa / eta, 500,
                                               4000, 16, 600, 23);
  const double y2 = spin_y2(s.a02, dr), y2_error = s.a02_error * (dr + 2) / dr;
  const double y3 = spin_y3(s.a03, dr), y3_error = s.a03_error * (dr + 2) * (dr + 4) / (dr * dr);
  EXPECT_GT(y2 - 5.0 / 3, 10 * y2_error);
  auto cutoff_for = [&](double target) {  // ⟨y²⟩ decreases with λ
    double lo = 1e-3, hi = 10;
    for (int it = 0; it < 40; ++it) {
      const double mid = std::sqrt(lo * hi);
      (gkt::weakly_frictional_spin_moments(d, mid).y2 > target ? lo : hi) = mid;
    }
    return std::sqrt(lo * hi);
  };
  const double lambda = cutoff_for(y2), lambda_up = cutoff_for(y2 + y2_error);
  const double predicted = gkt::weakly_frictional_spin_moments(d, lambda).y3,
               carried = std::abs(gkt::weakly_frictional_spin_moments(d, lambda_up).y3 - predicted);
  EXPECT_NEAR(y3, predicted, 4 * std::hypot(y3_error, carried) + 0.06 * predicted)
      << "⟨y²⟩ = " << y2 << ", λ = " << lambda;
  const double x = hcs.scaled_temperature_ratio;
  EXPECT_NEAR(lambda / x, 0.35 * kappa, 0.5 * 0.35 * kappa) << "λ = " << lambda;
}

// The closed forms: r_c, the two branches' limits, the tail exponent, the family's Maxwellian member
// (disks at λ = 1/2: ⟨y²⟩ = 3, ⟨y³⟩ = 15) and its shell limit λ → ∞ (⟨y²⟩ → 1).
TEST(WeaklyFrictionalLimit, ClosedForms) {
  // κ = 1, d = 3 gives r_c = 0: every r > 0 is hot, with η_t θ/κ = r/4
  EXPECT_NEAR(gkt::weakly_frictional_hcs(3, 8, 1).critical_ratio, 0, 1e-15);
  EXPECT_TRUE(gkt::weakly_frictional_hcs(3, 8, 1).hot_spins);
  EXPECT_NEAR(gkt::weakly_frictional_hcs(3, 8, 1).scaled_temperature_ratio, 2, 1e-12);
  // cold branch at r = 0, κ = 2/5: 1 − 1/ϑ = 3κ·4/12 = 0.4
  EXPECT_NEAR(gkt::weakly_frictional_hcs(3, 0, 0.4).scaled_temperature_ratio, 1 / 0.6, 1e-12);
  EXPECT_DOUBLE_EQ(gkt::weakly_frictional_spin_tail_exponent(3), 21.0 / 8);
  EXPECT_DOUBLE_EQ(gkt::weakly_frictional_spin_tail_exponent(2), 2.5);
  const auto gauss = gkt::weakly_frictional_spin_moments(2, 0.5);
  EXPECT_NEAR(gauss.y2, 3, 1e-5);
  EXPECT_NEAR(gauss.y3, 15, 1e-4);
  EXPECT_NEAR(gauss.drift_slope, 2, 1e-6);
  // the shell limit: Var y → (b + c1)/(λb), the Ornstein–Uhlenbeck width of (19.64), b + c1 = 136/45, b = 32/15
  const double shell = 200, variance = gkt::weakly_frictional_spin_moments(3, shell).y2 - 1;
  EXPECT_NEAR(variance * shell * (32.0 / 15) / (136.0 / 45), 1, 0.03);
  EXPECT_TRUE(std::isinf(gkt::weakly_frictional_spin_moments(3, 0).y2));
  // a smaller cutoff, a heavier tail
  EXPECT_GT(gkt::weakly_frictional_spin_moments(3, 0.1).y3, gkt::weakly_frictional_spin_moments(3, 0.3).y3);
}

TEST(WeaklyFrictionalLimit, RejectsBadInput) {
  EXPECT_THROW(gkt::weakly_frictional_hcs(4, 1, 0.4), std::invalid_argument);
  EXPECT_THROW(gkt::weakly_frictional_hcs(3, -1, 0.4), std::invalid_argument);
  EXPECT_THROW(gkt::weakly_frictional_hcs(3, 1, 0), std::invalid_argument);
  EXPECT_THROW(gkt::weakly_frictional_hcs(3, 6, 0.4), std::invalid_argument);  // r = r_c
  EXPECT_THROW(gkt::weakly_frictional_spin_moments(3, -1), std::invalid_argument);
  EXPECT_THROW(gkt::weakly_frictional_spin_moments(1, 1), std::invalid_argument);
  EXPECT_THROW(gkt::weakly_frictional_spin_tail_exponent(1), std::invalid_argument);
}

}  // namespace
