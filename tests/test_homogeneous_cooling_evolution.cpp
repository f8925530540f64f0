// Time evolution of the homogeneous cooling gas (CVODE): long-time fixed point, Haff's law,
// logarithmic growth of collisions, the elastic limit, and convergence as rtol decreases.
#include <gtest/gtest.h>

#include <cmath>

#include "gkt/evolution/homogeneous_cooling_evolution.hpp"

using gkt::HcsScheme;
using gkt::Rational;

namespace {
std::vector<double> log_times(double from, double to, int n) {
  std::vector<double> t;
  for (int i = 0; i < n; ++i) t.push_back(from * std::pow(to / from, static_cast<double>(i) / (n - 1)));
  return t;
}
}  // namespace

// From a Maxwellian the cumulants relax to the stationary HCS values of the Newton solver
// (theory.md (9.3)), to the integration tolerance.
TEST(HcsEvolution, RelaxesToTheHcsFixedPoint) {
  for (int d : {2, 3}) {
    gkt::HomogeneousCoolingState h(d);
    for (const Rational& alpha : {Rational(9, 10), Rational(4, 5), Rational(3, 5)}) {
      const int k_max = 6;
      const auto fixed = h.solve(alpha, k_max, HcsScheme::nonlinear);
      ASSERT_TRUE(fixed.solved);
      const auto r = gkt::evolve_homogeneous_cooling(h.hierarchy(alpha, k_max), 1.0, {0.0}, {1e4}, 1e-10, 1e-14);
      const auto& last = r.samples.back();
      for (int k = 2; k <= k_max; ++k)
        EXPECT_NEAR(last.a[k], fixed.a[k], 1e-8) << "d=" << d << " alpha=" << alpha << " k=" << k;
      EXPECT_NEAR(last.cooling_rate, fixed.cooling_rate, 1e-9);
    }
  }
}

// Haff's law (PHYSICS.md: T = T0/(1 + t/t0)², 1/t0 = ζ(0)/2; in τ = ω_M(0) t, ζ/ω_M = (4/(d+2))ζ*):
// once the cumulants are stationary, T(τ)(1 + (2/(d+2)) ζ* τ)² → 1, and the collisions per
// particle grow logarithmically, C = (⟨1⟩/b) ln(1 + bτ) + const with b = (2/(d+2)) ζ*.
TEST(HcsEvolution, HaffsLawAndLogarithmicCollisions) {
  for (int d : {2, 3}) {
    gkt::HomogeneousCoolingState h(d);
    const Rational alpha(4, 5);
    const auto hierarchy = h.hierarchy(alpha, 5);
    const auto fixed = h.solve(alpha, 5, HcsScheme::nonlinear);
    // Start in the HCS: Haff exactly from τ = 0.
    std::vector<double> a0(fixed.a.begin() + 2, fixed.a.end());
    const auto times = log_times(1e-2, 1e5, 15);
    const auto r = gkt::evolve_homogeneous_cooling(hierarchy, 1.0, a0, times, 1e-10, 1e-16);
    const double b = 2.0 / (d + 2) * fixed.cooling_rate, rate = hierarchy.collision_rate(fixed.a);
    for (const auto& s : r.samples) {
      EXPECT_NEAR(s.temperature * std::pow(1 + b * s.time, 2), 1.0, 1e-7) << "d=" << d << " tau=" << s.time;
      EXPECT_NEAR(s.collisions, rate / b * std::log1p(b * s.time), 1e-7 * (1 + s.collisions)) << s.time;
    }
    // From a Maxwellian the deficit to Haff's law is a transient (measured maximum at α = 0.8:
    // 5e-4 in 3D, 1.2e-3 in 2D, where |a2| is larger) that has decayed below 1e-5 at τ = 1e5.
    const auto m = gkt::evolve_homogeneous_cooling(hierarchy, 1.0, {0.0}, times, 1e-10, 1e-16);
    for (const auto& s : m.samples) EXPECT_NEAR(s.temperature * std::pow(1 + b * s.time, 2), 1.0, 2e-3);
    EXPECT_NEAR(m.samples.back().temperature * std::pow(1 + b * m.samples.back().time, 2), 1.0, 1e-5);
  }
}

// α = 1: the Maxwellian is stationary and the temperature constant; an initial a2 relaxes to 0
// (elastic H-theorem) while T stays T0 and one collision per particle takes τ = 1.
TEST(HcsEvolution, ElasticLimit) {
  gkt::HomogeneousCoolingState h(3);
  const auto r = gkt::evolve_homogeneous_cooling(h.hierarchy(Rational(1), 4), 2.5, {0.1}, {1.0, 100.0}, 1e-10, 1e-14);
  EXPECT_NEAR(r.samples.back().temperature, 2.5, 1e-9);
  EXPECT_NEAR(r.samples.back().a[2], 0.0, 1e-8);
  const auto maxwell = gkt::evolve_homogeneous_cooling(h.hierarchy(Rational(1), 4), 1.0, {0.0}, {1.0}, 1e-10, 1e-14);
  EXPECT_NEAR(maxwell.samples.front().collisions, 1.0, 1e-9);
  EXPECT_EQ(maxwell.samples.front().a[2], 0.0);
}

// The solution converges as rtol decreases: differences shrink with the tolerance.
TEST(HcsEvolution, ConvergesAsToleranceDecreases) {
  gkt::HomogeneousCoolingState h(3);
  const auto hierarchy = h.hierarchy(Rational(1, 2), 5);
  const auto times = log_times(0.1, 1e3, 9);
  const auto ref = gkt::evolve_homogeneous_cooling(hierarchy, 1.0, {0.0}, times, 1e-12, 1e-18);
  double previous = 1;
  for (double rtol : {1e-4, 1e-6, 1e-8, 1e-10}) {
    const auto r = gkt::evolve_homogeneous_cooling(hierarchy, 1.0, {0.0}, times, rtol, rtol * 1e-6);
    double worst = 0;
    for (std::size_t i = 0; i < times.size(); ++i) {
      worst = std::max(worst, std::abs(r.samples[i].temperature / ref.samples[i].temperature - 1));
      worst = std::max(worst, std::abs(r.samples[i].a[2] - ref.samples[i].a[2]));
    }
    EXPECT_LT(worst, 100 * rtol) << rtol;
    EXPECT_LT(worst, previous) << rtol;
    previous = worst;
  }
}

TEST(HcsEvolution, RejectsBadInput) {
  gkt::HomogeneousCoolingState h(3);
  const auto hierarchy = h.hierarchy(Rational(4, 5), 3);
  EXPECT_THROW((void)gkt::evolve_homogeneous_cooling(hierarchy, -1.0, {}, {1.0}, 1e-8, 1e-12), std::invalid_argument);
  EXPECT_THROW((void)gkt::evolve_homogeneous_cooling(hierarchy, 1.0, {}, {2.0, 1.0}, 1e-8, 1e-12),
               std::invalid_argument);
  EXPECT_THROW((void)gkt::evolve_homogeneous_cooling(hierarchy, 1.0, {}, {1.0}, 0.0, 1e-12), std::invalid_argument);
}

// The dense (Enskog) gas: its homogeneous collision operator is χ times Boltzmann's, so the dense
// trajectory at τ is the dilute one at χτ (theory.md §12.4): T, a_k and the collisions per particle
// agree to the integration tolerance (two CVODE runs with different step sequences), ζ* is χ times
// the dilute one. χ(φ = 0.25, Carnahan–Starling) = 2.370…; χ < 1 or not finite is refused.
TEST(HcsEvolution, DenseGasIsTheDiluteOneWithTimeScaledByChi) {
  for (int d : {2, 3}) {
    gkt::HomogeneousCoolingState h(d);
    const auto hierarchy = h.hierarchy(Rational(7, 10), 4);
    const double phi = 0.25;
    const double chi = d == 3 ? (1 - phi / 2) / std::pow(1 - phi, 3) : (1 - 7 * phi / 16) / std::pow(1 - phi, 2);
    const auto times = log_times(1e-2, 1e3, 12);
    std::vector<double> scaled;
    for (const double t : times) scaled.push_back(chi * t);
    const auto dense = gkt::evolve_homogeneous_cooling(hierarchy, 1.0, {0.05}, times, 1e-11, 1e-16, chi);
    const auto dilute = gkt::evolve_homogeneous_cooling(hierarchy, 1.0, {0.05}, scaled, 1e-11, 1e-16);
    for (std::size_t i = 0; i < times.size(); ++i) {
      const auto &a = dense.samples[i], &b = dilute.samples[i];
      EXPECT_DOUBLE_EQ(a.time, times[i]);
      EXPECT_NEAR(a.temperature / b.temperature, 1, 1e-8) << d << " " << times[i];
      EXPECT_NEAR(a.collisions / b.collisions, 1, 1e-8) << d << " " << times[i];
      for (int k = 2; k <= 4; ++k) EXPECT_NEAR(a.a[k], b.a[k], 1e-9) << d << " " << k;
      EXPECT_NEAR(a.cooling_rate / (chi * b.cooling_rate), 1, 1e-8) << d << " " << times[i];
    }
    // The dense gas cools faster at the same τ.
    EXPECT_LT(dense.samples.back().temperature, 0.5 * dilute.samples.front().temperature);
  }
  gkt::HomogeneousCoolingState h(3);
  const auto hierarchy = h.hierarchy(Rational(4, 5), 3);
  for (const double chi : {0.5, std::nan(""), static_cast<double>(INFINITY)})
    EXPECT_THROW((void)gkt::evolve_homogeneous_cooling(hierarchy, 1.0, {}, {1.0}, 1e-8, 1e-12, chi),
                 std::invalid_argument);
}
