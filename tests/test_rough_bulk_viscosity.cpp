// Bulk viscosity and first-order cooling rate of rough spheres and disks at first Sonine
// (docs/theory.md §19.9): Pidduck's perfectly rough elastic spheres ([chapman1970] §11.6), a second
// method (the two-temperature balance equations of a uniformly dilated gas, integrated in time,
// must stay on the Chapman–Enskog normal solution), the singular quasi-smooth limit; and κ*, μ*
// of disks (theory.md (19.15)–(19.16) with d = 2) against the smooth first Sonine at β = −1.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

#include "dsmc_rough.hpp"
#include "gkt/transport/rough/rough_bulk_viscosity.hpp"
#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"
#include "gkt/transport/rough/rough_thermal_conductivity.hpp"

using gkt::Rational;

TEST(RoughBulkViscosity, PidduckGas) {
  for (long k10 : {4L, 1L, 10L, 5L}) {
    const double k = k10 / 10.0;
    // [chapman1970] §11.6: ϖ = (1+κ)²/(32κσ²) √(mkT/π) in the first approximation; η0 = (5/(16σ²))√(mkT/π).
    const double published = (1 + k) * (1 + k) / (32 * k) / (5.0 / 16);
    const auto s = gkt::rough_bulk_viscosity_at(3, Rational(1), Rational(1), Rational(k10, 10), 1.0);
    EXPECT_NEAR(s.bulk_viscosity, published, 1e-13) << "kappa=" << k;
    EXPECT_NEAR(s.cooling_rate_first_order, 0, 1e-15);
    EXPECT_NEAR(gkt::rough_bulk_viscosity(3, Rational(1), Rational(1), Rational(k10, 10)).bulk_viscosity, published,
                1e-12);
    // Disks (derived, not published): 4d_r²(1+κ)²/((d+d_r)²(d+2)(d−1)κ) = (1+κ)²/(9κ).
    const auto disks = gkt::rough_bulk_viscosity(2, Rational(1), Rational(1), Rational(k10, 10));
    EXPECT_NEAR(disks.bulk_viscosity, (1 + k) * (1 + k) / (9 * k), 1e-12);
    EXPECT_NEAR(disks.cooling_rate_first_order, 0, 1e-14);
  }
}

namespace {

// The Maxwellian rates of theory.md (19.12) in units of ν = nσ^{d−1}v_t·(its (5.3) constant), written
// out here independently of the library: ζ_t/ν and ζ_r/ν at the ratio r = T_r/T_t.
struct Rates {
  int d;
  double alpha, eta, kappa;
  [[nodiscard]] double dr() const { return d == 3 ? 3.0 : 1.0; }
  [[nodiscard]] double translational(double r) const {
    return 2.0 / d * ((1 - alpha * alpha) / 2 + (d - 1) * (eta * (1 - eta) - eta * eta * r / kappa));
  }
  [[nodiscard]] double rotational(double r) const {
    return 2.0 * (d - 1) / dr() * (eta / kappa) * (1 - eta / kappa - eta / r);
  }
};

}  // namespace

// Second method: a gas dilated uniformly at the constant rate D = ∇·u obeys, in the Maxwellian
// (first-Sonine) approximation, dT_t/dt = −(2/d)D T_t − ζ_t T_t, dT_r/dt = −ζ_r T_r, dn/dt = −nD,
// ζ_{t,r} = n√T_t F_{t,r}(T_r/T_t). Started on the predicted normal solution (T_r/T_t = θe^δ,
// δ = ln-split of (19.18)), it must stay on it while the gas cools by a factor ~5 — a wrong ζ*/2
// (the ∂_t⁽⁰⁾ of 1/ν0) or Γ* would pull it off by tens of percent — and the pressure deficit and the
// cooling rate of T = (dT_t + d_rT_r)/(d + d_r) give η_b* and ζ_U.
TEST(RoughBulkViscosity, NormalSolutionOfTheDilatedGas) {
  struct Case {
    int d;
    long a10, b10;
  };
  for (const Case c : {Case{3, 9, 5}, Case{3, 7, 0}, Case{3, 5, 10}, Case{2, 8, 5}, Case{2, 6, -5}}) {
    const Rational alpha(c.a10, 10), beta(c.b10, 10), kappa = c.d == 3 ? Rational(2, 5) : Rational(1, 2);
    const double k = kappa.to_double(), eta = (1 + c.b10 / 10.0) * k / (2 * (1 + k));
    const Rates f{c.d, c.a10 / 10.0, eta, k};
    const double theta = gkt::rough_homogeneous_cooling_state(c.d, alpha, beta, kappa, gkt::RoughHcsScheme::maxwellian)
                             .temperature_ratio;
    const auto s = gkt::rough_bulk_viscosity(c.d, alpha, beta, kappa);
    const double d = c.d, dr = f.dr(), g = (d + 2) / 4, dilation = 1e-7;
    const double tau_t = (d + dr) / (d + dr * theta);  // T_t/T on the HCS
    // State y = (ln T_t, ln T_r, ln n), T_t(0) = n(0) = 1: ν0 = (4/(d+2)) n√T_t.
    const auto nu0 = [&](const std::array<double, 3>& y) { return std::exp(y[2] + y[0] / 2) / g; };
    // δ = Δ D/ν0 with Δ = η_b*(d + d_rθ)/(d_rθ) (theory.md (19.18)).
    const double big_delta = s.bulk_viscosity * (d + dr * theta) / (dr * theta);
    const auto split = [&](const std::array<double, 3>& y) { return big_delta * dilation / nu0(y); };
    const auto rhs = [&](const std::array<double, 3>& y) {
      const double nu = std::exp(y[2] + y[0] / 2), r = std::exp(y[1] - y[0]);
      return std::array<double, 3>{-2 / d * dilation - nu * f.translational(r), -nu * f.rotational(r), -dilation};
    };
    std::array<double, 3> y{0, std::log(theta), 0};
    y[1] += split(y);
    const double h = 1e-3;
    double worst_split = 0, worst_bulk = 0, worst_zeta = 0;
    for (int step = 1; step <= 20000; ++step) {
      const auto k1 = rhs(y);
      std::array<double, 3> t{};
      for (int i = 0; i < 3; ++i) t[i] = y[i] + h / 2 * k1[i];
      const auto k2 = rhs(t);
      for (int i = 0; i < 3; ++i) t[i] = y[i] + h / 2 * k2[i];
      const auto k3 = rhs(t);
      for (int i = 0; i < 3; ++i) t[i] = y[i] + h * k3[i];
      const auto k4 = rhs(t);
      for (int i = 0; i < 3; ++i) y[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
      if (step % 1000 != 0) continue;
      const double tt = std::exp(y[0]), tr = std::exp(y[1]), n = std::exp(y[2]), r = tr / tt;
      const double delta = std::log(r / theta);
      worst_split = std::max(worst_split, std::abs(delta / split(y) - 1));
      // η_b: nT_t − nτ_tT = −η_b D, reduced by η0(T_t) = nT_t/ν0.
      const double temperature = (d * tt + dr * tr) / (d + dr);
      const double bulk = -(tt - tau_t * temperature) / tt * nu0(y) / dilation;
      worst_bulk = std::max(worst_bulk, std::abs(bulk / s.bulk_viscosity - 1));
      // ζ of T minus the HCS ζ at the same T and n, per unit D.
      const double zeta =
          n * std::sqrt(tt) * (d * tt * f.translational(r) + dr * tr * f.rotational(r)) / ((d + dr) * temperature);
      const double zeta0 = n * std::sqrt(tau_t * temperature) * f.translational(theta);
      const double zeta_u = (zeta - zeta0) / dilation;
      worst_zeta = std::max(worst_zeta, std::abs(zeta_u - s.cooling_rate_first_order));
    }
    const double cooled = std::exp(y[0]);
    EXPECT_LT(cooled, 0.95) << "the gas must cool during the run";
    EXPECT_LT(worst_split, 2e-4) << c.d << " " << c.a10 << " " << c.b10;
    EXPECT_LT(worst_bulk, 2e-4) << c.d << " " << c.a10 << " " << c.b10;
    EXPECT_LT(worst_zeta, 2e-4 * (1 + std::abs(s.cooling_rate_first_order))) << c.d << " " << c.a10 << " " << c.b10;
  }
}

// β → −1⁺: θ ~ 1/η_t² and (d − 1)η_t²θ/κ → (1 − α²)/2 (theory.md §19.5), so Γ* → ((d+2)/4)(1 − α²)/d,
// ζ* → 0 and η_b* → 8/((d+2)(1 − α²)): finite, while the smooth gas (β = −1) has none — singular
// like θ, a20 and C. At β = −1 itself both columns are NaN (no rotational cooling state).
TEST(RoughBulkViscosity, QuasiSmoothLimit) {
  for (int d : {3, 2}) {
    for (long a10 : {8L, 5L}) {
      const double a = a10 / 10.0;
      const auto s = gkt::rough_bulk_viscosity(d, Rational(a10, 10), Rational(-999999, 1000000), Rational(2, 5));
      EXPECT_NEAR(s.bulk_viscosity, 8 / ((d + 2) * (1 - a * a)), 1e-3 * s.bulk_viscosity) << d << " " << a;
      EXPECT_NEAR(s.cooling_rate_first_order, 0, 1e-3);
      const auto smooth = gkt::rough_bulk_viscosity(d, Rational(a10, 10), Rational(-1), Rational(2, 5));
      EXPECT_TRUE(std::isnan(smooth.bulk_viscosity));
      EXPECT_TRUE(std::isnan(smooth.cooling_rate_first_order));
    }
  }
}

// Disks: at β = −1 the translational flux is the smooth first Sonine of d = 2,
// κ* = ((d−1)/d)/(ν_κ* − 2ζ*), μ* = 2ζ*κ*/(2ν_κ* − 3ζ*), ν_κ* = ((1+α)/d)[(d−1)/2 + (3/16)(d+8)(1−α)],
// ζ* = ((d+2)/(4d))(1−α²) ([garzo2019]; theory.md §10.3); the d = 3 overloads are dimension = 3.
TEST(RoughThermalConductivity, DisksSmoothLimitAndSpheresOverload) {
  for (long a10 : {9L, 5L, 2L}) {
    const double a = a10 / 10.0, d = 2;
    const double nu = (1 + a) / d * ((d - 1) / 2 + 3.0 / 16 * (d + 8) * (1 - a)),
                 zeta = (d + 2) / (4 * d) * (1 - a * a);
    const auto c = gkt::rough_thermal_conductivity(2, Rational(a10, 10), Rational(-1), Rational(1, 2));
    const double kappa_star = (d - 1) / d / (nu - 2 * zeta);
    EXPECT_NEAR(c.translational, kappa_star, 1e-12) << a;
    EXPECT_NEAR(c.density_heat_translational, 2 * zeta * kappa_star / (2 * nu - 3 * zeta), 1e-12) << a;
    EXPECT_TRUE(std::isnan(c.total));
    const auto three = gkt::rough_thermal_conductivity(3, Rational(a10, 10), Rational(1, 2), Rational(2, 5));
    EXPECT_EQ(three.total, gkt::rough_thermal_conductivity(Rational(a10, 10), Rational(1, 2), Rational(2, 5)).total);
  }
  // Elastic perfectly rough disks: no cooling, no μ; the spin carries heat (total above translational).
  const auto pidduck = gkt::rough_thermal_conductivity_at(2, Rational(1), Rational(1), Rational(1, 2), 1.0);
  EXPECT_NEAR(pidduck.density_heat_total, 0, 1e-14);
  EXPECT_GT(pidduck.total, pidduck.translational);
}

// DSMC of a uniformly dilated gas (tests/dsmc_rough.hpp with ∇·u = ±ε ν0(T_t), ε = 0.05, 3D, κ = 2/5):
// with the dilatation slaved to ν0 the ratio settles where Γ* δ = (2/d) ε, δ = ln(θ_ε/θ_0), so the DSMC
// measures the relaxation rate Γ* of (19.17) — the kinetic input of η_b and ζ_U — including everything the
// Maxwellian approximation leaves out. Central difference ±ε removes the O(ε²) term; the same seed for
// ±ε (correlated runs) and batches of 5 collisions per particle (longer than the relaxation time 1/Γ*).
TEST(RoughBulkViscosity, RelaxationRateAgainstDsmc) {
  struct Case {
    long a10, b10;
  };
  for (const Case c : {Case{9, 5}, Case{7, 10}, Case{7, 0}, Case{5, 5}}) {
    const double alpha = c.a10 / 10.0, beta = c.b10 / 10.0, kappa = 0.4, eps = 0.05;
    const double inf = std::numeric_limits<double>::infinity();
    const auto run = [&](double e) {
      return gkt::test::run_rough_hcs_dsmc(3, alpha, beta, kappa, 1.0, 4000, 20, 60, 5, 5, inf, e);
    };
    const auto plus = run(eps), minus = run(-eps), zero = run(0);
    const double delta = (std::log(plus.theta) - std::log(minus.theta)) / 2;
    const double delta_error = 0.5 * std::hypot(plus.theta_error / plus.theta, minus.theta_error / minus.theta);
    const double measured = 2.0 / 3 * eps / delta, measured_error = measured * delta_error / delta;
    // (19.17) at the DSMC's own θ, and the library's at the Maxwellian θ.
    const double eta = (1 + beta) * kappa / (2 * (1 + kappa)), theta = zero.theta;
    const double maxwellian = 1.25 * 4 * eta * eta / kappa * (1 / (3 * theta) + theta / 3);
    const auto s = gkt::rough_bulk_viscosity(3, Rational(c.a10, 10), Rational(c.b10, 10), Rational(2, 5));
    std::printf(
        "Gamma* alpha=%.1f beta=%.1f: DSMC %.4f +- %.4f, (19.17) at DSMC theta %.4f, at Maxwellian theta %.4f\n", alpha,
        beta, measured, measured_error, maxwellian, s.relaxation_rate);
    EXPECT_NEAR(maxwellian, measured, 0.1 * measured + 3 * measured_error);
  }
}
