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

namespace {

using gkt::FloorCondition;
using gkt::GravityColumnProblem;
using gkt::solve_gravity_column;

// First-Sonine dilute 3D values at α = 0.8 (engine, standard scheme, nonlinear a2): the test only
// needs a representative inelastic κ* > μ* > 0, ζ* > 0.
GravityColumnProblem inelastic_problem(int intervals) {
  GravityColumnProblem p;
  p.dimension = 3;
  p.transport = {1.30, 0.26, 0.27};
  p.particles_per_area = 2;
  p.floor = FloorCondition::temperature;
  p.floor_value = 5;
  p.lid_height = 30;
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
    p.floor_value = floor == FloorCondition::temperature ? 5 : 3;
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
      EXPECT_NEAR(c.temperature.front(), 5, 1e-12);
    } else {
      EXPECT_NEAR(c.floor_heat_flux, 3, 1e-12);
    }
  }
}

TEST(GravityColumn, ConvergesAtSecondOrder) {
  const auto coarse = solve_gravity_column(inelastic_problem(250));
  const auto mid = solve_gravity_column(inelastic_problem(500));
  const auto fine = solve_gravity_column(inelastic_problem(1000));
  for (double z : {0.0, 3.0, 15.0, 29.0}) {
    const auto a = gkt::column_at(coarse, z), b = gkt::column_at(mid, z), f = gkt::column_at(fine, z);
    const double e1 = std::abs(a.temperature - b.temperature), e2 = std::abs(b.temperature - f.temperature);
    const double n1 = std::abs(a.number_density - b.number_density), n2 = std::abs(b.number_density - f.number_density);
    if (z > 0) {
      EXPECT_NEAR(e1 / e2, 4, 0.6) << "z=" << z;
    }
    EXPECT_NEAR(n1 / n2, 4, 0.6) << "z=" << z;
    EXPECT_LT(n2, 5e-3 * f.number_density);  // the model uses 16 and 32 times finer grids
  }
  // The inelastic column cools upward from the floor, then the μ* term warms its dilute top.
  EXPECT_LT(fine.temperature[fine.z.size() / 2], fine.temperature.front());
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
  const auto c = solve_gravity_column(inelastic_problem(100));
  EXPECT_THROW(static_cast<void>(gkt::column_at(c, 31)), std::invalid_argument);
  EXPECT_THROW(static_cast<void>(gkt::column_at(c, -0.1)), std::invalid_argument);
}

}  // namespace
