// Garzó–Hrenya–Dufty's published first Sonine truncation (theory.md §17.10): the closed form against
// the exact engine restricted to the same truncation, the elastic limit against Chapman & Cowling's
// and Hirschfelder–Curtiss–Bird's first approximations, the identical-species and tracer limits, and
// the dense engine's κ and ζ_U against GDH's printed closed forms (with the B_k erratum).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "gkt/models/transport_model.hpp"
#include "gkt/transport/common/reference_gas.hpp"
#include "gkt/transport/mixture/mixture.hpp"
#include "gkt/transport/mixture/mixture_cooling_state.hpp"
#include "gkt/transport/mixture/mixture_navier_stokes.hpp"
#include "gkt/transport/mixture/published_first_sonine.hpp"
#include "gkt/transport/mixture/revised_enskog_functionals.hpp"
#include "gkt/transport/mixture/tracer_diffusion.hpp"
#include "gkt/transport/monodisperse/navier_stokes.hpp"
#include "mixture_test_helpers.hpp"
#include "transport/mixture/dense_cell_closures.hpp"

using gkt::Rational;
using gkt::test::relative;

namespace {

gkt::Mixture binary(int d, double m2, double s2, double x1, double alpha, double phi = 0) {
  return gkt::make_mixture(d, {{1.0, 1.0, x1, "1"}, {m2, s2, 1 - x1, "2"}}, alpha, phi);
}

/// A ternary with unequal masses, sizes and a restitution matrix.
gkt::Mixture ternary(int d, double phi = 0) {
  gkt::Mixture m = gkt::make_mixture(d, {{1.0, 1.0, 0.5, "1"}, {2.5, 1.3, 0.3, "2"}, {0.4, 0.8, 0.2, "3"}}, 0.8, phi);
  const double a[3][3] = {{0.9, 0.75, 0.85}, {0.75, 0.7, 0.95}, {0.85, 0.95, 0.6}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m.alpha[static_cast<std::size_t>(i * 3 + j)] = a[i][j];
  return m;
}

/// Every coefficient of the closed form against the engine's published truncation (relative to max(1, |value|)).
void expect_equal(const gkt::PublishedFirstSonine& c, const gkt::MixtureTransportValues& e,
                  const gkt::MixtureCoolingState& hcs, std::size_t s, double tol, const std::string& what) {
  EXPECT_LT(relative(c.cooling_rate, hcs.cooling_rate), tol) << what;
  EXPECT_LT(relative(c.shear_viscosity, e.shear_viscosity), tol) << what;
  EXPECT_LT(relative(c.thermal_conductivity, e.thermal_conductivity), tol) << what;
  for (std::size_t i = 0; i < s; ++i) {
    EXPECT_LT(relative(c.temperature_ratio[i], hcs.temperature_ratio[i]), tol) << what;
    EXPECT_LT(relative(c.thermal_diffusion[i], e.thermal_diffusion[i]), tol) << what << " D^T_" << i;
    EXPECT_LT(relative(c.pressure_diffusion[i], e.pressure_diffusion[i]), tol) << what;
    EXPECT_LT(relative(c.dufour[i], e.dufour[i]), tol) << what << " D''_" << i;
    EXPECT_LT(relative(c.heat_mobility[i], e.heat_mobility[i]), tol) << what << " L_" << i;
    EXPECT_LT(relative(c.shear_viscosity_species[i], e.shear_viscosity_kinetic[i]), tol) << what;
    for (std::size_t j = 0; j < s; ++j) {
      EXPECT_LT(relative(c.mutual_diffusion[i * 4 + j], e.mutual_diffusion[i * s + j]), tol) << what << " D_" << i << j;
      EXPECT_LT(relative(c.mobility[i * 4 + j], e.mobility[i * s + j]), tol) << what << " D^F_" << i << j;
    }
  }
}

}  // namespace

// (a) The closed form (collision integrals (17.16)–(17.17), derived by hand) equals the engine
// restricted to the same truncation (exact engine moments, MixtureTruncation::published): binaries
// with unequal masses, sizes and temperatures, a ternary with a restitution matrix, α = 1 and a tracer.
TEST(PublishedFirstSonine, ClosedFormEqualsEngineRestrictedToTheTruncation) {
  for (int d : {2, 3}) {
    std::vector<std::pair<std::string, gkt::Mixture>> cases;
    for (double alpha : {1.0, 0.9, 0.6, 0.3})
      for (double m2 : {0.25, 3.0, 10.0}) cases.emplace_back("binary", binary(d, m2, 1.7, 0.3, alpha));
    cases.emplace_back("tracer", binary(d, 4.0, 0.6, 0.0, 0.7));
    cases.emplace_back("ternary", ternary(d));
    for (const auto& [name, m] : cases) {
      const gkt::MixtureNavierStokes engine(m, 1);
      const auto e = engine.coefficients(1, gkt::MixtureTruncation::published);
      const auto c = gkt::published_first_sonine(gkt::mixture_cell(m));
      expect_equal(c, e, engine.cooling_state(), m.size(), 1e-12,
                   name + " d=" + std::to_string(d) + " m2=" + std::to_string(m.species[1].mass.value()) +
                       " alpha=" + std::to_string(m.restitution(0, 1)));
    }
  }
}

// The published truncation is not the complete order 1: with unequal species the mass-flux rows of
// gkt's order 1 see the heat trial functions, and the coefficients move (theory.md §17.10 gives the
// sizes); for identical species the coupling vanishes in the heat flux and the shear mode (λ*, D''*, η*
// are the same), while D_ij is the tagged particle's first approximation against gkt's second.
TEST(PublishedFirstSonine, DiffersFromTheCompleteOrderOneOnlyForUnequalSpecies) {
  for (int d : {2, 3}) {
    const gkt::MixtureNavierStokes unequal(binary(d, 4.0, 1.5, 0.5, 0.8), 1);
    const auto p = unequal.coefficients(1, gkt::MixtureTruncation::published), c = unequal.coefficients(1);
    EXPECT_GT(relative(p.mutual_diffusion[0], c.mutual_diffusion[0]), 1e-3);
    EXPECT_GT(relative(p.thermal_conductivity, c.thermal_conductivity), 1e-3);
    EXPECT_LT(relative(p.shear_viscosity, c.shear_viscosity), 1e-14);  // the shear mode is the same
    const gkt::MixtureNavierStokes same(binary(d, 1.0, 1.0, 0.3, 0.6), 1);
    const auto ps = same.coefficients(1, gkt::MixtureTruncation::published), cs = same.coefficients(1);
    EXPECT_LT(relative(ps.thermal_conductivity, cs.thermal_conductivity), 1e-13);
    EXPECT_LT(relative(ps.dufour[0] + ps.dufour[1], cs.dufour[0] + cs.dufour[1]), 1e-13);
    EXPECT_LT(relative(ps.shear_viscosity, cs.shear_viscosity), 1e-13);
    EXPECT_GT(relative(ps.mutual_diffusion[0], cs.mutual_diffusion[0]), 1e-3);
  }
  EXPECT_THROW(
      (void)gkt::MixtureNavierStokes(binary(3, 2, 1, 0.5, 0.8), 2).coefficients(2, gkt::MixtureTruncation::published),
      std::invalid_argument);
}

// Dilute ternaries whose mass-flux elimination pivots in the second column: the closed form's LU
// once replayed its row swaps wrongly there (these two states were 38–50 % off in D_ij and λ*; about a
// fifth of random dilute ternaries with m, σ spread over e^{±2}, e^{±1} were affected). Equal to the
// engine's published truncation to 1e-12 now.
TEST(PublishedFirstSonine, DiluteTernariesThatPivotEqualTheEngine) {
  struct State {
    int d;
    double m[3], sigma[3], x[3], alpha[6];  // α_11, α_12, α_13, α_22, α_23, α_33
  };
  const State states[] = {
      {3, {0.97, 4.2, 3.66}, {0.48, 0.57, 2.7}, {0.36, 0.35, 0.29}, {0.99, 0.41, 0.63, 0.8, 0.54, 0.79}},
      {2, {0.24, 3.44, 0.74}, {0.71, 0.82, 0.84}, {0.72, 0.01, 0.27}, {0.85, 0.8, 0.32, 0.52, 0.69, 0.82}}};
  const int pair[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};
  for (const State& c : states) {
    gkt::Mixture m = gkt::make_mixture(
        c.d, {{c.m[0], c.sigma[0], c.x[0], "1"}, {c.m[1], c.sigma[1], c.x[1], "2"}, {c.m[2], c.sigma[2], c.x[2], "3"}},
        1.0);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m.alpha[static_cast<std::size_t>(i * 3 + j)] = c.alpha[pair[i][j]];
    const gkt::MixtureNavierStokes engine(m, 1);
    expect_equal(gkt::published_first_sonine(gkt::mixture_cell(m)),
                 engine.coefficients(1, gkt::MixtureTruncation::published), engine.cooling_state(), 3, 1e-12,
                 "pivoting ternary d=" + std::to_string(c.d));
  }
}

// (b) α = 1, dilute: the mass flux is Chapman & Cowling's first approximation [D12]_1 (their
// (9.81,1) generalised to d), the thermal diffusion at fixed pressure D^T_i − D^p_i vanishes (their
// [D_T]_1 = 0), and η is Hirschfelder, Curtiss & Bird's first approximation for a binary of rigid
// spheres (their (8.2-22), A* = 1), an independent closed form.
TEST(PublishedFirstSonine, ElasticLimitIsChapmanCowlingFirstApproximation) {
  for (int d : {2, 3})
    for (double m2 : {0.1, 1.0, 3.0, 50.0})
      for (double s2 : {0.5, 1.0, 2.0})
        for (double x1 : {0.2, 0.5, 0.9}) {
          const auto c = gkt::published_first_sonine(gkt::mixture_cell(binary(d, m2, s2, x1, 1.0)));
          const double mbar = x1 + (1 - x1) * m2, sbar = x1 + (1 - x1) * s2;
          const double m1 = 1 / mbar, mm2 = m2 / mbar, s12 = (1 + s2) / 2 / sbar;  // in m̄, σ̄
          // [D12]_1 n/D0 with D0 = (d/(4c_d))√(T/m̄)/(nσ̄^{d−1}): √((m1+m2)/(2m1m2)) / s12^{d−1}.
          const double d12 = std::sqrt((m1 + mm2) / (2 * m1 * mm2)) / std::pow(s12, d - 1);
          EXPECT_LT(relative(m1 * c.mutual_diffusion[0] - mm2 * c.mutual_diffusion[1], mm2 * d12), 1e-12)
              << d << " " << m2 << " " << s2 << " " << x1;
          for (int i = 0; i < 2; ++i)
            EXPECT_LT(std::abs(c.thermal_diffusion[i] - c.pressure_diffusion[i]), 1e-13) << d << " " << m2;
          if (d != 3) continue;
          // HCB (8.2-22): 1/[η]_1 = (X + Y)/(1 + Z) with the pure and the 1–2 viscosities [η_k]_1 =
          // (5/16)√(m_k T/π)/σ_k², [η12]_1 = (5/16)√(2m1m2T/(π(m1+m2)))/σ12² (reduced by η0 of m̄, σ̄).
          const double s1 = 1 / sbar, ss2 = s2 / sbar, x2 = 1 - x1;
          const double e1 = std::sqrt(m1) / (s1 * s1), e2 = std::sqrt(mm2) / (ss2 * ss2);
          const double e12 = std::sqrt(2 * m1 * mm2 / (m1 + mm2)) / (s12 * s12);
          const double r = m1 / mm2, q = (m1 + mm2) * (m1 + mm2) / (4 * m1 * mm2);
          const double x = x1 * x1 / e1 + 2 * x1 * x2 / e12 + x2 * x2 / e2;
          const double y = 0.6 * (x1 * x1 / e1 * r + 2 * x1 * x2 * q * e12 / (e1 * e2) + x2 * x2 / e2 / r);
          const double z = 0.6 * (x1 * x1 * r + 2 * x1 * x2 * (q * (e12 / e1 + e12 / e2) - 1) + x2 * x2 / r);
          EXPECT_LT(relative(c.shear_viscosity, (1 + z) / (x + y)), 1e-12) << m2 << " " << s2 << " " << x1;
        }
}

// (c) Identical species: the published truncation is the one-component first Sonine (η*, κ*, μ* of
// NavierStokesSolver with a2 = 0 at order 1) and D_1j = (δ_1j − x_1) D_self with the tagged particle's
// first-order D_self. Tracer: x_1 = 0 gives the Boltzmann–Lorentz first approximation of the tracer
// (TracerDiffusion order 1), and x_1 = 1e-9 is continuous with it.
TEST(PublishedFirstSonine, IdenticalSpeciesAndTracerLimits) {
  for (int d : {2, 3}) {
    gkt::NavierStokesSolver one(d);
    for (double alpha : {1.0, 0.8, 0.5, 0.2}) {
      const auto c = gkt::published_first_sonine(gkt::mixture_cell(binary(d, 1, 1, 0.3, alpha)));
      const auto o = one.solve(Rational::from_double(alpha), 1, {1.0, 0.0, 0.0});
      EXPECT_LT(relative(c.shear_viscosity, o.shear_viscosity), 1e-13) << d << " " << alpha;
      EXPECT_LT(relative(c.thermal_conductivity, o.thermal_conductivity), 1e-13) << d << " " << alpha;
      EXPECT_LT(relative(c.dufour[0] + c.dufour[1], o.density_heat_coefficient), 1e-13) << d << " " << alpha;
      EXPECT_LT(std::abs(c.temperature_ratio[0] - 1) + std::abs(c.thermal_diffusion[0]), 1e-13);
      const double self = gkt::TracerDiffusion({d, 1, 1, alpha, alpha}, 1).coefficient(1);
      EXPECT_LT(relative(c.mutual_diffusion[0], 0.7 * self), 1e-13);
      EXPECT_LT(relative(c.mutual_diffusion[1], -0.3 * self), 1e-13);
    }
    for (double m1 : {0.1, 3.0}) {
      const gkt::Mixture tracer = gkt::make_mixture(d, {{m1, 1.5, 0.0, "tracer"}, {1.0, 1.0, 1.0, "host"}}, 0.9);
      gkt::Mixture near = tracer;
      near.species[0].fraction = 1e-9;
      near.species[1].fraction = 1 - 1e-9;
      const auto c = gkt::published_first_sonine(gkt::mixture_cell(tracer));
      const auto n = gkt::published_first_sonine(gkt::mixture_cell(near));
      const double lorentz = gkt::TracerDiffusion({d, m1, 1.5, 0.9, 0.9}, 1).coefficient(1);
      EXPECT_LT(relative(c.mutual_diffusion[0] * m1, lorentz), 1e-12) << d << " " << m1;
      EXPECT_LT(relative(n.mutual_diffusion[0], c.mutual_diffusion[0]), 1e-6);
      EXPECT_LT(relative(n.thermal_conductivity, c.thermal_conductivity), 1e-6);
    }
  }
}

// The closed form's HCS (binary: Newton in ln(γ_1/γ_2); three species: damped Newton in ln γ) converges where the
// library's bracketed sweep does:
// mass ratios 10^±3 with diameter ratios 0.1 and 10, α down to 0.1, tracer to nearly pure, d = 2, 3 —
// γ_i equal mixture_cooling_state's Maxwellian ratios to 1e-10 and every coefficient is finite.
TEST(PublishedFirstSonine, CoolingStateConvergesAtExtremeRatios) {
  for (int d : {2, 3})
    for (double m2 : {1e-3, 1e3})
      for (double s2 : {0.1, 10.0})
        for (double alpha : {0.9, 0.5, 0.1})
          for (double x1 : {0.0, 0.5, 0.99}) {
            const gkt::Mixture m = binary(d, m2, s2, x1, alpha);
            const auto c = gkt::published_first_sonine(gkt::mixture_cell(m));
            const auto h = gkt::mixture_cooling_state(m, gkt::MixtureHcsScheme::maxwellian);
            for (std::size_t i = 0; i < 2; ++i)
              EXPECT_LT(std::abs(c.temperature_ratio[i] / h.temperature_ratio[i] - 1), 1e-10)
                  << d << " " << m2 << " " << s2 << " " << alpha << " " << x1;
            EXPECT_LT(relative(c.cooling_rate, h.cooling_rate), 1e-10);
            EXPECT_TRUE(std::isfinite(c.thermal_conductivity) && std::isfinite(c.shear_viscosity) &&
                        std::isfinite(c.mutual_diffusion[0]) && std::isfinite(c.heat_mobility[1]));
          }
}

// The binary's HCS solves its scalar equation for γ_1/γ_2 (Newton in ln τ, bisection outside the bracket).
// It converges where the two-species damped Newton it replaced stopped at a residual of 2e-3 and threw:
// a heavy minority species (m_2/m_1 = 1000, σ_2/σ_1 = 0.3, x_1 = 0.9) and elastic collisions among the
// light majority (α_11 = 1, α_12 = 0.9, α_22 = 0.8), d = 2, 3, dilute and φ = 0.25. γ_i equal
// mixture_cooling_state's Maxwellian ratios to 1e-10 (its bracketed sweep, an independent method), and
// Σ x_i γ_i = 1 to round-off.
TEST(PublishedFirstSonine, BinaryCoolingStateConvergesWhereTheTwoSpeciesNewtonStopped) {
  for (int d : {2, 3})
    for (double phi : {0.0, 0.25}) {
      gkt::Mixture m = binary(d, 1000, 0.3, 0.9, 0.9, phi);
      m.alpha = {1.0, 0.9, 0.9, 0.8};
      const auto c = gkt::published_first_sonine(gkt::mixture_cell(m));
      const auto h = gkt::mixture_cooling_state(m, gkt::MixtureHcsScheme::maxwellian);
      for (std::size_t i = 0; i < 2; ++i)
        EXPECT_LT(std::abs(c.temperature_ratio[i] / h.temperature_ratio[i] - 1), 1e-10) << d << " " << phi;
      EXPECT_LT(relative(c.cooling_rate, h.cooling_rate), 1e-10) << d << " " << phi;
      EXPECT_LT(std::abs(0.9 * c.temperature_ratio[0] + 0.1 * c.temperature_ratio[1] - 1), 1e-15);
      EXPECT_GT(c.temperature_ratio[1], 2 * c.temperature_ratio[0]);  // far from equipartition
      EXPECT_TRUE(std::isfinite(c.thermal_conductivity) && std::isfinite(c.shear_viscosity));
    }
}

// Bad input names the field; the closed form is the dilute gas's.
TEST(PublishedFirstSonine, RefusesBadInput) {
  gkt::MixtureCell cell = gkt::mixture_cell(binary(3, 2, 1, 0.5, 0.8));
  cell.fraction[0] = 0.7;
  EXPECT_THROW((void)gkt::published_first_sonine(cell), std::invalid_argument);
  cell = gkt::mixture_cell(binary(3, 2, 1, 0.5, 0.8));
  cell.restitution[1] = 0.5;  // α_01 ≠ α_10
  EXPECT_THROW((void)gkt::published_first_sonine(cell), std::invalid_argument);
  cell = gkt::mixture_cell(binary(3, 2, 1, 0.5, 0.8, 0.2));  // dense states are taken …
  cell.packing_fraction = 0.6;                               // … below φ_max only
  EXPECT_THROW((void)gkt::published_first_sonine(cell), std::invalid_argument);
  cell.packing_fraction = -0.1;
  EXPECT_THROW((void)gkt::published_first_sonine(cell), std::invalid_argument);
}

// The dense published truncation drops ϖ_i (GDH): κ is GDH's closed form κ^c =
// (B_3(d+1)/(2d²)) Σ_ij m_jμ_ij(1+α_ij)χ_ij σ_ij^{d+1} n_in_j ⟨g_ij⟩ and ζ_U GDH's
// −((d+2)/(dnT)) B_4 Σ_ij (1−α_ij²) μ_ji χ_ij σ_ij^d n_i n_j T_i (PRE 76, 031303; seed 003), both with
// B_k = π^{(d−1)/2} Γ((k+1)/2)/Γ((k+d)/2) — seed 003 prints Γ((d+1)/2) in the numerator, which
// fails here for ζ_U (and, in 2D, for the HCS cooling rate ζ^(0) with B_3; theory.md §17.10).
// Physical units: T = 1, n from φ.
TEST(PublishedFirstSonine, DenseBulkViscosityAndCoolingRateAreGdhClosedForms) {
  for (int d : {2, 3})
    for (double phi : {0.1, 0.3}) {
      gkt::Mixture m = binary(d, 3.0, 1.6, 0.4, 0.75, phi);
      for (int variant = 0; variant < 2; ++variant) {
        if (variant == 1) m.alpha = {0.9, 0.75, 0.75, 0.6};
        const gkt::MixtureNavierStokes engine(m, 1);
        const auto v = engine.coefficients(1, gkt::MixtureTruncation::published);
        const auto& gamma = engine.cooling_state().temperature_ratio;
        double volume = 0;
        for (const auto& sp : m.species) volume += sp.fraction * std::pow(sp.diameter, d);
        const double T = 1, n = phi / (gkt::unit_sphere_volume(d) * volume);
        const double eta0 = gkt::reference_gas(d, m.mean_mass(), m.mean_diameter(), n, T).viscosity;
        const std::vector<double> chi = m.contact_values();
        auto b = [&](int k, double numerator) {
          return std::pow(std::numbers::pi, (d - 1) / 2.0) * std::tgamma(numerator) / std::tgamma((k + d) / 2.0);
        };
        double kappa = 0, zeta_u = 0, zeta_u_printed = 0, zeta0 = 0, zeta0_printed = 0;
        for (std::size_t i = 0; i < 2; ++i)
          for (std::size_t j = 0; j < 2; ++j) {
            const double mi = m.species[i].mass.value(), mj = m.species[j].mass.value();
            const double mu_ij = mi / (mi + mj), mu_ji = 1 - mu_ij, a = m.restitution(i, j);
            const double s = 0.5 * (m.species[i].diameter + m.species[j].diameter), c = chi[i * 2 + j];
            const double ni = n * m.species[i].fraction, nj = n * m.species[j].fraction;
            // ⟨g_ij⟩ over Maxwellians at γ_i T, γ_j T
            const double g = std::tgamma((d + 1) / 2.0) / std::tgamma(d / 2.0) *
                             std::sqrt(2 * gamma[i] * T / mi + 2 * gamma[j] * T / mj);
            kappa += b(3, 2.0) * (d + 1) / (2.0 * d * d) * mj * mu_ij * (1 + a) * c * std::pow(s, d + 1) * ni * nj * g;
            const double common =
                (d + 2.0) / (d * n * T) * (1 - a * a) * mu_ji * c * std::pow(s, d) * ni * nj * gamma[i] * T;
            zeta_u -= b(4, 2.5) * common;
            zeta_u_printed -= b(4, (d + 1) / 2.0) * common;
            // ζ^(0) = (B_3/(2dnT)) Σ_ij (1 − α_ij²) (m_im_j/(m_i+m_j)) χ_ij σ_ij^{d−1} n_i n_j ⟨g_ij³⟩ (seed 003),
            // ⟨g³⟩ = (Γ((d+3)/2)/Γ(d/2)) (2T_i/m_i + 2T_j/m_j)^{3/2}
            const double g3 = std::tgamma((d + 3) / 2.0) / std::tgamma(d / 2.0) *
                              std::pow(2 * gamma[i] * T / mi + 2 * gamma[j] * T / mj, 1.5);
            const double cooling =
                (1 - a * a) * mi * mj / (mi + mj) * c * std::pow(s, d - 1) * ni * nj * g3 / (2.0 * d * n * T);
            zeta0 += b(3, 2.0) * cooling;
            zeta0_printed += b(3, (d + 1) / 2.0) * cooling;
          }
        // the HCS cooling rate, reduced by ν0 = nT/η0
        const double nu0 = n * T / eta0, zeta_hcs = engine.cooling_state().cooling_rate;
        EXPECT_LT(relative(zeta0 / nu0, zeta_hcs), 1e-12) << d << " " << phi;
        if (d == 2) {
          EXPECT_GT(std::abs(zeta0_printed / nu0 - zeta_hcs), 0.05 * zeta_hcs) << phi;
        }
        EXPECT_LT(relative(v.bulk_viscosity, kappa / eta0), 1e-12) << d << " " << phi << " " << variant;
        EXPECT_LT(relative(v.cooling_rate_first_order, zeta_u), 1e-12) << d << " " << phi << " " << variant;
        EXPECT_GT(std::abs(v.cooling_rate_first_order - zeta_u_printed), 0.1 * std::abs(zeta_u)) << d << " " << phi;
        for (double w : v.temperature_first_order) EXPECT_EQ(w, 0.0);
      }
    }
}

// The mixture model's `scheme = "published"` (conventions.md) returns the engine's published
// truncation at order 1, differs from the default "standard", and refuses another order or a tolerance
// with a one-line error naming the key.
TEST(PublishedFirstSonine, MixtureModelSchemeKey) {
  auto model = gkt::make_transport_model("mixture");
  gkt::ParameterPoint p;
  p.numbers = {{"species", Rational(2)},       {"mass_1", Rational(1)},        {"mass_2", Rational(4)},
               {"diameter_1", Rational(1)},    {"diameter_2", Rational(3, 2)}, {"fraction_1", Rational(1, 2)},
               {"fraction_2", Rational(1, 2)}, {"alpha", Rational(4, 5)},      {"dimension", Rational(3)}};
  p.choices["scheme"] = "published";
  const std::vector<std::string> names{"thermal_conductivity", "mutual_diffusion_1_2", "thermal_diffusion_1",
                                       "heat_mobility_1"};
  const auto published = model->evaluate(p, names, {1, std::nullopt});
  const gkt::MixtureNavierStokes engine(binary(3, 4, 1.5, 0.5, 0.8), 1);
  const auto e = engine.coefficients(1, gkt::MixtureTruncation::published);
  const double expected[] = {e.thermal_conductivity, e.mutual_diffusion[1], e.thermal_diffusion[0], e.heat_mobility[0]};
  for (std::size_t k = 0; k < names.size(); ++k) {
    EXPECT_LT(relative(published[k].value.to_double(), expected[k]), 1e-14) << names[k];
    EXPECT_EQ(published[k].order, 1);
  }
  p.choices["scheme"] = "standard";
  EXPECT_GT(relative(model->evaluate(p, names, {1, std::nullopt})[0].value.to_double(), expected[0]), 1e-2);
  p.choices["scheme"] = "published";
  auto message = [&](const gkt::OrderRequest& order) {
    try {
      (void)model->evaluate(p, names, order);
    } catch (const std::invalid_argument& error) {
      return std::string(error.what());
    }
    return std::string();
  };
  EXPECT_EQ(message({2, std::nullopt}).rfind("order: scheme = \"published\" exists at order = 1 only", 0), 0U);
  EXPECT_EQ(message({1, Rational(1, 1000)}).rfind("tolerance: ", 0), 0U);
}

// (d) Dense (theory.md §17.10 "Dense closed form"): the closed form with the collisional-transfer
// averages (18.23)–(18.24), derived by computer algebra, equals the engine's published truncation at
// φ > 0 (exact engine moments, Eigen solves) for binaries with unequal masses and sizes and the ternary
// with a restitution matrix (I_ℓij by the lens-centroid closure) and a quaternary, d = 2, 3, φ from 0.02
// to 0.45 — every coefficient, p*, P_j, κ and ζ_U, to 1e-12 (observed ≤ 7e-15). The ternaries and
// quaternaries pivot in the second column of the mass-flux solve at some of these φ, which the closed
// form's LU once got wrong (it swapped the earlier multipliers and replayed the swaps one by one).
TEST(PublishedFirstSonine, DenseClosedFormEqualsEngine) {
  for (int d : {2, 3})
    for (double phi : {0.02, 0.2, 0.45}) {
      std::vector<std::pair<std::string, gkt::Mixture>> cases;
      cases.emplace_back("binary", binary(d, 3.0, 1.7, 0.3, 0.7, phi));
      cases.emplace_back("light", binary(d, 0.2, 0.6, 0.6, 0.9, phi));
      cases.emplace_back("equal sizes", binary(d, 5.0, 1.0, 0.5, 0.5, phi));
      cases.emplace_back("ternary", ternary(d, phi));
      gkt::Mixture four = gkt::make_mixture(
          d, {{1.0, 1.0, 0.4, "1"}, {2.0, 1.4, 0.3, "2"}, {0.5, 0.7, 0.2, "3"}, {3.0, 1.2, 0.1, "4"}}, 0.8, phi);
      if (phi == 0.45) cases.emplace_back("quaternary", four);  // the engine's s = 4 solve is the slow part
      for (const auto& [name, m] : cases) {
        const gkt::MixtureNavierStokes engine(m, 1);
        const auto e = engine.coefficients(1, gkt::MixtureTruncation::published);
        const auto c = gkt::published_first_sonine(gkt::mixture_cell(m));
        const std::string what = name + " d=" + std::to_string(d) + " phi=" + std::to_string(phi);
        expect_equal(c, e, engine.cooling_state(), m.size(), 1e-12, what);
        EXPECT_LT(relative(c.bulk_viscosity, e.bulk_viscosity), 1e-12) << what;
        EXPECT_LT(relative(c.cooling_rate_first_order, e.cooling_rate_first_order), 1e-12) << what;
        EXPECT_LT(relative(c.pressure, e.pressure), 1e-12) << what;
        for (std::size_t j = 0; j < m.size(); ++j) {
          EXPECT_LT(relative(c.pressure_derivative[j], e.pressure_derivative[j]), 1e-12) << what;
          EXPECT_LT(relative(c.dufour[j], e.dufour[j]), 1e-12) << what << " D''_" << j;
        }
        EXPECT_GT(c.bulk_viscosity, 0) << what;
      }
    }
}

// At φ → 0 the dense closed form is the dilute one: φ = 0 gives the dilute gas's numbers with κ = ζ_U = 0,
// p* = P_j = 1, and φ = 1e-9 differs from them by O(φ) (checked at 1e-7).
TEST(PublishedFirstSonine, DenseReducesToDiluteAtZeroPackingFraction) {
  for (int d : {2, 3}) {
    const auto dilute = gkt::published_first_sonine(gkt::mixture_cell(ternary(d)));
    const auto near = gkt::published_first_sonine(gkt::mixture_cell(ternary(d, 1e-9)));
    EXPECT_EQ(dilute.bulk_viscosity, 0.0);
    EXPECT_EQ(dilute.pressure, 1.0);
    EXPECT_EQ(dilute.pressure_derivative[2], 1.0);
    EXPECT_LT(relative(near.thermal_conductivity, dilute.thermal_conductivity), 1e-7);
    EXPECT_LT(relative(near.shear_viscosity, dilute.shear_viscosity), 1e-7);
    EXPECT_LT(std::abs(near.bulk_viscosity) + std::abs(near.cooling_rate_first_order), 1e-7);
    for (std::size_t k = 0; k < 16; ++k) {
      EXPECT_LT(relative(near.mutual_diffusion[k], dilute.mutual_diffusion[k]), 1e-7) << k;
      EXPECT_LT(relative(near.heat_mobility_species[k], dilute.heat_mobility_species[k]), 1e-7) << k;
    }
    for (std::size_t k = 0; k < 4; ++k) {
      EXPECT_LT(relative(near.dufour[k], dilute.dufour[k]), 1e-7) << k;
      EXPECT_LT(relative(near.pressure_derivative[k], dilute.pressure_derivative[k]), 1e-7) << k;
    }
  }
}

// The fixed-size closures (dense_cell_closures.hpp) equal the library's χ_ij, n ∂χ_ij/∂n_ℓ and I_ℓij
// (Mixture::contact_values, contact_value_derivatives, revised_enskog_functionals) — binary (18.20) and
// ternary/quaternary (lens-centroid closure), d = 2, 3.
TEST(PublishedFirstSonine, DenseCellClosuresEqualTheLibrary) {
  for (int d : {2, 3})
    for (double phi : {0.1, 0.4}) {
      std::vector<gkt::Mixture> cases{
          binary(d, 3.0, 1.7, 0.3, 0.7, phi), ternary(d, phi),
          gkt::make_mixture(d, {{1.0, 1.0, 0.4, "1"}, {2.0, 1.4, 0.3, "2"}, {0.5, 0.7, 0.2, "3"}, {3.0, 2.2, 0.1, "4"}},
                            0.8, phi)};
      for (const gkt::Mixture& m : cases) {
        const std::size_t s = m.size();
        gkt::detail::DenseCellGeometry g;
        g.d = d;
        g.s = static_cast<int>(s);
        g.packing_fraction = phi;
        for (std::size_t i = 0; i < s; ++i) {
          g.sigma[i] = m.species[i].diameter / m.mean_diameter();
          g.fraction[i] = m.species[i].fraction;
        }
        const auto c = gkt::detail::dense_cell_closures(g);
        const auto chi = m.contact_values(), dchi = m.contact_value_derivatives();
        const auto functionals = gkt::revised_enskog_functionals(m);
        double largest = 0;
        for (std::size_t i = 0; i < s; ++i)
          for (std::size_t j = 0; j < s; ++j) {
            EXPECT_LT(relative(c.chi[i * 4 + j], chi[i * s + j]), 1e-14);
            for (std::size_t l = 0; l < s; ++l) {
              EXPECT_LT(relative(c.log_chi_derivative[(i * 4 + j) * 4 + l] * chi[i * s + j], dchi[(i * s + j) * s + l]),
                        1e-13);
              const double f = functionals[(i * s + j) * s + l];
              EXPECT_LT(relative(c.functionals[(i * 4 + j) * 4 + l], f), 1e-12) << d << " " << s << " " << i << j << l;
              largest = std::max(largest, std::abs(f));
            }
          }
        EXPECT_GT(largest, 1e-3);  // the comparison is not between zeros
      }
    }
}
