// `gkt table`: evaluate a scene over its parameter sweep and format the result table.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "gkt/models/column_catalogue.hpp"
#include "scene.hpp"
#include "table_writer.hpp"

namespace gkt::cli {

/// Output options of `gkt table`.
struct TableOptions {
  bool exact = false;  ///< cells as exact rationals (refused where a value is not rational)
  int jobs = 1;        ///< rows evaluated in parallel, each worker with its own model instance
  /// --units physical: coefficient columns (and their errors) times physical_scale of their
  /// reduction (column_catalogue.hpp) for this reference gas; not with `exact`.
  std::optional<PhysicalReference> physical = std::nullopt;
};

/// What a streamed table computation reports, every call on the calling thread, rows in sweep order.
struct RowObserver {
  /// After each finished row: its cells, rows done so far, rows in the sweep.
  std::function<void(const std::vector<std::string>& row, std::size_t done, std::size_t total)> on_row;
  /// About every 100 ms while the next row is being computed (a progress clock).
  std::function<void(std::size_t done, std::size_t total)> on_wait;
  /// Polled between rows and while waiting; true ends the sweep early (Table::interrupted).
  std::function<bool()> stop;
};

/// Returns the number of rows of the scene's sweep: the product of its axis lengths.
std::size_t sweep_size(const Scene& scene);

/// Returns the table without rows: model, columns (swept parameters, coefficients, their errors,
/// order), numeric flags and planned_rows.
Table table_header(const Scene& scene, const TableOptions& options);

/// Returns the computed table for a validated scene (one row per parameter point).
/// Throws std::invalid_argument for input the model rejects or --exact on inexact values.
Table compute_table(const Scene& scene, const TableOptions& options, std::vector<std::string>& warnings);

/// Returns the table like compute_table, reporting each row to `observer` as it is finished
/// (options.jobs workers, output order and bytes independent of jobs). When observer.stop ended
/// the sweep, the table holds the finished rows with `interrupted` set, and rows still being
/// computed run on in detached threads: the caller must then end the process (std::_Exit).
Table compute_table(const Scene& scene, const TableOptions& options, std::vector<std::string>& warnings,
                    const RowObserver& observer);

}  // namespace gkt::cli
