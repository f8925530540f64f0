#include "evolve_command.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

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

/// Reads the choice `spec.name` of the scene into `point` (absent: not in `point`); a true/false
/// choice is a TOML boolean. The model's guard checks the value against the choices.
void read_choice(const toml::table& t, const ParameterSpec& spec, ParameterPoint& point) {
  const auto* node = t.get(spec.name);
  if (node == nullptr) return;
  if (spec.choices == std::vector<std::string>{"false", "true"}) {
    if (!node->is_boolean()) throw error(spec.name + ": must be true or false");
    point.choices[spec.name] = node->as_boolean()->get() ? "true" : "false";
    return;
  }
  if (!node->is_string()) throw error(spec.name + ": must be " + spec.allowed() + ", got a non-string");
  point.choices[spec.name] = node->as_string()->get();
}

/// Returns the output times of the scene: its list `times`, or t_end/points log-spaced.
std::vector<double> read_output_times(const toml::table& t) {
  if (const auto* list = t.get("times")) {
    if (t.contains("t_end") || t.contains("points")) throw error("times: give either times or t_end/points");
    const auto* array = list->as_array();
    if (array == nullptr || array->empty()) throw error("times: must be a non-empty list of increasing times > 0");
    if (array->size() > static_cast<std::size_t>(kMaxPoints))
      throw error("times: at most " + std::to_string(kMaxPoints) + " output times, got " +
                  std::to_string(array->size()));
    std::vector<double> times;
    for (const auto& item : *array) times.push_back(scene_number(item, "times").to_double());
    return times;
  }
  if (!t.contains("t_end")) throw error("t_end: required (a number > 0), or give times = [...]");
  const auto time_specs = output_time_parameters();
  ParameterPoint range;
  for (const auto& spec : time_specs) read_number(t, spec, range);
  validate_parameters(time_specs, range, "the output times");
  const Rational t_end = range.numbers.at("t_end");
  const Rational points = range.number("points", find_parameter(time_specs, "points").default_value);
  return log_spaced_times(t_end.to_double(), static_cast<int>(points.to_double()));
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

Table evolve(const toml::table& scene, std::string& counters) {
  toml::table t = scene;
  flatten_mixture(t);  // a mixture's [[species]] tables and α matrix become its indexed keys
  const auto* model_node = t.get("model");
  if (model_node == nullptr || !model_node->is_string()) throw unsupported_model();
  const std::string model_name = model_node->as_string()->get();
  const auto names = transport_model_names();
  if (std::find(names.begin(), names.end(), model_name) == names.end()) throw unsupported_model();
  const auto model = make_transport_model(model_name);
  if (!model->supports(Capability::evolve)) throw unsupported_model();

  // The model's evolution parameters, the output times (unless the model sets its own, from its
  // t_end and points) and the coefficients offered along the trajectory are the keys.
  const auto specs = model->evolution_parameters();
  const bool own_times = sets_own_output_times(specs);
  const auto time_specs = own_times ? std::vector<ParameterSpec>{} : output_time_parameters();
  std::set<std::string> valid{"model"};
  if (!own_times) valid.insert("times");
  if (!model->trajectory_coefficients().empty()) valid.insert("coefficients");
  for (const auto& s : specs) valid.insert(s.name);
  for (const auto& s : time_specs) valid.insert(s.name);
  for (const auto& [key, value] : t) {
    const std::string k(key.str());
    if (!valid.contains(k))
      throw error(k + ": unknown key for gkt evolve with model \"" + model_name +
                  "\"; valid keys: " + join(indexed_keys_collapsed(valid)));
  }
  TrajectoryRequest request;
  for (const auto& spec : specs) {
    if (spec.kind == ParameterSpec::Kind::choice)
      read_choice(t, spec, request.parameters);
    else
      read_number(t, spec, request.parameters);
  }

  if (!own_times) request.times = read_output_times(t);
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
    if (e.tolerances() || t.contains("times") || message.rfind("times:", 0) != 0) throw;  // max_steps: as is
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
  counters = "cvode: " + (trajectory.linear_solver.empty() ? "" : "linear_solver=" + trajectory.linear_solver + " ") +
             "steps=" + std::to_string(n.steps) + " rhs=" + std::to_string(n.rhs_evaluations) +
             (trajectory.linear_solver.empty() ? " jacobians=" + std::to_string(n.jacobian_evaluations) : "") +
             " error_test_failures=" + std::to_string(n.error_test_failures) +
             " newton_iterations=" + std::to_string(n.nonlinear_iterations);
  return table;
}

}  // namespace gkt::cli
