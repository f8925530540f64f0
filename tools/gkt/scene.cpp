#include "scene.hpp"

#include "table_writer.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include <toml++/toml.h>

namespace gkt::cli {

namespace {

constexpr long kMaxSweepPoints = 1000000;

/// The error for `message`, kept on one line: control characters a scene or --set may carry into an
/// echoed key or value are written as \xNN (found by tests/fuzz/fuzz_scene).
std::invalid_argument error(const std::string& message) {
  std::string line;
  for (const char c : message) {
    if (static_cast<unsigned char>(c) >= 0x20 && c != 0x7f) {
      line += c;
      continue;
    }
    char escaped[5];
    std::snprintf(escaped, sizeof escaped, "\\x%02x", static_cast<unsigned>(static_cast<unsigned char>(c)));
    line += escaped;
  }
  return std::invalid_argument(line);
}

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

/// Mixtures: the [[species]] tables become mass_k, diameter_k, fraction_k (k from 1) and the
/// integer `species`; a restitution matrix `alpha = [[…], …]` becomes alpha_i_j (i ≤ j). Keys
/// given explicitly (e.g. --set mass_2=…) win over the tables.
void flatten_mixture(toml::table& scene) {
  const toml::node* node = scene.get("species");
  if (node == nullptr) return;
  const auto* array = node->as_array();
  if (array == nullptr || !array->is_array_of_tables())
    throw error("species: must be [[species]] tables with mass, diameter, fraction (and an optional name)");
  toml::table flat;
  int k = 0;
  for (const auto& item : *array) {
    ++k;
    const toml::table& t = *item.as_table();
    const std::string at = "species[" + std::to_string(k) + "].";
    for (const auto& [key, value] : t) {
      const std::string field(key.str());
      if (field == "name") {
        if (!value.is_string()) throw error(at + "name: must be a string");
        continue;
      }
      if (field != "mass" && field != "diameter" && field != "fraction")
        throw error(at + field + ": unknown key; valid keys: diameter, fraction, mass, name");
      const std::string flat_key = field + "_" + std::to_string(k);
      if (!scene.contains(flat_key)) flat.insert_or_assign(flat_key, value);
    }
    for (const char* field : {"mass", "diameter", "fraction"})
      if (!t.contains(field) && !scene.contains(std::string(field) + "_" + std::to_string(k)))
        throw error(at + field + ": required (a number > 0)");
  }
  scene.erase("species");
  for (const auto& [key, value] : flat) scene.insert_or_assign(key, value);
  scene.insert_or_assign("species", static_cast<int64_t>(k));

  const auto* alpha = scene.get_as<toml::array>("alpha");
  if (alpha == nullptr || alpha->empty() || !alpha->get(0)->is_array()) return;  // a number or a sweep
  const std::string shape =
      "alpha: a restitution matrix must be " + std::to_string(k) + " x " + std::to_string(k) + " (one row per species)";
  if (static_cast<int>(alpha->size()) != k) throw error(shape);
  std::vector<std::vector<const toml::node*>> rows;
  for (const auto& row : *alpha) {
    const auto* r = row.as_array();
    if (r == nullptr || static_cast<int>(r->size()) != k) throw error(shape);
    rows.emplace_back();
    for (const auto& v : *r) rows.back().push_back(&v);
  }
  for (int i = 0; i < k; ++i)
    for (int j = i; j < k; ++j) {
      const std::string name = "alpha_" + std::to_string(i + 1) + "_" + std::to_string(j + 1);
      const Rational a = scene_number(*rows[i][j], name), b = scene_number(*rows[j][i], name);
      if (a != b)
        throw error("alpha: the restitution matrix must be symmetric, got alpha[" + std::to_string(i + 1) + "][" +
                    std::to_string(j + 1) + "] = " + a.to_decimal_string() + " and alpha[" + std::to_string(j + 1) +
                    "][" + std::to_string(i + 1) + "] = " + b.to_decimal_string());
      if (!scene.contains(name)) scene.insert_or_assign(name, *rows[i][j]);
    }
  scene.erase("alpha");
}

}  // namespace

toml::table read_scene_table(const std::string& path, const std::vector<std::string>& overrides) try {
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
} catch (const std::invalid_argument& e) {
  throw error(e.what());  // one line, also for messages of the library
}

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides, bool require_order) try {
  toml::table table = read_scene_table(path, overrides);
  flatten_mixture(table);
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

  ParameterPoint fixed;  // single-valued numbers: what the model's coefficient list may depend on
  for (const auto& [key, value] : table)
    if (value.is_integer() || value.is_floating_point())
      fixed.numbers[std::string(key.str())] = scene_number(value, "");
  for (const auto& spec : specs)  // a key not given is single-valued too: its default
    if (spec.kind != ParameterSpec::Kind::choice && !table.contains(spec.name))
      fixed.numbers[spec.name] = spec.default_value;
  const auto names = model->scene_coefficient_names(fixed);
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
    scene.coefficients = model->default_coefficients(fixed);
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
} catch (const std::invalid_argument& e) {
  throw error(e.what());  // one line, also for messages of the library (model names, choices)
}

}  // namespace gkt::cli
