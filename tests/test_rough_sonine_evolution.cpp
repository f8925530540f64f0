// Free cooling of rough spheres and disks at Sonine order N (docs/theory.md §19.13, (19.25b)–(19.25c); `gkt evolve`
// with `order`): the linear scheme's balances of every a_pq (and b_pq) integrated in time, against
//  (1) the steady Sonine HCS of the same order and ansatz (rough_sonine_cooling_state, §19.14) at late times, and
//      Haff's law;
//  (2) the order-1 trajectories of other engine tables (RoughCoolingRates, RoughOrientedCoolingRates) at N = 1;
//  (3) α = β = 1 (energy conserved, cumulants back to 0) and β = −1 (T_r untouched);
//  (4) the library DSMC from a cold spin: a02 and θ at the first collisions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "gkt/evolution/rough_cooling_evolution.hpp"
#include "gkt/transport/rough/rough_oriented_cooling_rates.hpp"
#include "gkt/transport/rough/rough_sonine_cooling_rates.hpp"
#include "gkt/transport/rough/rough_sonine_cooling_state.hpp"
#include "rough_evolution_checks.hpp"

namespace gkt {
namespace {

// The late-time state is the steady linear HCS of the same order and ansatz: θ, ζ*, every a_pq and b_pq, C.
TEST(RoughSonineEvolution, RelaxesToTheSonineHcsOfTheSameOrder) {
  struct Case {
    int d, order;
    Rational alpha, beta;
    RoughSonineAnsatz ansatz;
    double tr0;
  };
  const Rational kappa(2, 5);
  for (const Case& c : {Case{3, 2, Rational(9, 10), Rational(1, 2), RoughSonineAnsatz::oriented, 0.01},
                        Case{3, 3, Rational(7, 10), Rational(1), RoughSonineAnsatz::isotropic, 5},
                        Case{2, 2, Rational(9, 10), Rational(1, 2), RoughSonineAnsatz::isotropic, 0.01},
                        Case{3, 2, Rational(7, 10), Rational(-1), RoughSonineAnsatz::isotropic, 2}}) {
    const auto steady =
        rough_sonine_cooling_state(c.d, c.alpha, c.beta, kappa, c.order, RoughSonineScheme::linear, c.ansatz);
    ASSERT_TRUE(steady.solved);
    const RoughSonineCoolingRates rates(c.d, c.alpha, c.beta, kappa, c.order, c.ansatz);
    const auto run = evolve_rough_sonine_cooling(rates, 1, c.tr0, {1e-10, 1e5, 2e5}, 1e-11, 1e-14);
    const auto& end = run.samples.back();
    const std::string where = std::to_string(c.d) + "D N=" + std::to_string(c.order) + " beta=" + c.beta.to_string();
    if (c.beta == Rational(-1)) {
      for (const auto& s : run.samples) EXPECT_EQ(s.rotational_temperature, c.tr0) << where;  // no torque
    } else {
      EXPECT_NEAR(end.rotational_temperature / end.translational_temperature, steady.temperature_ratio, 1e-8) << where;
    }
    test::expect_sample_at_cooling_state(end, steady, c.d, where);
    const double exponent = std::log(end.translational_temperature / run.samples[1].translational_temperature) /
                            std::log(end.time / run.samples[1].time);
    EXPECT_NEAR(exponent, -2, 1e-3) << where;
    // The first sample is the initial distribution (Maxwellians): every cumulant ~ 0.
    for (const double a : run.samples[0].cumulants) EXPECT_LT(std::abs(a), 1e-4) << where;
  }
}

// At N = 1 the balances of the order-N tables (RoughSonineBalances, six forms) are those of the first-Sonine
// trajectory's own tables (RoughCoolingRates, three tables; RoughOrientedCoolingRates): the same trajectory to the
// integrator's tolerance.
TEST(RoughSonineEvolution, OrderOneIsTheFirstSonineTrajectory) {
  const Rational alpha(9, 10), beta(1, 2), kappa(2, 5);
  const std::vector<double> times{0.01, 0.3, 3, 30, 300};
  const RoughCumulants a0{0.1, -0.2, 0.05};
  const RoughCoolingRates first(3, alpha, beta, kappa);
  {
    const RoughSonineCoolingRates rates(3, alpha, beta, kappa, 1, RoughSonineAnsatz::isotropic);
    const auto generic = evolve_rough_sonine_cooling(rates, 1, 0.01, times, 1e-12, 1e-15, a0);
    const auto old = evolve_rough_cooling(first, true, 1, 0.01, times, 1e-12, 1e-15, a0);
    for (std::size_t i = 0; i < times.size(); ++i) {
      const auto &g = generic.samples[i], &o = old.samples[i];
      EXPECT_NEAR(g.translational_temperature / o.translational_temperature, 1, 1e-9) << i;
      EXPECT_NEAR(g.rotational_temperature / o.rotational_temperature, 1, 1e-9) << i;
      EXPECT_NEAR(g.collisions, o.collisions, 1e-9 * o.collisions) << i;
      EXPECT_NEAR(g.a20, o.a20, 1e-10) << i;
      EXPECT_NEAR(g.a02, o.a02, 1e-10) << i;
      EXPECT_NEAR(g.a11, o.a11, 1e-10) << i;
      EXPECT_NEAR(g.cooling_rate, o.cooling_rate, 1e-10) << i;
    }
  }
  const RoughSonineCoolingRates rates(3, alpha, beta, kappa, 1, RoughSonineAnsatz::oriented);
  const RoughOrientedCoolingRates oriented(alpha, beta, kappa);
  const auto generic = evolve_rough_sonine_cooling(rates, 1, 0.01, times, 1e-12, 1e-15);
  const auto old = evolve_rough_oriented_cooling(first, oriented, 1, 0.01, times, 1e-12, 1e-15);
  for (std::size_t i = 0; i < times.size(); ++i) {
    const auto &g = generic.samples[i], &o = old.samples[i];
    EXPECT_NEAR(g.rotational_temperature / o.rotational_temperature, 1, 1e-9) << i;
    EXPECT_NEAR(g.a02, o.a02, 1e-10) << i;
    EXPECT_NEAR(g.b00, o.b00, 1e-10) << i;
    EXPECT_NEAR(g.orientation_correlation, o.orientation_correlation, 1e-10) << i;
  }
}

// α = β = 1: d T_t + d_r T_r conserved; from a hot spin both temperatures and every cumulant relax to equilibrium.
TEST(RoughSonineEvolution, ElasticPerfectlyRoughGasConservesEnergy) {
  for (const int d : {3, 2}) {
    const double dr = d == 3 ? 3 : 1, energy = d * 1 + dr * 4;
    const RoughSonineCoolingRates rates(d, Rational(1), Rational(1), Rational(2, 5), 2,
                                        d == 3 ? RoughSonineAnsatz::oriented : RoughSonineAnsatz::isotropic);
    const auto run = evolve_rough_sonine_cooling(rates, 1, 4, {0.1, 1, 10, 300}, 1e-11, 1e-14);
    for (const auto& s : run.samples)
      EXPECT_NEAR(d * s.translational_temperature + dr * s.rotational_temperature, energy, 1e-8 * energy) << d;
    const auto& end = run.samples.back();
    EXPECT_NEAR(end.translational_temperature, energy / (d + dr), 1e-7) << d;
    for (const double a : end.cumulants) EXPECT_NEAR(a, 0, 1e-7) << d;
    for (const double b : end.orientation_coefficients) EXPECT_NEAR(b, 0, 1e-7) << d;
  }
}

TEST(RoughSonineEvolution, BadInputNamesTheField) {
  EXPECT_THROW(
      RoughSonineCoolingRates(3, Rational(9, 10), Rational(1, 2), Rational(2, 5), 0, RoughSonineAnsatz::isotropic),
      std::invalid_argument);
  const RoughSonineCoolingRates smooth(3, Rational(9, 10), Rational(-1), Rational(2, 5), 2,
                                       RoughSonineAnsatz::isotropic);
  EXPECT_THROW((void)evolve_rough_sonine_cooling(smooth, 1, 1, {1}, 1e-8, 1e-12, {0, 0.1, 0}), std::invalid_argument);
  const RoughSonineCoolingRates rates(3, Rational(9, 10), Rational(1, 2), Rational(2, 5), 2,
                                      RoughSonineAnsatz::isotropic);
  EXPECT_THROW((void)evolve_rough_sonine_cooling(rates, 1, 1, {1}, 1e-8, 1e-12, {-0.5, 0, 0}), std::invalid_argument);
  EXPECT_THROW((void)evolve_rough_sonine_cooling(rates, -1, 1, {1}, 1e-8, 1e-12), std::invalid_argument);
}

}  // namespace
}  // namespace gkt
