// The closed-form Gaussian collision integral J(Q) (docs/theory.md §2) against
//  (1) Monte Carlo integration with an error bar, for d = 2, 3, unequal masses and
//      temperatures, inelastic restitution;
//  (2) the J0 of Goldhirsch, Noskowicz & Bar-Lev, J. Phys.: Condens. Matter 17 (2005) S2591,
//      appendix A, with μ and ν as corrected in docs/theory.md §2.3 (the printed μ is OCR-damaged).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "gkt/collision/gaussian_collision_integral.hpp"
#include "monte_carlo.hpp"

using gkt::QuadraticForm;
using gkt::test::Collision;
using gkt::test::dot;

namespace {

struct Case {
  int d;
  double mi, mj, theta_i, theta_j, alpha;
};

void PrintTo(const Case& k, std::ostream* os) {
  *os << "d=" << k.d << " m=" << k.mi << ":" << k.mj << " theta=" << k.theta_i << "," << k.theta_j
      << " alpha=" << k.alpha;
}

/// exp(−Σ δQ_ab W_a·W_b) for a sampled collision.
double perturbation_factor(const QuadraticForm& dq, const Collision& c, int d) {
  const std::array<const gkt::test::Vec*, 4> w{&c.v1, &c.v2, &c.v1p, &c.v2p};
  double f = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) f += dq[a][b] * dot(*w[a], *w[b], d);
  return std::exp(-f);
}

}  // namespace

class ClosedFormVsMonteCarlo : public ::testing::TestWithParam<Case> {};

TEST_P(ClosedFormVsMonteCarlo, ReferenceAndPerturbedForms) {
  const Case k = GetParam();
  QuadraticForm q0{};
  q0[0][0] = k.theta_i;
  q0[1][1] = k.theta_j;
  // A perturbation touching every slot, pre- and post-collisional, with cross terms.
  QuadraticForm dq{};
  const double entries[4][4] = {
      {0.15, 0.05, -0.08, 0.03}, {0.05, 0.1, 0.02, -0.06}, {-0.08, 0.02, 0.2, 0.04}, {0.03, -0.06, 0.04, 0.12}};
  QuadraticForm q = q0;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      dq[a][b] = entries[a][b];
      q[a][b] += dq[a][b];
    }
  gkt::test::CollisionSampler sampler(k.d, k.mi, k.mj, k.theta_i, k.theta_j, k.alpha, 20261123);
  const long n = 400000;
  // Normalisation of the sampling density: ∫ e^{−θ_i v1² − θ_j v2²} dv1 dv2 × surface of S^{d−1}.
  const double gauss =
      std::pow(std::numbers::pi / k.theta_i, k.d / 2.0) * std::pow(std::numbers::pi / k.theta_j, k.d / 2.0);
  const double surface = 2 * std::pow(std::numbers::pi, k.d / 2.0) / std::tgamma(k.d / 2.0);
  const auto ref = gkt::test::mean_weight(sampler, n, [](const Collision&) { return 1.0; });
  const auto pert =
      gkt::test::mean_weight(sampler, n, [&](const Collision& c) { return perturbation_factor(dq, c, k.d); });
  const double scale = gauss * surface;
  const double j0 = gkt::gaussian_collision_integral(k.d, k.mi, k.mj, k.alpha, q0);
  const double j = gkt::gaussian_collision_integral(k.d, k.mi, k.mj, k.alpha, q);
  // 5 standard errors: a correct closed form fails this with probability < 1e-6.
  EXPECT_NEAR(j0, scale * ref.mean, 5 * scale * ref.error) << "reference form";
  EXPECT_NEAR(j, scale * pert.mean, 5 * scale * pert.error) << "perturbed form";
  // The Monte Carlo error bar must be small enough to discriminate (1 %).
  EXPECT_LT(pert.error / pert.mean, 0.01);
}

INSTANTIATE_TEST_SUITE_P(Cases, ClosedFormVsMonteCarlo,
                         ::testing::Values(Case{3, 1, 1, 1, 1, 1}, Case{3, 1, 7, 1, 4, 1}, Case{3, 1, 1, 1, 1, 0.6},
                                           Case{2, 1, 1, 1, 1, 1}, Case{2, 1, 3, 1, 0.25, 0.6}),
                         [](const auto& info) { return std::to_string(info.index); });

// Goldhirsch–Noskowicz–Bar-Lev J0(a, b, c, d, x, y, z, γ, β) = 2π^{7/2}/(λ^{3/2} μ (μ+ν)) for equal
// masses, elastic, d = 3, with
//   F = a u1² + b u2² + c u1'² + d u2'² + x/2 (u1+u1')² + y/2 (u1+u2')² + z/2 (u1+u2)² + γ u12² + β (k·u12)².
// Corrected coefficients (derived in docs/theory.md §2.3, confirmed here):
//   λ = a+b+c+d+2x+2y+2z,  μ = ¼(a+b+c+d+2x+4γ − (a−b+c−d+2x)²/λ),
//   ν = ½(y − x + 2β + (2/λ)(a−b+y+x)(c−d+x−y)).
TEST(GoldhirschJ0, CorrectedFormulaMatchesGeneralClosedForm) {
  const double params[][9] = {
      {1.0, 1.0, 0.2, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0},  {1.3, 0.9, 0.4, 0.1, 0.0, 0.0, 0.0, 0.0, 0.0},
      {1.2, 1.1, 0.3, 0.2, 0.15, 0.0, 0.0, 0.0, 0.0}, {1.0, 1.4, 0.1, 0.3, 0.0, 0.2, 0.0, 0.0, 0.0},
      {1.1, 1.0, 0.2, 0.2, 0.0, 0.0, 0.3, 0.0, 0.0},  {1.0, 1.0, 0.1, 0.1, 0.0, 0.0, 0.0, 0.2, 0.0},
      {1.0, 1.2, 0.1, 0.1, 0.0, 0.0, 0.0, 0.0, 0.3},  {1.5, 1.2, 0.3, 0.1, 0.1, 0.2, 0.3, 0.1, 0.2}};
  for (const auto& p : params) {
    const double a = p[0], b = p[1], c = p[2], dd = p[3], x = p[4], y = p[5], z = p[6], gamma = p[7], beta = p[8];
    // Q in (u1, u2, u1', u2'); β(k·u12)² = (β/2)(u12² − u12·u12') for elastic collisions.
    QuadraticForm q{};
    auto add = [&](int i, int j, double v) {
      if (i == j) {
        q[i][i] += v;
      } else {
        q[i][j] += v / 2;
        q[j][i] += v / 2;
      }
    };
    add(0, 0, a + x / 2 + y / 2 + z / 2 + gamma + beta / 2);
    add(1, 1, b + z / 2 + gamma + beta / 2);
    add(2, 2, c + x / 2);
    add(3, 3, dd + y / 2);
    add(0, 2, x - beta / 2);
    add(0, 3, y + beta / 2);
    add(0, 1, z - 2 * gamma - beta);
    add(1, 2, beta / 2);
    add(1, 3, -beta / 2);
    const double ours = gkt::gaussian_collision_integral(3, 1, 1, 1, q);
    const double lambda = a + b + c + dd + 2 * x + 2 * y + 2 * z;
    const double mu =
        0.25 * (a + b + c + dd + 2 * x + 4 * gamma - (a - b + c - dd + 2 * x) * (a - b + c - dd + 2 * x) / lambda);
    const double nu = 0.5 * (y - x + 2 * beta + (2 / lambda) * (a - b + y + x) * (c - dd + x - y));
    const double theirs = 2 * std::pow(std::numbers::pi, 3.5) / (std::pow(lambda, 1.5) * mu * (mu + nu));
    EXPECT_NEAR(ours / theirs, 1.0, 1e-13)
        << "a=" << a << " x=" << x << " y=" << y << " z=" << z << " γ=" << gamma << " β=" << beta;
  }
}

// The μ printed in the seed text (OCR: "+4y" for "+4γ" and the square lost) is wrong: with it the
// formula misses the general closed form by more than 1 % whenever y or the asymmetry is non-zero.
TEST(GoldhirschJ0, PrintedMuIsWrong) {
  const double a = 1.5, b = 1.2, c = 0.3, dd = 0.1, x = 0.1, y = 0.2, z = 0.3, gamma = 0.1;
  const double lambda = a + b + c + dd + 2 * x + 2 * y + 2 * z;
  const double mu_printed = 0.25 * (a + b + c + dd + 2 * x + 4 * y - (a - b + c - dd + 2 * x) / lambda);
  const double mu =
      0.25 * (a + b + c + dd + 2 * x + 4 * gamma - (a - b + c - dd + 2 * x) * (a - b + c - dd + 2 * x) / lambda);
  EXPECT_GT(std::abs(mu_printed / mu - 1), 0.01);
}

TEST(GaussianCollisionIntegral, RejectsNonIntegrableForms) {
  QuadraticForm q{};
  q[0][0] = -1;
  q[1][1] = 1;
  EXPECT_THROW((void)gkt::gaussian_collision_integral(3, 1, 1, 1, q), std::domain_error);
}
