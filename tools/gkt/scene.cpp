#include "scene.hpp"

#include "table_writer.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>

#include <toml++/toml.h>

namespace gkt::cli {

namespace {

constexpr long kMaxSweepPoints = 1000000;  // rows of a table: the product over every swept key
constexpr std::size_t kMaxSceneBytes = 64UL << 20;

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
  if (assignment.find_first_of("\n\r") != std::string::npos)
    throw error("--set: KEY=VALUE must be one line (a second line would be dropped), got '" + quote_short(assignment) +
                "'");
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw error("--set: expected KEY=VALUE, got '" + quote_short(assignment) + "'");
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

/// Refuses, before any value is read, a scene whose sweeps make more than kMaxSweepPoints rows:
/// the product over every swept key (lists and ranges), not each key alone.
void check_row_count(const toml::table& table, const std::vector<ParameterSpec>& specs) {
  double rows = 1;
  std::string keys, factors;
  for (const auto& spec : specs) {
    const auto* node = table.get(spec.name);
    if (node == nullptr || spec.kind == ParameterSpec::Kind::choice) continue;
    double count = 1;
    if (const auto* array = node->as_array()) count = static_cast<double>(array->size());
    if (const auto* range = node->as_table())
      if (const auto* points = range->get("points"); points != nullptr && points->is_integer())
        count = std::max<double>(1, static_cast<double>(points->as_integer()->get()));
    if (count <= 1) continue;
    rows *= count;
    keys += (keys.empty() ? "" : ", ") + spec.name;
    factors += (factors.empty() ? "" : " x ") + std::to_string(static_cast<long long>(count));
  }
  if (rows > static_cast<double>(kMaxSweepPoints)) {
    char total[32];
    std::snprintf(total, sizeof total, "%.3g", rows);
    throw error(keys + ": the sweep makes " + total + " rows (" + factors + "); at most " +
                std::to_string(kMaxSweepPoints) + " rows per table");
  }
}

/// A restitution matrix `key = [[…], …]` (alpha; beta of rough grains) of k species becomes key_i_j (i ≤ j);
/// a number or a sweep is left alone.
void flatten_restitution_matrix(toml::table& scene, const std::string& key, int k) {
  const auto* matrix = scene.get_as<toml::array>(key);
  if (matrix == nullptr || matrix->empty() || !matrix->get(0)->is_array()) return;  // a number or a sweep
  const std::string shape = key + ": a restitution matrix must be " + std::to_string(k) + " x " + std::to_string(k) +
                            " (one row per species)";
  if (static_cast<int>(matrix->size()) != k) throw error(shape);
  std::vector<std::vector<const toml::node*>> rows;
  for (const auto& row : *matrix) {
    const auto* r = row.as_array();
    if (r == nullptr || static_cast<int>(r->size()) != k) throw error(shape);
    rows.emplace_back();
    for (const auto& v : *r) rows.back().push_back(&v);
  }
  for (int i = 0; i < k; ++i)
    for (int j = i; j < k; ++j) {
      const std::string name = key + "_" + std::to_string(i + 1) + "_" + std::to_string(j + 1);
      const Rational a = scene_number(*rows[i][j], name), b = scene_number(*rows[j][i], name);
      if (a != b)
        throw error(key + ": the restitution matrix must be symmetric, got " + key + "[" + std::to_string(i + 1) +
                    "][" + std::to_string(j + 1) + "] = " + a.to_decimal_string() + " and " + key + "[" +
                    std::to_string(j + 1) + "][" + std::to_string(i + 1) + "] = " + b.to_decimal_string());
      if (!scene.contains(name)) scene.insert_or_assign(name, *rows[i][j]);
    }
  scene.erase(key);
}

}  // namespace

/// Mixtures: the [[species]] tables become mass_k, diameter_k, fraction_k (and moment_of_inertia_k of
/// rough grains; k from 1) and the integer `species`; a restitution matrix `alpha = [[…], …]` becomes
/// alpha_i_j (i ≤ j), and `beta = [[…], …]` beta_i_j. Keys
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
      if (field != "mass" && field != "diameter" && field != "fraction" && field != "moment_of_inertia")
        throw error(at + field + ": unknown key; valid keys: diameter, fraction, mass, moment_of_inertia, name");
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

  for (const std::string restitution : {"alpha", "beta"}) flatten_restitution_matrix(scene, restitution, k);
}

/// Returns the keys with their species/pair indices collapsed: mass_1 … mass_4 become mass_i,
/// alpha_1_2 … alpha_4_4 become alpha_i_j (a short list of valid keys).
std::vector<std::string> indexed_keys_collapsed(const std::set<std::string>& keys) {
  std::vector<std::string> out;
  for (const auto& key : keys) {
    std::string base = key;
    int indices = 0;
    for (;;) {
      const auto underscore = base.rfind('_');
      if (underscore == std::string::npos || underscore + 1 == base.size() ||
          base.find_first_not_of("0123456789", underscore + 1) != std::string::npos)
        break;
      base.resize(underscore);
      ++indices;
    }
    if (indices == 1) base += "_i";
    if (indices == 2) base += "_i_j";
    if (indices > 2) base = key;
    if (std::find(out.begin(), out.end(), base) == out.end()) out.push_back(base);
  }
  return out;
}

toml::table parse_scene_text(const std::string& text, const std::string& source) {
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw error("scene: " + source + ":" + std::to_string(e.source().begin.line) + ": " + std::string(e.description()));
  }
}

void apply_overrides(toml::table& scene, const std::vector<std::string>& overrides) {
  for (const auto& o : overrides) apply_override(scene, o);
}

toml::table read_scene_table(const std::string& path, const std::vector<std::string>& overrides) try {
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored))
    throw error("scene: '" + path + "' is a directory, not a scene file (TOML)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw error("scene: cannot open '" + path + "'");
  std::string text;  // read in bounded pieces: /dev/zero or a huge file is refused, not read forever
  std::array<char, 1 << 16> piece{};
  while (in.read(piece.data(), piece.size()) || in.gcount() > 0) {
    text.append(piece.data(), static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxSceneBytes)
      throw error("scene: '" + path + "' is larger than " + std::to_string(kMaxSceneBytes >> 20) + " MB");
  }
  if (in.bad()) throw error("scene: cannot read '" + path + "'");
  toml::table table = parse_scene_text(text, path);
  apply_overrides(table, overrides);
  return table;
} catch (const std::invalid_argument& e) {
  throw error(e.what());  // one line, also for messages of the library
}

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides, bool require_order) {
  return load_scene(read_scene_table(path, overrides), require_order);
}

Scene load_scene(toml::table table, bool require_order) try {
  flatten_mixture(table);
  Scene scene;
  const auto* model_node = table.get("model");
  if (model_node == nullptr || !model_node->is_string()) {
    throw error("model: required string; valid models: " + join(transport_model_names(), "\""));
  }
  scene.model = model_node->as_string()->get();
  const auto models = transport_model_names();
  if (std::find(models.begin(), models.end(), scene.model) == models.end())
    throw error("model: unknown model \"" + quote_short(scene.model) + "\"; valid models: " + join(models, "\""));
  const auto model = make_transport_model(scene.model);

  std::vector<ParameterSpec> specs = model->parameters();
  for (auto& spec : order_parameters(model->max_order())) specs.push_back(std::move(spec));

  // The number of species first: a fifth [[species]] table is "at most 4 species", not an
  // unknown key diameter_5.
  for (const auto& spec : specs)
    if (spec.name == "species" && table.contains("species")) spec.check(scene_number(*table.get("species"), "species"));
  std::set<std::string> valid_keys{"model", "coefficients"};
  for (const auto& s : specs) valid_keys.insert(s.name);
  for (const auto& [key, value] : table) {
    const std::string k(key.str());
    if (!valid_keys.contains(k)) {
      throw error(quote_short(k) + ": unknown key for model \"" + scene.model +
                  "\"; valid keys: " + join(indexed_keys_collapsed(valid_keys)));
    }
  }

  ParameterPoint fixed;  // single-valued numbers: what the model's coefficient list may depend on
  for (const auto& [key, value] : table) {
    if (value.is_integer() || value.is_floating_point())
      fixed.numbers[std::string(key.str())] = scene_number(value, std::string(key.str()));
    if (value.is_string()) fixed.choices[std::string(key.str())] = value.as_string()->get();  // e.g. hcs
  }
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
        throw error("coefficients: unknown coefficient '" + quote_short(name) + "' for model \"" + scene.model +
                    "\"; valid: " + join(names));
      }
      if (std::find(scene.coefficients.begin(), scene.coefficients.end(), name) != scene.coefficients.end())
        throw error("coefficients: '" + name + "' is listed twice");
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
  check_row_count(table, specs);
  // Ranges that depend on a fixed dimension (packing fraction) are quoted for that dimension:
  // the scene's spec of a key whose range differs between d = 2 and d = 3.
  const auto scene_specs = model->scene_parameters(fixed);
  std::vector<ParameterSpec> per_dimension[2];
  for (int d : {2, 3}) {
    ParameterPoint point;
    point.numbers["dimension"] = Rational(d);
    per_dimension[d - 2] = model->scene_parameters(point);
  }
  auto find = [](const std::vector<ParameterSpec>& list, const std::string& name) {
    return std::find_if(list.begin(), list.end(), [&](const ParameterSpec& s) { return s.name == name; });
  };
  auto dimension_dependent = [&](const std::string& name) {
    const auto a = find(per_dimension[0], name), b = find(per_dimension[1], name);
    return fixed.numbers.contains("dimension") && a != per_dimension[0].end() && b != per_dimension[1].end() &&
           (a->min != b->min || a->max != b->max);
  };
  for (const auto& spec : specs) {
    const auto* node = table.get(spec.name);
    if (node == nullptr) continue;
    if (spec.kind == ParameterSpec::Kind::choice) {
      if (!node->is_string()) throw error(spec.name + ": must be " + spec.allowed());
      const std::string value = node->as_string()->get();
      if (std::find(spec.choices.begin(), spec.choices.end(), value) == spec.choices.end())
        throw error(spec.name + ": must be " + spec.allowed() + ", got \"" + quote_short(value) + "\"");
      scene.choices[spec.name] = value;
      continue;
    }
    if (node->is_string())
      throw error(spec.name + ": must be a number, a list of numbers or { from = a, to = b, points = k }");
    Axis axis = read_axis(spec.name, *node);
    const auto scene_spec = find(scene_specs, spec.name);
    const ParameterSpec& range = scene_spec == scene_specs.end() ? spec : *scene_spec;
    const bool per_dimension_range = dimension_dependent(spec.name);
    for (const auto& v : axis.values) {
      try {
        range.check(v);
      } catch (const std::invalid_argument&) {
        if (!per_dimension_range) throw;
        throw error(spec.name + ": must be " + range.allowed() + " for dimension = " +
                    fixed.number("dimension", Rational(3)).to_decimal_string() + ", got " + v.to_decimal_string());
      }
    }
    scene.axes.push_back(std::move(axis));
  }
  return scene;
} catch (const std::invalid_argument& e) {
  throw error(e.what());  // one line, also for messages of the library (model names, choices)
}

}  // namespace gkt::cli
