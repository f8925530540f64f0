// The C API of the dilute ternary's table (gkt.h, lib/c_api/ternary_table.cpp): it builds the
// table the C++ class builds from the same species, restitution matrix, order, nodes and tolerance,
// returns its values bit for bit (single cell, batch, reduced; the span batch of cell.hpp too), and
// refuses bad states naming the cell and asymmetric restitution matrices naming the pair.
#include <gtest/gtest.h>

#include <vector>

#include "gkt/cell.hpp"
#include "gkt/gkt.h"
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
