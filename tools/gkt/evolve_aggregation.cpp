#include "evolve_aggregation.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "gkt/evolution/aggregation_evolution.hpp"
#include "gkt/transport/common/pair_correlation.hpp"
#include "scene.hpp"

namespace gkt::cli {

namespace {

constexpr long kMaxPoints = 100000;
constexpr long kMaxSizes = 20000;
constexpr long kMaxDistributionRows = 1000000;

/// A single number in [lo, hi] (open at lo if lo_open), or `fallback` if the key is absent.
double number(const toml::table& t, const std::string& key, double fallback, double lo, bool lo_open, double hi,
              const std::string& allowed) {
  const auto* node = t.get(key);
  if (node == nullptr) return fallback;
  if (node->is_array() || node->is_table())
    throw std::invalid_argument(key + ": must be a single number (" + allowed + ")");
  const double v = scene_number(*node, key).to_double();
  if ((lo_open ? v <= lo : v < lo) || v > hi)
    throw std::invalid_argument(key + ": must be " + allowed + ", got " + format_number(v));
  return v;
}

std::string choice(const toml::table& t, const std::string& key, const std::vector<std::string>& allowed) {
  const auto* node = t.get(key);
  if (node == nullptr) return allowed.front();
  const std::string v = node->is_string() ? node->as_string()->get() : "";
  for (const auto& a : allowed)
    if (v == a) return v;
  throw std::invalid_argument(key + ": must be one of " + join(allowed, "\"") + ", got " +
                              (node->is_string() ? "\"" + quote_short(v) + "\"" : std::string("a non-string")));
}

}  // namespace

Table evolve_aggregation_scene(const toml::table& t, std::string& counters) {
  const std::set<std::string> valid{
      "model", "dimension",        "alpha", "critical_energy", "criterion", "kernel", "kernel_constant",
      "sizes", "packing_fraction", "t_end", "points",          "rtol",      "atol",   "distribution",
      "grid",  "grid_ratio"};
  for (const auto& [key, value] : t) {
    const std::string k(key.str());
    if (!valid.contains(k))
      throw std::invalid_argument(k + ": unknown key for gkt evolve with model \"aggregation\"; valid keys: " +
                                  join({valid.begin(), valid.end()}));
  }
  AggregationGas gas;
  const double dim = number(t, "dimension", 3, 2, false, 3, "2 or 3");
  if (dim != 2 && dim != 3) throw std::invalid_argument("dimension: must be 2 or 3, got " + format_number(dim));
  gas.dimension = static_cast<int>(dim);
  gas.alpha = number(t, "alpha", 1, 0, true, 1, "a number in (0, 1]");
  gas.critical_energy = number(t, "critical_energy", 1, 0, false, 1e6, "a number in [0, 1e6] (theta*/theta0)");
  const std::string criterion = choice(t, "criterion", {"relative-speed", "normal-impact", "always"});
  gas.criterion = criterion == "normal-impact" ? StickingCriterion::normal_impact
                  : criterion == "always"      ? StickingCriterion::always
                                               : StickingCriterion::relative_speed;
  const std::string kernel = choice(t, "kernel", {"kinetic", "constant", "sum"});
  gas.kernel = kernel == "constant" ? AggregationKernel::constant
               : kernel == "sum"    ? AggregationKernel::sum
                                    : AggregationKernel::kinetic;
  gas.kernel_constant = number(t, "kernel_constant", 1, 0, true, 1e6, "a number in (0, 1e6]");
  const double max_phi = max_packing_fraction(gas.dimension).to_double();
  const double phi =
      number(t, "packing_fraction", 0, 0, false, max_phi,
             "a number in [0, " + format_number(max_phi) + ") for dimension = " + std::to_string(gas.dimension));
  if (phi >= max_phi)
    throw std::invalid_argument("packing_fraction: must be a number in [0, " + format_number(max_phi) + "), got " +
                                format_number(phi));
  const auto* phi_node = t.get("packing_fraction");
  const Rational phi_exact = phi_node != nullptr ? scene_number(*phi_node, "packing_fraction") : Rational(0);
  gas.pair_correlation = pair_correlations().front().contact_value(gas.dimension, phi_exact).to_double();
  const std::string grid = choice(t, "grid", {"uniform", "geometric"});
  const double sizes = number(t, "sizes", 100, 2, false, grid == "uniform" ? kMaxSizes : 1e12,
                              grid == "uniform" ? "an integer in [2, 20000]" : "an integer in [2, 1e12]");
  if (sizes != std::floor(sizes))
    throw std::invalid_argument(std::string("sizes: must be an integer in [2, ") +
                                (grid == "uniform" ? "20000]" : "1e12]"));
  if (grid == "uniform" && t.contains("grid_ratio"))
    throw std::invalid_argument("grid_ratio: only with grid = \"geometric\"");
  const double ratio = number(t, "grid_ratio", 1.1, 1, true, 2, "a number in (1, 2]");
  std::vector<double> pivots;
  if (grid == "uniform") {
    for (int k = 1; k <= static_cast<int>(sizes); ++k) pivots.push_back(k);
  } else {
    pivots = geometric_pivots(ratio, sizes);
    if (pivots.size() > static_cast<std::size_t>(kMaxSizes))
      throw std::invalid_argument("grid_ratio: the grid has " + std::to_string(pivots.size()) +
                                  " pivots; at most 20000");
  }
  if (!t.contains("t_end")) throw std::invalid_argument("t_end: required (a number > 0, in units of t_0)");
  const double t_end = number(t, "t_end", 1, 0, true, 1e12, "a number in (0, 1e12]");
  const double points = number(t, "points", 50, 1, false, kMaxPoints, "an integer in [1, 100000]");
  if (points != std::floor(points)) throw std::invalid_argument("points: must be an integer in [1, 100000]");
  const double rtol = number(t, "rtol", 1e-8, 0, true, 0.1, "a number in (0, 0.1]");
  const double atol = number(t, "atol", 1e-14, 0, true, 1, "a number in (0, 1]");
  bool distribution = false;
  if (const auto* node = t.get("distribution")) {
    if (!node->is_boolean()) throw std::invalid_argument("distribution: must be true or false");
    distribution = node->as_boolean()->get();
  }
  const int n = static_cast<int>(points), k_max = static_cast<int>(pivots.size());
  if (distribution && static_cast<long>(n) * k_max > kMaxDistributionRows)
    throw std::invalid_argument("distribution: points x sizes = " + std::to_string(static_cast<long>(n) * k_max) +
                                " rows; at most 1000000");
  std::vector<double> times;  // log-spaced from t_end/100 (or 0.01 if earlier) to t_end
  const double start = std::min(0.01, t_end / 100);
  for (int i = 0; i < n; ++i)
    times.push_back(n == 1 ? t_end : start * std::pow(t_end / start, static_cast<double>(i) / (n - 1)));

  AggregationResult result;
  try {
    result = evolve_aggregation(gas, pivots, times, rtol, atol, distribution);
  } catch (const EvolutionFailure& e) {
    const std::string message = e.what();
    if (e.tolerances()) throw;
    throw std::invalid_argument("t_end" + message.substr(message.find(':')));
  }
  Table table;
  table.model = "aggregation";
  table.columns = {"time", "temperature", "number_density", "mass", "mean_size", "success_factor"};
  if (distribution) {
    table.columns.emplace_back("size");
    table.columns.emplace_back("size_density");
  }
  table.numeric.assign(table.columns.size(), true);
  for (const auto& s : result.samples) {
    const std::vector<std::string> row{format_number(s.time),           format_number(s.temperature),
                                       format_number(s.number_density), format_number(s.mass),
                                       format_number(s.mean_size),      format_number(s.success_factor)};
    if (!distribution) {
      table.rows.push_back(row);
      continue;
    }
    for (int k = 1; k <= k_max; ++k) {
      auto long_row = row;
      long_row.push_back(format_number(pivots[static_cast<std::size_t>(k - 1)]));
      long_row.push_back(format_number(s.distribution[static_cast<std::size_t>(k - 1)]));
      table.rows.push_back(std::move(long_row));
    }
  }
  const auto& c = result.counters;
  counters = "cvode: linear_solver=" + result.linear_solver + " steps=" + std::to_string(c.steps) +
             " rhs=" + std::to_string(c.rhs_evaluations) +
             " error_test_failures=" + std::to_string(c.error_test_failures) +
             " newton_iterations=" + std::to_string(c.nonlinear_iterations);
  return table;
}

}  // namespace gkt::cli
