// `gkt evolve` with model = "aggregation": the population balance of sticking grains coupled to
// the granular temperature (docs/theory.md §20, docs/conventions.md).
#pragma once

#include <string>

#include <toml++/toml.h>

#include "table_writer.hpp"

namespace gkt::cli {

/// Returns the time series (or, with distribution = true, the long-format size distribution) of
/// the aggregation scene `t`, and the CVODE counters as one line in `counters`. Throws
/// std::invalid_argument (one line naming the field) on bad input.
Table evolve_aggregation_scene(const toml::table& t, std::string& counters);

}  // namespace gkt::cli
