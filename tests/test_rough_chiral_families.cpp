// Exact first-Sonine elements with the lowest aligned and chiral families (theory.md §19.22): against a Monte Carlo
// over collisions in vector form with the families written out in components (as gkt_rough_trial_families_mc), and
// the time-reversal relation (19.47) at Pidduck's gas (equilibrium θ = 1).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "gkt/transport/rough/rough_sonine_transport.hpp"
#include "rough_monte_carlo.hpp"
#include "rough_tensors.hpp"
#include "transport/rough/rough_chiral_families.hpp"

namespace {

using gkt::Rational;
using gkt::detail::RoughChiralFamilyElements;
using gkt::test::contract;
using gkt::test::cross;
using gkt::test::dot3;
using gkt::test::M3;
using gkt::test::sym;
using gkt::test::traceless;
using gkt::test::Vec3;

/// The tensor and vector families of gkt_rough_trial_families_mc, in components (w = ŵ, for disks along ẑ).
std::vector<M3> tensors(int d, const Vec3& c, const Vec3& w) {
  const double p = dot3(c, w), y = dot3(w, w);
  const M3 cc = traceless(sym(c, c), d);
  if (d == 2) return {cc, sym(c, Vec3{-c[1], c[0], 0}, w[2])};
  M3 t2 = traceless(sym(c, w, p), 3);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) t2[i][j] -= y / 3 * cc[i][j];
  return {cc, traceless(sym(w, w), 3), t2, sym(c, cross(c, w)), sym(w, cross(c, w), p)};
}
std::vector<Vec3> vectors(int d, const Vec3& c, const Vec3& w) {
  const double x = dot3(c, c), y = dot3(w, w), p = dot3(c, w), h = (d + 2) / 2.0, hr = d == 3 ? 1.5 : 0.5;
  std::vector<Vec3> out(2);
  for (int k = 0; k < 3; ++k) {
    out[0][k] = c[k] * (x - h);
    out[1][k] = c[k] * (y - hr);
  }
  if (d == 2) {
    out.push_back({-c[1] * w[2], c[0] * w[2], 0});
    return out;
  }
  Vec3 f{};
  for (int k = 0; k < 3; ++k) f[k] = w[k] * p - c[k] * y / 3;
  out.push_back(f);
  out.push_back(cross(c, w));
  return out;
}

}  // namespace

// Every tensor and vector element (product, aligned and chiral) against 3 × 10⁵ collisions: within 5σ, and the
// chiral–product couplings resolved (|value| > 5σ for most).
TEST(RoughChiralFamilies, ElementsAgainstMonteCarlo) {
  struct Case {
    int d;
    double alpha, beta, kappa, theta;
    Rational a, b, k;
  };
  for (const Case& cs : {Case{3, 0.7, 0.3, 0.4, 1.3, Rational(7, 10), Rational(3, 10), Rational(2, 5)},
                         Case{3, 0.9, 0.5, 0.4, 0.9, Rational(9, 10), Rational(1, 2), Rational(2, 5)},
                         Case{2, 0.9, 0.5, 0.5, 0.8, Rational(9, 10), Rational(1, 2), Rational(1, 2)}}) {
    const RoughChiralFamilyElements exact(cs.d, cs.a, cs.b, cs.k);
    const double tau = cs.theta / cs.kappa, lambda = std::sqrt(tau);
    gkt::test::RoughCollisionSampler sampler(cs.d, cs.alpha, cs.beta, cs.kappa, cs.theta, 77 + cs.d);
    const int nt = exact.size(2), nv = exact.size(1);
    const std::size_t n = static_cast<std::size_t>(nt * nt + nv * nv);
    gkt::test::RatioAverages acc(n);
    for (long s = 0; s < 300000; ++s) {
      const gkt::test::RoughCollision c = sampler.draw();
      if (c.weight == 0) continue;
      acc.sample(c.weight);
      Vec3 w1{}, w2{}, w1p{};
      for (int k = 0; k < 3; ++k) {
        w1[k] = c.w[2][k] / lambda;
        w2[k] = c.w[3][k] / lambda;
        w1p[k] = c.w[6][k] / lambda;
      }
      const auto t1 = tensors(cs.d, c.w[0], w1), t2 = tensors(cs.d, c.w[1], w2), t1p = tensors(cs.d, c.w[4], w1p);
      const auto v1 = vectors(cs.d, c.w[0], w1), v2 = vectors(cs.d, c.w[1], w2), v1p = vectors(cs.d, c.w[4], w1p);
      std::size_t i = 0;
      const auto add = [&](double h) { acc.add(i++, c.weight, h); };
      for (int p = 0; p < nt; ++p)
        for (int q = 0; q < nt; ++q)
          add(contract(t1[q], t1[p]) - contract(t1[q], t1p[p]) + contract(t2[q], t1[p]) - contract(t2[q], t1p[p]));
      for (int p = 0; p < nv; ++p)
        for (int q = 0; q < nv; ++q)
          add(dot3(v1[q], v1[p]) - dot3(v1[q], v1p[p]) + dot3(v2[q], v1[p]) - dot3(v2[q], v1p[p]));
    }
    int resolved = 0, chiral_product = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const bool tensor = i < static_cast<std::size_t>(nt * nt);
      const int rank = tensor ? 2 : 1, m = tensor ? nt : nv;
      const int j = static_cast<int>(tensor ? i : i - static_cast<std::size_t>(nt * nt));
      const int p = j / m, q = j % m;
      const auto [mean, error] = acc.estimate(i);
      const double value = exact.element(rank, p, q, tau);
      EXPECT_NEAR(value, mean, 5 * error) << "d " << cs.d << " rank " << rank << " test " << p << " trial " << q;
      if (exact.chiral(rank, p) != exact.chiral(rank, q)) {
        ++chiral_product;
        if (std::abs(value) > 5 * error) ++resolved;
      }
    }
    EXPECT_GE(2 * resolved, chiral_product) << "d " << cs.d;
  }
}

// (19.47): at α = β = 1, ⟨φ, 𝓛ψ⟩ = ε_φ ε_ψ ⟨ψ, 𝓛φ⟩ with ε the parity under (c, ŵ) → (−c, −ŵ): the chiral couplings of
// the other parity antisymmetric (to 1e-10), the rest symmetric; and not all zero.
TEST(RoughChiralFamilies, TimeReversalAtPidduck) {
  for (int d : {2, 3}) {
    const Rational kappa = d == 3 ? Rational(2, 5) : Rational(1, 2);
    const RoughChiralFamilyElements exact(d, Rational(1), Rational(1), kappa);
    // parities: tensor (cc)°, T1, T2 even, (c(c×ŵ))_sym and p(ŵ(c×ŵ))_sym (degree 5) odd; 2D ŵ(cc⊥)_sym odd;
    // vector: products and F odd, c × ŵ (ŵ c⊥) even; scalars even.
    const std::array<std::vector<int>, 3> parity{std::vector<int>(static_cast<std::size_t>(exact.size(0)), 1),
                                                 d == 3 ? std::vector<int>{-1, -1, -1, 1} : std::vector<int>{-1, -1, 1},
                                                 d == 3 ? std::vector<int>{1, 1, 1, -1, -1} : std::vector<int>{1, -1}};
    double largest_antisymmetric = 0;
    const double tau = 1 / kappa.to_double();  // equilibrium: T_r = T_t, θ = 1
    for (int rank = 0; rank <= 2; ++rank)
      for (int i = 0; i < exact.size(rank); ++i)
        for (int j = 0; j < exact.size(rank); ++j) {
          const double eps = parity[static_cast<std::size_t>(rank)][static_cast<std::size_t>(i)] *
                             parity[static_cast<std::size_t>(rank)][static_cast<std::size_t>(j)];
          const double a = exact.element(rank, i, j, tau), b = exact.element(rank, j, i, tau);
          EXPECT_NEAR(a, eps * b, 1e-10 * (1 + std::abs(a))) << "d " << d << " rank " << rank << " " << i << j;
          if (eps < 0) largest_antisymmetric = std::max(largest_antisymmetric, std::abs(a));
        }
    EXPECT_GT(largest_antisymmetric, 0.01) << "d " << d;
  }
}

// RoughTrialSpace::full at N = 1 (its product block from RoughCollisionElements, its families from
// RoughChiralFamilyElements' second list, the library's solve): the changes over the product space against §19.21's
// Monte Carlo table ("aligned + chiral", 3D κ = 2/5; "chiral alone", 2D κ = 1/2: no aligned family there), within 3σ.
TEST(RoughChiralFamilies, FullSpaceReproducesTheMonteCarloTable) {
  struct Row {
    int d;
    Rational alpha, beta;
    double eta, eta_error, kappa, kappa_error, mu, mu_error;
  };
  const std::vector<Row> rows{{3, Rational(1), Rational(1), 0.0502, 0.0016, 0.108, 0.011, 0, 0.001},
                              {3, Rational(9, 10), Rational(1, 2), 0.0229, 0.0009, 0.071, 0.012, 0.049, 0.009},
                              {3, Rational(1, 2), Rational(1, 2), 0.0137, 0.0010, 0.118, 0.026, 0.122, 0.029},
                              {2, Rational(1), Rational(1), -0.0151, 0.0009, -0.066, 0.008, 0, 0.001},
                              {2, Rational(9, 10), Rational(1, 2), -0.0060, 0.0008, -0.055, 0.007, -0.047, 0.007}};
  // The same systems assembled and solved by gkt_rough_trial_families_mc ... exact (its own product block and solve,
  // theory.md §19.22's table): Pidduck's gas 3D η* = 1.101724, κ* = 1.641475; 2D η* = 1.271179, κ* = 1.463505.
  const gkt::RoughSonineTransport spheres(3, Rational(1), Rational(1), Rational(2, 5), 1, gkt::RoughTrialSpace::full);
  EXPECT_NEAR(spheres.at_maxwellian_state(1).shear_viscosity, 1.101724, 1e-6);
  EXPECT_NEAR(spheres.at_maxwellian_state(1).thermal_conductivity, 1.641475, 1e-6);
  const gkt::RoughSonineTransport disks(2, Rational(1), Rational(1), Rational(1, 2), 1, gkt::RoughTrialSpace::full);
  EXPECT_NEAR(disks.at_maxwellian_state(1).shear_viscosity, 1.271179, 1e-6);
  EXPECT_NEAR(disks.at_maxwellian_state(1).thermal_conductivity, 1.463505, 1e-6);
  for (const Row& r : rows) {
    const Rational kappa = r.d == 3 ? Rational(2, 5) : Rational(1, 2);
    const gkt::RoughSonineTransport products(r.d, r.alpha, r.beta, kappa, 1);
    const gkt::RoughSonineTransport full(r.d, r.alpha, r.beta, kappa, 1, gkt::RoughTrialSpace::full);
    const auto p = products.at_maxwellian_state(1), f = full.at_maxwellian_state(1);
    const std::string where = "d " + std::to_string(r.d) + " alpha " + r.alpha.to_string();
    EXPECT_NEAR(f.shear_viscosity - p.shear_viscosity, r.eta, 3 * r.eta_error) << where;
    EXPECT_NEAR(f.thermal_conductivity - p.thermal_conductivity, r.kappa, 3 * r.kappa_error) << where;
    EXPECT_NEAR(f.density_heat_coefficient - p.density_heat_coefficient, r.mu, 3 * r.mu_error) << where;
  }
}
