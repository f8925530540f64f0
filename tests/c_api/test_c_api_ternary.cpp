// The C API of the ternary's table (gkt.h, lib/c_api/ternary_table.cpp): it builds the dilute
// table the C++ class builds from the same species, restitution matrix, order, nodes and tolerance,
// returns its values bit for bit (single cell, batch, reduced; the span batch of cell.hpp too), and
// refuses bad states naming the cell and asymmetric restitution matrices naming the pair; the dense
// table (φ as a third axis) agrees with direct dense solves and refuses states above its φ_max, bad φ
// and tolerances it cannot meet.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "gkt/cell.hpp"
#include "gkt/gkt.h"
#include "gkt/transport/common/reference_gas.hpp"
#include "gkt/transport/mixture/mixture_navier_stokes.hpp"
#include "gkt/transport/mixture/ternary_transport_table.hpp"

namespace {

constexpr double kMass[3] = {1.0, 2.0, 3.5}, kDiameter[3] = {1.0, 1.3, 0.8};
constexpr double kAlpha[9] = {0.9, 0.85, 0.75, 0.85, 0.8, 0.8, 0.75, 0.8, 0.7};

}  // namespace

TEST(CApiTernaryTable, RoundTrip) {
  gkt_ternary_table* c = nullptr;
  ASSERT_EQ(gkt_ternary_table_create(3, kMass, kDiameter, kAlpha, 1, 5, 5e-2, &c), GKT_OK) << gkt_last_error();
  gkt::Mixture m = gkt::make_mixture(
      3, {{kMass[0], kDiameter[0], 0.3, "1"}, {kMass[1], kDiameter[1], 0.3, "2"}, {kMass[2], kDiameter[2], 0.4, "3"}},
      1.0);
  m.alpha.assign(kAlpha, kAlpha + 9);
  const gkt::TernaryTransportTable t(m, 1, 5, 5e-2);
  double error = -1;
  ASSERT_EQ(gkt_ternary_table_interpolation_error(c, &error), GKT_OK);
  EXPECT_EQ(error, t.interpolation_error());
  int pieces = 0, solves = 0;
  double seconds = 0;
  ASSERT_EQ(gkt_ternary_table_build_cost(c, &pieces, &solves, &seconds), GKT_OK);
  EXPECT_EQ(pieces, t.pieces());
  EXPECT_EQ(solves, t.build_solves());
  const double x1[2] = {0.21, 0.05}, x2[2] = {0.44, 0.9}, n[2] = {2.0, 0.3}, temperature[2] = {1.5, 4.0};
  gkt_ternary_transport out[2];
  ASSERT_EQ(gkt_ternary_table_evaluate_cells(c, 2, x1, x2, n, temperature, out), GKT_OK) << gkt_last_error();
  for (std::size_t i = 0; i < 2; ++i) {
    const auto v = t.evaluate(x1[i], x2[i], n[i], temperature[i]);
    gkt_ternary_transport single{};
    ASSERT_EQ(gkt_ternary_table_evaluate(c, x1[i], x2[i], n[i], temperature[i], &single), GKT_OK);
    EXPECT_EQ(single.shear_viscosity, v.shear_viscosity);
    EXPECT_EQ(out[i].shear_viscosity, v.shear_viscosity);
    EXPECT_EQ(out[i].cooling_rate, v.cooling_rate);
    for (std::size_t k = 0; k < 9; ++k) EXPECT_EQ(out[i].mutual_diffusion[k], v.mutual_diffusion[k]);
    for (std::size_t k = 0; k < 3; ++k) {
      EXPECT_EQ(out[i].dufour[k], v.dufour[k]);
      EXPECT_EQ(out[i].temperature_ratio[k], v.temperature_ratio[k]);
    }
    gkt_ternary_transport reduced{};
    ASSERT_EQ(gkt_ternary_table_evaluate_reduced(c, x1[i], x2[i], &reduced), GKT_OK);
    EXPECT_EQ(reduced.thermal_conductivity, t.evaluate_reduced(x1[i], x2[i]).thermal_conductivity);
  }
  // The span batch of cell.hpp equals the single calls too.
  std::vector<gkt::TernaryTransport> batch(2);
  gkt::evaluate(t, x1, x2, n, temperature, batch);
  EXPECT_EQ(batch[1].thermal_conductivity, t.evaluate(x1[1], x2[1], n[1], temperature[1]).thermal_conductivity);
  const double bad_x2[2] = {0.44, 0.96};
  EXPECT_EQ(gkt_ternary_table_evaluate_cells(c, 2, x1, bad_x2, n, temperature, out), GKT_INVALID_ARGUMENT);
  EXPECT_STREQ(gkt_last_error(), "fraction_2[1]: must be a number in [0, 1 - fraction_1], got 0.96");
  const double asymmetric[9] = {0.9, 0.85, 0.75, 0.8, 0.8, 0.8, 0.75, 0.8, 0.7};
  gkt_ternary_table* refused = nullptr;
  EXPECT_EQ(gkt_ternary_table_create(3, kMass, kDiameter, asymmetric, 1, 5, 5e-2, &refused), GKT_INVALID_ARGUMENT);
  EXPECT_STREQ(gkt_last_error(),
               "alpha: the restitution matrix must be symmetric, got alpha_1_2 = 0.85 and alpha_2_1 = 0.8");
  EXPECT_EQ(refused, nullptr);
  gkt_ternary_table_destroy(c);
}

namespace {

// The dense ternary of tests/test_ternary_transport_table.cpp (DenseEqualsDirectSolves): three similar species,
// 3 starting nodes per axis and in φ ∈ [0, 0.1], tolerance 5e-2 (a coarse table: a few seconds to build).
constexpr double kDenseMass[3] = {1.0, 1.2, 1.4}, kDenseDiameter[3] = {1.0, 1.1, 0.95};
constexpr double kDenseAlpha[9] = {0.9, 0.85, 0.8, 0.85, 0.8, 0.8, 0.8, 0.8, 0.85};
constexpr double kDensePhiMax = 0.1, kDenseTolerance = 5e-2;

/// True if message begins with prefix.
bool starts_with(const char* message, const char* prefix) { return std::string(message).rfind(prefix, 0) == 0; }

}  // namespace

// The dense table through the C API (gkt_ternary_table_create_dense): off the nodes its reduced set equals direct
// dense solves within the tolerance it was built for; the physical set is the reduced one times the reference gas
// (p = p* nT, κ_b = κ_b* η0); a state above φ_max is GKT_OUT_OF_RANGE naming the cell, a bad φ names
// packing_fraction, and a tolerance the table cannot meet (the order-1 pole of a 10:1 mass ratio, no refinement
// allowed; dilute, φ_max = 0 through the same call: the dense refusal costs ~20 s of splitting) is refused with the
// library's one-line message and no handle.
TEST(CApiTernaryTable, DenseAgreesWithDirectSolvesAndRefuses) {
  gkt_ternary_table* c = nullptr;
  ASSERT_EQ(gkt_ternary_table_create_dense(3, kDenseMass, kDenseDiameter, kDenseAlpha, 1, 3, 3, kDenseTolerance,
                                           kDensePhiMax, 3, &c),
            GKT_OK)
      << gkt_last_error();
  double error = -1;
  ASSERT_EQ(gkt_ternary_table_interpolation_error(c, &error), GKT_OK);
  EXPECT_LE(error, kDenseTolerance);
  const double x1 = 0.21, x2 = 0.44, phi = 0.07;
  gkt::Mixture m = gkt::make_mixture(3,
                                     {{kDenseMass[0], kDenseDiameter[0], x1, "1"},
                                      {kDenseMass[1], kDenseDiameter[1], x2, "2"},
                                      {kDenseMass[2], kDenseDiameter[2], 1 - x1 - x2, "3"}},
                                     1.0);
  m.alpha.assign(kDenseAlpha, kDenseAlpha + 9);
  m.packing_fraction = phi;
  const gkt::MixtureNavierStokes ns(m, 1);
  const auto v = ns.coefficients(1);
  gkt_ternary_transport reduced{};
  ASSERT_EQ(gkt_ternary_table_evaluate_reduced_dense(c, x1, x2, phi, &reduced), GKT_OK) << gkt_last_error();
  const std::pair<double, double> pairs[] = {{reduced.shear_viscosity, v.shear_viscosity},
                                             {reduced.thermal_conductivity, v.thermal_conductivity},
                                             {reduced.bulk_viscosity, v.bulk_viscosity},
                                             {reduced.cooling_rate_first_order, v.cooling_rate_first_order},
                                             {reduced.pressure, v.pressure},
                                             {reduced.mutual_diffusion[0], v.mutual_diffusion[0]},
                                             {reduced.dufour[2], v.dufour[2]},
                                             {reduced.cooling_rate, ns.cooling_state().cooling_rate}};
  for (const auto& [table, solved] : pairs)
    EXPECT_LE(std::abs(table - solved) / std::max(1.0, std::abs(solved)), error);
  EXPECT_GT(reduced.pressure, 1.1);      // p* = 1 + O(φχ): the dense table, not the dilute one
  EXPECT_GT(reduced.bulk_viscosity, 0);  // κ_b vanishes in the dilute gas
  // Physical: n from φ = n v_d Σ x_i σ_i^d, T = 0.8.
  const double x[3] = {x1, x2, 1 - x1 - x2}, temperature = 0.8;
  double volume = 0, mbar = 0, sbar = 0;
  for (int i = 0; i < 3; ++i) {
    volume += x[i] * std::pow(kDenseDiameter[i], 3);
    mbar += x[i] * kDenseMass[i];
    sbar += x[i] * kDenseDiameter[i];
  }
  const double n = phi / (gkt::unit_sphere_volume(3) * volume);
  const gkt::ReferenceGas ref = gkt::reference_gas(3, mbar, sbar, n, temperature);
  gkt_ternary_transport physical{};
  ASSERT_EQ(gkt_ternary_table_evaluate(c, x1, x2, n, temperature, &physical), GKT_OK) << gkt_last_error();
  EXPECT_NEAR(physical.pressure, reduced.pressure * n * temperature, 1e-12 * n * temperature);
  EXPECT_NEAR(physical.bulk_viscosity, reduced.bulk_viscosity * ref.viscosity, 1e-12 * ref.viscosity);
  EXPECT_NEAR(physical.shear_viscosity, reduced.shear_viscosity * ref.viscosity, 1e-12 * ref.viscosity);
  // Above φ_max: out of range, named by cell; nothing written.
  const double cx1[2] = {x1, x1}, cx2[2] = {x2, x2}, cn[2] = {n, 2 * n}, ct[2] = {temperature, temperature};
  gkt_ternary_transport cells[2]{};
  EXPECT_EQ(gkt_ternary_table_evaluate_cells(c, 2, cx1, cx2, cn, ct, cells), GKT_OUT_OF_RANGE);
  EXPECT_TRUE(starts_with(gkt_last_error(), "number_density[1]: the packing fraction n v_d sum_i x_i sigma_i^d = "))
      << gkt_last_error();
  EXPECT_EQ(cells[0].shear_viscosity, 0);
  EXPECT_EQ(gkt_ternary_table_evaluate_reduced_dense(c, x1, x2, 0.25, &reduced), GKT_OUT_OF_RANGE);
  EXPECT_STREQ(gkt_last_error(), "packing_fraction: must be in [0, 0.1] (the table's max_packing_fraction), got 0.25");
  EXPECT_EQ(gkt_ternary_table_evaluate_reduced_dense(c, x1, x2, -0.01, &reduced), GKT_INVALID_ARGUMENT);
  EXPECT_STREQ(gkt_last_error(), "packing_fraction: must be a number >= 0, got -0.01");
  gkt_ternary_table_destroy(c);
  // A dilute table is the dense call with φ_max = 0: only φ = 0 is covered.
  gkt_ternary_table* refused = nullptr;
  EXPECT_EQ(gkt_ternary_table_create_dense(3, kDenseMass, kDenseDiameter, kDenseAlpha, 1, 3, 3, kDenseTolerance, 0.6, 3,
                                           &refused),
            GKT_INVALID_ARGUMENT);
  EXPECT_TRUE(starts_with(gkt_last_error(), "max_packing_fraction: must be a number in [0, ")) << gkt_last_error();
  EXPECT_EQ(gkt_ternary_table_create_dense(3, kDenseMass, kDenseDiameter, kDenseAlpha, 1, 3, 2, kDenseTolerance,
                                           kDensePhiMax, 3, &refused),
            GKT_INVALID_ARGUMENT);
  EXPECT_TRUE(starts_with(gkt_last_error(), "max_nodes: must be an integer in [nodes, 33]")) << gkt_last_error();
  const double pole_mass[3] = {1.0, 10.0, 1.0}, unit[3] = {1.0, 1.0, 1.0};
  const double alpha[9] = {0.8, 0.8, 0.8, 0.8, 0.8, 0.8, 0.8, 0.8, 0.8};
  EXPECT_EQ(gkt_ternary_table_create_dense(3, pole_mass, unit, alpha, 1, 3, 3, kDenseTolerance, 0.0, 3, &refused),
            GKT_INVALID_ARGUMENT);
  EXPECT_TRUE(starts_with(gkt_last_error(), "tolerance: the interpolation error ")) << gkt_last_error();
  EXPECT_EQ(std::string(gkt_last_error()).find('\n'), std::string::npos);
  EXPECT_EQ(refused, nullptr);
}

// The tables about the cumulant HCS through the C API (gkt_binary_table_create_about, gkt_ternary_table_create_about;
// theory.md §17.14): a binary of identical species about the nonlinear HCS with a_2 equals the direct solve about the
// same reference at an off-node composition to round-off (its coefficients do not depend on x_1) and differs from the
// Maxwellian solve; an unknown reference and an hcs_order outside [2, 6] are refused naming the field, no handle.
TEST(CApiTernaryTable, TablesAboutTheCumulantHcs) {
  const double mass[2] = {1.0, 1.0}, diameter[2] = {1.0, 1.0}, alpha[4] = {0.7, 0.7, 0.7, 0.7};
  gkt_binary_table* b = nullptr;
  ASSERT_EQ(gkt_binary_table_create_about(3, mass, diameter, alpha, 1, 3, 0.0, 3, 1e-9, nullptr, "nonlinear", 2, &b),
            GKT_OK)
      << gkt_last_error();
  gkt_binary_transport r{};
  ASSERT_EQ(gkt_binary_table_evaluate_reduced(b, 0.3, 0.0, &r), GKT_OK);
  const gkt::Mixture m = gkt::make_mixture(3, {{1.0, 1.0, 0.3, "1"}, {1.0, 1.0, 0.7, "2"}}, 0.7);
  const auto about = gkt::MixtureNavierStokes(m, 1, {gkt::MixtureHcsScheme::nonlinear, 2}).coefficients(1);
  const auto maxwellian = gkt::MixtureNavierStokes(m, 1).coefficients(1);
  EXPECT_NEAR(r.thermal_conductivity, about.thermal_conductivity, 1e-12 * about.thermal_conductivity);
  EXPECT_NEAR(r.shear_viscosity, about.shear_viscosity, 1e-12 * about.shear_viscosity);
  EXPECT_GT(std::abs(r.thermal_conductivity / maxwellian.thermal_conductivity - 1), 1e-3);
  gkt_binary_table_destroy(b);
  gkt_binary_table* refused = nullptr;
  EXPECT_EQ(gkt_binary_table_create_about(3, mass, diameter, alpha, 1, 3, 0.0, 3, 1e-3, nullptr, "hcs", 2, &refused),
            GKT_INVALID_ARGUMENT);
  EXPECT_STREQ(gkt_last_error(), "reference: must be \"maxwellian\", \"linear\" or \"nonlinear\", got \"hcs\"");
  EXPECT_EQ(refused, nullptr);
  gkt_ternary_table* t = nullptr;
  EXPECT_EQ(gkt_ternary_table_create_about(3, kMass, kDiameter, kAlpha, 1, 3, 3, 5e-2, 0.0, 3, "linear", 7, &t),
            GKT_INVALID_ARGUMENT);
  EXPECT_STREQ(gkt_last_error(), "hcs_order: must be an integer in [2, 6] for a table about the cumulant HCS, got 7");
  EXPECT_EQ(t, nullptr);
}
