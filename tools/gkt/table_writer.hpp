// Formatting of result tables (CSV, JSON) and output that replaces a file only when it is complete
// (or carries an end marker, docs/conventions.md "Long runs").
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace gkt::cli {

/// A computed table: column names and rows of already formatted cells.
struct Table {
  std::string model;
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
  std::vector<bool> numeric;     ///< per column: emit as a JSON number (else a string)
  std::size_t planned_rows = 0;  ///< rows of the whole sweep (more than rows.size() if interrupted)
  bool interrupted = false;      ///< the sweep was ended by a signal: rows holds the finished ones
  /// A JSON object whose members to_json writes after "model" (version, scene, units) and, for
  /// "column_descriptions", after "columns" (describe.hpp); empty: none (CSV never uses it).
  std::string description_json;
};

/// Returns x in the shortest decimal that reads back as the same double (std::to_chars).
std::string format_number(double x);

/// Returns the items joined by ", ", each wrapped in `quote` (e.g. "\"" for names).
std::string join(const std::vector<std::string>& items, const std::string& quote = "");

/// Returns `text` as it is echoed in a message: at most 40 characters, then "…" (a 1 MB value
/// never comes back whole).
std::string quote_short(const std::string& text);

/// Returns the table as CSV (header line, one line per row).
std::string to_csv(const Table& t);
/// Returns the CSV line of a header or a row (cells joined by ',', then a newline).
std::string csv_line(const std::vector<std::string>& cells);
/// Returns the last line of an interrupted CSV table: "# interrupted after N of M rows".
std::string csv_interrupted_line(const Table& t);
/// Returns the table as JSON: {"model": …, "gkt_version": …, "columns": […], "rows": [{column:
/// value, …}, …]}, with the members of description_json (if any) after "gkt_version" and
/// "columns", and for an
/// interrupted table followed by "interrupted": true and "planned_rows": M.
std::string to_json(const Table& t);

/// Where a command's output goes: standard output (empty path) or the file `path`. Built before
/// any computation, so that a path that cannot be written is refused first:
/// - a regular file or a new name: a temporary file beside it, created now, renamed over the
///   target only when the whole content is written (the target keeps its permissions);
/// - a FIFO or a character device (/dev/null, a terminal; also through a symbolic link such as
///   /dev/stdout): written directly, never replaced;
/// - anything else (a symbolic link to a file, a directory, a block device, a socket, a missing
///   or unwritable folder): refused.
/// Every error is std::invalid_argument "<path>: …" (one line, the user's path; never the
/// temporary file's); on any error the target is untouched and the temporary file removed.
class OutputTarget {
 public:
  explicit OutputTarget(std::string path);
  ~OutputTarget();
  OutputTarget(const OutputTarget&) = delete;
  OutputTarget& operator=(const OutputTarget&) = delete;
  OutputTarget(OutputTarget&&) = delete;
  OutputTarget& operator=(OutputTarget&&) = delete;

  /// Writes `content` and commits it (flushes standard output, or renames the temporary file into
  /// place). Throws std::invalid_argument "<path>: write failed (<reason>)" or "standard output:
  /// write failed (<reason>)" when anything is lost (a full disk, /dev/full, a closed stream).
  void write(const std::string& content);

  /// Writes `chunk` now: to standard output (flushed), the FIFO or device, or the temporary file,
  /// which grows until commit(). Throws like write(); a temporary file is then discarded.
  void append(const std::string& chunk);
  /// Ends the output: flushes standard output, closes the FIFO or device, or renames the
  /// temporary file over the target. Throws like write().
  void commit();

 private:
  enum class Kind { standard_output, replace, direct };
  std::string path_;
  Kind kind_ = Kind::standard_output;
  std::string temporary_;  ///< Kind::replace: the temporary file beside the target
  int descriptor_ = -1;    ///< open on temporary_ (replace) or on the target (direct, from the first append)
  unsigned mode_ = 0;      ///< permissions the committed file gets
  long owner_ = -1, group_ = -1;
};

}  // namespace gkt::cli
