// The C API against the C++ calls it wraps, value for value (exact equality where the C layer only
// copies, 1e-15 relative where it multiplies or divides by a reference value), and the thread-local
// last error.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include "gkt/cell.hpp"
#include "gkt/gkt.h"
#include "gkt/models/transport_model.hpp"
#include "gkt/transport/common/pair_correlation.hpp"
#include "gkt/transport/common/reference_gas.hpp"

namespace {

void expect_relative(double got, double want, double tolerance, const std::string& what) {
  EXPECT_NEAR(got, want, tolerance * std::max(1e-300, std::abs(want))) << what;
}

TEST(CApi, FirstSonineEqualsTheCppCall) {
  for (int d : {2, 3})
    for (double alpha : {0.3, 0.55, 0.8, 0.95, 1.0}) {
      gkt_first_sonine c{};
      ASSERT_EQ(gkt_first_sonine_values(d, alpha, &c), GKT_OK);
      const gkt::FirstSonineValues v = gkt::first_sonine_values(d, alpha);
      EXPECT_EQ(c.a2, v.a2);
      EXPECT_EQ(c.cooling_rate, v.cooling_rate);
      EXPECT_EQ(c.shear_viscosity, v.shear_viscosity);
      EXPECT_EQ(c.thermal_conductivity, v.thermal_conductivity);
      EXPECT_EQ(c.density_heat_coefficient, v.density_heat_coefficient);

      const gkt_gas gas{1.7, 0.3, 0.9, 2.2};
      gkt_first_sonine p{};
      ASSERT_EQ(gkt_first_sonine_physical(d, alpha, &gas, &p), GKT_OK);
      const gkt::ReferenceGas ref = gkt::reference_gas(d, gas.mass, gas.diameter, gas.number_density, gas.temperature);
      expect_relative(p.shear_viscosity, v.shear_viscosity * ref.viscosity, 1e-15, "eta");
      expect_relative(p.thermal_conductivity, v.thermal_conductivity * ref.conductivity, 1e-15, "kappa");
      expect_relative(p.cooling_rate, v.cooling_rate * ref.collision_frequency, 1e-15, "zeta");
      expect_relative(p.density_heat_coefficient,
                      v.density_heat_coefficient * gas.temperature * ref.conductivity / gas.number_density, 1e-15,
                      "mu");
    }
}

TEST(CApi, EnskogEqualsTheCppCallWithTheExactClosure) {
  const auto& closure = gkt::pair_correlation("carnahan-starling");
  for (int d : {2, 3})
    for (double phi : {0.0, 0.05, 0.2, 0.45}) {
      gkt_enskog_state s{};
      ASSERT_EQ(gkt_enskog_state_at(d, phi, &s), GKT_OK);
      const gkt::Rational exact = gkt::Rational::from_double(phi);
      expect_relative(s.chi, closure.contact_value(d, exact).to_double(), 1e-14, "chi");
      expect_relative(s.phi_dchi, closure.packing_derivative(d, exact).to_double(), 1e-14, "phi dchi");
      gkt_enskog_first_sonine c{};
      ASSERT_EQ(gkt_enskog_first_sonine_values(d, 0.7, phi, &c), GKT_OK);
      const gkt::EnskogFirstSonineValues v = gkt::enskog_first_sonine_values(d, 0.7, gkt::enskog_state(d, phi));
      EXPECT_EQ(c.a2, v.a2);
      EXPECT_EQ(c.cooling_rate, v.cooling_rate);
      EXPECT_EQ(c.pressure, v.pressure);
      EXPECT_EQ(c.shear_viscosity, v.shear_viscosity);
      EXPECT_EQ(c.bulk_viscosity, v.bulk_viscosity);
      EXPECT_EQ(c.thermal_conductivity, v.thermal_conductivity);
      EXPECT_EQ(c.density_heat_coefficient, v.density_heat_coefficient);
      EXPECT_EQ(c.cooling_rate_first_order, v.cooling_rate_first_order);
    }
  // Physical: φ from n and σ, the reference gas at n, T.
  const gkt_gas gas{2.0, 0.8, 0.5, 1.3};
  const double phi = gas.number_density * gkt::unit_sphere_volume(3) * std::pow(gas.diameter, 3);
  const gkt::EnskogFirstSonineValues v = gkt::enskog_first_sonine_values(3, 0.9, gkt::enskog_state(3, phi));
  const gkt::ReferenceGas ref = gkt::reference_gas(3, gas.mass, gas.diameter, gas.number_density, gas.temperature);
  gkt_enskog_first_sonine p{};
  ASSERT_EQ(gkt_enskog_first_sonine_physical(3, 0.9, &gas, &p), GKT_OK);
  expect_relative(p.pressure, v.pressure * gas.number_density * gas.temperature, 1e-15, "p");
  expect_relative(p.bulk_viscosity, v.bulk_viscosity * ref.viscosity, 1e-15, "bulk");
  expect_relative(p.shear_viscosity, v.shear_viscosity * ref.viscosity, 1e-15, "eta");
  expect_relative(p.cooling_rate, v.cooling_rate * ref.collision_frequency, 1e-15, "zeta");
}

TEST(CApi, ModelEqualsTheRegistryCall) {
  gkt_model* model = nullptr;
  ASSERT_EQ(gkt_model_create("smooth-inelastic", &model), GKT_OK);
  ASSERT_EQ(gkt_model_set_number(model, "alpha", 0.7), GKT_OK);
  ASSERT_EQ(gkt_model_set_number(model, "packing_fraction", 0.1), GKT_OK);
  ASSERT_EQ(gkt_model_set_number(model, "dimension", 2), GKT_OK);
  const char* names[] = {"shear_viscosity", "thermal_conductivity", "a3"};
  gkt_coefficient c[3];
  ASSERT_EQ(gkt_model_evaluate(model, 3, names, 2, c), GKT_OK) << gkt_last_error();
  gkt_model_destroy(model);

  auto cpp = gkt::make_transport_model("smooth-inelastic");
  gkt::ParameterPoint point;
  point.numbers = {{"alpha", gkt::Rational(7, 10)}, {"packing_fraction", gkt::Rational(1, 10)}, {"dimension", 2}};
  const auto v = cpp->evaluate(point, {names[0], names[1], names[2]}, gkt::OrderRequest{2, std::nullopt});
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(c[i].value, v[i].value.to_double()) << names[i];
    EXPECT_EQ(c[i].error, v[i].error.to_double()) << names[i];
    EXPECT_EQ(c[i].order, 2);
    EXPECT_EQ(c[i].defined, 1);
  }
}

TEST(CApi, BinaryTableEqualsTheCppTable) {
  const double mass[2] = {1, 4}, diameter[2] = {1, 1.5}, alpha[4] = {0.9, 0.85, 0.85, 0.8};
  gkt_binary_table* table = nullptr;
  ASSERT_EQ(gkt_binary_table_create(3, mass, diameter, alpha, 1, 4, 0.3, 3, &table), GKT_OK) << gkt_last_error();
  gkt::Mixture mixture = gkt::make_mixture(3, {{1, 1, 0.5, ""}, {4, 1.5, 0.5, ""}}, 0.9);
  mixture.alpha = {0.9, 0.85, 0.85, 0.8};
  const gkt::BinaryTransportTable cpp(mixture, 1, 4, 0.3, 3);
  const double x1 = 0.37, n = 0.05, t = 1.9;
  gkt_binary_transport p{}, r{};
  ASSERT_EQ(gkt_binary_table_evaluate(table, x1, n, t, &p), GKT_OK);
  const gkt::BinaryTransport v = cpp.evaluate(x1, n, t);
  EXPECT_EQ(p.cooling_rate, v.cooling_rate);
  EXPECT_EQ(p.shear_viscosity, v.shear_viscosity);
  EXPECT_EQ(p.thermal_conductivity, v.thermal_conductivity);
  EXPECT_EQ(p.pressure, v.pressure);
  EXPECT_EQ(p.bulk_viscosity, v.bulk_viscosity);
  EXPECT_EQ(p.cooling_rate_first_order, v.cooling_rate_first_order);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(p.mutual_diffusion[k], v.mutual_diffusion[k]);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(p.temperature_ratio[i], v.temperature_ratio[i]);
    EXPECT_EQ(p.thermal_diffusion[i], v.thermal_diffusion[i]);
    EXPECT_EQ(p.pressure_diffusion[i], v.pressure_diffusion[i]);
    EXPECT_EQ(p.dufour[i], v.dufour[i]);
  }
  // Reduced at the same φ: the physical values over the reference gas of (m̄, σ̄) at n, T.
  const double phi = n * gkt::unit_sphere_volume(3) * (x1 * 1 + (1 - x1) * std::pow(1.5, 3));
  ASSERT_EQ(gkt_binary_table_evaluate_reduced(table, x1, phi, &r), GKT_OK);
  const gkt::ReferenceGas ref = gkt::reference_gas(3, x1 * 1 + (1 - x1) * 4, x1 * 1 + (1 - x1) * 1.5, n, t);
  expect_relative(r.shear_viscosity, v.shear_viscosity / ref.viscosity, 1e-13, "eta*");
  expect_relative(r.thermal_conductivity, v.thermal_conductivity / ref.conductivity, 1e-13, "lambda*");
  expect_relative(r.cooling_rate, v.cooling_rate / ref.collision_frequency, 1e-13, "zeta*");
  expect_relative(r.pressure, v.pressure / (n * t), 1e-13, "p*");
  expect_relative(r.dufour[0], v.dufour[0] * t / ref.conductivity, 1e-13, "dufour*");
  expect_relative(r.mutual_diffusion[1], v.mutual_diffusion[1] / (n * ref.self_diffusion), 1e-13, "D12*");
  double error = -1;
  ASSERT_EQ(gkt_binary_table_interpolation_error(table, &error), GKT_OK);
  EXPECT_EQ(error, cpp.interpolation_error());
  gkt_binary_table_destroy(table);
}

// Mass ratio 10 at order 1 has a pole of the truncated solution at x_1 ≈ 0.970 (theory.md §17.8):
// the C API refuses the table as the library does, with its one-line message, and writes no handle.
TEST(CApi, BinaryTableRefusesATableThatMissesItsTolerance) {
  const double mass[2] = {1, 10}, diameter[2] = {1, 1}, alpha[4] = {0.8, 0.8, 0.8, 0.8};
  gkt_binary_table* table = nullptr;
  EXPECT_EQ(gkt_binary_table_create_to_tolerance(3, mass, diameter, alpha, 1, 8, 0, 3, 1e-3, nullptr, &table),
            GKT_INVALID_ARGUMENT);
  EXPECT_EQ(table, nullptr);
  const std::string what = gkt_last_error();
  EXPECT_EQ(what.rfind("tolerance: the interpolation error ", 0), 0u) << what;
  EXPECT_NE(what.find("on x_1 in [0.96"), std::string::npos) << what;
}

// The last error belongs to the thread that failed: another thread's failure does not change it.
TEST(CApi, LastErrorIsPerThread) {
  gkt_first_sonine v{};
  ASSERT_EQ(gkt_first_sonine_values(3, 2.0, &v), GKT_INVALID_ARGUMENT);
  const std::string mine = gkt_last_error();
  std::string theirs;
  std::thread other([&] {
    EXPECT_EQ(std::string(gkt_last_error()), "");
    EXPECT_EQ(gkt_first_sonine_values(5, 0.5, &v), GKT_INVALID_ARGUMENT);
    theirs = gkt_last_error();
  });
  other.join();
  EXPECT_EQ(mine.rfind("alpha: must be a number in (0, 1]", 0), 0u) << mine;
  EXPECT_EQ(theirs.rfind("dimension: must be 2 or 3", 0), 0u) << theirs;
  EXPECT_EQ(std::string(gkt_last_error()), mine);
}

}  // namespace
