// The `gkt` program: golden outputs (regression data, float-tolerant diff) and the bad-input
// contract (one-line error naming the field, exit code 2, no output file left behind).
#include <gtest/gtest.h>

#include <cmath>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_run.hpp"
#include "sanitizer.hpp"

namespace fs = std::filesystem;

namespace {

using gkt::test::CliRun;
using gkt::test::parse_csv;
using gkt::test::read_file;
using gkt::test::run_gkt;
using gkt::test::scene_path;

std::string golden_path(const std::string& name) { return std::string(GKT_SOURCE_DIR) + "/tests/golden/" + name; }

bool is_number(const std::string& s, double& x) {
  char* end = nullptr;
  x = std::strtod(s.c_str(), &end);
  return !s.empty() && end == s.c_str() + s.size() && std::isfinite(x);  // nan, inf: compared as text
}

/// Float-tolerant CSV comparison: header exact; numeric cells within a relative tolerance
/// (looser for *_error columns, printed to 3 digits); other cells exact.
void expect_csv_close(const std::string& actual, const std::string& expected) {
  const auto a = parse_csv(actual), e = parse_csv(expected);
  ASSERT_EQ(a.size(), e.size());
  ASSERT_FALSE(e.empty());
  ASSERT_EQ(a[0], e[0]);
  for (std::size_t r = 1; r < e.size(); ++r) {
    ASSERT_EQ(a[r].size(), e[r].size()) << "row " << r;
    for (std::size_t c = 0; c < e[r].size(); ++c) {
      double x = 0, y = 0;
      const bool error_column = e[0][c].ends_with("_error");
      if (is_number(a[r][c], x) && is_number(e[r][c], y)) {
        EXPECT_NEAR(x, y, (error_column ? 2e-2 : 1e-12) * std::abs(y)) << e[0][c] << " row " << r;
      } else {
        EXPECT_EQ(a[r][c], e[r][c]) << e[0][c] << " row " << r;
      }
    }
  }
}

/// Float-tolerant comparison of `--format json` tables: same columns and rows, values within the
/// tolerances of expect_csv_close.
void expect_json_close(const std::string& actual, const std::string& expected) {
  const auto got = nlohmann::json::parse(actual);
  const auto want = nlohmann::json::parse(expected);
  ASSERT_EQ(got["columns"], want["columns"]);
  ASSERT_EQ(got["rows"].size(), want["rows"].size());
  for (std::size_t k = 0; k < want["rows"].size(); ++k)
    for (const auto& [key, value] : want["rows"][k].items()) {
      const double tol = key.ends_with("_error") ? 2e-2 : 1e-12;
      EXPECT_NEAR(got["rows"][k][key].template get<double>(), value.template get<double>(),
                  tol * std::abs(value.template get<double>()))
          << key;
    }
}

/// One line of tests/golden/manifest.tsv: a golden file and the gkt command whose output it holds.
struct GoldenCase {
  std::string golden;      // file name in tests/golden/
  std::string subcommand;  // table, stability, evolve
  std::string scene;       // relative to the source tree
  std::string options;     // shell-quoted, may be empty
  std::string error;       // a malformed manifest line, reported by the test

  /// The command as the golden file's header names it: `table tables/scenes/x.toml --exact`.
  std::string command() const { return subcommand + " " + scene + (options.empty() ? "" : " " + options); }
};

void PrintTo(const GoldenCase& g, std::ostream* os) { *os << g.golden; }

/// Returns the lines of tests/golden/manifest.tsv (tab-separated: golden file, subcommand, scene,
/// options); a missing, empty or malformed manifest gives a case that fails with the reason.
std::vector<GoldenCase> read_golden_manifest() {
  std::vector<GoldenCase> cases;
  std::ifstream in(golden_path("manifest.tsv"));
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> fields;
    std::stringstream fs(line);
    std::string field;
    while (std::getline(fs, field, '\t')) fields.push_back(field);
    if (fields.size() == 3) fields.emplace_back();
    if (fields.size() != 4 || fields[0].empty()) {
      cases.push_back({"malformed_line_" + std::to_string(cases.size() + 1), "", "", "",
                       "tests/golden/manifest.tsv: expected 3 or 4 tab-separated fields, got: " + line});
      continue;
    }
    cases.push_back({fields[0], fields[1], fields[2], fields[3], ""});
  }
  if (cases.empty()) cases.push_back({"manifest", "", "", "", "tests/golden/manifest.tsv: missing or empty"});
  return cases;
}

}  // namespace

// ---- golden outputs (regression data, tests/golden/README.md): one test per manifest line -------

class CliGolden : public ::testing::TestWithParam<GoldenCase> {};

// Runs the command of one manifest line and compares its output with the golden file after the
// header line, which must name the same command (a manifest edit without regenerating fails).
TEST_P(CliGolden, MatchesGoldenFile) {
  const GoldenCase& g = GetParam();
  ASSERT_TRUE(g.error.empty()) << g.error;
  const std::string text = read_file(golden_path(g.golden));
  const std::size_t eol = text.find('\n');
  ASSERT_NE(eol, std::string::npos) << g.golden << ": missing or empty";
  const std::string header = text.substr(0, eol);
  const std::string named = "# regression data: gkt " + g.command() + " (gkt ";
  EXPECT_EQ(header.rfind(named, 0), 0U) << g.golden << " header: " << header << "\nexpected to begin with: " << named
                                        << "\nregenerate: bash tools/regenerate_goldens.sh";
  const CliRun r = run_gkt(g.subcommand + " " + std::string(GKT_SOURCE_DIR) + "/" + g.scene +
                           (g.options.empty() ? "" : " " + g.options));
  ASSERT_EQ(r.status, 0) << r.err;
  if (g.golden.ends_with(".json"))
    expect_json_close(r.out, text.substr(eol + 1));
  else
    expect_csv_close(r.out, text.substr(eol + 1));
}

INSTANTIATE_TEST_SUITE_P(Manifest, CliGolden, ::testing::ValuesIn(read_golden_manifest()), [](const auto& info) {
  std::string name = info.param.golden.substr(0, info.param.golden.rfind('.'));
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
});

// Every file in tests/golden/ (but README.md and the manifest) is listed once, and every listed one exists.
TEST(CliGoldenManifest, ListsEveryGoldenFileOnce) {
  std::map<std::string, int> listed;
  for (const GoldenCase& g : read_golden_manifest()) {
    EXPECT_TRUE(g.error.empty()) << g.error;
    ++listed[g.golden];
  }
  std::set<std::string> present;
  for (const auto& entry : fs::directory_iterator(golden_path(""))) {
    const std::string name = entry.path().filename().string();
    if (name != "README.md" && name != "manifest.tsv" && !name.starts_with(".")) present.insert(name);
  }
  for (const auto& [name, count] : listed) {
    EXPECT_EQ(count, 1) << name << " listed " << count << " times";
    EXPECT_TRUE(present.contains(name)) << name << ": listed in the manifest, missing in tests/golden/";
  }
  for (const std::string& name : present)
    EXPECT_TRUE(listed.contains(name)) << name << ": not in tests/golden/manifest.tsv";
}

// ---- published and exact values through the CLI (independent of the regression data) ----------

TEST(CliValues, ExactTable) {
  const CliRun r = run_gkt("table " + scene_path("hard_spheres_exact.toml") + " --exact");
  ASSERT_EQ(r.status, 0) << r.err;
  // The published exact values appear verbatim (Chapman & Cowling §10.51).
  EXPECT_NE(r.out.find("205/202,45/44"), std::string::npos);
}

TEST(CliValues, ConvergedJson) {
  const CliRun r = run_gkt("table " + scene_path("hard_spheres_converged.toml") + " --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto got = nlohmann::json::parse(r.out);
  // Pekeris & Alterman (1957): 1.016034, 1.025218.
  EXPECT_NEAR(got["rows"][0]["shear_viscosity"].template get<double>(), 1.016034, 5e-7);
  EXPECT_NEAR(got["rows"][0]["thermal_conductivity"].template get<double>(), 1.025218, 5e-7);
}

TEST(CliValues, HcsFirstSonineExact) {
  const CliRun r = run_gkt("table " + scene_path("hcs_first_sonine.toml") + " --exact");
  ASSERT_EQ(r.status, 0) << r.err;
  // van Noije & Ernst (1998) at α = 1/2, 3D: a2 = 16/305 = 4/76.25.
  EXPECT_NE(r.out.find("1/2,16/305,"), std::string::npos);
}

// The modified scheme through the CLI: exact first-Sonine values equal the closed forms printed by
// the modified closed forms (3D, α = 1/2: κ* = 10784/6615 against the standard 86272/45135), and
// `gkt formula` emits the modified evaluator.
TEST(CliValues, ModifiedSchemeFirstSonine) {
  const std::string scene = scene_path("navier_stokes_first_sonine.toml");
  const CliRun modified = run_gkt("table " + scene + " --exact --set 'scheme=\"modified\"' --set 'alpha=[0.5]'");
  const CliRun standard = run_gkt("table " + scene + " --exact --set 'alpha=[0.5]'");
  ASSERT_EQ(modified.status, 0) << modified.err;
  ASSERT_EQ(standard.status, 0) << standard.err;
  EXPECT_NE(modified.out.find("1/2,488/391,10784/6615,"), std::string::npos);
  EXPECT_NE(standard.out.find(",86272/45135,"), std::string::npos);
  const CliRun formula =
      run_gkt("formula " + scene + " --coefficient thermal_conductivity --set 'scheme=\"modified\"' --format cpp");
  ASSERT_EQ(formula.status, 0) << formula.err;
  EXPECT_NE(formula.out.find("modified_first_sonine_thermal_conductivity_d3"), std::string::npos);
}

// Dense gas through the CLI: p* and ζ* = χ ζ*_dilute are exact rationals (3D, α = 1/2, φ = 3/10).
TEST(CliValues, EnskogFirstSonine) {
  const CliRun exact = run_gkt("table " + scene_path("enskog_first_sonine.toml") +
                               " --exact --set 'coefficients=[\"pressure\", \"cooling_rate\"]' --set 'alpha=[0.5]'");
  ASSERT_EQ(exact.status, 0) << exact.err;
  // χ(3/10) = (17/20)/(343/1000) = 850/343; p* = 1 + 2 (3/2)(3/10) χ = 1108/343.
  EXPECT_NE(exact.out.find("1/2,3/10,1108/343,"), std::string::npos) << exact.out;
}

// Binary mixture HCS through [[species]] tables (the physics is checked in tests/test_mixture.cpp).
TEST(CliValues, MixtureHcs) {
  // Identical species through the CLI, Maxwellian scheme: equipartition, ζ* of the one-component
  // gas (5/12)(1 − α²).
  const CliRun same = run_gkt("table " + scene_path("mixture_hcs.toml") +
                              " --set mass_2=1 --set diameter_2=1 --set alpha=0.6 --set packing_fraction=0" +
                              " --set hcs=maxwellian --set 'coefficients=[\"cooling_rate\", \"temperature_ratio_1\"]'");
  ASSERT_EQ(same.status, 0) << same.err;
  EXPECT_NE(same.out.find("\n0.26666666666666666,1,"), std::string::npos) << same.out;
  // hcs_order = 3 adds the a3_species_i columns; a2 moves from its first-Sonine value.
  const CliRun third =
      run_gkt("table " + scene_path("mixture_hcs.toml") +
              " --set hcs_order=3 --set 'mass_2=[2]' --set 'alpha=[0.7]' --set 'packing_fraction=[0]'");
  ASSERT_EQ(third.status, 0) << third.err;
  EXPECT_NE(third.out.find("a3_species_1,a3_species_2"), std::string::npos) << third.out;
}

// Navier–Stokes coefficients of a dilute mixture (the physics in tests/test_mixture_navier_stokes.cpp).
TEST(CliValues, MixtureTransport) {
  // Identical species through the CLI: η* and κ* of the one-component gas about a Maxwellian HCS
  // at α = 0.5, first order: 1/(ν_η − ζ/2) = 1.28 and 1.70666… (= 128/75).
  const CliRun same = run_gkt("table " + scene_path("mixture_transport.toml") +
                              " --set mass_2=1 --set diameter_2=1 --set alpha=0.5 --set order=1 --set dimension=3" +
                              " --set 'coefficients=[\"shear_viscosity\", \"thermal_conductivity\"]'");
  ASSERT_EQ(same.status, 0) << same.err;
  EXPECT_NE(same.out.find("\n1.28,"), std::string::npos) << same.out;
  EXPECT_NE(same.out.find(",1.70666666666666"), std::string::npos) << same.out;
}

// basis_width = "auto" (theory.md (17.30)): where the rule keeps width 1 (α = 0.9, m2/m1 = 2: A*²/4 ≫ 12)
// the table is the standard one byte for byte; it widens at α = 0.5 and changes the values; it is refused,
// naming the key, with exit 2 and no output, for a dense gas, the cumulant reference or an unknown choice.
TEST(CliValues, MixtureAutomaticBasisWidth) {
  const std::string base = "table " + scene_path("mixture_transport.toml") +
                           " --set mass_2=2 --set diameter_2=1 --set order=6 --set dimension=3" +
                           " --set 'coefficients=[\"mutual_diffusion_1_2\", \"thermal_conductivity\"]'";
  const CliRun standard = run_gkt(base + " --set alpha=0.9"),
               automatic = run_gkt(base + " --set alpha=0.9 --set 'basis_width=\"auto\"'");
  ASSERT_EQ(standard.status, 0) << standard.err;
  ASSERT_EQ(automatic.status, 0) << automatic.err;
  EXPECT_EQ(standard.out, automatic.out);
  const CliRun wide = run_gkt(base + " --set alpha=0.5 --set 'basis_width=\"auto\"'"),
               narrow = run_gkt(base + " --set alpha=0.5");
  ASSERT_EQ(wide.status, 0) << wide.err;
  EXPECT_NE(wide.out, narrow.out);
  for (const char* bad :
       {" --set packing_fraction=0.1 --set 'basis_width=\"auto\"'",
        " --set 'reference_state=\"hcs\"' --set 'basis_width=\"auto\"'", " --set 'basis_width=\"wide\"'"}) {
    const CliRun r = run_gkt(base + " --set alpha=0.5" + bad);
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_EQ(r.err.rfind("gkt: error: basis_width: ", 0), 0U) << r.err;
    EXPECT_TRUE(r.out.empty()) << bad;
  }
}

TEST(CliValues, NavierStokesFirstSonineExact) {
  const CliRun r = run_gkt("table " + scene_path("navier_stokes_first_sonine.toml") + " --exact");
  ASSERT_EQ(r.status, 0) << r.err;
  // Elastic row: η* = κ* = 1, μ* = ζ* = 0 exactly.
  EXPECT_NE(r.out.find("\n1,1,1,0,0,"), std::string::npos);
}

// The committed generated closed forms are what `gkt formula --format cpp` prints now.
TEST(CliFormula, GeneratedFileIsCurrent) {
  const fs::path scene = fs::temp_directory_path() / ("gkt_formula_" + std::to_string(::getpid()) + ".toml");
  std::ofstream(scene) << "model = \"smooth-inelastic\"\n";
  std::string expected =
      "// Generated by tools/generate_first_sonine.sh: do not edit. Exact first-Sonine closed forms of\n"
      "// the dilute smooth inelastic gas (docs/theory.md (10.8)), coefficients rounded to double.\n";
  for (int d : {2, 3})
    for (const char* c :
         {"a2", "cooling_rate", "shear_viscosity", "thermal_conductivity", "density_heat_coefficient"}) {
      const CliRun r = run_gkt("formula " + scene.string() + " --set dimension=" + std::to_string(d) +
                               " --coefficient " + c + " --format cpp");
      ASSERT_EQ(r.status, 0) << r.err;
      expected += r.out;
    }
  EXPECT_EQ(
      read_file(std::string(GKT_SOURCE_DIR) + "/lib/transport/closed_forms/generated/first_sonine_closed_forms.inc"),
      expected)
      << "regenerate with: bash tools/generate_first_sonine.sh";
  std::ofstream(scene) << "model = \"smooth-inelastic\"\npacking_fraction = 0.25\n";
  expected =
      "// Generated by tools/generate_first_sonine.sh: do not edit. Exact first-Sonine closed forms of\n"
      "// the dense (Enskog) smooth inelastic gas (docs/theory.md §15.7), coefficients rounded to double.\n";
  for (int d : {2, 3})
    for (const char* c : {"a2", "cooling_rate", "pressure", "shear_viscosity", "bulk_viscosity", "thermal_conductivity",
                          "density_heat_coefficient", "cooling_rate_first_order"}) {
      const CliRun r = run_gkt("formula " + scene.string() + " --set dimension=" + std::to_string(d) +
                               " --coefficient " + c + " --format cpp");
      ASSERT_EQ(r.status, 0) << r.err;
      expected += r.out;
    }
  fs::remove(scene);
  EXPECT_EQ(read_file(std::string(GKT_SOURCE_DIR) +
                      "/lib/transport/closed_forms/generated/enskog_first_sonine_closed_forms.inc"),
            expected)
      << "regenerate with: bash tools/generate_first_sonine.sh";
}

TEST(CliFormula, TextLatexAndHardSpheres) {
  const CliRun text = run_gkt("formula " + scene_path("hcs_first_sonine.toml") + " --coefficient a2");
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_EQ(text.out,
            "(-16/15*alpha^3 + 16/15*alpha^2 + 8/15*alpha - 8/15)/(alpha^3 - alpha^2 + 17/30*alpha - 27/10)\n");
  const CliRun latex = run_gkt("formula " + scene_path("hcs_first_sonine.toml") + " --coefficient a2 --format latex");
  EXPECT_EQ(latex.out.rfind("\\frac{-\\frac{16}{15}\\alpha^{3}", 0), 0U) << latex.out;
  // A mixture scene has no closed forms: refused, not answered with the one-component gas's.
  const CliRun mixture = run_gkt("formula " + scene_path("mixture_hcs.toml") + " --coefficient cooling_rate");
  EXPECT_EQ(mixture.status, 2);
  EXPECT_NE(mixture.err.find(
                "model: gkt formula has closed forms for \"hard-spheres\" and \"smooth-inelastic\", got \"mixture\""),
            std::string::npos)
      << mixture.err;
  EXPECT_TRUE(mixture.out.empty());
  const CliRun hs =
      run_gkt("formula " + scene_path("hard_spheres_exact.toml") + " --coefficient shear_viscosity --order 2");
  EXPECT_EQ(hs.out, "205/202\n");
  for (const auto& [args, message] : std::vector<std::pair<std::string, std::string>>{
           {" --coefficient a3", "coefficient: no first-Sonine closed form for 'a3'"},
           {" --coefficient a2 --order 2", "--order: \"smooth-inelastic\" has closed forms at order 1 only"},
           {" --coefficient viscosity", "--coefficient: unknown coefficient 'viscosity'"},
           {" --coefficient a2 --set 'dimension=[2,3]'", "dimension: a formula needs a single value"},
           {" --coefficient a2 --format mathml", "--format"},
           {" --coefficient shear_viscosity --set packing_fraction=0.2 --set 'scheme=\"modified\"'",
            "scheme: dense-gas closed forms exist for \"standard\" only"}}) {
    const CliRun bad = run_gkt("formula " + scene_path("hcs_first_sonine.toml") + args);
    EXPECT_EQ(bad.status, 2) << args;
    EXPECT_NE(bad.err.find(message), std::string::npos) << bad.err;
    EXPECT_TRUE(bad.out.empty());
  }
}

TEST(CliEvolve, StatisticsAndBadInput) {
  const CliRun r = run_gkt("evolve " + scene_path("cooling_constant_alpha.toml"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("cvode: steps="), std::string::npos);
  const fs::path dir = fs::temp_directory_path() / ("gkt_evolve_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string out = (dir / "series.csv").string();
  for (const auto& [args, message] : std::vector<std::pair<std::string, std::string>>{
           {" --set t_end=0", "t_end: must be a number > 0"},
           {" --set rtol=0", "rtol: must be a number in (0, 0.1]"},
           {" --set atol=-1", "atol: must be a number in (0, 1]"},
           {" --set a2=0.9", "a2: must be a number in [-0.5333333333333333, 0.8]"},
           {" --set temperature=-2", "temperature: must be a number > 0"},
           {" --set alpha=1.2", "alpha: must be a number in (0, 1]"},
           {" --set points=0", "points: must be an integer in [1, 1000000]"},
           {" --set order=13", "order: must be an integer in [1, 12]"},
           {" --set 'times=[2, 1]'", "times: must be a non-empty list of increasing times > 0"},
           {" --set delta=0.1", "delta: unknown key for gkt evolve"},
           {" --set 'model=\"hard-spheres\"'",
            "model: gkt evolve supports \"aggregation\", \"mixture\", \"rough\", \"rough-walton\", "
            "\"smooth-inelastic\""}}) {
    const CliRun bad = run_gkt("evolve " + scene_path("cooling_constant_alpha.toml") + " --output " + out + args);
    EXPECT_EQ(bad.status, 2) << args << ": " << bad.err;
    EXPECT_NE(bad.err.find(message), std::string::npos) << bad.err;
    EXPECT_EQ(bad.err.find('\n'), bad.err.size() - 1) << bad.err;
    EXPECT_FALSE(fs::exists(out)) << args;
  }
  fs::remove_all(dir);
}

// `packing_fraction` in gkt evolve (theory.md §12.4): once relaxed, the dense trajectory's ζ*, a2, η*,
// κ*, μ* and critical sizes equal `gkt table` / `gkt stability` for the Enskog gas at the same order
// (to the integration tolerance); a φ beyond the dimension's range is refused naming the key.
TEST(CliEvolve, DenseGas) {
  const std::string dense = " --set packing_fraction=0.25";
  const std::string names =
      " --set 'coefficients=[\"shear_viscosity\", \"thermal_conductivity\", "
      "\"density_heat_coefficient\", \"critical_wavenumber_shear\"]'";
  const CliRun r = run_gkt("evolve " + scene_path("cooling_constant_alpha.toml") + dense + names);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = parse_csv(r.out);
  ASSERT_EQ(rows[0].size(), 11U);
  ASSERT_EQ(rows[0][6], "cooling_rate");
  const CliRun t =
      run_gkt("table " + scene_path("navier_stokes_converged.toml") + " --set alpha=0.8 --set order=3" + dense +
              " --set 'coefficients=[\"cooling_rate\", \"a2\", \"shear_viscosity\", "
              "\"thermal_conductivity\", \"density_heat_coefficient\", "
              "\"critical_wavenumber_shear\"]'");
  ASSERT_EQ(t.status, 0) << t.err;
  const auto reference = parse_csv(t.out);
  std::size_t first = 0;  // the reference's first coefficient column (after any swept keys)
  while (reference[0][first] != "cooling_rate") ++first;
  const auto& last = rows.back();
  EXPECT_NEAR(std::stod(last[6]), std::stod(reference[1][first]), 1e-9);
  EXPECT_NEAR(std::stod(last[3]), std::stod(reference[1][first + 1]), 1e-9);
  for (std::size_t c = 0; c < 4; ++c)
    EXPECT_NEAR(std::stod(last[7 + c]), std::stod(reference[1][first + 2 + c]), 1e-8) << rows[0][7 + c];
  const CliRun bad = run_gkt("evolve " + scene_path("cooling_constant_alpha.toml") + " --set packing_fraction=0.6");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("packing_fraction: must be a number in [0, 0.5] for dimension = 3, got 0.6"),
            std::string::npos)
      << bad.err;
}

// `gkt evolve` for a mixture (theory.md §16.7): from equipartition the last row's T_i/T, a2,i and ζ*
// are `gkt table`'s HCS in the same scheme (to the integration tolerance, 1e-9 at rtol = 1e-10), T
// falls; bad input exits 2 with one line naming the key.
TEST(CliEvolve, Mixture) {
  const fs::path scene = fs::temp_directory_path() / ("gkt_mixture_evolve_" + std::to_string(::getpid()) + ".toml");
  std::ofstream(scene) << "model = \"mixture\"\nalpha = 0.8\npacking_fraction = 0.1\nt_end = 2000\npoints = 4\n"
                          "rtol = 1e-10\natol = 1e-14\n"
                          "[[species]]\nmass = 1\ndiameter = 1\nfraction = 0.5\n"
                          "[[species]]\nmass = 4\ndiameter = 1.2\nfraction = 0.5\n";
  const CliRun r = run_gkt("evolve " + scene.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("cvode: steps="), std::string::npos);
  const auto rows = parse_csv(r.out);
  ASSERT_EQ(rows.size(), 5U);
  const std::vector<std::string> columns{"time",         "temperature",  "temperature_ratio_1", "temperature_ratio_2",
                                         "a2_species_1", "a2_species_2", "cooling_rate"};
  EXPECT_EQ(rows[0], columns);
  // The HCS of `gkt table`: a scene without the evolve keys.
  const fs::path hcs = fs::temp_directory_path() / ("gkt_mixture_hcs_" + std::to_string(::getpid()) + ".toml");
  std::ofstream(hcs) << "model = \"mixture\"\nalpha = 0.8\npacking_fraction = 0.1\norder = 1\n"
                        "coefficients = [\"temperature_ratio_1\", \"temperature_ratio_2\", \"a2_species_1\", "
                        "\"a2_species_2\", \"cooling_rate\"]\n"
                        "[[species]]\nmass = 1\ndiameter = 1\nfraction = 0.5\n"
                        "[[species]]\nmass = 4\ndiameter = 1.2\nfraction = 0.5\n";
  const CliRun t = run_gkt("table " + hcs.string());
  ASSERT_EQ(t.status, 0) << t.err;
  const auto reference = parse_csv(t.out);
  for (std::size_t c = 0; c < 5; ++c)
    EXPECT_NEAR(std::stod(rows.back()[2 + c]), std::stod(reference[1][c]), 1e-9) << columns[2 + c];
  EXPECT_GT(std::abs(std::stod(rows[1][2]) - std::stod(reference[1][0])), 1e-3);  // not relaxed at τ = 0.01
  EXPECT_LT(std::stod(rows.back()[1]), 1e-3);
  // Given initial ratios (Σ x_i γ_i = 1) relax to the same state; the Maxwellian scheme has no a2 columns.
  const CliRun g = run_gkt("evolve " + scene.string() +
                           " --set temperature_ratio_1=1.5 --set temperature_ratio_2=0.5 --set hcs='\"maxwellian\"'");
  ASSERT_EQ(g.status, 0) << g.err;
  EXPECT_EQ(parse_csv(g.out)[0].size(), 5U);
  for (const auto& [args, message] : std::vector<std::pair<std::string, std::string>>{
           {" --set temperature_ratio_1=1.5", "temperature_ratio_i: the initial ratios T_i/T must satisfy"},
           {" --set temperature_ratio_3=1", "temperature_ratio_3: the scene has 2 species"},
           {" --set a2_species_1=0.9", "a2_species_1: must be a number in"},
           {" --set hcs_order=9", "hcs_order: must be an integer in [2, 5]"},
           {" --set 'coefficients=[\"shear_viscosity\"]'",
            "coefficients: unknown key for gkt evolve with model \"mixture\""},
           {" --set hcs='\"maxwellian\"' --set a2_species_2=0.1", "a2_species_2: hcs = \"maxwellian\" carries no"},
           {" --set order=2", "order: unknown key for gkt evolve with model \"mixture\""}}) {
    const CliRun bad = run_gkt("evolve " + scene.string() + args);
    EXPECT_EQ(bad.status, 2) << args << ": " << bad.err;
    EXPECT_NE(bad.err.find(message), std::string::npos) << args << ": " << bad.err;
    EXPECT_EQ(bad.err.find('\n'), bad.err.size() - 1) << bad.err;
  }
  fs::remove(scene);
  fs::remove(hcs);
}

// Transport coefficients along a trajectory: once the cumulants have relaxed, η*, κ*, μ* about
// the instantaneous a(τ) equal `gkt table` at the same order about the stationary HCS (to the
// integration tolerance); along a viscoelastic trajectory η* − 1 and μ* are both ∝ δ'(τ), so
// their ratio is η̃1/μ̃1 = (359/1920)/(19/40) at every time.
TEST(CliEvolve, TransportAlongTrajectory) {
  const std::string names =
      " --set 'coefficients=[\"shear_viscosity\", \"thermal_conductivity\", "
      "\"density_heat_coefficient\"]'";
  const CliRun r = run_gkt("evolve " + scene_path("cooling_constant_alpha.toml") + names);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = parse_csv(r.out);
  const CliRun hcs =
      run_gkt("table " + scene_path("navier_stokes_converged.toml") + " --set alpha=0.8 --set order=3" + names);
  ASSERT_EQ(hcs.status, 0) << hcs.err;
  const auto reference = parse_csv(hcs.out);
  ASSERT_EQ(rows[0].size(), 10U);
  for (std::size_t c = 0; c < 3; ++c)
    EXPECT_NEAR(std::stod(rows.back()[7 + c]), std::stod(reference[1][c]), 1e-9) << rows[0][7 + c];
  // Viscoelastic: η*, κ*, μ* are the δ'-series of `gkt table` (order 1: η*(0) = κ*(0) = 1) at
  // δ'(τ) = δ (2T/T0)^{1/10}, δ = 0.1 in the scene.
  const CliRun v = run_gkt("evolve " + scene_path("cooling_viscoelastic.toml") + names);
  ASSERT_EQ(v.status, 0) << v.err;
  const CliRun vt = run_gkt("table " + scene_path("viscoelastic_constants.toml"));
  ASSERT_EQ(vt.status, 0) << vt.err;
  const auto vr = parse_csv(v.out), series = parse_csv(vt.out);
  auto column = [&](const std::string& name) {
    const auto it = std::find(series[0].begin(), series[0].end(), name);
    EXPECT_NE(it, series[0].end()) << name;
    return std::stod(series[1][static_cast<std::size_t>(it - series[0].begin())]);
  };
  ASSERT_EQ(vr[0][5], "shear_viscosity");
  for (std::size_t i = 1; i < vr.size(); ++i) {
    const double dp = 0.1 * std::pow(2 * std::stod(vr[i][2]), 0.1);
    std::size_t c = 0;
    for (const std::string name : {"shear_viscosity", "thermal_conductivity", "density_heat_coefficient"}) {
      double expected = name == "density_heat_coefficient" ? 0.0 : 1.0;
      for (int j = 3; j >= 1; --j) expected += column(name + "_" + std::to_string(j)) * std::pow(dp, j);
      EXPECT_NEAR(std::stod(vr[i][5 + c]), expected, 1e-12) << name << " row " << i;
      ++c;
    }
  }
  // Time-dependent critical size: constant α relaxes to `gkt stability` at the same order; for
  // viscoelastic grains k⊥c* = √(ζ*/η*) ∝ δ'^{1/2} ∝ T^{1/20} at late times, so L_c* ∝ T^{−1/20}
  // (∝ t^{1/12} with T ∝ t^{−5/3}): the log-slope over the last three decades of T is −1/20 within 5 %.
  const std::string critical = " --set 'coefficients=[\"critical_wavenumber_shear\", \"critical_length\"]'";
  const CliRun c = run_gkt("evolve " + scene_path("cooling_constant_alpha.toml") + critical);
  ASSERT_EQ(c.status, 0) << c.err;
  const CliRun s =
      run_gkt("stability " + scene_path("hcs_stability.toml") + " --set alpha=0.8 --set order=3" + critical);
  ASSERT_EQ(s.status, 0) << s.err;
  const auto crows = parse_csv(c.out), srows = parse_csv(s.out);
  EXPECT_NEAR(std::stod(crows.back()[7]), std::stod(srows[1][0]), 1e-9);
  EXPECT_NEAR(std::stod(crows.back()[8]), std::stod(srows[1][1]), 1e-7);
  const CliRun vc = run_gkt("evolve " + scene_path("cooling_viscoelastic.toml") + critical);
  ASSERT_EQ(vc.status, 0) << vc.err;
  const auto vcr = parse_csv(vc.out);
  const std::size_t length = vcr[0].size() - 1;
  ASSERT_EQ(vcr[0][length], "critical_length");
  const auto& late = vcr.back();
  std::size_t earlier = vcr.size() - 1;
  while (earlier > 1 && std::stod(vcr[earlier][2]) < 1e3 * std::stod(late[2])) --earlier;
  const double slope = std::log(std::stod(late[length]) / std::stod(vcr[earlier][length])) /
                       std::log(std::stod(late[2]) / std::stod(vcr[earlier][2]));
  EXPECT_NEAR(slope, -1.0 / 20, 0.05 / 20) << "rows " << earlier << ", " << vcr.size() - 1;
  // The heat mode of viscoelastic grains: k∥c*² (κ* − μ*)/ζ* = (4/5)(1 − λ_T), λ_T = ∂ln ζ/∂ln T →
  // 3/5 at late times (δ' ≈ 0.012: λ_T = 0.598), i.e. 0.32 — not the 0.4 of constant α (14.6).
  const CliRun vh = run_gkt("evolve " + scene_path("cooling_viscoelastic.toml") +
                            " --set 'coefficients=[\"thermal_conductivity\", \"density_heat_coefficient\", "
                            "\"critical_wavenumber_heat\"]'");
  ASSERT_EQ(vh.status, 0) << vh.err;
  const auto vh_rows = parse_csv(vh.out);
  const auto& last = vh_rows.back();
  const double kh = std::stod(last[7]);
  EXPECT_NEAR(kh * kh * (std::stod(last[5]) - std::stod(last[6])) / std::stod(last[4]), 0.32, 2e-3);
  const CliRun bad = run_gkt("evolve " + scene_path("cooling_viscoelastic.toml") +
                             " --set order=9 --set 'coefficients=[\"thermal_conductivity\"]'");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("order: viscoelastic transport along the trajectory needs an integer in [1, 8], got 9"),
            std::string::npos)
      << bad.err;
  EXPECT_TRUE(bad.out.empty());
}

// The constants themselves: golden file viscoelastic_constants.csv (tests/golden/manifest.tsv).
TEST(CliViscoelastic, StabilityAndBadInput) {
  // `gkt stability` at one δ': k⊥c*² = ζ*/η* and k∥c*² = (4/5)(1 − λ_T) ζ*/(κ* − μ*) with
  // λ_T(0.05) = 0.592, from the same series (order 3).
  const CliRun st = run_gkt("stability " + scene_path("viscoelastic_constants.toml") +
                            " --set delta_prime=0.05 --set order=3 --set 'coefficients=[\"cooling_rate\", "
                            "\"shear_viscosity\", \"thermal_conductivity\", \"density_heat_coefficient\", "
                            "\"critical_wavenumber_shear\", \"critical_wavenumber_heat\"]'");
  ASSERT_EQ(st.status, 0) << st.err;
  const auto sv = parse_csv(st.out)[1];
  const double zeta = std::stod(sv[0]), ks = std::stod(sv[4]), kh = std::stod(sv[5]);
  EXPECT_NEAR(ks * ks, zeta / std::stod(sv[1]), 1e-14);
  EXPECT_NEAR(kh * kh * (std::stod(sv[2]) - std::stod(sv[3])) / zeta, 0.8 * (1 - 0.592), 1e-3);
  const CliRun defaults = run_gkt("stability " + scene_path("viscoelastic_constants.toml") + " --set delta_prime=0.05");
  ASSERT_EQ(defaults.status, 0) << defaults.err;
  EXPECT_EQ(parse_csv(defaults.out)[0][0], "critical_wavenumber_shear");
  for (const auto& [command, message] : std::vector<std::pair<std::string, std::string>>{
           {"table " + scene_path("viscoelastic_constants.toml") + " --set c1=-1", "c1: must be a number in (0, 10]"},
           {"table " + scene_path("viscoelastic_constants.toml") + " --set order=7",
            "order: must be an integer in [1, 6], got 7"},
           {"table " + scene_path("viscoelastic_constants.toml") + " --exact",
            "--exact: a requested coefficient is not"},
           {"stability " + scene_path("viscoelastic_constants.toml"),
            "delta_prime: required for 'critical_wavenumber_shear' (a number in [0, 0.3])"},
           {"stability " + scene_path("viscoelastic_constants.toml") + " --set delta_prime=0.4",
            "delta_prime: must be a number in [0, 0.3], got 0.4"},
           {"evolve " + scene_path("cooling_viscoelastic.toml") + " --set delta=0.5",
            "delta: must be a number in [0, 0.3]"},
           {"evolve " + scene_path("cooling_viscoelastic.toml") + " --set alpha=0.9",
            "alpha: unknown key for gkt evolve"},
           {"evolve " + scene_path("cooling_viscoelastic.toml") + " --set dimension=2",
            "dimension: \"viscoelastic\" is three-dimensional"}}) {
    const CliRun bad = run_gkt(command);
    EXPECT_EQ(bad.status, 2) << command << ": " << bad.err;
    EXPECT_NE(bad.err.find(message), std::string::npos) << bad.err;
    EXPECT_TRUE(bad.out.empty());
  }
}

// The rough model (docs/theory.md §19; golden file rough_hcs.csv in tests/golden/manifest.tsv): the β = −1 limit
// against the smooth-inelastic model's first Sonine a2 and cooling rate, and bad input.
TEST(CliRough, SmoothLimitAndBadInput) {
  const CliRun rough = run_gkt("table " + scene_path("rough_hcs.toml") +
                               " --set beta=-1 --set 'coefficients=[\"cooling_rate\", \"a20\", "
                               "\"rotational_temperature_ratio\"]'");
  const CliRun smooth = run_gkt("table " + scene_path("hcs_first_sonine.toml"));  // the same alphas
  ASSERT_EQ(rough.status, 0) << rough.err;
  ASSERT_EQ(smooth.status, 0) << smooth.err;
  const auto rt = parse_csv(rough.out), st = parse_csv(smooth.out);
  ASSERT_EQ(rt.size(), st.size());
  for (std::size_t row = 1; row < rt.size(); ++row) {
    EXPECT_NEAR(std::stod(rt[row][1]), std::stod(st[row][2]), 1e-14);  // cooling_rate
    EXPECT_NEAR(std::stod(rt[row][2]), std::stod(st[row][1]), 1e-14);  // a20 = a2
    EXPECT_EQ(rt[row][3], "nan");                                      // no rotational cooling state at beta = -1
  }
  for (const auto& [set, message] : std::vector<std::pair<std::string, std::string>>{
           {"beta=1.5", "beta: must be a number in [-1, 1], got 1.5"},
           {"beta=-1.25", "beta: must be a number in [-1, 1], got -1.25"},
           {"moment_of_inertia=0", "moment_of_inertia: must be a number in (0, 1], got 0"},
           {"moment_of_inertia=1.5", "moment_of_inertia: must be a number in (0, 1], got 1.5"},
           {"alpha=0", "alpha: must be a number in (0, 1], got 0"},
           {"dimension=4", "dimension: must be 2 or 3, got 4"},
           // Order N > 1 exists for the HCS (§19.14) and Navier-Stokes columns (§19.16); the scene asks for C too.
           {"order=2 --set 'hcs=\"maxwellian\"'", "hcs: \"maxwellian\" is a first approximation"},
           {"order=9", "order: must be an integer in [1, 8], got 9"},
           {"dimension=2", "coefficients: orientation_correlation needs dimension = 3"},
           {"'hcs=\"quadratic\"'", "hcs: must be one of"}}) {
    const CliRun bad = run_gkt("table " + scene_path("rough_hcs.toml") + " --set " + set);
    EXPECT_EQ(bad.status, 2) << set << ": " << bad.err;
    EXPECT_NE(bad.err.find(message), std::string::npos) << bad.err;
    EXPECT_TRUE(bad.out.empty());
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  }
}

// The rough binary mixture through two [[species]] tables (theory.md §19.17, §19.26; golden files
// rough_mixture_hcs*.csv; the limits in tests/test_rough_mixture_model.cpp): the CLI's values at the two states of
// the test-side DSMC (tests/test_rough_mixture_cooling_state.cpp, AgainstDsmc: 600 + 1400 spheres, seed 20261202,
// its means ± batch errors copied from theory.md §19.17) within that test's tolerances (γ 0.01, θ 4 %: the
// Maxwellian approximation's own error), and bad input: exit 2, one line naming the key, no output.
TEST(CliRough, BinaryMixture) {
  const CliRun run =
      run_gkt("table " + scene_path("rough_mixture_hcs.toml") + " --set 'alpha=[0.9]' --set 'beta=[0.5, 1]'");
  ASSERT_EQ(run.status, 0) << run.err;
  const auto t = parse_csv(run.out);
  ASSERT_EQ(t.size(), 3u);
  ASSERT_EQ(t[0][2], "temperature_ratio_1");
  // DSMC (γ_1, γ_2, θ_1, θ_2) at β = 0.5 and β = 1 (α = 0.9 on all pairs).
  const std::array<std::array<double, 4>, 2> dsmc{std::array<double, 4>{0.9146, 1.0366, 0.8057, 0.9577},
                                                  std::array<double, 4>{0.9835, 1.0071, 1.1114, 1.1136}};
  for (std::size_t row = 0; row < 2; ++row) {
    for (std::size_t k = 0; k < 2; ++k) EXPECT_NEAR(std::stod(t[row + 1][2 + k]), dsmc[row][k], 0.01) << row;
    for (std::size_t k = 2; k < 4; ++k) EXPECT_NEAR(std::stod(t[row + 1][2 + k]) / dsmc[row][k], 1.0, 0.04) << row;
    EXPECT_NEAR(0.3 * std::stod(t[row + 1][2]) + 0.7 * std::stod(t[row + 1][3]), 1.0, 1e-14);
  }
  for (const auto& [set, message] : std::vector<std::pair<std::string, std::string>>{
           {"fraction_2=0.6", "fraction: the mole fractions x_1 + x_2 must sum to 1, got 0.9"},
           {"mass_1=-1", "mass_1: must be a number in (0, 1000000000], got -1"},
           {"beta_1_2=1.5", "beta_1_2: must be a number in [-1, 1], got 1.5"},
           {"'beta=[[0.5, 0], [0.1, 0.5]]'", "beta: the restitution matrix must be symmetric"},
           {"moment_of_inertia_2=0", "moment_of_inertia_2: must be a number in (0, 1], got 0"},
           {"moment_of_inertia_1=1.5", "moment_of_inertia_1: must be a number in (0, 1], got 1.5"},
           {"'hcs=\"nonlinear\"'",
            "hcs: the rough binary mixture (species = 2) has the Maxwellian and the first-Sonine linear HCS"},
           {"order=2", "order: must be exactly 1, got 2"},
           {"'hcs=\"linear\"' --set order=2", "order: must be exactly 1, got 2"},
           {"'coefficients=[\"a20_1\"]'", "coefficients: a20_1 needs the first-Sonine HCS"},
           {"'hcs=\"linear\"' --set alpha=0.5 --set beta=-0.5", "hcs: the first-Sonine linear HCS of this rough"},
           {"'coefficients=[\"a20\"]'", "coefficients: unknown coefficient 'a20'"}}) {
    const CliRun bad = run_gkt("table " + scene_path("rough_mixture_hcs.toml") + " --set " + set);
    EXPECT_EQ(bad.status, 2) << set << ": " << bad.err;
    EXPECT_NE(bad.err.find(message), std::string::npos) << bad.err;
    EXPECT_TRUE(bad.out.empty());
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  }
  // Per-species keys without the tables.
  const CliRun one = run_gkt("table " + scene_path("rough_hcs.toml") + " --set mass_1=2");
  EXPECT_EQ(one.status, 2) << one.err;
  EXPECT_NE(one.err.find("mass_1: per-species keys need species = 2"), std::string::npos) << one.err;
  EXPECT_TRUE(one.out.empty());
}

// hcs = "linear" for the rough binary (theory.md §19.30): the cumulant columns a20_i, a02_i, a11_i join the HCS
// columns, and the values lie within 4σ of the test-side DSMC of that section (α = 0.9, β = 0.5, 3000 spheres:
// θ_1 0.7971 ± 0.0050, θ_2 0.9632 ± 0.0042, a02_1 0.1174 ± 0.0098, a02_2 0.0889 ± 0.0049).
TEST(CliRough, BinaryMixtureFirstSonine) {
  const CliRun run = run_gkt("table " + scene_path("rough_mixture_hcs.toml") +
                             " --set 'alpha=[0.9]' --set 'beta=[0.5]' --set 'hcs=\"linear\"'");
  ASSERT_EQ(run.status, 0) << run.err;
  const auto t = parse_csv(run.out);
  ASSERT_EQ(t.size(), 2u);
  const std::vector<std::string> head{"alpha",
                                      "beta",
                                      "temperature_ratio_1",
                                      "temperature_ratio_2",
                                      "rotational_temperature_ratio_1",
                                      "rotational_temperature_ratio_2",
                                      "cooling_rate",
                                      "a20_1",
                                      "a02_1",
                                      "a11_1",
                                      "a20_2",
                                      "a02_2",
                                      "a11_2"};
  for (std::size_t k = 0; k < head.size(); ++k) ASSERT_EQ(t[0][k], head[k]);
  EXPECT_NEAR(std::stod(t[1][4]), 0.7971, 4 * 0.0050);
  EXPECT_NEAR(std::stod(t[1][5]), 0.9632, 4 * 0.0042);
  EXPECT_NEAR(std::stod(t[1][8]), 0.1174, 4 * 0.0098);
  EXPECT_NEAR(std::stod(t[1][11]), 0.0889, 4 * 0.0049);
}

// The cumulant reference of the rough Navier-Stokes columns (theory.md §19.16, conventions.md `reference_state`,
// `hcs_order`): with the keys order 1 comes from the Sonine solver about the HCS (an error estimate, another value);
// bad combinations exit 2 with one line naming the key.
TEST(CliRough, CumulantReferenceKeys) {
  const std::string base = "table " + scene_path("rough_hcs.toml") +
                           " --set 'alpha=[0.9]' --set 'coefficients=[\"shear_viscosity\", \"thermal_conductivity\"]'";
  const CliRun plain = run_gkt(base);
  const CliRun reference = run_gkt(base + " --set 'reference_state=\"hcs\"' --set 'hcs=\"nonlinear\"'");
  ASSERT_EQ(plain.status, 0) << plain.err;
  ASSERT_EQ(reference.status, 0) << reference.err;
  const auto p = parse_csv(plain.out), r = parse_csv(reference.out);
  ASSERT_EQ(p.size(), 2u);
  ASSERT_EQ(r.size(), 2u);
  ASSERT_EQ(p[0][2], "thermal_conductivity");  // alpha, shear_viscosity, thermal_conductivity, errors, order
  EXPECT_EQ(p[1][3], "nan");                   // the first approximation: no error estimate
  EXPECT_NE(r[1][3], "nan");                   // about the HCS: the Sonine solver's error (6.1)
  EXPECT_GT(std::abs(std::stod(r[1][2]) - std::stod(p[1][2])), 1e-3);  // κ*: the cumulants move it
  for (const auto& [set, message] : std::vector<std::pair<std::string, std::string>>{
           {"hcs_order=3", "hcs_order: needs reference_state = \"hcs\""},
           {"'reference_state=\"hcs\"' --set 'hcs=\"maxwellian\"'", "reference_state: \"hcs\" needs hcs ="},
           {"'reference_state=\"hcs\"' --set hcs_order=5", "hcs_order: must be an integer in [2, 4], got 5"},
           {"'reference_state=\"hcs\"' --set order=5", "order: shear_viscosity of model rough with reference_state"},
           {"'reference_state=\"sonine\"'", "reference_state: must be one of"}}) {
    const CliRun bad = run_gkt(base + " --set " + set);
    EXPECT_EQ(bad.status, 2) << set << ": " << bad.err;
    EXPECT_NE(bad.err.find(message), std::string::npos) << bad.err;
    EXPECT_TRUE(bad.out.empty());
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  }
}

// trial_space (theory.md §19.21, §19.22, conventions.md): the default is the product space; "aligned" adds the
// aligned-spin families (η*, κ* rise at (0.9, 0.5)), "full" also the chiral ones (κ* falls back below the aligned
// value); bad values and combinations exit 2 with one line naming the key.
TEST(CliRough, TrialSpaceKey) {
  const std::string base = "table " + scene_path("rough_hcs.toml") +
                           " --set 'alpha=[0.9]' --set order=2 --set "
                           "'coefficients=[\"shear_viscosity\", \"thermal_conductivity\"]'";
  const CliRun plain = run_gkt(base);
  const CliRun products = run_gkt(base + " --set 'trial_space=\"products\"'");
  const CliRun aligned = run_gkt(base + " --set 'trial_space=\"aligned\"'");
  const CliRun full = run_gkt(base + " --set 'trial_space=\"full\"'");
  for (const CliRun* r : {&plain, &products, &aligned, &full}) ASSERT_EQ(r->status, 0) << r->err;
  EXPECT_EQ(plain.out, products.out);
  const auto p = parse_csv(products.out), a = parse_csv(aligned.out), f = parse_csv(full.out);
  ASSERT_EQ(p.size(), 2u);
  ASSERT_EQ(a.size(), 2u);
  ASSERT_EQ(f.size(), 2u);
  EXPECT_GT(std::stod(a[1][1]), std::stod(p[1][1]) + 0.01);  // η*: +2 % with the aligned families
  EXPECT_GT(std::stod(a[1][2]), std::stod(p[1][2]) + 0.05);  // κ*: +7 %
  EXPECT_LT(std::stod(f[1][2]), std::stod(a[1][2]) - 0.03);  // the chiral families lower κ*
  for (const auto& [set, message] : std::vector<std::pair<std::string, std::string>>{
           {"'trial_space=\"chiral\"'", "trial_space: must be one of"},
           {"'trial_space=\"aligned\"' --set dimension=2", "trial_space: \"aligned\" needs dimension = 3"},
           {"'trial_space=\"full\"' --set order=1", "trial_space: \"full\" needs a Sonine order"},
           {"'trial_space=\"full\"' --set 'reference_state=\"hcs\"'", "is built about Maxwellians only"},
           // its members follow the order (theory.md (19.155)): orders past 4 would take minutes per state
           {"'trial_space=\"full\"' --set order=5", "order: trial_space = \"full\" takes orders 1 to 4"},
           // The stability values at order 1 are the first approximation's too: refused, not silently products.
           {"'trial_space=\"full\"' --set order=1 --set 'coefficients=[\"critical_length\"]'",
            "trial_space: \"full\" needs a Sonine order"},
           {"'trial_space=\"aligned\"' --set order=1 --set 'coefficients=[\"critical_wavenumber_heat\"]'",
            "trial_space: \"aligned\" needs a Sonine order"},
           // Keys that shape only the Navier-Stokes and stability columns: refused, not silently ignored, in a table
           // of HCS columns alone.
           {"'trial_space=\"full\"' --set 'coefficients=[\"rotational_temperature_ratio\", \"cooling_rate\"]'",
            "trial_space: \"full\" applies to the Navier-Stokes columns"},
           {"'reference_state=\"hcs\"' --set 'coefficients=[\"cooling_rate\", \"a20\"]'",
            "reference_state: \"hcs\" applies to the Navier-Stokes columns"},
           // The fourth-field closure shapes the stability columns alone.
           {"'rotational_temperature_closure=\"field\"' --set 'coefficients=[\"shear_viscosity\"]' --set order=1",
            "rotational_temperature_closure: \"field\" applies to the stability columns"}}) {
    const CliRun bad = run_gkt(base + " --set " + set);
    EXPECT_EQ(bad.status, 2) << set << ": " << bad.err;
    EXPECT_NE(bad.err.find(message), std::string::npos) << bad.err;
    EXPECT_TRUE(bad.out.empty());
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  }
}

// With the default product trial space a rough Navier-Stokes or stability column asked for at order >= 2 or to a
// tolerance carries one warning per table: its _error is the Sonine truncation in that space only, and the aligned
// and chiral families (theory.md §19.21, §19.22) move the values by percents (conventions.md, "Warnings"). None with
// trial_space = "full", none at order 1 (error nan), none for the HCS columns alone; stdout is unchanged.
TEST(CliRough, TrialSpaceCaveatWarning) {
  const std::string base = "table " + scene_path("rough_hcs.toml") + " --set 'alpha=[0.9, 0.7]'";
  const std::string ns = " --set 'coefficients=[\"shear_viscosity\", \"critical_length\"]'";
  const std::string caveat = "covers the Sonine truncation in the product trial space only";
  const auto warnings = [&caveat](const std::string& err) {
    std::size_t n = 0;
    for (auto at = err.find(caveat); at != std::string::npos; at = err.find(caveat, at + 1)) ++n;
    return n;
  };
  const CliRun order2 = run_gkt(base + ns + " --set order=2");
  const CliRun products2 = run_gkt(base + ns + " --set order=2 --set 'trial_space=\"products\"'");
  const CliRun tolerance = run_gkt(base + ns + " --set tolerance=1e-3");
  const CliRun swept = run_gkt(base + ns + " --set 'order=[1, 2]'");
  // One state for the full space: its members follow the order (tables to 4 with M = 2, theory.md (19.155)).
  const CliRun full = run_gkt(base + ns + " --set 'alpha=[0.9]' --set order=2 --set 'trial_space=\"full\"'");
  const CliRun order1 = run_gkt(base + ns + " --set order=1");
  const CliRun hcs_only =
      run_gkt(base + " --set order=2 --set 'coefficients=[\"cooling_rate\", \"a20\"]' --set 'hcs=\"linear\"'");
  const CliRun stability = run_gkt("stability " + scene_path("rough_hcs.toml") + " --set 'alpha=[0.9]' --set order=2");
  for (const CliRun* r : {&order2, &products2, &tolerance, &swept, &full, &order1, &hcs_only, &stability})
    ASSERT_EQ(r->status, 0) << r->err;
  EXPECT_EQ(warnings(order2.err), 1u) << order2.err;  // one per table, not one per row
  EXPECT_NE(order2.err.find("trial_space = \"full\" adds the aligned and chiral families"), std::string::npos);
  EXPECT_NE(order2.err.find("shear_viscosity, critical_length"), std::string::npos) << order2.err;
  EXPECT_EQ(warnings(products2.err), 1u) << products2.err;
  EXPECT_EQ(products2.out, order2.out);  // the warning changes no value
  EXPECT_EQ(warnings(tolerance.err), 1u) << tolerance.err;
  EXPECT_EQ(warnings(swept.err), 1u) << swept.err;
  EXPECT_EQ(warnings(stability.err), 1u) << stability.err;
  EXPECT_EQ(warnings(full.err), 0u) << full.err;
  EXPECT_EQ(warnings(order1.err), 0u) << order1.err;
  EXPECT_EQ(warnings(hcs_only.err), 0u) << hcs_only.err;
}

// Order N > 1 of the rough Navier-Stokes columns (theory.md §19.16): the order-2 error column is (6.3) from the
// order-2 … 5 values printed by the CLI itself ((6.1) unless the changes flip sign; then order 5 tells an
// alternation from a turn); order 1 stays the first approximation with a nan error.
TEST(CliRough, HigherSonineOrderAndItsError) {
  const std::string base = "table " + scene_path("rough_hcs.toml") +
                           " --set alpha=0.9 --set 'coefficients=[\"shear_viscosity\", \"bulk_viscosity\"]'";
  std::map<int, std::vector<std::string>> row;
  for (int n = 1; n <= 5; ++n) {
    const CliRun run = run_gkt(base + " --set order=" + std::to_string(n));
    ASSERT_EQ(run.status, 0) << run.err;
    const auto t = parse_csv(run.out);
    ASSERT_EQ(t.size(), 2u);
    row[n] = t[1];
  }
  EXPECT_EQ(row[1][2], "nan");
  for (std::size_t c = 0; c < 2; ++c) {
    const double v2 = std::stod(row[2][c]), v3 = std::stod(row[3][c]), v4 = std::stod(row[4][c]);
    const double v5 = std::stod(row[5][c]);
    // (6.1): the geometric tail with a 25 % margin, or both corrections when they do not shrink; (6.3): where
    // the changes flip sign and the third keeps the second's sign, Δ1 plus the monotone tail after the turn.
    const double s1 = v3 - v2, s2 = v4 - v3, s3 = v5 - v4;
    const double d1 = std::abs(s1), d2 = std::abs(s2), ratio = s2 / s1;
    const bool turned = s1 * s2 < 0 && s2 * s3 > 0;
    const double q = s3 / s2;
    const double expected = turned ? (q < 1 ? 1.25 * (d1 + d2 / (1 - q)) : d1 + d2 + std::abs(s3))
                                   : (std::abs(ratio) < 1 ? 1.25 * d1 / (1 - ratio) : d1 + d2);
    EXPECT_NEAR(std::stod(row[2][2 + c]), expected, 0.01 * expected) << c;
    EXPECT_NE(row[2][c], row[1][c]);
    EXPECT_EQ(row[2].back(), "2");
  }
}

// A tolerance the rough Navier–Stokes sequences cannot meet because they wander (3D (α, β) = (0.7, 0.5), κ = 2/5:
// κ*, η_b*, ζ_U settle locally but later orders move by more than (6.3) claims): the row is written, the warning
// names the tolerance and says why — the window of theory.md (19.100)–(19.101) refuted the local estimate.
TEST(CliRough, ToleranceWarningSaysTheSequenceWanders) {
  const fs::path scene = fs::temp_directory_path() / ("gkt_rough_window_" + std::to_string(::getpid()) + ".toml");
  std::ofstream(scene) << "model = \"rough\"\ndimension = 3\nalpha = 0.7\nbeta = 0.5\nmoment_of_inertia = 0.4\n"
                          "tolerance = 1e-4\ncoefficients = [\"thermal_conductivity\", \"bulk_viscosity\", "
                          "\"cooling_rate_first_order\"]\n";
  const CliRun run = run_gkt("table " + scene.string() + " --quiet");
  fs::remove(scene);
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_EQ(parse_csv(run.out).size(), 2u);
  EXPECT_NE(run.err.find("tolerance 0.0001 not reached"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("error estimate widened"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("the sequence wanders"), std::string::npos) << run.err;
}

// The linear scheme's no-root region (theory.md §19.6): `hcs = "linear"` refuses it with one line naming the
// state and the region; `"linear-or-maxwellian"` gives the Maxwellian θ and nan cumulants there.
TEST(CliRough, LinearSchemeNoRootRegion) {
  const std::string state =
      " --set alpha=0.5 --set beta=0 --set 'coefficients=[\"rotational_temperature_ratio\", \"a20\"]'";
  const CliRun bad = run_gkt("table " + scene_path("rough_hcs.toml") + state);
  EXPECT_EQ(bad.status, 2) << bad.err;
  EXPECT_NE(bad.err.find("hcs: the linear scheme has no root at dimension = 3, alpha = 0.5, beta = 0, "
                         "moment_of_inertia = 0.4 (the strongly inelastic, weakly rough region"),
            std::string::npos)
      << bad.err;
  EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  EXPECT_TRUE(bad.out.empty());
  const CliRun fallback =
      run_gkt("table " + scene_path("rough_hcs.toml") + state + " --set 'hcs=\"linear-or-maxwellian\"'");
  const CliRun maxwellian = run_gkt("table " + scene_path("rough_hcs.toml") + state + " --set 'hcs=\"maxwellian\"'");
  ASSERT_EQ(fallback.status, 0) << fallback.err;
  ASSERT_EQ(maxwellian.status, 0) << maxwellian.err;
  const auto f = parse_csv(fallback.out), m = parse_csv(maxwellian.out);
  EXPECT_EQ(f[0][0], "rotational_temperature_ratio");
  EXPECT_EQ(f[1][0], m[1][0]);  // θ: the Maxwellian one
  EXPECT_EQ(f[1][1], "nan");    // no cumulants
}

// Higher Sonine orders of the rough HCS (theory.md §19.14): `order` (or `tolerance`) and hcs =
// "nonlinear" reach θ, ζ* and the cumulants with an error from the next order; order 1 "nonlinear"
// differs from the first-Sonine "linear" only by the products of cumulants; C beyond order 1 comes from the
// oriented HCS in either scheme (refused for the first approximations "maxwellian", "linear-or-maxwellian"), the
// HCS columns refuse an order above 3, with one line.
TEST(CliRough, SonineOrdersOfTheCoolingState) {
  const std::string hcs =
      " --set 'alpha=[0.9]' --set 'coefficients=[\"rotational_temperature_ratio\", \"a20\", \"a03\"]'";
  const CliRun first = run_gkt("table " + scene_path("rough_hcs.toml") + hcs);
  const CliRun second = run_gkt("table " + scene_path("rough_hcs.toml") + hcs + " --set order=2");
  const CliRun nonlinear = run_gkt("table " + scene_path("rough_hcs.toml") + hcs + " --set 'hcs=\"nonlinear\"'");
  ASSERT_EQ(first.status, 0) << first.err;
  ASSERT_EQ(second.status, 0) << second.err;
  ASSERT_EQ(nonlinear.status, 0) << nonlinear.err;
  const auto f = parse_csv(first.out), s = parse_csv(second.out), n = parse_csv(nonlinear.out);
  ASSERT_EQ(s[0].size(), 8U);  // alpha, three values, three errors, order
  EXPECT_EQ(s[0][4], "rotational_temperature_ratio_error");
  EXPECT_EQ(f[1][3], "0");  // a03 is truncated at first Sonine
  EXPECT_NE(s[1][3], "0");
  EXPECT_EQ(s[1][7], "2");
  EXPECT_NEAR(std::stod(s[1][1]), 0.85229, 2e-5);  // theory.md §19.14: the oriented ansatz in 3D (isotropic 0.85507)
  EXPECT_GT(std::abs(std::stod(s[1][1]) - std::stod(f[1][1])), 3e-4);
  EXPECT_LT(std::stod(s[1][4]), 3e-4);  // error |θ_3 − θ_2|
  EXPECT_NEAR(std::stod(n[1][1]), std::stod(f[1][1]), 2e-4);
  EXPECT_NE(n[1][1], f[1][1]);
  for (const auto& [set, message] : std::vector<std::pair<std::string, std::string>>{
           {"tolerance=1e-3 --set 'hcs=\"linear-or-maxwellian\"'",
            "hcs: \"linear-or-maxwellian\" is a first approximation"},
           {"order=4", "order: rotational_temperature_ratio of model rough takes orders 1 to 3, got 4"}}) {
    const CliRun bad = run_gkt("table " + scene_path("rough_hcs.toml") + " --set " + set);
    EXPECT_EQ(bad.status, 2) << set << ": " << bad.err;
    EXPECT_NE(bad.err.find(message), std::string::npos) << bad.err;
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  }
  // The orientation columns (theory.md §19.14): order 1 is the first approximation of §19.8 (C = 1/3 + b00/5,
  // b10 truncated), order 2 the oriented Sonine HCS (θ, C and b_pq of one solution, with errors); disks refused.
  const std::string orient =
      " --set 'alpha=[0.9]' --set 'coefficients=[\"orientation_correlation\", \"b00\", \"b10\"]'";
  const CliRun o1 = run_gkt("table " + scene_path("rough_hcs.toml") + orient);
  const CliRun o2 = run_gkt("table " + scene_path("rough_hcs.toml") + orient + " --set order=2");
  ASSERT_EQ(o1.status, 0) << o1.err;
  ASSERT_EQ(o2.status, 0) << o2.err;
  const auto r1 = parse_csv(o1.out), r2 = parse_csv(o2.out);
  EXPECT_NEAR(std::stod(r1[1][1]), 1.0 / 3 + std::stod(r1[1][2]) / 5, 1e-15);
  EXPECT_EQ(r1[1][3], "0");
  EXPECT_NEAR(std::stod(r2[1][1]), 0.32983, 2e-5);
  EXPECT_NEAR(std::stod(r2[1][2]), -0.01948, 2e-5);
  EXPECT_NE(r2[1][3], "0");
  EXPECT_LT(std::stod(r2[1][4]), 2e-3);  // error |C_3 − C_2|
  // The nonlinear scheme beyond order 1 is oriented too (theory.md §19.14): C and b00 within the products of the
  // cumulants of the linear values (0.32980, −0.01936 at order 2).
  const CliRun n2 =
      run_gkt("table " + scene_path("rough_hcs.toml") + orient + " --set order=2 --set 'hcs=\"nonlinear\"'");
  ASSERT_EQ(n2.status, 0) << n2.err;
  const auto rn = parse_csv(n2.out);
  EXPECT_NEAR(std::stod(rn[1][1]), std::stod(r2[1][1]), 1e-4);
  EXPECT_NE(rn[1][1], r2[1][1]);
  EXPECT_NEAR(std::stod(rn[1][2]), std::stod(r2[1][2]), 5e-4);
  EXPECT_LT(std::stod(rn[1][4]), 2e-3);  // error |C_3 − C_2|
  const CliRun disks = run_gkt("table " + scene_path("rough_hcs.toml") + orient + " --set dimension=2 --set order=2");
  EXPECT_EQ(disks.status, 2);
  EXPECT_NE(disks.err.find("coefficients: orientation_correlation needs dimension = 3"), std::string::npos)
      << disks.err;
  const CliRun maxwellian =
      run_gkt("table " + scene_path("rough_hcs.toml") + hcs + " --set order=2 --set 'hcs=\"maxwellian\"'");
  EXPECT_EQ(maxwellian.status, 2);
  EXPECT_NE(maxwellian.err.find("hcs: \"maxwellian\" is a first approximation"), std::string::npos) << maxwellian.err;
}

// `gkt evolve` with the rough model (theory.md §19.13; golden rough_evolve.csv): the last row equals
// `gkt table` with the same keys (θ, ζ*, a20, a02, a11 of the steady linear scheme), the Maxwellian
// scheme has no cumulant columns, and bad input is refused with one line (the linear scheme's no-root
// region by name, theory.md §19.6).
TEST(CliRoughEvolve, RelaxesToTheTableAndRefusesBadInput) {
  const CliRun evolve = run_gkt("evolve " + scene_path("rough_evolve.toml"));
  const CliRun table = run_gkt("table " + scene_path("rough_hcs.toml") +
                               " --set 'alpha=[0.9]' --set 'coefficients=[\"rotational_temperature_ratio\", "
                               "\"cooling_rate\", \"a20\", \"a02\", \"a11\"]'");
  ASSERT_EQ(evolve.status, 0) << evolve.err;
  ASSERT_EQ(table.status, 0) << table.err;
  EXPECT_NE(evolve.err.find("cvode: steps="), std::string::npos);
  const auto et = parse_csv(evolve.out), tt = parse_csv(table.out);
  ASSERT_EQ(et[0],
            (std::vector<std::string>{"time", "collisions", "translational_temperature", "rotational_temperature",
                                      "rotational_temperature_ratio", "cooling_rate", "a20", "a02", "a11"}));
  ASSERT_EQ(et.size(), 14u);
  for (std::size_t k = 0; k < 5; ++k)
    EXPECT_NEAR(std::stod(et.back()[4 + k]), std::stod(tt[1][1 + k]), 1e-8) << et[0][4 + k];
  EXPECT_LT(std::stod(et[1][4]), 0.02);  // starts cold: θ(0) = 0.01
  const CliRun maxwellian = run_gkt("evolve " + scene_path("rough_evolve.toml") + " --set 'hcs=\"maxwellian\"'");
  ASSERT_EQ(maxwellian.status, 0) << maxwellian.err;
  EXPECT_EQ(parse_csv(maxwellian.out)[0].size(), 6u);
  for (const auto& [set, message] : std::vector<std::pair<std::string, std::string>>{
           {"beta=1.5", "beta: must be a number in [-1, 1], got 1.5"},
           {"moment_of_inertia=0", "moment_of_inertia: must be a number in (0, 1], got 0"},
           {"rotational_temperature=0", "rotational_temperature: must be a number > 0"},
           {"translational_temperature=-1", "translational_temperature: must be a number > 0"},
           {"order=4", "order: must be an integer in [1, 3], got 4"},
           {"order=2 --set 'hcs=\"maxwellian\"'", "order: must be 1 with hcs = \"maxwellian\""},
           {"'hcs=\"cubic\"'", "hcs: must be one of"},
           {"dimension=2 --set 'hcs=\"nonlinear-oriented\"'", "hcs: \"nonlinear-oriented\" needs dimension = 3"},
           {"alpha=0.5 --set beta=0", "hcs: the linear scheme has no root at dimension = 3, alpha = 0.5, beta = 0"}}) {
    const CliRun bad = run_gkt("evolve " + scene_path("rough_evolve.toml") + " --set " + set);
    EXPECT_EQ(bad.status, 2) << set << ": " << bad.err;
    EXPECT_NE(bad.err.find(message), std::string::npos) << bad.err;
    EXPECT_TRUE(bad.out.empty());
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  }
  // The fallback is there only when asked for: the Maxwellian scheme's columns in the no-root region.
  const CliRun fallback = run_gkt("evolve " + scene_path("rough_evolve.toml") +
                                  " --set alpha=0.5 --set beta=0 --set 'hcs=\"linear-or-maxwellian\"'");
  ASSERT_EQ(fallback.status, 0) << fallback.err;
  EXPECT_EQ(parse_csv(fallback.out)[0].size(), 6u);
  // Walton friction (Maxwellian rates by quadrature): friction = 10⁶ is the constant-β gas with β = β0.
  const std::string walton_keys = " --set beta0=0.5 --set friction=1000000 --set points=5 --set rtol=1e-11";
  const CliRun walton = run_gkt("evolve " + scene_path("rough_walton_evolve.toml") + walton_keys);
  ASSERT_EQ(walton.status, 0) << walton.err;
  const auto wt = parse_csv(walton.out),
             mt = parse_csv(run_gkt("evolve " + scene_path("rough_evolve.toml") +
                                    " --set 'hcs=\"maxwellian\"' --set points=5 --set rtol=1e-11")
                                .out);
  ASSERT_EQ(wt.size(), mt.size());
  ASSERT_EQ(wt[0], mt[0]);
  for (std::size_t row = 1; row < wt.size(); ++row)
    EXPECT_NEAR(std::stod(wt[row][4]) / std::stod(mt[row][4]), 1, 1e-7) << "row " << row;
  const CliRun bad_friction =
      run_gkt("evolve " + scene_path("rough_walton_evolve.toml") + walton_keys + " --set friction=-1");
  EXPECT_EQ(bad_friction.status, 2);
  EXPECT_NE(bad_friction.err.find("friction: must be a number in [0, 1000000], got -1"), std::string::npos)
      << bad_friction.err;
}

// Initial cumulants of the rough linear scheme (keys a20, a02, a11, like the smooth model's a2):
// explicit zeros print the same bytes as the default (the golden rough_evolve.csv), nonzero values
// still end on `gkt table`'s HCS, unrealizable ones and cumulants without the linear scheme are refused
// with one line naming the field (exit 2).
// hcs = "linear-oriented" (theory.md §19.13): the linear scheme with the orientation term b00 P; the trajectory ends
// on the oriented first-Sonine HCS (θ = 0.852432, C = 0.32927 at (0.9, 0.5), theory.md §19.14), 0.35 % below the
// isotropic θ; disks refused with one line.
TEST(CliRoughEvolve, OrientedScheme) {
  const CliRun run = run_gkt("evolve " + scene_path("rough_evolve.toml") + " --set 'hcs=\"linear-oriented\"'");
  const CliRun iso = run_gkt("evolve " + scene_path("rough_evolve.toml"));
  ASSERT_EQ(run.status, 0) << run.err;
  ASSERT_EQ(iso.status, 0) << iso.err;
  const auto o = parse_csv(run.out), i = parse_csv(iso.out);
  ASSERT_EQ(o[0].size(), 11u);
  EXPECT_EQ(o[0][9], "b00");
  EXPECT_EQ(o[0][10], "orientation_correlation");
  EXPECT_NEAR(std::stod(o.back()[4]), 0.852432, 2e-6);
  EXPECT_NEAR(std::stod(o.back()[10]), 0.32927, 2e-5);
  EXPECT_NEAR(std::stod(o.back()[10]), 1.0 / 3 + std::stod(o.back()[9]) / 5, 1e-12);
  EXPECT_NEAR(std::stod(o.back()[4]) / std::stod(i.back()[4]) - 1, -0.0035, 3e-4);
  const CliRun disks =
      run_gkt("evolve " + scene_path("rough_evolve.toml") + " --set dimension=2 --set 'hcs=\"linear-oriented\"'");
  EXPECT_EQ(disks.status, 2);
  EXPECT_NE(disks.err.find("hcs: \"linear-oriented\" needs dimension = 3"), std::string::npos) << disks.err;
  EXPECT_EQ(std::count(disks.err.begin(), disks.err.end(), '\n'), 1) << disks.err;
  EXPECT_TRUE(disks.out.empty());
}

TEST(CliRoughEvolve, InitialCumulants) {
  const std::string quick = " --set t_end=100000 --set points=3";
  const CliRun plain = run_gkt("evolve " + scene_path("rough_evolve.toml"));
  const CliRun zeros = run_gkt("evolve " + scene_path("rough_evolve.toml") + " --set a20=0 --set a02=0 --set a11=0");
  ASSERT_EQ(plain.status, 0) << plain.err;
  ASSERT_EQ(zeros.status, 0) << zeros.err;
  EXPECT_EQ(plain.out, zeros.out);
  const CliRun moved =
      run_gkt("evolve " + scene_path("rough_evolve.toml") + quick + " --set a20=0.1 --set a02=-0.2 --set a11=0.05");
  ASSERT_EQ(moved.status, 0) << moved.err;
  const CliRun table = run_gkt("table " + scene_path("rough_hcs.toml") +
                               " --set 'alpha=[0.9]' --set 'coefficients=[\"rotational_temperature_ratio\", "
                               "\"cooling_rate\", \"a20\", \"a02\", \"a11\"]'");
  ASSERT_EQ(table.status, 0) << table.err;
  const auto mt = parse_csv(moved.out), tt = parse_csv(table.out);
  ASSERT_EQ(mt.size(), 4u);
  for (std::size_t k = 0; k < 5; ++k)
    EXPECT_NEAR(std::stod(mt.back()[4 + k]), std::stod(tt[1][1 + k]), 1e-8) << mt[0][4 + k];
  for (const auto& [set, message] : std::vector<std::pair<std::string, std::string>>{
           {"a20=-0.45", "a20: must be >= -2/(d+2) = -0.400000 for dimension = 3"},
           {"a20=-0.6", "a20: must be a number >= -0.5, got -0.6"},
           {"a02=-0.5", "a02: must be >= -2/(d_r+2) = -0.400000 for dimension = 3"},
           {"a11=0.7", "a11: must be in [-0.666667, 0.666667] at these a20, a02"},
           {"a11=-1e301", "a11: must be in [-0.666667, 0.666667] at these a20, a02"},  // no schema bound below
           {"a20=0.1 --set 'hcs=\"maxwellian\"'", "a20, a02, a11: initial cumulants need the linear scheme"}}) {
    const CliRun bad = run_gkt("evolve " + scene_path("rough_evolve.toml") + " --set " + set);
    EXPECT_EQ(bad.status, 2) << set << ": " << bad.err;
    EXPECT_NE(bad.err.find(message), std::string::npos) << bad.err;
    EXPECT_TRUE(bad.out.empty());
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  }
  // Disks: −2/(d+2) = −1/2, and a02 down to −2/3 (one rotational degree of freedom).
  const CliRun disks = run_gkt("evolve " + scene_path("rough_evolve.toml") + quick +
                               " --set dimension=2 --set moment_of_inertia=0.5 --set a20=-0.45 --set a02=-0.6");
  EXPECT_EQ(disks.status, 0) << disks.err;
  // Walton: cumulants need hcs = "linear" (the default stays the Maxwellian equations); with it the last row
  // equals `gkt table`'s linear HCS (theory.md §19.19).
  const CliRun walton = run_gkt("evolve " + scene_path("rough_walton_evolve.toml") + " --set a20=0.1");
  EXPECT_EQ(walton.status, 2);
  EXPECT_NE(walton.err.find("a20, a02, a11: initial cumulants need the linear scheme"), std::string::npos)
      << walton.err;
  const CliRun linear = run_gkt("evolve " + scene_path("rough_walton_evolve.toml") + quick +
                                " --set rotational_temperature=0.5 --set 'hcs=\"linear\"' --set a02=0.1");
  ASSERT_EQ(linear.status, 0) << linear.err;
  const CliRun walton_table =
      run_gkt("table " + scene_path("rough_walton.toml") +
              " --set 'alpha=[0.9]' --set 'friction=[1]' --set beta0=1 --set 'hcs=\"linear\"' --set "
              "'coefficients=[\"rotational_temperature_ratio\", \"cooling_rate\", \"a20\", \"a02\", \"a11\"]'");
  ASSERT_EQ(walton_table.status, 0) << walton_table.err;
  const auto lt = parse_csv(linear.out), wt = parse_csv(walton_table.out);
  ASSERT_EQ(lt.size(), 4u);
  ASSERT_EQ(lt[0][6], "a20");
  for (std::size_t k = 0; k < 5; ++k) {
    const auto column = std::find(wt[0].begin(), wt[0].end(), lt[0][4 + k]);
    ASSERT_NE(column, wt[0].end()) << lt[0][4 + k];
    EXPECT_NEAR(std::stod(lt.back()[4 + k]), std::stod(wt[1][static_cast<std::size_t>(column - wt[0].begin())]), 1e-7)
        << lt[0][4 + k];
  }
}

// rough-walton's first-Sonine HCS columns (theory.md §19.19): hcs = "linear" moves θ and prints the step from the
// Maxwellian as its error; μ_f = 10⁶ equals the rough model's linear scheme; where the linear scheme has no root
// (the constant-β no-root state (0.5, 0) at μ_f = 10⁶) "linear" refuses with one line and "linear-or-maxwellian"
// falls back to the Maxwellian θ with nan cumulants; the default stays the Maxwellian columns.
TEST(CliRoughWalton, LinearHcsColumns) {
  const std::string hcs_columns =
      " --set 'coefficients=[\"rotational_temperature_ratio\", \"cooling_rate\", \"a20\", \"a02\", \"a11\"]'";
  const std::string state = " --set 'alpha=[0.9]' --set 'friction=[0.5]'";
  const CliRun maxwellian = run_gkt("table " + scene_path("rough_walton.toml") + state + hcs_columns);
  const CliRun linear =
      run_gkt("table " + scene_path("rough_walton.toml") + state + hcs_columns + " --set 'hcs=\"linear\"'");
  ASSERT_EQ(maxwellian.status, 0) << maxwellian.err;
  ASSERT_EQ(linear.status, 0) << linear.err;
  const auto m = parse_csv(maxwellian.out), l = parse_csv(linear.out);
  const auto column = [](const std::vector<std::string>& header, const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const std::size_t theta = column(l[0], "rotational_temperature_ratio"),
                    theta_error = column(l[0], "rotational_temperature_ratio_error"), a02 = column(l[0], "a02");
  ASSERT_LT(theta_error, l[0].size());
  EXPECT_EQ(m[1][a02], "0");
  EXPECT_GT(std::stod(l[1][a02]), 0.05);  // the spin tail is longer than a Maxwellian's
  const double step = std::abs(std::stod(l[1][theta]) - std::stod(m[1][theta]));
  EXPECT_GT(step, 0.01);
  EXPECT_NEAR(std::stod(l[1][theta_error]), step, 0.01 * step);
  // μ_f = 10⁶: the rough model's linear scheme (β = β0 = 0.5).
  const CliRun big = run_gkt("table " + scene_path("rough_walton.toml") + hcs_columns +
                             " --set 'alpha=[0.9]' --set 'friction=[1000000]' --set beta0=0.5 --set 'hcs=\"linear\"'");
  const CliRun rough = run_gkt("table " + scene_path("rough_hcs.toml") + hcs_columns + " --set 'alpha=[0.9]'");
  ASSERT_EQ(big.status, 0) << big.err;
  ASSERT_EQ(rough.status, 0) << rough.err;
  const auto b = parse_csv(big.out), r = parse_csv(rough.out);
  for (const char* name : {"rotational_temperature_ratio", "cooling_rate", "a20", "a02", "a11"})
    EXPECT_NEAR(std::stod(b[1][column(b[0], name)]), std::stod(r[1][column(r[0], name)]), 1e-6) << name;
  const std::string no_root = " --set 'alpha=[0.5]' --set 'friction=[1000000]' --set beta0=0";
  const CliRun refused =
      run_gkt("table " + scene_path("rough_walton.toml") + no_root + hcs_columns + " --set 'hcs=\"linear\"'");
  EXPECT_EQ(refused.status, 2);
  EXPECT_TRUE(refused.out.empty());
  EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
  EXPECT_NE(refused.err.find("hcs: the linear scheme of the Walton gas has no root"), std::string::npos);
  const CliRun fallback = run_gkt("table " + scene_path("rough_walton.toml") + no_root + hcs_columns +
                                  " --set 'hcs=\"linear-or-maxwellian\"'");
  ASSERT_EQ(fallback.status, 0) << fallback.err;
  const auto f = parse_csv(fallback.out);
  EXPECT_NEAR(std::stod(f[1][column(f[0], "rotational_temperature_ratio")]), 2.0604, 1e-4);  // theory.md §19.6
  EXPECT_EQ(f[1][column(f[0], "a02")], "nan");
}

// rough-walton's HCS columns at Sonine orders 2, 3 (theory.md §19.25): the error printed at order N is the step
// from order N − 1 (the order-2 and order-1 rows), θ moves by less than that step's predecessor; order 4, and the
// Navier–Stokes columns at order 3, are refused with one line (exit 2) and no output.
TEST(CliRoughWalton, SonineOrdersOfTheCoolingState) {
  const std::string hcs =
      " --set 'coefficients=[\"rotational_temperature_ratio\", \"cooling_rate\", \"a20\", "
      "\"a02\", \"a11\"]' --set 'alpha=[0.9]' --set 'friction=[0.5]' --set 'hcs=\"linear\"'";
  std::vector<std::vector<std::vector<std::string>>> rows;
  for (int n = 1; n <= 3; ++n) {
    const CliRun run = run_gkt("table " + scene_path("rough_walton.toml") + hcs + " --set order=" + std::to_string(n));
    ASSERT_EQ(run.status, 0) << run.err;
    rows.push_back(parse_csv(run.out));
  }
  const auto& header = rows[0][0];
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  for (const char* name : {"rotational_temperature_ratio", "cooling_rate", "a20", "a02", "a11"})
    for (std::size_t n = 1; n < 3; ++n) {
      const double step = std::abs(std::stod(rows[n][1][column(name)]) - std::stod(rows[n - 1][1][column(name)]));
      EXPECT_NEAR(std::stod(rows[n][1][column(std::string(name) + "_error")]), step, 0.01 * step + 1e-12) << name;
    }
  const auto theta = [&](std::size_t n) { return std::stod(rows[n][1][column("rotational_temperature_ratio")]); };
  EXPECT_LT(std::abs(theta(2) - theta(1)), std::abs(theta(1) - theta(0)));
  EXPECT_NEAR(theta(2), 0.89423, 1e-5);  // theory.md §19.25
  for (const std::string& bad :
       {hcs + " --set order=4", hcs + " --set order=3 --set 'coefficients=[\"shear_viscosity\"]'"}) {
    const CliRun refused = run_gkt("table " + scene_path("rough_walton.toml") + bad);
    EXPECT_EQ(refused.status, 2) << bad;
    EXPECT_TRUE(refused.out.empty());
    EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
    EXPECT_NE(refused.err.find("order: "), std::string::npos) << refused.err;
  }
}

// rough-walton's oriented HCS (hcs = "linear-oriented", theory.md §19.29): at order 2 the columns
// orientation_correlation and b00, b10, b01 print the oriented solution with the step from order 1 as error, C = 1/3 +
// b00/5 at order 1 (b10 = 0 there, outside the ansatz); disks, the orientation columns without it and reference_state =
// "hcs" with it are refused with one line (exit 2) and no output.
TEST(CliRoughWalton, OrientedCoolingState) {
  const std::string oriented =
      " --set 'coefficients=[\"rotational_temperature_ratio\", \"a11\", \"orientation_correlation\", \"b00\", "
      "\"b10\", \"b01\"]' --set 'alpha=[0.9]' --set 'friction=[0.5]' --set 'hcs=\"linear-oriented\"'";
  std::vector<std::vector<std::vector<std::string>>> rows;
  for (int n = 1; n <= 2; ++n) {
    const CliRun run =
        run_gkt("table " + scene_path("rough_walton.toml") + oriented + " --set order=" + std::to_string(n));
    ASSERT_EQ(run.status, 0) << run.err;
    rows.push_back(parse_csv(run.out));
  }
  const auto& header = rows[0][0];
  const auto at = [&](std::size_t n, const std::string& name) {
    return std::stod(
        rows[n][1][static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin())]);
  };
  EXPECT_NEAR(at(0, "orientation_correlation"), 1.0 / 3 + at(0, "b00") / 5, 1e-12);  // (19.28)
  EXPECT_EQ(at(0, "b10"), 0.0);
  EXPECT_NEAR(at(0, "orientation_correlation_error"), 1.0 / 3 - at(0, "orientation_correlation"), 1e-5);
  for (const char* name : {"rotational_temperature_ratio", "a11", "orientation_correlation", "b00", "b01"}) {
    const double step = std::abs(at(1, name) - at(0, name));
    EXPECT_NEAR(at(1, std::string(name) + "_error"), step, 0.01 * step + 1e-12) << name;
  }
  EXPECT_LT(at(1, "orientation_correlation"), 1.0 / 3 - 0.005);  // theory.md §19.29: C = 0.3275
  EXPECT_NEAR(at(1, "rotational_temperature_ratio"), 0.88708, 1e-5);
  for (const auto& [bad, field] :
       {std::pair{oriented + " --set dimension=2 --set moment_of_inertia=0.5", "hcs: "},
        std::pair{oriented + " --set 'hcs=\"linear\"'", "coefficients: "},
        std::pair{oriented + " --set 'reference_state=\"hcs\"' --set 'coefficients=[\"shear_viscosity\"]'",
                  "reference_state: "}}) {
    const CliRun refused = run_gkt("table " + scene_path("rough_walton.toml") + bad);
    EXPECT_EQ(refused.status, 2) << bad;
    EXPECT_TRUE(refused.out.empty());
    EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
    EXPECT_NE(refused.err.find(field), std::string::npos) << refused.err;
  }
}

// rough-walton's Navier–Stokes columns about the first-Sonine Walton HCS (reference_state = "hcs", theory.md §19.25):
// for disks at friction = 10⁶ the rough model's values about its linear HCS of degree 2 (to 1e-6: the grazing sliding
// of a finite μ_f; spheres differ: the rough model's reference carries the orientation terms b_pq, §19.16, the Walton
// one does not); order 2 and the HCS columns are refused with one line (exit 2).
TEST(CliRoughWalton, TransportAboutTheCumulantHcs) {
  const std::string columns =
      " --set 'coefficients=[\"shear_viscosity\", \"thermal_conductivity\", \"bulk_viscosity\"]'";
  const CliRun walton = run_gkt("table " + scene_path("rough_walton.toml") + columns +
                                " --set 'alpha=[0.9]' --set 'friction=[1000000]' --set beta0=0.5 --set "
                                "'reference_state=\"hcs\"' --set dimension=2 --set moment_of_inertia=0.5");
  const CliRun rough = run_gkt("table " + scene_path("rough_hcs.toml") + columns +
                               " --set 'alpha=[0.9]' --set order=1 --set 'reference_state=\"hcs\"' --set hcs_order=2"
                               " --set dimension=2 --set moment_of_inertia=0.5");
  ASSERT_EQ(walton.status, 0) << walton.err;
  ASSERT_EQ(rough.status, 0) << rough.err;
  const auto w = parse_csv(walton.out), r = parse_csv(rough.out);
  const auto column = [](const std::vector<std::string>& header, const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  for (const char* name : {"shear_viscosity", "thermal_conductivity", "bulk_viscosity"})
    EXPECT_NEAR(std::stod(w[1][column(w[0], name)]), std::stod(r[1][column(r[0], name)]), 1e-6) << name;
  for (const std::string& bad : {std::string(" --set order=2"), std::string(" --set 'coefficients=[\"a20\"]'")}) {
    const CliRun refused = run_gkt("table " + scene_path("rough_walton.toml") + columns +
                                   " --set 'alpha=[0.9]' --set 'friction=[0.5]' --set 'reference_state=\"hcs\"'" + bad);
    EXPECT_EQ(refused.status, 2) << bad;
    EXPECT_TRUE(refused.out.empty());
    EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
  }
}

// `gkt evolve` at Sonine order 2 (theory.md §19.13, (19.25b)–(19.25c)): the oriented trajectory's last row equals
// `gkt table` at order 2 (the oriented linear HCS) in θ, ζ*, a20, a02, a11, a03, b00, b01 and C; its columns add the
// cubic cumulants and b10, b01 after the order-1 ones.
TEST(CliRoughEvolve, SonineOrderTwoRelaxesToTheTable) {
  const CliRun evolve =
      run_gkt("evolve " + scene_path("rough_evolve.toml") + " --set order=2 --set 'hcs=\"linear-oriented\"'");
  const CliRun table =
      run_gkt("table " + scene_path("rough_hcs.toml") +
              " --set 'alpha=[0.9]' --set order=2 --set 'coefficients=[\"rotational_temperature_ratio\", "
              "\"cooling_rate\", \"a20\", \"a02\", \"a11\", \"a03\", \"b00\", \"b01\", "
              "\"orientation_correlation\"]'");
  ASSERT_EQ(evolve.status, 0) << evolve.err;
  ASSERT_EQ(table.status, 0) << table.err;
  const auto et = parse_csv(evolve.out), tt = parse_csv(table.out);
  ASSERT_EQ(et[0],
            (std::vector<std::string>{"time", "collisions", "translational_temperature", "rotational_temperature",
                                      "rotational_temperature_ratio", "cooling_rate", "a20", "a02", "a11", "a30", "a21",
                                      "a12", "a03", "b00", "b10", "b01", "orientation_correlation"}));
  for (const std::string name : {"rotational_temperature_ratio", "cooling_rate", "a20", "a02", "a11", "a03", "b00",
                                 "b01", "orientation_correlation"}) {
    const auto e = std::find(et[0].begin(), et[0].end(), name) - et[0].begin();
    const auto t = std::find(tt[0].begin(), tt[0].end(), name) - tt[0].begin();
    ASSERT_LT(static_cast<std::size_t>(t), tt[0].size()) << name;
    EXPECT_NEAR(std::stod(et.back()[static_cast<std::size_t>(e)]), std::stod(tt[1][static_cast<std::size_t>(t)]), 1e-8)
        << name;
  }
}

// The nonlinear scheme in `gkt evolve` (theory.md §19.24): the last row is `gkt table`'s nonlinear HCS (order 1,
// isotropic), not the linear one's, and the columns are those of the linear scheme.
TEST(CliRoughEvolve, NonlinearSchemeRelaxesToTheNonlinearTable) {
  const CliRun evolve = run_gkt("evolve " + scene_path("rough_evolve.toml") + " --set 'hcs=\"nonlinear\"'");
  const std::string keys =
      " --set 'alpha=[0.9]' --set order=1 --set 'coefficients=[\"rotational_temperature_ratio\", "
      "\"cooling_rate\", \"a20\", \"a02\", \"a11\"]'";
  const CliRun table = run_gkt("table " + scene_path("rough_hcs.toml") + keys + " --set 'hcs=\"nonlinear\"'");
  const CliRun linear = run_gkt("table " + scene_path("rough_hcs.toml") + keys + " --set 'hcs=\"linear\"'");
  ASSERT_EQ(evolve.status, 0) << evolve.err;
  ASSERT_EQ(table.status, 0) << table.err;
  ASSERT_EQ(linear.status, 0) << linear.err;
  const auto et = parse_csv(evolve.out), tt = parse_csv(table.out), lt = parse_csv(linear.out);
  ASSERT_EQ(et[0],
            (std::vector<std::string>{"time", "collisions", "translational_temperature", "rotational_temperature",
                                      "rotational_temperature_ratio", "cooling_rate", "a20", "a02", "a11"}));
  for (const std::string name : {"rotational_temperature_ratio", "cooling_rate", "a20", "a02", "a11"}) {
    const auto e = static_cast<std::size_t>(std::find(et[0].begin(), et[0].end(), name) - et[0].begin());
    const auto t = static_cast<std::size_t>(std::find(tt[0].begin(), tt[0].end(), name) - tt[0].begin());
    ASSERT_LT(t, tt[0].size()) << name;
    EXPECT_NEAR(std::stod(et.back()[e]), std::stod(tt[1][t]), 1e-8) << name;
    if (name == "rotational_temperature_ratio") {
      EXPECT_GT(std::abs(std::stod(et.back()[e]) - std::stod(lt[1][t])), 1e-5);  // not the linear HCS
    }
  }
}

// The N = 3 nonlinear stall from a cold spin (theory.md §19.24): exit 2 with one line naming the step budget and
// what to do, nothing on standard output (the trajectory is written only when complete); a modest budget keeps it
// fast, and a budget of 0 is refused as input.
TEST(CliRoughEvolve, ColdSpinThirdOrderNonlinearStopsAtTheStepBudget) {
  const std::string base =
      "evolve " + scene_path("rough_evolve.toml") + " --set 'hcs=\"nonlinear\"' --set order=3 --set max_steps=";
  const CliRun r = run_gkt(base + "2000");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_EQ(r.err.rfind("gkt: error: max_steps: the nonlinear Sonine scheme at order 3 used its 2000 CVODE steps", 0),
            0U)
      << r.err;
  EXPECT_NE(r.err.find("hcs = \"linear\", or a warmer rotational_temperature"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  const CliRun zero = run_gkt(base + "0");
  EXPECT_EQ(zero.status, 2);
  EXPECT_EQ(zero.err.rfind("gkt: error: max_steps:", 0), 0U) << zero.err;
}

// The CVODE step budget over the whole trajectory of every other `gkt evolve` path (docs/conventions.md): a budget of
// three steps stops each one before its first output time with one line naming max_steps and the time reached, exit
// 2, nothing on standard output; a budget of 0 is refused as input.
TEST(CliEvolve, EveryPathStopsAtTheStepBudget) {
  for (const std::string& scene : std::vector<std::string>{
           scene_path("cooling_constant_alpha.toml"), scene_path("cooling_viscoelastic.toml"),
           scene_path("mixture_evolve.toml"), scene_path("aggregation_evolve.toml"),
           scene_path("rough_walton_evolve.toml"), scene_path("rough_walton_evolve.toml") + " --set 'hcs=\"linear\"'",
           scene_path("rough_evolve.toml"), scene_path("rough_evolve.toml") + " --set 'hcs=\"maxwellian\"'",
           scene_path("rough_evolve.toml") + " --set 'hcs=\"linear-oriented\"'"}) {
    const CliRun r = run_gkt("evolve " + scene + " --set max_steps=3");
    EXPECT_EQ(r.status, 2) << scene;
    EXPECT_TRUE(r.out.empty()) << scene << r.out;
    EXPECT_EQ(r.err.rfind("gkt: error: max_steps: used its 3 CVODE steps before time = ", 0), 0U) << scene << r.err;
    EXPECT_NE(r.err.find("(stopped at time = "), std::string::npos) << scene << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << scene << r.err;
    const CliRun zero = run_gkt("evolve " + scene + " --set max_steps=0");
    EXPECT_EQ(zero.status, 2) << scene;
    EXPECT_TRUE(zero.out.empty()) << scene << zero.out;
    EXPECT_EQ(zero.err.rfind("gkt: error: max_steps:", 0), 0U) << scene << zero.err;
  }
}

// `gkt stability` about the Sonine HCS (reference_state = "hcs", theory.md (19.33)): values with error columns (the
// Sonine and cumulant-degree steps), moved from the Maxwellian first approximation (disks, (0.9, 0.5)).
TEST(CliRoughStability, AboutTheSonineHcs) {
  const std::string base = "stability " + scene_path("rough_stability.toml") +
                           " --set dimension=2 --set moment_of_inertia=0.5 --set alpha=0.9 --set beta=0.5";
  const CliRun plain = run_gkt(base);
  const CliRun hcs = run_gkt(base + " --set 'reference_state=\"hcs\"' --set 'hcs=\"nonlinear\"'");
  ASSERT_EQ(plain.status, 0) << plain.err;
  ASSERT_EQ(hcs.status, 0) << hcs.err;
  const auto p = parse_csv(plain.out), h = parse_csv(hcs.out);
  ASSERT_EQ(h[0], p[0]);
  ASSERT_EQ(h[0][0], "critical_wavenumber_shear");
  EXPECT_EQ(p[1][3], "nan");  // the first approximation has no error estimate
  for (std::size_t c = 0; c < 3; ++c) {
    EXPECT_GT(std::stod(h[1][c + 3]), 0) << h[0][c];
    EXPECT_GT(std::abs(std::stod(h[1][c]) - std::stod(p[1][c])), 1e-5) << h[0][c];
  }
}

// `gkt stability` for rough spheres (theory.md §19.15): the three stability columns by default; β = −1
// (spin decoupled) equals the smooth gas's first-Sonine stability at the Maxwellian (checked against
// the library in test_rough_hcs_stability.cpp); α = β = 1 is stable (0, 0, inf); the stability values
// do not need the linear scheme's root (hcs = "linear", its no-root region, still answers); rough-walton
// answers too.
TEST(CliRoughStability, ColumnsLimitsAndNoRootRegion) {
  const CliRun r =
      run_gkt("stability " + scene_path("rough_stability.toml") + " --set 'alpha=[1, 0.5]' --set 'beta=[1, 0]'");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto t = parse_csv(r.out);
  ASSERT_EQ(t.size(), 5u);
  EXPECT_EQ(t[0][2], "critical_wavenumber_shear");
  EXPECT_EQ(t[0][3], "critical_wavenumber_heat");
  EXPECT_EQ(t[0][4], "critical_length");
  EXPECT_EQ(t[1][2], "0");
  EXPECT_EQ(t[1][3], "0");
  EXPECT_EQ(t[1][4], "inf");
  EXPECT_GT(std::stod(t[4][2]), 0);  // α = 0.5, β = 0: no linear root (theory.md §19.6), still an answer
  EXPECT_GT(std::stod(t[4][3]), 0);
  const CliRun walton = run_gkt("stability " + scene_path("rough_walton.toml") +
                                " --set 'alpha=[0.9]' --set 'friction=[0.5]' --set "
                                "'coefficients=[\"critical_wavenumber_shear\", \"critical_length\"]'");
  ASSERT_EQ(walton.status, 0) << walton.err;
  const auto w = parse_csv(walton.out);
  ASSERT_EQ(w.size(), 2u) << walton.out;
  EXPECT_EQ(w[0][2], "critical_wavenumber_shear");
  EXPECT_GT(std::stod(w[1][2]), 0) << walton.out;
}

// `rotational_temperature_closure = "field"` (theory.md §19.15.1): T_r as a fourth field gives the three-field
// critical values (det M4 = −Γ* det M3, (19.38); to 1e-10, the bisection's accuracy) at strong and medium roughness,
// spheres and disks; a bad value and the field closure about the nonlinear Sonine HCS (theory.md §19.27) are refused
// with one line.
TEST(CliRoughStability, RotationalTemperatureAsAField) {
  const std::string base =
      "stability " + scene_path("rough_stability.toml") + " --set 'alpha=[0.9, 0.7]' --set 'beta=[0.5, -0.5, 0]'";
  for (const std::string dims : {"", " --set dimension=2 --set moment_of_inertia=0.5"}) {
    const CliRun slaved = run_gkt(base + dims);
    const CliRun field = run_gkt(base + dims + " --set 'rotational_temperature_closure=\"field\"'");
    ASSERT_EQ(slaved.status, 0) << slaved.err;
    ASSERT_EQ(field.status, 0) << field.err;
    const auto a = parse_csv(slaved.out), b = parse_csv(field.out);
    ASSERT_EQ(a.size(), 7u);
    ASSERT_EQ(a[0], b[0]);
    for (std::size_t r = 1; r < a.size(); ++r)
      for (std::size_t c = 2; c < 5; ++c) {
        const double x = std::stod(a[r][c]), y = std::stod(b[r][c]);
        EXPECT_GT(x, 0) << r << c;
        EXPECT_NEAR(y, x, 1e-10 * x) << dims << r << c;
      }
  }
  for (const auto& [args, message] : std::vector<std::pair<std::string, std::string>>{
           {" --set 'rotational_temperature_closure=\"free\"'", "rotational_temperature_closure: must be one of"},
           {" --set 'rotational_temperature_closure=\"field\"' --set 'reference_state=\"hcs\"' --set "
            "'hcs=\"nonlinear\"'",
            "rotational_temperature_closure: \"field\" with reference_state = \"hcs\" needs hcs = \"linear\""}}) {
    const CliRun bad = run_gkt(base + args);
    EXPECT_EQ(bad.status, 2) << args << ": " << bad.err;
    EXPECT_NE(bad.err.find(message), std::string::npos) << bad.err;
    EXPECT_EQ(bad.err.find('\n'), bad.err.size() - 1) << bad.err;
    EXPECT_TRUE(bad.out.empty());
  }
}

// The rough-walton model (theory.md §19.10): friction = 1e6 reproduces the rough model with beta = beta0
// (Maxwellian), and bad input is refused with one line.
TEST(CliRoughWalton, ConstantBetaLimitAndBadInput) {
  const CliRun walton = run_gkt("table " + scene_path("rough_walton.toml") +
                                " --set friction=1000000 --set 'coefficients=[\"rotational_temperature_ratio\", "
                                "\"cooling_rate\", \"bulk_viscosity\"]'");
  const CliRun rough =
      run_gkt("table " + scene_path("rough_hcs.toml") +
              " --set beta=1 --set 'alpha=[0.9, 0.7]' --set 'hcs=\"maxwellian\"' --set "
              "'coefficients=[\"rotational_temperature_ratio\", \"cooling_rate\", \"bulk_viscosity\"]'");
  ASSERT_EQ(walton.status, 0) << walton.err;
  ASSERT_EQ(rough.status, 0) << rough.err;
  const auto wt = parse_csv(walton.out), rt = parse_csv(rough.out);
  ASSERT_EQ(wt.size(), 3U);
  ASSERT_EQ(rt.size(), 3U);
  for (std::size_t row = 1; row < 3; ++row) {
    EXPECT_NEAR(std::stod(wt[row][1]), std::stod(rt[row][1]), 1e-8);  // theta (columns: alpha, ...)
    EXPECT_NEAR(std::stod(wt[row][2]), std::stod(rt[row][2]), 1e-8);  // cooling_rate
    EXPECT_NEAR(std::stod(wt[row][3]), std::stod(rt[row][3]), 1e-6);  // bulk_viscosity
  }
  for (const auto& [set, message] : std::vector<std::pair<std::string, std::string>>{
           {"friction=-0.5", "friction: must be a number in [0, 1000000], got -0.5"},
           {"beta0=1.5", "beta0: must be a number in [-1, 1], got 1.5"},
           {"moment_of_inertia=0", "moment_of_inertia: must be a number in (0, 1], got 0"},
           {"beta=0.5", "beta: unknown key for model \"rough-walton\""},
           {"order=4", "order: must be an integer in [1, 3], got 4"},
           {"order=2",
            "coefficients: rotational_temperature_ratio of model rough-walton is computed at order 1 only"}}) {
    const CliRun bad = run_gkt("table " + scene_path("rough_walton.toml") + " --set " + set);
    EXPECT_EQ(bad.status, 2) << set << ": " << bad.err;
    EXPECT_NE(bad.err.find(message), std::string::npos) << bad.err;
    EXPECT_TRUE(bad.out.empty());
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  }
}

// order = 2 (theory.md §19.20): the Navier–Stokes columns of the Sonine solver with quadrature elements at the
// Maxwellian Walton θ, the error from orders 3 and 4. μ_f = 10⁶ (every impact but the most grazing sticks) equals
// the constant-β model's order 2 with its error (2D: the cheaper tables, ~3 s of CPU).
TEST(CliRoughWalton, SecondSonineOrderIsTheConstantBetaOneAtLargeFriction) {
  GKT_SKIP_UNDER_SANITIZER("10 s");  // the order-4 Walton tables take minutes there
  const std::string common =
      " --set dimension=2 --set moment_of_inertia=0.5 --set alpha=0.9 --set order=2 "
      "--set 'coefficients=[\"shear_viscosity\", \"bulk_viscosity\"]'";
  const CliRun walton = run_gkt("table " + scene_path("rough_walton.toml") + " --set friction=1000000" + common);
  const CliRun rough = run_gkt("table " + scene_path("rough_hcs.toml") + " --set beta=1" + common);
  ASSERT_EQ(walton.status, 0) << walton.err;
  ASSERT_EQ(rough.status, 0) << rough.err;
  const auto w = parse_csv(walton.out), r = parse_csv(rough.out);
  ASSERT_EQ(w.size(), 2U) << walton.out;
  ASSERT_EQ(w[0], (std::vector<std::string>{"shear_viscosity", "bulk_viscosity", "shear_viscosity_error",
                                            "bulk_viscosity_error", "order"}));
  ASSERT_EQ(r[0], w[0]);
  for (std::size_t c = 0; c < 2; ++c) EXPECT_NEAR(std::stod(w[1][c]), std::stod(r[1][c]), 1e-9) << c;
  for (std::size_t c = 2; c < 4; ++c) EXPECT_NEAR(std::stod(w[1][c]), std::stod(r[1][c]), 1e-6) << c;
  EXPECT_GT(std::stod(w[1][2]), 0);
  EXPECT_EQ(w[1][4], "2");
}

// The dilute and dense (theory.md (14.4)–(14.5)) analyses: golden files hcs_stability.csv and
// hcs_stability_dense.csv (tests/golden/manifest.tsv).
TEST(CliStability, RefusesModelsWithoutStability) {
  const fs::path scene = fs::temp_directory_path() / ("gkt_stability_" + std::to_string(::getpid()) + ".toml");
  std::ofstream(scene) << "model = \"hard-spheres\"\norder = 2\n";
  const CliRun bad = run_gkt("stability " + scene.string());
  fs::remove(scene);
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("model: \"hard-spheres\" has no stability analysis; use \"mixture\", \"rough\", "
                         "\"rough-walton\", \"smooth-inelastic\" or \"viscoelastic\""),
            std::string::npos)
      << bad.err;
}

// α = 1 is valid (issue 17): the elastic gas never clusters, k⊥c* = k∥c* = 0 and L_c* = inf (JSON
// null), errors 0 — and the sweep through it keeps every row (it exited 1 with "internal error:
// Rational: non-finite double" before).
TEST(CliStability, ElasticEndIsInfinite) {
  const CliRun r = run_gkt("stability " + scene_path("hcs_stability.toml") + " --set 'alpha=[0.9, 1]' --set order=2");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = parse_csv(r.out);
  ASSERT_EQ(rows.size(), 3u) << r.out;
  EXPECT_EQ(rows[2], (std::vector<std::string>{"1", "0", "0", "inf", "0", "0", "0", "2"})) << r.out;
  const CliRun json = run_gkt("stability " + scene_path("hcs_stability.toml") + " --set alpha=1 --format json");
  ASSERT_EQ(json.status, 0) << json.err;
  EXPECT_TRUE(nlohmann::json::parse(json.out)["rows"][0]["critical_length"].is_null()) << json.out;
}

TEST(Cli, SetOverridesSceneKeys) {
  const CliRun r = run_gkt("table " + scene_path("hard_spheres_exact.toml") +
                           " --exact --set order=2 --set 'coefficients=[\"self_diffusion\"]'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(parse_csv(r.out)[1][0], "59/58");
}

TEST(Cli, VersionAndHelp) {
  EXPECT_EQ(run_gkt("--version").out, std::string("gkt ") + GKT_VERSION + "\n");
  const CliRun help = run_gkt("table --help");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.out.find("--exact"), std::string::npos);
  const CliRun models = run_gkt("models");
  EXPECT_NE(models.out.find("hard-spheres"), std::string::npos);
}

struct BadInput {
  std::string label;
  std::string scene;   // scene file content ("" = do not create one)
  std::string extra;   // extra command-line arguments
  std::string expect;  // substring of the one-line error (the field name)
};

void PrintTo(const BadInput& b, std::ostream* os) { *os << b.label; }

class CliBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(CliBadInput, OneLineErrorExitTwoNoOutput) {
  const BadInput b = GetParam();
  const fs::path dir = fs::temp_directory_path() / ("gkt_bad_" + std::to_string(::getpid()) + "_" + b.label);
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path scene = dir / "scene.toml";
  if (!b.scene.empty()) std::ofstream(scene) << b.scene;
  const fs::path output = dir / "table.csv";
  const CliRun r = run_gkt("table " + scene.string() + " --output " + output.string() + " " + b.extra);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_TRUE(r.out.empty());
  ASSERT_FALSE(r.err.empty());
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "not one line: " << r.err;
  EXPECT_NE(r.err.find(b.expect), std::string::npos) << r.err;
  // Nothing left behind: neither the output nor a temporary file.
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) files += entry.path().filename() != "scene.toml";
  EXPECT_EQ(files, 0U);
  fs::remove_all(dir);
}

const std::string kGood = "model = \"hard-spheres\"\ndimension = 3\norder = 2\n";
const std::string kMixtureSpecies =
    "[[species]]\nmass = 1\ndiameter = 1\nfraction = 0.5\n[[species]]\nmass = 2\ndiameter = 1\nfraction = 0.5\n";
// A binary mixture whose second species is left open: the case appends its fraction line.
const std::string kMixture =
    "model = \"mixture\"\norder = 1\nalpha = 0.9\n[[species]]\nmass = 1\ndiameter = 1\n"
    "fraction = 0.5\n[[species]]\nmass = 2\ndiameter = 1.5\n";

INSTANTIATE_TEST_SUITE_P(
    Cases, CliBadInput,
    ::testing::Values(
        BadInput{"unknown_key", kGood + "temperature = 2\n", "", "temperature: unknown key"},
        BadInput{"wrong_type", "model = \"hard-spheres\"\ndimension = \"three\"\norder = 2\n", "",
                 "dimension: must be a number"},
        BadInput{"dimension_4", "model = \"hard-spheres\"\ndimension = 4\norder = 2\n", "",
                 "dimension: must be 2 or 3"},
        BadInput{"dimension_in_sweep", "model = \"hard-spheres\"\ndimension = [3, 2, 1]\norder = 2\n", "",
                 "dimension: must be 2 or 3"},
        BadInput{"order_zero", "model = \"hard-spheres\"\norder = 0\n", "", "order: must be an integer in [1, 40]"},
        BadInput{"order_too_high", "model = \"hard-spheres\"\norder = 41\n", "",
                 "order: must be an integer in [1, 40]"},
        BadInput{"order_fraction", "model = \"hard-spheres\"\norder = 2.5\n", "", "order: must be an integer"},
        BadInput{"tolerance_zero", "model = \"hard-spheres\"\ntolerance = 0\n", "",
                 "tolerance: must be a number in (0, 1]"},
        BadInput{"tolerance_negative", "model = \"hard-spheres\"\ntolerance = -1e-3\n", "",
                 "tolerance: must be a number in (0, 1]"},
        BadInput{"order_and_tolerance", kGood + "tolerance = 1e-6\n", "", "order: give exactly one"},
        BadInput{"neither_order_nor_tolerance", "model = \"hard-spheres\"\n", "", "order: give exactly one"},
        BadInput{"unknown_model", "model = \"soft-spheres\"\norder = 1\n", "",
                 "model: unknown model \"soft-spheres\"; valid models: \"aggregation\", \"gravity-column\", "
                 "\"hard-spheres\""},
        BadInput{"missing_model", "order = 1\n", "", "model: required"},
        BadInput{"unknown_coefficient", kGood + "coefficients = [\"bulk_viscosity\"]\n", "",
                 "coefficients: unknown coefficient"},
        BadInput{"malformed_toml", "model = \"hard-spheres\norder = \n", "", "scene: "},
        BadInput{"missing_file", "", "", "scene: cannot open"},
        BadInput{"bad_range", "model = \"hard-spheres\"\norder = { from = 1, to = 3, points = 0 }\n", "",
                 "order.points: must be"},
        BadInput{"bad_range_key", "model = \"hard-spheres\"\norder = { from = 1, to = 3, step = 1 }\n", "",
                 "order.step: unknown range key"},
        BadInput{"bad_set", kGood, "--set dimension", "--set: expected KEY=VALUE"},
        BadInput{"set_out_of_range", kGood, "--set dimension=7", "dimension: must be 2 or 3"},
        BadInput{"bad_format", kGood, "--format xml", "--format"},
        BadInput{"packing_fraction_3d", "model = \"smooth-inelastic\"\npacking_fraction = 0.5001\norder = 1\n", "",
                 "packing_fraction: must be a number in [0, 0.5] for dimension = 3, got 0.5001"},
        BadInput{"packing_fraction_2d",
                 "model = \"smooth-inelastic\"\ndimension = 2\npacking_fraction = 0.71\norder = 1\n", "",
                 "packing_fraction: must be a number in [0, 0.7]"},
        BadInput{"packing_fraction_negative", "model = \"smooth-inelastic\"\npacking_fraction = -0.1\norder = 1\n", "",
                 "packing_fraction: must be a number in [0, 0.5] for dimension = 3, got -0.1"},
        BadInput{"unknown_pair_correlation",
                 "model = \"smooth-inelastic\"\npacking_fraction = 0.2\npair_correlation = \"py\"\norder = 1\n", "",
                 "pair_correlation: must be one of \"carnahan-starling\", got \"py\""},
        BadInput{"unknown_scheme", "model = \"smooth-inelastic\"\nscheme = \"improved\"\norder = 1\n", "",
                 "scheme: must be one of \"standard\", \"modified\", \"tail\", got \"improved\""},
        BadInput{"alpha_zero", "model = \"smooth-inelastic\"\nalpha = 0\norder = 1\n", "",
                 "alpha: must be a number in (0, 1], got 0"},
        BadInput{"alpha_above_one", "model = \"smooth-inelastic\"\nalpha = 1.5\norder = 1\n", "",
                 "alpha: must be a number in (0, 1], got 1.5"},
        BadInput{"alpha_in_sweep", "model = \"smooth-inelastic\"\nalpha = [0.5, -0.1]\norder = 1\n", "",
                 "alpha: must be a number in (0, 1]"},
        BadInput{"unknown_hcs", "model = \"smooth-inelastic\"\nhcs = \"quadratic\"\norder = 1\n", "",
                 "hcs: must be one of \"nonlinear\", \"linear\""},
        BadInput{"hcs_not_string", "model = \"smooth-inelastic\"\nhcs = 2\norder = 1\n", "", "hcs: must be one of"},
        BadInput{"linear_order_two", "model = \"smooth-inelastic\"\nhcs = \"linear\"\nalpha = 0.5\norder = 2\n", "",
                 "hcs: \"linear\" is the first Sonine approximation"},
        BadInput{"linear_a3",
                 "model = \"smooth-inelastic\"\nhcs = \"linear\"\nalpha = 0.5\norder = 1\ncoefficients = [\"a3\"]\n",
                 "", "coefficients: a3 is not computed"},
        BadInput{"exact_not_rational", "model = \"smooth-inelastic\"\nalpha = 0.5\norder = 2\n", "--exact",
                 "--exact: a requested coefficient is not a rational number"},
        BadInput{"order_above_model_max", "model = \"smooth-inelastic\"\nalpha = 0.5\norder = 21\n", "",
                 "order: must be an integer in [1, 20]"},
        BadInput{"mixture_fractions", kMixture + "fraction = 0.4\n", "",
                 "fraction: the species fractions must sum to 1 (within 1e-12), got 0.9"},
        BadInput{"mixture_mass", kMixture + "fraction = 0.5\n", "--set mass_2=-3", "mass_2: must be a number in (0,"},
        BadInput{"mixture_diameter_zero", kMixture + "fraction = 0.5\n", "--set diameter_1=0",
                 "diameter_1: must be a number in (0,"},
        BadInput{"mixture_alpha_asymmetric",
                 "model = \"mixture\"\norder = 1\nalpha = [[0.9, 0.8], [0.7, 0.9]]\n" + kMixtureSpecies, "",
                 "alpha: the restitution matrix must be symmetric, got alpha[1][2] = 0.8 and alpha[2][1] = 0.7"},
        BadInput{"mixture_alpha_range",
                 "model = \"mixture\"\norder = 1\nalpha = [[0.9, 1.2], [1.2, 0.9]]\n" + kMixtureSpecies, "",
                 "alpha_1_2: must be a number in (0, 1], got 1.2"},
        BadInput{"mixture_alpha_shape", "model = \"mixture\"\norder = 1\nalpha = [[0.9, 0.8]]\n" + kMixtureSpecies, "",
                 "alpha: a restitution matrix must be 2 x 2"},
        BadInput{"mixture_packing", kMixture + "fraction = 0.5\n", "--set packing_fraction=0.5",
                 "packing_fraction: must be a number in [0, 0.5) for dimension = 3"},
        BadInput{"mixture_species_key", kMixture + "fraction = 0.5\ncharge = 1\n", "",
                 "species[2].charge: unknown key; valid keys: diameter, fraction, mass, moment_of_inertia, name"},
        BadInput{"mixture_species_missing", kMixture, "", "species[2].fraction: required"},
        BadInput{"mixture_one_species",
                 "model = \"mixture\"\norder = 1\n[[species]]\nmass = 1\ndiameter = 1\nfraction = 1\n", "",
                 "species: must be an integer in [2, 4], got 1"},
        BadInput{"tracer_dense", kMixture + "fraction = 0.5\n",
                 "--set packing_fraction=0.1 --set 'coefficients=[\"tracer_diffusion_1\"]'",
                 "coefficients: tracer_diffusion_1 is computed for the dilute gas only"},
        BadInput{"mixture_no_third_species", kMixture + "fraction = 0.5\n",
                 "--set 'coefficients=[\"temperature_ratio_3\"]'",
                 "coefficients: unknown coefficient 'temperature_ratio_3'"},
        BadInput{"mixture_transport_order", kMixture + "fraction = 0.5\n", "--set order=13",
                 "order: must be an integer in [1, 12]"},
        BadInput{"mixture_hcs_order", kMixture + "fraction = 0.5\n", "--set hcs_order=6",
                 "hcs_order: must be an integer in [2, 5]"},
        BadInput{"mixture_hcs_order_type", kMixture + "fraction = 0.5\n", "--set hcs_order=2.5",
                 "hcs_order: must be an integer in [2, 5]"}),
    [](const auto& info) { return info.param.label; });

// Without a subcommand the program is misused: exit 2 and a one-line error.
TEST(Cli, MissingSubcommandExitsTwo) {
  const CliRun r = run_gkt("");
  EXPECT_EQ(r.status, 2);
}

// Sticking grains (issue 21; the physics is checked in tests/test_aggregation.cpp): the columns,
// exact mass conservation, the long-format size distribution, ψ of the seed's closed form through
// `gkt table`, and bad input as one line with exit status 2.
TEST(CliAggregation, EvolveTableAndBadInput) {
  const CliRun r = run_gkt("evolve " + scene_path("aggregation_evolve.toml"));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = parse_csv(r.out);
  ASSERT_EQ(rows.size(), 13U);
  EXPECT_EQ(rows[0],
            (std::vector<std::string>{"time", "temperature", "number_density", "mass", "mean_size", "success_factor"}));
  for (std::size_t i = 1; i < rows.size(); ++i) {
    EXPECT_NEAR(std::stod(rows[i][3]), 1.0, 1e-12);
    EXPECT_NEAR(std::stod(rows[i][4]) * std::stod(rows[i][2]), std::stod(rows[i][3]), 1e-12);
  }
  const CliRun dist = run_gkt("evolve " + scene_path("aggregation_evolve.toml") +
                              " --set distribution=true --set points=2 --set sizes=10");
  ASSERT_EQ(dist.status, 0) << dist.err;
  const auto long_rows = parse_csv(dist.out);
  ASSERT_EQ(long_rows.size(), 21U);
  double mass = 0;
  for (std::size_t i = 11; i < long_rows.size(); ++i) mass += std::stod(long_rows[i][6]) * std::stod(long_rows[i][7]);
  EXPECT_NEAR(mass, 1.0, 1e-12);

  const CliRun table = run_gkt("table " + scene_path("aggregation_pair.toml") +
                               " --set critical_energy=1 --set size_j=1 --set 'coefficients=[\"success_factor\"]'");
  ASSERT_EQ(table.status, 0) << table.err;
  const auto t = parse_csv(table.out);
  ASSERT_EQ(t.size(), 2U);
  ASSERT_EQ(t[0][0], "success_factor");
  EXPECT_NEAR(std::stod(t[1][0]), 1 - 2 * std::exp(-1.0), 1e-14);  // liu2011aggregation eq. (48), x = 1

  for (const auto& [args, message] : std::vector<std::pair<std::string, std::string>>{
           {" --set critical_energy=-1", "critical_energy: must be a number in [0, 1000000], got -1"},
           {" --set sizes=1", "sizes: must be an integer in [2, "},
           {" --set sizes=20001", "sizes: must be an integer in [2, 20000], got 20001"},
           {" --set distribution=1", "distribution: must be true or false"},
           {" --set 'times=[1.0]'", "times: unknown key for gkt evolve with model \"aggregation\""},
           {" --set 'kernel=\"foo\"'", "kernel: must be one of \"kinetic\", \"constant\", \"sum\""},
           {" --set 'criterion=\"sticky\"'", "criterion: must be one of"},
           {" --set order=2", "order: unknown key for gkt evolve with model \"aggregation\""},
           {" --set grid_ratio=1.2", "grid_ratio: only with grid = \"geometric\""},
           {" --set 'grid=\"geometric\"' --set grid_ratio=3", "grid_ratio: must be a number in (1, 2]"}}) {
    const CliRun bad = run_gkt("evolve " + scene_path("aggregation_evolve.toml") + args);
    EXPECT_EQ(bad.status, 2) << args << ": " << bad.err;
    EXPECT_NE(bad.err.find(message), std::string::npos) << bad.err;
    EXPECT_EQ(bad.err.find('\n'), bad.err.size() - 1) << bad.err;
  }
}
