// `gkt dsmc`: bad input (one line, exit 2, no output left), the output independent of --jobs, a
// seed fixes the output, and Haff's law from the command line. The golden outputs are in
// tests/golden/manifest.tsv (dsmc_*.csv).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct DsmcCliRun {
  int status = -1;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Runs `gkt dsmc` with arguments (shell-quoted by the caller) in `dir`'s files.
DsmcCliRun run_dsmc(const fs::path& dir, const std::string& args) {
  static int counter = 0;
  const fs::path out = dir / ("out" + std::to_string(counter)), err = dir / ("err" + std::to_string(counter++));
  const std::string cmd = std::string(GKT_CLI_PATH) + " dsmc " + args + " >" + out.string() + " 2>" + err.string();
  const int raw = std::system(cmd.c_str());
  DsmcCliRun r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  fs::remove(out);
  fs::remove(err);
  return r;
}

fs::path fresh_dir(const std::string& label) {
  const fs::path dir = fs::temp_directory_path() / ("gkt_dsmc_" + std::to_string(::getpid()) + "_" + label);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

const std::string kSmooth =
    "model = \"smooth-inelastic\"\ndimension = 3\nalpha = 0.8\nparticles = 1000\ncollisions_per_particle = 10\n"
    "batches = 5\nruns = 4\nseed = 9\n";

std::vector<std::vector<double>> numbers(const std::string& csv) {
  std::vector<std::vector<double>> rows;
  std::stringstream lines(csv);
  std::string line;
  std::getline(lines, line);  // header
  while (std::getline(lines, line)) {
    rows.emplace_back();
    std::stringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) rows.back().push_back(std::stod(cell));
  }
  return rows;
}

struct DsmcBadInput {
  std::string label, scene, extra, expect;
};

void PrintTo(const DsmcBadInput& b, std::ostream* os) { *os << b.label; }

class CliDsmcBadInput : public ::testing::TestWithParam<DsmcBadInput> {};

TEST_P(CliDsmcBadInput, OneLineErrorExitTwoNoOutput) {
  const DsmcBadInput b = GetParam();
  const fs::path dir = fresh_dir(b.label);
  std::ofstream(dir / "scene.toml") << b.scene;
  const fs::path output = dir / "result.csv";
  const DsmcCliRun r = run_dsmc(dir, (dir / "scene.toml").string() + " --output " + output.string() + " " + b.extra);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_TRUE(r.out.empty());
  ASSERT_FALSE(r.err.empty());
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "not one line: " << r.err;
  EXPECT_NE(r.err.find(b.expect), std::string::npos) << r.err;
  std::size_t files = 0;  // neither the output nor a temporary file
  for (const auto& entry : fs::directory_iterator(dir)) files += entry.path().filename() != "scene.toml";
  EXPECT_EQ(files, 0U);
  fs::remove_all(dir);
}

const std::string kMixture =
    "model = \"mixture\"\ndimension = 3\nalpha = 0.8\nparticles = 100\ncollisions_per_particle = 2\nruns = 2\n"
    "seed = 1\n[[species]]\nmass = 1\ndiameter = 1\nfraction = 0.5\n[[species]]\nmass = 2\ndiameter = 1\n";

const std::string kShear =
    "model = \"uniform-shear\"\ndimension = 2\nalpha = 0.7\nparticles = 2000\ncollisions_per_particle = 40\n"
    "runs = 8\nseed = 23\n";

const std::string kColumn =
    "model = \"gravity-column\"\ndimension = 3\nalpha = 0.99\nparticles_per_area = 5\nfloor_value = 50\n"
    "lid_height = 150\nsettle_time = 150\nsample_time = 150\nparticles = 3000\nruns = 4\nseed = 3\n";

INSTANTIATE_TEST_SUITE_P(
    Cases, CliDsmcBadInput,
    ::testing::Values(
        DsmcBadInput{"alpha", kSmooth, "--set alpha=1.5", "alpha: must be a number in (0, 1]"},
        DsmcBadInput{"alpha_sweep", kSmooth, "--set 'alpha=[0.5, 0.9]'", "alpha: must be a single number"},
        DsmcBadInput{"dimension", kSmooth, "--set dimension=4", "dimension: must be 2 or 3"},
        DsmcBadInput{"particles", kSmooth, "--set particles=1", "particles: must be an integer in [2, 10000000]"},
        DsmcBadInput{"particles_fraction", kSmooth, "--set particles=10.5", "particles: must be an integer"},
        DsmcBadInput{"runs", kSmooth, "--set runs=1", "runs: must be an integer in [2, 100000]"},
        DsmcBadInput{"seed", kSmooth, "--set seed=-3", "seed: must be an integer in [0, "},
        DsmcBadInput{"collisions", kSmooth, "--set collisions_per_particle=0", "collisions_per_particle: must be"},
        DsmcBadInput{"too_few_collisions", kSmooth, "--set batches=100000",
                     "collisions_per_particle: must give each of the 100000 batches"},
        DsmcBadInput{"missing_seed",
                     "model = \"smooth-inelastic\"\ndimension = 3\nalpha = 0.8\nparticles = 100\n"
                     "collisions_per_particle = 1\nruns = 2\n",
                     "", "seed: required"},
        DsmcBadInput{"unknown_key", kSmooth + "order = 2\n", "", "order: unknown key for gkt dsmc"},
        DsmcBadInput{"no_dsmc_model", kSmooth, "--set model=hard-spheres", "model: \"hard-spheres\" has no DSMC"},
        DsmcBadInput{"output_key", kSmooth + "[output]\ntail = true\n", "", "output.tail: unknown key"},
        DsmcBadInput{"output_both", kSmooth + "[output]\nhaff = true\ndistribution = true\n", "",
                     "output: choose one of distribution and haff"},
        DsmcBadInput{"jobs", kSmooth, "--jobs 0", "--jobs: must be an integer in [1, 64]"},
        DsmcBadInput{"viscoelastic_2d",
                     "model = \"viscoelastic\"\ndimension = 2\ndelta_prime = 0.1\nparticles = 100\n"
                     "collisions_per_particle = 1\nruns = 2\nseed = 1\n",
                     "", "dimension: must be 3 for model \"viscoelastic\""},
        DsmcBadInput{"rough_beta",
                     "model = \"rough\"\ndimension = 3\nalpha = 0.9\nbeta = 1.5\nmoment_of_inertia = 0.4\n"
                     "particles = 100\ncollisions_per_particle = 1\nruns = 2\nseed = 1\n",
                     "", "beta: must be a number in [-1, 1]"},
        DsmcBadInput{"mixture_fractions", kMixture + "fraction = 0.4\n", "",
                     "fraction_i: the fractions must add up to 1"},
        DsmcBadInput{"mixture_distribution", kMixture + "fraction = 0.5\n[output]\ndistribution = true\n", "",
                     "output.distribution: not available for model \"mixture\""},
        DsmcBadInput{"shear_alpha_range", kShear, "--set alpha=1.5", "alpha: must be a number in (0, 1]"},
        DsmcBadInput{"shear_elastic", kShear, "--set alpha=1", "alpha: must be a number in (0, 1) for gkt dsmc"},
        DsmcBadInput{"shear_rate", kShear, "--set shear_rate=0", "shear_rate: must be a number in (0, 100]"},
        DsmcBadInput{"shear_dimension", kShear, "--set dimension=1", "dimension: must be 2 or 3"},
        DsmcBadInput{"shear_haff", kShear + "[output]\nhaff = true\n", "",
                     "output.haff: not available for model \"uniform-shear\""},
        DsmcBadInput{"shear_unknown_key", kShear + "beta = 0.5\n", "",
                     "beta: unknown key for gkt dsmc with model \"uniform-shear\""},
        DsmcBadInput{"viscosity_kicks", kSmooth, "--set viscosity_kicks=0",
                     "viscosity_kicks: must be an integer in [1, 1000000]"},
        DsmcBadInput{"viscosity_kick", kSmooth + "viscosity_kicks = 2\n", "--set viscosity_kick=0.7",
                     "viscosity_kick: must be a number in (0, 0.5]"},
        DsmcBadInput{"viscosity_window", kSmooth + "viscosity_kicks = 2\n", "--set viscosity_window=0",
                     "viscosity_window: must be a number in (0, 1000]"},
        DsmcBadInput{"viscosity_without_kicks", kSmooth, "--set viscosity_kick=0.2",
                     "viscosity_kicks: required with viscosity_window or viscosity_kick"},
        DsmcBadInput{"packing_fraction", kSmooth, "--set packing_fraction=0.6",
                     "packing_fraction: must be a number in [0, 0.5], got 0.6"},
        DsmcBadInput{"pair_correlation", kSmooth, "--set packing_fraction=0.2 --set pair_correlation=nope",
                     "pair_correlation: must be one of"},
        DsmcBadInput{"dense_viscosity", kSmooth + "viscosity_kicks = 2\n", "--set packing_fraction=0.2",
                     "viscosity_kicks: the strained-HCS viscosity is simulated for the dilute gas only"},
        DsmcBadInput{"dense_shear", kShear, "--set packing_fraction=0.8",
                     "packing_fraction: must be a number in [0, 0.7], got 0.8"},
        DsmcBadInput{"dense_rough", "model = \"rough\"\npacking_fraction = 0.2\n", "",
                     "packing_fraction: unknown key for gkt dsmc with model \"rough\""},
        DsmcBadInput{"viscosity_haff", kSmooth + "viscosity_kicks = 2\n[output]\nhaff = true\n", "",
                     "viscosity_kicks: the shear viscosity is a summary column"},
        DsmcBadInput{"viscosity_shear_model", kShear, "--set viscosity_kicks=2",
                     "viscosity_kicks: unknown key for gkt dsmc with model \"uniform-shear\""},
        DsmcBadInput{"column_heat_flux_floor", kColumn, "--set floor=heat_flux",
                     "floor: must be \"temperature\" for gkt dsmc with model \"gravity-column\""},
        DsmcBadInput{"column_collisions", kColumn, "--set collisions_per_particle=10",
                     "collisions_per_particle: unknown key for gkt dsmc with model \"gravity-column\""},
        DsmcBadInput{"column_height", kColumn, "--set height=10", "height: unknown key for gkt dsmc"},
        DsmcBadInput{"column_alpha", kColumn, "--set alpha=0", "alpha: must be a number in (0, 1]"},
        DsmcBadInput{"column_lid", kColumn, "--set lid_height=-1", "lid_height: must be"},
        DsmcBadInput{"column_floor_value", kColumn, "--set floor_value=0", "floor_value: must be"},
        DsmcBadInput{"column_particles", kColumn, "--set particles=50", "particles: must be an integer in [100, "},
        DsmcBadInput{"column_cells", kColumn, "--set cell_height=100",
                     "cell_height: must give between 2 and 100000 cells"},
        DsmcBadInput{"column_time_step", kColumn, "--set time_step=2", "time_step: must be a number in (0, 1]"},
        DsmcBadInput{"column_sample_time", kColumn, "--set sample_time=0.05", "sample_time: must be at least 5"},
        DsmcBadInput{"column_missing_sample_time",
                     "model = \"gravity-column\"\ndimension = 3\nalpha = 0.99\nparticles_per_area = 5\n"
                     "floor_value = 50\nlid_height = 150\nparticles = 3000\nruns = 4\nseed = 3\n",
                     "", "sample_time: required"},
        DsmcBadInput{"column_haff", kColumn + "[output]\nhaff = true\n", "",
                     "output.haff: not available for model \"gravity-column\""}));

// The runs are spread over threads, the table is not: --jobs 1 and --jobs 3 print the same bytes,
// a second run with the same seed too, another seed something else.
TEST(CliDsmc, OutputIndependentOfJobsAndFixedBySeed) {
  const fs::path dir = fresh_dir("jobs");
  std::ofstream(dir / "scene.toml") << kSmooth;
  const std::string scene = (dir / "scene.toml").string();
  const DsmcCliRun one = run_dsmc(dir, scene + " --jobs 1"), three = run_dsmc(dir, scene + " --jobs 3"),
                   again = run_dsmc(dir, scene + " --jobs 2"), other = run_dsmc(dir, scene + " --set seed=10");
  ASSERT_EQ(one.status, 0) << one.err;
  EXPECT_EQ(one.out, three.out);
  EXPECT_EQ(one.out, again.out);
  EXPECT_NE(one.out, other.out);
  EXPECT_EQ(one.out.substr(0, one.out.find('\n')), "a2,a2_error,a3,a3_error,cooling_rate,cooling_rate_error");
  fs::remove_all(dir);
}

// [output] haff = true: T(t)/T0 follows (1 + ζ* t/2)^{−2} with the runs' own ζ* within 4 standard
// errors of T at each sampled time; the distribution rows integrate to ≤ 1 and approach the
// Maxwellian near c = 1 (ratio within 5 %).
TEST(CliDsmc, HaffLawAndDistribution) {
  const fs::path dir = fresh_dir("haff");
  std::ofstream(dir / "scene.toml") << kSmooth << "[output]\nhaff = true\n";
  const DsmcCliRun haff = run_dsmc(dir, (dir / "scene.toml").string() + " --set particles=2000 --set runs=6");
  ASSERT_EQ(haff.status, 0) << haff.err;
  EXPECT_EQ(haff.out.substr(0, haff.out.find('\n')),
            "collisions_per_particle,time,time_error,temperature,temperature_error,haff");
  const auto rows = numbers(haff.out);
  ASSERT_EQ(rows.size(), 5U);
  for (const auto& r : rows) {
    EXPECT_LT(r[3], 1);
    EXPECT_GT(r[4], 0);
    EXPECT_NEAR(r[3], r[5], 4 * r[4] + 1e-3 * r[5]) << "t = " << r[1];
  }
  std::ofstream(dir / "scene.toml") << kSmooth << "[output]\ndistribution = true\n";
  const DsmcCliRun dist = run_dsmc(dir, (dir / "scene.toml").string() + " --set particles=4000");
  ASSERT_EQ(dist.status, 0) << dist.err;
  double total = 0;
  for (const auto& r : numbers(dist.out)) {
    total += r[1] * 0.1;
    if (std::abs(r[0] - 1) < 0.06) {
      EXPECT_NEAR(r[4], 1, 0.05) << "c = " << r[0];
    }
  }
  EXPECT_LE(total, 1 + 1e-12);
  EXPECT_GT(total, 0.999);
  fs::remove_all(dir);
}

// The referee from the command line: `gkt dsmc` against `gkt table` (converged nonlinear Sonine HCS)
// at α = 0.8, 2D and 3D: a2, a3 and ζ* within 4 standard errors (8 runs of 5000 particles, 60
// collisions per particle; σ(a2) ≈ 1.5e-3, itself uncertain by ~25 % from 8 runs, so a2 = 0 — the
// Maxwellian — is required to be excluded by 5σ only).
TEST(CliDsmc, AgreesWithGktTable) {
  const fs::path dir = fresh_dir("table");
  std::ofstream(dir / "dsmc.toml") << kSmooth;
  std::ofstream(dir / "table.toml") << "model = \"smooth-inelastic\"\nhcs = \"nonlinear\"\nalpha = 0.8\n"
                                       "tolerance = 1e-6\ncoefficients = [\"a2\", \"a3\", \"cooling_rate\"]\n";
  for (int d : {3, 2}) {
    const std::string dim = " --set dimension=" + std::to_string(d);
    const DsmcCliRun sim = run_dsmc(dir, (dir / "dsmc.toml").string() + dim +
                                             " --set particles=5000 --set runs=8 --set collisions_per_particle=60");
    ASSERT_EQ(sim.status, 0) << sim.err;
    const std::string table_cmd = std::string(GKT_CLI_PATH) + " table " + (dir / "table.toml").string() + dim + " > " +
                                  (dir / "table.csv").string();
    ASSERT_EQ(std::system(table_cmd.c_str()), 0);
    const auto dsmc = numbers(sim.out), sonine = numbers(slurp(dir / "table.csv"));
    ASSERT_EQ(dsmc.size(), 1U);
    ASSERT_EQ(sonine.size(), 1U);
    // dsmc: a2, a2_error, a3, a3_error, cooling_rate, cooling_rate_error; table: a2, a3, cooling_rate, …
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(dsmc[0][2 * k], sonine[0][k], 4 * dsmc[0][2 * k + 1]) << "d = " << d << " column " << k;
    EXPECT_GT(std::abs(dsmc[0][0]), 5 * dsmc[0][1]) << "d = " << d << ": DSMC cannot tell a2 from 0";
  }
  fs::remove_all(dir);
}

// The Enskog HCS (theory.md §21.7): at φ = 0.3 (3D, Carnahan–Starling χ = 2.478) and φ = 0.5 (2D,
// Henderson χ = 3.125) `gkt dsmc` and the dense `gkt table` agree on a2, a3 and ζ* = χ ζ*_dilute within 4
// standard errors (8 runs of 5000 particles, 60 collisions per particle); the dilute ζ* is excluded
// by 20σ. Then Haff's law at φ = 0.3 with the table's dense ζ* (not the runs' own): T(t)/T0 within 4
// standard errors of (1 + ζ* t ν0(T0)/2)^{−2} at every batch.
TEST(CliDsmc, EnskogHcsAgreesWithDenseGktTable) {
  const fs::path dir = fresh_dir("enskog");
  std::ofstream(dir / "dsmc.toml") << kSmooth;
  std::ofstream(dir / "table.toml") << "model = \"smooth-inelastic\"\nhcs = \"nonlinear\"\nalpha = 0.8\n"
                                       "tolerance = 1e-6\ncoefficients = [\"a2\", \"a3\", \"cooling_rate\"]\n";
  auto table = [&](const std::string& args) {
    const std::string cmd = std::string(GKT_CLI_PATH) + " table " + (dir / "table.toml").string() + args + " > " +
                            (dir / "table.csv").string();
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    return numbers(slurp(dir / "table.csv"));
  };
  for (const auto& [d, phi] : {std::pair{3, "0.3"}, std::pair{2, "0.5"}}) {
    const std::string dim = " --set dimension=" + std::to_string(d),
                      dense = " --set packing_fraction=" + std::string(phi);
    const DsmcCliRun sim = run_dsmc(dir, (dir / "dsmc.toml").string() + dim + dense +
                                             " --set particles=5000 --set runs=8 --set collisions_per_particle=60");
    ASSERT_EQ(sim.status, 0) << sim.err;
    const auto dsmc = numbers(sim.out), enskog = table(dim + dense), dilute = table(dim);
    ASSERT_EQ(dsmc.size(), 1U);
    ASSERT_EQ(enskog.size(), 1U);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(dsmc[0][2 * k], enskog[0][k], 4 * dsmc[0][2 * k + 1]) << "d = " << d << " column " << k;
    EXPECT_GT(std::abs(dsmc[0][4] - dilute[0][2]), 20 * dsmc[0][5]) << "d = " << d << ": the dilute cooling rate";
  }
  const double zeta = table(" --set dimension=3 --set packing_fraction=0.3")[0][2];
  std::ofstream(dir / "dsmc.toml") << kSmooth << "packing_fraction = 0.3\n[output]\nhaff = true\n";
  const DsmcCliRun haff = run_dsmc(dir, (dir / "dsmc.toml").string() + " --set particles=2000 --set runs=6");
  ASSERT_EQ(haff.status, 0) << haff.err;
  const auto rows = numbers(haff.out);
  ASSERT_EQ(rows.size(), 5U);
  for (const auto& r : rows) {
    const double law = 1 / ((1 + 0.5 * zeta * r[1]) * (1 + 0.5 * zeta * r[1]));
    EXPECT_NEAR(r[3], law, 4 * r[4] + 1e-3 * law) << "t = " << r[1];
  }
  EXPECT_LT(rows.back()[3], 0.5);  // the gas did cool: the law is tested, not its t = 0 value
  fs::remove_all(dir);
}

// The shear viscosity of the strained HCS (theory.md §21.6) is an extra summary column, after the
// usual three, only when viscosity_kicks is given; α = 1: the elastic η* = 1.016034 within 5σ
// (4 runs × 40 kicks of ε = 0.5, N = 1000: σ ≈ 0.02).
TEST(CliDsmc, ShearViscosityColumn) {
  const fs::path dir = fresh_dir("viscosity");
  std::ofstream(dir / "scene.toml") << kSmooth;
  const std::string scene = (dir / "scene.toml").string();
  const DsmcCliRun plain = run_dsmc(dir, scene + " --set alpha=1"),
                   kicked = run_dsmc(dir, scene +
                                              " --set alpha=1 --set viscosity_kicks=40 --set viscosity_window=12 "
                                              "--set viscosity_kick=0.5");
  ASSERT_EQ(plain.status, 0) << plain.err;
  ASSERT_EQ(kicked.status, 0) << kicked.err;
  const std::string usual = "a2,a2_error,a3,a3_error,cooling_rate,cooling_rate_error";
  EXPECT_EQ(plain.out.substr(0, plain.out.find('\n')), usual);
  EXPECT_EQ(kicked.out.substr(0, kicked.out.find('\n')), usual + ",shear_viscosity,shear_viscosity_error");
  const auto row = numbers(kicked.out);
  ASSERT_EQ(row.size(), 1U);
  ASSERT_EQ(row[0].size(), 8U);
  EXPECT_GT(row[0][7], 0);
  EXPECT_NEAR(row[0][6], 1.016034, 5 * row[0][7]);
  // the unkicked columns come from the same runs as without the kicks
  EXPECT_EQ(numbers(plain.out)[0][0], row[0][0]);
  fs::remove_all(dir);
}

// SIGTERM while the runs go on: exit 143 and no file at all (neither the output nor its temporary
// file; no partial averages). 10⁵ runs never finish in the half second before the signal; a signal
// that arrives before gkt's handler (a slow sanitized start) ends the process with 143 too.
TEST(CliDsmc, SignalLeavesNoOutput) {
  const fs::path dir = fresh_dir("signal");
  std::ofstream(dir / "scene.toml") << kSmooth;
  const std::string cmd = "sh -c '" + std::string(GKT_CLI_PATH) + " dsmc " + (dir / "scene.toml").string() +
                          " --set runs=100000 --set particles=20000 --output " + (dir / "out.csv").string() +
                          " 2>/dev/null & pid=$!; sleep 0.5; kill -TERM $pid; wait $pid; echo $? > " +
                          (dir / "status").string() + "'";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  EXPECT_EQ(slurp(dir / "status"), "143\n");
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(dir))
    files += entry.path().filename() != "scene.toml" && entry.path().filename() != "status";
  EXPECT_EQ(files, 0U);
  fs::remove_all(dir);
}

// Uniform shear flow (theory.md §22.5): `gkt table`'s columns with their errors, the same bytes for
// --jobs 1 and 2, and at α = 0.7 the steady state of the theory.md table (10 runs × 2·10⁴
// particles) within 4 combined standard errors from 8 runs × 2000 particles × (20 + 40) collisions
// per particle started at Grad's a*; γ lies many σ above Grad's (22.6) (the DSMC's +5–6 %).
TEST(CliDsmc, UniformShearAgreesWithTheDocumentedSteadyState) {
  const fs::path dir = fresh_dir("shear");
  std::ofstream(dir / "scene.toml") << kShear;
  const std::string scene = (dir / "scene.toml").string();
  struct Documented {
    int d;
    std::string header;
    std::vector<double> value, error;  // γ, P_xx, P_yy, [P_zz,] P_xy over 2nT; Grad's γ last
    double grad_gamma;
  };
  const std::vector<Documented> documented{
      {2,
       "reduced_shear_rate,reduced_shear_rate_error,stress_xx,stress_xx_error,stress_yy,stress_yy_error,"
       "stress_xy,stress_xy_error",
       {0.78027, 0.63066, 0.36934, -0.21945},
       {0.00035, 0.00016, 0.00016, 0.00012},
       0.74320},
      {3,
       "reduced_shear_rate,reduced_shear_rate_error,stress_xx,stress_xx_error,stress_yy,stress_yy_error,"
       "stress_zz,stress_zz_error,stress_xy,stress_xy_error",
       {0.85264, 0.71443, 0.38172, 0.40386, -0.25237},
       {0.00040, 0.00018, 0.00017, 0.00016, 0.00013},
       0.80551}};
  for (const auto& doc : documented) {
    const std::string dim = " --set dimension=" + std::to_string(doc.d);
    const DsmcCliRun one = run_dsmc(dir, scene + dim + " --jobs 1"), two = run_dsmc(dir, scene + dim + " --jobs 2");
    ASSERT_EQ(one.status, 0) << one.err;
    EXPECT_EQ(one.out, two.out);
    EXPECT_EQ(one.out.substr(0, one.out.find('\n')), doc.header);
    const auto rows = numbers(one.out);
    ASSERT_EQ(rows.size(), 1U);
    ASSERT_EQ(rows[0].size(), 2 * doc.value.size());
    for (std::size_t k = 0; k < doc.value.size(); ++k) {
      const double mean = rows[0][2 * k], error = rows[0][2 * k + 1];
      EXPECT_GT(error, 0) << "d = " << doc.d << " column " << k;
      EXPECT_NEAR(mean, doc.value[k], 4 * std::hypot(error, doc.error[k])) << "d = " << doc.d << " column " << k;
    }
    EXPECT_GT(rows[0][0] - doc.grad_gamma, 5 * rows[0][1]) << "d = " << doc.d << ": DSMC cannot tell γ from Grad's";
  }
  fs::remove_all(dir);
}

// The Enskog uniform shear flow from the command line (theory.md §22.8): with a vanishing shear rate
// the gas is in its cooling state, so the pressure (2/d) Σ_i P_ii/(2nT) = p/(nT) is the exact
// 1 + 2^{d−2}(1+α)φχ of (15.5) (2D, α = 0.8, φ = 0.3, Henderson χ = 1.6122…) within 4σ, and P_xy = 0.
TEST(CliDsmc, EnskogShearSceneHasTheDensePressure) {
  const fs::path dir = fresh_dir("enskog_shear");
  std::ofstream(dir / "scene.toml") << kShear;
  const DsmcCliRun r = run_dsmc(dir, (dir / "scene.toml").string() +
                                         " --set alpha=0.8 --set shear_rate=1e-9 --set packing_fraction=0.3 "
                                         "--set relaxation=5 --set collisions_per_particle=10 --set runs=4");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto row = numbers(r.out);
  ASSERT_EQ(row.size(), 1U);
  ASSERT_EQ(row[0].size(), 8U);  // γ, P_xx, P_yy, P_xy with errors (2D)
  const double phi = 0.3, chi = (1 - 7 * phi / 16) / ((1 - phi) * (1 - phi));
  EXPECT_NEAR(row[0][2] + row[0][4], 1 + 1.8 * phi * chi, 4 * std::hypot(row[0][3], row[0][5]));
  EXPECT_NEAR(row[0][6], 0, 4 * row[0][7]);
  fs::remove_all(dir);
}

// The column in gravity (theory.md §23.3): one row per cell with n, T, q and their errors over the
// runs, the same bytes for --jobs 1 and 2; below the Knudsen height (z ≈ 36σ) the profile follows
// `gkt table` with model gravity-column given the DSMC's lowest-cell temperature as its floor (the
// wall's Knudsen layer, theory.md §23.3), at 10.5, 20.5 and 30.5σ within 4 standard errors plus 4 %:
// the documented deviation of the long runs (1–2 % in n, 1–2.5 % in T) plus ≈ 1.2 % from putting
// the cell centred at 0.5σ at z = 0 (hydrodynamics' T falls that much in half a cell); an elastic
// DSMC, isothermal at the wall's 50 mgσ, would miss T ≈ 28 at 30σ by more than half. The mass
// N = ∫n dz = 5 within 0.5 %; the heat flux falls with height (the gas dissipates what the floor
// gives it).
TEST(CliDsmc, GravityColumnFollowsHydrodynamicsBelowTheKnudsenHeight) {
  const fs::path dir = fresh_dir("column");
  std::ofstream(dir / "scene.toml") << kColumn;
  const std::string scene = (dir / "scene.toml").string();
  const DsmcCliRun one = run_dsmc(dir, scene + " --jobs 1"), two = run_dsmc(dir, scene + " --jobs 2");
  ASSERT_EQ(one.status, 0) << one.err;
  EXPECT_EQ(one.out, two.out);
  EXPECT_EQ(one.out.substr(0, one.out.find('\n')),
            "height,number_density,number_density_error,temperature,temperature_error,heat_flux,heat_flux_error");
  const auto dsmc = numbers(one.out);
  ASSERT_EQ(dsmc.size(), 150U);
  double mass = 0;
  for (const auto& r : dsmc) mass += r[1];
  EXPECT_NEAR(mass, 5, 0.025);
  EXPECT_GT(dsmc[0][5], 4 * dsmc[0][6]);
  EXPECT_GT(dsmc[0][5], dsmc[30][5] + 4 * std::hypot(dsmc[0][6], dsmc[30][6]));
  std::ofstream(dir / "table.toml") << "model = \"gravity-column\"\ndimension = 3\nalpha = 0.99\norder = 2\n"
                                       "particles_per_area = 5\nlid_height = 150\nfloor = \"temperature\"\n"
                                       "floor_value = "
                                    << dsmc[0][3] << "\nheight = [10.5, 20.5, 30.5]\n"
                                    << "coefficients = [\"number_density\", \"temperature\"]\n";
  const std::string table_cmd =
      std::string(GKT_CLI_PATH) + " table " + (dir / "table.toml").string() + " > " + (dir / "table.csv").string();
  ASSERT_EQ(std::system(table_cmd.c_str()), 0);
  const auto hydro = numbers(slurp(dir / "table.csv"));
  ASSERT_EQ(hydro.size(), 3U);
  for (std::size_t k = 0; k < 3; ++k) {
    const auto& r = dsmc[10 * (k + 1)];
    ASSERT_DOUBLE_EQ(r[0], 10.5 + 10.0 * static_cast<double>(k));
    EXPECT_GT(r[2], 0);
    ASSERT_DOUBLE_EQ(hydro[k][0], r[0]);  // table: height, number_density, temperature, errors, order
    EXPECT_NEAR(r[1], hydro[k][1], 4 * r[2] + 0.04 * hydro[k][1]) << "n at z = " << r[0];
    EXPECT_NEAR(r[3], hydro[k][2], 4 * r[4] + 0.04 * hydro[k][2]) << "T at z = " << r[0];
  }
  fs::remove_all(dir);
}

}  // namespace
