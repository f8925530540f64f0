// Free cooling of rough spheres and disks in the nonlinear Sonine scheme (docs/theory.md §19.24, (19.110)–(19.113);
// `gkt evolve` with hcs = "nonlinear" / "nonlinear-oriented"): every product of the unknowns kept in the moment
// equations (19.25b), against
//  (1) the steady nonlinear Sonine HCS of the same order and ansatz (rough_sonine_cooling_state, §19.14) at late
//      times, d = 2, 3;
//  (2) the linear scheme for small cumulants (α = β = 1): the two trajectories differ by O(a²), checked by halving
//      the initial cumulants;
//  (3) β = −1: the translational cumulants follow the smooth gas's nonlinear hierarchy (evolve_homogeneous_cooling,
//      other tables) — the quadratic terms and the collision count checked against an independent code;
//  (4) the library DSMC from a cold spin: a02 and θ at the first collisions, nonlinear against linear.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "dsmc_rough.hpp"
#include "gkt/evolution/homogeneous_cooling_evolution.hpp"
#include "gkt/evolution/rough_cooling_evolution.hpp"
#include "gkt/transport/monodisperse/homogeneous_cooling_state.hpp"
#include "gkt/transport/rough/rough_sonine_cooling_rates.hpp"
#include "gkt/transport/rough/rough_sonine_cooling_state.hpp"
#include "rough_evolution_checks.hpp"

namespace gkt {
namespace {

// The late-time state is the steady nonlinear HCS of the same order and ansatz: θ, ζ*, every a_pq, b_pq and C.
TEST(RoughNonlinearEvolution, RelaxesToTheNonlinearHcs) {
  struct Case {
    int d, order;
    Rational alpha, beta;
    RoughSonineAnsatz ansatz;
    double tr0;
    RoughCumulants a0;
  };
  const Rational kappa(2, 5);
  for (const Case& c :
       {Case{3, 1, Rational(9, 10), Rational(1, 2), RoughSonineAnsatz::isotropic, 0.01, {}},
        Case{3, 2, Rational(7, 10), Rational(1), RoughSonineAnsatz::isotropic, 5, {0.1, -0.2, 0.05}},
        Case{3, 1, Rational(9, 10), Rational(1, 2), RoughSonineAnsatz::oriented, 0.01, {}},
        Case{3, 2, Rational(9, 10), Rational(1, 2), RoughSonineAnsatz::oriented, 0.1, {}},
        Case{2, 2, Rational(9, 10), Rational(1, 2), RoughSonineAnsatz::isotropic, 0.01, {0.2, -0.4, 0.1}}}) {
    const auto steady =
        rough_sonine_cooling_state(c.d, c.alpha, c.beta, kappa, c.order, RoughSonineScheme::nonlinear, c.ansatz);
    ASSERT_TRUE(steady.solved);
    const RoughSonineCoolingRates rates(c.d, c.alpha, c.beta, kappa, c.order, c.ansatz, RoughSonineScheme::nonlinear);
    ASSERT_EQ(rates.scheme(), RoughSonineScheme::nonlinear);
    const auto run = evolve_rough_sonine_cooling(rates, 1, c.tr0, {1e-10, 1e5, 2e5}, 1e-11, 1e-14, c.a0);
    const auto& end = run.samples.back();
    const std::string where = std::to_string(c.d) + "D N=" + std::to_string(c.order) + " alpha=" + c.alpha.to_string() +
                              (c.ansatz == RoughSonineAnsatz::oriented ? " oriented" : "");
    EXPECT_NEAR(end.rotational_temperature / end.translational_temperature, steady.temperature_ratio, 1e-8) << where;
    test::expect_sample_at_cooling_state(end, steady, c.d, where);
    // Not the linear scheme's fixed point: the products move θ by more than the tolerance (§19.14 table).
    const auto linear =
        rough_sonine_cooling_state(c.d, c.alpha, c.beta, kappa, c.order, RoughSonineScheme::linear, c.ansatz);
    EXPECT_GT(std::abs(linear.temperature_ratio - steady.temperature_ratio), 1e-6) << where;
    const double exponent = std::log(end.translational_temperature / run.samples[1].translational_temperature) /
                            std::log(end.time / run.samples[1].time);
    EXPECT_NEAR(exponent, -2, 1e-3) << where;
    EXPECT_NEAR(run.samples[0].a20, c.a0[0], 1e-6) << where;  // the first sample carries a(0)
  }
}

/// Returns max over the samples of |θ_nl − θ_lin| and of |a_nl − a_lin| (every a_pq), at order 1.
std::array<double, 2> scheme_difference(int d, const RoughCumulants& a0, const std::vector<double>& times) {
  const Rational one(1), kappa(2, 5);
  const RoughSonineCoolingRates lin(d, one, one, kappa, 1, RoughSonineAnsatz::isotropic, RoughSonineScheme::linear);
  const RoughSonineCoolingRates nl(d, one, one, kappa, 1, RoughSonineAnsatz::isotropic, RoughSonineScheme::nonlinear);
  const auto rl = evolve_rough_sonine_cooling(lin, 1, 1, times, 1e-12, 1e-16, a0);
  const auto rn = evolve_rough_sonine_cooling(nl, 1, 1, times, 1e-12, 1e-16, a0);
  std::array<double, 2> out{0, 0};
  for (std::size_t i = 0; i < times.size(); ++i) {
    const auto &l = rl.samples[i], &n = rn.samples[i];
    out[0] = std::max(out[0], std::abs(n.rotational_temperature / n.translational_temperature -
                                       l.rotational_temperature / l.translational_temperature));
    for (std::size_t w = 0; w < l.cumulants.size(); ++w)
      out[1] = std::max(out[1], std::abs(n.cumulants[w] - l.cumulants[w]));
  }
  return out;
}

// α = β = 1 (the HCS is equilibrium, every cumulant 0): from small a(0) the nonlinear and linear trajectories differ
// by the dropped products only, O(a(0)²): halving a(0) divides the difference by 4 (to O(a(0)) corrections), while
// each trajectory moves by O(a(0)).
TEST(RoughNonlinearEvolution, DiffersFromTheLinearSchemeAtSecondOrder) {
  const std::vector<double> times{0.1, 0.3, 1, 3, 10, 30};
  for (const int d : {3, 2}) {
    const RoughCumulants base = d == 3 ? RoughCumulants{0.1, -0.2, 0.05} : RoughCumulants{0.2, -0.3, 0.1};
    std::vector<std::array<double, 2>> diff;
    for (const double eps : {0.4, 0.2, 0.1}) {
      diff.push_back(scheme_difference(d, {eps * base[0], eps * base[1], eps * base[2]}, times));
      EXPECT_GT(diff.back()[1], 1e-6 * eps * eps) << d;  // the schemes do differ
    }
    for (std::size_t k = 0; k < 2; ++k) {
      const double r1 = diff[0][k] / diff[1][k], r2 = diff[1][k] / diff[2][k];
      std::printf("d=%d %s: differences %.3e %.3e %.3e, ratios %.4f %.4f\n", d, k == 0 ? "theta" : "a", diff[0][k],
                  diff[1][k], diff[2][k], r1, r2);
      EXPECT_NEAR(r2, 4, 0.05) << d << " " << k;  // measured 3.993–4.008 (theory.md §19.24)
      EXPECT_LT(std::abs(r2 - 4), std::abs(r1 - 4) + 1e-3) << d << " " << k;  // the O(a³) rest shrinks
    }
  }
}

// β = −1: no torque, the spin decouples and the translational distribution is the smooth gas's. The nonlinear
// rough trajectory of order N (a20 … a_{N+1,0}) is the smooth nonlinear hierarchy of K = N + 1 (theory.md (9.2)–(9.4),
// the smooth engine's tables, its collision rate Σ a_k a_l C(k, l)), from the same a20(0).
TEST(RoughNonlinearEvolution, SmoothLimitIsTheSmoothNonlinearHierarchy) {
  const std::vector<double> times{0.01, 0.1, 1, 10, 100, 1000};
  for (const int d : {3, 2}) {
    const Rational alpha(7, 10);
    const int order = 2;
    const RoughSonineCoolingRates rates(d, alpha, Rational(-1), Rational(2, 5), order, RoughSonineAnsatz::isotropic,
                                        RoughSonineScheme::nonlinear);
    const auto rough = evolve_rough_sonine_cooling(rates, 1, 3, times, 1e-12, 1e-16, {0.3, 0, 0});
    HomogeneousCoolingState h(d);
    const auto smooth = evolve_homogeneous_cooling(h.hierarchy(alpha, order + 1), 1, {0.3}, times, 1e-12, 1e-16);
    for (std::size_t i = 0; i < times.size(); ++i) {
      const RoughEvolutionSample& r = rough.samples[i];
      const EvolutionSample& s = smooth.samples[i];
      EXPECT_DOUBLE_EQ(r.rotational_temperature, 3) << d;  // no torque (exp(ln 3) to an ulp)
      EXPECT_NEAR(r.translational_temperature / s.temperature, 1, 1e-8) << d << " t=" << times[i];
      EXPECT_NEAR(r.collisions / s.collisions, 1, 1e-8) << d << " t=" << times[i];
      EXPECT_NEAR(r.cooling_rate, s.cooling_rate, 1e-8) << d << " t=" << times[i];
      ASSERT_EQ(r.cumulants.size(), s.a.size() - 2) << d;  // a_2 … a_K of the smooth hierarchy
      for (std::size_t p = 0; p < r.cumulants.size(); ++p)
        EXPECT_NEAR(r.cumulants[p], s.a[p + 2], 1e-8) << d << " t=" << times[i] << " p=" << p + 2;
    }
  }
}

}  // namespace
}  // namespace gkt

namespace gkt {
namespace {

/// Returns a02 and θ of the trajectory at `collisions` per particle (linear interpolation on a dense time grid).
std::array<std::vector<double>, 2> at_collisions(const RoughEvolutionResult& run,
                                                 const std::vector<double>& collisions) {
  std::array<std::vector<double>, 2> out;
  for (const double c : collisions) {
    std::size_t i = 1;
    while (i + 1 < run.samples.size() && run.samples[i].collisions < c) ++i;
    const auto &lo = run.samples[i - 1], &hi = run.samples[i];
    const double f = (c - lo.collisions) / (hi.collisions - lo.collisions);
    out[0].push_back(lo.a02 + f * (hi.a02 - lo.a02));
    const double tl = lo.rotational_temperature / lo.translational_temperature,
                 th = hi.rotational_temperature / hi.translational_temperature;
    out[1].push_back(tl + f * (th - tl));
  }
  return out;
}

// The stall of N = 3 from a cold spin (theory.md §19.24, "Where it stalls"): θ(0) = 0.01 at (0.9, 0.5), 3D, the
// nonlinear scheme's cumulants grow past 10² and CVODE's steps shrink; the step budget over the whole trajectory
// (not per output time: 40 output times below τ = 0.01 would each get a fresh budget otherwise) stops it with a
// message naming the cause, while the linear scheme from the same start reaches τ = 0.01 within the same budget.
TEST(RoughNonlinearEvolution, ColdSpinAtThirdOrderExhaustsTheStepBudget) {
  const Rational alpha(9, 10), beta(1, 2), kappa(2, 5);
  std::vector<double> times;
  for (int i = 1; i <= 40; ++i) times.push_back(0.01 * i / 40);
  constexpr long budget = 2000;
  const RoughSonineCoolingRates linear(3, alpha, beta, kappa, 3, RoughSonineAnsatz::isotropic,
                                       RoughSonineScheme::linear);
  const RoughEvolutionResult ok = evolve_rough_sonine_cooling(linear, 1, 0.01, times, 1e-10, 1e-14, {}, budget);
  ASSERT_EQ(ok.samples.size(), times.size());
  EXPECT_LE(ok.counters.steps, budget);
  const RoughSonineCoolingRates nonlinear(3, alpha, beta, kappa, 3, RoughSonineAnsatz::isotropic,
                                          RoughSonineScheme::nonlinear);
  try {
    (void)evolve_rough_sonine_cooling(nonlinear, 1, 0.01, times, 1e-10, 1e-14, {}, budget);
    ADD_FAILURE() << "the cold-spin N = 3 nonlinear trajectory did not stop";
  } catch (const EvolutionFailure& e) {
    const std::string message = e.what();
    std::printf("%s\n", message.c_str());
    EXPECT_EQ(message.rfind("max_steps: the nonlinear Sonine scheme at order 3 used its 2000 CVODE steps", 0), 0U);
    EXPECT_NE(message.find("use a lower order"), std::string::npos);
    EXPECT_EQ(message.find('\n'), std::string::npos);
    EXPECT_LT(e.time(), 0.01);
  }
  EXPECT_THROW((void)evolve_rough_sonine_cooling(nonlinear, 1, 0.01, times, 1e-10, 1e-14, {}, 0),
               std::invalid_argument);
}

// The library DSMC (independent of the engine) from a cold spin, θ(0) = 0.01 at (0.9, 0.5), 3D (four runs of 20000
// particles, snapshots every 0.1 collisions per particle; the spin kurtosis a02 rises to ~4 and relaxes): the oriented
// nonlinear and linear trajectories of orders 1 and 2 against a02 and θ at 0.5 … 3 collisions (theory.md §19.13: the
// linear order 2 follows a02 within the DSMC's error where the first-Sonine one drifts by 1.5–3.5σ).
// theory.md §19.24 records the χ² of each; the test asserts what holds there: the order 2 of both schemes within 4σ
// everywhere, θ of every trajectory within 4σ, the order resolved (χ² of a02 at N = 1 over 4× that at N = 2, both
// schemes) and the scheme not: at the same order the nonlinear and linear a02 differ by less than 0.1σ of the DSMC at
// every point (measured: 3e-4 against σ = 0.003–0.026), so this DSMC cannot tell which scheme is closer.
TEST(RoughNonlinearEvolution, EarlySpinCumulantAgainstDsmc) {
  const Rational alpha(9, 10), beta(1, 2), kappa(2, 5);
  const double theta0 = 0.01;
  std::vector<double> times;
  for (int i = 0; i <= 300; ++i) times.push_back(1e-3 * std::pow(10.0, 4.0 * i / 300));
  const int batches = 30, runs = 4;
  std::vector<double> collisions;
  for (int b = 1; b <= batches; ++b) collisions.push_back(0.1 * b);
  // [scheme][order − 1]: scheme 0 linear, 1 nonlinear.
  std::array<std::array<std::array<std::vector<double>, 2>, 2>, 2> traj;
  for (int s = 0; s < 2; ++s)
    for (int n = 1; n <= 2; ++n) {
      const RoughSonineCoolingRates rates(3, alpha, beta, kappa, n, RoughSonineAnsatz::oriented,
                                          s == 0 ? RoughSonineScheme::linear : RoughSonineScheme::nonlinear);
      traj[s][n - 1] = at_collisions(evolve_rough_sonine_cooling(rates, 1, theta0, times, 1e-10, 1e-14), collisions);
    }
  std::vector<std::vector<double>> a02(batches), theta(batches);
  for (int r = 0; r < runs; ++r) {
    RoughDsmcParameters p;
    p.alpha = 0.9;
    p.beta = 0.5;
    p.kappa = 0.4;
    p.initial_temperature_ratio = theta0;
    const auto sim = run_rough_hcs_dsmc(3, p, test::schedule(20000, 0, batches, 0.1, 11 + r));
    for (std::size_t b = 0; b < static_cast<std::size_t>(batches); ++b) {
      a02[b].push_back(sim.a02[b]);
      theta[b].push_back(sim.temperature_ratio[b]);
    }
  }
  std::array<std::array<double, 2>, 2> chi2_a{}, chi2_t{};
  for (const std::size_t b : {4, 9, 14, 19, 24, 29}) {  // 0.5, 1, …, 3 collisions per particle
    double m = 0, e = 0, mt = 0, et = 0;
    test::batch_mean(a02[b], m, e);
    test::batch_mean(theta[b], mt, et);
    std::printf(
        "C=%.1f a02 DSMC %.4f +- %.4f lin %.4f %.4f nl %.4f %.4f | theta DSMC %.4f +- %.4f lin %.4f %.4f nl %.4f "
        "%.4f\n",
        collisions[b], m, e, traj[0][0][0][b], traj[0][1][0][b], traj[1][0][0][b], traj[1][1][0][b], mt, et,
        traj[0][0][1][b], traj[0][1][1][b], traj[1][0][1][b], traj[1][1][1][b]);
    EXPECT_NEAR(traj[0][1][0][b], m, 4 * e) << collisions[b];
    EXPECT_NEAR(traj[1][1][0][b], m, 4 * e) << collisions[b];
    for (int s = 0; s < 2; ++s)
      for (int n = 0; n < 2; ++n) {
        EXPECT_NEAR(traj[s][n][1][b], mt, 4 * et) << collisions[b] << " scheme " << s << " N=" << n + 1;
        chi2_a[s][n] += std::pow((traj[s][n][0][b] - m) / e, 2);
        if (s == 1) {
          EXPECT_LT(std::abs(traj[1][n][0][b] - traj[0][n][0][b]), 0.1 * e) << collisions[b];
        }
        chi2_t[s][n] += std::pow((traj[s][n][1][b] - mt) / et, 2);
      }
  }
  std::printf("chi2 a02 (6 points): linear N=1 %.2f N=2 %.2f, nonlinear N=1 %.2f N=2 %.2f\n", chi2_a[0][0],
              chi2_a[0][1], chi2_a[1][0], chi2_a[1][1]);
  std::printf("chi2 theta (6 points): linear N=1 %.2f N=2 %.2f, nonlinear N=1 %.2f N=2 %.2f\n", chi2_t[0][0],
              chi2_t[0][1], chi2_t[1][0], chi2_t[1][1]);
  for (int s = 0; s < 2; ++s) EXPECT_GT(chi2_a[s][0], 4 * chi2_a[s][1]) << s;
}

}  // namespace
}  // namespace gkt
