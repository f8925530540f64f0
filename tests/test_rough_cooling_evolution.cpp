// Free cooling of rough spheres and disks (docs/theory.md §19.13) against
//  (1) the closed-form solution of the Maxwellian two-temperature equations: with ds = √T_t dτ the
//      ratio obeys a Riccati equation with constant coefficients ([huthmann1997]; [luding1998]
//      eqs. 9–11 in 3D; theory.md (19.12) for any d), solved in closed form, and τ(s) by quadrature;
//  (2) the steady HCS solver (θ, ζ*, a20, a02, a11 of both schemes) at late times, and Haff's law;
//  (3) the limits α = β = 1 (energy conserved, equipartition) and β = −1 (frozen spin, smooth Haff);
//  (4) Walton friction (Maxwellian rates by quadrature): its HCS θ at late times, and the constant-β
//      trajectory as μ_f → ∞;
//  (5) bad input;
//  (6) nonzero initial cumulants a20, a02, a11: the same HCS at late times, zeros bit for bit the
//      default, unrealizable values refused.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "gkt/evolution/rough_cooling_evolution.hpp"
#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"
#include "gkt/transport/rough/rough_walton.hpp"

using gkt::Rational;

namespace {

/// The Maxwellian equations in the collision variable s (ds = √T_t dτ, theory.md (19.12)):
///   d ln T_t/ds = −(P − Qθ),   d ln T_r/ds = −(R − S/θ),   dθ/ds = S + (P − R)θ − Qθ²,
/// with η = (1+β)κ/(2(1+κ)), P = (2/d)[(1−α²)/2 + (d−1)η(1−η)], Q = (2/d)(d−1)η²/κ,
/// R = (2(d−1)/d_r)(η/κ)(1 − η/κ), S = (2(d−1)/d_r)η²/κ. In 3D, P = (4/3)A, Q = S = (4/3)B,
/// R = (4/3)C with Huthmann–Zippelius's A, B, C. With θ± the roots, u = (θ − θ+)/(θ − θ−) decays as
/// u0 e^{−λs}, λ = Q(θ+ − θ−), and ln(T_t/T_t(0)) = −(P − Qθ+)s + ln((1 − u)/(1 − u0)).
struct ClosedForm {
  double p, q, r, s, plus, minus, u0, lambda, t0;

  ClosedForm(int d, double alpha, double beta, double kappa, double tt0, double tr0) : t0(tt0) {
    const double eta = (1 + beta) * kappa / (2 * (1 + kappa)), dr = d == 3 ? 3 : 1;
    p = 2.0 / d * ((1 - alpha * alpha) / 2 + (d - 1) * eta * (1 - eta));
    q = 2.0 / d * (d - 1) * eta * eta / kappa;
    r = 2 * (d - 1) / dr * (eta / kappa) * (1 - eta / kappa);
    s = 2 * (d - 1) / dr * eta * eta / kappa;
    const double disc = std::sqrt((p - r) * (p - r) + 4 * q * s);
    plus = (p - r + disc) / (2 * q);
    minus = (p - r - disc) / (2 * q);
    const double theta0 = tr0 / tt0;
    u0 = (theta0 - plus) / (theta0 - minus);
    lambda = q * (plus - minus);
  }
  [[nodiscard]] double u(double x) const { return u0 * std::exp(-lambda * x); }
  [[nodiscard]] double theta(double x) const { return (plus - minus * u(x)) / (1 - u(x)); }
  [[nodiscard]] double translational(double x) const {
    return t0 * std::exp(-(p - q * plus) * x) * (1 - u(x)) / (1 - u0);
  }
  /// τ(s) = ∫_0^s T_t^{−1/2} ds' (composite Simpson, 20000 panels).
  [[nodiscard]] double time(double x) const {
    const int n = 20000;
    const double h = x / n;
    double sum = 0;
    for (int i = 0; i <= n; ++i) {
      const double w = (i == 0 || i == n) ? 1 : (i % 2 == 1 ? 4 : 2);
      sum += w / std::sqrt(translational(i * h));
    }
    return sum * h / 3;
  }
};

std::vector<double> log_times(double first, double last, int n) {
  std::vector<double> t;
  for (int i = 0; i < n; ++i) t.push_back(first * std::pow(last / first, static_cast<double>(i) / (n - 1)));
  return t;
}

}  // namespace

TEST(RoughCoolingEvolution, MaxwellianMatchesClosedFormSolution) {
  struct Case {
    int d;
    Rational alpha, beta, kappa;
    double tt0, tr0;
  };
  for (const Case& c : {Case{3, Rational(9, 10), Rational(1, 2), Rational(2, 5), 1, 0.01},
                        Case{3, Rational(7, 10), Rational(-1, 2), Rational(1, 4), 2, 20},
                        Case{2, Rational(7, 10), Rational(-3, 10), Rational(1, 2), 1, 2},
                        Case{2, Rational(1, 2), Rational(1), Rational(1), 0.5, 0.1}}) {
    const gkt::RoughCoolingRates rates(c.d, c.alpha, c.beta, c.kappa);
    const auto run = gkt::evolve_rough_cooling(rates, false, c.tt0, c.tr0, log_times(0.01, 1e4, 15), 1e-12, 1e-14);
    const ClosedForm exact(c.d, c.alpha.to_double(), c.beta.to_double(), c.kappa.to_double(), c.tt0, c.tr0);
    for (const auto& s : run.samples) {
      // Maxwellian: collisions per particle = s exactly (dC/dτ = √T_t).
      const double theta = s.rotational_temperature / s.translational_temperature;
      EXPECT_NEAR(theta / exact.theta(s.collisions), 1, 1e-9) << "d=" << c.d << " tau=" << s.time;
      EXPECT_NEAR(s.translational_temperature / exact.translational(s.collisions), 1, 1e-9) << "tau=" << s.time;
      EXPECT_NEAR(exact.time(s.collisions) / s.time, 1, 1e-9) << "tau=" << s.time;
    }
  }
}

// Late times: θ, ζ* and the cumulants are those of the steady solver (the same balances), and T_t
// follows Haff's law T_t ∝ τ^{−2} (local exponent −2).
TEST(RoughCoolingEvolution, RelaxesToSteadyStateAndHaffLaw) {
  struct Case {
    int d;
    Rational alpha, beta, kappa;
    double tr0;
  };
  for (const Case& c : {Case{3, Rational(9, 10), Rational(1, 2), Rational(2, 5), 0.01},
                        Case{3, Rational(1, 2), Rational(1, 2), Rational(2, 5), 5},
                        Case{2, Rational(9, 10), Rational(1, 2), Rational(1, 2), 1}})
    for (const bool linear : {false, true}) {
      const auto steady = gkt::rough_homogeneous_cooling_state(
          c.d, c.alpha, c.beta, c.kappa, linear ? gkt::RoughHcsScheme::linear : gkt::RoughHcsScheme::maxwellian);
      const gkt::RoughCoolingRates rates(c.d, c.alpha, c.beta, c.kappa);
      const auto run = gkt::evolve_rough_cooling(rates, linear, 1, c.tr0, {1e5, 2e5}, 1e-11, 1e-14);
      const auto& end = run.samples.back();
      EXPECT_NEAR(end.rotational_temperature / end.translational_temperature, steady.temperature_ratio, 1e-8)
          << "d=" << c.d << " alpha=" << c.alpha << " linear=" << linear;
      EXPECT_NEAR(end.cooling_rate, steady.cooling_rate, 1e-8);
      EXPECT_NEAR(end.a20, steady.a20, 1e-8);
      EXPECT_NEAR(end.a02, linear ? steady.a02 : 0, 1e-8);
      EXPECT_NEAR(end.a11, linear ? steady.a11 : 0, 1e-8);
      const double exponent = std::log(end.translational_temperature / run.samples[0].translational_temperature) /
                              std::log(end.time / run.samples[0].time);
      EXPECT_NEAR(exponent, -2, 1e-3);
    }
}

// α = β = 1: no energy is lost, (d T_t + d_r T_r) stays put and both relax to its mean.
TEST(RoughCoolingEvolution, ElasticPerfectlyRoughConservesEnergy) {
  for (int d : {2, 3})
    for (const bool linear : {false, true}) {
      const double dr = d == 3 ? 3 : 1, tr0 = 4;
      const gkt::RoughCoolingRates rates(d, Rational(1), Rational(1), Rational(2, 5));
      const auto run = gkt::evolve_rough_cooling(rates, linear, 1, tr0, log_times(0.01, 100, 10), 1e-11, 1e-14);
      const double energy = d + dr * tr0;
      for (const auto& s : run.samples)
        EXPECT_NEAR(d * s.translational_temperature + dr * s.rotational_temperature, energy, 1e-8 * energy);
      const auto& end = run.samples.back();
      EXPECT_NEAR(end.translational_temperature, energy / (d + dr), 1e-8);
      EXPECT_NEAR(end.rotational_temperature, energy / (d + dr), 1e-8);
      EXPECT_NEAR(end.a20, 0, 1e-7);
      EXPECT_NEAR(end.a02, 0, 1e-7);
      EXPECT_NEAR(end.a11, 0, 1e-7);
    }
}

// β = −1: the spin is not touched (T_r constant) and T_t cools as the smooth gas: Maxwellian,
// T_t = (1 + (1 − α²)τ/(2d))^{−2} (z_t = (1 − α²)/d, theory.md (19.12) at η_t = 0).
TEST(RoughCoolingEvolution, SmoothLimitFreezesTheSpin) {
  for (int d : {2, 3}) {
    const double alpha = 0.8;
    const gkt::RoughCoolingRates rates(d, Rational(4, 5), Rational(-1), Rational(2, 5));
    const auto run = gkt::evolve_rough_cooling(rates, false, 1, 3, log_times(0.01, 1e3, 8), 1e-12, 1e-14);
    for (const auto& s : run.samples) {
      EXPECT_DOUBLE_EQ(s.rotational_temperature, 3);
      const double haff = std::pow(1 + (1 - alpha * alpha) * s.time / (2 * d), -2);
      EXPECT_NEAR(s.translational_temperature / haff, 1, 1e-9) << "tau=" << s.time;
    }
  }
}

TEST(RoughCoolingEvolution, BadInputNamesTheField) {
  const gkt::RoughCoolingRates rates(3, Rational(9, 10), Rational(1, 2), Rational(2, 5));
  auto message = [&](double tt, double tr, std::vector<double> times) {
    try {
      (void)gkt::evolve_rough_cooling(rates, true, tt, tr, times, 1e-8, 1e-12);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(0, 1, {1}).rfind("translational_temperature:", 0), 0u);
  EXPECT_EQ(message(1, -1, {1}).rfind("rotational_temperature:", 0), 0u);
  EXPECT_EQ(message(1, std::nan(""), {1}).rfind("rotational_temperature:", 0), 0u);
  EXPECT_EQ(message(1, 1, {2, 1}).rfind("times:", 0), 0u);
  EXPECT_EQ(message(1, 1, {0}).rfind("times:", 0), 0u);
  EXPECT_THROW(gkt::RoughCoolingRates(3, Rational(9, 10), Rational(2), Rational(2, 5)), std::invalid_argument);
}

// Walton friction: the trajectory ends on the HCS θ of the same rates (the root of ζ_t = ζ_r, found by
// bisection here as rough_walton_cooling_state does; `gkt table` gives 1.0475878279 at (0.9, 1, 2/5, 1),
// 3D), and μ_f = 10⁶ follows the constant-β trajectory (β = β0; quadrature against the exact engine).
TEST(RoughCoolingEvolution, WaltonFrictionRelaxesToItsHcsAndConstantBetaLimit) {
  auto walton = [](int d, double alpha, double beta0, double kappa, double friction) {
    return gkt::RoughMaxwellianRates([=](double theta) {
      const auto r = gkt::rough_walton_rates(d, alpha, beta0, kappa, friction, theta);
      return std::array<double, 2>{4.0 / (d + 2) * r.translational, 4.0 / (d + 2) * r.rotational};
    });
  };
  for (int d : {2, 3}) {
    const auto rates = walton(d, 0.9, 1, 0.4, 1);
    double lo = std::log(0.01), hi = std::log(100);  // z_t − z_r > 0 for a cold spin, < 0 for a hot one
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      const auto z = rates(std::exp(mid));
      (z[0] - z[1] > 0 ? lo : hi) = mid;
    }
    const double theta = std::exp(0.5 * (lo + hi));
    const auto run = gkt::evolve_rough_maxwellian_cooling(d, rates, 1, 0.1, {1e4, 2e4}, 1e-10, 1e-14);
    const auto& end = run.samples.back();
    EXPECT_NEAR(end.rotational_temperature / end.translational_temperature / theta, 1, 1e-7) << "d=" << d;
    EXPECT_NEAR(end.cooling_rate, (d + 2) / 4.0 * rates(theta)[0], 1e-7);
    if (d == 3) {
      EXPECT_NEAR(theta, 1.0475878279, 1e-9);
    }

    const gkt::RoughCoolingRates constant(d, Rational(7, 10), Rational(1, 2), Rational(2, 5));
    const auto times = log_times(0.1, 100, 4);
    const auto exact = gkt::evolve_rough_cooling(constant, false, 1, 3, times, 1e-11, 1e-14);
    const auto limit =
        gkt::evolve_rough_maxwellian_cooling(d, walton(d, 0.7, 0.5, 0.4, 1e6), 1, 3, times, 1e-11, 1e-14);
    for (std::size_t i = 0; i < times.size(); ++i) {
      EXPECT_NEAR(limit.samples[i].translational_temperature / exact.samples[i].translational_temperature, 1, 1e-7);
      EXPECT_NEAR(limit.samples[i].rotational_temperature / exact.samples[i].rotational_temperature, 1, 1e-7);
    }
  }
  EXPECT_THROW((void)gkt::evolve_rough_maxwellian_cooling(4, walton(3, 0.9, 1, 0.4, 1), 1, 1, {1}, 1e-8, 1e-12),
               std::invalid_argument);
}

// (6) From nonzero (realizable) initial cumulants the linear scheme relaxes to the same HCS as from
// Maxwellians (the steady solver's θ, ζ*, a20, a02, a11 to 1e-8), the first sample still carries the
// initial values, and explicit zeros reproduce the default run bit for bit.
TEST(RoughCoolingEvolution, InitialCumulantsRelaxToTheHcs) {
  struct Case {
    int d;
    Rational alpha, beta, kappa;
    gkt::RoughCumulants a;
  };
  for (const Case& c : {Case{3, Rational(9, 10), Rational(1, 2), Rational(2, 5), {0.1, -0.2, 0.05}},
                        Case{3, Rational(7, 10), Rational(1), Rational(2, 5), {-0.3, 0.5, -0.2}},
                        Case{2, Rational(9, 10), Rational(1, 2), Rational(1, 2), {0.2, -0.4, 0.1}}}) {
    const auto steady =
        gkt::rough_homogeneous_cooling_state(c.d, c.alpha, c.beta, c.kappa, gkt::RoughHcsScheme::linear);
    const gkt::RoughCoolingRates rates(c.d, c.alpha, c.beta, c.kappa);
    const auto run = gkt::evolve_rough_cooling(rates, true, 1, 2, {1e-9, 1e5, 2e5}, 1e-11, 1e-14, c.a);
    const auto& first = run.samples.front();
    EXPECT_NEAR(first.a20, c.a[0], 1e-6);
    EXPECT_NEAR(first.a02, c.a[1], 1e-6);
    EXPECT_NEAR(first.a11, c.a[2], 1e-6);
    const auto& end = run.samples.back();
    EXPECT_NEAR(end.rotational_temperature / end.translational_temperature, steady.temperature_ratio, 1e-8)
        << "d=" << c.d << " alpha=" << c.alpha;
    EXPECT_NEAR(end.cooling_rate, steady.cooling_rate, 1e-8);
    EXPECT_NEAR(end.a20, steady.a20, 1e-8);
    EXPECT_NEAR(end.a02, steady.a02, 1e-8);
    EXPECT_NEAR(end.a11, steady.a11, 1e-8);
    // The cumulants change the early cooling: a20 > 0 at τ = 0 is a different trajectory.
    const auto from_maxwellian = gkt::evolve_rough_cooling(rates, true, 1, 2, {0.5}, 1e-11, 1e-14);
    const auto from_cumulants = gkt::evolve_rough_cooling(rates, true, 1, 2, {0.5}, 1e-11, 1e-14, c.a);
    EXPECT_GT(std::abs(from_cumulants.samples[0].translational_temperature -
                       from_maxwellian.samples[0].translational_temperature),
              1e-6);
    const auto zero = gkt::evolve_rough_cooling(rates, true, 1, 2, {0.5, 50}, 1e-10, 1e-14, {0.0, 0.0, 0.0});
    const auto plain = gkt::evolve_rough_cooling(rates, true, 1, 2, {0.5, 50}, 1e-10, 1e-14);
    for (std::size_t i = 0; i < 2; ++i) {
      EXPECT_EQ(zero.samples[i].translational_temperature, plain.samples[i].translational_temperature);
      EXPECT_EQ(zero.samples[i].rotational_temperature, plain.samples[i].rotational_temperature);
      EXPECT_EQ(zero.samples[i].a02, plain.samples[i].a02);
    }
  }
}

// Unrealizable initial cumulants (theory.md (19.24a)) and cumulants without the linear scheme are
// refused, naming the field.
TEST(RoughCoolingEvolution, InitialCumulantsMustBeRealizable) {
  auto message = [](int d, const gkt::RoughCumulants& a) -> std::string {
    try {
      gkt::check_rough_initial_cumulants(d, a);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(message(3, {-0.39, -0.39, 0}), "");
  EXPECT_EQ(message(2, {-0.5, -0.66, 0}), "");  // Var c² = 0 is allowed
  EXPECT_EQ(message(3, {-0.41, 0, 0}).rfind("a20: must be >= -2/(d+2)", 0), 0u) << message(3, {-0.41, 0, 0});
  EXPECT_EQ(message(2, {-0.45, 0, 0}), "");  // −1/2 for disks
  EXPECT_EQ(message(3, {0, -0.41, 0}).rfind("a02: must be >= -2/(d_r+2)", 0), 0u);
  EXPECT_EQ(message(2, {0, -0.6, 0}), "");  // −2/3 for disks (one rotational degree of freedom)
  // Cauchy–Schwarz: d d_r a11² ≤ (2 + (d+2)a20)(2 + (d_r+2)a02), |a11| ≤ 2/3 at a20 = a02 = 0 (3D).
  EXPECT_EQ(message(3, {0, 0, 0.66}), "");
  EXPECT_EQ(message(3, {0, 0, -0.67}).rfind("a11: must be in [-0.666667, 0.666667]", 0), 0u)
      << message(3, {0, 0, -0.67});
  EXPECT_EQ(message(2, {0, 0, 1.41}), "");  // |a11| ≤ √2 for disks
  EXPECT_EQ(message(2, {0, 0, 1.42}).rfind("a11:", 0), 0u);
  EXPECT_EQ(message(3, {NAN, 0, 0}), "a20: must be a finite number");
  const gkt::RoughCoolingRates rates(3, Rational(9, 10), Rational(1, 2), Rational(2, 5));
  try {
    gkt::evolve_rough_cooling(rates, false, 1, 1, {1}, 1e-8, 1e-12, {0.1, 0, 0});
    ADD_FAILURE() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("Maxwellian scheme carries no cumulants"), std::string::npos) << e.what();
  }
}
