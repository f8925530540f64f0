// Free cooling of a granular mixture (CVODE, theory.md §16.7): from equipartition (or given ratios)
// T_i/T and a_k,i relax to the HCS of the steady solver; started in the HCS, Haff's law; bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "gkt/evolution/mixture_cooling_evolution.hpp"
#include "gkt/transport/mixture/mixture_cooling_state.hpp"

using gkt::MixtureHcsScheme;

namespace {
gkt::Mixture unequal_binary(int d, double phi) {
  return gkt::make_mixture(d, {{1, 1, 0.5, ""}, {4, 1, 0.5, ""}}, 0.8, phi);
}
}  // namespace

// The long-time limit of the trajectory is the rest point of the same equations, i.e. the HCS of
// mixture_cooling_state in the same scheme: the DSMC binary of theory.md §16.3 (m2/m1 = 4, α = 0.8,
// 3D) in the linear scheme at K = 2 and 3 and, for an unequal-size dense ternary from unequal
// initial temperatures, in the Maxwellian scheme. Tolerance: the trajectory decays as e^{−λτ} with
// λ = O(ζ*); at τ = 2000 what is left is CVODE's error, rtol = 1e-10 → 1e-9 on γ_i, a_k,i, ζ*.
TEST(MixtureEvolution, LongTimeLimitIsTheHcs) {
  struct Case {
    gkt::Mixture mixture;
    MixtureHcsScheme scheme;
    int k;
    std::vector<double> start;
  };
  const gkt::Mixture ternary =
      gkt::make_mixture(2, {{1, 1, 0.2, ""}, {3, 1.5, 0.5, ""}, {0.5, 0.7, 0.3, ""}}, 0.7, 0.2);
  for (const Case& c : {Case{unequal_binary(3, 0), MixtureHcsScheme::linear, 2, {1, 1}},
                        Case{unequal_binary(3, 0), MixtureHcsScheme::linear, 3, {1.5, 0.5}},
                        Case{ternary, MixtureHcsScheme::maxwellian, 2, {2, 0.6, 1}}}) {
    const gkt::MixtureCoolingState hcs = gkt::mixture_cooling_state(c.mixture, c.scheme, c.k);
    ASSERT_TRUE(hcs.solved);
    const auto r = gkt::evolve_mixture_cooling(c.mixture, c.scheme, c.k, c.start, {}, {1.0, 2000.0}, 1e-10, 1e-14);
    const auto& early = r.samples.front();
    const auto& last = r.samples.back();
    for (std::size_t i = 0; i < c.mixture.size(); ++i) {
      EXPECT_NEAR(last.temperature_ratio[i], hcs.temperature_ratio[i], 1e-9) << i;
      // Not there at τ = 1: the test can tell a relaxed state from the start.
      EXPECT_GT(std::abs(early.temperature_ratio[i] - hcs.temperature_ratio[i]), 1e-3) << i;
      for (int k = 2; k <= c.k; ++k)
        EXPECT_NEAR(last.cumulants[i][static_cast<std::size_t>(k)], hcs.cumulants[i][static_cast<std::size_t>(k)], 1e-9)
            << i << " " << k;
    }
    EXPECT_NEAR(last.cooling_rate, hcs.cooling_rate, 1e-9);
  }
}

// Started in the HCS the state stays there and T follows Haff's law: dT/dτ = −ζ* T √(T/T(0)) with
// τ = ν0(0) t gives T/T(0) = (1 + ζ*τ/2)^{−2} (to the integration tolerance, up to τ = 10⁴).
TEST(MixtureEvolution, HaffsLawFromTheHcs) {
  for (int d : {2, 3}) {
    const gkt::Mixture m = unequal_binary(d, 0.25);
    const gkt::MixtureCoolingState hcs = gkt::mixture_cooling_state(m, MixtureHcsScheme::linear, 2);
    const std::vector<std::vector<double>> a{{hcs.a2[0]}, {hcs.a2[1]}};
    const auto r = gkt::evolve_mixture_cooling(m, MixtureHcsScheme::linear, 2, hcs.temperature_ratio, a,
                                               {0.1, 10.0, 1e3, 1e4}, 1e-10, 1e-16);
    for (const auto& s : r.samples) {
      EXPECT_NEAR(s.temperature * std::pow(1 + hcs.cooling_rate * s.time / 2, 2), 1, 1e-7) << d << " " << s.time;
      EXPECT_NEAR(s.temperature_ratio[0], hcs.temperature_ratio[0], 1e-9);
      EXPECT_NEAR(s.cumulants[1][2], hcs.a2[1], 1e-9);
    }
  }
}

// Bad input: one line naming the field.
TEST(MixtureEvolution, RejectsBadInput) {
  const gkt::Mixture m = unequal_binary(3, 0);
  auto message = [&](MixtureHcsScheme scheme, int k, std::vector<double> start, std::vector<std::vector<double>> a,
                     std::vector<double> times) {
    try {
      (void)gkt::evolve_mixture_cooling(m, scheme, k, start, a, times, 1e-8, 1e-12);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const auto L = MixtureHcsScheme::linear;
  EXPECT_EQ(message(L, 2, {1.2, 1}, {}, {1}).rfind("temperature_ratio_i: ", 0), 0U);
  EXPECT_EQ(message(L, 2, {-1, 3}, {}, {1}).rfind("temperature_ratio_1: ", 0), 0U);
  EXPECT_EQ(message(L, 2, {1}, {}, {1}).rfind("temperature_ratio: ", 0), 0U);
  EXPECT_EQ(message(L, 7, {1, 1}, {}, {1}).rfind("hcs_order: ", 0), 0U);
  EXPECT_EQ(message(MixtureHcsScheme::maxwellian, 2, {1, 1}, {{0.1}, {0}}, {1}).rfind("a2_species_i: ", 0), 0U);
  EXPECT_EQ(message(L, 2, {1, 1}, {{0.1, 0.2}, {0}}, {1}).rfind("a2_species_i: ", 0), 0U);
  EXPECT_EQ(message(L, 2, {1, 1}, {}, {2, 1}).rfind("times: ", 0), 0U);
}

// The interpolated pair moments of MixtureCoolingDynamics give the rates of the exact
// mixture_cooling_rates to 1e-12 inside the tabulated range of ln(γ_1/γ_2) and the exact ones outside
// it (3D binary m2/m1 = 4, linear K = 3, a state away from the HCS).
TEST(MixtureEvolution, InterpolatedMomentsEqualExactOnes) {
  const gkt::Mixture m = unequal_binary(3, 0.1);
  const std::vector<double> low{0, -0.5, 0.5, 0}, high{0, 0.1, -0.1, 0};
  const gkt::MixtureCoolingDynamics dynamics(m, MixtureHcsScheme::linear, 3, low, high);
  const std::vector<std::vector<double>> a{{1, 0, -0.02, 0.004}, {1, 0, 0.01, -0.003}};
  for (const double g1 : {0.8, 0.93, 1.0, 0.3}) {  // ln(γ_1/γ_2) = −0.45 … 0 inside, −1.9 outside
    const std::vector<double> gamma{g1, 2 - g1};
    const auto exact = gkt::mixture_cooling_rates(m, gamma, a, MixtureHcsScheme::linear);
    const auto fast = dynamics.rates(gamma, a);
    EXPECT_NEAR(fast.mixture_cooling_rate, exact.mixture_cooling_rate, 1e-12) << g1;
    for (std::size_t i = 0; i < 2; ++i) {
      EXPECT_NEAR(fast.cooling_rate[i], exact.cooling_rate[i], 1e-12) << g1;
      for (std::size_t k = 2; k <= 3; ++k) EXPECT_NEAR(fast.cumulant_rate[i][k], exact.cumulant_rate[i][k], 1e-12);
    }
    EXPECT_GT(std::abs(exact.cumulant_rate[0][2]), 1e-4);  // the rates are not trivially zero
  }
}
