// The dense (Enskog) mixture about an HCS with cumulants in f⁰ (theory.md §17.11, (17.22)–(17.25)): the
// weighted pair transfer against the Maxwellian one, identical species against the one-component Enskog
// solver with the same a_k in f⁰ (its own one-species collisional-transfer tables, theory.md §15), the
// dropped conservation rows, φ → 0 continuity to the dilute cumulant reference, and the dense stencil
// derivatives against the exact Maxwellian ones.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "gkt/operators/mixture_collisional_transfer.hpp"
#include "gkt/operators/weighted_pair_transfer.hpp"
#include "gkt/transport/common/pair_correlation.hpp"
#include "gkt/transport/mixture/mixture.hpp"
#include "gkt/transport/mixture/mixture_cooling_state.hpp"
#include "gkt/transport/mixture/mixture_navier_stokes.hpp"
#include "gkt/transport/monodisperse/navier_stokes.hpp"
#include "mixture_test_helpers.hpp"

using gkt::MixtureHcsScheme;
using gkt::Rational;
using gkt::test::relative;

namespace {

gkt::Mixture binary(int d, double m2, double s2, double x1, double alpha, double phi) {
  return gkt::make_mixture(d, {{1.0, 1.0, x1, "1"}, {m2, s2, 1 - x1, "2"}}, alpha, phi);
}

void expect_equal(const std::vector<double>& a, const std::vector<double>& b, double tol, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t k = 0; k < a.size(); ++k) EXPECT_LT(relative(a[k], b[k]), tol) << what << " [" << k << "]";
}

}  // namespace

// With the weights a = (1, 0, …) the weighted averages contracted are the Maxwellian pair's, which
// pair_transfer_moments builds from other moments (no X1, X2 weight slots): unequal masses and widths.
TEST(MixtureDenseReference, WeightedTransferWithMaxwellianWeightsIsTheMaxwellianPair) {
  for (int d : {2, 3}) {
    const Rational mass_ratio(2, 3), root(5, 4), alpha(4, 5);
    const auto m = gkt::pair_transfer_moments(d, mass_ratio, root, alpha, 3, 0.7, 1.3);
    const auto w = gkt::weighted_pair_transfer_moments(d, mass_ratio, root, alpha, 3, 3, 0.7, 1.3);
    const std::vector<double> a{1, 0, 0, 0};
    const auto c = gkt::contracted_pair_transfer(w, a, a);
    const std::string at = "d = " + std::to_string(d);
    expect_equal(c.source_density, m.source_density, 1e-13, at + " source_density");
    expect_equal(c.source_temperature, m.source_temperature, 1e-13, at + " source_temperature");
    expect_equal(c.source_shear, m.source_shear, 1e-13, at + " source_shear");
    expect_equal(c.source_scalar, m.source_scalar, 1e-13, at + " source_scalar");
    expect_equal(c.shear_flux_partner, m.shear_flux_partner, 1e-13, at + " shear_flux_partner");
    expect_equal(c.shear_flux_self, m.shear_flux_self, 1e-13, at + " shear_flux_self");
    expect_equal(c.heat_flux_partner, m.heat_flux_partner, 1e-13, at + " heat_flux_partner");
    expect_equal(c.heat_flux_self, m.heat_flux_self, 1e-13, at + " heat_flux_self");
    expect_equal(c.pressure_partner, m.pressure_partner, 1e-13, at + " pressure_partner");
    expect_equal(c.pressure_self, m.pressure_self, 1e-13, at + " pressure_self");
    expect_equal(c.cooling_partner, m.cooling_partner, 1e-13, at + " cooling_partner");
    expect_equal(c.cooling_self, m.cooling_self, 1e-13, at + " cooling_self");
    EXPECT_LT(relative(c.shear_gradient, m.shear_gradient), 1e-13) << at;
    EXPECT_LT(relative(c.cooling_gradient, m.cooling_gradient), 1e-13) << at;
    EXPECT_LT(relative(c.energy, m.energy), 1e-13) << at;
    EXPECT_LT(relative(c.energy_self, m.energy_self), 1e-13) << at;
    EXPECT_LT(relative(c.energy_partner, m.energy_partner), 1e-13) << at;
    // A cumulant weight changes the averages (a_2 on either particle; the p = 0 shear source is quadratic in
    // the velocities, so S_2 weights leave it alone: p = 1).
    const std::vector<double> a2{1, 0, 0.1, 0};
    const auto c2 = gkt::contracted_pair_transfer(w, a2, a);
    const auto c3 = gkt::contracted_pair_transfer(w, a, a2);
    EXPECT_GT(std::abs(c2.source_shear[1] - m.source_shear[1]), 1e-4) << at;
    EXPECT_GT(std::abs(c3.source_shear[1] - m.source_shear[1]), 1e-4) << at;
    EXPECT_GT(std::abs(c2.energy_self - m.energy_self), 1e-4) << at;
    EXPECT_GT(std::abs(c3.energy_partner - m.energy_partner), 1e-4) << at;
  }
}

// Identical species at φ > 0 about the nonlinear HCS with a_2 … a_K (K = 2, 3, 4): η*, λ*, Σ_j D''_j* (= μ*),
// the bulk viscosity and ζ_U equal NavierStokesSolver's Enskog values with the same a_k in f⁰ at orders 1–3;
// ζ* is χ times the dilute one and the a_k are the dilute ones; D^T_i and T_i^(1) vanish. The Maxwellian
// reference misses λ* by more than 10⁻³.
TEST(MixtureDenseReference, IdenticalSpeciesEqualOneComponentEnskogWithCumulants) {
  const auto& closure = gkt::pair_correlation("carnahan-starling");
  for (int d : {2, 3}) {
    gkt::NavierStokesSolver one(d);
    for (double phi : {0.2, 0.4})
      for (double alpha : {0.8, 0.5})
        for (int K : {2, 3, 4}) {
          if (phi < 0.3 && K > 2) continue;  // K = 3, 4 at φ = 0.4 only (run time)
          const gkt::MixtureReference reference{MixtureHcsScheme::nonlinear, K};
          const gkt::MixtureNavierStokes ns(binary(d, 1, 1, 0.3, alpha, phi), 3, reference);
          const gkt::MixtureCoolingState dilute =
              gkt::mixture_cooling_state(binary(d, 1, 1, 0.3, alpha, 0), MixtureHcsScheme::nonlinear, K);
          const std::vector<double>& a = ns.cooling_state().cumulants[0];
          ASSERT_GT(std::abs(a[2]), 1e-3);
          const Rational exact_phi = Rational::from_double(phi);
          const gkt::EnskogState dense{phi, closure.contact_value(d, exact_phi).to_double(),
                                       closure.packing_derivative(d, exact_phi).to_double()};
          const std::string at = std::to_string(d) + "D phi " + std::to_string(phi) + " alpha " +
                                 std::to_string(alpha) + " K " + std::to_string(K);
          EXPECT_LT(relative(ns.cooling_state().cooling_rate, dense.chi * dilute.cooling_rate), 1e-12) << at;
          for (std::size_t k = 2; k < a.size(); ++k) EXPECT_LT(std::abs(a[k] - dilute.cumulants[0][k]), 1e-12) << at;
          for (int order = 1; order <= 3; ++order) {
            const auto v = ns.coefficients(order);
            const auto o = one.solve(Rational::from_double(alpha), order, a, gkt::SonineScheme::standard, dense);
            const std::string where = at + " N " + std::to_string(order);
            EXPECT_LT(relative(v.shear_viscosity, o.shear_viscosity), 1e-12) << where;
            EXPECT_LT(relative(v.thermal_conductivity, o.thermal_conductivity), 1e-12) << where;
            // μ* carries n∂ζ/∂n_j of the seven-point stencil (h = 10⁻³; rounding ≈ 10⁻¹⁶/h): 1.1·10⁻¹² seen.
            EXPECT_LT(relative(v.dufour[0] + v.dufour[1], o.density_heat_coefficient), 2e-12) << where;
            EXPECT_LT(relative(v.bulk_viscosity, o.bulk_viscosity), 1e-12) << where;
            EXPECT_LT(relative(v.cooling_rate_first_order, o.cooling_rate_first_order), 1e-12) << where;
            EXPECT_LT(std::abs(v.thermal_diffusion[0]) + std::abs(v.thermal_diffusion[1]), 1e-12) << where;
            EXPECT_LT(std::abs(v.temperature_first_order[0]) + std::abs(v.temperature_first_order[1]), 1e-12) << where;
          }
          const auto maxwellian = gkt::MixtureNavierStokes(binary(d, 1, 1, 0.3, alpha, phi), 1).coefficients(1);
          EXPECT_GT(relative(maxwellian.thermal_conductivity, ns.coefficients(1).thermal_conductivity), 1e-3) << at;
        }
  }
}

// The dense stencil derivatives (φ moves with n_j): for the Maxwellian scheme they equal the exact implicit
// derivatives of §16.6 with the contact values' own density dependence (theory.md (18.1)); ternary with a
// restitution matrix and unequal sizes, d = 2, 3.
TEST(MixtureDenseReference, DenseStencilDerivativesEqualTheExactOnes) {
  for (int d : {2, 3}) {
    gkt::Mixture m = gkt::make_mixture(d, {{1, 1, 0.3, ""}, {4, 1.6, 0.5, ""}, {0.4, 0.7, 0.2, ""}}, 0.7, 0.3);
    m.alpha = {0.9, 0.7, 0.6, 0.7, 0.5, 0.8, 0.6, 0.8, 0.95};
    const auto exact = gkt::mixture_cooling_sensitivity(m, gkt::mixture_cooling_state(m));
    const auto stencil = gkt::mixture_cooling_sensitivity(m, gkt::MixtureReference{});
    for (std::size_t k = 0; k < 9; ++k)
      EXPECT_NEAR(stencil.temperature_ratio[k], exact.temperature_ratio[k], 1e-9) << d;
    for (std::size_t j = 0; j < 3; ++j) {
      EXPECT_NEAR(stencil.cooling_rate[j], exact.cooling_rate[j], 1e-9) << d << " " << j;
      // The contact values' part is not small: the dilute derivative differs.
      gkt::Mixture dilute = m;
      dilute.packing_fraction = 0;
      const auto thin = gkt::mixture_cooling_sensitivity(dilute, gkt::mixture_cooling_state(dilute));
      EXPECT_GT(std::abs(exact.cooling_rate[j] - thin.cooling_rate[j]), 1e-2) << d << " " << j;
    }
  }
}

// The solver replaces the momentum row of the vector modes and the total-energy row of the ∇·u mode by
// constraints, always those of the first most abundant species; listing the species in the other order
// drops the other species' rows, so the coefficients agree only if the dropped rows hold — only if the
// cumulant-weighted transfer sources carry exactly −∇p^c and the ∇·u rows close the energy balance (ζ_U).
// The stencil derivatives are computed per ordering (independent HCS solves): 1e-9.
TEST(MixtureDenseReference, DroppedConservationRowsHold) {
  for (int d : {2, 3}) {
    const double alpha = 0.7;
    gkt::Mixture m = gkt::make_mixture(d, {{1, 1, 0.5, ""}, {3, 1.6, 0.5, ""}}, alpha, 0.25);
    m.alpha = {alpha, 0.9 * alpha, 0.9 * alpha, 0.8 * alpha};
    gkt::Mixture r = gkt::make_mixture(d, {{3, 1.6, 0.5, ""}, {1, 1, 0.5, ""}}, alpha, 0.25);
    r.alpha = {0.8 * alpha, 0.9 * alpha, 0.9 * alpha, alpha};
    const gkt::MixtureReference reference{MixtureHcsScheme::nonlinear, 3};
    const auto a = gkt::MixtureNavierStokes(m, 2, reference).coefficients(2);
    const auto b = gkt::MixtureNavierStokes(r, 2, reference).coefficients(2);
    const std::string at = std::to_string(d) + "D";
    EXPECT_LT(relative(a.shear_viscosity, b.shear_viscosity), 1e-9) << at;
    EXPECT_LT(relative(a.thermal_conductivity, b.thermal_conductivity), 1e-9) << at;
    EXPECT_LT(relative(a.bulk_viscosity, b.bulk_viscosity), 1e-9) << at;
    EXPECT_LT(relative(a.cooling_rate_first_order, b.cooling_rate_first_order), 1e-9) << at;
    EXPECT_GT(std::abs(a.temperature_first_order[0]), 1e-3) << at;
    for (std::size_t i = 0; i < 2; ++i) {
      EXPECT_LT(relative(a.thermal_diffusion[i], b.thermal_diffusion[1 - i]), 1e-9) << at;
      EXPECT_LT(relative(a.dufour[i], b.dufour[1 - i]), 1e-9) << at;
      EXPECT_LT(relative(a.temperature_first_order[i], b.temperature_first_order[1 - i]), 1e-9) << at;
      for (std::size_t j = 0; j < 2; ++j)
        EXPECT_LT(relative(a.mutual_diffusion[i * 2 + j], b.mutual_diffusion[(1 - i) * 2 + 1 - j]), 1e-9) << at;
    }
    // Σ_i D^T_i = 0 and Σ_i m_i D_ij = 0 (the sources carry −∇p only).
    EXPECT_LT(std::abs(a.thermal_diffusion[0] + a.thermal_diffusion[1]), 1e-12) << at;
    for (std::size_t j = 0; j < 2; ++j)
      EXPECT_LT(std::abs(a.mutual_diffusion[j] + 3 * a.mutual_diffusion[2 + j]), 1e-12) << at;
  }
}

// φ → 0: the dense solver with cumulants tends to the dilute one (φ = 10⁻⁹ within 10⁻⁷ of φ = 0, while
// φ = 10⁻² is farther than 3·10⁻⁵), unequal binary, d = 2, 3, orders 1 and 2.
TEST(MixtureDenseReference, ContinuousAtZeroPackingFraction) {
  const gkt::MixtureReference reference{MixtureHcsScheme::nonlinear, 2};
  for (int d : {2, 3}) {
    const auto dilute = gkt::MixtureNavierStokes(binary(d, 2, 1.5, 0.4, 0.7, 0), 2, reference);
    const auto thin = gkt::MixtureNavierStokes(binary(d, 2, 1.5, 0.4, 0.7, 1e-9), 2, reference);
    const auto dense = gkt::MixtureNavierStokes(binary(d, 2, 1.5, 0.4, 0.7, 1e-2), 2, reference);
    for (int order = 1; order <= 2; ++order) {
      const auto a = dilute.coefficients(order), b = thin.coefficients(order), c = dense.coefficients(order);
      const std::string at = std::to_string(d) + "D N " + std::to_string(order);
      EXPECT_LT(relative(b.shear_viscosity, a.shear_viscosity), 1e-7) << at;
      EXPECT_LT(relative(b.thermal_conductivity, a.thermal_conductivity), 1e-7) << at;
      EXPECT_LT(std::abs(b.bulk_viscosity), 1e-7) << at;
      EXPECT_LT(std::abs(b.cooling_rate_first_order), 1e-7) << at;
      for (std::size_t k = 0; k < 4; ++k) EXPECT_LT(relative(b.mutual_diffusion[k], a.mutual_diffusion[k]), 1e-7) << at;
      for (std::size_t k = 0; k < 2; ++k) {
        EXPECT_LT(relative(b.thermal_diffusion[k], a.thermal_diffusion[k]), 1e-7) << at;
        EXPECT_LT(relative(b.dufour[k], a.dufour[k]), 1e-7) << at;
      }
      EXPECT_GT(relative(c.thermal_conductivity, a.thermal_conductivity), 3e-5) << at;
    }
  }
}
