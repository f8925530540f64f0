// The Maxwellian HCS of a binary mixture of rough spheres and disks (docs/theory.md §19.17):
// the engine's energy-change coefficients against the hand-derived closed form (19.54), exactly;
// identical species against the one-component rough HCS; β = −1 translational rates against the
// smooth mixture's (16.4); α = β = 1 equipartition; the HCS's four rates equal.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "gkt/transport/mixture/mixture_cooling_state.hpp"
#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"
#include "gkt/transport/rough/rough_mixture_cooling_state.hpp"
#include "rough_binary_fixture.hpp"
#include "rough_mixture_dsmc.hpp"

using gkt::Rational;
using gkt::RoughBinaryMixture;
using gkt::RoughMixtureComponent;
using gkt::test::binary;
using gkt::test::kHeavy;
using gkt::test::kLight;

// (19.54): with V = T_t,i/m_i + T_t,j/m_j, W = T_r,i/(κ_i m_i) + T_r,j/(κ_j m_j), n_i = (1+α)m_j/(m_i+m_j),
// t_i = (1+β)M/m_i, r_i = t_i/κ_i,
//   ⟨ΔE_t,i⟩ = −2n_i T_t,i − (d−1)t_i T_t,i + m_i n_i² V + (d−1)(m_i/2) t_i² (V + W),
//   ⟨ΔE_r,i⟩ = (d−1)[−r_i T_r,i + (κ_i m_i/2) r_i² (V + W)],
// and the same with i ↔ j for the partner.
TEST(RoughMixtureCoolingState, EnergyChangesAreTheClosedForm) {
  const Rational one(1), two(2);
  const std::array<Rational, 4> t{Rational(2, 3), Rational(5, 7), Rational(3, 11), Rational(4, 5)};
  for (int d : {2, 3})
    for (const auto& restitution : {std::pair{Rational(7, 10), Rational(2, 5)}, {Rational(1, 2), Rational(-3, 5)}}) {
      const Rational alpha = restitution.first, beta = restitution.second;  // captured below (clang 14)
      const auto c = gkt::rough_pair_energy_changes(d, alpha, beta, kLight, kHeavy);
      const Rational mi = kLight.mass, mj = kHeavy.mass, ki = kLight.kappa, kj = kHeavy.kappa;
      const Rational big_m = one / ((one + ki) / (ki * mi) + (one + kj) / (kj * mj));
      const Rational v = t[0] / mi + t[1] / mj, w = t[2] / (ki * mi) + t[3] / (kj * mj), dm1(d - 1);
      const auto translational = [&](const Rational& m_a, const Rational& m_b, const Rational& t_a) {
        const Rational n = (one + alpha) * m_b / (m_a + m_b), tt = (one + beta) * big_m / m_a;
        return -two * n * t_a - dm1 * tt * t_a + m_a * n * n * v + dm1 * m_a / two * tt * tt * (v + w);
      };
      const auto rotational = [&](const Rational& m_a, const Rational& k_a, const Rational& tr_a) {
        const Rational r = (one + beta) * big_m / (m_a * k_a);
        return dm1 * (-r * tr_a + k_a * m_a / two * r * r * (v + w));
      };
      const std::array<Rational, 4> expected{translational(mi, mj, t[0]), translational(mj, mi, t[1]),
                                             rotational(mi, ki, t[2]), rotational(mj, kj, t[3])};
      for (std::size_t r = 0; r < 4; ++r) {
        Rational value(0);
        for (std::size_t k = 0; k < 4; ++k) value += c.coefficient[r][k] * t[k];
        EXPECT_EQ(value, expected[r]) << "d=" << d << " row " << r;
      }
    }
}

// Two identical components (any fractions) are one rough gas: γ_i = 1, θ_i and ζ* of the
// one-component Maxwellian HCS (Huthmann–Zippelius in 3D).
TEST(RoughMixtureCoolingState, IdenticalSpeciesAreTheOneComponentGas) {
  for (int d : {2, 3})
    for (const auto& [alpha, beta] : {std::pair{Rational(9, 10), Rational(1, 2)},
                                      {Rational(1, 2), Rational(-4, 5)},
                                      {Rational(7, 10), Rational(1)}}) {
      const Rational kappa(2, 5);
      const RoughMixtureComponent a{Rational(3), kappa, 1.5, 0.25}, b{Rational(3), kappa, 1.5, 0.75};
      const auto state = gkt::rough_mixture_cooling_state(binary(d, a, b, {alpha, alpha, alpha}, {beta, beta, beta}));
      const auto one = gkt::rough_homogeneous_cooling_state(d, alpha, beta, kappa, gkt::RoughHcsScheme::maxwellian);
      for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_NEAR(state.temperature_ratio[i], 1.0, 1e-12) << "d=" << d;
        EXPECT_NEAR(state.rotational_ratio[i], one.temperature_ratio, 1e-12 * one.temperature_ratio) << "d=" << d;
      }
      EXPECT_NEAR(state.cooling_rate, one.cooling_rate, 1e-12 * one.cooling_rate) << "d=" << d;
    }
}

// β = −1 on every pair: the translational rates are the smooth mixture's (16.4), at any temperatures, and the
// HCS's γ_i, ζ* the smooth mixture's Maxwellian HCS.
TEST(RoughMixtureCoolingState, SmoothLimitTranslationalRatesAreTheSmoothMixture) {
  for (int d : {2, 3}) {
    const Rational alpha(3, 4);
    const auto rough = binary(d, kLight, kHeavy, {alpha, alpha, alpha}, {Rational(-1), Rational(-1), Rational(-1)});
    gkt::Species s1, s2;
    s1.mass = gkt::ExactValue(kLight.mass);
    s1.diameter = kLight.diameter;
    s1.fraction = kLight.fraction;
    s2.mass = gkt::ExactValue(kHeavy.mass);
    s2.diameter = kHeavy.diameter;
    s2.fraction = kHeavy.fraction;
    const gkt::Mixture smooth = gkt::make_mixture(d, {s1, s2}, alpha.to_double());
    const std::array<double, 4> temps{0.8, 0.9, 0.5, 2.0};
    const double t = kLight.fraction * temps[0] + kHeavy.fraction * temps[1];
    const std::vector<double> gamma{temps[0] / t, temps[1] / t}, chi(4, 1.0);
    std::vector<double> rates(2);
    gkt::species_cooling_rates(smooth, gamma, chi, rates);
    const auto r = gkt::rough_mixture_cooling_rates(rough, temps);
    EXPECT_NEAR(r[0], rates[0], 1e-12) << "d=" << d;
    EXPECT_NEAR(r[1], rates[1], 1e-12) << "d=" << d;
    EXPECT_EQ(r[2], 0.0);
    EXPECT_EQ(r[3], 0.0);
    // The HCS: both spins decoupled (θ_i = +∞), γ_i and ζ* the smooth mixture's Maxwellian HCS (theory.md (19.130)).
    const auto hcs = gkt::rough_mixture_cooling_state(rough);
    const auto smooth_hcs = gkt::mixture_cooling_state(smooth, gkt::MixtureHcsScheme::maxwellian);
    EXPECT_TRUE(std::isinf(hcs.rotational_ratio[0]) && std::isinf(hcs.rotational_ratio[1]));
    EXPECT_NEAR(hcs.temperature_ratio[0], smooth_hcs.temperature_ratio[0], 1e-10) << "d=" << d;
    EXPECT_NEAR(hcs.temperature_ratio[1], smooth_hcs.temperature_ratio[1], 1e-10) << "d=" << d;
    EXPECT_NEAR(hcs.cooling_rate, smooth_hcs.cooling_rate, 1e-10 * smooth_hcs.cooling_rate) << "d=" << d;
  }
}

// Elastic, perfectly rough: equipartition among the four temperatures and ζ* = 0.
TEST(RoughMixtureCoolingState, ElasticPerfectlyRoughIsEquipartition) {
  for (int d : {2, 3}) {
    const Rational one(1);
    const auto state = gkt::rough_mixture_cooling_state(binary(d, kLight, kHeavy, {one, one, one}, {one, one, one}));
    for (std::size_t i = 0; i < 2; ++i) {
      EXPECT_NEAR(state.temperature_ratio[i], 1.0, 1e-10);
      EXPECT_NEAR(state.rotational_ratio[i], 1.0, 1e-10);
    }
    EXPECT_NEAR(state.cooling_rate, 0.0, 1e-12);
  }
}

// At the HCS the four rates coincide with ζ*; values printed for the docs.
TEST(RoughMixtureCoolingState, FourRatesAreEqualAtTheHcs) {
  for (int d : {2, 3}) {
    const auto m = binary(d, kLight, kHeavy, {Rational(9, 10), Rational(4, 5), Rational(7, 10)},
                          {Rational(1, 2), Rational(0), Rational(-1, 2)});
    const auto s = gkt::rough_mixture_cooling_state(m);
    const double t1 = s.temperature_ratio[0], t2 = s.temperature_ratio[1];
    const auto r =
        gkt::rough_mixture_cooling_rates(m, {t1, t2, s.rotational_ratio[0] * t1, s.rotational_ratio[1] * t2});
    for (double x : r) EXPECT_NEAR(x, s.cooling_rate, 1e-10 * std::abs(s.cooling_rate)) << "d=" << d;
    EXPECT_NEAR(kLight.fraction * t1 + kHeavy.fraction * t2, 1.0, 1e-14);
    EXPECT_GT(s.cooling_rate, 0);
    std::printf("rough mixture HCS d=%d: gamma = %.6f %.6f, theta = %.6f %.6f, zeta* = %.6f\n", d, t1, t2,
                s.rotational_ratio[0], s.rotational_ratio[1], s.cooling_rate);
  }
}

// One decoupled spin (β_11 = β_12 = −1, β_22 = 1/2; theory.md (19.130)): θ_1 = +∞ and at the state the three
// remaining rates equal ζ* whatever T_r,1 (it enters no row), while T_r,1 itself does not change.
TEST(RoughMixtureCoolingState, OneDecoupledSpinCoolsWithoutIt) {
  for (int d : {2, 3}) {
    const Rational a(9, 10), m1(-1);
    const auto m = binary(d, kLight, kHeavy, {a, a, a}, {m1, m1, Rational(1, 2)});
    const auto s = gkt::rough_mixture_cooling_state(m);
    EXPECT_TRUE(std::isinf(s.rotational_ratio[0]));
    ASSERT_TRUE(std::isfinite(s.rotational_ratio[1]));
    const double t1 = s.temperature_ratio[0], t2 = s.temperature_ratio[1];
    for (double tr1 : {0.1, 7.0}) {
      const auto r = gkt::rough_mixture_cooling_rates(m, {t1, t2, tr1, s.rotational_ratio[1] * t2});
      for (std::size_t k : {std::size_t{0}, std::size_t{1}, std::size_t{3}})
        EXPECT_NEAR(r[k], s.cooling_rate, 1e-10 * s.cooling_rate) << "d=" << d << " k=" << k;
      EXPECT_EQ(r[2], 0.0);
    }
  }
}

// Santos's "mimicry" of polydisperse disks ([santos2018disks], abstract): with common α, β, κ and
// masses m_i ∝ 2σ_i + ⟨σ⟩ a binary gas of disks has (nearly) the monodisperse θ = T_r/T_t in both
// components. Here σ2/σ1 = 2, x_i = 1/2: masses 7/2 and 11/2 keep θ_i within 0.2 % of the
// one-component θ, while equal-density disks (m ∝ σ²) and spheres with the same masses do not.
TEST(RoughMixtureCoolingState, PolydisperseDisksMimicTheMonodisperseGas) {
  for (const auto& restitution : {std::pair{Rational(9, 10), Rational(1, 2)}, {Rational(7, 10), Rational(0)}}) {
    const Rational alpha = restitution.first, beta = restitution.second;  // captured below (clang 14)
    const std::array<Rational, 3> a{alpha, alpha, alpha}, b{beta, beta, beta};
    const auto deviation = [&](int d, const Rational& kappa, const Rational& m1, const Rational& m2) {
      const auto mix = gkt::rough_mixture_cooling_state(binary(d, {m1, kappa, 1.0, 0.5}, {m2, kappa, 2.0, 0.5}, a, b));
      const double theta = gkt::rough_homogeneous_cooling_state(d, alpha, beta, kappa, gkt::RoughHcsScheme::maxwellian)
                               .temperature_ratio;
      return std::max(std::abs(mix.rotational_ratio[0] / theta - 1), std::abs(mix.rotational_ratio[1] / theta - 1));
    };
    const double mimic = deviation(2, Rational(1, 2), Rational(7, 2), Rational(11, 2));
    EXPECT_LT(mimic, 2e-3) << "alpha=" << alpha << " beta=" << beta;
    EXPECT_GT(deviation(2, Rational(1, 2), Rational(1), Rational(4)), 10 * mimic);
    EXPECT_GT(deviation(3, Rational(2, 5), Rational(7, 2), Rational(11, 2)), 10 * mimic);
  }
}

// A DSMC of the binary mixture (tests/rough_mixture_dsmc.hpp: the rigid-body rule, no engine; it gives the
// one-component θ = 0.852 ± 0.005 at (0.9, 0.5), as the library's DSMC, §19.6) against the Maxwellian HCS at
// unequal masses (1, 4), sizes (1, 2), κ (2/5, 1/2) and x (0.3, 0.7). The Maxwellian approximation is not
// exact (one component: θ 1.8 % above the DSMC at (0.9, 0.5)), so γ_i within 0.01, θ_i within 4 % and the
// ratio θ_2/θ_1 within 3 %; in the first state the DSMC must tell the two components' θ apart (> 10 %).
TEST(RoughMixtureCoolingState, AgainstDsmc) {
  const std::array<gkt::test::McRoughSpecies, 2> species{gkt::test::McRoughSpecies{1.0, 1.0, 0.4, 1.0, 1.0},
                                                         gkt::test::McRoughSpecies{4.0, 2.0, 0.5, 1.0, 1.0}};
  const Rational a(9, 10), half(1, 2), one(1);
  for (const Rational& beta : {half, one}) {
    const auto state = gkt::rough_mixture_cooling_state(binary(3, kLight, kHeavy, {a, a, a}, {beta, beta, beta}));
    const double b = beta.to_double();
    const auto dsmc =
        gkt::test::run_rough_mixture_dsmc(species, {600, 1400}, {0.9, 0.9, 0.9}, {b, b, b}, 40, 40, 2, 20261202);
    const std::array<double, 4> maxwellian{state.temperature_ratio[0], state.temperature_ratio[1],
                                           state.rotational_ratio[0], state.rotational_ratio[1]};
    for (std::size_t k = 0; k < 4; ++k)
      std::printf("rough mixture DSMC beta=%.1f: %s = %.4f +- %.4f (Maxwellian %.4f)\n", b, k < 2 ? "gamma" : "theta",
                  dsmc.mean[k], dsmc.error[k], maxwellian[k]);
    for (std::size_t k = 0; k < 2; ++k) EXPECT_NEAR(dsmc.mean[k], maxwellian[k], 0.01) << "gamma " << k;
    for (std::size_t k = 2; k < 4; ++k) EXPECT_NEAR(dsmc.mean[k] / maxwellian[k], 1.0, 0.04) << "theta " << k;
    EXPECT_NEAR((dsmc.mean[3] / dsmc.mean[2]) / (maxwellian[3] / maxwellian[2]), 1.0, 0.03);
    if (beta == half) {
      EXPECT_GT(dsmc.mean[3] / dsmc.mean[2], 1.1);
    }
  }
}

TEST(RoughMixtureCoolingState, RejectsBadInput) {
  auto m = binary(3, kLight, kHeavy, {Rational(1), Rational(1), Rational(1)}, {Rational(0), Rational(0), Rational(0)});
  m.species[1].fraction = 0.5;
  EXPECT_THROW(gkt::rough_mixture_cooling_state(m), std::invalid_argument);
  m.species[1].fraction = 0.7;
  m.beta[1] = Rational(2);
  EXPECT_THROW(gkt::rough_mixture_cooling_state(m), std::invalid_argument);
  m.beta[1] = Rational(0);
  m.species[0].kappa = Rational(3, 2);
  EXPECT_THROW(gkt::rough_mixture_cooling_state(m), std::invalid_argument);
  m.species[0].kappa = Rational(2, 5);
  EXPECT_THROW(gkt::rough_mixture_cooling_rates(m, {1, 1, 0, 1}), std::invalid_argument);
}
