#include "evolve_command.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

#include "evolve_aggregation.hpp"
#include "gkt/evolution/homogeneous_cooling_evolution.hpp"
#include "gkt/models/transport_model.hpp"
#include "scene.hpp"

namespace gkt::cli {

namespace {

constexpr long kMaxPoints = 1000000;  // output times, as the table cap (docs/conventions.md)

std::invalid_argument error(const std::string& message) { return std::invalid_argument(message); }

/// Returns the exact value of the single number `spec.name` of the scene (absent: not in `point`).
void read_number(const toml::table& t, const ParameterSpec& spec, ParameterPoint& point) {
  const auto* node = t.get(spec.name);
  if (node == nullptr) return;
  if (node->is_array() || node->is_table()) {
    const std::string allowed = spec.allowed();  // "a number in (0, 1]" reads "a single number in (0, 1]"
    throw error(spec.name + ": must be a single number" +
                (allowed.starts_with("a number ") ? allowed.substr(8) : " (" + allowed + ")"));
  }
  point.numbers[spec.name] = scene_number(*node, spec.name);
}

/// Returns the models that integrate a cooling trajectory, for the error of any other model.
std::invalid_argument unsupported_model() {
  std::vector<std::string> names;
  for (const auto& name : transport_model_names())
    if (make_transport_model(name)->supports(Capability::evolve)) names.push_back("\"" + name + "\"");
  std::string listed = names.empty() ? "" : names.back();
  if (names.size() > 1) listed = join({names.begin(), names.end() - 1}) + " and " + listed;
  return error("model: gkt evolve supports " + listed);
}

}  // namespace

Table evolve(const std::string& scene_path, const std::vector<std::string>& overrides, std::string& counters) {
  return evolve(read_scene_table(scene_path, overrides), counters);
}

Table evolve(const toml::table& t, std::string& counters) {
  const auto* model_node = t.get("model");
  if (model_node != nullptr && model_node->is_string() && model_node->as_string()->get() == "aggregation")
    return evolve_aggregation_scene(t, counters);  // sticking grains (issue 21): evolve_aggregation.cpp
  if (model_node == nullptr || !model_node->is_string()) throw unsupported_model();
  const std::string model_name = model_node->as_string()->get();
  const auto names = transport_model_names();
  if (std::find(names.begin(), names.end(), model_name) == names.end()) throw unsupported_model();
  const auto model = make_transport_model(model_name);
  if (!model->supports(Capability::evolve)) throw unsupported_model();

  // The model's evolution parameters, the output times and the coefficients are the keys.
  const auto specs = model->evolution_parameters();
  const auto time_specs = output_time_parameters();
  std::set<std::string> valid{"model", "times", "coefficients"};
  for (const auto& s : specs) valid.insert(s.name);
  for (const auto& s : time_specs) valid.insert(s.name);
  for (const auto& [key, value] : t) {
    const std::string k(key.str());
    if (!valid.contains(k))
      throw error(k + ": unknown key for gkt evolve; valid keys: " + join({valid.begin(), valid.end()}));
  }
  TrajectoryRequest request;
  for (const auto& spec : specs) read_number(t, spec, request.parameters);

  if (const auto* list = t.get("times")) {
    if (t.contains("t_end") || t.contains("points")) throw error("times: give either times or t_end/points");
    const auto* array = list->as_array();
    if (array == nullptr || array->empty()) throw error("times: must be a non-empty list of increasing times > 0");
    if (array->size() > static_cast<std::size_t>(kMaxPoints))
      throw error("times: at most " + std::to_string(kMaxPoints) + " output times, got " +
                  std::to_string(array->size()));
    for (const auto& item : *array) request.times.push_back(scene_number(item, "times").to_double());
  } else {
    if (!t.contains("t_end")) throw error("t_end: required (a number > 0), or give times = [...]");
    ParameterPoint range;
    for (const auto& spec : time_specs) read_number(t, spec, range);
    validate_parameters(time_specs, range, "the output times");
    const Rational t_end = range.numbers.at("t_end");
    const Rational points = range.number("points", find_parameter(time_specs, "points").default_value);
    request.times = log_spaced_times(t_end.to_double(), static_cast<int>(points.to_double()));
  }
  if (const auto* c = t.get("coefficients")) {
    const auto* array = c->as_array();
    if (array == nullptr || array->empty()) throw error("coefficients: must be a non-empty list of names");
    for (const auto& item : *array) request.coefficients.push_back(item.is_string() ? item.as_string()->get() : "");
  }

  Trajectory trajectory;
  try {
    trajectory = model->evolve(request);
  } catch (const EvolutionFailure& e) {  // "times: …" is the scene's t_end unless it lists times
    const std::string message = e.what();
    if (e.tolerances() || t.contains("times")) throw;
    throw error("t_end" + message.substr(message.find(':')));
  }
  Table table;
  table.model = model_name;
  table.columns = trajectory.columns;
  table.numeric.assign(table.columns.size(), true);
  for (const auto& values : trajectory.rows) {
    std::vector<std::string> row;
    for (const double v : values) row.push_back(format_number(v));
    table.rows.push_back(std::move(row));
  }
  const auto& n = trajectory.counters;
  counters = "cvode: steps=" + std::to_string(n.steps) + " rhs=" + std::to_string(n.rhs_evaluations) +
             " jacobians=" + std::to_string(n.jacobian_evaluations) +
             " error_test_failures=" + std::to_string(n.error_test_failures) +
             " newton_iterations=" + std::to_string(n.nonlinear_iterations);
  return table;
}

}  // namespace gkt::cli
