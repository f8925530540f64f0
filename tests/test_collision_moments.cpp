// Sonine collision moments M(p, q) = ⟨ψ_q(unknown)·ψ_p(test)⟩/J0 from the exact engine against
// direct Monte Carlo integration of the collision integral (independent: samples velocities,
// applies the collision rule, evaluates Sonine polynomials by recurrence). Cases required by
// issue 3: equal masses elastic; mass ratio 1:7 with unequal temperatures; α = 0.6; d = 2.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>
#include <tuple>

#include "gkt/algebra/sonine.hpp"
#include "gkt/collision/collision_moments.hpp"
#include "gkt/collision/gaussian_collision_integral.hpp"
#include "gkt/operators/linearized_operator.hpp"
#include "monte_carlo.hpp"

using gkt::Rational;
using gkt::Slot;
using gkt::test::Collision;
using gkt::test::dot;

namespace {

struct Case {
  std::string label;
  int d;
  long mi, mj;
  Rational theta_i, theta_j, alpha;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.label; }

const gkt::test::Vec& velocity(const Collision& c, Slot s) {
  switch (s) {
    case Slot::v1:
      return c.v1;
    case Slot::v2:
      return c.v2;
    case Slot::v1_post:
      return c.v1p;
    case Slot::v2_post:
      return c.v2p;
  }
  return c.v1;
}

/// ψ_q(u_a)·ψ_p(u_b) with tensor indices contracted, evaluated directly.
double basis_product(const Collision& c, const Case& k, Slot a, Slot b, int rank, int p, int q) {
  const double ta = (gkt::slot_species(a) == 0 ? k.theta_i : k.theta_j).to_double();
  const double tb = (gkt::slot_species(b) == 0 ? k.theta_i : k.theta_j).to_double();
  const auto& ua = velocity(c, a);
  const auto& ub = velocity(c, b);
  const double xa = ta * dot(ua, ua, k.d), xb = tb * dot(ub, ub, k.d);
  const double cab = std::sqrt(ta * tb) * dot(ua, ub, k.d);
  const long twice_m = gkt::sonine_twice_m(k.d, rank);
  const double sonine = gkt::sonine_value(twice_m, q, xa) * gkt::sonine_value(twice_m, p, xb);
  const double tensor = rank == 0 ? 1.0 : rank == 1 ? cab : cab * cab - xa * xb / k.d;
  return sonine * tensor;
}

}  // namespace

class MomentsVsMonteCarlo : public ::testing::TestWithParam<Case> {};

TEST_P(MomentsVsMonteCarlo, LowOrders) {
  const Case k = GetParam();
  const gkt::CollisionPair pair{k.d, Rational(k.mi), Rational(k.mj), k.theta_i, k.theta_j};
  const int n_max = 2;
  const std::pair<Slot, Slot> slot_pairs[] = {
      {Slot::v1, Slot::v1_post}, {Slot::v2, Slot::v1_post}, {Slot::v1, Slot::v2_post}, {Slot::v2, Slot::v1}};
  for (int rank = 0; rank <= 2; ++rank) {
    for (const auto& [a, b] : slot_pairs) {
      const auto exact = gkt::sonine_collision_moments<Rational>(pair, k.alpha, a, b, rank, n_max);
      std::vector<std::function<double(const Collision&)>> integrands;
      for (int p = 0; p <= n_max; ++p)
        for (int q = 0; q <= n_max; ++q)
          integrands.emplace_back([&, p, q](const Collision& c) { return basis_product(c, k, a, b, rank, p, q); });
      gkt::test::CollisionSampler sampler(k.d, static_cast<double>(k.mi), static_cast<double>(k.mj),
                                          k.theta_i.to_double(), k.theta_j.to_double(), k.alpha.to_double(),
                                          1000 + 10 * rank + static_cast<int>(a) * 3 + static_cast<int>(b));
      const auto mc = gkt::test::weighted_averages(sampler, 200000, integrands);
      std::size_t idx = 0;
      for (int p = 0; p <= n_max; ++p)
        for (int q = 0; q <= n_max; ++q, ++idx) {
          const double e = exact(p, q).to_double();
          // 5 standard errors plus a floor for entries that vanish identically.
          EXPECT_NEAR(e, mc[idx].mean, 5 * mc[idx].error + 1e-3)
              << k.label << " rank " << rank << " slots " << static_cast<int>(a) << "->" << static_cast<int>(b)
              << " p=" << p << " q=" << q << " exact=" << exact(p, q) << " mc=" << mc[idx].mean << "±" << mc[idx].error;
        }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, MomentsVsMonteCarlo,
    ::testing::Values(Case{"equal masses, elastic, d=3", 3, 1, 1, Rational(1), Rational(1), Rational(1)},
                      Case{"mass ratio 1:7, T_i != T_j, d=3", 3, 1, 7, Rational(1), Rational(4), Rational(1)},
                      Case{"alpha=0.6, d=3", 3, 1, 1, Rational(1), Rational(1), Rational(3, 5)},
                      Case{"d=2, alpha=0.6, mass ratio 1:3, T_i != T_j", 2, 1, 3, Rational(1), Rational(1, 4),
                           Rational(3, 5)}),
    [](const auto& info) { return std::to_string(info.index); });

// J0 = K_d √(θ_i+θ_j) (θ_iθ_j)^{−(d+1)/2}, checked against the general closed form at the
// reference quadratic form.
TEST(ReferenceCollisionIntegral, MatchesClosedForm) {
  for (int d : {2, 3}) {
    const gkt::CollisionPair pair{d, Rational(1), Rational(7), Rational(3, 2), Rational(5, 4)};
    gkt::QuadraticForm q{};
    q[0][0] = 1.5;
    q[1][1] = 1.25;
    EXPECT_NEAR(gkt::reference_collision_integral(pair) / gkt::gaussian_collision_integral(d, 1, 7, 0.3, q), 1.0,
                1e-14);
  }
}

// Symbolic α (Q[α]) evaluated at α = 3/5 equals the numeric-α computation exactly.
TEST(CollisionMoments, SymbolicAlphaAgreesWithNumeric) {
  const gkt::CollisionPair pair{3, Rational(1), Rational(3), Rational(1), Rational(1, 4)};
  const auto alpha = gkt::RationalPolynomial::variable();
  for (int rank = 0; rank <= 2; ++rank) {
    const auto symbolic =
        gkt::sonine_collision_moments<gkt::RationalPolynomial>(pair, alpha, Slot::v2, Slot::v1_post, rank, 3);
    const auto numeric =
        gkt::sonine_collision_moments<Rational>(pair, Rational(3, 5), Slot::v2, Slot::v1_post, rank, 3);
    for (int p = 0; p <= 3; ++p)
      for (int q = 0; q <= 3; ++q) {
        EXPECT_EQ(symbolic(p, q).evaluate(Rational(3, 5)), numeric(p, q)) << rank << " " << p << " " << q;
        // Gain terms are polynomials in α of degree ≤ 2(p + rank) ... bounded by the test degree.
        EXPECT_LE(symbolic(p, q).degree(), 2 * (p + 1) + rank);
      }
  }
}

TEST(CollisionMoments, OddRankNeedsRationalGeometricMean) {
  const gkt::CollisionPair pair{3, Rational(1), Rational(1), Rational(1), Rational(2)};
  EXPECT_THROW((void)gkt::sonine_collision_moments<Rational>(pair, Rational(1), Slot::v1, Slot::v2_post, 1, 1),
               std::domain_error);
  EXPECT_NO_THROW((void)gkt::sonine_collision_moments<Rational>(pair, Rational(1), Slot::v1, Slot::v2_post, 2, 1));
}

// The operator about the HCS, L^(k) (partner weighted by S_k(c²)), by an identity that takes a
// different path through the engine: a Maxwellian of temperature τ is
// f_M Σ_k (1−τ)^k S_k(c²) (Sonine generating function), so Σ_k (1−τ)^k L^(k) must equal the
// operator whose partner is a Maxwellian at temperature τ — computed here directly from moment
// tables of a pair with unequal widths θ = 1/τ and no weight variable. τ = 16/25 (√θ = 5/4
// rational), α = 3/5, d = 2, 3, ranks 0–2, p, q ≤ 2; series to k = 30 (0.36^30 ≈ 5e-14).
TEST(HcsLinearizedOperator, WeightedOperatorEqualsHotterPartner) {
  const Rational alpha(3, 5), tau(16, 25), theta(25, 16);
  const int k_max = 30, n_max = 2;
  for (int d : {3, 2}) {
    for (int rank = 0; rank <= 2; ++rank) {
      const auto weighted = gkt::hcs_linearized_operator_matrices<Rational>(d, alpha, rank, n_max, k_max);
      const long twice_m = gkt::sonine_twice_m(d, rank);
      // One term: ⟨ψ_q(a)·ψ_p(b)⟩ for a pair whose partner of the unknown has width θ, with the basis
      // scaled at θ = 1 (x = u², c = u) — rescaled onto the table's X = θ_s u², c = √(θ_aθ_b) u.
      auto term = [&](const gkt::CollisionPair& pair, Slot a, Slot b, int p, int q) {
        const auto sq = gkt::sonine_coefficients(twice_m, q), sp = gkt::sonine_coefficients(twice_m, p);
        const Rational ta = pair.theta(a), tb = pair.theta(b);
        Rational sum;
        if (a == b) {
          const gkt::CollisionMomentTable<Rational> t(pair, alpha, {a}, {2 * n_max + rank}, std::nullopt, 0);
          const Rational yy = rank == 2 ? Rational(d - 1, static_cast<unsigned long>(d)) : Rational(1);
          for (int i = 0; i <= q; ++i)
            for (int j = 0; j <= p; ++j) sum += sq[i] * sp[j] * yy * t.moment({i + j + rank}) / ta.pow(i + j + rank);
          return sum;
        }
        const gkt::CollisionMomentTable<Rational> t(pair, alpha, {a, b}, {n_max + 1, n_max + 1}, std::make_pair(a, b),
                                                    rank);
        const Rational cscale = (ta * tb).exact_sqrt();  // c_table = √(θ_aθ_b) u_a·u_b
        for (int i = 0; i <= q; ++i)
          for (int j = 0; j <= p; ++j) {
            Rational y = t.moment({i, j}, rank) / (ta.pow(i) * tb.pow(j) * cscale.pow(rank));
            if (rank == 2) y -= t.moment({i + 1, j + 1}, 0) / (ta.pow(i + 1) * tb.pow(j + 1) * Rational(d));
            sum += sq[i] * sp[j] * y;
          }
        return sum;
      };
      // Unknown at v1 with a hot partner at v2; unknown at v2 (θ = 1) with the hot particle at v1
      // carrying the test function (basis at θ = 1 there too).
      const gkt::CollisionPair hot_partner{d, Rational(1), Rational(1), Rational(1), theta};
      const gkt::CollisionPair hot_tested{d, Rational(1), Rational(1), theta, Rational(1)};
      // Normalisation: ∫∫∫ w φ_M φ_τ F = ν √((1+τ)/2) ⟨F⟩_table; φ_M φ_M Σ h_k S_k gives ν Σ h_k L^(k).
      const double norm = std::sqrt((1 + tau.to_double()) / 2);
      for (int p = 0; p <= n_max; ++p)
        for (int q = 0; q <= n_max; ++q) {
          const Rational direct =
              term(hot_partner, Slot::v1, Slot::v1, p, q) - term(hot_partner, Slot::v1, Slot::v1_post, p, q) +
              term(hot_tested, Slot::v2, Slot::v1, p, q) - term(hot_tested, Slot::v2, Slot::v1_post, p, q);
          Rational series;
          Rational h(1);
          for (int k = 0; k <= k_max; ++k, h *= Rational(1) - tau) series += h * weighted[k](p, q);
          EXPECT_NEAR(series.to_double(), norm * direct.to_double(), 1e-12 * (1 + std::abs(series.to_double())))
              << "d=" << d << " rank=" << rank << " p=" << p << " q=" << q;
        }
    }
  }
}

// The extra power (σ̂·g)^s of viscoelastic restitution (theory.md (2.9)): moments
// ⟨(σ̂·g)^s X_1^a X_1'^b⟩/J0 against Monte Carlo, masses 1:3, θ = 1, 1/4, α = 0.6, s = 1/5, 2/5, 1.
TEST(CollisionMomentTable, FractionalPowerOfImpactVelocityVsMonteCarlo) {
  const gkt::CollisionPair pair{3, Rational(1), Rational(3), Rational(1), Rational(1, 4)};
  for (const Rational& s : {Rational(1, 5), Rational(2, 5), Rational(1)}) {
    const gkt::CollisionMomentTable<Rational> t(pair, Rational(3, 5), {Slot::v1, Slot::v1_post}, {2, 2}, std::nullopt,
                                                0, s);
    std::vector<std::function<double(const Collision&)>> integrands;
    std::vector<std::pair<int, int>> powers;
    for (int a = 0; a <= 2; ++a)
      for (int b = 0; b <= 2 - a; ++b) {
        powers.emplace_back(a, b);
        integrands.emplace_back([a, b, s](const Collision& c) {
          const double x1 = dot(c.v1, c.v1, 3), x1p = dot(c.v1p, c.v1p, 3);
          return std::pow(c.weight, s.to_double()) * std::pow(x1, a) * std::pow(x1p, b);
        });
      }
    gkt::test::CollisionSampler sampler(3, 1, 3, 1, 0.25, 0.6, 4242);
    const auto mc = gkt::test::weighted_averages(sampler, 400000, integrands);
    for (std::size_t i = 0; i < powers.size(); ++i) {
      const double engine = t.moment({powers[i].first, powers[i].second}).to_double() * t.power_factor();
      EXPECT_NEAR(engine, mc[i].mean, 5 * mc[i].error)
          << "s=" << s << " a=" << powers[i].first << " b=" << powers[i].second;
      EXPECT_LT(mc[i].error, 0.02 * std::abs(mc[i].mean)) << "Monte Carlo too noisy to discriminate";
    }
  }
}
