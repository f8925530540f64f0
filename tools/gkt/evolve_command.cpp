#include "evolve_command.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <set>
#include <stdexcept>

#include "evolve_aggregation.hpp"
#include "gkt/evolution/hcs_stability.hpp"
#include "gkt/evolution/homogeneous_cooling_evolution.hpp"
#include "gkt/operators/viscoelastic_hierarchy.hpp"
#include "gkt/transport/monodisperse/homogeneous_cooling_state.hpp"
#include "gkt/transport/monodisperse/navier_stokes.hpp"
#include "gkt/transport/viscoelastic/viscoelastic_transport.hpp"
#include "scene.hpp"

namespace gkt::cli {

namespace {

constexpr int kMaxOrder = 12;
constexpr long kMaxPoints = 1000000;
constexpr int kMaxViscoelasticOrder = 8;  // viscoelastic_transport_series

std::invalid_argument error(const std::string& message) { return std::invalid_argument(message); }

/// A single number with an allowed (open or closed) range.
double number(const toml::table& t, const std::string& key, double fallback, double lo, bool lo_open, double hi,
              const std::string& allowed) {
  const auto* node = t.get(key);
  if (node == nullptr) return fallback;
  if (node->is_array() || node->is_table()) throw error(key + ": must be a single number (" + allowed + ")");
  const double v = scene_number(*node, key).to_double();
  if ((lo_open ? v <= lo : v < lo) || v > hi) throw error(key + ": must be " + allowed + ", got " + format_number(v));
  return v;
}

const char* table_model(bool viscoelastic) { return viscoelastic ? "viscoelastic" : "smooth-inelastic"; }

}  // namespace

Table evolve(const std::string& scene_path, const std::vector<std::string>& overrides, std::string& counters) {
  const toml::table t = read_scene_table(scene_path, overrides);
  const auto* model_node = t.get("model");
  if (model_node != nullptr && model_node->is_string() && model_node->as_string()->get() == "aggregation")
    return evolve_aggregation_scene(t, counters);  // sticking grains (issue 21): evolve_aggregation.cpp
  const bool viscoelastic =
      model_node != nullptr && model_node->is_string() && model_node->as_string()->get() == "viscoelastic";
  std::set<std::string> valid{"model", "dimension", "order", "t_end", "points",
                              "times", "rtol",      "atol",  "a2",    "coefficients"};
  if (viscoelastic) {
    valid.insert("delta");
  } else {
    valid.insert("alpha");
    valid.insert("temperature");
  }
  for (const auto& [key, value] : t) {
    const std::string k(key.str());
    if (!valid.contains(k)) {
      throw error(k + ": unknown key for gkt evolve; valid keys: " + join({valid.begin(), valid.end()}));
    }
  }
  if (model_node == nullptr || !model_node->is_string() ||
      (!viscoelastic && model_node->as_string()->get() != "smooth-inelastic"))
    throw error(
        "model: gkt evolve supports \"smooth-inelastic\" (constant restitution), \"viscoelastic\" and \"aggregation\"");
  const double dim = number(t, "dimension", 3, 2, false, 3, "2 or 3");
  if (dim != 2 && dim != 3) throw error("dimension: must be 2 or 3, got " + format_number(dim));
  const int d = static_cast<int>(dim);
  if (viscoelastic && d != 3) throw error("dimension: \"viscoelastic\" is three-dimensional (3)");
  Rational alpha(1);
  double delta = 0;
  if (viscoelastic) {
    if (!t.contains("delta")) throw error("delta: required for \"viscoelastic\", a number in [0, 0.3]");
    delta = number(t, "delta", 0, 0, false, 0.3, "a number in [0, 0.3] (the delta expansion is for small delta)");
  } else {
    const auto* alpha_node = t.get("alpha");
    if (alpha_node == nullptr) throw error("alpha: required, a number in (0, 1]");
    if (alpha_node->is_array() || alpha_node->is_table()) throw error("alpha: must be a single number in (0, 1]");
    alpha = scene_number(*alpha_node, "alpha");
    if (alpha.sign() <= 0 || alpha > Rational(1))
      throw error("alpha: must be a number in (0, 1], got " + alpha.to_decimal_string());
  }
  const double order = number(t, "order", 3, 1, false, kMaxOrder, "an integer in [1, 12]");
  if (order != std::floor(order)) throw error("order: must be an integer in [1, 12], got " + format_number(order));
  const int k_max = static_cast<int>(order) + 1;  // cumulants a_2 … a_{order+1}
  const double rtol = number(t, "rtol", 1e-8, 0, true, 0.1, "a number in (0, 0.1]");
  const double atol = number(t, "atol", 1e-12, 0, true, 1, "a number in (0, 1]");
  const double temperature = number(t, "temperature", 1, 0, true, 1e300, "a number > 0");
  // Positivity of f_M(1 + a2 S_2): at c = 0 (a2 ≥ −8/(d(d+2))) and at the minimum of S_2
  // (a2 ≤ 4/(d+2)); docs/theory.md §12.
  const double a2_lo = -8.0 / (d * (d + 2)), a2_hi = 4.0 / (d + 2);
  const double a2 = number(t, "a2", 0, a2_lo, false, a2_hi,
                           "a number in [" + format_number(a2_lo) + ", " + format_number(a2_hi) +
                               "] (a positive distribution at c = 0 and at the minimum of S2)");
  std::vector<double> times;
  if (const auto* list = t.get("times")) {
    if (t.contains("t_end") || t.contains("points")) throw error("times: give either times or t_end/points");
    const auto* array = list->as_array();
    if (array == nullptr || array->empty()) throw error("times: must be a non-empty list of increasing times > 0");
    if (array->size() > static_cast<std::size_t>(kMaxPoints))
      throw error("times: at most " + std::to_string(kMaxPoints) + " output times, got " +
                  std::to_string(array->size()));
    for (const auto& item : *array) {
      const double v = scene_number(item, "times").to_double();
      if (!(v > 0) || (!times.empty() && !(v > times.back())))
        throw error("times: must be a non-empty list of increasing times > 0");
      times.push_back(v);
    }
  } else {
    if (!t.contains("t_end")) throw error("t_end: required (a number > 0), or give times = [...]");
    const double t_end = number(t, "t_end", 1, 0, true, 1e300, "a number > 0");
    const double points = number(t, "points", 50, 1, false, kMaxPoints, "an integer in [1, 1000000]");
    if (points != std::floor(points)) throw error("points: must be an integer in [1, 1000000]");
    // Log-spaced from the first collisions (τ = 0.01, or t_end/100 if earlier) to t_end.
    const int n = static_cast<int>(points);
    const double start = std::min(0.01, t_end / 100);
    for (int i = 0; i < n; ++i)
      times.push_back(n == 1 ? t_end : start * std::pow(t_end / start, static_cast<double>(i) / (n - 1)));
  }

  // Transport coefficients along the trajectory (theory.md §12.3), only those asked for.
  const std::vector<std::string> offered{"shear_viscosity",          "thermal_conductivity",
                                         "density_heat_coefficient", "critical_wavenumber_shear",
                                         "critical_wavenumber_heat", "critical_length"};
  std::vector<std::string> coefficients;
  if (const auto* c = t.get("coefficients")) {
    const auto* array = c->as_array();
    if (array == nullptr || array->empty()) throw error("coefficients: must be a non-empty list of names");
    for (const auto& item : *array) {
      const std::string name = item.is_string() ? item.as_string()->get() : "";
      if (std::find(offered.begin(), offered.end(), name) == offered.end())
        throw error("coefficients: '" + name + "' is not offered along a " + std::string(table_model(viscoelastic)) +
                    " trajectory; valid: " + join(offered));
      coefficients.push_back(name);
    }
  }

  EvolutionResult result;
  try {
    if (viscoelastic) {
      result = evolve_viscoelastic_cooling(ViscoelasticHierarchy(k_max), delta, {a2}, times, rtol, atol);
    } else {
      HomogeneousCoolingState hcs(d);
      result = evolve_homogeneous_cooling(hcs.hierarchy(alpha, k_max), temperature, {a2}, times, rtol, atol);
    }
  } catch (const EvolutionFailure& e) {  // "times: …" is the scene's t_end unless it lists times
    const std::string message = e.what();
    if (e.tolerances() || t.contains("times")) throw;
    throw error("t_end" + message.substr(message.find(':')));
  }
  Table table;
  table.model = table_model(viscoelastic);
  table.columns = {"time", "collisions", "temperature"};
  for (int k = 2; k <= k_max; ++k) {
    std::string name(1, 'a');
    name += std::to_string(k);
    table.columns.push_back(name);
  }
  table.columns.emplace_back("cooling_rate");
  for (const auto& c : coefficients) table.columns.push_back(c);
  table.numeric.assign(table.columns.size(), true);
  std::optional<NavierStokesSolver> solver;
  std::optional<ViscoelasticTransportSeries> series;
  if (!coefficients.empty()) {
    if (viscoelastic) {
      if (order > kMaxViscoelasticOrder)
        throw error("order: viscoelastic transport along the trajectory needs an integer in [1, " +
                    std::to_string(kMaxViscoelasticOrder) + "], got " + format_number(order));
      series = viscoelastic_transport_series(static_cast<int>(order));
    } else {
      solver.emplace(d);
    }
  }
  for (const auto& s : result.samples) {
    std::vector<std::string> row{format_number(s.time), format_number(s.collisions), format_number(s.temperature)};
    for (int k = 2; k <= k_max; ++k) row.push_back(format_number(s.a[static_cast<std::size_t>(k)]));
    row.push_back(format_number(s.cooling_rate));
    if (!coefficients.empty()) {
      NavierStokesValues v;
      StabilityDensity dilute;
      if (viscoelastic) {  // the δ'-series at Sonine order N, δ'(τ) = δ (2T/T0)^{1/10} (theory.md §13.2)
        const ViscoelasticState state = viscoelastic_state(*series, delta * std::pow(2.0 * s.temperature, 0.1));
        v.shear_viscosity = state.shear_viscosity;
        v.thermal_conductivity = state.thermal_conductivity;
        v.density_heat_coefficient = state.density_heat_coefficient;
        dilute.cooling_temperature_exponent = state.cooling_temperature_exponent;
      } else {  // order N about the instantaneous cumulants a(τ)
        v = solver->solve(alpha, static_cast<int>(order), s.a);
      }
      // Critical sizes at the instantaneous state (theory.md §12.3), ζ*(τ) from the hierarchy; for
      // viscoelastic grains ζ ∝ n T^{λ_T} with λ_T(δ') of the series (theory.md (14.6)).
      const HcsStability stability = hcs_stability(d, s.cooling_rate, v.shear_viscosity, v.thermal_conductivity,
                                                   v.density_heat_coefficient, dilute);
      for (const auto& c : coefficients)
        row.push_back(format_number(c == "shear_viscosity"             ? v.shear_viscosity
                                    : c == "thermal_conductivity"      ? v.thermal_conductivity
                                    : c == "density_heat_coefficient"  ? v.density_heat_coefficient
                                    : c == "critical_wavenumber_shear" ? stability.shear_wavenumber
                                    : c == "critical_wavenumber_heat"  ? stability.heat_wavenumber
                                                                       : stability.critical_length));
    }
    table.rows.push_back(std::move(row));
  }
  const auto& c = result.counters;
  counters = "cvode: steps=" + std::to_string(c.steps) + " rhs=" + std::to_string(c.rhs_evaluations) +
             " jacobians=" + std::to_string(c.jacobian_evaluations) +
             " error_test_failures=" + std::to_string(c.error_test_failures) +
             " newton_iterations=" + std::to_string(c.nonlinear_iterations);
  return table;
}

}  // namespace gkt::cli
