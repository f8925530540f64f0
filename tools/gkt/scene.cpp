#include "scene.hpp"

#include "table_writer.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include <toml++/toml.h>

namespace gkt::cli {

namespace {

constexpr long kMaxSweepPoints = 1000000;

std::invalid_argument error(const std::string& message) { return std::invalid_argument(message); }

}  // namespace

/// Exact value of a TOML number: integers exactly, floats by their shortest round-trip decimal.
Rational scene_number(const toml::node& node, const std::string& key) {
  if (const auto* i = node.as_integer()) return Rational(static_cast<long>(i->get()));
  if (const auto* f = node.as_floating_point()) {
    const double x = f->get();
    if (!std::isfinite(x)) throw error(key + ": must be a finite number");
    return Rational::parse(format_number(x));
  }
  throw error(key + ": must be a number, a list of numbers or { from = a, to = b, points = k }");
}

namespace {

/// Values of a numeric key: a number, an array, or an inclusive linear range.
Axis read_axis(const std::string& key, const toml::node& node) {
  Axis axis{key, {}, false};
  if (const auto* array = node.as_array()) {
    if (array->empty()) throw error(key + ": a sweep list must not be empty");
    axis.swept = true;
    for (const auto& item : *array) axis.values.push_back(scene_number(item, key));
    return axis;
  }
  if (const auto* range = node.as_table()) {
    for (const auto& [sub, value] : *range) {
      const std::string s(sub.str());
      if (s != "from" && s != "to" && s != "points")
        throw error(key + "." + s + ": unknown range key; valid keys: from, to, points");
    }
    if (!range->contains("from") || !range->contains("to") || !range->contains("points"))
      throw error(key + ": a range needs from, to and points");
    const Rational from = scene_number(*range->get("from"), key + ".from");
    const Rational to = scene_number(*range->get("to"), key + ".to");
    const auto* points_node = range->get("points")->as_integer();
    if (points_node == nullptr || points_node->get() < 1 || points_node->get() > kMaxSweepPoints)
      throw error(key + ".points: must be an integer in [1, " + std::to_string(kMaxSweepPoints) + "]");
    const long points = static_cast<long>(points_node->get());
    axis.swept = true;
    for (long k = 0; k < points; ++k)
      axis.values.push_back(points == 1 ? from
                                        : from + (to - from) * Rational(k, static_cast<unsigned long>(points - 1)));
    return axis;
  }
  axis.values.push_back(scene_number(node, key));
  return axis;
}

void apply_override(toml::table& scene, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) throw error("--set: expected KEY=VALUE, got '" + assignment + "'");
  std::string key = assignment.substr(0, eq);
  while (!key.empty() && key.back() == ' ') key.pop_back();
  const std::string value = assignment.substr(eq + 1);
  toml::table parsed;
  try {
    parsed = toml::parse("value = " + value);
  } catch (const toml::parse_error&) {
    // Bare words are strings: --set model=hard-spheres.
    parsed = toml::table{{"value", value}};
  }
  scene.insert_or_assign(key, *parsed.get("value"));
  // `order` and `tolerance` are alternatives: setting one replaces the other.
  if (key == "order") scene.erase("tolerance");
  if (key == "tolerance") scene.erase("order");
  // `times` and `t_end`/`points` (gkt evolve) are alternatives too.
  if (key == "times") {
    scene.erase("t_end");
    scene.erase("points");
  }
  if (key == "t_end" || key == "points") scene.erase("times");
}

}  // namespace

toml::table read_scene_table(const std::string& path, const std::vector<std::string>& overrides) {
  std::ifstream in(path);
  if (!in) throw error("scene: cannot open '" + path + "'");
  std::stringstream text;
  text << in.rdbuf();
  toml::table table;
  try {
    table = toml::parse(text.str(), path);
  } catch (const toml::parse_error& e) {
    throw error("scene: " + path + ":" + std::to_string(e.source().begin.line) + ": " + std::string(e.description()));
  }
  for (const auto& o : overrides) apply_override(table, o);
  return table;
}

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides, bool require_order) {
  toml::table table = read_scene_table(path, overrides);
  Scene scene;
  const auto* model_node = table.get("model");
  if (model_node == nullptr || !model_node->is_string()) {
    throw error("model: required string; valid models: " + join(transport_model_names(), "\""));
  }
  scene.model = model_node->as_string()->get();
  const auto model = make_transport_model(scene.model);  // throws on unknown names

  std::vector<ParameterSpec> specs = model->parameters();
  specs.push_back({"order",
                   ParameterSpec::Kind::integer,
                   Rational(1),
                   Rational(model->max_order()),
                   true,
                   true,
                   Rational(1),
                   "Sonine order (number of polynomials)",
                   {}});
  specs.push_back({"tolerance",
                   ParameterSpec::Kind::real,
                   Rational(0),
                   Rational(1),
                   false,
                   true,
                   Rational(0),
                   "target estimated truncation error",
                   {}});

  std::set<std::string> valid_keys{"model", "coefficients"};
  for (const auto& s : specs) valid_keys.insert(s.name);
  for (const auto& [key, value] : table) {
    const std::string k(key.str());
    if (!valid_keys.contains(k)) {
      throw error(k + ": unknown key for model \"" + scene.model +
                  "\"; valid keys: " + join({valid_keys.begin(), valid_keys.end()}));
    }
  }

  const auto names = model->coefficient_names();
  if (const auto* c = table.get("coefficients")) {
    const auto* array = c->as_array();
    if (array == nullptr || array->empty()) throw error("coefficients: must be a non-empty list of names");
    for (const auto& item : *array) {
      if (!item.is_string()) throw error("coefficients: must be a list of strings");
      const std::string name = item.as_string()->get();
      if (std::find(names.begin(), names.end(), name) == names.end()) {
        throw error("coefficients: unknown coefficient '" + name + "' for model \"" + scene.model +
                    "\"; valid: " + join(names));
      }
      scene.coefficients.push_back(name);
    }
    scene.coefficients_given = true;
  } else {
    scene.coefficients = names;
  }

  const bool has_order = table.contains("order"), has_tolerance = table.contains("tolerance");
  if ((has_order && has_tolerance) || (require_order && !has_order && !has_tolerance))
    throw error("order: give exactly one of 'order' (an integer in [1, " + std::to_string(model->max_order()) +
                "]) or 'tolerance' (a number in (0, 1])");
  for (const auto& spec : specs) {
    const auto* node = table.get(spec.name);
    if (node == nullptr) continue;
    if (spec.kind == ParameterSpec::Kind::choice) {
      if (!node->is_string()) throw error(spec.name + ": must be " + spec.allowed());
      const std::string value = node->as_string()->get();
      spec.check(value);
      scene.choices[spec.name] = value;
      continue;
    }
    if (node->is_string())
      throw error(spec.name + ": must be a number, a list of numbers or { from = a, to = b, points = k }");
    Axis axis = read_axis(spec.name, *node);
    for (const auto& v : axis.values) spec.check(v);
    scene.axes.push_back(std::move(axis));
  }
  return scene;
}

}  // namespace gkt::cli
