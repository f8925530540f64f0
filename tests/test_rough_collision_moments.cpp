// The rough-sphere collision engine (docs/theory.md §19) against
//  (1) Monte Carlo with error bars, the collision applied in vector form from the impulse
//      (tests/rough_monte_carlo.hpp), d = 3 and d = 2, moments up to degree 4 in the velocities;
//  (2) the smooth engine at β = −1 (exact equality);
//  (3) closed forms of the energy change per collision derived by hand (theory.md (19.6)–(19.8)),
//      numeric and with θ symbolic.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

#include "gkt/collision/quadratic_form_moments.hpp"
#include "gkt/collision/rough_collision_moments.hpp"
#include "rough_monte_carlo.hpp"

using gkt::Rational;
using gkt::RationalPolynomial;
using gkt::rough_dot_form;
using gkt::RoughCollisionMoments;
using gkt::RoughForm;
using gkt::RoughSlot;
using gkt::test::RoughCollision;

namespace {

double mc_dot(const RoughCollision& c, RoughSlot a, RoughSlot b) {
  return gkt::test::dot3(c.w[static_cast<std::size_t>(a)], c.w[static_cast<std::size_t>(b)]);
}

struct RoughCase {
  int d;
  Rational alpha, beta, kappa, theta;
};

void PrintTo(const RoughCase& k, std::ostream* os) {
  *os << "d=" << k.d << " alpha=" << k.alpha << " beta=" << k.beta << " kappa=" << k.kappa << " theta=" << k.theta;
}

}  // namespace

TEST(RoughCollisionRule, MonteCarloRuleObeysTheContactLawAndConservation) {
  // The test's own rule (impulse form) must reproduce the definition of α and β and conserve
  // momentum and angular momentum; otherwise the Monte Carlo below checks nothing.
  for (int d : {2, 3}) {
    gkt::test::RoughCollisionSampler sampler(d, 0.7, 0.3, 0.4, 1.5, 7);
    for (int s = 0; s < 200; ++s) {
      const RoughCollision c = sampler.draw();
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(c.w[4][k] + c.w[5][k], c.w[0][k] + c.w[1][k], 1e-12);  // momentum
        EXPECT_NEAR(c.w[6][k] - c.w[2][k], c.w[7][k] - c.w[3][k], 1e-12);  // equal spin changes
      }
    }
  }
  // Exact per-collision check with σ̂ = x̂ (contact law and angular momentum).
  for (int d : {2, 3}) {
    RoughCollision c;
    c.w[0] = {0.3, -0.7, d == 3 ? 0.2 : 0.0};
    c.w[1] = {-0.5, 0.4, d == 3 ? -0.1 : 0.0};
    c.w[2] = {d == 3 ? 0.6 : 0.0, d == 3 ? -0.2 : 0.0, 0.9};
    c.w[3] = {d == 3 ? -0.3 : 0.0, d == 3 ? 0.5 : 0.0, -0.4};
    const gkt::test::Vec3 sigma{1, 0, 0};
    const double alpha = 0.7, beta = 0.3, kappa = 0.4;
    gkt::test::apply_rough_rule(c, sigma, alpha, beta, kappa);
    auto contact = [&](int pre) {  // g_c = v1 − v2 + (w1 + w2) × σ̂
      const int o = pre ? 0 : 4;
      gkt::test::Vec3 ws{};
      for (int k = 0; k < 3; ++k) ws[k] = c.w[o + 2][k] + c.w[o + 3][k];
      const auto rim = gkt::test::cross(ws, sigma);
      gkt::test::Vec3 g{};
      for (int k = 0; k < 3; ++k) g[k] = c.w[o][k] - c.w[o + 1][k] + rim[k];
      return g;
    };
    const auto g = contact(1), gp = contact(0);
    EXPECT_NEAR(gp[0], -alpha * g[0], 1e-14);
    EXPECT_NEAR(gp[1], -beta * g[1], 1e-14);
    EXPECT_NEAR(gp[2], -beta * g[2], 1e-14);
    // Angular momentum about the midpoint: r1 = −σ̂/2, r2 = +σ̂/2 (units σ = 1, m = 1), spin
    // angular momentum I ω = (κ/4)·2w = (κ/2) w.
    for (int k = 0; k < 3; ++k) {
      auto l = [&](int o) {
        const gkt::test::Vec3 r1{-0.5, 0, 0}, r2{0.5, 0, 0};
        return gkt::test::cross(r1, c.w[o])[k] + gkt::test::cross(r2, c.w[o + 1])[k] +
               0.5 * kappa * (c.w[o + 2][k] + c.w[o + 3][k]);
      };
      EXPECT_NEAR(l(4), l(0), 1e-14) << "d=" << d << " component " << k;
    }
  }
}

class RoughMomentsVsMonteCarlo : public ::testing::TestWithParam<RoughCase> {};

TEST_P(RoughMomentsVsMonteCarlo, MixedMomentsToDegreeFour) {
  const RoughCase k = GetParam();
  const auto params = gkt::rough_parameters(k.d, k.alpha, k.beta, k.kappa, k.theta);
  // Four forms touching every slot: v1'², w1'², v1·v2' + w1'·w2, w2'² − v2·v1.
  const std::vector<RoughForm> forms{
      rough_dot_form(RoughSlot::v1_post, RoughSlot::v1_post), rough_dot_form(RoughSlot::w1_post, RoughSlot::w1_post),
      rough_dot_form(RoughSlot::v1, RoughSlot::v2_post) + rough_dot_form(RoughSlot::w1_post, RoughSlot::w2),
      rough_dot_form(RoughSlot::w2_post, RoughSlot::w2_post) +
          gkt::scaled(rough_dot_form(RoughSlot::v2, RoughSlot::v1), Rational(-1))};
  const RoughCollisionMoments<Rational> engine(params, forms, {2, 2, 2, 1});
  using F = std::function<double(const RoughCollision&)>;
  const std::vector<F> mc_forms{
      [](const RoughCollision& c) { return mc_dot(c, RoughSlot::v1_post, RoughSlot::v1_post); },
      [](const RoughCollision& c) { return mc_dot(c, RoughSlot::w1_post, RoughSlot::w1_post); },
      [](const RoughCollision& c) {
        return mc_dot(c, RoughSlot::v1, RoughSlot::v2_post) + mc_dot(c, RoughSlot::w1_post, RoughSlot::w2);
      },
      [](const RoughCollision& c) {
        return mc_dot(c, RoughSlot::w2_post, RoughSlot::w2_post) - mc_dot(c, RoughSlot::v2, RoughSlot::v1);
      }};
  const std::vector<std::array<int, 4>> exponents{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1},
                                                  {1, 1, 0, 0}, {0, 2, 0, 0}, {2, 0, 0, 0}, {0, 0, 2, 0},
                                                  {1, 0, 1, 1}, {0, 1, 1, 1}, {1, 1, 1, 0}};
  gkt::test::RoughCollisionSampler sampler(k.d, k.alpha.to_double(), k.beta.to_double(), k.kappa.to_double(),
                                           k.theta.to_double(), 20261201);
  const long samples = 300000;
  gkt::test::RatioAverages acc(exponents.size());
  for (long s = 0; s < samples; ++s) {
    const RoughCollision c = sampler.draw();
    if (c.weight == 0) continue;
    acc.sample(c.weight);
    std::array<double, 4> values{};
    for (std::size_t v = 0; v < 4; ++v) values[v] = mc_forms[v](c);
    for (std::size_t e = 0; e < exponents.size(); ++e) {
      double h = 1;
      for (std::size_t v = 0; v < 4; ++v) h *= std::pow(values[v], exponents[e][v]);
      acc.add(e, c.weight, h);
    }
  }
  for (std::size_t e = 0; e < exponents.size(); ++e) {
    const auto [mean, error] = acc.estimate(e);
    const double exact = engine.moment(exponents[e]).to_double();
    // 5 standard errors: a correct engine fails this with probability < 1e-6 per moment.
    EXPECT_NEAR(exact, mean, 5 * error) << "moment " << e;
    EXPECT_LT(error, 0.04 * (std::abs(exact) + 1)) << "Monte Carlo too noisy to discriminate, moment " << e;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, RoughMomentsVsMonteCarlo,
    ::testing::Values(RoughCase{3, Rational(7, 10), Rational(2, 5), Rational(2, 5), Rational(3, 2)},
                      RoughCase{3, Rational(1), Rational(1), Rational(1, 4), Rational(1, 2)},
                      RoughCase{2, Rational(3, 5), Rational(-3, 10), Rational(1, 2), Rational(1, 2)},
                      RoughCase{2, Rational(9, 10), Rational(4, 5), Rational(1), Rational(2)}),
    [](const auto& info) { return std::to_string(info.index); });

// At β = −1 the spin decouples: moments of translational forms are the smooth engine's, exactly,
// and the spin is unchanged by the collision.
TEST(RoughCollisionMoments, SmoothLimitIsTheSmoothEngine) {
  for (int d : {2, 3}) {
    const Rational alpha(3, 5);
    const auto params = gkt::rough_parameters(d, alpha, Rational(-1), Rational(2, 5), Rational(7, 3));
    const std::vector<RoughForm> forms{rough_dot_form(RoughSlot::v1_post, RoughSlot::v1_post),
                                       rough_dot_form(RoughSlot::v1, RoughSlot::v2_post),
                                       rough_dot_form(RoughSlot::v2, RoughSlot::v2),
                                       rough_dot_form(RoughSlot::w1_post, RoughSlot::w1_post) +
                                           gkt::scaled(rough_dot_form(RoughSlot::w1, RoughSlot::w1), Rational(-1))};
    const RoughCollisionMoments<Rational> rough(params, forms, {3, 2, 2, 2});
    gkt::CollisionPair pair;
    pair.dimension = d;
    const std::vector<gkt::VelocityForm> smooth_forms{
        gkt::dot_form(gkt::slot_vector(gkt::Slot::v1_post), gkt::slot_vector(gkt::Slot::v1_post)),
        gkt::dot_form(gkt::slot_vector(gkt::Slot::v1), gkt::slot_vector(gkt::Slot::v2_post)),
        gkt::dot_form(gkt::slot_vector(gkt::Slot::v2), gkt::slot_vector(gkt::Slot::v2))};
    const gkt::QuadraticFormMoments<Rational> smooth(pair, alpha, smooth_forms, {3, 2, 2});
    for (int a = 0; a <= 3; ++a)
      for (int b = 0; b <= 2; ++b)
        for (int c = 0; c <= 2; ++c) {
          EXPECT_EQ(rough.moment({a, b, c, 0}), smooth.moment({a, b, c, 0})) << d << a << b << c;
          EXPECT_TRUE(rough.moment({a, b, c, 1}).is_zero());
          EXPECT_TRUE(rough.moment({a, b, c, 2}).is_zero());
        }
  }
}

namespace {

/// The translational and rotational energy forms of particle 1 and the total, in units where
/// E = v1² + v2² + κ(w1² + w2²): ΔE_t1 = v1'² − v1², ΔE_r1 = w1'² − w1², ΔE.
std::vector<RoughForm> energy_change_forms(const Rational& kappa) {
  const RoughForm dv1 = rough_dot_form(RoughSlot::v1_post, RoughSlot::v1_post) +
                        gkt::scaled(rough_dot_form(RoughSlot::v1, RoughSlot::v1), Rational(-1));
  const RoughForm dw1 = rough_dot_form(RoughSlot::w1_post, RoughSlot::w1_post) +
                        gkt::scaled(rough_dot_form(RoughSlot::w1, RoughSlot::w1), Rational(-1));
  const RoughForm dv2 = rough_dot_form(RoughSlot::v2_post, RoughSlot::v2_post) +
                        gkt::scaled(rough_dot_form(RoughSlot::v2, RoughSlot::v2), Rational(-1));
  const RoughForm dw2 = rough_dot_form(RoughSlot::w2_post, RoughSlot::w2_post) +
                        gkt::scaled(rough_dot_form(RoughSlot::w2, RoughSlot::w2), Rational(-1));
  return {dv1, dw1, dv1 + dv2 + gkt::scaled(dw1 + dw2, kappa)};
}

}  // namespace

// Hand-derived (theory.md (19.6)–(19.8)), with η_n = (1+α)/2, η_t = (1+β)κ/(2(1+κ)), τ = θ/κ:
//   ⟨ΔE⟩    = −(1 − α²) − ½ (1 − β²) (κ/(1+κ)) (d−1)(1 + τ),
//   ⟨Δv1²⟩  = −2η_n(1−η_n) − (d−1) η_t (1 − η_t) + (d−1) η_t² τ,
//   ⟨Δw1²⟩  = (d−1)(η_t/κ) [−τ + (η_t/κ)(1 + τ)].
TEST(RoughCollisionMoments, EnergyChangePerCollisionClosedForms) {
  for (int d : {2, 3})
    for (const auto& [alpha, beta, kappa, theta] :
         {std::array<Rational, 4>{Rational(7, 10), Rational(2, 5), Rational(2, 5), Rational(3, 2)},
          std::array<Rational, 4>{Rational(1, 5), Rational(-4, 5), Rational(1), Rational(1, 3)},
          std::array<Rational, 4>{Rational(1), Rational(1), Rational(1, 2), Rational(1)}}) {
      const RoughCollisionMoments<Rational> m(gkt::rough_parameters(d, alpha, beta, kappa, theta),
                                              energy_change_forms(kappa), {1, 1, 1});
      const Rational one(1), tau = theta / kappa, dm1(d - 1);
      const Rational en = (one + alpha) / Rational(2), et = (one + beta) * kappa / (Rational(2) * (one + kappa));
      EXPECT_EQ(m.moment({0, 0, 1, 0}),
                -(one - alpha * alpha) - (one - beta * beta) * kappa / (one + kappa) * dm1 * (one + tau) / Rational(2));
      EXPECT_EQ(m.moment({1, 0, 0, 0}), -Rational(2) * en * (one - en) - dm1 * et * (one - et) + dm1 * et * et * tau);
      EXPECT_EQ(m.moment({0, 1, 0, 0}), dm1 * (et / kappa) * (-tau + (et / kappa) * (one + tau)));
    }
}

// θ symbolic (ring variable λ = √(θ/κ)): the energy change is 1 − α² plus a polynomial in λ²,
// and evaluating any symbolic moment at λ² = θ/κ reproduces the numeric engine.
TEST(RoughCollisionMoments, SymbolicTemperatureRatio) {
  const Rational alpha(4, 5), beta(1, 2), kappa(2, 5);
  for (int d : {2, 3}) {
    const auto forms = energy_change_forms(kappa);
    const RoughCollisionMoments<RationalPolynomial> symbolic(
        gkt::rough_parameters_symbolic_temperature(d, alpha, beta, kappa), forms, {2, 2, 1});
    const Rational one(1);
    RationalPolynomial expected = RationalPolynomial::variable();
    expected *= RationalPolynomial::variable();
    expected += RationalPolynomial(one);
    expected *= -(one - beta * beta) * kappa / (one + kappa) * Rational(d - 1) / Rational(2);
    expected -= RationalPolynomial(one - alpha * alpha);
    EXPECT_EQ(symbolic.moment({0, 0, 1, 0}), expected);
    for (const Rational& theta : {Rational(1, 3), Rational(5, 4)}) {
      const RoughCollisionMoments<Rational> numeric(gkt::rough_parameters(d, alpha, beta, kappa, theta), forms,
                                                    {2, 2, 1});
      // λ = √(θ/κ) is irrational in general; the moments are even in λ: evaluate at ±√ via λ² only.
      for (const auto& k : {std::array<int, 4>{2, 0, 0, 0}, {1, 1, 0, 0}, {0, 2, 1, 0}, {2, 2, 1, 0}}) {
        const RationalPolynomial p = symbolic.moment(k);
        Rational value(0), power(1);
        for (long j = 0; j <= p.degree(); ++j) {
          if (j % 2 == 1) {
            EXPECT_TRUE(p.coefficient(j).is_zero()) << "odd power of lambda";
            continue;
          }
          value += p.coefficient(j) * power;
          power *= theta / kappa;
        }
        EXPECT_EQ(value, numeric.moment(k)) << "d=" << d << " theta=" << theta;
      }
    }
  }
}

TEST(RoughCollisionMoments, RejectsBadParametersAndMixedForms) {
  EXPECT_THROW(gkt::rough_parameters(3, Rational(1, 2), Rational(3, 2), Rational(2, 5), Rational(1)),
               std::invalid_argument);
  EXPECT_THROW(gkt::rough_parameters(3, Rational(1, 2), Rational(0), Rational(0), Rational(1)), std::invalid_argument);
  EXPECT_THROW(gkt::rough_parameters(3, Rational(0), Rational(0), Rational(2, 5), Rational(1)), std::invalid_argument);
  EXPECT_THROW(gkt::rough_parameters(4, Rational(1), Rational(0), Rational(2, 5), Rational(1)), std::invalid_argument);
  EXPECT_THROW(gkt::rough_parameters(3, Rational(1), Rational(0), Rational(2, 5), Rational(0)), std::invalid_argument);
  const auto p = gkt::rough_parameters(3, Rational(1), Rational(0), Rational(2, 5), Rational(1));
  const auto disks = gkt::rough_parameters(2, Rational(1), Rational(0), Rational(1, 2), Rational(1));
  EXPECT_THROW(RoughCollisionMoments<Rational>(disks, {rough_dot_form(RoughSlot::v1, RoughSlot::w1)}, {1}),
               std::invalid_argument);
  (void)p;
}

// Forms coupling v and w (3D): the normal block couples, the tangential block becomes Hermitian
// (theory.md (19.5a)). Moments of (v1·w1)², (v1'·w1')², (v1'·w2)(v2·w1'), … against Monte Carlo.
TEST(RoughCollisionMoments, TranslationSpinCouplingAgainstMonteCarlo) {
  const Rational alpha(7, 10), beta(1, 2), kappa(2, 5), theta(3, 2);
  const auto params = gkt::rough_parameters(3, alpha, beta, kappa, theta);
  const std::vector<RoughForm> forms{
      rough_dot_form(RoughSlot::v1_post, RoughSlot::w1_post), rough_dot_form(RoughSlot::v1, RoughSlot::w1),
      rough_dot_form(RoughSlot::v1_post, RoughSlot::v1_post),
      rough_dot_form(RoughSlot::v2, RoughSlot::w1_post) + rough_dot_form(RoughSlot::w2_post, RoughSlot::w2_post)};
  const RoughCollisionMoments<Rational> engine(params, forms, {2, 2, 1, 2});
  const std::vector<std::array<int, 4>> exponents{{1, 0, 0, 0}, {2, 0, 0, 0}, {0, 2, 0, 0}, {1, 1, 0, 0}, {2, 0, 1, 0},
                                                  {0, 0, 0, 1}, {1, 0, 0, 1}, {0, 0, 0, 2}, {2, 2, 0, 0}, {0, 1, 0, 1}};
  gkt::test::RoughCollisionSampler sampler(3, 0.7, 0.5, 0.4, 1.5, 4242);
  const long samples = 300000;
  gkt::test::RatioAverages acc(exponents.size());
  for (long s = 0; s < samples; ++s) {
    const RoughCollision c = sampler.draw();
    if (c.weight == 0) continue;
    acc.sample(c.weight);
    const std::array<double, 4> values{
        mc_dot(c, RoughSlot::v1_post, RoughSlot::w1_post), mc_dot(c, RoughSlot::v1, RoughSlot::w1),
        mc_dot(c, RoughSlot::v1_post, RoughSlot::v1_post),
        mc_dot(c, RoughSlot::v2, RoughSlot::w1_post) + mc_dot(c, RoughSlot::w2_post, RoughSlot::w2_post)};
    for (std::size_t e = 0; e < exponents.size(); ++e) {
      double h = 1;
      for (std::size_t v = 0; v < 4; ++v) h *= std::pow(values[v], exponents[e][v]);
      acc.add(e, c.weight, h);
    }
  }
  for (std::size_t e = 0; e < exponents.size(); ++e) {
    const auto [mean, error] = acc.estimate(e);
    const double exact = engine.moment(exponents[e]).to_double();
    EXPECT_NEAR(exact, mean, 5 * error) << "moment " << e;
    EXPECT_LT(error, 0.04 * (std::abs(exact) + 1)) << "moment " << e;
  }
}

namespace {

/// The six forms of the nonlinear HCS balances (theory.md §19.12): c1², ŵ1², c2², ŵ2², c1'², ŵ1'².
std::vector<RoughForm> six_energy_forms() {
  return {
      rough_dot_form(RoughSlot::v1, RoughSlot::v1),           rough_dot_form(RoughSlot::w1, RoughSlot::w1),
      rough_dot_form(RoughSlot::v2, RoughSlot::v2),           rough_dot_form(RoughSlot::w2, RoughSlot::w2),
      rough_dot_form(RoughSlot::v1_post, RoughSlot::v1_post), rough_dot_form(RoughSlot::w1_post, RoughSlot::w1_post)};
}

}  // namespace

// More than four forms (the recurrence in eight variables): a six-form table must contain the
// lower tables exactly — forms at power 0 drop out, a form that is the sum of two others expands
// binomially, and the order of the forms does not matter (the box is walked as an odometer).
TEST(RoughCollisionMoments, SixFormsContainTheLowerTables) {
  for (int d : {2, 3}) {
    const auto params = gkt::rough_parameters(d, Rational(7, 10), Rational(1, 2), Rational(2, 5), Rational(6, 5));
    const auto f = six_energy_forms();
    const RoughCollisionMoments<Rational> six(params, f, {2, 1, 1, 1, 2, 1});
    // Power 0: the four-form table of (c1², ŵ1², c1'², ŵ1'²) and the two-form table of (c2², ŵ2²).
    const RoughCollisionMoments<Rational> four(params, {f[0], f[1], f[4], f[5]}, {2, 1, 2, 1});
    const RoughCollisionMoments<Rational> two(params, {f[2], f[3]}, {1, 1});
    for (int a = 0; a <= 2; ++a)
      for (int b = 0; b <= 1; ++b)
        for (int c = 0; c <= 2; ++c)
          for (int e = 0; e <= 1; ++e) EXPECT_EQ(six.moment({a, b, 0, 0, c, e}), four.moment({a, b, c, e}));
    for (int a = 0; a <= 1; ++a)
      for (int b = 0; b <= 1; ++b) EXPECT_EQ(six.moment({0, 0, a, b, 0, 0}), two.moment({a, b}));
    // Reversed order of the forms: the same moments at reversed exponents.
    const std::vector<RoughForm> reversed(f.rbegin(), f.rend());
    const RoughCollisionMoments<Rational> backwards(params, reversed, {1, 2, 1, 1, 1, 2});
    for (int a = 0; a <= 2; ++a)
      for (int b = 0; b <= 1; ++b)
        for (int c = 0; c <= 1; ++c)
          for (int g = 0; g <= 2; ++g)
            EXPECT_EQ(six.moment({a, b, c, 1, g, 1}), backwards.moment({1, g, 1, c, b, a})) << a << b << c << g;
    // A sixth form that is the sum of two others: ⟨(c1² + ŵ1'²) M⟩ = ⟨c1² M⟩ + ⟨ŵ1'² M⟩, and the
    // seventh and eighth variables (ΔE-like differences) in the same table.
    const std::vector<RoughForm> eight{f[0], f[1], f[2],        f[3],
                                       f[4], f[5], f[0] + f[5], f[4] + gkt::scaled(f[0], Rational(-1))};
    const RoughCollisionMoments<Rational> sums(params, eight, {1, 1, 1, 1, 1, 1, 1, 1});
    for (int b = 0; b <= 1; ++b)
      for (int c = 0; c <= 1; ++c) {
        EXPECT_EQ(sums.moment({0, b, c, 1, 0, 0, 1, 0}),
                  sums.moment({1, b, c, 1, 0, 0, 0, 0}) + sums.moment({0, b, c, 1, 0, 1, 0, 0}));
        EXPECT_EQ(sums.moment({0, b, c, 0, 0, 0, 0, 1}),
                  sums.moment({0, b, c, 0, 1, 0, 0, 0}) - sums.moment({1, b, c, 0, 0, 0, 0, 0}));
        EXPECT_EQ(sums.moment({0, b, c, 0, 0, 0, 1, 1}),
                  sums.moment({1, b, c, 0, 1, 0, 0, 0}) - six.moment({2, b, c, 0, 0, 0}) +
                      sums.moment({0, b, c, 0, 1, 1, 0, 0}) - sums.moment({1, b, c, 0, 0, 1, 0, 0}));
      }
    EXPECT_THROW(RoughCollisionMoments<Rational>(params, std::vector<RoughForm>(10, f[0]), std::vector<int>(10, 1)),
                 std::invalid_argument);  // nine forms at most (kMaxRoughForms)
  }
}

// One six-form moment family, ⟨c1² ŵ1² c2² ŵ2² c1'² ŵ1'²⟩ and two of its faces, against Monte Carlo.
TEST(RoughCollisionMoments, SixFormMomentsAgainstMonteCarlo) {
  const int d = 3;
  const double alpha = 0.7, beta = 0.5, kappa = 0.4, theta = 1.2;
  const auto params = gkt::rough_parameters(d, Rational(7, 10), Rational(1, 2), Rational(2, 5), Rational(6, 5));
  const RoughCollisionMoments<Rational> engine(params, six_energy_forms(), {1, 1, 1, 1, 1, 1});
  const std::vector<std::array<int, 6>> exponents{{1, 1, 1, 1, 1, 1}, {1, 0, 1, 0, 1, 1}, {0, 1, 0, 1, 1, 1}};
  const std::array<std::array<RoughSlot, 2>, 6> slots{{{RoughSlot::v1, RoughSlot::v1},
                                                       {RoughSlot::w1, RoughSlot::w1},
                                                       {RoughSlot::v2, RoughSlot::v2},
                                                       {RoughSlot::w2, RoughSlot::w2},
                                                       {RoughSlot::v1_post, RoughSlot::v1_post},
                                                       {RoughSlot::w1_post, RoughSlot::w1_post}}};
  gkt::test::RoughCollisionSampler sampler(d, alpha, beta, kappa, theta, 20261202);
  const long samples = 400000;
  gkt::test::RatioAverages acc(exponents.size());
  for (long s = 0; s < samples; ++s) {
    const RoughCollision c = sampler.draw();
    if (c.weight == 0) continue;
    acc.sample(c.weight);
    std::array<double, 6> values{};
    for (std::size_t v = 0; v < 6; ++v) values[v] = mc_dot(c, slots[v][0], slots[v][1]);
    for (std::size_t e = 0; e < exponents.size(); ++e) {
      double h = 1;
      for (std::size_t v = 0; v < 6; ++v)
        if (exponents[e][v] == 1) h *= values[v];
      acc.add(e, c.weight, h);
    }
  }
  for (std::size_t e = 0; e < exponents.size(); ++e) {
    const auto [mean, error] = acc.estimate(e);
    const double exact = engine.moment(exponents[e]).to_double();
    EXPECT_NEAR(exact, mean, 5 * error) << "moment " << e;
    EXPECT_LT(error, 0.1 * std::abs(exact)) << "Monte Carlo too noisy to discriminate, moment " << e;
  }
}

// A down-closed kept set (caps on the total degree per particle): the kept moments equal the full
// table's, exactly; the others are refused.
TEST(RoughCollisionMoments, KeptSetEqualsTheFullTable) {
  const auto params = gkt::rough_parameters(3, Rational(4, 5), Rational(1, 2), Rational(2, 5), Rational(3, 2));
  const auto f = six_energy_forms();
  const std::vector<int> degrees{2, 2, 1, 1, 2, 2};
  const RoughCollisionMoments<Rational> full(params, f, degrees);
  auto keep = [](const gkt::RoughExponents& e) { return e[0] + e[1] <= 2 && e[2] + e[3] <= 1 && e[4] + e[5] <= 2; };
  const RoughCollisionMoments<Rational> kept(params, f, degrees, keep);
  int compared = 0;
  for (int a = 0; a <= 2; ++a)
    for (int b = 0; b <= 2; ++b)
      for (int c = 0; c <= 1; ++c)
        for (int e = 0; e <= 1; ++e)
          for (int g = 0; g <= 2; ++g)
            for (int h = 0; h <= 2; ++h) {
              const gkt::RoughExponents k{a, b, c, e, g, h};
              if (keep(k)) {
                EXPECT_EQ(kept.moment(k), full.moment(k));
                ++compared;
              } else {
                EXPECT_THROW((void)kept.moment(k), std::out_of_range);
              }
            }
  EXPECT_EQ(compared, 6 * 3 * 6);
}
