// The thermodynamics of the revised Enskog mixture (theory.md §18.12): the chemical-potential
// derivatives against second differences of a free energy computed by another route (Simpson in λ
// of the pressure from Mixture::contact_values), Gibbs–Duhem against the solver's ∂p/∂n_l, and the
// functionals I_ℓij: zero for equal diameters, their two binary rows antisymmetric (Gibbs–Duhem
// again, the rows are computed separately), continuous in the tracer and dilute limits, exact at
// third-virial order (the Mayer lens); for three species the closures of theory.md §18.12 against
// (18.19), the merged binary, the tracer and dilute limits and the lens.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "gkt/transport/mixture/mixture.hpp"
#include "gkt/transport/mixture/mixture_navier_stokes.hpp"
#include "gkt/transport/mixture/revised_enskog_functionals.hpp"

namespace {

double sphere_volume(int d) {  // v_d: the volume of a sphere of unit diameter
  return std::pow(std::numbers::pi, d / 2.0) / (std::pow(2.0, d) * std::tgamma(d / 2.0 + 1));
}

/// The mixture of `base`'s species at the partial densities n (diameters as given).
gkt::Mixture at_densities(const gkt::Mixture& base, const std::vector<double>& n) {
  gkt::Mixture m = base;
  double total = 0, phi = 0;
  for (std::size_t k = 0; k < n.size(); ++k) {
    total += n[k];
    phi += sphere_volume(base.dimension) * n[k] * std::pow(base.species[k].diameter, base.dimension);
  }
  double sum = 0;
  for (std::size_t k = 0; k + 1 < n.size(); ++k) sum += (m.species[k].fraction = n[k] / total);
  m.species.back().fraction = 1 - sum;
  m.packing_fraction = phi;
  return m;
}

/// Returns p^ex(λn)/(Tλ²) = B_2 Σ_jk n_j n_k σ_jk^d χ_jk(λn) (at λ = 0 the second virial term, χ = 1).
double scaled_excess_pressure(const gkt::Mixture& base, const std::vector<double>& n, double lambda) {
  const int d = base.dimension;
  const std::size_t s = base.size();
  std::vector<double> scaled = n;
  for (double& v : scaled) v *= lambda;
  gkt::Mixture dilute = base;
  dilute.packing_fraction = 0;
  const auto chi = (lambda > 0 ? at_densities(base, scaled) : dilute).contact_values();
  const double b2 = std::pow(std::numbers::pi, d / 2.0) / (2 * std::tgamma(d / 2.0 + 1));
  double p = 0;
  for (std::size_t j = 0; j < s; ++j)
    for (std::size_t k = 0; k < s; ++k)
      p += b2 * n[j] * n[k] * std::pow(0.5 * (base.species[j].diameter + base.species[k].diameter), d) * chi[j * s + k];
  return p;
}

/// Returns a^ex/T = ∫_0^1 dλ p^ex(λn)/(Tλ²) by composite Simpson (2000 panels; the integrand is a
/// smooth rational function of λ with its poles beyond λ = 2).
double excess_free_energy(const gkt::Mixture& base, const std::vector<double>& n) {
  const int panels = 2000;
  double sum = 0;
  const double h = 1.0 / panels;
  for (int k = 0; k <= panels; ++k) {
    const double w = (k == 0 || k == panels) ? 1 : (k % 2 ? 4 : 2);
    sum += w * scaled_excess_pressure(base, n, k * h);
  }
  return sum * h / 3;
}

std::vector<double> densities(const gkt::Mixture& m) {
  double volume = 0;
  for (const auto& sp : m.species) volume += sp.fraction * std::pow(sp.diameter, m.dimension);
  const double n = m.packing_fraction / (sphere_volume(m.dimension) * volume);
  std::vector<double> out;
  for (const auto& sp : m.species) out.push_back(n * sp.fraction);
  return out;
}

/// Returns 2 n_j V (c − R)·σ̂/σ_ij in 3D: the first-order-in-density I_ℓij of the Mayer term (test
/// ThirdVirialLens). Sphere A (radius σ_iℓ) at x = 0, sphere B (radius σ_jℓ) at x = σ_ij; the
/// cross-section is quadratic on each side of the plane x0 where the spheres meet, so one Simpson panel
/// per side integrates the volume and the first moment exactly.
double mayer_lens_functional(double sigma_i, double sigma_j, double sigma_l, double n_j) {
  const double distance = 0.5 * (sigma_i + sigma_j);
  const double ra = 0.5 * (sigma_i + sigma_l), rb = 0.5 * (sigma_j + sigma_l);
  const double x0 = (distance * distance + ra * ra - rb * rb) / (2 * distance);
  auto area = [&](double x) {
    return std::numbers::pi * (x < x0 ? rb * rb - (x - distance) * (x - distance) : ra * ra - x * x);
  };
  auto simpson = [&](double a, double b, int power) {
    auto g = [&](double x) { return std::pow(x, power) * area(x); };
    return (b - a) / 6 * (g(a) + 4 * g(0.5 * (a + b)) + g(b));
  };
  const double lo = distance - rb, hi = ra;
  const double volume = simpson(lo, x0, 0) + simpson(x0, hi, 0);
  const double centroid = (simpson(lo, x0, 1) + simpson(x0, hi, 1)) / volume;
  return 2 * n_j * volume * (centroid - 0.5 * distance) / distance;
}

gkt::Mixture binary(int d, double phi, double sigma2, double x1, double alpha = 1) {
  return gkt::make_mixture(d, {{1, 1, x1, ""}, {8, sigma2, 1 - x1, ""}}, alpha, phi);
}

gkt::Mixture ternary(int d, double phi, const std::vector<double>& sigma, const std::vector<double>& x) {
  return gkt::make_mixture(d, {{1, sigma[0], x[0], ""}, {2.5, sigma[1], x[1], ""}, {4, sigma[2], x[2], ""}}, 0.8, phi);
}

std::vector<gkt::FunctionalClosure> closures() {
  return {gkt::FunctionalClosure::lens_centroid, gkt::FunctionalClosure::contact_point,
          gkt::FunctionalClosure::gradient};
}

/// Returns the largest relative residual over i, ℓ of (18.19): n_i ∂(μ_i/T)/∂n_ℓ against
/// δ_iℓ + 2B_2 n_i Σ_j σ_ij^d χ_ij [δ_jℓ + ½(n_j ∂_ℓ ln χ_ij + I_ℓij)], with the mixture's contact values and
/// their derivatives (Mixture, not the functionals' own) and the given I (at (i·s + j)·s + ℓ).
double chemical_potential_residual(const gkt::Mixture& m, const std::vector<double>& functionals) {
  const int d = m.dimension;
  const std::size_t s = m.size();
  const auto mu = gkt::chemical_potential_derivatives(m);
  const auto chi = m.contact_values();
  const auto dchi = m.contact_value_derivatives();  // n ∂χ_ij/∂n_ℓ
  const std::vector<double> n = densities(m);
  double total = 0;
  for (double v : n) total += v;
  const double b2 = std::pow(std::numbers::pi, d / 2.0) / (2 * std::tgamma(d / 2.0 + 1));
  double worst = 0;
  for (std::size_t i = 0; i < s; ++i)
    for (std::size_t l = 0; l < s; ++l) {
      double rhs = i == l ? 1.0 : 0.0;
      for (std::size_t j = 0; j < s; ++j) {
        const std::size_t p = i * s + j;
        const double sigma = 0.5 * (m.species[i].diameter + m.species[j].diameter);
        rhs += 2 * b2 * n[i] * std::pow(sigma, d) * chi[p] *
               ((j == l ? 1.0 : 0.0) + 0.5 * (n[j] * dchi[p * s + l] / (total * chi[p]) + functionals[p * s + l]));
      }
      worst = std::max(worst, std::abs(rhs - mu[i * s + l]) / std::abs(mu[i * s + l]));
    }
  return worst;
}

}  // namespace

// n_i ∂(μ_i/T)/∂n_ℓ = δ_iℓ + n_i ∂²(a^ex/T)/∂n_i∂n_ℓ with a^ex from Simpson in λ and central second
// differences (step 1e-3 of n_k: truncation ~1e-7, rounding of the 1e-13 Simpson values ~1e-7 too), so 1e-5.
TEST(RevisedEnskogFunctionals, ChemicalPotentialsEqualFreeEnergyDifferences) {
  for (int d : {2, 3})
    for (double phi : {0.1, 0.4}) {
      gkt::Mixture m = gkt::make_mixture(d, {{1, 1, 0.3, ""}, {4, 1.6, 0.5, ""}, {0.4, 0.7, 0.2, ""}}, 1.0, phi);
      const auto mu = gkt::chemical_potential_derivatives(m);
      const std::vector<double> n = densities(m);
      for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t l = 0; l < 3; ++l) {
          const double hi = 1e-3 * n[i], hl = 1e-3 * n[l];
          auto a = [&](double di, double dl) {
            std::vector<double> v = n;
            v[i] += di;
            v[l] += dl;
            return excess_free_energy(m, v);
          };
          const double second = (a(hi, hl) - a(hi, -hl) - a(-hi, hl) + a(-hi, -hl)) / (4 * hi * hl);
          const double expected = (i == l ? 1.0 : 0.0) + n[i] * second;
          EXPECT_NEAR(mu[i * 3 + l], expected, 1e-5 * std::abs(expected)) << d << " " << phi << " " << i << l;
        }
    }
}

// Gibbs–Duhem: Σ_i n_i ∂μ_i/∂n_ℓ = ∂p/∂n_ℓ, the solver's P_ℓ of (18.2) for the elastic gas.
TEST(RevisedEnskogFunctionals, GibbsDuhemGivesThePressureDerivative) {
  for (int d : {2, 3}) {
    gkt::Mixture m = gkt::make_mixture(d, {{1, 1, 0.3, ""}, {4, 1.6, 0.5, ""}, {0.4, 0.7, 0.2, ""}}, 1.0, 0.3);
    const auto mu = gkt::chemical_potential_derivatives(m);
    const auto p = gkt::MixtureNavierStokes(m, 1).coefficients(1).pressure_derivative;
    for (std::size_t l = 0; l < 3; ++l) EXPECT_NEAR(mu[l] + mu[3 + l] + mu[6 + l], p[l], 1e-13 * p[l]) << d << " " << l;
  }
}

TEST(RevisedEnskogFunctionals, VanishForEqualDiametersAndDiluteGas) {
  for (int d : {2, 3}) {
    for (double v : gkt::revised_enskog_functionals(binary(d, 0.3, 1.0, 0.4))) EXPECT_EQ(v, 0.0);
    for (double v : gkt::revised_enskog_functionals(binary(d, 0.0, 2.0, 0.4))) EXPECT_EQ(v, 0.0);
    // Continuous at φ → 0: I = O(φ) (the overlap lens of the exact first-order contact value is off
    // the midpoint; test ThirdVirialLens), so halving φ halves I to O(φ).
    const auto small = gkt::revised_enskog_functionals(binary(d, 1e-3, 2.0, 0.4));
    const auto half = gkt::revised_enskog_functionals(binary(d, 5e-4, 2.0, 0.4));
    for (std::size_t k = 0; k < small.size(); ++k) {
      EXPECT_LT(std::abs(small[k]), 1e-2);
      if (small[k] != 0) {
        EXPECT_NEAR(small[k] / half[k], 2, 0.01) << d << " " << k;
      }
    }
  }
}

// The rows i = 1, 2 give I_ℓ12 and I_ℓ21 separately; g_ij(r1, r2) = g_ji(r2, r1) needs
// x_1 I_ℓ12 + x_2 I_ℓ21 = 0, which holds only if the chemical potentials and the virial pressure of
// the closure are one thermodynamics (Gibbs–Duhem). I_ℓii = 0; the values are not small.
TEST(RevisedEnskogFunctionals, BinaryRowsAreAntisymmetric) {
  for (int d : {2, 3})
    for (double phi : {0.2, 0.45})
      for (double sigma2 : {0.5, 2.0, 5.0}) {
        const double x1 = 0.3;
        const auto f = gkt::revised_enskog_functionals(binary(d, phi, sigma2, x1));
        for (std::size_t l = 0; l < 2; ++l) {
          EXPECT_EQ(f[(0 * 2 + 0) * 2 + l], 0.0);
          EXPECT_EQ(f[(1 * 2 + 1) * 2 + l], 0.0);
          const double i12 = f[(0 * 2 + 1) * 2 + l], i21 = f[(1 * 2 + 0) * 2 + l];
          EXPECT_GT(std::abs(i12), 1e-3) << d << " " << phi << " " << sigma2;
          EXPECT_NEAR(x1 * i12 + (1 - x1) * i21, 0, 1e-12 * std::abs(i12)) << d << " " << phi << " " << sigma2;
        }
      }
}

// The tracer limit is continuous: x_1 = 0 and 1e-9 give the same I_ℓij (1e-8), and I_ℓ21 → 0 (to
// rounding: it is the host's row, a difference of O(1) terms).
TEST(RevisedEnskogFunctionals, TracerLimitIsContinuous) {
  for (int d : {2, 3}) {
    const auto zero = gkt::revised_enskog_functionals(binary(d, 0.3, 2.0, 0.0));
    const auto small = gkt::revised_enskog_functionals(binary(d, 0.3, 2.0, 1e-9));
    for (std::size_t k = 0; k < zero.size(); ++k)
      EXPECT_NEAR(zero[k], small[k], 1e-8 * std::max(1.0, std::abs(zero[k])));
    EXPECT_NEAR(zero[(1 * 2 + 0) * 2 + 0], 0.0, 1e-13);
    EXPECT_GT(std::abs(zero[(0 * 2 + 1) * 2 + 0]), 1e-3);
  }
}

// Three or more species (theory.md §18.12): (18.19) fixes s − 1 of the s(s−1)/2 antisymmetric K_ℓij per ℓ;
// each closure adds the gradient that makes it hold. For every closure: (18.19) to rounding for every i, ℓ
// (I = 0 misses it by > 1e-4, so the check can fail), x_i I_ℓij + x_j I_ℓji = 0, I_ℓii = 0, values not
// small; and the closures differ (what (18.19) leaves open is not nothing).
TEST(RevisedEnskogFunctionals, TernaryClosuresSatisfyTheChemicalPotentials) {
  for (int d : {2, 3})
    for (double phi : {0.1, 0.3, 0.45})
      for (const auto& sigma : std::vector<std::vector<double>>{{1, 1.5, 2}, {1, 0.4, 3}}) {
        const gkt::Mixture m = ternary(d, phi, sigma, {0.3, 0.4, 0.3});
        const std::string at = std::to_string(d) + " " + std::to_string(phi) + " " + std::to_string(sigma[1]);
        EXPECT_GT(chemical_potential_residual(m, std::vector<double>(27, 0.0)), 1e-4) << at;
        std::vector<std::vector<double>> all;
        for (auto closure : closures()) {
          const auto f = gkt::revised_enskog_functionals(m, closure);
          EXPECT_LT(chemical_potential_residual(m, f), 1e-12) << at;
          double largest = 0;
          for (double v : f) largest = std::max(largest, std::abs(v));
          EXPECT_GT(largest, 1e-3) << at;
          for (std::size_t l = 0; l < 3; ++l)
            for (std::size_t i = 0; i < 3; ++i) {
              EXPECT_EQ(f[(i * 3 + i) * 3 + l], 0.0);
              for (std::size_t j = 0; j < 3; ++j) {
                const double xi = m.species[i].fraction, xj = m.species[j].fraction;
                EXPECT_NEAR(xi * f[(i * 3 + j) * 3 + l] + xj * f[(j * 3 + i) * 3 + l], 0, 1e-14 * largest) << at;
              }
            }
          all.push_back(f);
        }
        double spread = 0;
        for (std::size_t k = 0; k < all[0].size(); ++k) spread = std::max(spread, std::abs(all[0][k] - all[2][k]));
        EXPECT_GT(spread, 1e-4) << at;
      }
}

// Species 2 and 3 identical (σ_1 ≠ σ_2 = σ_3) are the binary with them merged (x_B = x_2 + x_3): K_ℓ23 = 0,
// K_ℓ12 = K_ℓ13 and ∇n_2, ∇n_3 act as ∇n_B, so I_ℓ1k = I^bin_ℓ'1B x_k/x_B (k = 2, 3), I_ℓk1 = I^bin_ℓ'B1 and
// I_ℓ23 = 0, ℓ' the merged index. The binary is the exact (18.20), so every closure must reproduce it.
TEST(RevisedEnskogFunctionals, TernaryWithIdenticalSpeciesIsTheBinary) {
  for (int d : {2, 3})
    for (double phi : {0.2, 0.4}) {
      const std::vector<double> x{0.3, 0.25, 0.45};
      const gkt::Mixture three = ternary(d, phi, {1, 1.7, 1.7}, x);
      const auto b = gkt::revised_enskog_functionals(binary(d, phi, 1.7, 0.3));
      double scale = 0;
      for (double v : b) scale = std::max(scale, std::abs(v));
      for (auto closure : closures()) {
        const auto f = gkt::revised_enskog_functionals(three, closure);
        for (std::size_t l = 0; l < 3; ++l) {
          const std::size_t lb = l == 0 ? 0 : 1;
          for (std::size_t k = 1; k < 3; ++k) {
            EXPECT_NEAR(f[(0 * 3 + k) * 3 + l], b[(0 * 2 + 1) * 2 + lb] * x[k] / 0.7, 1e-10 * scale) << d << phi << l;
            EXPECT_NEAR(f[(k * 3 + 0) * 3 + l], b[(1 * 2 + 0) * 2 + lb], 1e-10 * scale) << d << phi << l;
          }
          EXPECT_NEAR(f[(1 * 3 + 2) * 3 + l], 0, 1e-12 * scale) << d << phi << l;
          EXPECT_NEAR(f[(2 * 3 + 1) * 3 + l], 0, 1e-12 * scale) << d << phi << l;
        }
      }
    }
}

// Equal diameters and φ = 0 give exactly 0; I = O(φ) as φ → 0 (halving φ = 1e-3 halves I to 1 %).
TEST(RevisedEnskogFunctionals, TernaryVanishForEqualDiametersAndDiluteGas) {
  for (int d : {2, 3}) {
    for (double v : gkt::revised_enskog_functionals(ternary(d, 0.3, {1.3, 1.3, 1.3}, {0.2, 0.3, 0.5})))
      EXPECT_EQ(v, 0.0);
    for (double v : gkt::revised_enskog_functionals(ternary(d, 0.0, {1, 1.5, 2}, {0.2, 0.3, 0.5}))) EXPECT_EQ(v, 0.0);
    const auto small = gkt::revised_enskog_functionals(ternary(d, 1e-3, {1, 1.5, 2}, {0.2, 0.3, 0.5}));
    const auto half = gkt::revised_enskog_functionals(ternary(d, 5e-4, {1, 1.5, 2}, {0.2, 0.3, 0.5}));
    for (std::size_t k = 0; k < small.size(); ++k) {
      EXPECT_LT(std::abs(small[k]), 1e-2);
      if (small[k] != 0) {
        EXPECT_NEAR(small[k] / half[k], 2, 0.01) << d << " " << k;
      }
    }
  }
}

// A tracer third species: x_3 = 0 and 1e-9 give the same I_ℓij (1e-8); at x_3 = 0 the hosts' rows of
// (18.19) no longer see species 3, so their I_ℓ12, I_ℓ21 (ℓ = 1, 2) are the binary's exact (18.20), the
// I_ℓi3 vanish (they carry n_3) and the tracer's I_ℓ3j are finite and not small.
TEST(RevisedEnskogFunctionals, TernaryTracerLimitIsContinuous) {
  for (int d : {2, 3}) {
    const auto zero = gkt::revised_enskog_functionals(ternary(d, 0.3, {1, 1.5, 2}, {0.4, 0.6, 0}));
    const auto small = gkt::revised_enskog_functionals(ternary(d, 0.3, {1, 1.5, 2}, {0.4, 0.6 - 1e-9, 1e-9}));
    for (std::size_t k = 0; k < zero.size(); ++k)
      EXPECT_NEAR(zero[k], small[k], 1e-8 * std::max(1.0, std::abs(zero[k]))) << d << " " << k;
    const auto b = gkt::revised_enskog_functionals(binary(d, 0.3, 1.5, 0.4));
    for (std::size_t l = 0; l < 2; ++l) {
      EXPECT_NEAR(zero[(0 * 3 + 1) * 3 + l], b[(0 * 2 + 1) * 2 + l], 1e-12 * std::abs(b[(0 * 2 + 1) * 2 + l])) << d;
      EXPECT_NEAR(zero[(1 * 3 + 0) * 3 + l], b[(1 * 2 + 0) * 2 + l], 1e-12 * std::abs(b[(1 * 2 + 0) * 2 + l])) << d;
    }
    for (std::size_t l = 0; l < 3; ++l)
      for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_EQ(zero[(i * 3 + 2) * 3 + l], 0.0);
        EXPECT_GT(std::abs(zero[(2 * 3 + i) * 3 + l]), 1e-3) << d << " " << i << l;
      }
  }
}

// An exact, independent route in 3D. To first order in density the contact value of a non-uniform
// fluid is g_ij(r1, r2) = 1 + Σ_ℓ ∫dr3 n_ℓ(r3) over the lens L_ijℓ where |r3 − r1| < σ_iℓ and
// |r3 − r2| < σ_jℓ (the Mayer term; BGHLM, like Percus–Yevick, is exact at this order). Expanding
// n_ℓ(r3) about the midpoint R gives the ∇n_ℓ part V_ijℓ (c_ijℓ − R)·∇n_ℓ, c the lens's centroid, so
// (18.18) at φ → 0 is I_ℓij = 2 n_j V_ijℓ (c_ijℓ − R)·σ̂/σ_ij: the lens sits off the midpoint when
// σ_i ≠ σ_j. The chemical-potential route (the third virial coefficient of the closure) must give it;
// at φ = 1e-6 the O(φ) remainder is ~1e-6 relative, so 1e-5.
TEST(RevisedEnskogFunctionals, ThirdVirialLens) {
  const double phi = 1e-6;
  for (double sigma2 : {0.3, 2.0, 4.0}) {
    const gkt::Mixture m = binary(3, phi, sigma2, 0.4);
    const auto f = gkt::revised_enskog_functionals(m);
    const std::vector<double> n = densities(m), sigma{1.0, sigma2};
    for (std::size_t i = 0; i < 2; ++i) {
      const std::size_t j = 1 - i;
      for (std::size_t l = 0; l < 2; ++l) {
        const double expected = mayer_lens_functional(sigma[i], sigma[j], sigma[l], n[j]);
        EXPECT_NEAR(f[(i * 2 + j) * 2 + l], expected, 1e-5 * std::abs(expected)) << sigma2 << " " << i << l;
      }
    }
  }
}

// The ternary at φ = 1e-6 (3D): the lens-centroid closure's reference is the Mayer term itself, so every
// I_ℓij equals the lens (1e-5, the O(φ) remainder); the gradient closure misses it (> 1 % somewhere) —
// the Mayer K_ℓij is not a gradient (K_ℓ12 + K_ℓ23 + K_ℓ31 ≠ 0), which is what (18.19) cannot see.
TEST(RevisedEnskogFunctionals, TernaryThirdVirialLens) {
  const gkt::Mixture m = ternary(3, 1e-6, {1, 1.5, 2}, {0.3, 0.4, 0.3});
  const std::vector<double> n = densities(m), sigma{1, 1.5, 2};
  const auto lens = gkt::revised_enskog_functionals(m, gkt::FunctionalClosure::lens_centroid);
  const auto gradient = gkt::revised_enskog_functionals(m, gkt::FunctionalClosure::gradient);
  double gradient_miss = 0;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) {
      if (i == j) continue;
      for (std::size_t l = 0; l < 3; ++l) {
        const double expected = mayer_lens_functional(sigma[i], sigma[j], sigma[l], n[j]);
        EXPECT_NEAR(lens[(i * 3 + j) * 3 + l], expected, 1e-5 * std::abs(expected)) << i << j << l;
        gradient_miss = std::max(gradient_miss, std::abs(gradient[(i * 3 + j) * 3 + l] / expected - 1));
      }
    }
  EXPECT_GT(gradient_miss, 1e-2);
}
