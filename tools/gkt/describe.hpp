// Self-describing output (issue 19): what a table's JSON carries besides its rows (gkt's version,
// the resolved scene, each column's meaning, reduction and unit) and `gkt models --describe`.
#pragma once

#include <optional>
#include <string>

#include "gkt/models/column_catalogue.hpp"
#include "gkt/models/transport_model.hpp"
#include "scene.hpp"

namespace gkt::cli {

/// Returns a JSON object (text) with "units" ("reduced" or "physical"; physical:
/// also "reference", the SI reference values), "scene" (every key of the scene's model as used,
/// defaults included, and the list "defaults_applied") and "column_descriptions" (per column of
/// the table: meaning, reduced_by, unit of the printed values and si_unit); to_json puts its
/// members before the table's columns.
std::string describe_table(const Scene& scene, const std::optional<PhysicalReference>& physical);

/// Returns the dimension of a scene if it is fixed (the scene's value or the model's default; 3
/// for a model without the key), or nullopt if the scene sweeps it.
std::optional<int> scene_dimension(const Scene& scene);

/// Returns the description of one model (`name`) or of every model (empty): its keys with kind,
/// allowed values, default and meaning, the commands it supports, its evolution keys and its
/// columns with meaning, reduction and SI unit; JSON when `json`, else text.
std::string describe_models(const std::string& name, bool json);

/// Returns the registered models that support `capability`, quoted and joined for an error message
/// (e.g. "\"mixture\", \"rough\" or \"smooth-inelastic\"").
std::string models_supporting(Capability capability);

}  // namespace gkt::cli
