// Navier–Stokes coefficients of a dense (revised Enskog) granular mixture (theory.md §18): the
// contact values' density derivatives against finite differences, identical species against the
// one-component Enskog solver (itself tested against Garzó & Dufty and Chapman & Cowling), the
// conservation rows that the solver drops (they must hold whichever species' row is dropped), the
// bulk viscosity against the closed forms of Garzó, Dufty & Hrenya plus the partial-temperature
// term, and continuity at φ → 0.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "gkt/evolution/hcs_stability.hpp"
#include "gkt/transport/common/pair_correlation.hpp"
#include "gkt/transport/mixture/mixture.hpp"
#include "gkt/transport/mixture/mixture_navier_stokes.hpp"
#include "gkt/transport/mixture/mixture_transport_table.hpp"
#include "gkt/transport/mixture/revised_enskog_functionals.hpp"
#include "gkt/transport/monodisperse/navier_stokes.hpp"
#include "mixture_test_helpers.hpp"

using gkt::Rational;
using gkt::test::growing_modes;
using gkt::test::relative;

namespace {

/// The mixture with the partial densities n_k (fractions renormalised, the last one closing the sum
/// to 1 exactly) at the packing fraction that these densities give relative to `base` at n = 1.
gkt::Mixture at_densities(const gkt::Mixture& base, const std::vector<double>& n) {
  gkt::Mixture m = base;
  const int d = base.dimension;
  double total = 0, volume = 0, volume0 = 0;
  for (std::size_t k = 0; k < n.size(); ++k) {
    total += n[k];
    volume += n[k] * std::pow(base.species[k].diameter, d);
    volume0 += base.species[k].fraction * std::pow(base.species[k].diameter, d);
  }
  double sum = 0;
  for (std::size_t k = 0; k + 1 < n.size(); ++k) {
    m.species[k].fraction = n[k] / total;
    sum += m.species[k].fraction;
  }
  m.species.back().fraction = 1 - sum;
  m.packing_fraction = base.packing_fraction * volume / volume0;
  return m;
}

/// Returns B_k = π^{(d−1)/2} Γ((k+1)/2)/Γ((k+d)/2) of [garzo2007mixture] (seed 003 prints Γ((d+1)/2)).
double b_constant(int d, int k) {
  return std::pow(std::numbers::pi, (d - 1) / 2.0) * std::tgamma((k + 1) / 2.0) / std::tgamma((k + d) / 2.0);
}

/// Returns n = φ/(v_d Σ x_i σ_i^d) for the mixture's diameters as given (the tests' physical units).
double number_density(const gkt::Mixture& m) {
  const int d = m.dimension;
  double volume = 0;
  for (const auto& sp : m.species) volume += sp.fraction * std::pow(sp.diameter, d);
  const double v_d = std::pow(std::numbers::pi, d / 2.0) / (std::pow(2.0, d) * std::tgamma(d / 2.0 + 1));
  return m.packing_fraction / (v_d * volume);
}

/// Returns η0 = ((d+2)/(8c_d)) √(m̄T)/σ̄^{d−1}, c_d = π^{(d−1)/2}/Γ(d/2): the reduction of η* and κ*.
double reference_viscosity(const gkt::Mixture& m, double temperature) {
  const int d = m.dimension;
  const double c_d = std::pow(std::numbers::pi, (d - 1) / 2.0) / std::tgamma(d / 2.0);
  return (d + 2) / (8 * c_d) * std::sqrt(m.mean_mass() * temperature) / std::pow(m.mean_diameter(), d - 1);
}

/// Returns the pair (i, j)'s term of GDH's collisional bulk viscosity
/// κ^c = (B_3(d+1)/(2d²)) Σ_ij m_j μ_ij (1+α_ij) χ_ij σ_ij^{d+1} n_i n_j ⟨g_ij⟩, ⟨g_ij⟩ over Maxwellians at γ_i T.
double gdh_bulk_viscosity_pair(const gkt::Mixture& m, const std::vector<double>& gamma, double n, double temperature,
                               std::size_t i, std::size_t j) {
  const int d = m.dimension;
  const std::size_t s = m.size();
  const double mi = m.species[i].mass.value(), mj = m.species[j].mass.value(), mu_ij = mi / (mi + mj);
  const double sigma = 0.5 * (m.species[i].diameter + m.species[j].diameter);
  const double g = std::tgamma((d + 1) / 2.0) / std::tgamma(d / 2.0) *
                   std::sqrt(2 * gamma[i] * temperature / mi + 2 * gamma[j] * temperature / mj);
  return b_constant(d, 3) * (d + 1) / (2.0 * d * d) * mj * mu_ij * (1 + m.restitution(i, j)) *
         m.contact_values()[i * s + j] * std::pow(sigma, d + 1) * n * m.species[i].fraction * n *
         m.species[j].fraction * g;
}

gkt::Mixture ternary(int d, double phi) {
  gkt::Mixture m = gkt::make_mixture(d, {{1, 1, 0.3, ""}, {4, 1.6, 0.5, ""}, {0.4, 0.7, 0.2, ""}}, 0.7, phi);
  m.alpha = {0.9, 0.7, 0.6, 0.7, 0.5, 0.8, 0.6, 0.8, 0.95};
  return m;
}

}  // namespace

// n ∂χ_ij/∂n_l of the BGHLM (3D) and Jenkins–Mancini (2D) closures against central differences
// of contact_values() in the partial densities (h = 1e-5: truncation ~1e-10).
TEST(MixtureEnskog, ContactValueDerivativesEqualFiniteDifferences) {
  for (int d : {2, 3}) {
    const gkt::Mixture base = ternary(d, 0.35);
    const auto exact = base.contact_value_derivatives();
    for (std::size_t l = 0; l < 3; ++l) {
      const double h = 1e-5;
      std::vector<double> up{0.3, 0.5, 0.2}, down = up;
      up[l] += h;
      down[l] -= h;
      const auto cu = at_densities(base, up).contact_values(), cd = at_densities(base, down).contact_values();
      for (std::size_t ij = 0; ij < 9; ++ij)
        EXPECT_NEAR(exact[ij * 3 + l], (cu[ij] - cd[ij]) / (2 * h), 1e-8) << d << " " << ij << " " << l;
    }
  }
}

// Dense HCS: n ∂ln γ_i/∂n_j and n ∂ζ/∂n_j/ν0 by implicit differentiation (now with the contact
// values moving) against central differences of the HCS itself.
TEST(MixtureEnskog, CoolingStateSensitivityEqualsFiniteDifferences) {
  for (int d : {2, 3}) {
    const gkt::Mixture base = ternary(d, 0.3);
    const auto sens = gkt::mixture_cooling_sensitivity(base, gkt::mixture_cooling_state(base));
    // ζ in units fixed at the base state: ζ* ν0 ∝ ζ* n σ̄^{d−1}/√m̄.
    auto at = [&](const std::vector<double>& n, std::vector<double>& gamma) {
      const gkt::Mixture m = at_densities(base, n);
      const auto s = gkt::mixture_cooling_state(m);
      gamma = s.temperature_ratio;
      return s.cooling_rate * (n[0] + n[1] + n[2]) * std::pow(m.mean_diameter(), d - 1) / std::sqrt(m.mean_mass());
    };
    const double unit = std::pow(base.mean_diameter(), d - 1) / std::sqrt(base.mean_mass());
    for (std::size_t j = 0; j < 3; ++j) {
      const double h = 1e-5;
      std::vector<double> up{0.3, 0.5, 0.2}, down = up, gu, gd;
      up[j] += h;
      down[j] -= h;
      EXPECT_NEAR(sens.cooling_rate[j], (at(up, gu) - at(down, gd)) / (2 * h) / unit, 1e-8) << d << " " << j;
      for (std::size_t i = 0; i < 3; ++i)
        EXPECT_NEAR(sens.temperature_ratio[i * 3 + j], (std::log(gu[i]) - std::log(gd[i])) / (2 * h), 1e-8);
    }
  }
}

// Identical species at φ > 0: η*, λ*, Σ_j D''_j* (= μ*), bulk viscosity, ζ_U and p* equal the
// one-component Enskog solver about the Maxwellian HCS (a separate assembly from the one-species
// collisional-transfer tables of theory.md §15) at every order; D^T_i and the first-order partial
// temperatures vanish.
TEST(MixtureEnskog, IdenticalSpeciesGiveOneComponentEnskog) {
  for (int d : {2, 3}) {
    gkt::NavierStokesSolver one(d);
    const auto& closure = gkt::pair_correlation("carnahan-starling");
    for (double phi : {0.1, 0.4})
      for (double alpha : {1.0, 0.8, 0.5, 0.2}) {
        const gkt::MixtureNavierStokes ns(gkt::make_mixture(d, {{1, 1, 0.3, ""}, {1, 1, 0.7, ""}}, alpha, phi), 3);
        const Rational exact_phi = Rational::from_double(phi);
        const gkt::EnskogState dense{phi, closure.contact_value(d, exact_phi).to_double(),
                                     closure.packing_derivative(d, exact_phi).to_double()};
        for (int order = 1; order <= 3; ++order) {
          const auto v = ns.coefficients(order);
          const auto o =
              one.solve(Rational::from_double(alpha), order, {1.0, 0.0, 0.0}, gkt::SonineScheme::standard, dense);
          const std::string at = std::to_string(d) + " " + std::to_string(phi) + " " + std::to_string(alpha);
          EXPECT_LT(relative(v.shear_viscosity, o.shear_viscosity), 1e-12) << at << " " << order;
          EXPECT_LT(relative(v.thermal_conductivity, o.thermal_conductivity), 1e-12) << at;
          EXPECT_LT(relative(v.dufour[0] + v.dufour[1], o.density_heat_coefficient), 1e-12) << at;
          EXPECT_LT(relative(v.bulk_viscosity, o.bulk_viscosity), 1e-12) << at;
          EXPECT_LT(relative(v.cooling_rate_first_order, o.cooling_rate_first_order), 1e-12) << at;
          EXPECT_LT(relative(v.pressure, dense.pressure(d, alpha)), 1e-13) << at;
          EXPECT_LT(std::abs(v.thermal_diffusion[0]) + std::abs(v.thermal_diffusion[1]), 1e-13) << at;
          EXPECT_LT(std::abs(v.temperature_first_order[0]) + std::abs(v.temperature_first_order[1]), 1e-12) << at;
        }
      }
  }
}

// The solver replaces one row of each conservation law by a constraint: the momentum row of the
// vector modes (total momentum zero) and the total-energy row of the ∇·u mode (Σ_i n_i T_i^(1) = 0),
// always that of the first most abundant species. With equal fractions, listing the species in the
// other order drops the other species' row; the coefficients agree only if the dropped rows hold,
// i.e. only if the collisional-transfer sources carry exactly −∇p^c (momentum) and the work and
// cooling terms close the energy balance (ζ_U). Binary and ternary, d = 2, 3, restitution matrix.
TEST(MixtureEnskog, DroppedConservationRowsHold) {
  for (int d : {2, 3})
    for (double alpha : {1.0, 0.7}) {
      gkt::Mixture m = gkt::make_mixture(d, {{1, 1, 0.5, ""}, {3, 1.6, 0.5, ""}}, alpha, 0.25);
      m.alpha = {alpha, 0.9 * alpha, 0.9 * alpha, 0.8 * alpha};
      gkt::Mixture r = gkt::make_mixture(d, {{3, 1.6, 0.5, ""}, {1, 1, 0.5, ""}}, alpha, 0.25);
      r.alpha = {0.8 * alpha, 0.9 * alpha, 0.9 * alpha, alpha};
      const auto a = gkt::MixtureNavierStokes(m, 2).coefficients(2), b = gkt::MixtureNavierStokes(r, 2).coefficients(2);
      EXPECT_LT(relative(a.shear_viscosity, b.shear_viscosity), 1e-12) << d << " " << alpha;
      EXPECT_LT(relative(a.thermal_conductivity, b.thermal_conductivity), 1e-12);
      EXPECT_LT(relative(a.bulk_viscosity, b.bulk_viscosity), 1e-12);
      EXPECT_LT(relative(a.cooling_rate_first_order, b.cooling_rate_first_order), 1e-12);
      EXPECT_GT(std::abs(a.temperature_first_order[0]), 1e-3);  // the energy row is not trivially satisfied
      for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_LT(relative(a.thermal_diffusion[i], b.thermal_diffusion[1 - i]), 1e-12);
        EXPECT_LT(relative(a.dufour[i], b.dufour[1 - i]), 1e-12);
        EXPECT_LT(relative(a.temperature_first_order[i], b.temperature_first_order[1 - i]), 1e-11);
        for (std::size_t j = 0; j < 2; ++j)
          EXPECT_LT(relative(a.mutual_diffusion[i * 2 + j], b.mutual_diffusion[(1 - i) * 2 + 1 - j]), 1e-12);
      }
    }
}

// Bulk viscosity of an unequal binary against closed forms: Garzó, Dufty & Hrenya's collisional
// κ^c = (B_3(d+1)/(2d²)) Σ_ij m_j μ_ij (1+α_ij) χ_ij σ_ij^{d+1} n_i n_j ⟨g_ij⟩ (PRE 76, 031303
// (2007); seed 003, with B_k = π^{(d−1)/2} Γ((k+1)/2)/Γ((k+d)/2) — the seed's OCR has Γ((d+1)/2)), plus
// the pressure of the first-order partial temperatures, −B_2 Σ_ij μ_ji (1+α_ij) σ_ij^d χ_ij n_i n_j T ϖ_i
// (per ∇·u/ν0), which GDH 2007 leave out. Exact relations; tolerance 1e-12.
TEST(MixtureEnskog, BulkViscosityEqualsClosedForms) {
  for (int d : {2, 3})
    for (double phi : {0.15, 0.35}) {
      gkt::Mixture m = gkt::make_mixture(d, {{1, 1, 0.35, ""}, {2.5, 1.5, 0.65, ""}}, 0.8, phi);
      m.alpha = {0.9, 0.75, 0.75, 0.6};
      const gkt::MixtureNavierStokes ns(m, 3);
      const auto v = ns.coefficients(3);
      const auto& gamma = ns.cooling_state().temperature_ratio;
      const auto chi = m.contact_values();
      const double T = 1, n = number_density(m), eta0 = reference_viscosity(m, T);
      double kappa = 0, partial = 0;
      for (std::size_t i = 0; i < 2; ++i)
        for (std::size_t j = 0; j < 2; ++j) {
          const double mi = m.species[i].mass.value(), mj = m.species[j].mass.value(), mu_ji = mj / (mi + mj);
          const double sigma = 0.5 * (m.species[i].diameter + m.species[j].diameter), a = m.restitution(i, j);
          const double ni = n * m.species[i].fraction, nj = n * m.species[j].fraction;
          kappa += gdh_bulk_viscosity_pair(m, gamma, n, T, i, j);
          partial -= b_constant(d, 2) * mu_ji * (1 + a) * std::pow(sigma, d) * chi[i * 2 + j] * ni * nj * T *
                     v.temperature_first_order[i] / (n * T / eta0);
        }
      EXPECT_GT(std::abs(partial), 1e-3 * kappa) << d << " " << phi;  // the partial temperatures do contribute
      EXPECT_LT(relative(v.bulk_viscosity, (kappa + partial) / eta0), 1e-12) << d << " " << phi;
    }
}

// φ → 0 is continuous: φ = 1e-9 equals the dilute (Boltzmann) coefficients to 1e-7; the dense-only
// quantities go to their dilute values (bulk viscosity and ζ_U to 0, p* to 1).
TEST(MixtureEnskog, DiluteLimitIsContinuous) {
  for (int d : {2, 3}) {
    gkt::Mixture m = ternary(d, 0);
    const auto dilute = gkt::MixtureNavierStokes(m, 2).coefficients(2);
    m.packing_fraction = 1e-9;
    const auto dense = gkt::MixtureNavierStokes(m, 2).coefficients(2);
    EXPECT_LT(relative(dense.shear_viscosity, dilute.shear_viscosity), 1e-7) << d;
    EXPECT_LT(relative(dense.thermal_conductivity, dilute.thermal_conductivity), 1e-7);
    for (std::size_t k = 0; k < 9; ++k)
      EXPECT_LT(relative(dense.mutual_diffusion[k], dilute.mutual_diffusion[k]), 1e-7);
    for (std::size_t k = 0; k < 3; ++k) {
      EXPECT_LT(relative(dense.thermal_diffusion[k], dilute.thermal_diffusion[k]), 1e-7);
      EXPECT_LT(relative(dense.dufour[k], dilute.dufour[k]), 1e-7);
    }
    EXPECT_LT(std::abs(dense.bulk_viscosity) + std::abs(dense.cooling_rate_first_order), 1e-7);
    EXPECT_LT(std::abs(dense.pressure - 1), 1e-8);
  }
}

// Hard cases at φ = 0.4 (3D) / 0.6 (2D): mass ratios 10^±3 with diameter ratios 0.1 and 10
// (α = 0.5) give finite coefficients, positive η*, λ*, bulk viscosity, and orders 2 → 3 move η* by
// less than 2 %.
TEST(MixtureEnskog, ExtremeRatiosStayFinite) {
  for (int d : {2, 3})
    for (double mass : {1e-3, 1e3})
      for (double size : {0.1, 10.0}) {
        const gkt::Mixture m = gkt::make_mixture(d, {{1, 1, 0.5, ""}, {mass, size, 0.5, ""}}, 0.5, d == 3 ? 0.4 : 0.6);
        const gkt::MixtureNavierStokes ns(m, 3);
        const auto v2 = ns.coefficients(2), v3 = ns.coefficients(3);
        EXPECT_GT(v3.shear_viscosity, 0) << d << " " << mass << " " << size;
        EXPECT_GT(v3.thermal_conductivity, 0);
        EXPECT_GT(v3.bulk_viscosity, 0);
        EXPECT_TRUE(std::isfinite(v3.cooling_rate_first_order));
        for (double x : v3.mutual_diffusion) EXPECT_TRUE(std::isfinite(x));
        EXPECT_LT(relative(v2.shear_viscosity, v3.shear_viscosity), 0.02) << d << " " << mass << " " << size;
      }
}

// Dense segregation criterion (theory.md (18.10)): identical species do not segregate (Λ = 0 for
// any g*), and an intruder's Λ is the limit x_1 → 0 (x_1 = 0 and 1e-8 agree to 1e-6).
TEST(MixtureEnskog, ThermalDiffusionFactor) {
  for (int d : {2, 3})
    for (double alpha : {1.0, 0.7}) {
      const auto same =
          gkt::MixtureNavierStokes(gkt::make_mixture(d, {{1, 1, 0.3, ""}, {1, 1, 0.7, ""}}, alpha, 0.3), 2)
              .coefficients(2);
      for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_LT(std::abs(same.segregation[i]), 1e-12) << d << " " << alpha;
        EXPECT_LT(std::abs(same.segregation_gravity[i]), 1e-12);
      }
      auto intruder = [&](double x1) {
        return gkt::MixtureNavierStokes(gkt::make_mixture(d, {{4, 2, x1, ""}, {1, 1, 1 - x1, ""}}, alpha, 0.3), 2)
            .coefficients(2);
      };
      const auto zero = intruder(0), small = intruder(1e-8);
      EXPECT_GT(std::abs(zero.segregation[0]), 0.05) << d << " " << alpha;
      EXPECT_LT(relative(small.segregation[0], zero.segregation[0]), 1e-6) << d << " " << alpha;
      EXPECT_LT(relative(small.segregation_gravity[0], zero.segregation_gravity[0]), 1e-6);
    }
}

// Reciprocity of the elastic dense mixture. The elastic Enskog operator is symmetric in
// ⟨X, Y⟩ = Σ_i ∫X_i Y_i/f_i, so ⟨ℬ^l, S^𝒜⟩ = ⟨𝒜, S^l⟩. For equal-temperature Maxwellians the adjoint of
// the ∇T transfer source is −q^c(f^(1))/T (the collisional heat flux) and that of the ∇n_l source is
// −2B_2 Σ_ij σ_ij^d χ_ij [δ_jl + ½(n_j ∂_l ln χ_ij + I_lij)] × (number flux of species i), since
// ∫dv2 dσ̂ Θ(σ̂·g)(σ̂·g) σ̂ f_j(v2) = B_2 n_j V1 and the same with (2θ_j V2² − d) vanishes; by (18.19) the
// sum over j is ∂(μ_i/T)/∂n_l − δ_il/n_i. With ⟨⟨ΔE_1⟩⟩ = 0 (equal temperatures) this gives, at every
// Galerkin order, the Onsager relation in the forces ∇(μ_i/T) (theory.md (18.12)):
//     T D''_l/n_l − (d/2)(m_l/ρ) Σ_i D_il = Σ_i (ρ D^T_i/m_i) ∂(μ_i/T)/∂n_l.
// Nothing in the assembly imposes it: it ties the K sources, the collisional heat flux (unequal
// masses), p, ∂p/∂n_l and the I_lij of (18.19) together. Unequal masses and diameters; binary and ternary.
TEST(MixtureEnskog, ElasticReciprocity) {
  const double T = 1;
  for (int d : {2, 3})
    for (double phi : {0.2, 0.35})
      for (double s2 : {1.0, 1.7, 0.0}) {
        // s2 = 0: a ternary with three diameters, its I_ℓij closed as in theory.md §18.12 (every
        // closure satisfies (18.19), which is all the elastic sources see).
        const gkt::Mixture m =
            s2 > 0 ? gkt::make_mixture(d, {{1, 1, 0.4, ""}, {3.5, s2, 0.6, ""}}, 1.0, phi)
                   : gkt::make_mixture(d, {{1, 1, 0.3, ""}, {3.5, 1.7, 0.45, ""}, {0.6, 0.6, 0.25, ""}}, 1.0, phi);
        const std::size_t s = m.size();
        const gkt::MixtureNavierStokes ns(m, 3);
        const double n = number_density(m), mbar = m.mean_mass(), eta0 = reference_viscosity(m, T);
        // κ0 = (d(d+2)/(2(d−1))) η0/m̄ and D0 = (2d/(d+2)) η0/(ρ) (docs/conventions.md).
        const double kappa0 = d * (d + 2) / (2.0 * (d - 1)) * eta0 / mbar;
        const double d0 = 2.0 * d / (d + 2) * eta0 / (n * mbar);
        const double rho = n * mbar;
        const auto mu = gkt::chemical_potential_derivatives(m);  // n_i ∂(μ_i/T)/∂n_l
        for (int order : {1, 3}) {
          const auto v = ns.coefficients(order);
          for (std::size_t l = 0; l < s; ++l) {
            const double ml = m.species[l].mass.value(), nl = n * m.species[l].fraction;
            double lhs = v.dufour[l] * kappa0 / nl, rhs = 0, scale = std::abs(lhs);
            for (std::size_t i = 0; i < s; ++i) {
              const double term = d / 2.0 * ml / rho * v.mutual_diffusion[i * s + l] * n * d0;
              lhs -= term;
              scale += std::abs(term);
              rhs += rho * v.thermal_diffusion[i] * d0 / m.species[i].mass.value() * mu[i * s + l] /
                     (n * m.species[i].fraction);
            }
            // Ternary: relative to the largest term (one side may nearly cancel).
            EXPECT_LT(std::abs(lhs - rhs), 1e-12 * (s == 2 ? std::abs(lhs) : scale))
                << d << " " << phi << " " << s2 << " " << order << " " << l;
          }
        }
      }
}

// Species 2 and 3 identical (mass, diameter, restitution) with σ_1 ≠ σ_2: the dense ternary is the binary
// with them merged (x_B = x_2 + x_3) at every order, α < 1 — species 1's fluxes, the summed fluxes of 2 and
// 3 (D_2j + D_3j = D_Bj', D^T, D^p alike), the heat flux per ∇n_k (D''_k/x_k = D''_B/x_B) and the scalars.
// Both sides carry I_ℓij: the binary its exact (18.20), the ternary the closure of theory.md §18.12 (with
// I = 0 in the ternary D_12* misses by ~1e-2).
TEST(MixtureEnskog, TernaryWithIdenticalSpeciesIsTheBinary) {
  for (int d : {2, 3})
    for (double phi : {0.1, 0.35}) {
      gkt::Mixture two = gkt::make_mixture(d, {{1, 1, 0.3, ""}, {3, 1.7, 0.7, ""}}, 0.8, phi);
      two.alpha = {0.9, 0.75, 0.75, 0.6};
      gkt::Mixture three = gkt::make_mixture(d, {{1, 1, 0.3, ""}, {3, 1.7, 0.25, ""}, {3, 1.7, 0.45, ""}}, 0.8, phi);
      three.alpha = {0.9, 0.75, 0.75, 0.75, 0.6, 0.6, 0.75, 0.6, 0.6};
      const gkt::MixtureNavierStokes nb(two, 2), nt(three, 2);
      const std::vector<double> x{0.3, 0.25, 0.45};
      for (int order : {1, 2}) {
        const auto b = nb.coefficients(order), t = nt.coefficients(order);
        const std::string at = std::to_string(d) + " " + std::to_string(phi) + " " + std::to_string(order);
        EXPECT_LT(relative(t.shear_viscosity, b.shear_viscosity), 1e-10) << at;
        EXPECT_LT(relative(t.thermal_conductivity, b.thermal_conductivity), 1e-10) << at;
        EXPECT_LT(relative(t.bulk_viscosity, b.bulk_viscosity), 1e-10) << at;
        EXPECT_LT(relative(t.cooling_rate_first_order, b.cooling_rate_first_order), 1e-10) << at;
        EXPECT_LT(relative(t.pressure, b.pressure), 1e-10) << at;
        for (std::size_t j = 0; j < 3; ++j) {
          const std::size_t jb = j == 0 ? 0 : 1;
          EXPECT_LT(relative(t.mutual_diffusion[j], b.mutual_diffusion[jb]), 1e-10) << at << " " << j;
          EXPECT_LT(relative(t.mutual_diffusion[3 + j] + t.mutual_diffusion[6 + j], b.mutual_diffusion[2 + jb]), 1e-10)
              << at << " " << j;
        }
        EXPECT_LT(relative(t.thermal_diffusion[0], b.thermal_diffusion[0]), 1e-10) << at;
        EXPECT_LT(relative(t.thermal_diffusion[1] + t.thermal_diffusion[2], b.thermal_diffusion[1]), 1e-10) << at;
        EXPECT_LT(relative(t.pressure_diffusion[0], b.pressure_diffusion[0]), 1e-10) << at;
        EXPECT_LT(relative(t.pressure_diffusion[1] + t.pressure_diffusion[2], b.pressure_diffusion[1]), 1e-10) << at;
        EXPECT_LT(relative(t.dufour[0], b.dufour[0]), 1e-10) << at;
        for (std::size_t k = 1; k < 3; ++k) EXPECT_LT(relative(t.dufour[k] / x[k], b.dufour[1] / 0.7), 1e-10) << at;
      }
    }
}

// A tracer third species (x_3 = 0 against 1e-9, three diameters, α < 1): D_ij*, D''_i*, D^T_i* continuous
// to 1e-6 with the I_ℓij of §18.12 (the closure's rows are regular at n_3 = 0).
TEST(MixtureEnskog, TernaryTracerLimitIsContinuous) {
  for (int d : {2, 3}) {
    auto at = [&](double x3) {
      gkt::Mixture m = gkt::make_mixture(d, {{1, 1, 0.4, ""}, {2.5, 1.5, 0.6 - x3, ""}, {4, 2, x3, ""}}, 0.8, 0.3);
      return gkt::MixtureNavierStokes(m, 2).coefficients(2);
    };
    const auto zero = at(0), small = at(1e-9);
    for (std::size_t k = 0; k < 9; ++k)
      EXPECT_LT(relative(small.mutual_diffusion[k], zero.mutual_diffusion[k]), 1e-6) << d << " " << k;
    for (std::size_t i = 0; i < 3; ++i) {
      EXPECT_LT(relative(small.dufour[i], zero.dufour[i]), 1e-6) << d << " " << i;
      EXPECT_LT(relative(small.thermal_diffusion[i], zero.thermal_diffusion[i]), 1e-6) << d << " " << i;
    }
  }
}

// HCS stability of the dense mixture (theory.md (18.13)): identical species reproduce the
// one-component dense analysis (14.4)–(14.5) with the one-component Enskog coefficients; for an
// unequal binary and a ternary one growing mode disappears between 0.99 k∥c* and 1.01 k∥c*, where
// M has an eigenvalue below 1e-8.
TEST(MixtureEnskog, HcsStability) {
  const auto& closure = gkt::pair_correlation("carnahan-starling");
  for (int d : {2, 3}) {
    gkt::NavierStokesSolver one(d);
    const double phi = 0.25;
    const Rational exact_phi = Rational::from_double(phi);
    const double chi = closure.contact_value(d, exact_phi).to_double();
    const double phi_dchi = closure.packing_derivative(d, exact_phi).to_double();
    for (double alpha : {0.9, 0.6}) {
      const gkt::Mixture same = gkt::make_mixture(d, {{1, 1, 0.4, ""}, {1, 1, 0.6, ""}}, alpha, phi);
      const gkt::MixtureNavierStokes ns(same, 2);
      const auto v = ns.coefficients(2);
      const gkt::EnskogState dense{phi, chi, phi_dchi};
      const auto o = one.solve(Rational::from_double(alpha), 2, {1.0, 0.0, 0.0}, gkt::SonineScheme::standard, dense);
      const double factor = d == 3 ? 2.0 : 1.0;
      const gkt::StabilityDensity density{dense.pressure(d, alpha), factor * (1 + alpha) * phi * (chi + phi_dchi),
                                          phi_dchi / chi, o.bulk_viscosity, o.cooling_rate_first_order};
      const double zeta = chi * (d + 2) * (1 - alpha * alpha) / (4.0 * d);
      const auto expected =
          gkt::hcs_stability(d, zeta, o.shear_viscosity, o.thermal_conductivity, o.density_heat_coefficient, density);
      const auto got = gkt::mixture_hcs_stability(gkt::mixture_stability_input(same, ns, v));
      ASSERT_GT(expected.heat_wavenumber, 0.05) << d << " " << alpha;
      EXPECT_LT(relative(got.shear_wavenumber, expected.shear_wavenumber), 1e-12) << d << " " << alpha;
      EXPECT_LT(relative(got.heat_wavenumber, expected.heat_wavenumber), 1e-9) << d << " " << alpha;
    }
    gkt::Mixture binary = gkt::make_mixture(d, {{1, 1, 0.4, ""}, {3, 1.5, 0.6, ""}}, 0.7, phi);
    gkt::Mixture three = gkt::make_mixture(d, {{1, 1, 0.5, ""}, {1.5, 0.8, 0.3, ""}, {4, 2, 0.2, ""}}, 0.7, phi);
    for (const gkt::Mixture& m : {binary, three}) {
      const gkt::MixtureNavierStokes ns(m, 2);
      const auto in = gkt::mixture_stability_input(m, ns, ns.coefficients(2));
      const auto st = gkt::mixture_hcs_stability(in);
      ASSERT_GT(st.heat_wavenumber, 0.05) << d << " " << m.size();
      EXPECT_EQ(growing_modes(gkt::mixture_longitudinal_matrix(in, 0.99 * st.heat_wavenumber)),
                growing_modes(gkt::mixture_longitudinal_matrix(in, 1.01 * st.heat_wavenumber)) + 1)
          << d << " " << m.size();
      double smallest = INFINITY;
      for (const auto& e : gkt::mixture_longitudinal_matrix(in, st.heat_wavenumber).eigenvalues())
        smallest = std::min(smallest, std::abs(e));
      EXPECT_LT(smallest, 1e-8) << d << " " << m.size();
    }
  }
}

// The per-state table of a dense binary (theory.md §18.10): between its nodes in x_1 and φ it
// reproduces direct solves within 10× its own measured interpolation error (a coarse 12 × 6 grid keeps
// the test short; the benchmark's 24 × 12 grid is in docs/performance.md); φ follows n through
// φ = n v_d Σ x_i σ_i^d; the physical pressure is p* n T; above φ_max every value is nan.
TEST(MixtureEnskog, BinaryTransportTable) {
  const int d = 3;
  const gkt::Mixture m = gkt::make_mixture(d, {{1, 1, 0.5, ""}, {3, 1.5, 0.5, ""}}, 0.7);
  const gkt::BinaryTransportTable table(m, 1, 12, 0.3, 6);
  EXPECT_LT(table.interpolation_error(), 1e-3);
  const double tolerance = 10 * table.interpolation_error() + 1e-13, temperature = 1.3;
  for (const auto& [x1, phi] : std::vector<std::pair<double, double>>{{0.21, 0.05}, {0.64, 0.17}, {0.93, 0.28}}) {
    gkt::Mixture direct = m;
    direct.species[0].fraction = x1;
    direct.species[1].fraction = 1 - x1;
    direct.packing_fraction = phi;
    const auto v = gkt::MixtureNavierStokes(direct, 1).coefficients(1);
    const double volume = std::numbers::pi / 6 * (x1 + (1 - x1) * 1.5 * 1.5 * 1.5);
    const double n = phi / volume, mbar = x1 + 3 * (1 - x1), sbar = x1 + 1.5 * (1 - x1);
    const auto t = table.evaluate(x1, n, temperature);
    const double eta0 = 5 / (16 * std::sqrt(std::numbers::pi)) * std::sqrt(mbar * temperature) / (sbar * sbar);
    const double d0 = 3 / (8 * n * sbar * sbar) * std::sqrt(temperature / (std::numbers::pi * mbar));
    EXPECT_NEAR(t.shear_viscosity / eta0, v.shear_viscosity, tolerance * std::max(1.0, v.shear_viscosity)) << x1;
    EXPECT_NEAR(t.bulk_viscosity / eta0, v.bulk_viscosity, tolerance * std::max(1.0, v.bulk_viscosity)) << x1;
    EXPECT_NEAR(t.mutual_diffusion[1] / (n * d0), v.mutual_diffusion[1],
                tolerance * std::max(1.0, std::abs(v.mutual_diffusion[1])));
    EXPECT_NEAR(t.pressure / (n * temperature), v.pressure, tolerance * v.pressure) << x1;
    EXPECT_NEAR(t.cooling_rate_first_order, v.cooling_rate_first_order, tolerance) << x1;
  }
  EXPECT_TRUE(std::isnan(table.evaluate(0.5, 0.31 / (std::numbers::pi / 6 * (0.5 + 0.5 * 3.375)), 1).shear_viscosity));
}

// External-force coefficients L_ij (theory.md (18.14)): Σ_i L_ij = 0 (no net mass flux) and
// Σ_j L_ij m_j = 0 (a uniform gravitational field drives no diffusion), dilute and dense; for the
// dilute elastic gas a force F_j acts like −T∇ln n_j (Einstein), L_ij* = −x_j m_i m_j D_ij* (masses in m̄),
// at every order — the force system has its own ζ term, so inelastic gases depart from it.
TEST(MixtureEnskog, ForceMobility) {
  for (int d : {2, 3})
    for (double phi : {0.0, 0.25})
      for (double alpha : {1.0, 0.7}) {
        const gkt::Mixture m = gkt::make_mixture(d, {{1, 1, 0.3, ""}, {3, 1.4, 0.7, ""}}, alpha, phi);
        const gkt::MixtureNavierStokes ns(m, 3);
        const double mbar = m.mean_mass(), mass[2] = {1 / mbar, 3 / mbar}, x[2] = {0.3, 0.7};
        for (int order : {1, 3}) {
          const auto v = ns.coefficients(order);
          for (std::size_t j = 0; j < 2; ++j) {
            EXPECT_LT(std::abs(v.mobility[j] + v.mobility[2 + j]), 1e-12 * std::abs(v.mobility[j])) << d << " " << phi;
            EXPECT_LT(std::abs(v.mobility[j * 2] * mass[0] + v.mobility[j * 2 + 1] * mass[1]),
                      1e-12 * std::abs(v.mobility[j * 2]));
          }
          if (phi > 0) continue;
          for (std::size_t i = 0; i < 2; ++i)
            for (std::size_t j = 0; j < 2; ++j) {
              const double einstein = -x[j] * mass[i] * mass[j] * v.mutual_diffusion[i * 2 + j];
              if (alpha == 1.0)
                EXPECT_LT(std::abs(v.mobility[i * 2 + j] / einstein - 1), 1e-12) << d << " " << order << " " << i << j;
              else
                EXPECT_GT(std::abs(v.mobility[i * 2 + j] / einstein - 1), 1e-3) << d << " " << order << " " << i << j;
            }
        }
      }
}

// The heat flux per external force, L_j of q ∋ −Σ_j L_j F_j (GDH's Σ_i L_ij; theory.md (18.15)). In the
// dilute elastic gas a force F_j acts like −T∇ln n_j (the sources of (18.14) and (17.6) then coincide),
// so L_j* = −D''_j* at every order — two different solves (force mode with ζ(D + M), density mode with
// its ∂ζ/∂n_j source) that meet only at α = 1; a uniform gravitational field (F_j = m_j g) drives no
// heat flux, Σ_j L_j m_j = 0, dilute and dense. Inelastic gases depart from −D''_j* by more than 10⁻³.
TEST(MixtureEnskog, HeatFluxPerForce) {
  for (int d : {2, 3})
    for (double phi : {0.0, 0.25})
      for (double alpha : {1.0, 0.7}) {
        const gkt::Mixture m = gkt::make_mixture(d, {{1, 1, 0.3, ""}, {3, 1.4, 0.7, ""}}, alpha, phi);
        const gkt::MixtureNavierStokes ns(m, 3);
        const double mbar = m.mean_mass(), mass[2] = {1 / mbar, 3 / mbar};
        for (int order : {1, 2, 3}) {
          const auto v = ns.coefficients(order);
          ASSERT_EQ(v.heat_mobility.size(), 2U);
          EXPECT_LT(std::abs(v.heat_mobility[0] * mass[0] + v.heat_mobility[1] * mass[1]),
                    1e-12 * std::abs(v.heat_mobility[0]))
              << d << " " << phi << " " << alpha << " " << order;
          if (phi > 0) continue;
          for (std::size_t j = 0; j < 2; ++j) {
            const double relative = std::abs(v.heat_mobility[j] / -v.dufour[j] - 1);
            if (alpha == 1.0)
              EXPECT_LT(relative, 1e-12) << d << " " << order << " " << j;
            else
              EXPECT_GT(relative, 1e-3) << d << " " << order << " " << j;
          }
        }
      }
}

// Garzó, Dufty & Hrenya's first-Sonine shear viscosity of the dense mixture (PRE 76, 031303 (2007);
// seed 003): η = Σ_i η_i^k + η^c, η^c = (2B_2/(d+2)) Σ_ij μ_ij (1+α_ij) χ_ij n_i σ_ij^d η_j^k +
// (d/(d+2)) κ^c, with κ^c their bulk viscosity (B_k as in BulkViscosityEqualsClosedForms). At order 1
// (the basis Y_2 S_0 of GDH) the solver's η* equals it to 1e-13 for an unequal binary with unequal
// temperatures — a check of the mass-asymmetric collisional momentum flux against the paper.
TEST(MixtureEnskog, ShearViscosityEqualsGdhFirstSonine) {
  const double T = 1;
  for (int d : {2, 3})
    for (double alpha : {1.0, 0.7})
      for (double phi : {0.1, 0.3}) {
        gkt::Mixture m = gkt::make_mixture(d, {{1, 1, 0.35, ""}, {2.5, 1.5, 0.65, ""}}, alpha, phi);
        m.alpha = {alpha, 0.9 * alpha, 0.9 * alpha, 0.8 * alpha};
        const gkt::MixtureNavierStokes ns(m, 1);
        const auto v = ns.coefficients(1);
        const auto& gamma = ns.cooling_state().temperature_ratio;
        const auto chi = m.contact_values();
        const double n = number_density(m), eta0 = reference_viscosity(m, T);
        double eta = 0;
        for (std::size_t i = 0; i < 2; ++i) {
          eta += v.shear_viscosity_kinetic[i];
          for (std::size_t j = 0; j < 2; ++j) {
            const double mi = m.species[i].mass.value(), mj = m.species[j].mass.value(), mu_ij = mi / (mi + mj);
            const double sigma = 0.5 * (m.species[i].diameter + m.species[j].diameter), a = m.restitution(i, j);
            eta += 2 * b_constant(d, 2) / (d + 2) * mu_ij * (1 + a) * chi[i * 2 + j] * n * m.species[i].fraction *
                       std::pow(sigma, d) * v.shear_viscosity_kinetic[j] +
                   d / (d + 2.0) * gdh_bulk_viscosity_pair(m, gamma, n, T, i, j) / eta0;
          }
        }
        EXPECT_LT(relative(v.shear_viscosity, eta), 1e-13) << d << " " << alpha << " " << phi;
      }
}

// The tracer limit of the dense mixture is continuous: x_1 = 0 and 1e-9 give the same η*, λ*, κ*,
// ζ_U, p*, D_ij*, D^T_i*, D''_i* and drifts to 1e-6 (d = 2, 3; heavy and light, wide and narrow tracers).
TEST(MixtureEnskog, TracerLimitIsContinuous) {
  for (int d : {2, 3})
    for (const auto& [mass, size] : std::vector<std::pair<double, double>>{{4, 2}, {0.2, 0.6}}) {
      auto at = [&](double x1) {
        gkt::Mixture m = gkt::make_mixture(d, {{mass, size, x1, ""}, {1, 1, 1 - x1, ""}}, 0.7, 0.3);
        m.alpha = {0.6, 0.8, 0.8, 0.7};
        return gkt::MixtureNavierStokes(m, 2).coefficients(2);
      };
      const auto zero = at(0), small = at(1e-9);
      const std::string label = std::to_string(d) + " " + std::to_string(mass);
      EXPECT_LT(relative(small.shear_viscosity, zero.shear_viscosity), 1e-6) << label;
      EXPECT_LT(relative(small.thermal_conductivity, zero.thermal_conductivity), 1e-6) << label;
      EXPECT_LT(relative(small.bulk_viscosity, zero.bulk_viscosity), 1e-6) << label;
      EXPECT_LT(relative(small.cooling_rate_first_order, zero.cooling_rate_first_order), 1e-6) << label;
      EXPECT_LT(relative(small.pressure, zero.pressure), 1e-6) << label;
      for (std::size_t k = 0; k < 4; ++k) {
        EXPECT_LT(relative(small.mutual_diffusion[k], zero.mutual_diffusion[k]), 1e-6) << label << " " << k;
        EXPECT_LT(relative(small.drift[k], zero.drift[k]), 1e-6) << label << " " << k;
      }
      for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_LT(relative(small.thermal_diffusion[i], zero.thermal_diffusion[i]), 1e-6) << label;
        EXPECT_LT(relative(small.dufour[i], zero.dufour[i]), 1e-6) << label;
        EXPECT_LT(relative(small.thermal_drift[i], zero.thermal_drift[i]), 1e-6) << label;
      }
    }
}
