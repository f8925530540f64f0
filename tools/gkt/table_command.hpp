// `gkt table`: evaluate a scene over its parameter sweep and format the result table.
#pragma once

#include <string>
#include <vector>

#include "scene.hpp"
#include "table_writer.hpp"

namespace gkt::cli {

/// Output options of `gkt table`.
struct TableOptions {
  bool exact = false;  ///< cells as exact rationals (refused where a value is not rational)
};

/// Returns the computed table for a validated scene (one row per parameter point).
/// Throws std::invalid_argument for input the model rejects or --exact on inexact values.
Table compute_table(const Scene& scene, const TableOptions& options, std::vector<std::string>& warnings);

}  // namespace gkt::cli
