// gkt: command-line front end. Exit codes: 0 success, 2 bad input, usage or lost output, 1 internal error,
// 128 + signal for a table interrupted by SIGINT (130), SIGTERM (143) or SIGHUP (129).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>
#include <CLI/CLI.hpp>

#include "describe.hpp"
#include "dsmc_command.hpp"
#include "evolve_command.hpp"
#include "formula_command.hpp"
#include "gkt/models/transport_model.hpp"
#include "scene.hpp"
#include "table_command.hpp"
#include "table_writer.hpp"

namespace {

constexpr int kBadInput = 2;
constexpr int kMaxJobs = 64;  ///< --jobs cap: far above the cores of a workstation, a guard against typos

/// Returns `message` as one line of bounded length: control characters (a newline in a value)
/// become spaces and anything beyond 1000 characters is cut with "…" (room for the longest list of valid names).
std::string one_line(std::string message) {
  for (char& c : message)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  constexpr std::size_t kMaxLength = 1000;
  if (message.size() > kMaxLength) {
    std::size_t cut = kMaxLength;
    while (cut > 0 && (static_cast<unsigned char>(message[cut]) & 0xC0) == 0x80) --cut;  // not inside a UTF-8 character
    message.resize(cut);
    message += "…";
  }
  return message;
}

/// The signal (SIGINT, SIGTERM, SIGHUP) that asked a running table to stop; 0 while none did.
volatile std::sig_atomic_t stop_signal = 0;

extern "C" void request_stop(int signal_number) { stop_signal = signal_number; }

/// From here on SIGINT, SIGTERM and SIGHUP end the sweep after the finished rows instead of the
/// process (docs/conventions.md "Long runs"); the handler only records the signal.
void catch_stop_signals() {
  struct sigaction action {};
  action.sa_handler = request_stop;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  for (int signal_number : {SIGINT, SIGTERM, SIGHUP}) sigaction(signal_number, &action, nullptr);
}

/// The progress line "gkt: row 12/40 (30 %), 3.1 s" (gkt dsmc: "run") on standard error, redrawn in place (\r);
/// silent unless standard error is a terminal and --quiet was not given.
class Progress {
 public:
  explicit Progress(bool enabled, const char* unit = "row")
      : enabled_(enabled), unit_(unit), start_(std::chrono::steady_clock::now()) {}
  ~Progress() { clear(); }
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  void show(std::size_t done, std::size_t total) {
    if (!enabled_) return;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    char line[128];
    const int n = std::snprintf(line, sizeof line, "\rgkt: %s %zu/%zu (%d %%), %.1f s", unit_, done, total,
                                total == 0 ? 100 : static_cast<int>(100 * done / total), seconds);
    if (n <= 0) return;
    std::fputs(line, stderr);
    width_ = static_cast<std::size_t>(n) - 1;
  }
  void clear() {
    if (!enabled_ || width_ == 0) return;
    std::fprintf(stderr, "\r%*s\r", static_cast<int>(width_), "");
    width_ = 0;
  }

 private:
  bool enabled_;
  const char* unit_;  ///< what is counted: "row" (table), "run" (dsmc)
  std::chrono::steady_clock::time_point start_;
  std::size_t width_ = 0;  ///< characters on screen
};

struct TableRun {
  std::string format = "csv", output;
  bool exact = false, stability = false, quiet = false;
  int jobs = 1;
  std::string units = "reduced";  ///< or "physical": with the reference gas below (SI)
  std::optional<double> mass, diameter, number_density, temperature;
};

/// Returns the reference gas of --units physical (nullopt for reduced units); throws naming the
/// option if one is missing, not a number > 0, or given without --units physical.
std::optional<gkt::PhysicalReference> physical_reference(const TableRun& run, const gkt::cli::Scene& scene) {
  const std::pair<const char*, const std::optional<double>*> options[] = {{"--mass", &run.mass},
                                                                          {"--diameter", &run.diameter},
                                                                          {"--number-density", &run.number_density},
                                                                          {"--temperature", &run.temperature}};
  if (run.units != "physical") {
    for (const auto& [name, value] : options)
      if (value->has_value()) throw std::invalid_argument(std::string(name) + ": only with --units physical");
    return std::nullopt;
  }
  for (const auto& [name, value] : options) {
    if (!value->has_value())
      throw std::invalid_argument(std::string(name) +
                                  ": required with --units physical (the reference gas in SI: --mass kg, --diameter m, "
                                  "--number-density m^-d, --temperature K)");
    if (!std::isfinite(**value) || **value <= 0)
      throw std::invalid_argument(std::string(name) + ": must be a finite number > 0, got " +
                                  gkt::cli::format_number(**value));
  }
  if (run.exact) throw std::invalid_argument("--units physical: not with --exact (physical values are not rational)");
  const auto dimension = gkt::cli::scene_dimension(scene);
  if (!dimension)
    throw std::invalid_argument("--units physical: dimension must be one value (the units depend on it), not a sweep");
  const gkt::PhysicalReference reference{*run.mass, *run.diameter, *run.number_density, *run.temperature};
  for (const auto reduction :  // a scale that over- or underflows a double is refused before any work
       {gkt::Reduction::viscosity, gkt::Reduction::conductivity, gkt::Reduction::self_diffusion,
        gkt::Reduction::density_heat, gkt::Reduction::collision_frequency, gkt::Reduction::pressure,
        gkt::Reduction::wavenumber, gkt::Reduction::length, gkt::Reduction::mutual_diffusion, gkt::Reduction::dufour,
        gkt::Reduction::mobility})
    gkt::physical_scale(reduction, *dimension, reference);
  return reference;
}

int run_table(const std::string& scene_path, const std::vector<std::string>& overrides, const TableRun& run) {
  if (run.jobs < 1 || run.jobs > kMaxJobs)
    throw std::invalid_argument("--jobs: must be an integer in [1, " + std::to_string(kMaxJobs) + "], got " +
                                std::to_string(run.jobs));
  gkt::cli::OutputTarget target(run.output);  // refused before any work if it cannot be written
  auto scene = gkt::cli::load_scene(scene_path, overrides);
  // `gkt stability` is `gkt table` whose default coefficients are the HCS stability values.
  if (run.stability && !scene.coefficients_given) {
    if (!gkt::make_transport_model(scene.model)->supports(gkt::Capability::stability))
      throw std::invalid_argument("model: \"" + scene.model + "\" has no stability analysis; use " +
                                  gkt::cli::models_supporting(gkt::Capability::stability));
    scene.coefficients = gkt::stability_coefficient_names();
  }
  const gkt::cli::TableOptions options{run.exact, run.jobs, physical_reference(run, scene)};
  const bool csv = run.format != "json";
  Progress progress(!run.quiet && ::isatty(STDERR_FILENO) == 1);
  const std::string header = gkt::cli::csv_line(gkt::cli::table_header(scene, options).columns);
  gkt::cli::RowObserver observer;
  observer.stop = [] { return stop_signal != 0; };
  observer.on_wait = [&progress](std::size_t done, std::size_t total) { progress.show(done, total); };
  observer.on_row = [&](const std::vector<std::string>& row, std::size_t done, std::size_t total) {
    if (csv) {
      progress.clear();  // standard output may be the same terminal
      // The header goes with the first row: input the model refuses at once leaves no output.
      target.append(done == 1 ? header + gkt::cli::csv_line(row) : gkt::cli::csv_line(row));
    }
    progress.show(done, total);
  };
  catch_stop_signals();
  std::vector<std::string> warnings;
  std::size_t rows_written = 0;
  observer.on_row = [&, show_row = observer.on_row](const std::vector<std::string>& row, std::size_t done,
                                                    std::size_t total) {
    show_row(row, done, total);
    rows_written = done;
  };
  gkt::cli::Table table;
  try {
    table = gkt::cli::compute_table(scene, options, warnings, observer);
  } catch (const std::invalid_argument&) {
    // The rows already on standard output (or a FIFO) are not mistaken for the whole table.
    if (csv && rows_written > 0) try {
        target.append("# stopped by an error after " + std::to_string(rows_written) + " of " +
                      std::to_string(gkt::cli::sweep_size(scene)) + " rows\n");
      } catch (const std::invalid_argument&) {  // the output itself failed: the error says so
      }
    throw;
  }
  progress.clear();
  try {
    if (csv) {
      if (table.rows.empty()) target.append(header);  // no row yet, or none in the sweep
      if (table.interrupted) target.append(gkt::cli::csv_interrupted_line(table));
    } else {
      table.description_json = gkt::cli::describe_table(scene, options.physical);
      target.append(gkt::cli::to_json(table));
    }
    target.commit();
  } catch (const std::invalid_argument& e) {
    if (!table.interrupted) throw;
    std::cerr << "gkt: error: " << one_line(e.what()) << "\n";
    std::_Exit(kBadInput);  // detached workers may still run: no normal exit
  }
  for (const auto& w : warnings) std::cerr << "gkt: warning: " << w << "\n";
  if (!table.interrupted) return 0;
  std::cerr << "gkt: interrupted after " << table.rows.size() << " of " << table.planned_rows
            << " rows; the output ends with the marker (docs/conventions.md)\n";
  std::cerr.flush();
  std::_Exit(128 + stop_signal);  // rows still computing run in detached threads: no normal exit
}

/// `gkt dsmc`: every run, then the table written at once (atomically to a file); a signal stops the
/// runs not yet started and leaves no output (exit 128 + signal).
int run_dsmc(const std::string& scene_path, const std::vector<std::string>& overrides, const TableRun& run) {
  if (run.jobs < 1 || run.jobs > kMaxJobs)
    throw std::invalid_argument("--jobs: must be an integer in [1, " + std::to_string(kMaxJobs) + "], got " +
                                std::to_string(run.jobs));
  catch_stop_signals();  // before the temporary file exists: a signal never leaves it behind
  bool interrupted = false;
  gkt::cli::Table table;
  {
    gkt::cli::OutputTarget target(run.output);  // refused before any work if it cannot be written
    auto scene = gkt::cli::read_scene_table(scene_path, overrides);
    Progress progress(!run.quiet && ::isatty(STDERR_FILENO) == 1, "run");
    gkt::cli::DsmcRunOptions options;
    options.jobs = run.jobs;
    options.progress = [&progress](std::size_t done, std::size_t total) { progress.show(done, total); };
    options.stop = [] { return stop_signal != 0; };
    table = gkt::cli::dsmc(std::move(scene), options, interrupted);
    progress.clear();
    if (!interrupted) {
      target.write(run.format == "json" ? gkt::cli::to_json(table) : gkt::cli::to_csv(table));
      return 0;
    }
  }  // the temporary file of an interrupted run is removed here
  std::cerr << "gkt: interrupted; no output written\n";
  return 128 + stop_signal;
}

int run_models(const CLI::Option* describe, const std::string& describe_name, bool json) {
  if (describe->count() > 0 || json) {
    gkt::cli::OutputTarget("").write(gkt::cli::describe_models(describe_name, json));
    return 0;
  }
  std::ostringstream out;
  for (const auto& name : gkt::transport_model_names()) {
    const auto model = gkt::make_transport_model(name);
    out << name << ": " << model->description() << "\n  coefficients:";
    for (const auto& c : model->coefficient_names()) out << " " << c;
    out << "\n  parameters:";
    for (const auto& p : model->parameters()) out << " " << p.name << " (" << p.allowed() << ")";
    out << "\n  order: an integer in [1, " << model->max_order() << "] or tolerance in (0, 1]\n";
  }
  gkt::cli::OutputTarget("").write(out.str());
  return 0;
}

/// Returns the number of single-character edits (Levenshtein) between a and b.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

/// Throws "unknown subcommand '<word>'" (with the nearest name if it is a likely typo) when the
/// first argument is neither an option nor a subcommand: CLI11 would say "A subcommand is required".
void check_subcommand(int argc, char** argv, const CLI::App& app) {
  if (argc < 2 || argv[1][0] == '-') return;
  const std::string word = argv[1];
  std::string nearest;
  std::size_t best = 3;  // suggest only within two edits
  for (const auto* sub : app.get_subcommands({})) {
    if (sub->get_name() == word) return;
    const std::size_t d = edit_distance(word, sub->get_name());
    if (d < best) {
      best = d;
      nearest = sub->get_name();
    }
  }
  std::string names;
  for (const auto* sub : app.get_subcommands({})) names += (names.empty() ? "" : ", ") + sub->get_name();
  throw std::invalid_argument("unknown subcommand '" + gkt::cli::quote_short(word) + "'" +
                              (nearest.empty() ? "" : "; did you mean '" + nearest + "'?") + " (subcommands: " + names +
                              ")");
}

/// Returns `status` if standard output took what --help or --version printed, else reports the
/// loss (e.g. `gkt --help > /dev/full`) and returns the bad-input status.
int printed(int status) {
  std::cout.flush();
  if (std::cout && std::fflush(stdout) == 0 && std::ferror(stdout) == 0) return status;
  std::cerr << "gkt: error: standard output: write failed\n";
  return kBadInput;
}

int run(int argc, char** argv) {
  CLI::App app{
      "gkt: Chapman-Enskog transport coefficients of granular and molecular gases from exact "
      "Sonine expansions"};
  app.set_version_flag("--version", std::string("gkt ") + GKT_VERSION);
  app.require_subcommand(1);

  auto* table = app.add_subcommand("table", "Compute a table of transport coefficients for a scene (TOML)");
  std::string scene_path;
  TableRun table_run;
  std::vector<std::string> overrides;
  table->add_option("scene", scene_path, "Scene file (TOML), e.g. tables/scenes/*.toml")->required();
  table->add_option("--set", overrides, "Override a scene key: KEY=VALUE (VALUE in TOML syntax); repeatable")
      ->allow_extra_args(false);
  table->add_option("--format", table_run.format, "Output format")->check(CLI::IsMember({"csv", "json"}));
  table->add_option(
      "--output", table_run.output,
      "Output file (replaced when complete, or ends with an interrupted marker); default: standard output");
  table->add_flag("--exact", table_run.exact, "Print exact rationals (refused where a result is not rational)");
  const auto add_long_run_options = [](CLI::App* command, TableRun& run) {
    command->add_option("--jobs", run.jobs, "Rows evaluated in parallel, 1 to 64 (default 1); output unchanged");
    command->add_flag("--quiet", run.quiet, "No progress line on standard error (warnings stay)");
    command->add_option("--units", run.units, "reduced (default) or physical: SI values for the reference gas below")
        ->check(CLI::IsMember({"reduced", "physical"}));
    command->add_option("--mass", run.mass, "Reference particle mass m in kg (--units physical)");
    command->add_option("--diameter", run.diameter, "Reference particle diameter sigma in m (--units physical)");
    command->add_option("--number-density", run.number_density, "Number density n in m^-d (--units physical)");
    command->add_option("--temperature", run.temperature, "Temperature T in K (--units physical; k_B T is the energy)");
  };
  add_long_run_options(table, table_run);

  auto* formula = app.add_subcommand("formula", "Print a coefficient's exact closed form (text, LaTeX or C++)");
  std::string formula_scene, coefficient, formula_format = "text", formula_output;
  std::vector<std::string> formula_overrides;
  std::optional<int> formula_order;
  formula->add_option("scene", formula_scene, "Scene file (TOML): model, dimension")->required();
  formula->add_option("--coefficient", coefficient, "Canonical coefficient name")->required();
  formula->add_option("--order", formula_order, "Sonine order (default 1)");
  formula->add_option("--format", formula_format, "Output format")->check(CLI::IsMember({"text", "latex", "cpp"}));
  formula->add_option("--set", formula_overrides, "Override a scene key: KEY=VALUE; repeatable");
  formula->add_option("--output", formula_output, "Output file (written atomically); default: standard output");

  auto* stability = app.add_subcommand(
      "stability", "Critical wave numbers and system size of the homogeneous cooling state (like table)");
  std::string stability_scene;
  TableRun stability_run;
  stability_run.stability = true;
  std::vector<std::string> stability_overrides;
  stability
      ->add_option("scene", stability_scene,
                   "Scene file (TOML), model smooth-inelastic, mixture, viscoelastic, rough or rough-walton")
      ->required();
  stability->add_option("--set", stability_overrides, "Override a scene key: KEY=VALUE; repeatable");
  stability->add_option("--format", stability_run.format, "Output format")->check(CLI::IsMember({"csv", "json"}));
  stability->add_option(
      "--output", stability_run.output,
      "Output file (replaced when complete, or ends with an interrupted marker); default: standard output");
  add_long_run_options(stability, stability_run);

  auto* evolve = app.add_subcommand("evolve", "Integrate the cooling of a homogeneous gas: T(t), a2(t), ... (CVODE)");
  std::string evolve_scene, evolve_format = "csv", evolve_output;
  std::vector<std::string> evolve_overrides;
  evolve->add_option("scene", evolve_scene, "Scene file (TOML)")->required();
  evolve->add_option("--set", evolve_overrides, "Override a scene key: KEY=VALUE; repeatable");
  evolve->add_option("--format", evolve_format, "Output format")->check(CLI::IsMember({"csv", "json"}));
  evolve->add_option("--output", evolve_output, "Output file (written atomically); default: standard output");

  auto* dsmc = app.add_subcommand(
      "dsmc", "Direct simulation Monte Carlo of a homogeneous cooling gas: a2, a3, cooling rate, temperature ratios");
  std::string dsmc_scene;
  TableRun dsmc_run;
  std::vector<std::string> dsmc_overrides;
  dsmc->add_option("scene", dsmc_scene, "Scene file (TOML): model, dimension, alpha, particles, runs, seed, ...")
      ->required();
  dsmc->add_option("--set", dsmc_overrides, "Override a scene key: KEY=VALUE; repeatable");
  dsmc->add_option("--format", dsmc_run.format, "Output format")->check(CLI::IsMember({"csv", "json"}));
  dsmc->add_option("--output", dsmc_run.output, "Output file (written atomically); default: standard output");
  dsmc->add_option("--jobs", dsmc_run.jobs, "Runs simulated in parallel, 1 to 64 (default 1); output unchanged");
  dsmc->add_flag("--quiet", dsmc_run.quiet, "No progress line on standard error");

  auto* models = app.add_subcommand("models", "List the models with their coefficients and parameters");
  std::string describe_name;
  bool models_json = false;
  auto* describe = models
                       ->add_option("--describe", describe_name,
                                    "Describe every model, or the one named: keys (ranges, defaults), commands, "
                                    "columns (meaning, reduction, SI unit)")
                       ->expected(0, 1);
  models->add_flag("--json", models_json, "Machine-readable description (JSON; implies --describe)");

  try {
    check_subcommand(argc, argv, app);
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return printed(app.exit(e));
  } catch (const CLI::CallForAllHelp& e) {
    return printed(app.exit(e));
  } catch (const CLI::CallForVersion& e) {
    return printed(app.exit(e));
  } catch (const CLI::ParseError& e) {
    std::cerr << "gkt: error: " << one_line(e.what()) << " (see gkt --help)\n";
    return kBadInput;
  } catch (const std::invalid_argument& e) {
    std::cerr << "gkt: error: " << one_line(e.what()) << " (see gkt --help)\n";
    return kBadInput;
  }

  try {
    if (table->parsed()) return run_table(scene_path, overrides, table_run);
    if (stability->parsed()) return run_table(stability_scene, stability_overrides, stability_run);
    if (dsmc->parsed()) return run_dsmc(dsmc_scene, dsmc_overrides, dsmc_run);
    if (evolve->parsed()) {
      gkt::cli::OutputTarget target(evolve_output);
      std::string counters;
      const auto table = gkt::cli::evolve(evolve_scene, evolve_overrides, counters);
      target.write(evolve_format == "json" ? gkt::cli::to_json(table) : gkt::cli::to_csv(table));
      std::cerr << "gkt: " << counters << "\n";
      return 0;
    }
    if (formula->parsed()) {
      gkt::cli::OutputTarget target(formula_output);
      target.write(gkt::cli::formula(formula_scene, formula_overrides, coefficient, formula_order, formula_format));
      return 0;
    }
    return run_models(describe, describe_name, models_json);
  } catch (const std::invalid_argument& e) {
    std::cerr << "gkt: error: " << one_line(e.what()) << "\n";
    return kBadInput;
  }
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {  // anything but bad input is a defect
    std::cerr << "gkt: internal error: " << one_line(e.what()) << "\n";
    return 1;
  }
}
