// Granular mixtures, homogeneous cooling state (Maxwellian approximation, theory.md §16): the
// pair energy loss against the engine's exact collision moments, the one-component limit to
// round-off, equipartition at α = 1, the tracer limit against an independent 1D root, extreme
// mass and diameter ratios, three species, and the one-line input errors.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "dsmc_mixture.hpp"
#include "gkt/collision/collision_moments.hpp"
#include "gkt/transport/common/pair_correlation.hpp"
#include "gkt/transport/mixture/mixture.hpp"
#include "gkt/transport/mixture/mixture_cooling_state.hpp"
#include "gkt/transport/mixture/tracer_diffusion.hpp"
#include "gkt/transport/monodisperse/hard_spheres.hpp"
#include "gkt/transport/monodisperse/homogeneous_cooling_state.hpp"

using gkt::Rational;

namespace {

gkt::Mixture binary(int d, double m2, double s2, double x1, double alpha, double phi = 0) {
  return gkt::make_mixture(d, {{1.0, 1.0, x1, "1"}, {m2, s2, 1 - x1, "2"}}, alpha, phi);
}

}  // namespace

// ⟨X1' − X1⟩/J0 over two Maxwellians at different temperatures: the closed form of (16.3)
// against the engine's exact moments E(0,0,1) − E(1,0,0) for unequal masses, widths and α.
TEST(Mixture, PairEnergyChangeEqualsEngine) {
  for (int d : {2, 3})
    for (const auto& [mi, mj, ti, tj] :
         std::vector<std::array<Rational, 4>>{{Rational(1), Rational(3), Rational(1), Rational(2, 5)},
                                              {Rational(7), Rational(2), Rational(5, 3), Rational(1, 4)},
                                              {Rational(1), Rational(1000), Rational(1), Rational(1000)}})
      for (const Rational& alpha : {Rational(1), Rational(7, 10), Rational(1, 5)}) {
        const gkt::CollisionPair pair{d, mi, mj, ti, tj};
        const auto e = gkt::scalar_collision_moments<Rational>(pair, alpha, 1);
        const double engine = (e(0, 0, 1) - e(1, 0, 0)).to_double();
        const double mu_ji = (mj / (mi + mj)).to_double();
        EXPECT_NEAR(gkt::pair_energy_change(mu_ji, alpha.to_double(), (ti / tj).to_double()), engine,
                    1e-14 * std::max(1.0, std::abs(engine)))
            << d << " " << mi << " " << mj << " " << alpha;
      }
}

// K_d of (θ_iθ_j)^{d/2} J0 = K_d √(1/θ_i + 1/θ_j), the step from (16.2) to (16.4).
TEST(Mixture, CollisionIntegralConstant) {
  for (int d : {2, 3}) {
    const gkt::CollisionPair pair{d, Rational(3), Rational(5), Rational(2), Rational(7)};
    const double ti = 2, tj = 7;
    const double k_d = std::pow(M_PI, (3 * d - 1) / 2.0) / std::tgamma(d / 2.0);
    EXPECT_NEAR(gkt::reference_collision_integral(pair) * std::pow(ti * tj, d / 2.0) / std::sqrt(1 / ti + 1 / tj), k_d,
                1e-12 * k_d);
  }
}

// Identical species: equipartition and ζ* = χ (d+2)(1−α²)/(4d), the one-component Maxwellian
// value of the smooth-inelastic model (first_sonine_hcs at a2 = 0), to round-off; χ_ij reduces to
// Carnahan–Starling (3D) / Henderson (2D).
TEST(Mixture, IdenticalSpeciesGiveOneComponentGas) {
  for (int d : {2, 3})
    for (const double alpha : {1.0, 0.8, 0.3})
      for (const double phi : {0.0, 0.2, 0.45}) {
        const auto state = gkt::mixture_cooling_state(binary(d, 1.0, 1.0, 0.3, alpha, phi));
        ASSERT_TRUE(state.solved);
        const Rational phi_q = Rational::from_double(phi);
        const double chi = gkt::pair_correlation("carnahan-starling").contact_value(d, phi_q).to_double();
        for (const double x : state.chi) EXPECT_NEAR(x, chi, 1e-14 * chi);
        const double zeta =
            chi * gkt::first_sonine_hcs(d).cooling_rate_0.evaluate(Rational::from_double(alpha)).to_double();
        EXPECT_NEAR(state.cooling_rate, zeta, 1e-14) << d << " " << alpha << " " << phi;
        for (const double g : state.temperature_ratio) EXPECT_NEAR(g, 1.0, 1e-14);
      }
}

// First Sonine, linear in a2,i: identical species give the one-component linear scheme — van
// Noije–Ernst's a2 and ζ* = χ ζ*(a2) — to round-off, though the mixture equations (16.7) are the
// X² moments of two coupled species and the one-component ones the S_2 projection of one.
TEST(Mixture, IdenticalSpeciesGiveVanNoijeErnst) {
  for (int d : {2, 3}) {
    const auto hcs = gkt::first_sonine_hcs(d);
    for (const double alpha : {0.9, 0.5, 0.2})
      for (const double phi : {0.0, 0.3}) {
        const auto state =
            gkt::mixture_cooling_state(binary(d, 1.0, 1.0, 0.3, alpha, phi), gkt::MixtureHcsScheme::linear);
        ASSERT_TRUE(state.solved) << d << " " << alpha;
        const Rational a = Rational::from_double(alpha);
        const double chi = state.chi[0];
        for (std::size_t i = 0; i < 2; ++i) {
          EXPECT_NEAR(state.a2[i], hcs.a2.evaluate(a).to_double(), 1e-13) << d << " " << alpha;
          EXPECT_NEAR(state.temperature_ratio[i], 1.0, 1e-13);
        }
        EXPECT_NEAR(state.cooling_rate, chi * hcs.cooling_rate.evaluate(a).to_double(), 1e-13) << d << " " << alpha;
      }
  }
}

// Nonlinear first Sonine (products a2,i a2,j kept): identical species give the one-component HCS
// solver's nonlinear K = 2 a2 and ζ* (Newton on the S_2 projection, §9.2) to 1e-12; linear and
// nonlinear differ at O(a2²) (binary m2/m1 = 3, σ2/σ1 = 1.5, α = 0.3: 2e-3 … 1e-2 against a2 ≈ 0.12–0.19).
TEST(Mixture, NonlinearSchemeMatchesOneComponentNonlinear) {
  for (int d : {2, 3}) {
    gkt::HomogeneousCoolingState one(d);
    for (const double alpha : {0.9, 0.5, 0.2})
      for (int k = 2; k <= 4; ++k) {  // (16.7a) with the products: the X^p balances of two species
        if (k > 2 && alpha == 0.9) continue;
        const auto state =
            gkt::mixture_cooling_state(binary(d, 1.0, 1.0, 0.4, alpha, 0.2), gkt::MixtureHcsScheme::nonlinear, k);
        ASSERT_TRUE(state.solved) << d << " " << alpha << " " << k;
        const auto reference = one.solve(Rational::from_double(alpha), k, gkt::HcsScheme::nonlinear);
        for (std::size_t i = 0; i < 2; ++i)
          for (int q = 2; q <= k; ++q)
            EXPECT_NEAR(state.cumulants[i][static_cast<std::size_t>(q)], reference.a[static_cast<std::size_t>(q)],
                        1e-12)
                << d << " " << alpha << " " << k;
        EXPECT_NEAR(state.cooling_rate, state.chi[0] * reference.cooling_rate, 1e-12) << d << " " << alpha;
      }
    const auto mix = binary(d, 3.0, 1.5, 0.5, 0.3, 0.0);
    const auto lin = gkt::mixture_cooling_state(mix, gkt::MixtureHcsScheme::linear);
    const auto non = gkt::mixture_cooling_state(mix, gkt::MixtureHcsScheme::nonlinear);
    ASSERT_TRUE(lin.solved && non.solved);
    for (std::size_t i = 0; i < 2; ++i) {
      EXPECT_NEAR(non.a2[i], lin.a2[i], 2 * lin.a2[i] * lin.a2[i] + 1e-3) << d;
      EXPECT_NE(non.a2[i], lin.a2[i]);
    }
  }
}

// α = 1: equipartition holds exactly whatever the masses, sizes and density (no cooling).
TEST(Mixture, ElasticMixtureIsInEquipartition) {
  for (int d : {2, 3}) {
    const auto state = gkt::mixture_cooling_state(binary(d, 7.0, 2.5, 0.4, 1.0, 0.2));
    ASSERT_TRUE(state.solved);
    EXPECT_NEAR(state.cooling_rate, 0.0, 1e-15);
    for (const double g : state.temperature_ratio) EXPECT_NEAR(g, 1.0, 1e-14);
  }
}

// Tracer limit x_1 → 0: γ_1 is continuous, and equals the root of ζ_1(γ_1) = ζ_2 with the host
// gas at its own HCS (γ_2 = 1), found here by bisection — an independent route.
TEST(Mixture, TracerLimitIsContinuous) {
  for (int d : {2, 3}) {
    const double m2 = 0.2, s2 = 0.6, alpha = 0.7, phi = 0.25;
    const auto near = gkt::mixture_cooling_state(binary(d, m2, s2, 1e-9, alpha, phi));
    const auto small = gkt::mixture_cooling_state(binary(d, m2, s2, 1e-5, alpha, phi));
    ASSERT_TRUE(near.solved && small.solved);
    EXPECT_NEAR(near.temperature_ratio[0], small.temperature_ratio[0], 1e-3 * near.temperature_ratio[0]);
    EXPECT_NEAR(near.temperature_ratio[1], 1.0, 1e-8);
    // x_1 = 0 is accepted: the tracer itself.
    const gkt::Mixture tracer = binary(d, m2, s2, 0.0, alpha, phi);
    const auto exact = gkt::mixture_cooling_state(tracer);
    ASSERT_TRUE(exact.solved);
    EXPECT_NEAR(exact.temperature_ratio[0], near.temperature_ratio[0], 1e-7);
    EXPECT_EQ(exact.temperature_ratio[1], 1.0);
    // Bisection on ln γ_1 with x_1 = 0 in the rates (a tracer does not change the host).
    const auto chi = tracer.contact_values();
    auto f = [&](double ln_gamma) {
      const double gamma[] = {std::exp(ln_gamma), 1.0};
      double rates[2];
      gkt::species_cooling_rates(tracer, gamma, chi, rates);
      return rates[0] - rates[1];
    };
    double lo = -5, hi = 5;
    ASSERT_LT(f(lo) * f(hi), 0.0);
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (f(lo) * f(mid) <= 0 ? hi : lo) = mid;
    }
    EXPECT_NEAR(near.temperature_ratio[0], std::exp(0.5 * (lo + hi)), 1e-7) << d;
  }
}

// Mass ratios 10⁻³ … 10³ and diameter ratios 0.1 … 10, strong dissipation and high density: the
// solve converges, γ_i stay positive and finite with Σ x_i γ_i = 1; heavier grains are hotter
// (breakdown of equipartition, equal α).
TEST(Mixture, ExtremeRatiosConverge) {
  for (int d : {2, 3})
    for (const double m2 : {1e-3, 0.1, 10.0, 1e3})
      for (const double s2 : {0.1, 1.0, 10.0})
        for (const double alpha : {0.9, 0.5, 0.1}) {
          const double phi = d == 3 ? 0.4 : 0.6;
          const auto state = gkt::mixture_cooling_state(binary(d, m2, s2, 0.5, alpha, phi));
          EXPECT_TRUE(state.solved) << d << " " << m2 << " " << s2 << " " << alpha;
          const double g1 = state.temperature_ratio[0], g2 = state.temperature_ratio[1];
          EXPECT_TRUE(std::isfinite(g1) && std::isfinite(g2) && g1 > 0 && g2 > 0);
          EXPECT_NEAR(0.5 * g1 + 0.5 * g2, 1.0, 1e-13);
          if (s2 == 1.0) {
            EXPECT_EQ(g2 > g1, m2 > 1) << d << " " << m2 << " " << alpha;
          }
        }
}

// Relabelling the species and changing the units of mass and length change nothing: (1, 1) +
// (0.5, 10) is (1, 1) + (2, 0.1) with masses ×2, diameters ×0.1 and the species swapped. Both
// schemes, first-Sonine iteration included (it sees different rational widths in the engine).
TEST(Mixture, InvariantUnderRelabellingAndUnits) {
  for (const auto scheme : {gkt::MixtureHcsScheme::maxwellian, gkt::MixtureHcsScheme::linear}) {
    const auto a = gkt::mixture_cooling_state(binary(3, 0.5, 10.0, 0.3, 0.5, 0.3), scheme);
    const auto b =
        gkt::mixture_cooling_state(gkt::make_mixture(3, {{1.0, 1.0, 0.7, ""}, {2.0, 0.1, 0.3, ""}}, 0.5, 0.3), scheme);
    ASSERT_TRUE(a.solved && b.solved);
    EXPECT_NEAR(a.temperature_ratio[0], b.temperature_ratio[1], 1e-11);
    EXPECT_NEAR(a.temperature_ratio[1], b.temperature_ratio[0], 1e-11);
    EXPECT_NEAR(a.a2[0], b.a2[1], 1e-11);
    EXPECT_NEAR(a.a2[1], b.a2[0], 1e-11);
    EXPECT_NEAR(a.cooling_rate, b.cooling_rate, 1e-11);
  }
}

// First Sonine at extreme ratios (α = 0.5, φ = 0.3): converges, and the a2,i correction moves the
// temperature ratios by at most 10 % of the Maxwellian values (measured ≤ 7.8 %).
TEST(Mixture, FirstSonineExtremeRatios) {
  for (int d : {2, 3})
    for (const double m2 : {1e-3, 1e3})
      for (const double s2 : {0.1, 10.0}) {
        const auto mix = binary(d, m2, s2, 0.5, 0.5, 0.3);
        const auto m = gkt::mixture_cooling_state(mix);
        const auto l = gkt::mixture_cooling_state(mix, gkt::MixtureHcsScheme::linear);
        ASSERT_TRUE(m.solved && l.solved) << d << " " << m2 << " " << s2;
        for (std::size_t i = 0; i < 2; ++i) {
          EXPECT_NEAR(l.temperature_ratio[i], m.temperature_ratio[i], 0.1 * m.temperature_ratio[i]) << d << " " << m2;
          EXPECT_TRUE(std::abs(l.a2[i]) < 1) << d << " " << m2 << " " << s2 << " a2 = " << l.a2[i];
        }
      }
}

// Three species: equal cooling rates and the normalisation; merging two identical species of a
// ternary gives the binary result.
TEST(Mixture, ThreeSpeciesReduceToBinary) {
  for (int d : {2, 3}) {
    for (const auto scheme : {gkt::MixtureHcsScheme::maxwellian, gkt::MixtureHcsScheme::linear}) {
      const auto two = gkt::mixture_cooling_state(binary(d, 4.0, 1.5, 0.4, 0.75, 0.2), scheme);
      const auto three = gkt::mixture_cooling_state(
          gkt::make_mixture(d, {{1.0, 1.0, 0.25, ""}, {4.0, 1.5, 0.6, ""}, {1.0, 1.0, 0.15, ""}}, 0.75, 0.2), scheme);
      ASSERT_TRUE(two.solved && three.solved);
      EXPECT_NEAR(three.temperature_ratio[0], two.temperature_ratio[0], 1e-11);
      EXPECT_NEAR(three.temperature_ratio[2], two.temperature_ratio[0], 1e-11);
      EXPECT_NEAR(three.temperature_ratio[1], two.temperature_ratio[1], 1e-11);
      EXPECT_NEAR(three.a2[0], two.a2[0], 1e-11);
      EXPECT_NEAR(three.a2[2], two.a2[0], 1e-11);
      EXPECT_NEAR(three.a2[1], two.a2[1], 1e-11);
      EXPECT_NEAR(three.cooling_rate, two.cooling_rate, 1e-11);
    }
  }
}

TEST(Mixture, BadInputNamesTheField) {
  auto message = [](const gkt::Mixture& m) {
    try {
      m.validate();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(message(binary(3, 1, 1, 0.5, 0.9)), "");
  EXPECT_NE(message(binary(3, -1, 1, 0.5, 0.9)).find("mass_2: must be a number > 0"), std::string::npos);
  EXPECT_NE(message(binary(3, 1, 0, 0.5, 0.9)).find("diameter_2: must be a number > 0"), std::string::npos);
  EXPECT_NE(message(binary(3, 1, 1, 0.5, 1.2)).find("alpha_1_1: must be a number in (0, 1]"), std::string::npos);
  EXPECT_NE(message(binary(3, 1, 1, 0.5, 0.9, 0.5)).find("packing_fraction: must be a number in [0, 0.5)"),
            std::string::npos);
  auto m = binary(3, 1, 1, 0.5, 0.9);
  m.species[0].fraction = 0.4;
  EXPECT_NE(message(m).find("fraction: the species fractions must sum to 1"), std::string::npos);
  m = binary(3, 1, 1, 0.5, 0.9);
  m.alpha[1] = 0.8;
  EXPECT_NE(message(m).find("alpha_1_2: the restitution matrix must be symmetric"), std::string::npos);
}

// Tracer diffusion (theory.md §16.5). A tracer identical to an elastic host is a tagged host
// particle: its D* equals the hard-sphere self-diffusion of the one-component solver (exact
// rationals, OperatorPart::tracer) at every order, through a different route (the pair's masses
// and widths as doubles, the Galerkin pieces of the Navier–Stokes modes).
TEST(TracerDiffusion, ElasticTaggedParticleIsSelfDiffusion) {
  for (int d : {2, 3}) {
    const gkt::TracerDiffusion tracer({d, 1.0, 1.0, 1.0, 1.0}, 8);
    gkt::HardSphereSonineSystem hs(d);
    for (int n = 1; n <= 8; ++n)
      EXPECT_NEAR(tracer.coefficient(n),
                  hs.reduced_coefficient(gkt::HardSphereCoefficient::self_diffusion, n).to_double(), 1e-13)
          << d << " " << n;
  }
}

// Identical inelastic tracer, first Sonine: D* = 1/(ν_D − d ζ*/(d+2)) with ν_D = (1+α)/2 (the
// momentum-transfer rate) and ζ* = (d+2)(1−α²)/(4d): D* = 4/(1+α)², continuous to α = 1.
TEST(TracerDiffusion, InelasticTaggedParticleFirstSonine) {
  for (int d : {2, 3})
    for (const double alpha : {1.0, 0.9, 0.5, 0.2}) {
      const gkt::TracerDiffusion tracer({d, 1.0, 1.0, alpha, alpha}, 1);
      EXPECT_NEAR(tracer.coefficient(1), 4 / ((1 + alpha) * (1 + alpha)), 1e-13) << d << " " << alpha;
    }
}

// Unequal tracers converge in Sonine order where the tracer is not much lighter than the host
// (at m0/m = 0.1 the Lorentz-gas limit converges slowly): the estimate at order 4 is below 1e-3
// and the orders 4…8 stay within it. A heavy tracer at strong dissipation (m0/m = 100, α = 0.8)
// has T0/T ≈ 5·10³ and no positive D* beyond first order: flagged, not printed as a value.
TEST(TracerDiffusion, ConvergesOrFlags) {
  for (int d : {2, 3}) {
    for (const double mass : {0.5, 2.0, 10.0}) {
      const gkt::TracerDiffusion t({d, mass, 1.5, 0.8, 0.9}, 10);
      const auto e = t.estimate(4);
      EXPECT_TRUE(e.converging) << d << " " << mass;
      EXPECT_LT(e.error.to_double(), 1e-3 * e.value.to_double()) << d << " " << mass;
      for (int n = 5; n <= 8; ++n)
        EXPECT_NEAR(t.coefficient(n), e.value.to_double(), 2 * e.error.to_double() + 1e-12) << d << " " << mass;
    }
    const gkt::TracerDiffusion heavy({d, 100.0, 1.0, 0.8, 0.8}, 4);
    EXPECT_GT(heavy.temperature_ratio(), 1e3);
    EXPECT_LT(heavy.coefficient(2), 0.0);
  }
}

// Elastic tracer, first approximation: Chapman & Cowling (1970) §10.1 (hard spheres; 2D by the same
// route), [D12]_1 = (d Γ(d/2)/(4π^{(d−1)/2})) √(T(m0 + m)/(2 m0 m))/(n σ_0h^{d−1}), i.e.
// D0* = (σ/σ_0h)^{d−1} √((m0 + m)/(2 m0)) in units of the host's D0 — for any masses and sizes.
TEST(TracerDiffusion, ElasticFirstApproximationIsChapmanCowling) {
  for (int d : {2, 3})
    for (const double mass : {0.01, 0.3, 1.0, 7.0, 200.0})
      for (const double size : {0.2, 1.0, 3.0}) {
        const gkt::TracerDiffusion t({d, mass, size, 1.0, 1.0}, 1);
        const double sigma_0h = 0.5 * (1 + size);
        EXPECT_NEAR(t.coefficient(1), std::pow(1 / sigma_0h, d - 1) * std::sqrt((mass + 1) / (2 * mass)),
                    1e-12 * t.coefficient(1))
            << d << " " << mass << " " << size;
      }
}

// Lorentz gas (3D): a light tracer among heavy scatterers has the exact D = ⟨v⟩ λ/3, λ = 1/(nπσ_0h²),
// 32/(9π) = 1.1318 times the first approximation, and the second approximation is 13/12 of the
// first (Chapman & Cowling 1970 §10.5). The Sonine sequence at m0/m = 1e-6 (O(1e-6) from the limit)
// climbs towards 32/(9π) monotonically, slowly (the classic case): order 12 is within 0.4 %
// (measured 0.18 %) and every order is below the limit.
TEST(TracerDiffusion, LorentzLimit) {
  const gkt::TracerDiffusion t({3, 1e-6, 1.0, 1.0, 1.0}, 12);
  const double first = t.coefficient(1), limit = 32 / (9 * M_PI);
  EXPECT_NEAR(t.coefficient(2) / first, 13.0 / 12.0, 1e-5);
  double previous = 0;
  for (int n = 1; n <= 12; ++n) {
    const double ratio = t.coefficient(n) / first;
    EXPECT_GT(ratio, previous) << n;
    EXPECT_LT(ratio, limit) << n;
    previous = ratio;
  }
  EXPECT_NEAR(previous, limit, 0.004 * limit);
}

// DSMC of the binary HCS (the library's DSMC, gkt/simulation/homogeneous_dsmc.hpp: no Sonine
// expansion, no cooling-rate formula): equimolar, m2/m1 = 4, equal sizes, α = 0.8, 2·10⁴ particles,
// 100 batches of five collisions per particle (batches of one collision per particle are correlated:
// their standard error understated the run-to-run spread 2.6-fold). Within the error the
// `temperature_ratio_1_error` column reports (|first Sonine − Maxwellian|) plus 4σ, in both dimensions.
// 3D: T_1/T at K = 4 agrees within 4σ and the Maxwellian one is excluded; the first-Sonine T_1/T is
// not asserted within 4σ any more: 24 independent runs (2·10⁴ particles, 100 collisions per particle
// each) give 0.85911 ± 0.00024, 5.5σ from first Sonine (0.85779) and 2σ from K = 4 (0.85861). 2D: the
// first-Sonine value is off by more than the statistics (its truncation error, like the 2D
// one-component a2). The species cumulants: the linear scheme with a_2 … a_4 gives a2,i within 4σ of
// the DSMC in both dimensions, where the first-Sonine a2,1 of 2D is excluded.
TEST(MixtureDsmc, TemperatureRatioAgreesWithFirstSonine) {
  for (int d : {3, 2}) {
    const auto sample =
        gkt::test::run_mixture_hcs_dsmc(d, {10000, 10000}, {1, 4}, {1, 1}, {0.8, 0.8, 0.8, 0.8}, 10, 100, 5.0, 7);
    const gkt::Mixture m = binary(d, 4, 1, 0.5, 0.8);
    const double linear = gkt::mixture_cooling_state(m, gkt::MixtureHcsScheme::linear).temperature_ratio[0];
    const double maxwellian = gkt::mixture_cooling_state(m, gkt::MixtureHcsScheme::maxwellian).temperature_ratio[0];
    const double dsmc = sample.temperature_ratio[0], sigma = sample.temperature_ratio_error[0];
    std::cout << "[ DSMC ] d=" << d << " T1/T = " << dsmc << " ± " << sigma << " (first Sonine " << linear
              << ", Maxwellian " << maxwellian << "); a2,1 = " << sample.a2[0] << " ± " << sample.a2_error[0]
              << ", a2,2 = " << sample.a2[1] << " ± " << sample.a2_error[1] << "\n";
    // The cumulants: first Sonine (K = 2) against the linear scheme carrying a_2 … a_4 (16.7a).
    const auto k4 = gkt::mixture_cooling_state(m, gkt::MixtureHcsScheme::linear, 4);
    const auto k2 = gkt::mixture_cooling_state(m, gkt::MixtureHcsScheme::linear, 2);
    std::cout << "[ DSMC ]   a2,1 at K = 2: " << k2.a2[0] << ", K = 4: " << k4.a2[0] << "; a2,2: " << k2.a2[1] << ", "
              << k4.a2[1] << "; T1/T at K = 4: " << k4.temperature_ratio[0] << "\n";
    for (std::size_t i = 0; i < 2; ++i) EXPECT_NEAR(k4.a2[i], sample.a2[i], 4 * sample.a2_error[i]) << d << " " << i;
    if (d == 2) {
      EXPECT_GT(std::abs(k2.a2[0] - sample.a2[0]), 4 * sample.a2_error[0]);
    }
    EXPECT_LE(std::abs(dsmc - linear), std::abs(linear - maxwellian) + 4 * sigma) << d;
    EXPECT_LT(std::abs(dsmc - linear), std::abs(dsmc - maxwellian)) << d;
    if (d == 3) {
      EXPECT_NEAR(k4.temperature_ratio[0], dsmc, 4 * sigma);
      EXPECT_GT(std::abs(dsmc - maxwellian), 4 * sigma);
    }
  }
}
