// Free cooling of rough spheres with the velocity–spin orientation term b00 P (docs/theory.md §19.13, the linear
// first-Sonine scheme of (19.26a) at order 1; `gkt evolve` with hcs = "linear-oriented") against
//  (1) the steady oriented solver (rough_sonine_cooling_state, order 1, linear, oriented) at late times: θ, ζ*,
//      a20, a02, a11, b00 and C = 1/3 + b00/5, from a cold and from a hot spin, and Haff's law;
//  (2) the isotropic scheme it extends: it starts at b00 = 0 and differs from the isotropic trajectory only through
//      b00 (θ moves by the orientation shift, −0.35 % at (0.9, 0.5), theory.md §19.14);
//  (3) α = β = 1: energy conserved, b00 = 0 at equipartition and back to 0 after a hot-spin start; bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "gkt/evolution/rough_cooling_evolution.hpp"
#include "gkt/transport/rough/rough_oriented_cooling_rates.hpp"
#include "gkt/transport/rough/rough_sonine_cooling_state.hpp"

using gkt::Rational;

TEST(RoughOrientedEvolution, RelaxesToTheOrientedSteadyState) {
  struct Case {
    Rational alpha, beta;
    double tr0;
  };
  for (const Case& c : {Case{Rational(9, 10), Rational(1, 2), 0.01}, Case{Rational(7, 10), Rational(1), 5}}) {
    const Rational kappa(2, 5);
    const auto steady = gkt::rough_sonine_cooling_state(3, c.alpha, c.beta, kappa, 1, gkt::RoughSonineScheme::linear,
                                                        gkt::RoughSonineAnsatz::oriented);
    ASSERT_TRUE(steady.solved);
    const gkt::RoughCoolingRates rates(3, c.alpha, c.beta, kappa);
    const gkt::RoughOrientedCoolingRates oriented(c.alpha, c.beta, kappa);
    const auto run = gkt::evolve_rough_oriented_cooling(rates, oriented, 1, c.tr0, {1e-7, 1e5, 2e5}, 1e-11, 1e-14);
    EXPECT_LT(std::abs(run.samples[0].b00), 1e-3) << c.alpha;  // starts at 0 (Maxwellian directions)
    const auto& end = run.samples.back();
    EXPECT_NEAR(end.rotational_temperature / end.translational_temperature, steady.temperature_ratio, 1e-8) << c.alpha;
    EXPECT_NEAR(end.cooling_rate, steady.cooling_rate, 1e-8);
    EXPECT_NEAR(end.a20, steady.cumulant(2, 0), 1e-8);
    EXPECT_NEAR(end.a02, steady.cumulant(0, 2), 1e-8);
    EXPECT_NEAR(end.a11, steady.cumulant(1, 1), 1e-8);
    EXPECT_NEAR(end.b00, steady.orientation_coefficient(0, 0), 1e-8);
    EXPECT_NEAR(end.orientation_correlation, steady.orientation_correlation, 1e-9);
    EXPECT_LT(end.orientation_correlation, 1.0 / 3 - 1e-4);  // C < 1/3 at both states
    const double exponent = std::log(end.translational_temperature / run.samples[1].translational_temperature) /
                            std::log(end.time / run.samples[1].time);
    EXPECT_NEAR(exponent, -2, 1e-3);
    // Against the isotropic linear trajectory: the same equations without b00, a different late θ.
    const auto iso = gkt::evolve_rough_cooling(rates, true, 1, c.tr0, {1e5, 2e5}, 1e-11, 1e-14);
    const auto& iso_end = iso.samples.back();
    EXPECT_GT(std::abs(end.rotational_temperature / end.translational_temperature -
                       iso_end.rotational_temperature / iso_end.translational_temperature),
              1e-4);
  }
}

// α = β = 1: energy conserved. From equipartition (T_r = T_t) the gas is in equilibrium and b00 stays 0; from a hot
// spin the exchange of energy between the unequal temperatures orients the gas for a while (b00 ≠ 0), and b00
// returns to 0 with the equipartition.
TEST(RoughOrientedEvolution, ElasticPerfectlyRoughRelaxesToUnoriented) {
  const gkt::RoughCoolingRates rates(3, Rational(1), Rational(1), Rational(2, 5));
  const gkt::RoughOrientedCoolingRates oriented(Rational(1), Rational(1), Rational(2, 5));
  for (const double tr0 : {1.0, 4.0}) {
    const double energy = 3 + 3 * tr0;
    const auto run = gkt::evolve_rough_oriented_cooling(rates, oriented, 1, tr0, {0.1, 1, 10, 100}, 1e-11, 1e-14);
    double largest = 0;
    for (const auto& s : run.samples) {
      EXPECT_NEAR(3 * s.translational_temperature + 3 * s.rotational_temperature, energy, 1e-8 * energy);
      EXPECT_NEAR(s.orientation_correlation, 1.0 / 3 + s.b00 / 5, 1e-14);
      largest = std::max(largest, std::abs(s.b00));
    }
    if (tr0 == 1) {
      EXPECT_LT(largest, 1e-12);
    } else {
      EXPECT_GT(largest, 1e-3);
    }
    EXPECT_NEAR(run.samples.back().translational_temperature, energy / 6, 1e-8);
    EXPECT_NEAR(run.samples.back().b00, 0, 1e-7);
  }
}

TEST(RoughOrientedEvolution, BadInputNamesTheField) {
  EXPECT_THROW(gkt::RoughOrientedCoolingRates(Rational(9, 10), Rational(-1), Rational(2, 5)), std::invalid_argument);
  const gkt::RoughCoolingRates disks(2, Rational(9, 10), Rational(1, 2), Rational(2, 5));
  const gkt::RoughCoolingRates other_kappa(3, Rational(9, 10), Rational(1, 2), Rational(1, 4));
  const gkt::RoughOrientedCoolingRates oriented(Rational(9, 10), Rational(1, 2), Rational(2, 5));
  EXPECT_THROW((void)gkt::evolve_rough_oriented_cooling(disks, oriented, 1, 1, {1}, 1e-8, 1e-12),
               std::invalid_argument);
  EXPECT_THROW((void)gkt::evolve_rough_oriented_cooling(other_kappa, oriented, 1, 1, {1}, 1e-8, 1e-12),
               std::invalid_argument);
  EXPECT_THROW((void)gkt::evolve_rough_oriented_cooling(
                   gkt::RoughCoolingRates(3, Rational(9, 10), Rational(1, 2), Rational(2, 5)), oriented, 1, 1, {1},
                   1e-8, 1e-12, {-0.5, 0, 0}),
               std::invalid_argument);  // a20 below −2/5
}
