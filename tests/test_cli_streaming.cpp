// `gkt table` and `gkt stability` on long work (issue 19 item 5): rows streamed as they finish,
// --jobs N with output identical to --jobs 1, SIGINT/SIGTERM keeping the finished rows with the
// end marker of docs/conventions.md ("Long runs"), the progress line only on a terminal.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace {

std::string read_file(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string scene_path(const std::string& name) { return std::string(GKT_SOURCE_DIR) + "/tables/scenes/" + name; }

/// A fresh scratch folder for one test.
fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("gkt_stream_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

struct CliRun {
  int status = -1;
  std::string out, err;
};

/// Runs `gkt <args>` through the shell (60 s timeout), standard output and error captured in files
/// (neither is a terminal).
CliRun run_gkt(const std::string& args) {
  static int counter = 0;
  const fs::path dir = scratch("runs");
  const fs::path out = dir / ("out" + std::to_string(counter));
  const fs::path err = dir / ("err" + std::to_string(counter++));
  const std::string cmd =
      "timeout 60 " + std::string(GKT_CLI_PATH) + " " + args + " >" + out.string() + " 2>" + err.string();
  const int raw = std::system(cmd.c_str());
  CliRun r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = read_file(out);
  r.err = read_file(err);
  return r;
}

std::size_t count_lines(const std::string& text) {
  std::size_t n = 0;
  for (char c : text) n += c == '\n' ? 1 : 0;
  return n;
}

/// Starts gkt with `args` (no shell), standard output to `out`, standard error to `err`; returns its pid.
pid_t spawn_gkt(const std::vector<std::string>& args, const fs::path& out, const fs::path& err) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int o = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(o, STDOUT_FILENO);
    ::dup2(e, STDERR_FILENO);
    std::vector<char*> argv;
    std::string binary = GKT_CLI_PATH;
    argv.push_back(binary.data());
    std::vector<std::string> copy = args;
    for (auto& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    ::execv(binary.c_str(), argv.data());
    ::_exit(127);
  }
  return pid;
}

/// Returns N of a trailing "\n# interrupted after N of <planned> rows\n" line, or -1 if `text` does
/// not end with one (a plain parser: GCC 12's <regex> trips -Wmaybe-uninitialized under ASan).
long interrupted_rows(const std::string& text, const std::string& planned) {
  const std::string prefix = "\n# interrupted after ", suffix = " of " + planned + " rows\n";
  if (text.size() < suffix.size() || text.compare(text.size() - suffix.size(), suffix.size(), suffix) != 0) return -1;
  const std::size_t start = text.rfind(prefix);
  if (start == std::string::npos) return -1;
  const std::string digits = text.substr(start + prefix.size(), text.size() - suffix.size() - start - prefix.size());
  if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) return -1;
  return std::stol(digits);
}

/// Waits until `ready()` or 60 s; returns whether it became true.
template <class Ready>
bool wait_for(Ready ready) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < end) {
    if (ready()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return false;
}

/// Returns the exit status of `pid` (-1 if it did not exit normally).
int exit_status(pid_t pid) {
  int raw = 0;
  ::waitpid(pid, &raw, 0);
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

// The 56-row segregation scene (tolerance sweep to order 7, seconds per row at small alpha).
const std::string kSlow = "segregation.toml";
const std::string kSlowRows = "56";

}  // namespace

// Rows computed by two workers come out in sweep order, byte for byte as with one worker,
// warnings included (a tolerance sweep: rows of very different cost).
TEST(CliStreaming, JobsGiveTheSameBytesAsOneJob) {
  const std::string segregation = "table " + scene_path(kSlow) + " --set 'alpha=[1, 0.8]' --set 'mass_1=[0.5, 4]'";
  const CliRun one = run_gkt(segregation + " --jobs 1");
  ASSERT_EQ(one.status, 0) << one.err;
  EXPECT_EQ(count_lines(one.out), 9U);  // header and 2 x 2 x 2 rows
  const CliRun two = run_gkt(segregation + " --jobs 2");
  EXPECT_EQ(two.status, 0) << two.err;
  EXPECT_EQ(two.out, one.out);
  EXPECT_EQ(two.err, one.err);
  const std::string stability = "stability " + scene_path("hcs_stability.toml") + " --format json";
  const CliRun json_one = run_gkt(stability);
  ASSERT_EQ(json_one.status, 0) << json_one.err;
  const CliRun json_two = run_gkt(stability + " --jobs 2");
  EXPECT_EQ(json_two.status, 0) << json_two.err;
  EXPECT_EQ(json_two.out, json_one.out);
}

TEST(CliStreaming, JobsOutsideOneToSixtyFourAreRefused) {
  for (const char* jobs : {"0", "-1", "65"}) {
    const CliRun r = run_gkt("table " + scene_path("hcs_stability.toml") + " --jobs " + jobs);
    EXPECT_EQ(r.status, 2) << jobs;
    EXPECT_TRUE(r.out.empty()) << jobs;
    EXPECT_EQ(r.err, std::string("gkt: error: --jobs: must be an integer in [1, 64], got ") + jobs + "\n");
  }
}

// SIGINT while rows are being computed: the rows already on standard output stay, the table ends
// with "# interrupted after N of M rows" (N the rows printed), exit 130.
TEST(CliStreaming, InterruptKeepsFinishedRowsOnStandardOutput) {
  const fs::path dir = scratch("sigint");
  const pid_t pid = spawn_gkt({"table", scene_path(kSlow)}, dir / "out", dir / "err");
  ASSERT_TRUE(wait_for([&] { return count_lines(read_file(dir / "out")) >= 3; }));  // header and two rows
  ::kill(pid, SIGINT);
  EXPECT_EQ(exit_status(pid), 130) << read_file(dir / "err");
  const std::string out = read_file(dir / "out");
  const long marked = interrupted_rows(out, kSlowRows);
  ASSERT_GE(marked, 0) << out.substr(out.size() > 300 ? out.size() - 300 : 0);
  const auto rows = static_cast<std::size_t>(marked);
  EXPECT_GE(rows, 2U);
  EXPECT_LT(rows, 56U);
  EXPECT_EQ(count_lines(out), rows + 2);  // header, rows, marker
  EXPECT_EQ(out.rfind("alpha,reduced_gravity,mass_1,", 0), 0U);
  EXPECT_NE(read_file(dir / "err").find("gkt: interrupted after " + std::to_string(rows) + " of 56 rows"),
            std::string::npos);
  fs::remove_all(dir);
}

// SIGTERM with --output: the growing temporary file is renamed over the target with the marker
// (exit 143), nothing is left beside it; JSON closes as valid JSON with "interrupted": true.
TEST(CliStreaming, TerminatedOutputFileEndsWithTheMarker) {
  const fs::path dir = scratch("sigterm");
  const fs::path target = dir / "table.csv";
  const pid_t pid =
      spawn_gkt({"table", scene_path(kSlow), "--jobs", "2", "--output", target.string()}, dir / "out", dir / "err");
  const auto temporary_lines = [&] {
    for (const auto& entry : fs::directory_iterator(dir))
      if (entry.path().filename().string().rfind(".table.csv.gkt-", 0) == 0) return count_lines(read_file(entry));
    return std::size_t{0};
  };
  ASSERT_TRUE(wait_for([&] { return temporary_lines() >= 3; }));  // the temporary file grows row by row
  EXPECT_FALSE(fs::exists(target));
  ::kill(pid, SIGTERM);
  EXPECT_EQ(exit_status(pid), 143) << read_file(dir / "err");
  const std::string table = read_file(target);
  EXPECT_GE(interrupted_rows(table, kSlowRows), 0) << table;
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 3U);  // out, err, table.csv: no temporary file

  const pid_t json = spawn_gkt({"table", scene_path(kSlow), "--format", "json"}, dir / "json", dir / "err");
  std::this_thread::sleep_for(std::chrono::seconds(2));
  ::kill(json, SIGINT);
  EXPECT_EQ(exit_status(json), 130);
  const auto doc = nlohmann::json::parse(read_file(dir / "json"));  // throws (fails) if not valid JSON
  EXPECT_EQ(doc.at("interrupted"), true);
  EXPECT_EQ(doc.at("planned_rows"), 56);
  EXPECT_LT(doc.at("rows").size(), 56U);
  fs::remove_all(dir);
}

// Standard error is a file here, not a terminal: no progress line, only what was there before.
TEST(CliStreaming, NoProgressLineWhenStandardErrorIsNotATerminal) {
  const CliRun r = run_gkt("stability " + scene_path("hcs_stability.toml") + " --jobs 2");
  EXPECT_EQ(r.status, 0);
  EXPECT_GT(count_lines(r.out), 2U);
  EXPECT_EQ(r.err.find("gkt: row"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\r'), std::string::npos) << r.err;
}

// Under a terminal (script(1) provides one) the progress line appears, and --quiet silences it.
TEST(CliStreaming, ProgressLineOnATerminalUnlessQuiet) {
  if (std::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "no script(1)";
  const fs::path dir = scratch("tty");
  const std::string table = std::string(GKT_CLI_PATH) + " table " + scene_path("hcs_stability.toml") + " --output " +
                            (dir / "t.csv").string();
  const auto typescript = [&](const std::string& extra) {
    const std::string cmd = "timeout 60 script -qec '" + table + extra + "' " + (dir / "typescript").string() +
                            " >/dev/null 2>&1 </dev/null";
    EXPECT_EQ(std::system(cmd.c_str()), 0);
    return read_file(dir / "typescript");
  };
  EXPECT_NE(typescript("").find("gkt: row "), std::string::npos);
  EXPECT_EQ(typescript(" --quiet").find("gkt: row "), std::string::npos);
  fs::remove_all(dir);
}

// With --jobs N, a worker starts row r only when r < (rows written) + 4N, so finished rows waiting
// for a slow earlier one stay bounded. A long sweep (60 rows, window 8 at --jobs 2) still gives
// the bytes of --jobs 1, and a row that fails after some others (3D packing fraction 0.6 at the
// tenth row) still ends the output after the nine rows before it, whatever the number of jobs
// (workers never abandon a row the writer still needs: no hang).
TEST(CliStreaming, BoundedWindowKeepsOrderAndErrors) {
  const std::string sweep =
      "table " + scene_path("hcs_cumulants.toml") + " --set 'alpha={from = 0.5, to = 1, points = 60}' --set order=3";
  const CliRun one = run_gkt(sweep + " --jobs 1");
  ASSERT_EQ(one.status, 0) << one.err;
  EXPECT_EQ(count_lines(one.out), 61U);
  const CliRun two = run_gkt(sweep + " --jobs 2");
  EXPECT_EQ(two.status, 0) << two.err;
  EXPECT_EQ(two.out, one.out);

  const std::string failing = "table " + scene_path("hcs_cumulants.toml") +
                              " --set 'dimension=[2, 2, 2, 2, 2, 2, 2, 2, 2, 3, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2]'"
                              " --set packing_fraction=0.6 --set alpha=0.9 --set order=1"
                              " --set 'coefficients=[\"a2\"]'";
  const CliRun serial = run_gkt(failing + " --jobs 1");
  EXPECT_EQ(serial.status, 2) << serial.err;
  EXPECT_NE(serial.out.find("# stopped by an error after 9 of 20 rows"), std::string::npos) << serial.out;
  EXPECT_NE(serial.err.find("packing_fraction: must be a number in [0, 0.5], got 0.6"), std::string::npos);
  for (const char* jobs : {" --jobs 2", " --jobs 4"}) {
    const CliRun parallel = run_gkt(failing + jobs);
    EXPECT_EQ(parallel.status, 2) << jobs << parallel.err;
    EXPECT_EQ(parallel.out, serial.out) << jobs;
    EXPECT_EQ(parallel.err, serial.err) << jobs;
  }
}
