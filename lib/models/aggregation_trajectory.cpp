// What `gkt evolve` asks the "aggregation" model for: the population balance of sticking grains
// coupled to the granular temperature, from monomers at θ0 = 1 (docs/theory.md §20,
// docs/conventions.md). The model sets its own output times (t_end, points) and size grid.
#include <cmath>
#include <stdexcept>

#include "gkt/evolution/aggregation_evolution.hpp"
#include "gkt/transport/common/pair_correlation.hpp"
#include "models/models.hpp"

namespace gkt::detail {

namespace {

constexpr long kMaxSizes = 20000;                   // pivots of the size grid
constexpr long kMaxDistributionRows = 1000000;      // points × pivots of the long format
const Rational kMaxScale = Rational(1000000);       // critical_energy, kernel_constant
const Rational kMaxTime = Rational::parse("1e12");  // t_end, in t_0

ParameterSpec number(const std::string& name, Rational lo, bool lo_in, Rational hi, Rational fallback,
                     const std::string& description) {
  return {name, ParameterSpec::Kind::real, lo, hi, lo_in, true, fallback, description, {}};
}

ParameterSpec integer(const std::string& name, Rational lo, Rational hi, Rational fallback,
                      const std::string& description) {
  return {name, ParameterSpec::Kind::integer, lo, hi, true, true, fallback, description, {}};
}

ParameterSpec choice(const std::string& name, std::vector<std::string> choices, const std::string& description) {
  return choice_spec(name, description, std::move(choices));
}

}  // namespace

std::vector<ParameterSpec> aggregation_evolution_parameters() {
  return {integer("dimension", Rational(2), Rational(3), Rational(3), "spatial dimension"),
          restitution_spec("alpha", "normal restitution of rebounding collisions"),
          number("critical_energy", Rational(0), true, kMaxScale, Rational(1),
                 "critical energy theta*/theta0 of two monomers; theta*_ij = theta*_11 mu_ij/mu_11"),
          choice("criterion", {"relative-speed", "normal-impact", "always"}, "when a collision sticks"),
          choice("kernel", {"kinetic", "constant", "sum"}, "aggregation kernel"),
          number("kernel_constant", Rational(0), false, kMaxScale, Rational(1),
                 "rate constant of the constant and sum kernels"),
          {"packing_fraction",
           ParameterSpec::Kind::real,
           Rational(0),
           Rational(1),
           true,
           false,
           Rational(0),
           "packing fraction, below the dimension's limit: chi(phi) of the default pair correlation multiplies every "
           "rate",
           {}},
          choice("grid", {"uniform", "geometric"}, "size grid: sizes 1 ... K, or geometric sectional pivots"),
          integer("sizes", Rational(2), Rational::parse("1e12"), Rational(100),
                  "largest cluster size (uniform: at most 20000)"),
          number("grid_ratio", Rational(1), false, Rational(2), Rational(11, 10),
                 "ratio of consecutive pivots of the geometric grid"),
          number("t_end", Rational(0), false, kMaxTime, Rational(1), "last output time, in t_0 (required)"),
          integer("points", Rational(1), Rational(100000), Rational(50),
                  "output times, log-spaced from min(0.01, t_end/100) to t_end"),
          number("rtol", Rational(0), false, Rational(1, 10), Rational::parse("1e-8"), "CVODE relative tolerance"),
          number("atol", Rational(0), false, Rational(1), Rational::parse("1e-14"), "CVODE absolute tolerance"),
          choice("distribution", {"false", "true"},
                 "true: the size distribution n_k(t) in long format (columns size, size_density)"),
          evolution_max_steps_parameter()};
}

Trajectory aggregation_trajectory(const TrajectoryRequest& request) {
  const SchemaPoint p(aggregation_evolution_parameters(), request.parameters);
  AggregationGas gas;
  gas.dimension = static_cast<int>(p.number("dimension").to_double());
  gas.alpha = p.number("alpha").to_double();
  gas.critical_energy = p.number("critical_energy").to_double();
  const std::string criterion = p.choice("criterion");
  gas.criterion = criterion == "normal-impact" ? StickingCriterion::normal_impact
                  : criterion == "always"      ? StickingCriterion::always
                                               : StickingCriterion::relative_speed;
  const std::string kernel = p.choice("kernel");
  gas.kernel = kernel == "constant" ? AggregationKernel::constant
               : kernel == "sum"    ? AggregationKernel::sum
                                    : AggregationKernel::kinetic;
  gas.kernel_constant = p.number("kernel_constant").to_double();
  const Rational phi = p.number("packing_fraction");
  const Rational max_phi = max_packing_fraction(gas.dimension);
  if (phi >= max_phi)
    throw std::invalid_argument("packing_fraction: must be a number in [0, " + max_phi.to_decimal_string() +
                                ") for dimension = " + std::to_string(gas.dimension) + ", got " +
                                phi.to_decimal_string());
  gas.pair_correlation = pair_correlations().front().contact_value(gas.dimension, phi).to_double();
  const bool uniform = p.choice("grid") == "uniform";
  const double sizes = p.number("sizes").to_double();
  if (uniform && sizes > kMaxSizes)
    throw std::invalid_argument("sizes: must be an integer in [2, 20000], got " +
                                p.number("sizes").to_decimal_string());
  if (uniform && p.given("grid_ratio")) throw std::invalid_argument("grid_ratio: only with grid = \"geometric\"");
  std::vector<double> pivots;
  if (uniform) {
    for (int k = 1; k <= static_cast<int>(sizes); ++k) pivots.push_back(k);
  } else {
    pivots = geometric_pivots(p.number("grid_ratio").to_double(), sizes);
    if (pivots.size() > static_cast<std::size_t>(kMaxSizes))
      throw std::invalid_argument("grid_ratio: the grid has " + std::to_string(pivots.size()) +
                                  " pivots; at most 20000");
  }
  if (!p.given("t_end")) throw std::invalid_argument("t_end: required (a number > 0, in units of t_0)");
  const int points = static_cast<int>(p.number("points").to_double());
  const bool distribution = p.choice("distribution") == "true";
  const long rows = static_cast<long>(points) * static_cast<long>(pivots.size());
  if (distribution && rows > kMaxDistributionRows)
    throw std::invalid_argument("distribution: points x sizes = " + std::to_string(rows) + " rows; at most 1000000");

  const AggregationResult result = evolve_aggregation(
      gas, pivots, log_spaced_times(p.number("t_end").to_double(), points), p.number("rtol").to_double(),
      p.number("atol").to_double(), distribution, static_cast<long>(p.number("max_steps").to_double()));
  Trajectory out;
  out.columns = {"time", "temperature", "number_density", "mass", "mean_size", "success_factor"};
  if (distribution) {
    out.columns.emplace_back("size");
    out.columns.emplace_back("size_density");
  }
  for (const auto& s : result.samples) {
    const std::vector<double> row{s.time, s.temperature, s.number_density, s.mass, s.mean_size, s.success_factor};
    if (!distribution) {
      out.rows.push_back(row);
      continue;
    }
    for (std::size_t k = 0; k < pivots.size(); ++k) {  // long format: one row per size
      auto long_row = row;
      long_row.push_back(pivots[k]);
      long_row.push_back(s.distribution[k]);
      out.rows.push_back(std::move(long_row));
    }
  }
  out.counters = result.counters;
  out.linear_solver = result.linear_solver;
  return out;
}

}  // namespace gkt::detail
