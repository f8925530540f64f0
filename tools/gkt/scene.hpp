// Scene files: what a `gkt` run asks for (TOML). Front-end layer: talks to the library only
// through the public model interface (gkt/models/transport_model.hpp).
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "gkt/algebra/rational.hpp"
#include "gkt/models/transport_model.hpp"

namespace gkt::cli {

/// One numeric scene key and the values it takes (one value unless swept).
struct Axis {
  std::string key;
  std::vector<Rational> values;
  bool swept = false;  ///< given as a list or a {from, to, points} range
};

/// A validated scene: model, requested coefficients and the parameter axes.
struct Scene {
  std::string model;
  std::vector<std::string> coefficients;
  bool coefficients_given = false;             ///< the scene (or --set) named them; else all of the model's
  std::vector<Axis> axes;                      ///< model parameters first, then order or tolerance
  std::map<std::string, std::string> choices;  ///< choice parameters (e.g. hcs = "linear")
};

/// Returns the scene read from `path` with `overrides` ("key=value", value in TOML syntax)
/// applied; validates every key, type and range against `model`'s parameter list.
/// Throws std::invalid_argument with a one-line message naming the field on bad input.
/// Returns the parsed TOML table of a scene file with `overrides` applied (one-line errors).
toml::table read_scene_table(const std::string& path, const std::vector<std::string>& overrides);

/// Returns the TOML table parsed from scene text; a syntax error throws std::invalid_argument
/// "scene: <source>:<line>: <what>" (`source` names the text, e.g. a path or "<string>").
toml::table parse_scene_text(const std::string& text, const std::string& source);

/// Applies `overrides` ("key=value", value in TOML syntax) to a scene table, as `--set` does.
void apply_overrides(toml::table& scene, const std::vector<std::string>& overrides);

/// Mixtures: turns the [[species]] tables into mass_k, diameter_k, fraction_k (k from 1) and the
/// integer `species`, and a restitution matrix into alpha_i_j (i ≤ j); keys given explicitly win.
void flatten_mixture(toml::table& scene);

/// Returns the keys with their species/pair indices collapsed (mass_1 … mass_4 become mass_i).
std::vector<std::string> indexed_keys_collapsed(const std::set<std::string>& keys);

/// Returns the exact value of a numeric TOML node; throws "<key>: must be a number …".
Rational scene_number(const toml::node& node, const std::string& key);

/// With require_order = false a scene may omit both `order` and `tolerance` (gkt formula).
Scene load_scene(const std::string& path, const std::vector<std::string>& overrides, bool require_order = true);

/// Returns the validated scene of an already parsed scene table (overrides applied), as load_scene
/// does for a file: the Python module's entry for scenes given as text or as a dict.
Scene load_scene(toml::table table, bool require_order = true);

}  // namespace gkt::cli
