// The `gkt` program under hostile input and hostile output paths (issue 17): every case is one
// line "gkt: error: <key or path>: …" with exit 2, nothing written or replaced, no hang and no
// silently wrong answer. The bad-input table of docs/conventions.md lists the same classes.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

struct CliRun {
  int status = -1;
  std::string out, err;
  double seconds = 0;
};

std::string read_file(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The binary under test; GKT_CLI in the environment points the suite at another build (e.g. the
/// one before a fix, to see each test fail there).
std::string gkt_binary() {
  const char* other = std::getenv("GKT_CLI");
  return other != nullptr ? other : GKT_CLI_PATH;
}

/// A fresh scratch folder for one test.
fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("gkt_hard_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// Runs `gkt <args>` under a 60 s timeout (a hang fails, it does not stall the suite). Standard
/// output goes to `stdout_to` (default: a capture file), standard error is captured.
CliRun run_gkt(const std::string& args, const std::string& stdout_to = "") {
  static int counter = 0;
  const fs::path dir = scratch("runs");
  const fs::path out = dir / ("out" + std::to_string(counter));
  const fs::path err = dir / ("err" + std::to_string(counter++));
  const std::string cmd = "timeout 60 " + gkt_binary() + " " + args + " >" +
                          (stdout_to.empty() ? out.string() : stdout_to) + " 2>" + err.string();
  const auto start = std::chrono::steady_clock::now();
  const int raw = std::system(cmd.c_str());
  CliRun r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = read_file(out);
  r.err = read_file(err);
  return r;
}

/// Expects the bad-input contract: exit 2, nothing on standard output, exactly one line on
/// standard error that starts "gkt: error: " and contains `expect`.
void expect_one_line_error(const CliRun& r, const std::string& expect) {
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out.substr(0, 200);
  EXPECT_EQ(r.err.rfind("gkt: error: ", 0), 0U) << r.err.substr(0, 300);
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "not one line: " << r.err.substr(0, 300);
  EXPECT_NE(r.err.find(expect), std::string::npos) << r.err.substr(0, 300);
}

/// Writes `text` to dir/name and returns the path.
std::string write_scene(const fs::path& dir, const std::string& text, const std::string& name = "scene.toml") {
  std::ofstream(dir / name) << text;
  return (dir / name).string();
}

const std::string kSmooth = "model = \"smooth-inelastic\"\nalpha = 0.9\norder = 2\n";
const std::string kCooling = "model = \"smooth-inelastic\"\nalpha = 0.9\nt_end = 10\npoints = 3\n";

// ---- output paths -------------------------------------------------------------------------

// A symbolic link is neither followed to a regular file nor replaced by one: refused, the link
// and its target as they were.
TEST(CliOutput, RefusesSymbolicLinkToFile) {
  const fs::path dir = scratch("symlink");
  const std::string scene = write_scene(dir, kSmooth);
  std::ofstream(dir / "data.csv") << "precious\n";
  fs::create_symlink("data.csv", dir / "link.csv");
  const CliRun r = run_gkt("table " + scene + " --output " + (dir / "link.csv").string());
  expect_one_line_error(r, (dir / "link.csv").string() + ": is a symbolic link");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir / "link.csv")));
  EXPECT_EQ(read_file(dir / "data.csv"), "precious\n");
  fs::remove_all(dir);
}

// A FIFO is written, not replaced by a regular file.
TEST(CliOutput, WritesIntoFifoWithoutReplacingIt) {
  const fs::path dir = scratch("fifo");
  const std::string scene = write_scene(dir, kSmooth);
  const fs::path fifo = dir / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);  // a reader, so the writer need not wait
  ASSERT_GE(reader, 0);
  const CliRun r = run_gkt("table " + scene + " --output " + fifo.string());
  std::string received(1 << 16, '\0');
  const ssize_t n = ::read(reader, received.data(), received.size());
  ::close(reader);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(fifo)));
  ASSERT_GT(n, 0);
  EXPECT_EQ(received.rfind("a2,a3,", 0), 0U);
  fs::remove_all(dir);
}

// A link to a character device (like /dev/stdout) is written through; the link stays a link and
// the device a device. The link is private to the test: a build that replaced it could not harm
// /dev/null itself.
TEST(CliOutput, WritesThroughLinkToCharacterDevice) {
  const fs::path dir = scratch("device");
  const std::string scene = write_scene(dir, kSmooth);
  fs::create_symlink("/dev/null", dir / "null");
  const CliRun r = run_gkt("table " + scene + " --output " + (dir / "null").string());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir / "null")));
  EXPECT_TRUE(fs::is_character_file(fs::status("/dev/null")));
  fs::remove_all(dir);
}

// Output lost on a device (through a link, as above) is an error naming the user's path.
TEST(CliOutput, FullDeviceIsAnError) {
  if (!fs::is_character_file("/dev/full")) GTEST_SKIP() << "no /dev/full";
  const fs::path dir = scratch("devfull");
  const std::string scene = write_scene(dir, kSmooth);
  fs::create_symlink("/dev/full", dir / "full");
  const CliRun r = run_gkt("table " + scene + " --output " + (dir / "full").string());
  expect_one_line_error(r, (dir / "full").string() + ": write failed");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir / "full")));
  fs::remove_all(dir);
}

// A directory, a missing folder, a place where no file can be created: one line naming the
// user's path (never the temporary file), exit 2, and before the computation — the scene asks for
// --exact on values that are not rational, an error found only while computing, so the output
// error must come first.
TEST(CliOutput, UnwritablePathsAreRefusedFirstNamingTheUserPath) {
  const fs::path dir = scratch("unwritable");
  const std::string scene = write_scene(dir, kSmooth);
  fs::create_directories(dir / "folder");
  const std::vector<std::pair<std::string, std::string>> cases{
      {(dir / "folder").string(), "is a directory"},
      {(dir / "missing" / "table.csv").string(), "folder '" + (dir / "missing").string() + "' does not exist"},
      {"/proc/gkt_table.csv", "cannot create a file in folder '/proc'"}};
  for (const auto& [path, what] : cases) {
    const CliRun r = run_gkt("table " + scene + " --exact --output " + path);
    expect_one_line_error(r, path + ": " + what);
    EXPECT_EQ(r.err.find("gkt-tmp"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  }
  EXPECT_FALSE(fs::exists(dir / "missing"));
  fs::remove_all(dir);
}

// A regular file is replaced atomically and keeps its permissions; a failed run leaves it as it
// was and leaves no temporary file behind.
TEST(CliOutput, RegularFileKeepsPermissionsAndSurvivesFailure) {
  const fs::path dir = scratch("regular");
  const std::string scene = write_scene(dir, kSmooth);
  const fs::path target = dir / "table.csv";
  std::ofstream(target) << "old\n";
  fs::permissions(target, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  const CliRun bad = run_gkt("table " + scene + " --exact --output " + target.string());
  EXPECT_EQ(bad.status, 2) << bad.err;
  EXPECT_EQ(read_file(target), "old\n");
  const CliRun good = run_gkt("table " + scene + " --output " + target.string());
  ASSERT_EQ(good.status, 0) << good.err;
  EXPECT_EQ(read_file(target).rfind("a2,a3,", 0), 0U);
  EXPECT_EQ(fs::status(target).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 2U);  // scene and table: no temporary file left
  fs::remove_all(dir);
}

// The temporary file is created before the computation; a run ended by SIGTERM leaves no
// temporary file: the finished rows replace the target, ending with the interrupted marker
// (docs/conventions.md "Long runs"; tests/test_cli_streaming.cpp covers the marker itself).
TEST(CliOutput, TerminatedRunLeavesNoTemporaryFile) {
  const fs::path dir = scratch("terminated");
  const std::string scene = write_scene(dir,
                                        "model = \"mixture\"\norder = 1\n"
                                        "alpha = { from = 0.5, to = 1, points = 1000000 }\n"
                                        "[[species]]\nmass = 1\ndiameter = 1\nfraction = 0.5\n"
                                        "[[species]]\nmass = 2\ndiameter = 1\nfraction = 0.5\n");
  const std::string cmd =
      "timeout 1 " + gkt_binary() + " table " + scene + " --output " + (dir / "table.csv").string() + " 2>/dev/null";
  const int raw = std::system(cmd.c_str());
  EXPECT_EQ(WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, 124);  // still computing when terminated
  // No temporary file is left. Whether the table exists depends on how far the run got in 1 s (a
  // loaded or sanitized build may still be validating the sweep): if it does, it is marked partial.
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().filename() != "scene.toml" && entry.path().filename() != "table.csv") ++files;
  EXPECT_EQ(files, 0U);
  if (fs::exists(dir / "table.csv")) {
    const std::string table = read_file(dir / "table.csv");
    EXPECT_NE(table.find(" of 1000000 rows\n"), std::string::npos) << table.substr(0, 200);
  }
  fs::remove_all(dir);
}

// A full standard output loses the output: every subcommand says so and exits 2.
TEST(CliOutput, FullStandardOutputIsAnError) {
  if (!fs::is_character_file("/dev/full")) GTEST_SKIP() << "no /dev/full";
  const fs::path dir = scratch("stdout_full");
  const std::string smooth = write_scene(dir, kSmooth, "smooth.toml");
  const std::string cooling = write_scene(dir, kCooling, "cooling.toml");
  const std::string closed_form = write_scene(dir, "model = \"smooth-inelastic\"\n", "formula.toml");
  const std::vector<std::string> commands{"table " + smooth, "stability " + smooth, "models",
                                          "formula " + closed_form + " --coefficient shear_viscosity",
                                          "evolve " + cooling};
  for (const auto& command : commands) {
    const CliRun r = run_gkt(command, "/dev/full");
    EXPECT_EQ(r.status, 2) << command << ": " << r.err;
    EXPECT_NE(r.err.find("gkt: error: standard output: write failed"), std::string::npos) << command << ": " << r.err;
  }
  fs::remove_all(dir);
}

// What --help and --version print is checked too.
TEST(CliOutput, FullStandardOutputForHelpAndVersion) {
  if (!fs::is_character_file("/dev/full")) GTEST_SKIP() << "no /dev/full";
  for (const char* args : {"--help", "--version", "table --help"}) {
    const CliRun r = run_gkt(args, "/dev/full");
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find("gkt: error: standard output: write failed"), std::string::npos) << args << ": " << r.err;
  }
}

// ---- scene values ---------------------------------------------------------------------------

TEST(CliScene, NonFiniteNumberNamesTheKey) {
  const fs::path dir = scratch("nonfinite");
  const std::string scene = write_scene(dir, kSmooth);
  for (const char* value : {"nan", "inf", "-inf"})
    expect_one_line_error(run_gkt("table " + scene + " --set alpha=" + value), "gkt: error: alpha: must be a finite");
  fs::remove_all(dir);
}

// alpha = 1e-300 gives κ* = 0.24 with an estimated error of 28 at order 2: the table is written,
// and a warning names the coefficient and its error.
TEST(CliScene, ValueBelowItsEstimatedErrorIsWarned) {
  const fs::path dir = scratch("unreliable");
  const std::string scene = write_scene(dir, kSmooth);
  const CliRun r = run_gkt("table " + scene + " --set alpha=1e-300 --set 'coefficients=[\"thermal_conductivity\"]'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.rfind("thermal_conductivity,thermal_conductivity_error,order\n0.24", 0), 0U) << r.out;
  EXPECT_NE(r.err.find("gkt: warning: thermal_conductivity: estimated error above the value in 1 of 1 row"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("+- 28.2"), std::string::npos) << r.err;
  // A converged value is not warned about.
  const CliRun fine = run_gkt("table " + scene + " --set 'coefficients=[\"shear_viscosity\"]'");
  ASSERT_EQ(fine.status, 0) << fine.err;
  EXPECT_TRUE(fine.err.empty()) << fine.err;
  fs::remove_all(dir);
}

// The row cap applies to the table: two sweeps of 10^5 points, or a list of 2·10^6 values, are
// refused before any work.
TEST(CliScene, SweepCapCountsEveryRow) {
  const fs::path dir = scratch("sweeps");
  const std::string two = write_scene(dir,
                                      "model = \"smooth-inelastic\"\norder = 1\n"
                                      "alpha = { from = 0.1, to = 1, points = 100000 }\n"
                                      "packing_fraction = { from = 0, to = 0.4, points = 100000 }\n",
                                      "two.toml");
  const CliRun r = run_gkt("table " + two);
  expect_one_line_error(r, "alpha, packing_fraction: the sweep makes 1e+10 rows (100000 x 100000); at most 1000000");
  EXPECT_LT(r.seconds, 5);
  std::string list = "model = \"smooth-inelastic\"\norder = 1\nalpha = [0.5";
  for (int i = 1; i < 2000000; ++i) list += ", 0.5";
  list += "]\n";
  const CliRun l = run_gkt("table " + write_scene(dir, list, "list.toml"));
  expect_one_line_error(l, "alpha: the sweep makes 2e+06 rows");
  EXPECT_LT(l.seconds, 30);
  fs::remove_all(dir);
}

// Solver failure inside the documented ranges: one line naming the key, exit 2, none of CVODE's
// own printing.
TEST(CliEvolveHardening, SolverFailureNamesTheKey) {
  const fs::path dir = scratch("cvode");
  const std::string scene = write_scene(dir, kCooling);
  const CliRun far = run_gkt("evolve " + scene + " --set t_end=1e300");
  expect_one_line_error(far, "gkt: error: t_end: CVODE: ");
  EXPECT_EQ(far.err.find("[CVODE"), std::string::npos) << far.err;
  const CliRun tight = run_gkt("evolve " + scene + " --set rtol=1e-300 --set atol=1e-300");
  expect_one_line_error(tight, "gkt: error: rtol: CVODE: ");
  EXPECT_NE(tight.err.find("too much accuracy"), std::string::npos) << tight.err;
  fs::remove_all(dir);
}

// The output times of gkt evolve are capped like its points.
TEST(CliEvolveHardening, TimesListIsCapped) {
  const fs::path dir = scratch("times");
  std::string text = "model = \"smooth-inelastic\"\nalpha = 0.9\ntimes = [1";
  for (int i = 2; i <= 1000001; ++i) text += ", " + std::to_string(i);
  text += "]\n";
  const CliRun r = run_gkt("evolve " + write_scene(dir, text));
  expect_one_line_error(r, "times: at most 1000000 output times, got 1000001");
  EXPECT_LT(r.seconds, 30);
  fs::remove_all(dir);
}

TEST(CliScene, FiveSpeciesSaysAtMostFour) {
  const fs::path dir = scratch("species");
  std::string text = "model = \"mixture\"\norder = 1\n";
  for (int i = 0; i < 5; ++i) text += "[[species]]\nmass = 1\ndiameter = 1\nfraction = 0.2\n";
  const CliRun r = run_gkt("table " + write_scene(dir, text));
  expect_one_line_error(r, "gkt: error: species: must be an integer in [2, 4], got 5");
  // An indexed key beyond the species: the valid keys are listed with their indices collapsed.
  const std::string two =
      "model = \"mixture\"\norder = 1\n[[species]]\nmass = 1\ndiameter = 1\nfraction = 0.5\n"
      "[[species]]\nmass = 2\ndiameter = 1\nfraction = 0.5\n";
  const CliRun k = run_gkt("table " + write_scene(dir, two, "two.toml") + " --set diameter_5=1");
  expect_one_line_error(k, "diameter_5: unknown key");
  EXPECT_NE(k.err.find("diameter_i"), std::string::npos) << k.err;
  EXPECT_LT(k.err.size(), 300U) << k.err;
  fs::remove_all(dir);
}

TEST(CliScene, DirectoryAsSceneNamesThePath) {
  const fs::path dir = scratch("scene_dir");
  expect_one_line_error(run_gkt("table " + dir.string()), "'" + dir.string() + "' is a directory");
  fs::remove_all(dir);
}

// A 1 MB string is echoed as at most ~40 characters and "…", wherever it appears (the line, with the list of
// valid names, stays under the 1000-character cap of one_line).
TEST(CliScene, LongStringsAreEchoedShort) {
  const fs::path dir = scratch("long_string");
  const std::string huge(1 << 20, 'x');
  const std::vector<std::string> scenes{"model = \"" + huge + "\"\norder = 1\n",
                                        "model = \"smooth-inelastic\"\norder = 1\nhcs = \"" + huge + "\"\n",
                                        "model = \"smooth-inelastic\"\norder = 1\ncoefficients = [\"" + huge + "\"]\n",
                                        "model = \"smooth-inelastic\"\norder = 1\n" + huge + " = 1\n"};
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    std::string name = std::to_string(i);  // append, not "s" + …: GCC 12's -Wrestrict misfires
    name.append(".toml");
    const CliRun r = run_gkt("table " + write_scene(dir, scenes[i], name));
    EXPECT_EQ(r.status, 2) << i;
    EXPECT_LT(r.err.size(), 1100U) << i << ": " << r.err.substr(0, 300);
    EXPECT_NE(r.err.find(std::string(40, 'x') + "…"), std::string::npos) << i << ": " << r.err.substr(0, 300);
  }
  fs::remove_all(dir);
}

// Numbers are quoted short: 1e300 is "1e+300", not 301 digits.
TEST(CliScene, HugeNumbersAreQuotedShort) {
  const fs::path dir = scratch("huge_number");
  const std::string mixture =
      "model = \"mixture\"\norder = 1\n[[species]]\nmass = 1e300\ndiameter = 1\nfraction = 0.5\n"
      "[[species]]\nmass = 1\ndiameter = 1\nfraction = 0.5\n";
  expect_one_line_error(run_gkt("table " + write_scene(dir, mixture)),
                        "mass_1: must be a number in (0, 1000000000], got 1e+300");
  expect_one_line_error(run_gkt("table " + write_scene(dir, mixture) + " --set mass_1=1 --set diameter_2=1e30"),
                        "diameter_2: must be a number in (0, 1000000000], got 1e+30");
  fs::remove_all(dir);
}

// The packing-fraction range quoted is the scene's dimension's.
TEST(CliScene, PackingFractionRangeOfTheDimension) {
  const fs::path dir = scratch("packing");
  const std::string scene = write_scene(dir, kSmooth);
  expect_one_line_error(run_gkt("table " + scene + " --set packing_fraction=-0.1"),
                        "packing_fraction: must be a number in [0, 0.5] for dimension = 3, got -0.1");
  expect_one_line_error(run_gkt("table " + scene + " --set dimension=2 --set packing_fraction=0.75"),
                        "packing_fraction: must be a number in [0, 0.7] for dimension = 2, got 0.75");
  fs::remove_all(dir);
}

TEST(CliScene, CoefficientListedTwice) {
  const fs::path dir = scratch("twice");
  expect_one_line_error(
      run_gkt("table " + write_scene(dir, kSmooth) + " --set 'coefficients=[\"a2\", \"shear_viscosity\", \"a2\"]'"),
      "coefficients: 'a2' is listed twice");
  fs::remove_all(dir);
}

// --set 'alpha=0.5<newline>order=3' would set alpha and drop the second line: refused.
TEST(CliScene, SetWithNewlineIsRefused) {
  const fs::path dir = scratch("set_newline");
  expect_one_line_error(run_gkt("table " + write_scene(dir, kSmooth) + " --set \"$(printf 'alpha=0.5\\norder=3')\""),
                        "--set: KEY=VALUE must be one line");
  fs::remove_all(dir);
}

TEST(CliUsage, UnknownSubcommandIsNamedWithSuggestion) {
  const CliRun r = run_gkt("tabel scene.toml");
  expect_one_line_error(r, "unknown subcommand 'tabel'; did you mean 'table'?");
  expect_one_line_error(run_gkt("frobnicate"), "unknown subcommand 'frobnicate'");
}

}  // namespace
