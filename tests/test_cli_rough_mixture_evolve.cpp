// `gkt evolve` with a rough binary mixture (model = "rough", two [[species]] tables; docs/theory.md §19.31,
// conventions.md): the shipped scene relaxes to `gkt table`'s Maxwellian HCS, the per-species initial temperatures
// reach the integrator, and bad input exits 2 with one line and no output.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "cli_run.hpp"

namespace {

using gkt::test::CliRun;
using gkt::test::parse_csv;
using gkt::test::run_gkt;
using gkt::test::scene_path;

/// Runs gkt with its streams under this test's own temporary folder.
CliRun run(const std::string& args) { return run_gkt(args, "gkt_rough_mixture_evolve_"); }

}  // namespace

// The last row of the shipped scene (τ = 10⁶) carries `gkt table`'s Maxwellian HCS (rough_mixture_hcs.toml at the
// same α, β) to 1e-8 in γ_i, θ_i and ζ*; the first row starts cold (θ_i < 0.02).
TEST(CliRoughMixtureEvolve, RelaxesToTheTable) {
  const CliRun evolve = run("evolve " + scene_path("rough_mixture_evolve.toml"));
  const CliRun table = run("table " + scene_path("rough_mixture_hcs.toml") + " --set 'alpha=[0.9]' --set 'beta=[0.5]'");
  ASSERT_EQ(evolve.status, 0) << evolve.err;
  ASSERT_EQ(table.status, 0) << table.err;
  EXPECT_NE(evolve.err.find("cvode: steps="), std::string::npos);
  const auto e = parse_csv(evolve.out), t = parse_csv(table.out);
  ASSERT_EQ(e[0],
            (std::vector<std::string>{
                "time", "temperature", "translational_temperature_1", "translational_temperature_2",
                "rotational_temperature_1", "rotational_temperature_2", "temperature_ratio_1", "temperature_ratio_2",
                "rotational_temperature_ratio_1", "rotational_temperature_ratio_2", "cooling_rate"}));
  ASSERT_EQ(e.size(), 14u);
  ASSERT_EQ(t[0][2], "temperature_ratio_1");
  for (std::size_t k = 0; k < 5; ++k)
    EXPECT_NEAR(std::stod(e.back()[6 + k]), std::stod(t[1][2 + k]), 1e-8) << e[0][6 + k];
  EXPECT_LT(std::stod(e[1][8]), 0.02);
  EXPECT_LT(std::stod(e[1][9]), 0.02);
}

// translational_temperature_i, rotational_temperature_i override the one-gas keys per species; without them both
// species start at translational_temperature, rotational_temperature.
TEST(CliRoughMixtureEvolve, PerSpeciesInitialTemperatures) {
  const CliRun r = run("evolve " + scene_path("rough_mixture_evolve.toml") +
                       " --set translational_temperature_1=2 --set translational_temperature_2=0.5 "
                       "--set rotational_temperature_2=3 --set 'times=[1e-9]'");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = parse_csv(r.out);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_NEAR(std::stod(rows[1][2]), 2, 1e-6);
  EXPECT_NEAR(std::stod(rows[1][3]), 0.5, 1e-6);
  EXPECT_NEAR(std::stod(rows[1][4]), 0.01, 1e-6);  // rotational_temperature
  EXPECT_NEAR(std::stod(rows[1][5]), 3, 1e-6);
  EXPECT_NEAR(std::stod(rows[1][1]), 0.3 * 2 + 0.7 * 0.5, 1e-6);
}

// Bad input: exit 2, one line naming the key, nothing on standard output.
TEST(CliRoughMixtureEvolve, RefusesBadInput) {
  const std::string mix = "evolve " + scene_path("rough_mixture_evolve.toml") + " --set ";
  for (const auto& [args, message] : std::vector<std::pair<std::string, std::string>>{
           {mix + "rotational_temperature_2=-1", "rotational_temperature_2: must be a number > 0"},
           {mix + "translational_temperature_1=0", "translational_temperature_1: must be a number > 0"},
           {mix + "rotational_temperature=0", "rotational_temperature: must be a number > 0"},
           {mix + "'hcs=\"linear\"'", "hcs: the rough binary mixture (species = 2) evolves in the Maxwellian"},
           {mix + "a20=0.1", "a20: the rough binary mixture (species = 2) evolves Maxwellians"},
           {mix + "order=2", "order: the rough binary mixture (species = 2) evolves at order 1 only"},
           {mix + "max_steps=5", "max_steps: used its 5 CVODE steps before time = "},
           {mix + "fraction_1=0.5", "fraction: the mole fractions x_1 + x_2 must sum to 1"},
           {mix + "beta_1_2=2", "beta_1_2: must be a number in [-1, 1]"},
           {"evolve " + scene_path("rough_evolve.toml") + " --set translational_temperature_1=2",
            "translational_temperature_1: per-species keys need species = 2"}}) {
    const CliRun bad = run(args);
    EXPECT_EQ(bad.status, 2) << args << ": " << bad.err;
    EXPECT_NE(bad.err.find(message), std::string::npos) << args << ": " << bad.err;
    EXPECT_TRUE(bad.out.empty()) << args;
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << args << ": " << bad.err;
  }
}
