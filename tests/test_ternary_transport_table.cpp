// The dilute ternary's per-cell table (theory.md §17.8, "Ternary tables"): at random compositions
// off the nodes it equals direct solves within the tolerance it was built for; on the edge x_3 = 0
// it is the binary table of species 1 and 2; and it refuses what it cannot interpolate (the C API:
// tests/c_api/test_c_api_ternary.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "gkt/transport/common/reference_gas.hpp"
#include "gkt/transport/mixture/mixture_navier_stokes.hpp"
#include "gkt/transport/mixture/mixture_transport_table.hpp"
#include "gkt/transport/mixture/ternary_transport_table.hpp"
#include "mixture_test_helpers.hpp"
#include "sanitizer.hpp"

namespace {

// Three unequal species (d = 3) with a full restitution matrix α_ij.
constexpr double kMass[3] = {1.0, 2.0, 3.5}, kDiameter[3] = {1.0, 1.3, 0.8};
constexpr double kAlpha[9] = {0.9, 0.85, 0.75, 0.85, 0.8, 0.8, 0.75, 0.8, 0.7};

gkt::Mixture ternary(double x1, double x2) {
  gkt::Mixture m = gkt::make_mixture(3,
                                     {{kMass[0], kDiameter[0], x1, "1"},
                                      {kMass[1], kDiameter[1], x2, "2"},
                                      {kMass[2], kDiameter[2], 1 - x1 - x2, "3"}},
                                     1.0);
  m.alpha.assign(kAlpha, kAlpha + 9);
  return m;
}

/// The reduced coefficients of a table entry, in the order the comparisons below walk them.
std::vector<double> flat(const gkt::TernaryTransport& t) {
  std::vector<double> out{t.cooling_rate, t.shear_viscosity, t.thermal_conductivity};
  out.insert(out.end(), t.temperature_ratio.begin(), t.temperature_ratio.end());
  out.insert(out.end(), t.mutual_diffusion.begin(), t.mutual_diffusion.end());
  out.insert(out.end(), t.thermal_diffusion.begin(), t.thermal_diffusion.end());
  out.insert(out.end(), t.pressure_diffusion.begin(), t.pressure_diffusion.end());
  out.insert(out.end(), t.dufour.begin(), t.dufour.end());
  return out;
}

/// The same coefficients from a direct solve at (x_1, x_2).
std::vector<double> direct(double x1, double x2, int order) {
  return gkt::test::table_values(gkt::MixtureNavierStokes(ternary(x1, x2), order), order);
}

}  // namespace

// Random compositions on the triangle (none a node: the generator does not know the grid) agree
// with direct solves within the tolerance the table was built for, relative to max(1, |value|); the
// physical set is the reduced one times the reference gas of (m̄, σ̄). 7 × 7 nodes miss 1e-3, so
// the build refines to 13 × 13. On the edge x_3 = 0 species 3 is a tracer and leaves species 1 and 2
// alone: the ternary table there equals the binary table of species 1 and 2 (the α_12 block) within
// both tables' measured errors.
TEST(TernaryTransportTable, EqualsDirectSolvesAndTheBinaryOnItsEdge) {
  const gkt::TernaryTransportTable t(ternary(0.3, 0.3), 1, 7, 1e-3);
  EXPECT_EQ(t.nodes_per_axis(), 13);
  EXPECT_EQ(t.pieces(), 1);
  EXPECT_LE(t.interpolation_error(), 1e-3);
  EXPECT_LE(t.validation_error(), t.interpolation_error());
  EXPECT_GT(t.build_solves(), 49);
  EXPECT_GT(t.build_seconds(), 0);
  std::mt19937 random(20);
  std::uniform_real_distribution<double> uniform(0, 1);
  double worst = 0;
  for (int k = 0; k < 12; ++k) {
    double x1 = uniform(random), x2 = uniform(random);
    if (x1 + x2 > 1) x1 = 1 - x1, x2 = 1 - x2;  // the reflection maps the square onto the triangle
    const std::vector<double> exact = direct(x1, x2, 1), interpolated = flat(t.evaluate_reduced(x1, x2));
    ASSERT_EQ(exact.size(), interpolated.size());
    for (std::size_t c = 0; c < exact.size(); ++c)
      worst = std::max(worst, gkt::test::relative(interpolated[c], exact[c]));
    const double n = 1.7, temperature = 0.6, x3 = 1 - x1 - x2;
    const double mbar = x1 * kMass[0] + x2 * kMass[1] + x3 * kMass[2];
    const double sbar = x1 * kDiameter[0] + x2 * kDiameter[1] + x3 * kDiameter[2];
    const gkt::ReferenceGas ref = gkt::reference_gas(3, mbar, sbar, n, temperature);
    const auto physical = t.evaluate(x1, x2, n, temperature);
    const auto reduced = t.evaluate_reduced(x1, x2);
    EXPECT_NEAR(physical.shear_viscosity, reduced.shear_viscosity * ref.viscosity, 1e-14 * ref.viscosity);
    EXPECT_NEAR(physical.mutual_diffusion[5], reduced.mutual_diffusion[5] * n * ref.self_diffusion,
                1e-14 * n * ref.self_diffusion * std::max(1.0, std::abs(reduced.mutual_diffusion[5])));
    EXPECT_DOUBLE_EQ(physical.pressure, n * temperature);
  }
  EXPECT_LE(worst, 1e-3);
  EXPECT_GT(worst, 0);  // the points are off the nodes: interpolation, not a lookup
  gkt::Mixture pair =
      gkt::make_mixture(3, {{kMass[0], kDiameter[0], 0.5, "1"}, {kMass[1], kDiameter[1], 0.5, "2"}}, 1.0);
  pair.alpha = {kAlpha[0], kAlpha[1], kAlpha[3], kAlpha[4]};
  const gkt::BinaryTransportTable binary(pair, 1, 12, 0, 12, 1e-6);
  const double tolerance = binary.interpolation_error() + t.interpolation_error();
  for (double x1 : {0.05, 0.37, 0.81}) {
    const double n = 1.3, temperature = 0.9;
    const auto b = binary.evaluate(x1, n, temperature);
    const auto e = t.evaluate(x1, 1 - x1, n, temperature);
    // Both reduced by the same reference gas (x_3 = 0: the binary's m̄, σ̄), compared as the tables
    // measure their errors.
    const gkt::ReferenceGas ref = gkt::reference_gas(3, x1 * kMass[0] + (1 - x1) * kMass[1],
                                                     x1 * kDiameter[0] + (1 - x1) * kDiameter[1], n, temperature);
    const auto near = [&](double ternary_value, double binary_value, double scale, const char* what) {
      const double reduced = binary_value / scale;
      EXPECT_NEAR(ternary_value / scale, reduced, tolerance * std::max(1.0, std::abs(reduced))) << what << " " << x1;
    };
    near(e.shear_viscosity, b.shear_viscosity, ref.viscosity, "eta");
    near(e.thermal_conductivity, b.thermal_conductivity, ref.conductivity, "lambda");
    near(e.cooling_rate, b.cooling_rate, ref.collision_frequency, "zeta");
    for (std::size_t i = 0; i < 2; ++i) {
      near(e.temperature_ratio[i], b.temperature_ratio[i], 1, "T_i/T");
      near(e.thermal_diffusion[i], b.thermal_diffusion[i], ref.self_diffusion, "D^T");
      near(e.pressure_diffusion[i], b.pressure_diffusion[i], ref.self_diffusion, "D^p");
      near(e.dufour[i], b.dufour[i], ref.conductivity / temperature, "D''");
      for (std::size_t j = 0; j < 2; ++j)
        near(e.mutual_diffusion[3 * i + j], b.mutual_diffusion[2 * i + j], n * ref.self_diffusion, "D_ij");
    }
  }
}

// Where no interpolant can be right — species 2 ten times heavier than 1 and 3 (which are equal),
// so that the order-1 solution has the binary's pole at a heavy fraction x_2 ≈ 0.03 all along the
// triangle — the build refuses, naming the error, the point and the region.
TEST(TernaryTransportTable, RefusesAPole) {
  gkt::Mixture m = gkt::make_mixture(3, {{1.0, 1.0, 0.4, "1"}, {10.0, 1.0, 0.2, "2"}, {1.0, 1.0, 0.4, "3"}}, 0.8);
  try {
    const gkt::TernaryTransportTable t(m, 1, 5, 1e-2, 5);
    ADD_FAILURE() << "built with error " << t.interpolation_error();
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("tolerance: the interpolation error ", 0), 0u) << message;
    EXPECT_NE(message.find("x_2/(1 - x_1) in ["), std::string::npos) << message;
    EXPECT_NE(message.find("splitting no longer helps"), std::string::npos) << message;
  }
}

// Dense (theory.md §18.10, "Dense ternary table"): φ is a third Chebyshev axis. At random interior
// states (x_1, x_2, φ) — off every node — the table equals direct dense ternary solves within its
// tolerance for every reduced value including p*, κ/η0 and ζ_U; evaluate(x_1, x_2, n, T) carries φ from n
// and returns nan above φ_max, evaluate_reduced refuses φ outside [0, φ_max]. Species close to each other
// (m = 1, 1.2, 1.4, σ = 1, 1.1, 0.95) and a loose tolerance keep the build to 134 dense solves (4 pieces of
// 3 × 3 × 3 nodes, about 5 s CPU): each dense ternary solve costs ~40 ms.
TEST(TernaryTransportTable, DenseEqualsDirectSolves) {
  GKT_SKIP_UNDER_SANITIZER("5 s");
  const double phi_max = 0.2, tolerance = 5e-2, mass[3] = {1.0, 1.2, 1.4}, diameter[3] = {1.0, 1.1, 0.95};
  auto ternary = [&](double x1, double x2) {
    gkt::Mixture m = gkt::make_mixture(
        3, {{mass[0], diameter[0], x1, "1"}, {mass[1], diameter[1], x2, "2"}, {mass[2], diameter[2], 1 - x1 - x2, "3"}},
        1.0);
    m.alpha = {0.9, 0.85, 0.8, 0.85, 0.8, 0.8, 0.8, 0.8, 0.85};
    return m;
  };
  const gkt::TernaryTransportTable t(ternary(0.3, 0.3), 1, 3, tolerance, 3, phi_max, 3);
  EXPECT_LE(t.interpolation_error(), tolerance);
  EXPECT_GE(t.packing_nodes(), 3);
  EXPECT_EQ(t.max_packing_fraction(), phi_max);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(0, 1);
  double worst = 0;
  for (int k = 0; k < 6; ++k) {
    double x1 = uniform(random), x2 = uniform(random);
    if (x1 + x2 > 1) x1 = 1 - x1, x2 = 1 - x2;
    const double phi = phi_max * uniform(random);
    gkt::Mixture m = ternary(x1, x2);
    m.packing_fraction = phi;
    const gkt::MixtureNavierStokes ns(m, 1);
    const auto v = ns.coefficients(1);
    std::vector<double> exact{ns.cooling_state().cooling_rate, v.shear_viscosity, v.thermal_conductivity};
    exact.insert(exact.end(), ns.cooling_state().temperature_ratio.begin(), ns.cooling_state().temperature_ratio.end());
    exact.insert(exact.end(), v.mutual_diffusion.begin(), v.mutual_diffusion.end());
    exact.insert(exact.end(), v.thermal_diffusion.begin(), v.thermal_diffusion.end());
    exact.insert(exact.end(), v.pressure_diffusion.begin(), v.pressure_diffusion.end());
    exact.insert(exact.end(), v.dufour.begin(), v.dufour.end());
    exact.insert(exact.end(), {v.pressure, v.bulk_viscosity, v.cooling_rate_first_order});
    const auto reduced = t.evaluate_reduced(x1, x2, phi);
    std::vector<double> interpolated = flat(reduced);
    interpolated.insert(interpolated.end(),
                        {reduced.pressure, reduced.bulk_viscosity, reduced.cooling_rate_first_order});
    ASSERT_EQ(exact.size(), interpolated.size());
    for (std::size_t c = 0; c < exact.size(); ++c)
      worst = std::max(worst, gkt::test::relative(interpolated[c], exact[c]));
    // Physical: n from φ = n v_d Σ x_i σ_i^d.
    const double x3 = 1 - x1 - x2, temperature = 0.8;
    double volume = 0;
    for (int i = 0; i < 3; ++i) volume += (i == 0 ? x1 : i == 1 ? x2 : x3) * std::pow(diameter[i], 3);
    const double n = phi / (gkt::unit_sphere_volume(3) * volume);
    const double mbar = x1 * mass[0] + x2 * mass[1] + x3 * mass[2];
    const double sbar = x1 * diameter[0] + x2 * diameter[1] + x3 * diameter[2];
    const gkt::ReferenceGas ref = gkt::reference_gas(3, mbar, sbar, n, temperature);
    const auto physical = t.evaluate(x1, x2, n, temperature);
    EXPECT_NEAR(physical.pressure, reduced.pressure * n * temperature, 1e-9 * n * temperature);
    EXPECT_NEAR(physical.bulk_viscosity, reduced.bulk_viscosity * ref.viscosity, 1e-9 * ref.viscosity);
    EXPECT_TRUE(std::isnan(t.evaluate(x1, x2, 1.2 * phi_max / phi * n, temperature).shear_viscosity));
  }
  EXPECT_LE(worst, tolerance);
  EXPECT_GT(worst, 0);
  EXPECT_THROW((void)t.evaluate_reduced(0.3, 0.3, 0.31), std::invalid_argument);
  EXPECT_THROW((void)t.evaluate_reduced(0.3, 0.3, -0.01), std::invalid_argument);
}

TEST(TernaryTransportTable, RefusesBadInput) {
  const gkt::Mixture m = ternary(0.3, 0.3);
  EXPECT_THROW(gkt::TernaryTransportTable(m, 1, 2), std::invalid_argument);
  EXPECT_THROW(gkt::TernaryTransportTable(m, 1, 34), std::invalid_argument);
  EXPECT_THROW(gkt::TernaryTransportTable(m, 1, 9, 1e-3, 8), std::invalid_argument);
  EXPECT_THROW(gkt::TernaryTransportTable(m, 0, 9), std::invalid_argument);
  EXPECT_THROW(gkt::TernaryTransportTable(m, 1, 9, 0.0), std::invalid_argument);
  EXPECT_THROW(gkt::TernaryTransportTable(m, 1, 5, 1e-2, 5, 0.6), std::invalid_argument);     // φ_max ≥ φ limit
  EXPECT_THROW(gkt::TernaryTransportTable(m, 1, 5, 1e-2, 5, -0.1), std::invalid_argument);    // φ_max < 0
  EXPECT_THROW(gkt::TernaryTransportTable(m, 1, 5, 1e-2, 5, 0.2, 2), std::invalid_argument);  // packing_nodes
  gkt::Mixture dense = m;
  dense.packing_fraction = 0.1;
  try {
    const gkt::TernaryTransportTable t(dense, 1, 5);
    ADD_FAILURE() << "a dense ternary accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "packing_fraction: a dilute ternary table (max_packing_fraction = 0) needs 0, got 0.1");
  }
  const gkt::TernaryTransportTable t(m, 1, 3, 1.0);  // any table: the checks come before interpolation
  try {
    (void)t.evaluate(0.6, 0.5, 1, 1);
    ADD_FAILURE() << "x_1 + x_2 > 1 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "fraction_2: must be a number in [0, 1 - fraction_1], got 0.5");
  }
  EXPECT_THROW((void)t.evaluate(-0.1, 0.5, 1, 1), std::invalid_argument);
  EXPECT_THROW((void)t.evaluate(0.1, 0.5, 0, 1), std::invalid_argument);
  EXPECT_THROW((void)t.evaluate(0.1, 0.5, 1, NAN), std::invalid_argument);
  // The vertices are states like any other (two tracers in the third species).
  for (auto [x1, x2] : {std::pair{0.0, 0.0}, std::pair{1.0, 0.0}, std::pair{0.0, 1.0}})
    EXPECT_TRUE(std::isfinite(t.evaluate(x1, x2, 1, 1).shear_viscosity)) << x1 << " " << x2;
}
