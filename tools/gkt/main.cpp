// gkt: command-line front end. Exit codes: 0 success, 2 bad input or usage, 1 internal error.
#include <algorithm>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "evolve_command.hpp"
#include "formula_command.hpp"
#include "gkt/models/transport_model.hpp"
#include "scene.hpp"
#include "table_command.hpp"
#include "table_writer.hpp"

namespace {

constexpr int kBadInput = 2;

int run_table(const std::string& scene_path, const std::vector<std::string>& overrides, const std::string& format,
              const std::string& output, bool exact, bool stability = false) {
  auto scene = gkt::cli::load_scene(scene_path, overrides);
  // `gkt stability` is `gkt table` whose default coefficients are the HCS stability values.
  if (stability && !scene.coefficients_given) {
    if (!gkt::make_transport_model(scene.model)->supports(gkt::Capability::stability))
      throw std::invalid_argument("model: \"" + scene.model +
                                  "\" has no stability analysis; use \"smooth-inelastic\" or \"mixture\"");
    scene.coefficients = gkt::stability_coefficient_names();
  }
  std::vector<std::string> warnings;
  const auto table = gkt::cli::compute_table(scene, {exact}, warnings);
  const std::string content = format == "json" ? gkt::cli::to_json(table) : gkt::cli::to_csv(table);
  gkt::cli::write_output(output, content);
  for (const auto& w : warnings) std::cerr << "gkt: warning: " << w << "\n";
  return 0;
}

int run_models() {
  for (const auto& name : gkt::transport_model_names()) {
    const auto model = gkt::make_transport_model(name);
    std::cout << name << ": " << model->description() << "\n  coefficients:";
    for (const auto& c : model->coefficient_names()) std::cout << " " << c;
    std::cout << "\n  parameters:";
    for (const auto& p : model->parameters()) std::cout << " " << p.name << " (" << p.allowed() << ")";
    std::cout << "\n  order: an integer in [1, " << model->max_order() << "] or tolerance in (0, 1]\n";
  }
  return 0;
}

int run(int argc, char** argv) {
  CLI::App app{
      "gkt: Chapman-Enskog transport coefficients of granular and molecular gases from exact "
      "Sonine expansions"};
  app.set_version_flag("--version", std::string("gkt ") + GKT_VERSION);
  app.require_subcommand(1);

  auto* table = app.add_subcommand("table", "Compute a table of transport coefficients for a scene (TOML)");
  std::string scene_path, format = "csv", output;
  std::vector<std::string> overrides;
  bool exact = false;
  table->add_option("scene", scene_path, "Scene file (TOML), e.g. tables/scenes/*.toml")->required();
  table->add_option("--set", overrides, "Override a scene key: KEY=VALUE (VALUE in TOML syntax); repeatable")
      ->allow_extra_args(false);
  table->add_option("--format", format, "Output format")->check(CLI::IsMember({"csv", "json"}));
  table->add_option("--output", output, "Output file (written atomically); default: standard output");
  table->add_flag("--exact", exact, "Print exact rationals (refused where a result is not rational)");

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
  std::string stability_scene, stability_format = "csv", stability_output;
  std::vector<std::string> stability_overrides;
  stability->add_option("scene", stability_scene, "Scene file (TOML), model smooth-inelastic, mixture or viscoelastic")
      ->required();
  stability->add_option("--set", stability_overrides, "Override a scene key: KEY=VALUE; repeatable");
  stability->add_option("--format", stability_format, "Output format")->check(CLI::IsMember({"csv", "json"}));
  stability->add_option("--output", stability_output, "Output file (written atomically); default: standard output");

  auto* evolve = app.add_subcommand("evolve", "Integrate the cooling of a homogeneous gas: T(t), a2(t), ... (CVODE)");
  std::string evolve_scene, evolve_format = "csv", evolve_output;
  std::vector<std::string> evolve_overrides;
  evolve->add_option("scene", evolve_scene, "Scene file (TOML)")->required();
  evolve->add_option("--set", evolve_overrides, "Override a scene key: KEY=VALUE; repeatable");
  evolve->add_option("--format", evolve_format, "Output format")->check(CLI::IsMember({"csv", "json"}));
  evolve->add_option("--output", evolve_output, "Output file (written atomically); default: standard output");

  app.add_subcommand("models", "List the models with their coefficients and parameters");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "gkt: error: " << e.what() << " (see gkt --help)\n";
    return kBadInput;
  }

  try {
    if (table->parsed()) return run_table(scene_path, overrides, format, output, exact);
    if (stability->parsed())
      return run_table(stability_scene, stability_overrides, stability_format, stability_output, false, true);
    if (evolve->parsed()) {
      std::string counters;
      const auto table = gkt::cli::evolve(evolve_scene, evolve_overrides, counters);
      gkt::cli::write_output(evolve_output,
                             evolve_format == "json" ? gkt::cli::to_json(table) : gkt::cli::to_csv(table));
      std::cerr << "gkt: " << counters << "\n";
      return 0;
    }
    if (formula->parsed()) {
      gkt::cli::write_output(formula_output, gkt::cli::formula(formula_scene, formula_overrides, coefficient,
                                                               formula_order, formula_format));
      return 0;
    }
    return run_models();
  } catch (const std::invalid_argument& e) {
    std::cerr << "gkt: error: " << e.what() << "\n";
    return kBadInput;
  }
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {  // anything but bad input is a defect
    std::cerr << "gkt: internal error: " << e.what() << "\n";
    return 1;
  }
}
