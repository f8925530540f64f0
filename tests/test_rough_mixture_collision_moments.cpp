// The two-species rough collision engine (docs/theory.md §19.17) against
//  (a) the one-species engine at equal species (exact equality, numeric and symbolic spin);
//  (b) the smooth mixture engine at β = −1 (exact equality of translational moments);
//  (c) momentum, spin-impulse and energy balances, exactly: the collision conserves total momentum,
//      the spin changes satisfy κ_i m_i Δw1 = κ_j m_j Δw2 (angular momentum), the energy change is
//      −(μ/2)(1−α²)u² − (M/2)(1−β²)g_c,t² collision by collision, and its mean is the closed form;
//  (d) Monte Carlo with error bars (the rigid-body impulse solved numerically, with ω and unequal
//      diameters: tests/rough_mixture_monte_carlo.hpp) at unequal masses, sizes, κ and temperatures.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <utility>
#include <vector>

#include "gkt/algebra/sonine.hpp"
#include "gkt/collision/collision_moments.hpp"
#include "gkt/collision/quadratic_form_moments.hpp"
#include "gkt/collision/rough_mixture_collision_moments.hpp"
#include "rough_mixture_monte_carlo.hpp"

using gkt::Rational;
using gkt::RationalPolynomial;
using gkt::rough_dot_form;
using gkt::RoughCollisionMoments;
using gkt::RoughForm;
using gkt::RoughSlot;
using gkt::RoughSpecies;

namespace {

/// Returns |Σ_k c_k W_k|² as a form.
RoughForm square(const std::vector<std::pair<RoughSlot, Rational>>& combination) {
  RoughForm f{};
  for (const auto& [a, ca] : combination)
    for (const auto& [b, cb] : combination) f = f + gkt::scaled(rough_dot_form(a, b), ca * cb);
  return f;
}

/// Returns W_a² − W_b².
RoughForm change(RoughSlot post, RoughSlot pre) {
  return rough_dot_form(post, post) + gkt::scaled(rough_dot_form(pre, pre), Rational(-1));
}

/// Every exponent vector of the box, the last form fastest.
std::vector<gkt::RoughExponents> box_of(const std::vector<int>& degrees) {
  std::vector<gkt::RoughExponents> out{gkt::RoughExponents{}};
  for (std::size_t v = 0; v < degrees.size(); ++v) {
    std::vector<gkt::RoughExponents> next;
    for (const auto& k : out)
      for (int e = 0; e <= degrees[v]; ++e) {
        auto m = k;
        m[v] = e;
        next.push_back(m);
      }
    out = std::move(next);
  }
  return out;
}

const RoughSpecies kSpeciesI{Rational(1), Rational(2, 5), Rational(3, 4), Rational(1, 2)};
const RoughSpecies kSpeciesJ{Rational(3), Rational(1, 2), Rational(1, 2), Rational(5, 4)};

}  // namespace

// (a) Equal species: m = 1, T_t = 1/2 (v in units of √(2T_t/m)), T_r = θ/2, so the widths are the
// one-species engine's (1, 1, κ/θ, κ/θ); every moment of a box of four forms (v·w coupling included
// for d = 3) must be equal, exactly.
TEST(RoughMixtureCollisionMoments, EqualSpeciesIsTheOneSpeciesEngine) {
  const Rational alpha(7, 10), beta(2, 5), kappa(2, 5), theta(3, 2);
  for (int d : {2, 3}) {
    const RoughSpecies s{Rational(1), kappa, Rational(1, 2), theta / Rational(2)};
    std::vector<RoughForm> forms{
        rough_dot_form(RoughSlot::v1_post, RoughSlot::v1_post), rough_dot_form(RoughSlot::w1_post, RoughSlot::w1_post),
        rough_dot_form(RoughSlot::v1, RoughSlot::v2_post) + rough_dot_form(RoughSlot::w1_post, RoughSlot::w2),
        change(RoughSlot::w2_post, RoughSlot::v2)};
    if (d == 3) forms[3] = forms[3] + rough_dot_form(RoughSlot::v1_post, RoughSlot::w2_post);
    const std::vector<int> degrees{2, 2, 1, 2};
    const RoughCollisionMoments<Rational> one(gkt::rough_parameters(d, alpha, beta, kappa, theta), forms, degrees);
    const auto two =
        gkt::rough_mixture_collision_moments(gkt::rough_mixture_parameters(d, alpha, beta, s, s), forms, degrees);
    for (const auto& k : box_of(degrees)) EXPECT_EQ(two.moment(k), one.moment(k)) << "d=" << d;
    // Symbolic spin: the one-species ring variable is λ = √(θ/κ) with ŵ ~ e^{−ŵ²}; the mixture's x
    // with T_r = κ/2 (b = κm/(2T_r) = 1) is the same variable.
    const RoughSpecies unit{Rational(1), kappa, Rational(1, 2), kappa / Rational(2)};
    const std::vector<RoughForm> spin_forms{forms[0], forms[1], forms[2]};
    const RoughCollisionMoments<RationalPolynomial> one_symbolic(
        gkt::rough_parameters_symbolic_temperature(d, alpha, beta, kappa), spin_forms, {2, 2, 1});
    const auto two_symbolic = gkt::rough_mixture_collision_moments(
        gkt::rough_mixture_parameters_symbolic_spin(d, alpha, beta, unit, unit), spin_forms, {2, 2, 1});
    for (const auto& k : box_of({2, 2, 1}))
      EXPECT_EQ(two_symbolic.moment(k), one_symbolic.moment(k)) << "symbolic d=" << d;
  }
}

// (a') Relabelling: the i–j collision seen from j (slots 1 ↔ 2, σ̂ → −σ̂) has the same moments.
// This is the check of the asymmetric rows (n_i ≠ n_j, t_i ≠ t_j) that equal species cannot see.
TEST(RoughMixtureCollisionMoments, RelabellingTheSpeciesLeavesMomentsUnchanged) {
  const auto swap = [](const RoughForm& f) {
    const std::array<std::size_t, 8> p{1, 0, 3, 2, 5, 4, 7, 6};
    RoughForm g{};
    for (std::size_t a = 0; a < 8; ++a)
      for (std::size_t b = 0; b < 8; ++b) g[p[a]][p[b]] = f[a][b];
    return g;
  };
  for (int d : {2, 3}) {
    const Rational alpha(3, 5), beta(1, 5);
    std::vector<RoughForm> forms{
        rough_dot_form(RoughSlot::v1_post, RoughSlot::v1_post), change(RoughSlot::w2_post, RoughSlot::w1),
        rough_dot_form(RoughSlot::v2_post, RoughSlot::v1) + rough_dot_form(RoughSlot::w1_post, RoughSlot::w2_post)};
    if (d == 3) forms[2] = forms[2] + rough_dot_form(RoughSlot::v2_post, RoughSlot::w1_post);
    std::vector<RoughForm> swapped;
    for (const auto& f : forms) swapped.push_back(swap(f));
    const std::vector<int> degrees{2, 2, 2};
    const auto ij = gkt::rough_mixture_collision_moments(
        gkt::rough_mixture_parameters(d, alpha, beta, kSpeciesI, kSpeciesJ), forms, degrees);
    const auto ji = gkt::rough_mixture_collision_moments(
        gkt::rough_mixture_parameters(d, alpha, beta, kSpeciesJ, kSpeciesI), swapped, degrees);
    for (const auto& k : box_of(degrees)) EXPECT_EQ(ij.moment(k), ji.moment(k)) << "d=" << d;
  }
}

// (b) β = −1: the spin decouples; translational moments equal the smooth mixture engine's
// (masses m_i, m_j, widths θ_k = m_k/(2T_t,k) in the same velocity unit), and the spin is unchanged.
TEST(RoughMixtureCollisionMoments, SmoothLimitIsTheSmoothMixtureEngine) {
  for (int d : {2, 3}) {
    const Rational alpha(4, 5);
    const auto params = gkt::rough_mixture_parameters(d, alpha, Rational(-1), kSpeciesI, kSpeciesJ);
    const std::vector<RoughForm> forms{
        rough_dot_form(RoughSlot::v1_post, RoughSlot::v1_post), rough_dot_form(RoughSlot::v1, RoughSlot::v2_post),
        rough_dot_form(RoughSlot::v2, RoughSlot::v2),
        change(RoughSlot::w1_post, RoughSlot::w1) + change(RoughSlot::w2_post, RoughSlot::w2)};
    const auto rough = gkt::rough_mixture_collision_moments(params, forms, {3, 2, 2, 1});
    gkt::CollisionPair pair;
    pair.dimension = d;
    pair.mass_i = kSpeciesI.mass;
    pair.mass_j = kSpeciesJ.mass;
    pair.theta_i = params.velocity_width_i;
    pair.theta_j = params.velocity_width_j;
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
        }
  }
}

// (b') Sonine × spherical-harmonic matrix elements ⟨ψ_q(c2)·ψ_p(c1')⟩/⟨1⟩, ψ_n = S_m^(n)(c²) Y_r(c), ranks
// 0, 1, 2, from the rough mixture table of c2², c1'² and c2·c1' (rough_mixture_reduced_dot; widths 1 and 4,
// so √(a_i a_j) = 2): at β = −1 every element equals the smooth mixture engine's sonine_collision_moments.
TEST(RoughMixtureCollisionMoments, SonineMatrixElementsAtBetaMinusOneAreTheSmoothMixture) {
  const RoughSpecies i{Rational(1), Rational(2, 5), Rational(1, 2), Rational(1, 3)};
  const RoughSpecies j{Rational(3), Rational(1, 2), Rational(3, 8), Rational(2)};
  const Rational alpha(7, 10);
  const int n_max = 2;
  for (int d : {2, 3}) {
    const auto p = gkt::rough_mixture_parameters(d, alpha, Rational(-1), i, j);
    const RoughForm xu = gkt::rough_mixture_reduced_square(p, RoughSlot::v2);
    const RoughForm xt = gkt::rough_mixture_reduced_square(p, RoughSlot::v1_post);
    const RoughForm c = gkt::rough_mixture_reduced_dot(p, RoughSlot::v2, RoughSlot::v1_post);
    const auto table = gkt::rough_mixture_collision_moments(p, {xu, xt, c}, {n_max + 1, n_max + 1, 2});
    gkt::CollisionPair pair;
    pair.dimension = d;
    pair.mass_i = i.mass;
    pair.mass_j = j.mass;
    pair.theta_i = p.velocity_width_i;
    pair.theta_j = p.velocity_width_j;
    for (int rank = 0; rank <= 2; ++rank) {
      const auto smooth =
          gkt::sonine_collision_moments<Rational>(pair, alpha, gkt::Slot::v2, gkt::Slot::v1_post, rank, n_max);
      const auto sonine = gkt::sonine_table(gkt::sonine_twice_m(d, rank), n_max);
      // ⟨X_u^k X_t^l Y_r⟩ with Y_0 = 1, Y_1 = c_u·c_t, Y_2 contracted = (c_u·c_t)² − X_u X_t/d.
      const auto harmonic = [&table, rank, d](int k, int l) {
        if (rank == 0) return table.moment(std::array<int, 3>{k, l, 0});
        if (rank == 1) return table.moment(std::array<int, 3>{k, l, 1});
        return table.moment(std::array<int, 3>{k, l, 2}) -
               table.moment(std::array<int, 3>{k + 1, l + 1, 0}) / Rational(d);
      };
      for (int tp = 0; tp <= n_max; ++tp)
        for (int uq = 0; uq <= n_max; ++uq) {
          Rational element(0);
          for (int k = 0; k <= uq; ++k)
            for (int l = 0; l <= tp; ++l)
              element += sonine[static_cast<std::size_t>(uq)][static_cast<std::size_t>(k)] *
                         sonine[static_cast<std::size_t>(tp)][static_cast<std::size_t>(l)] * harmonic(k, l);
          EXPECT_EQ(element, smooth(tp, uq)) << "d=" << d << " rank=" << rank << " p=" << tp << " q=" << uq;
        }
    }
  }
  // c_a·c_b needs a rational √(width_a width_b).
  const auto p = gkt::rough_mixture_parameters(3, alpha, Rational(0), kSpeciesI, kSpeciesJ);
  EXPECT_THROW(gkt::rough_mixture_reduced_dot(p, RoughSlot::v1, RoughSlot::v2), std::invalid_argument);
}

// (c) Balances, exactly. P = |m_i Δv1 + m_j Δv2|² and S = |κ_i m_i Δw1 − κ_j m_j Δw2|² vanish on every
// collision (⟨P X^k⟩ = ⟨S X^k⟩ = 0); with g_c,t² = |Δw1|²/r_i² (r_i = (1+β)M/(κ_i m_i)) and
// u² = (|Δv1|² − t_i² g_c,t²)/n_i², the residual R = ΔE + (μ/2)(1−α²)u² + (M/2)(1−β²)g_c,t² has
// ⟨R²⟩ = 0; and ⟨ΔE⟩ = −(μ/2)(1−α²)(1/a_i + 1/a_j) − (M/2)(1−β²)((d−1)/2)(1/a_i + 1/a_j + 1/b_i + 1/b_j).
TEST(RoughMixtureCollisionMoments, MomentumSpinAndEnergyBalancesAreExact) {
  const Rational one(1), two(2);
  for (int d : {2, 3})
    for (const auto& [alpha, beta] :
         {std::pair{Rational(7, 10), Rational(2, 5)}, {Rational(1, 5), Rational(-4, 5)}, {Rational(1), Rational(1)}}) {
      const auto p = gkt::rough_mixture_parameters(d, alpha, beta, kSpeciesI, kSpeciesJ);
      const Rational mi = p.mass_i, mj = p.mass_j, ki = p.kappa_i, kj = p.kappa_j, m_t = p.tangential_mass();
      const RoughForm momentum =
          square({{RoughSlot::v1_post, mi}, {RoughSlot::v1, -mi}, {RoughSlot::v2_post, mj}, {RoughSlot::v2, -mj}});
      const RoughForm spin = square({{RoughSlot::w1_post, ki * mi},
                                     {RoughSlot::w1, -ki * mi},
                                     {RoughSlot::w2_post, -kj * mj},
                                     {RoughSlot::w2, kj * mj}});
      const RoughForm energy = gkt::scaled(change(RoughSlot::v1_post, RoughSlot::v1), mi / two) +
                               gkt::scaled(change(RoughSlot::v2_post, RoughSlot::v2), mj / two) +
                               gkt::scaled(change(RoughSlot::w1_post, RoughSlot::w1), ki * mi / two) +
                               gkt::scaled(change(RoughSlot::w2_post, RoughSlot::w2), kj * mj / two);
      const Rational mu = mi * mj / (mi + mj), n_i = (one + alpha) * mj / (mi + mj), t_i = (one + beta) * m_t / mi;
      const Rational r_i = t_i / ki;
      const RoughForm dw1 = square({{RoughSlot::w1_post, one}, {RoughSlot::w1, -one}});
      const RoughForm dv1 = square({{RoughSlot::v1_post, one}, {RoughSlot::v1, -one}});
      RoughForm residual = energy;
      if (!r_i.is_zero()) {
        const RoughForm gct2 = gkt::scaled(dw1, one / (r_i * r_i));
        const RoughForm u2 = gkt::scaled(dv1 + gkt::scaled(gct2, -t_i * t_i), one / (n_i * n_i));
        residual = residual + gkt::scaled(u2, mu / two * (one - alpha * alpha)) +
                   gkt::scaled(gct2, m_t / two * (one - beta * beta));
      }
      const RoughForm x1 = gkt::rough_mixture_reduced_square(p, RoughSlot::v1);
      const auto m = gkt::rough_mixture_collision_moments(p, {momentum, spin, residual, energy, x1}, {1, 1, 2, 1, 2});
      for (int k = 0; k <= 2; ++k) {
        EXPECT_TRUE(m.moment({1, 0, 0, 0, k}).is_zero()) << "momentum d=" << d;
        EXPECT_TRUE(m.moment({0, 1, 0, 0, k}).is_zero()) << "spin d=" << d;
      }
      if (!r_i.is_zero()) {
        EXPECT_TRUE(m.moment({0, 0, 2, 0, 0}).is_zero()) << "energy residual d=" << d;
      }
      const Rational inv_a = one / p.velocity_width_i + one / p.velocity_width_j;
      const Rational inv_b = one / p.spin_width_i + one / p.spin_width_j;
      EXPECT_EQ(m.moment({0, 0, 0, 1, 0}), -mu / two * (one - alpha * alpha) * inv_a -
                                               m_t / two * (one - beta * beta) * Rational(d - 1, 2) * (inv_a + inv_b))
          << "d=" << d;
      if (alpha == one && beta == one) {  // elastic perfectly rough: energy conserved sample-wise
        EXPECT_TRUE(m.moment({0, 0, 0, 1, 1}).is_zero());
      }
    }
}

// Symbolic rotational temperatures: the moments are even polynomials in x and equal the numeric
// engine at x² = s (species' T_r scaled by s), exactly.
TEST(RoughMixtureCollisionMoments, SymbolicSpinScaleEqualsNumeric) {
  const Rational alpha(4, 5), beta(1, 2);
  for (int d : {2, 3}) {
    const std::vector<RoughForm> forms{
        change(RoughSlot::v1_post, RoughSlot::v1), change(RoughSlot::w2_post, RoughSlot::w2),
        rough_dot_form(RoughSlot::w1_post, RoughSlot::w2) + rough_dot_form(RoughSlot::v2_post, RoughSlot::v2_post)};
    const auto symbolic = gkt::rough_mixture_collision_moments(
        gkt::rough_mixture_parameters_symbolic_spin(d, alpha, beta, kSpeciesI, kSpeciesJ), forms, {2, 1, 2});
    for (const Rational& s : {Rational(1), Rational(9, 4)}) {
      RoughSpecies i = kSpeciesI, j = kSpeciesJ;
      i.rotational_temperature *= s;
      j.rotational_temperature *= s;
      const auto numeric =
          gkt::rough_mixture_collision_moments(gkt::rough_mixture_parameters(d, alpha, beta, i, j), forms, {2, 1, 2});
      for (const auto& k : box_of({2, 1, 2})) {
        const RationalPolynomial p = symbolic.moment(k);
        Rational value(0), power(1);
        for (long e = 0; e <= p.degree(); ++e) {
          if (e % 2 == 1) {
            EXPECT_TRUE(p.coefficient(e).is_zero()) << "odd power of x";
            continue;
          }
          value += p.coefficient(e) * power;
          power *= s;
        }
        EXPECT_EQ(value, numeric.moment(k)) << "d=" << d;
      }
    }
  }
}

TEST(RoughMixtureCollisionMoments, RejectsBadParameters) {
  RoughSpecies bad = kSpeciesI;
  bad.kappa = Rational(0);
  EXPECT_THROW(gkt::rough_mixture_parameters(3, Rational(1), Rational(0), bad, kSpeciesJ), std::invalid_argument);
  bad = kSpeciesJ;
  bad.mass = Rational(-1);
  EXPECT_THROW(gkt::rough_mixture_parameters(3, Rational(1), Rational(0), kSpeciesI, bad), std::invalid_argument);
  bad = kSpeciesJ;
  bad.rotational_temperature = Rational(0);
  EXPECT_THROW(gkt::rough_mixture_parameters(2, Rational(1), Rational(0), kSpeciesI, bad), std::invalid_argument);
  EXPECT_THROW(gkt::rough_mixture_parameters(3, Rational(0), Rational(0), kSpeciesI, kSpeciesJ), std::invalid_argument);
  EXPECT_THROW(gkt::rough_mixture_parameters(3, Rational(1), Rational(3, 2), kSpeciesI, kSpeciesJ),
               std::invalid_argument);
  EXPECT_THROW(gkt::rough_mixture_parameters(4, Rational(1), Rational(0), kSpeciesI, kSpeciesJ), std::invalid_argument);
  try {
    gkt::rough_mixture_parameters(3, Rational(1), Rational(0), kSpeciesI, bad);
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("species_j.rotational_temperature"), std::string::npos) << e.what();
  }
}

namespace {

double mc_dot(const gkt::test::RoughCollision& c, RoughSlot a, RoughSlot b) {
  return gkt::test::dot3(c.w[static_cast<std::size_t>(a)], c.w[static_cast<std::size_t>(b)]);
}

gkt::test::McRoughSpecies mc_species(const RoughSpecies& s, double diameter) {
  return {s.mass.to_double(), diameter, s.kappa.to_double(), s.translational_temperature.to_double(),
          s.rotational_temperature.to_double()};
}

}  // namespace

// The Monte Carlo rule itself: contact law, momentum and angular momentum about the origin
// (centres at ∓(σ_i/2)σ̂ and +(σ_j/2)σ̂ from the contact point), collision by collision.
TEST(RoughMixtureCollisionMoments, MonteCarloRuleObeysTheContactLawAndConservation) {
  using gkt::test::Vec3;
  for (int d : {2, 3}) {
    const auto i = mc_species(kSpeciesI, 1.0), j = mc_species(kSpeciesJ, 2.5);
    gkt::test::RoughMixtureCollisionSampler sampler(d, i, j, 0.7, 0.3, 11);
    for (int s = 0; s < 200; ++s) {
      const auto c = sampler.draw();
      const Vec3& n = c.sigma;
      Vec3 x1{}, x2{};
      for (int k = 0; k < 3; ++k) {
        x1[k] = -0.5 * i.diameter * n[k];
        x2[k] = 0.5 * j.diameter * n[k];
      }
      const auto contact = [&](int o, int oo) {
        Vec3 a = gkt::test::cross(c.omega[oo], gkt::test::Vec3{-x1[0], -x1[1], -x1[2]});
        Vec3 b = gkt::test::cross(c.omega[oo + 1], gkt::test::Vec3{-x2[0], -x2[1], -x2[2]});
        Vec3 g{};
        for (int k = 0; k < 3; ++k) g[k] = c.w.w[o][k] + a[k] - c.w.w[o + 1][k] - b[k];
        return g;
      };
      const Vec3 g = contact(0, 0), gp = contact(4, 2);
      const double u = gkt::test::dot3(n, g), up = gkt::test::dot3(n, gp);
      EXPECT_NEAR(up, -0.7 * u, 1e-12);
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(gp[k] - up * n[k], -0.3 * (g[k] - u * n[k]), 1e-12);
        EXPECT_NEAR(i.mass * c.w.w[4][k] + j.mass * c.w.w[5][k], i.mass * c.w.w[0][k] + j.mass * c.w.w[1][k], 1e-12);
      }
      const auto angular = [&](int o, int oo) {
        const Vec3 l1 = gkt::test::cross(x1, c.w.w[o]), l2 = gkt::test::cross(x2, c.w.w[o + 1]);
        Vec3 l{};
        for (int k = 0; k < 3; ++k)
          l[k] = i.mass * l1[k] + j.mass * l2[k] + i.inertia() * c.omega[oo][k] + j.inertia() * c.omega[oo + 1][k];
        return l;
      };
      const Vec3 l = angular(0, 0), lp = angular(4, 2);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(lp[k], l[k], 1e-12);
    }
  }
}

// (d) Monte Carlo with error bars at unequal masses, diameters (which must drop out), κ and
// temperatures: moments up to degree 4 touching every slot.
TEST(RoughMixtureCollisionMoments, MomentsAgainstMonteCarlo) {
  for (int d : {3, 2}) {
    const Rational alpha(7, 10), beta = d == 3 ? Rational(2, 5) : Rational(-1, 2);
    const auto params = gkt::rough_mixture_parameters(d, alpha, beta, kSpeciesI, kSpeciesJ);
    std::vector<RoughForm> forms{
        rough_dot_form(RoughSlot::v1_post, RoughSlot::v1_post), rough_dot_form(RoughSlot::w2_post, RoughSlot::w2_post),
        rough_dot_form(RoughSlot::v1, RoughSlot::v2_post) + rough_dot_form(RoughSlot::w1_post, RoughSlot::w2),
        change(RoughSlot::w1_post, RoughSlot::v2)};
    if (d == 3) forms[3] = forms[3] + rough_dot_form(RoughSlot::v2_post, RoughSlot::w1_post);
    const auto engine = gkt::rough_mixture_collision_moments(params, forms, {2, 2, 2, 1});
    using F = std::function<double(const gkt::test::RoughCollision&)>;
    const std::vector<F> mc_forms{
        [](const auto& c) { return mc_dot(c, RoughSlot::v1_post, RoughSlot::v1_post); },
        [](const auto& c) { return mc_dot(c, RoughSlot::w2_post, RoughSlot::w2_post); },
        [](const auto& c) {
          return mc_dot(c, RoughSlot::v1, RoughSlot::v2_post) + mc_dot(c, RoughSlot::w1_post, RoughSlot::w2);
        },
        [d](const auto& c) {
          return mc_dot(c, RoughSlot::w1_post, RoughSlot::w1_post) - mc_dot(c, RoughSlot::v2, RoughSlot::v2) +
                 (d == 3 ? mc_dot(c, RoughSlot::v2_post, RoughSlot::w1_post) : 0.0);
        }};
    const std::vector<std::array<int, 4>> exponents{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1},
                                                    {1, 1, 0, 0}, {0, 2, 0, 0}, {2, 0, 0, 0}, {0, 0, 2, 0},
                                                    {1, 0, 1, 1}, {0, 1, 1, 1}, {1, 1, 1, 0}};
    gkt::test::RoughMixtureCollisionSampler sampler(d, mc_species(kSpeciesI, 1.0), mc_species(kSpeciesJ, 2.5),
                                                    alpha.to_double(), beta.to_double(), 20261202);
    const long samples = 300000;
    gkt::test::RatioAverages acc(exponents.size());
    for (long s = 0; s < samples; ++s) {
      const auto c = sampler.draw().w;
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
      EXPECT_NEAR(exact, mean, 5 * error) << "d=" << d << " moment " << e;
      EXPECT_LT(error, 0.05 * (std::abs(exact) + 1)) << "Monte Carlo too noisy, d=" << d << " moment " << e;
    }
  }
}
