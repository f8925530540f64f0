// The shear viscosity measured by DSMC from the relaxation of a strained homogeneous cooling state
// (gkt/simulation/shear_viscosity_dsmc.hpp, docs/theory.md §21.6), with no Sonine input, against
// the converged elastic value and the converged Sonine η* at α = 0.8; bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "gkt/algebra/rational.hpp"
#include "gkt/simulation/random_stream.hpp"
#include "gkt/simulation/shear_viscosity_dsmc.hpp"
#include "gkt/transport/monodisperse/homogeneous_cooling_state.hpp"
#include "gkt/transport/monodisperse/navier_stokes.hpp"

namespace gkt {
namespace {

DsmcSchedule kicks(int particles, int count, double window, std::uint64_t seed) {
  DsmcSchedule s;
  s.particles = particles;
  s.relaxation = 20;
  s.batches = count;
  s.per_batch = window;
  s.seed = seed;
  return s;
}

/// η* from `runs` independent runs (mean and standard error over the runs).
DsmcEstimate measured(int d, double alpha, int runs) {
  std::vector<double> eta;
  for (int r = 0; r < runs; ++r) {
    const auto out = run_shear_viscosity_dsmc(d, {alpha, 0.5}, kicks(1000, 150, 15, dsmc_run_seed(23, r)));
    eta.push_back(mean_and_error(out.shear_viscosity).mean);
  }
  return mean_and_error(eta);
}

// 3D, 8 runs × 150 kicks (ε = 0.5) × 15 collisions per particle, N = 1000 (~2·10⁷ collisions per α,
// an error of ~0.5 %). α = 1: the converged elastic η* = 1.016034 (theory.md §7) within 4σ. α = 0.8:
// the converged Sonine η* (order 6, nonlinear HCS to a_7; 1.091821) within 4σ, and more than 4σ
// above the elastic value — the test fails if the weight e^{−ζ*τ/2} is dropped (η* ≈ 1.19) or its
// sign flipped, or if the kick's normalisation or the clock is off by a factor.
TEST(DsmcShearViscosity, AgreesWithElasticAndSonineValues) {
  const DsmcEstimate elastic = measured(3, 1.0, 8);
  EXPECT_NEAR(elastic.mean, 1.016034, 4 * elastic.error);
  EXPECT_GT(elastic.error, 0);
  EXPECT_LT(elastic.error, 0.015);  // the statistics this size is meant to give

  NavierStokesSolver ns(3);
  HomogeneousCoolingState h(3);
  const Rational alpha(4, 5);
  const double sonine = ns.solve(alpha, 6, h.solve(alpha, 7, HcsScheme::nonlinear).a).shear_viscosity;
  const DsmcEstimate inelastic = measured(3, 0.8, 8);
  EXPECT_NEAR(inelastic.mean, sonine, 4 * inelastic.error);
  EXPECT_GT(inelastic.mean - 1.016034, 4 * inelastic.error);
  std::cout << "[ DSMC ] eta* (3D, N = 1000, 8 runs x 150 kicks): alpha = 1: " << elastic.mean << " +- "
            << elastic.error << " (1.016034); alpha = 0.8: " << inelastic.mean << " +- " << inelastic.error
            << " (Sonine " << sonine << ")\n";
}

TEST(DsmcShearViscosity, BadInputNamesTheField) {
  auto message = [](int d, double alpha, double kick, const DsmcSchedule& s) {
    try {
      (void)run_shear_viscosity_dsmc(d, {alpha, kick}, s);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const DsmcSchedule good = kicks(100, 1, 1, 1);
  EXPECT_NE(message(3, 0, 0.25, good).find("alpha:"), std::string::npos);
  EXPECT_NE(message(3, 1.5, 0.25, good).find("alpha:"), std::string::npos);
  EXPECT_NE(message(3, 0.8, 0, good).find("viscosity_kick:"), std::string::npos);
  EXPECT_NE(message(3, 0.8, 0.6, good).find("viscosity_kick:"), std::string::npos);
  EXPECT_NE(message(4, 0.8, 0.25, good).find("dimension:"), std::string::npos);
  EXPECT_NE(message(3, 0.8, 0.25, kicks(1, 1, 1, 1)).find("particles:"), std::string::npos);
  EXPECT_EQ(message(2, 0.8, 0.25, good), "no error");
}

}  // namespace
}  // namespace gkt
