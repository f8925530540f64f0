// Formatting of result tables (CSV, JSON) and atomic output: nothing is written unless the
// whole table was computed.
#pragma once

#include <string>
#include <vector>

namespace gkt::cli {

/// A computed table: column names and rows of already formatted cells.
struct Table {
  std::string model;
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
  std::vector<bool> numeric;  ///< per column: emit as a JSON number (else a string)
};

/// Returns x in the shortest decimal that reads back as the same double (std::to_chars).
std::string format_number(double x);

/// Returns the items joined by ", ", each wrapped in `quote` (e.g. "\"" for names).
std::string join(const std::vector<std::string>& items, const std::string& quote = "");

/// Returns the table as CSV (header line, one line per row).
std::string to_csv(const Table& t);
/// Returns the table as JSON: {"model": …, "columns": […], "rows": [{column: value, …}, …]}.
std::string to_json(const Table& t);

/// Writes `content` to `path` atomically (temporary file in the same directory, then
/// rename), or to standard output if `path` is empty. Throws std::runtime_error on failure.
void write_output(const std::string& path, const std::string& content);

}  // namespace gkt::cli
