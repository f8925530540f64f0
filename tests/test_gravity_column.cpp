// The steady granular column in gravity (docs/theory.md §23; seed 001 §3.3.2): the elastic
// barometric limit, conservation of N, the energy balance, grid convergence, bad input, and the
// model gravity-column through the façade.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "gkt/algebra/rational.hpp"
#include "gkt/evolution/gravity_column.hpp"
#include "gkt/models/transport_model.hpp"
#include "gkt/simulation/gravity_column_dsmc.hpp"

namespace {

using gkt::FloorCondition;
using gkt::GravityColumnProblem;
using gkt::solve_gravity_column;

// A representative inelastic 3D gas (κ* > μ* > 0, ζ* > 0; near the engine's values at α ≈ 0.95):
// 5 particles per σ², floor at 50 mgσ (n(0)σ³ ≈ 0.1), lid at 60σ, where the lid still pushes.
GravityColumnProblem inelastic_problem(int intervals) {
  GravityColumnProblem p;
  p.dimension = 3;
  p.transport = {1.04, 0.03, 0.04};
  p.particles_per_area = 5;
  p.floor = FloorCondition::temperature;
  p.floor_value = 50;
  p.lid_height = 60;
  p.intervals = intervals;
  return p;
}

TEST(GravityColumn, ElasticColumnIsTheBarometricFormula) {
  for (int d : {2, 3}) {
    GravityColumnProblem p;
    p.dimension = d;
    p.transport = {1.0, 0.0, 0.0};
    p.particles_per_area = 3;
    p.floor_value = 2;  // T/(mgσ)
    p.lid_height = 7;
    p.intervals = 400;
    const auto c = solve_gravity_column(p);
    // n(z) = n(0) exp(−z/T), N = n(0) T (1 − e^{−H/T}), p(H) = n(H) T
    const double n0 = p.particles_per_area / (p.floor_value * (1 - std::exp(-p.lid_height / p.floor_value)));
    for (std::size_t j = 0; j < c.z.size(); j += 37) {
      EXPECT_NEAR(c.temperature[j], p.floor_value, 1e-12) << d;
      EXPECT_NEAR(c.number_density[j], n0 * std::exp(-c.z[j] / p.floor_value), 1e-10 * n0) << d << " z=" << c.z[j];
      EXPECT_NEAR(c.heat_flux[j], 0, 1e-12);
    }
    EXPECT_NEAR(c.z.back(), p.lid_height, 1e-10);
    EXPECT_NEAR(c.lid_pressure, n0 * std::exp(-p.lid_height / p.floor_value) * p.floor_value, 1e-10);
  }
}

TEST(GravityColumn, ConservesParticlesAndEnergy) {
  for (auto floor : {FloorCondition::temperature, FloorCondition::heat_flux}) {
    auto p = inelastic_problem(2000);
    p.floor = floor;
    p.floor_value = floor == FloorCondition::temperature ? 50 : 10;
    const auto c = solve_gravity_column(p);
    p.intervals *= 2;
    const auto fine = solve_gravity_column(p);
    // Trapezoid sums on the grid: second order, so the mismatch falls fourfold per doubling.
    EXPECT_NEAR(c.particles, p.particles_per_area, 1e-4 * p.particles_per_area);
    EXPECT_NEAR(std::abs(c.particles - p.particles_per_area) / std::abs(fine.particles - p.particles_per_area), 4, 0.4);
    EXPECT_NEAR(c.z.back(), p.lid_height, 1e-9 * p.lid_height);
    EXPECT_NEAR(c.heat_flux.back(), 0, 1e-9 * c.floor_heat_flux);  // elastic lid
    EXPECT_GT(c.floor_heat_flux, 0);
    EXPECT_NEAR(c.dissipation, c.floor_heat_flux, 5e-4 * c.floor_heat_flux);
    EXPECT_NEAR(std::abs(c.dissipation - c.floor_heat_flux) / std::abs(fine.dissipation - fine.floor_heat_flux), 4,
                0.6);
    if (floor == FloorCondition::temperature) {
      EXPECT_NEAR(c.temperature.front(), 50, 1e-12);
    } else {
      EXPECT_NEAR(c.floor_heat_flux, 10, 1e-12);
    }
  }
}

TEST(GravityColumn, ConvergesAtSecondOrder) {
  const auto coarse = solve_gravity_column(inelastic_problem(250));
  const auto mid = solve_gravity_column(inelastic_problem(500));
  const auto fine = solve_gravity_column(inelastic_problem(1000));
  // Node values (floor flux, lid pressure, the lid's n and T): the fourfold fall of second order.
  auto ratio = [&](auto get) { return std::abs(get(coarse) - get(mid)) / std::abs(get(mid) - get(fine)); };
  EXPECT_NEAR(ratio([](const auto& c) { return c.floor_heat_flux; }), 4, 0.3);
  EXPECT_NEAR(ratio([](const auto& c) { return c.lid_pressure; }), 4, 0.3);
  EXPECT_NEAR(ratio([](const auto& c) { return c.temperature.back(); }), 4, 0.3);
  EXPECT_NEAR(ratio([](const auto& c) { return c.number_density.back(); }), 4, 0.3);
  // Between nodes the interpolation in z adds a second-order error of either sign.
  for (double z : {0.0, 3.0, 20.0, 40.0, 59.0}) {
    const auto m = gkt::column_at(mid, z), f = gkt::column_at(fine, z);
    EXPECT_LT(std::abs(m.number_density - f.number_density), 2e-3 * f.number_density) << "z=" << z;
    EXPECT_LT(std::abs(m.temperature - f.temperature), 2e-4 * f.temperature) << "z=" << z;
  }
  // The inelastic column cools upward from the floor.
  EXPECT_LT(fine.temperature[fine.z.size() / 2], fine.temperature.front() / 5);
}

// No lid is the limit H → ∞ (theory.md §23.3): below a fixed height the column stops moving as the
// lid recedes — doubling H from 80σ to 160σ changes q(0), n and T at 20σ and 40σ at least tenfold
// less than from 40σ to 80σ, and by under 1e-4 — while the lid's own pressure falls.
TEST(GravityColumn, NoLidIsTheLimitOfARecedingLid) {
  std::vector<gkt::GravityColumnProfile> columns;
  for (double lid : {40.0, 80.0, 160.0}) {
    auto p = inelastic_problem(4000);
    p.lid_height = lid;
    columns.push_back(solve_gravity_column(p));
  }
  std::vector<std::vector<double>> values;  // q(0), n(20), T(20), n(40), T(40) per lid
  for (const auto& c : columns) {
    const auto low = gkt::column_at(c, 20), high = gkt::column_at(c, 40);
    values.push_back({c.floor_heat_flux, low.number_density, low.temperature, high.number_density, high.temperature});
  }
  for (std::size_t k = 0; k < values[0].size(); ++k) {
    const double first = std::abs(values[1][k] - values[0][k]), second = std::abs(values[2][k] - values[1][k]);
    EXPECT_LT(second, first / 10) << "quantity " << k;
    EXPECT_LT(second, 1e-4 * std::abs(values[2][k])) << "quantity " << k;
  }
  EXPECT_LT(columns[2].lid_pressure, columns[1].lid_pressure / 100);
}

TEST(GravityColumn, RejectsBadInput) {
  auto p = inelastic_problem(100);
  p.particles_per_area = 0;
  EXPECT_THROW(solve_gravity_column(p), std::invalid_argument);
  p = inelastic_problem(100);
  p.lid_height = -1;
  EXPECT_THROW(solve_gravity_column(p), std::invalid_argument);
  p = inelastic_problem(100);
  p.transport = {0.2, 0.3, 0.1};
  EXPECT_THROW(solve_gravity_column(p), std::invalid_argument);
  p = inelastic_problem(100);
  p.transport = {1, 0, 0};
  p.floor = FloorCondition::heat_flux;
  EXPECT_THROW(solve_gravity_column(p), std::invalid_argument);
  p = inelastic_problem(100);
  p.dimension = 4;
  EXPECT_THROW(solve_gravity_column(p), std::invalid_argument);
  p = inelastic_problem(100);
  p.transport = {0.386, -0.93, 0.41};  // the engine's order-2 numbers at α = 0.05 (3D): no positive √T
  EXPECT_THROW(solve_gravity_column(p), std::invalid_argument);
  const auto c = solve_gravity_column(inelastic_problem(100));
  EXPECT_THROW(static_cast<void>(gkt::column_at(c, 61)), std::invalid_argument);
  EXPECT_THROW(static_cast<void>(gkt::column_at(c, -0.1)), std::invalid_argument);
}

gkt::ParameterPoint column_point(double alpha, double z) {
  gkt::ParameterPoint p;
  p.numbers["dimension"] = gkt::Rational(3);
  p.numbers["alpha"] = gkt::Rational::from_double(alpha);
  p.numbers["particles_per_area"] = gkt::Rational(5);
  p.numbers["floor_value"] = gkt::Rational(50);
  p.numbers["lid_height"] = gkt::Rational(60);
  p.numbers["height"] = gkt::Rational::from_double(z);
  return p;
}

TEST(GravityColumnModel, ElasticRowsAreBarometricAndInelasticOnesUseTheEngine) {
  auto model = gkt::make_transport_model("gravity-column");
  const double n0 = 5 / (50 * (1 - std::exp(-60.0 / 50)));
  for (double z : {0.0, 13.0, 60.0}) {
    const auto v = model->evaluate(column_point(1, z), {"number_density", "temperature", "heat_flux"}, {});
    EXPECT_NEAR(v[0].value.to_double(), n0 * std::exp(-z / 50), 1e-9 * n0) << z;
    EXPECT_NEAR(v[1].value.to_double(), 50, 1e-9);
    EXPECT_NEAR(v[2].value.to_double(), 0, 1e-9);
  }
  // α = 0.95 at order 2: the column with the engine's κ*, μ*, ζ* conducts heat and cools upward;
  // the grid error estimate is small.
  gkt::OrderRequest order;
  order.order = 2;
  const auto floor = model->evaluate(column_point(0.95, 0), {"temperature", "heat_flux"}, order);
  const auto top = model->evaluate(column_point(0.95, 60), {"temperature", "heat_flux"}, order);
  EXPECT_NEAR(floor[0].value.to_double(), 50, 1e-9);
  EXPECT_GT(floor[1].value.to_double(), 1);
  EXPECT_LT(floor[1].error.to_double(), 1e-5 * floor[1].value.to_double());
  EXPECT_LT(top[0].value.to_double(), 10);
  EXPECT_NEAR(top[1].value.to_double(), 0, 1e-9 * floor[1].value.to_double());
  EXPECT_EQ(floor[0].order, 2);
}

TEST(GravityColumnModel, RefusesBadInputInOneLine) {
  auto model = gkt::make_transport_model("gravity-column");
  auto expect_refusal = [&](const gkt::ParameterPoint& p, const std::string& key) {
    try {
      static_cast<void>(model->evaluate(p, {"temperature"}, {}));
      ADD_FAILURE() << "accepted " << key;
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      EXPECT_TRUE(what.starts_with(key + ":")) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  };
  expect_refusal(column_point(0.9, 61), "height");
  auto p = column_point(0.9, 0);
  p.numbers["lid_height"] = gkt::Rational(0);
  expect_refusal(p, "lid_height");
  p = column_point(1, 0);
  p.choices["floor"] = "heat_flux";
  expect_refusal(p, "floor_value");
  p = column_point(0.9, 0);
  p.numbers["particles_per_area"] = gkt::Rational(-1);
  expect_refusal(p, "particles_per_area");
}

// The column's DSMC (theory.md §23.3): small runs (3000 particles, ~0.6 s each).
gkt::GravityColumnDsmcParameters small_dsmc(int d, double alpha, double wall, double lid) {
  gkt::GravityColumnDsmcParameters p;
  p.dimension = d;
  p.alpha = alpha;
  p.particles_per_area = 5;
  p.floor_temperature = wall;
  p.lid_height = lid;
  p.particles = 3000;
  p.settle_time = alpha == 1 ? 50 : 150;
  p.sample_time = alpha == 1 ? 100 : 150;
  p.seed = 3;
  return p;
}

TEST(GravityColumnDsmc, ElasticColumnIsIsothermalAndBarometric) {
  for (int d : {2, 3}) {
    const auto r = gkt::run_gravity_column_dsmc(small_dsmc(d, 1, 30, 60));
    const double n0 = 5 / (30 * (1 - std::exp(-2.0)));
    for (std::size_t c = 0; c < r.z.size() && r.z[c] < 25; ++c) {
      EXPECT_NEAR(r.temperature[c], 30, 0.04 * 30) << d << " z=" << r.z[c];
      EXPECT_NEAR(r.number_density[c], n0 * std::exp(-r.z[c] / 30), 0.05 * n0 * std::exp(-r.z[c] / 30))
          << d << " z=" << r.z[c];
    }
    EXPECT_LT(std::abs(r.floor_heat_flux), 0.01 * n0 * std::pow(30, 1.5)) << d;
  }
}

// The floor's energy input of a short run is too noisy to compare with (hydrodynamics' T moves three
// times as much as q(0), theory.md §23.3): the hydrodynamic floor takes the DSMC's temperature in
// the lowest cell (0.5σ up, past most of the wall's Knudsen layer).
TEST(GravityColumnDsmc, InelasticColumnFollowsHydrodynamicsGivenItsFloorTemperature) {
  const auto r = gkt::run_gravity_column_dsmc(small_dsmc(3, 0.99, 50, 150));
  EXPECT_GT(r.floor_heat_flux, 4);
  auto model = gkt::make_transport_model("gravity-column");
  gkt::ParameterPoint p;
  p.numbers["dimension"] = gkt::Rational(3);
  p.numbers["alpha"] = gkt::Rational(99, 100);
  p.numbers["particles_per_area"] = gkt::Rational(5);
  p.numbers["lid_height"] = gkt::Rational(150);
  p.choices["floor"] = "temperature";
  p.numbers["floor_value"] = gkt::Rational::from_double(r.temperature.front());
  gkt::OrderRequest order;
  order.order = 2;
  for (std::size_t c : {10U, 20U, 30U}) {  // Knudsen number < 0.1 there
    p.numbers["height"] = gkt::Rational::from_double(r.z[c]);
    const auto v = model->evaluate(p, {"number_density", "temperature"}, order);
    EXPECT_NEAR(r.number_density[c], v[0].value.to_double(), 0.05 * v[0].value.to_double()) << "z=" << r.z[c];
    EXPECT_NEAR(r.temperature[c], v[1].value.to_double(), 0.05 * v[1].value.to_double()) << "z=" << r.z[c];
  }
}

// Energy conservation inside the DSMC (theory.md §23.3): in the steady column the upward flux at a
// height is what the floor gave minus what collisions dissipated below it. The sampled heat_flux
// (kinetic at mid-flight + the collisional cell transfer) must meet it; the kinetic flux sampled at
// the start of each flight fell 2.5 % short of it at Δt = 0.02 and the cell transfer is 1 % of it.
TEST(GravityColumnDsmc, HeatFluxIsTheFloorInputLessTheDissipationBelow) {
  const auto r = gkt::run_gravity_column_dsmc(small_dsmc(3, 0.99, 50, 150));
  double below = 0, balance = 0, flux = 0, transfer = 0;
  const double dz = r.z[1] - r.z[0];
  for (std::size_t c = 0; r.z[c] < 30; ++c) {
    EXPECT_DOUBLE_EQ(r.heat_flux[c], r.kinetic_heat_flux[c] + r.collisional_heat_flux[c]);
    if (r.z[c] > 1) {
      balance += r.floor_heat_flux - below - r.dissipation[c] * dz / 2;
      flux += r.heat_flux[c];
      transfer += r.collisional_heat_flux[c];
    }
    below += r.dissipation[c] * dz;
  }
  EXPECT_GT(below, 0.3 * r.floor_heat_flux);  // the dissipation is sampled at all
  EXPECT_NEAR(flux / balance, 1, 0.015);
  EXPECT_GT(transfer / balance, 0.002);  // cells of 1σ, half a mean free path: ≈ 1 %
  EXPECT_LT(transfer / balance, 0.03);
}

TEST(GravityColumnDsmc, RefusesBadInput) {
  auto p = small_dsmc(3, 1, 30, 60);
  p.alpha = 0;
  EXPECT_THROW(gkt::run_gravity_column_dsmc(p), std::invalid_argument);
  p = small_dsmc(3, 1, 30, 60);
  p.cell_height = 40;
  EXPECT_THROW(gkt::run_gravity_column_dsmc(p), std::invalid_argument);
  p = small_dsmc(4, 1, 30, 60);
  EXPECT_THROW(gkt::run_gravity_column_dsmc(p), std::invalid_argument);
}

}  // namespace
