// Test helper: runs the gkt program (GKT_CLI_PATH) with shell-quoted arguments and captures its exit status, stdout
// and stderr; the shipped scenes' paths; a CSV text split into cells.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace gkt::test {

/// What one run of gkt gave back.
struct CliRun {
  int status = -1;
  std::string out, err;
};

/// Returns the whole content of file p ("" if it cannot be read).
inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Runs `gkt <args>` (the caller quotes for the shell) with stdout and stderr in files under a per-process temporary
/// folder named after `label`, and returns the exit status (-1 if it did not exit) and both streams.
inline CliRun run_gkt(const std::string& args, const std::string& label = "gkt_cli_test_") {
  static int counter = 0;
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / (label + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path out = dir / ("out" + std::to_string(counter));
  const fs::path err = dir / ("err" + std::to_string(counter++));
  const std::string cmd = std::string(GKT_CLI_PATH) + " " + args + " >" + out.string() + " 2>" + err.string();
  const int raw = std::system(cmd.c_str());
  CliRun r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = read_file(out);
  r.err = read_file(err);
  return r;
}

/// Returns the path of the shipped scene tables/scenes/<name>.
inline std::string scene_path(const std::string& name) {
  return std::string(GKT_SOURCE_DIR) + "/tables/scenes/" + name;
}

/// Returns the rows of a CSV text, each split at its commas (no quoting: gkt's tables have none).
inline std::vector<std::vector<std::string>> parse_csv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::stringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    std::vector<std::string> cells;
    std::stringstream cs(line);
    std::string cell;
    while (std::getline(cs, cell, ',')) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

}  // namespace gkt::test
