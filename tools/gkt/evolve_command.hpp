// `gkt evolve`: time series of a freely cooling homogeneous gas (T, cumulants, collisions).
#pragma once

#include <string>
#include <vector>

#include <toml++/toml.h>

#include "table_writer.hpp"

namespace gkt::cli {

/// Returns the computed time series for the scene, and the CVODE counters as one line in
/// `counters`. Throws std::invalid_argument (one line naming the field) on bad input.
Table evolve(const std::string& scene_path, const std::vector<std::string>& overrides, std::string& counters);

/// The same for an already parsed scene table (overrides applied): the Python module's entry.
Table evolve(const toml::table& scene, std::string& counters);

}  // namespace gkt::cli
