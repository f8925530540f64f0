// Collision moments with one triple product (theory.md §19.22, (19.90)–(19.92)): exact identities of the
// rule (momentum, the common torque), the antisymmetry of the triple product under a swap (a different split into
// symmetric and rotation terms), and Monte Carlo over collisions applied in vector form (rough_monte_carlo.hpp).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "gkt/collision/rough_collision_moments.hpp"
#include "gkt/collision/rough_collision_rule.hpp"
#include "gkt/collision/rough_triple_product_moments.hpp"
#include "rough_monte_carlo.hpp"

namespace {

using gkt::Rational;
using gkt::RoughForm;
using gkt::RoughSlot;
using gkt::RoughTripleProduct;
using gkt::RoughTripleProductMoments;
using gkt::test::RoughCollision;

const gkt::test::Vec3& vec(const RoughCollision& c, RoughSlot a) { return c.w[static_cast<std::size_t>(a)]; }
double mc_dot(const RoughCollision& c, RoughSlot a, RoughSlot b) { return gkt::test::dot3(vec(c, a), vec(c, b)); }
double mc_triple(const RoughCollision& c, const RoughTripleProduct& t) {
  return gkt::test::dot3(vec(c, t[0]), gkt::test::cross(vec(c, t[1]), vec(c, t[2])));
}

/// Forms c1², ŵ1'², c1·c2', w1·w1' (all dot products of the slots, scaled spins as the sampler's w).
std::vector<RoughForm> test_forms() {
  return {
      gkt::rough_dot_form(RoughSlot::v1, RoughSlot::v1), gkt::rough_dot_form(RoughSlot::w1_post, RoughSlot::w1_post),
      gkt::rough_dot_form(RoughSlot::v1, RoughSlot::v2_post), gkt::rough_dot_form(RoughSlot::w1, RoughSlot::w1_post)};
}

std::vector<RoughTripleProduct> triples(int d) {
  if (d == 2)
    return {{RoughSlot::w1, RoughSlot::v1, RoughSlot::v1_post},
            {RoughSlot::v1, RoughSlot::w1_post, RoughSlot::v2},
            {RoughSlot::v2_post, RoughSlot::v1, RoughSlot::w2},
            {RoughSlot::w1_post, RoughSlot::v1_post, RoughSlot::v2}};
  // One spin each (true scalars), and three polar vectors (a pseudoscalar: exactly 0 by parity).
  return {
      {RoughSlot::v1_post, RoughSlot::v1, RoughSlot::w1},      {RoughSlot::v2, RoughSlot::v1_post, RoughSlot::w1_post},
      {RoughSlot::w1_post, RoughSlot::v1, RoughSlot::v2_post}, {RoughSlot::v2_post, RoughSlot::w2, RoughSlot::v1},
      {RoughSlot::w2_post, RoughSlot::v1_post, RoughSlot::v2}, {RoughSlot::v1, RoughSlot::v2, RoughSlot::v1_post}};
}

}  // namespace

// Momentum v1' + v2' = v1 + v2 and the common torque w1' − w1 = w2' − w2 hold vector by vector, so the triple
// products built from them obey the same linear relations; a swap of two slots reverses the sign. Each side is
// split differently into normal × (symmetric or rotation) terms, so these fail for a wrong sign in (19.90).
TEST(RoughTripleProductMoments, ConservationAndAntisymmetryExact) {
  for (int d : {2, 3}) {
    const auto params = gkt::rough_parameters(d, Rational(7, 10), Rational(3, 10), Rational(2, 5), Rational(13, 10));
    const auto forms = test_forms();
    const std::vector<int> degrees{1, 1, 1, 1};
    const auto m = [&](RoughSlot a, RoughSlot b, RoughSlot c, const std::array<int, 4>& k) {
      return RoughTripleProductMoments<Rational>(params, {a, b, c}, forms, degrees).moment(k);
    };
    for (const std::array<int, 4> k : {std::array<int, 4>{0, 0, 0, 0}, {1, 0, 0, 0}, {0, 1, 1, 0}, {1, 1, 1, 1}}) {
      // momentum: T(v1', w1, v2) + T(v2', w1, v2) = T(v1, w1, v2) + T(v2, w1, v2) (the last is 0).
      EXPECT_EQ(m(RoughSlot::v1_post, RoughSlot::w1, RoughSlot::v2, k) +
                    m(RoughSlot::v2_post, RoughSlot::w1, RoughSlot::v2, k),
                m(RoughSlot::v1, RoughSlot::w1, RoughSlot::v2, k));
      // swap: T(v1', w1, v2) = −T(w1, v1', v2) = T(w1, v2, v1').
      EXPECT_EQ(m(RoughSlot::v1_post, RoughSlot::w1, RoughSlot::v2, k),
                -m(RoughSlot::w1, RoughSlot::v1_post, RoughSlot::v2, k));
      EXPECT_EQ(m(RoughSlot::v1_post, RoughSlot::w1, RoughSlot::v2, k),
                m(RoughSlot::w1, RoughSlot::v2, RoughSlot::v1_post, k));
      if (d == 3) {
        // torque: T(w1' − w1, v1, v2') = T(w2' − w2, v1, v2').
        EXPECT_EQ(m(RoughSlot::w1_post, RoughSlot::v1, RoughSlot::v2_post, k) -
                      m(RoughSlot::w1, RoughSlot::v1, RoughSlot::v2_post, k),
                  m(RoughSlot::w2_post, RoughSlot::v1, RoughSlot::v2_post, k) -
                      m(RoughSlot::w2, RoughSlot::v1, RoughSlot::v2_post, k));
        EXPECT_EQ(m(RoughSlot::v1, RoughSlot::w1_post, RoughSlot::w2, k),
                  -m(RoughSlot::w2, RoughSlot::w1_post, RoughSlot::v1, k));
      } else {
        // momentum with the spin first.
        EXPECT_EQ(m(RoughSlot::w1_post, RoughSlot::v1_post, RoughSlot::v1, k) +
                      m(RoughSlot::w1_post, RoughSlot::v2_post, RoughSlot::v1, k),
                  m(RoughSlot::w1_post, RoughSlot::v1, RoughSlot::v1, k) +
                      m(RoughSlot::w1_post, RoughSlot::v2, RoughSlot::v1, k));
      }
    }
  }
}

// Monte Carlo (4 × 10⁵ collisions, vector form): every triple product times up to two forms, within 5σ.
TEST(RoughTripleProductMoments, AgainstMonteCarlo) {
  struct Case {
    int d;
    double alpha, beta, kappa, theta;
    Rational a, b, k, t;
  };
  const std::vector<Case> cases{
      {3, 0.7, 0.3, 0.4, 1.3, Rational(7, 10), Rational(3, 10), Rational(2, 5), Rational(13, 10)},
      {2, 0.6, -0.3, 0.5, 0.5, Rational(3, 5), Rational(-3, 10), Rational(1, 2), Rational(1, 2)}};
  const std::vector<std::array<int, 4>> exponents{{0, 0, 0, 0}, {1, 0, 0, 0}, {0, 1, 0, 0},
                                                  {0, 0, 1, 0}, {0, 0, 0, 1}, {1, 1, 0, 0}};
  for (const Case& cs : cases) {
    const auto params = gkt::rough_parameters(cs.d, cs.a, cs.b, cs.k, cs.t);
    const auto forms = test_forms();
    const auto tri = triples(cs.d);
    std::vector<std::vector<double>> exact;
    for (const auto& t : tri) {
      const RoughTripleProductMoments<Rational> engine(params, t, forms, {1, 1, 1, 1});
      std::vector<double> row;
      for (const auto& e : exponents) row.push_back(engine.moment(e).to_double() * std::sqrt(std::numbers::pi / 2));
      exact.push_back(row);
    }
    gkt::test::RoughCollisionSampler sampler(cs.d, cs.alpha, cs.beta, cs.kappa, cs.theta, 9191 + cs.d);
    const long samples = 400000;
    const std::size_t n = tri.size() * exponents.size();
    gkt::test::RatioAverages acc(n);
    for (long s = 0; s < samples; ++s) {
      const RoughCollision c = sampler.draw();
      if (c.weight == 0) continue;
      acc.sample(c.weight);
      const std::array<double, 4> values{
          mc_dot(c, RoughSlot::v1, RoughSlot::v1), mc_dot(c, RoughSlot::w1_post, RoughSlot::w1_post),
          mc_dot(c, RoughSlot::v1, RoughSlot::v2_post), mc_dot(c, RoughSlot::w1, RoughSlot::w1_post)};
      for (std::size_t t = 0; t < tri.size(); ++t) {
        const double tp = mc_triple(c, tri[t]);
        for (std::size_t e = 0; e < exponents.size(); ++e) {
          double h = tp;
          for (std::size_t v = 0; v < 4; ++v) h *= std::pow(values[v], exponents[e][v]);
          acc.add(t * exponents.size() + e, c.weight, h);
        }
      }
    }
    int nonzero = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const auto [mean, error] = acc.estimate(i);
      const double value = exact[i / exponents.size()][i % exponents.size()];
      EXPECT_NEAR(value, mean, 5 * error)
          << "d " << cs.d << " triple " << i / exponents.size() << " moment " << i % exponents.size();
      if (std::abs(value) > 10 * error) ++nonzero;
      if (cs.d == 3 && i / exponents.size() == 5) {
        EXPECT_EQ(value, 0.0);  // pseudoscalar
      }
    }
    EXPECT_GE(nonzero, static_cast<int>(n / 2)) << "d " << cs.d;  // the comparison is not between zeros
  }
}

TEST(RoughTripleProductMoments, RefusesBadInput) {
  const auto disks = gkt::rough_parameters(2, Rational(1), Rational(1), Rational(1, 2), Rational(1));
  EXPECT_THROW(RoughTripleProductMoments<Rational>(disks, {RoughSlot::v1, RoughSlot::v2, RoughSlot::v1_post}, {}, {}),
               std::invalid_argument);
  EXPECT_THROW(RoughTripleProductMoments<Rational>(disks, {RoughSlot::w1, RoughSlot::w2, RoughSlot::v1}, {}, {}),
               std::invalid_argument);
  const auto spheres = gkt::rough_parameters(3, Rational(1), Rational(1), Rational(2, 5), Rational(1));
  EXPECT_THROW(RoughTripleProductMoments<Rational>(spheres, {RoughSlot::v1, RoughSlot::v2, RoughSlot::w1},
                                                   std::vector<RoughForm>(8), std::vector<int>(8, 1)),
               std::invalid_argument);
}
