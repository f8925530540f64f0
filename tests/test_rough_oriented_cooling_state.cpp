// The oriented Sonine HCS of rough spheres (docs/theory.md §19.14): the ansatz (19.26) plus the
// velocity–spin family b_pq P S_p^(5/2)(x) S_q^(5/2)(y), P = (c·ŵ)² − xy/3, in the linear scheme, against
//  (1) the limits: α = β = 1 is equilibrium (θ = 1, every a_pq and b_pq 0, C = 1/3); β = −1 decouples the
//      spin (no b, C = 1/3, the isotropic smooth values); disks have c·ŵ ≡ 0 (the oriented ansatz is the
//      isotropic one);
//  (2) the closed form of §19.8 (rough_orientation_correlation): b00 alone at the Maxwellian θ with the
//      a_pq left out is the same approximation;
//  (3) the in-suite DSMC (θ and C with error bars) at (0.9, 0.5), where the isotropic ansatz misses θ by
//      −0.37 % (two independent runs of 16000 particles), at strong roughness (0.7, 1) and at strong
//      inelasticity (0.3, 1) (one run of 8000 each; ~5 s in all);
//  (4) convergence of θ with the order at (0.9, 0.5).
// The nonlinear scheme with the oriented ansatz: test_rough_oriented_nonlinear.cpp (and its C against the DSMC
// here, sharing the runs).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "dsmc_rough.hpp"
#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"
#include "gkt/transport/rough/rough_orientation_correlation.hpp"
#include "gkt/transport/rough/rough_sonine_cooling_state.hpp"
#include "transport/rough/rough_sonine_balances.hpp"

using gkt::Rational;
using gkt::RoughSonineAnsatz;
using gkt::RoughSonineScheme;

namespace {

gkt::RoughSonineCoolingState oriented(int d, const Rational& alpha, const Rational& beta, const Rational& kappa,
                                      int order) {
  return gkt::rough_sonine_cooling_state(d, alpha, beta, kappa, order, RoughSonineScheme::linear,
                                         RoughSonineAnsatz::oriented);
}

/// Mean and standard error of independent runs' values.
struct RunMean {
  double mean = 0, error = 0;
};
RunMean run_mean(const std::vector<double>& x, const std::vector<double>& e) {
  // Two runs: the mean of the run means; the error from the batch errors combined (each within ~30 % of the run
  // spread for batches of ten collisions per particle, theory.md §21.4) and the run spread, whichever is larger.
  RunMean m;
  double var = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    m.mean += x[i] / static_cast<double>(x.size());
    var += e[i] * e[i];
  }
  double spread = 0;
  for (const double v : x) spread += (v - m.mean) * (v - m.mean);
  spread /= static_cast<double>(x.size() * (x.size() - 1));
  m.error = std::sqrt(std::max(var / static_cast<double>(x.size() * x.size()), spread));
  return m;
}

}  // namespace

TEST(RoughOrientedCoolingState, ElasticPerfectlyRoughIsEquilibrium) {
  for (int order : {1, 2, 3}) {
    const auto s = oriented(3, Rational(1), Rational(1), Rational(2, 5), order);
    ASSERT_TRUE(s.solved);
    EXPECT_NEAR(s.temperature_ratio, 1, 1e-12) << order;
    EXPECT_NEAR(s.cooling_rate, 0, 1e-13);
    EXPECT_EQ(s.orientation_indices.size(), static_cast<std::size_t>(order * (order + 1) / 2));
    for (const double a : s.cumulants) EXPECT_NEAR(a, 0, 1e-12) << order;
    for (const double b : s.orientation_coefficients) EXPECT_NEAR(b, 0, 1e-12) << order;
    EXPECT_NEAR(s.orientation_correlation, 1.0 / 3, 1e-13);
  }
}

TEST(RoughOrientedCoolingState, SmoothLimitAndDisksAreTheIsotropicAnsatz) {
  for (int d : {2, 3})
    for (int order : {1, 2}) {
      const Rational kappa(d == 3 ? 2 : 1, 5);
      for (const Rational& beta : {Rational(-1), Rational(1, 2)}) {
        if (d == 3 && beta != Rational(-1)) continue;  // spheres away from β = −1 do feel the b_pq (below)
        const auto o = oriented(d, Rational(4, 5), beta, kappa, order);
        const auto i =
            gkt::rough_sonine_cooling_state(d, Rational(4, 5), beta, kappa, order, RoughSonineScheme::linear);
        ASSERT_TRUE(o.solved && i.solved);
        EXPECT_TRUE(o.orientation_indices.empty()) << d << beta;
        EXPECT_TRUE(o.orientation_coefficients.empty());
        EXPECT_EQ(o.cooling_rate, i.cooling_rate) << d << beta << order;
        EXPECT_EQ(o.cumulants, i.cumulants);
        if (d == 2) {
          EXPECT_EQ(o.temperature_ratio, i.temperature_ratio);
          EXPECT_TRUE(std::isnan(o.orientation_correlation));  // ŵ ⟂ the plane of c: no orientation variable
        } else {
          EXPECT_TRUE(std::isinf(o.temperature_ratio));
          EXPECT_EQ(o.orientation_correlation, 1.0 / 3);  // β = −1: no correlation generated
        }
      }
    }
}

// The b00 balance alone at the Maxwellian τ with every a_pq = 0 is §19.8's first approximation (19.14),
// assembled there from 13 separate engine tables: b and C = 1/3 + b/5 agree.
TEST(RoughOrientedCoolingState, FirstTermAloneIsTheClosedForm) {
  for (const auto& [alpha, beta, kappa] : {std::array<Rational, 3>{Rational(9, 10), Rational(1, 2), Rational(2, 5)},
                                           std::array<Rational, 3>{Rational(1, 2), Rational(-1, 2), Rational(2, 5)},
                                           std::array<Rational, 3>{Rational(7, 10), Rational(1), Rational(1, 10)}}) {
    const auto closed = gkt::rough_orientation_correlation(alpha, beta, kappa);
    const gkt::detail::RoughSonineBalances b(3, alpha, beta, kappa, 2, false, true);
    ASSERT_EQ(b.orientations().size(), 1u);
    ASSERT_EQ(b.unknowns(), 4u);  // a20, a11, a02, b00
    EXPECT_DOUBLE_EQ(b.correlation_weights()[0], 0.2);
    const double tau = closed.temperature_ratio / kappa.to_double();
    std::vector<double> u(4, 0.0);
    const double f0 = b.residual(tau, u, true).back();
    u[3] = 1;
    const double f1 = b.residual(tau, u, true).back();
    const double b00 = -f0 / (f1 - f0);
    EXPECT_NEAR(b00, closed.b, 1e-12) << alpha << " " << beta;
    EXPECT_NEAR(1.0 / 3 + b.correlation_weights()[0] * b00, closed.correlation, 1e-13);
    EXPECT_LT(std::abs(closed.b), 0.1);
    EXPECT_GT(std::abs(closed.b), 1e-3);  // a correlation is generated
  }
}

// 3D κ = 2/5 (0.9, 0.5): θ converges with the order (successive differences below 3e-4) to 0.8522, and the shift
// from the isotropic ansatz is the −0.37 % of theory.md §19.14; C stays within 1e-3 of its first value.
TEST(RoughOrientedCoolingState, ConvergesWithOrder) {
  std::vector<double> theta, c, iso;
  for (int order = 1; order <= 3; ++order) {
    const auto s = oriented(3, Rational(9, 10), Rational(1, 2), Rational(2, 5), order);
    const auto i = gkt::rough_sonine_cooling_state(3, Rational(9, 10), Rational(1, 2), Rational(2, 5), order,
                                                   RoughSonineScheme::linear);
    ASSERT_TRUE(s.solved && i.solved) << order;
    EXPECT_EQ(s.orientation_indices.size(), static_cast<std::size_t>(order * (order + 1) / 2));
    theta.push_back(s.temperature_ratio);
    c.push_back(s.orientation_correlation);
    iso.push_back(i.temperature_ratio);
  }
  EXPECT_LT(std::abs(theta[1] - theta[0]), 3e-4);
  EXPECT_LT(std::abs(theta[2] - theta[1]), 3e-4);
  EXPECT_NEAR(theta[2], 0.8522, 2e-4);
  for (int n = 0; n < 3; ++n) {
    EXPECT_NEAR(theta[n] / iso[n] - 1, -0.0035, 0.0005) << n;
    EXPECT_NEAR(c[n], c[0], 1e-3);
    EXPECT_LT(c[n], 1.0 / 3 - 3e-3);
  }
}

// The theory side is order 2 with its error |v_3 − v_2| (the model's estimate, theory.md §19.14), added to 3σ of
// the DSMC. θ's DSMC error at this cost (~0.002) does not resolve the isotropic ansatz's −0.0031 (the 28-run
// comparison of §19.14 does); C's does (C = 1/3 is > 5σ off at (0.9, 0.5)).
TEST(RoughOrientedCoolingState, AgainstTheDsmc) {
  const Rational kappa(2, 5);
  const auto with_error = [&kappa](const Rational& alpha, const Rational& beta) {
    const auto s2 = oriented(3, alpha, beta, kappa, 2), s3 = oriented(3, alpha, beta, kappa, 3);
    EXPECT_TRUE(s2.solved && s3.solved);
    return std::array<double, 4>{s2.temperature_ratio, std::abs(s3.temperature_ratio - s2.temperature_ratio),
                                 s2.orientation_correlation,
                                 std::abs(s3.orientation_correlation - s2.orientation_correlation)};
  };
  // (0.9, 0.5): two independent runs (seeds 5, 6) of 16000 particles, 20 + 200 collisions per particle.
  {
    const auto s = with_error(Rational(9, 10), Rational(1, 2));
    std::vector<double> theta, theta_e, c, c_e;
    for (std::uint64_t seed : {5u, 6u}) {
      const auto sim = gkt::test::run_rough_hcs_dsmc(3, 0.9, 0.5, 0.4, s[0], 16000, 20, 20, 10, seed);
      theta.push_back(sim.theta);
      theta_e.push_back(sim.theta_error);
      c.push_back(sim.orientation);
      c_e.push_back(sim.orientation_error);
    }
    const RunMean t = run_mean(theta, theta_e), cc = run_mean(c, c_e);
    EXPECT_LT(t.error, 0.0025) << "DSMC too noisy";
    EXPECT_NEAR(s[0], t.mean, 3 * t.error + s[1]);
    EXPECT_NEAR(s[2], cc.mean, 3 * cc.error + s[3]);
    EXPECT_LT(cc.mean, 1.0 / 3 - 5 * cc.error);  // the isotropic ansatz's C = 1/3 is excluded
    // The nonlinear scheme (every product of a_pq and b_pq kept) at order 1, its error the spread to order 2.
    const auto n1 = gkt::rough_sonine_cooling_state(3, Rational(9, 10), Rational(1, 2), kappa, 1,
                                                    RoughSonineScheme::nonlinear, RoughSonineAnsatz::oriented);
    const auto n2 = gkt::rough_sonine_cooling_state(3, Rational(9, 10), Rational(1, 2), kappa, 2,
                                                    RoughSonineScheme::nonlinear, RoughSonineAnsatz::oriented);
    ASSERT_TRUE(n1.solved && n2.solved);
    EXPECT_NEAR(n1.orientation_correlation, cc.mean,
                3 * cc.error + std::abs(n2.orientation_correlation - n1.orientation_correlation));
    EXPECT_NEAR(n1.temperature_ratio, t.mean, 3 * t.error + std::abs(n2.temperature_ratio - n1.temperature_ratio));
  }
  // Strong roughness (0.7, 1) and strong inelasticity (0.3, 1): one run of 8000 particles, 20 + 100 per particle.
  for (const auto& [alpha, beta] :
       {std::array<Rational, 2>{Rational(7, 10), Rational(1)}, std::array<Rational, 2>{Rational(3, 10), Rational(1)}}) {
    const auto s = with_error(alpha, beta);
    const auto sim =
        gkt::test::run_rough_hcs_dsmc(3, alpha.to_double(), beta.to_double(), 0.4, s[0], 8000, 20, 10, 10, 5);
    EXPECT_NEAR(s[0], sim.theta, 3 * sim.theta_error + s[1]) << alpha;
    EXPECT_NEAR(s[2], sim.orientation, 3 * sim.orientation_error + s[3]) << alpha;
    EXPECT_LT(s[2], 1.0 / 3 - 5e-4);
  }
}

// β → −1⁺ at α = 0.5 (theory.md §19.14): θ ~ 1/η_t² diverges, C tends to a limit below 1/3 at orders 1 and 2
// (the closed form's 1/3 − 3(1 − α)/(8(7 − α)) = 0.3045 at first approximation), while β = −1 itself has
// C = 1/3: the quasi-smooth limit is singular.
TEST(RoughOrientedCoolingState, QuasiSmoothLimitOfTheCorrelationIsSingular) {
  const Rational alpha(1, 2), kappa(2, 5);
  for (int order : {1, 2}) {
    const auto near = oriented(3, alpha, Rational(-9999, 10000), kappa, order);
    const auto nearer = oriented(3, alpha, Rational(-99999, 100000), kappa, order);
    const auto at = oriented(3, alpha, Rational(-1), kappa, order);
    ASSERT_TRUE(near.solved && nearer.solved && at.solved) << order;
    EXPECT_GT(nearer.temperature_ratio, 50 * near.temperature_ratio);                          // θ ∝ 1/(1 + β)²
    EXPECT_NEAR(nearer.orientation_correlation, near.orientation_correlation, 1e-4) << order;  // a limit
    EXPECT_LT(nearer.orientation_correlation, 1.0 / 3 - 0.01) << order;
    EXPECT_EQ(at.orientation_correlation, 1.0 / 3);
  }
}
