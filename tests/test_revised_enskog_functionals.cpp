// The thermodynamics of the revised Enskog mixture (theory.md §18.12): the chemical-potential
// derivatives against second differences of a free energy computed by another route (Simpson in λ
// of the pressure from Mixture::contact_values), Gibbs–Duhem against the solver's ∂p/∂n_l, and the
// functionals I_ℓij: zero for equal diameters, their two binary rows antisymmetric (Gibbs–Duhem
// again, the rows are computed separately), continuous in the tracer and dilute limits.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
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

gkt::Mixture binary(int d, double phi, double sigma2, double x1, double alpha = 1) {
  return gkt::make_mixture(d, {{1, 1, x1, ""}, {8, sigma2, 1 - x1, ""}}, alpha, phi);
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

TEST(RevisedEnskogFunctionals, RefusesMoreThanTwoSpecies) {
  gkt::Mixture m = gkt::make_mixture(3, {{1, 1, 0.3, ""}, {4, 1.6, 0.5, ""}, {0.4, 0.7, 0.2, ""}}, 1.0, 0.3);
  EXPECT_THROW((void)gkt::revised_enskog_functionals(m), std::invalid_argument);
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
      const double distance = 0.5 * (sigma[i] + sigma[j]);
      for (std::size_t l = 0; l < 2; ++l) {
        // Sphere A (radius σ_iℓ) at x = 0, sphere B (radius σ_jℓ) at x = σ_ij; the cross-section is
        // quadratic on each side of the plane x0 where the spheres meet, so one Simpson panel per side
        // integrates the volume and the first moment exactly.
        const double ra = 0.5 * (sigma[i] + sigma[l]), rb = 0.5 * (sigma[j] + sigma[l]);
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
        const double expected = 2 * n[j] * volume * (centroid - 0.5 * distance) / distance;
        EXPECT_NEAR(f[(i * 2 + j) * 2 + l], expected, 1e-5 * std::abs(expected)) << sigma2 << " " << i << l;
      }
    }
  }
}
