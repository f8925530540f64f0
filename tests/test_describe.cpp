// Self-describing output (issue 19 item 6): the column catalogue against docs/conventions.md and
// every model, SI conversions against hand-derived elastic reference values, the JSON a table
// carries and `gkt models --describe`.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include "gkt/models/column_catalogue.hpp"
#include "gkt/models/transport_model.hpp"

namespace {

using gkt::Reduction;

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// One data row of a "canonical name" table of docs/conventions.md.
struct DocRow {
  std::vector<std::string> names;   ///< backticked names outside parentheses (no wildcards)
  std::vector<std::string> models;  ///< backticked model names inside parentheses, or the table's own
  std::string reduced_by;           ///< the "reduced by" cell
  std::string line;
};

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(' '), b = s.find_last_not_of(' ');
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

/// Returns the rows of every table of docs/conventions.md whose header starts "| canonical name";
/// the table under "Mixtures" (header naming [garzo2007mixture]) is the mixture model's.
std::vector<DocRow> documented_columns() {
  const auto models = gkt::transport_model_names();
  const std::set<std::string> model_names(models.begin(), models.end());
  std::istringstream in(read_text(std::filesystem::path(GKT_SOURCE_DIR) / "docs" / "conventions.md"));
  std::vector<DocRow> rows;
  std::string line;
  bool in_table = false, mixture_table = false;
  while (std::getline(in, line)) {
    if (line.starts_with("| canonical name")) {
      in_table = true;
      mixture_table = line.find("garzo2007mixture") != std::string::npos;
      continue;
    }
    if (!in_table) continue;
    if (!line.starts_with("|")) {
      in_table = false;
      continue;
    }
    if (line.starts_with("|---")) continue;
    std::vector<std::string> cells;
    std::size_t start = 1;
    for (std::size_t bar; (bar = line.find('|', start)) != std::string::npos; start = bar + 1)
      cells.push_back(trim(line.substr(start, bar - start)));
    DocRow row;
    row.line = line;
    row.reduced_by = cells.size() > 2 ? cells[2] : "";
    const std::string& first = cells.empty() ? line : cells[0];
    int depth = 0;
    for (std::size_t i = 0; i < first.size(); ++i) {
      if (first[i] == '(') ++depth;
      if (first[i] == ')') --depth;
      if (first[i] != '`') continue;
      const std::size_t close = first.find('`', i + 1);
      const std::string token = first.substr(i + 1, close - i - 1);
      i = close;
      if (depth > 0) {
        if (model_names.contains(token)) row.models.push_back(token);
      } else if (token.find('*') == std::string::npos) {
        row.names.push_back(token);
      }
    }
    if (mixture_table) row.models = {"mixture"};
    rows.push_back(row);
  }
  return rows;
}

/// Returns the index in column_catalogue() of the entry describe_column chose.
std::size_t entry_index(const gkt::ColumnDescription& d) {
  const auto& catalogue = gkt::column_catalogue();
  for (std::size_t k = 0; k < catalogue.size(); ++k)
    if (catalogue[k].name == d.name && catalogue[k].models == d.models) return k;
  return catalogue.size();
}

TEST(ColumnCatalogue, DescribesEveryColumnOfEveryModel) {
  for (const auto& name : gkt::transport_model_names()) {
    const auto model = gkt::make_transport_model(name);
    for (const auto& column : model->coefficient_names()) {
      gkt::ColumnDescription d;
      ASSERT_NO_THROW(d = gkt::describe_column(name, column)) << name << " " << column;
      EXPECT_FALSE(d.meaning.empty()) << column;
      EXPECT_FALSE(d.reduced_by.empty()) << column;
      const auto error = gkt::describe_column(name, column + "_error");
      EXPECT_EQ(error.reduction, d.reduction) << column;
      EXPECT_NE(error.meaning.find("estimated truncation error of " + column), std::string::npos);
    }
  }
  EXPECT_THROW(gkt::describe_column("hard-spheres", "viscosity"), std::invalid_argument);
  EXPECT_THROW(gkt::describe_column("hard-spheres", "omega0"), std::invalid_argument);  // viscoelastic only
}

TEST(ColumnCatalogue, ModelEntriesOverrideGeneralOnes) {
  EXPECT_EQ(gkt::describe_column("smooth-inelastic", "shear_viscosity").reduced_by, "η0");
  EXPECT_EQ(gkt::describe_column("rough", "shear_viscosity").reduced_by, "η0(T_t)");
  EXPECT_EQ(gkt::describe_column("rough-walton", "cooling_rate").reduced_by, "ν0(T_t)");
  EXPECT_EQ(gkt::describe_column("mixture", "shear_viscosity").reduced_by, "η0(m̄, σ̄)");
  EXPECT_EQ(gkt::describe_column("rough", "a11").reduction, Reduction::none);
  EXPECT_NE(gkt::describe_column("rough", "a11").meaning, gkt::describe_column("smooth-inelastic", "a11").meaning);
  EXPECT_EQ(gkt::describe_column("mixture", "mutual_diffusion_2_1").reduction, Reduction::mutual_diffusion);
  EXPECT_EQ(gkt::describe_column("mixture", "a3_species_2").reduction, Reduction::none);
  EXPECT_EQ(gkt::describe_column("mixture", "tracer_diffusion_1").reduction, Reduction::other_reference);
}

TEST(ColumnCatalogue, PatternsMatchIndicesOnly) {
  EXPECT_TRUE(gkt::column_matches("a<k>", "a2"));
  EXPECT_TRUE(gkt::column_matches("a<k>", "a16"));
  EXPECT_FALSE(gkt::column_matches("a<k>", "a"));
  EXPECT_FALSE(gkt::column_matches("a<k>", "a02"));
  EXPECT_FALSE(gkt::column_matches("a<k>", "a2_species_1"));
  EXPECT_TRUE(gkt::column_matches("mutual_diffusion_<i>_<j>", "mutual_diffusion_1_2"));
  EXPECT_TRUE(gkt::column_matches("mutual_diffusion_<i>_<j>", "mutual_diffusion_i_j"));
  EXPECT_FALSE(gkt::column_matches("mutual_diffusion_<i>_<j>", "mutual_diffusion_1"));
  EXPECT_FALSE(gkt::column_matches("shear_viscosity", "shear_viscosity_1"));
}

// The catalogue and docs/conventions.md agree: every documented name is described, with the
// documented reduction (a row naming one column: the same text; several: each entry's text
// inside the row's cell), and every catalogue entry is documented.
TEST(ColumnCatalogue, AgreesWithConventions) {
  const auto rows = documented_columns();
  ASSERT_GE(rows.size(), 30U) << "docs/conventions.md: canonical name tables not found";
  std::vector<bool> documented(gkt::column_catalogue().size(), false);
  for (const auto& row : rows) {
    ASSERT_FALSE(row.names.empty()) << row.line;
    for (const auto& name : row.names) {
      std::vector<std::string> models = row.models;
      if (models.empty()) models = {""};
      for (const auto& model : models) {
        gkt::ColumnDescription d;
        bool found = false;
        try {
          d = gkt::describe_column(model, name);
          found = true;
        } catch (const std::invalid_argument&) {
          for (const auto& m : gkt::transport_model_names()) {  // a row naming no model: the model that has it
            if (found) break;
            try {
              d = gkt::describe_column(m, name);
              found = true;
            } catch (const std::invalid_argument&) {
            }
          }
        }
        ASSERT_TRUE(found) << name << " (" << model << ") is documented but not in the catalogue: " << row.line;
        if (row.names.size() == 1)
          EXPECT_EQ(d.reduced_by, row.reduced_by) << name << " (" << model << ")";
        else
          EXPECT_NE(row.reduced_by.find(d.reduced_by), std::string::npos)
              << name << " (" << model << "): catalogue says '" << d.reduced_by << "', docs '" << row.reduced_by << "'";
        const std::size_t k = entry_index(d);
        ASSERT_LT(k, documented.size());
        documented[k] = true;
      }
    }
  }
  for (std::size_t k = 0; k < documented.size(); ++k)
    EXPECT_TRUE(documented[k]) << gkt::column_catalogue()[k].name << ": in the catalogue, not in docs/conventions.md";
}

TEST(PhysicalUnits, UnitsOfTheReductions) {
  EXPECT_EQ(gkt::si_unit(Reduction::viscosity, 3), "kg m^-1 s^-1");  // Pa s
  EXPECT_EQ(gkt::si_unit(Reduction::viscosity, 2), "kg s^-1");
  EXPECT_EQ(gkt::si_unit(Reduction::conductivity, 3), "kg m s^-3 K^-1");  // W m^-1 K^-1
  EXPECT_EQ(gkt::si_unit(Reduction::self_diffusion, 3), "m^2 s^-1");
  EXPECT_EQ(gkt::si_unit(Reduction::pressure, 3), "kg m^-1 s^-2");  // Pa
  EXPECT_EQ(gkt::si_unit(Reduction::collision_frequency, 2), "s^-1");
  EXPECT_EQ(gkt::si_unit(Reduction::density_heat, 3), "kg m^4 s^-3");  // W m^2
  EXPECT_EQ(gkt::si_unit(Reduction::none, 3), "1");
}

// Hand-derived elastic values (docs/conventions.md "Reference values", Chapman & Cowling's first
// approximation), written out per dimension, not through reference_gas's general-d formula.
TEST(PhysicalUnits, ScalesAreTheElasticFirstApproximation) {
  const double pi = std::numbers::pi, kB = 1.380649e-23;
  const gkt::PhysicalReference argon{6.6335e-26, 3.42e-10, 2.45e25, 273.15};
  const double m = argon.mass, s = argon.diameter, n = argon.number_density, T = kB * argon.temperature;
  const double eta3 = 5 / (16 * s * s) * std::sqrt(m * T / pi);
  const double d3 = 3 / (8 * n * s * s) * std::sqrt(T / (pi * m));
  const auto scale3 = [&](Reduction r) { return gkt::physical_scale(r, 3, argon); };
  EXPECT_NEAR(scale3(Reduction::viscosity), eta3, 1e-14 * eta3);
  EXPECT_NEAR(scale3(Reduction::conductivity), 15.0 / 4 * eta3 * kB / m, 1e-13 * eta3 * kB / m);
  EXPECT_NEAR(scale3(Reduction::self_diffusion), d3, 1e-14 * d3);
  EXPECT_NEAR(scale3(Reduction::collision_frequency), n * T / eta3, 1e-13 * n * T / eta3);
  EXPECT_NEAR(scale3(Reduction::pressure), n * T, 1e-14 * n * T);
  const double v0 = std::sqrt(2 * T / m);
  EXPECT_NEAR(scale3(Reduction::wavenumber), n * T / eta3 / v0, 1e-13 * n * T / eta3 / v0);
  EXPECT_NEAR(scale3(Reduction::length) * scale3(Reduction::wavenumber), 1, 1e-14);
  EXPECT_NEAR(scale3(Reduction::density_heat), T * 15.0 / 4 * eta3 / m / n, 1e-13 * T * 15.0 / 4 * eta3 / m / n);
  EXPECT_EQ(scale3(Reduction::none), 1);

  const gkt::PhysicalReference disks{1e-3, 5e-3, 1e4, 1e20};  // granular disks, T = k_B·1e20 J ≈ 1.4 mJ
  const double m2 = disks.mass, s2 = disks.diameter, n2 = disks.number_density, T2 = kB * disks.temperature;
  const double eta2 = 1 / (2 * s2) * std::sqrt(m2 * T2 / pi);
  EXPECT_NEAR(gkt::physical_scale(Reduction::viscosity, 2, disks), eta2, 1e-14 * eta2);
  EXPECT_NEAR(gkt::physical_scale(Reduction::conductivity, 2, disks), 4 * eta2 * kB / m2, 1e-13 * 4 * eta2 * kB / m2);
  const double d2 = 1 / (2 * n2 * s2) * std::sqrt(T2 / (pi * m2));
  EXPECT_NEAR(gkt::physical_scale(Reduction::self_diffusion, 2, disks), d2, 1e-14 * d2);
}

TEST(PhysicalUnits, RefusesABadReference) {
  EXPECT_THROW(gkt::physical_scale(Reduction::viscosity, 3, {0, 1, 1, 1}), std::invalid_argument);
  EXPECT_THROW(gkt::physical_scale(Reduction::viscosity, 3, {1, NAN, 1, 1}), std::invalid_argument);
  EXPECT_THROW(gkt::physical_scale(Reduction::viscosity, 3, {1, 1, -1, 1}), std::invalid_argument);
  EXPECT_THROW(gkt::physical_scale(Reduction::viscosity, 4, {1, 1, 1, 1}), std::invalid_argument);
  EXPECT_THROW(gkt::physical_scale(Reduction::mobility, 3, {1e-300, 1e-300, 1e-300, 1e-300}), std::invalid_argument);
}

// ---- the gkt program ---------------------------------------------------------------------------

struct CliRun {
  int status = -1;
  std::string out, err;
};

CliRun gkt_run(const std::string& args) {
  static int counter = 0;
  const auto dir = std::filesystem::temp_directory_path();
  const auto tag = std::to_string(::getpid()) + "_" + std::to_string(counter++);
  const auto out = dir / ("gkt_describe_out_" + tag), err = dir / ("gkt_describe_err_" + tag);
  const std::string cmd =
      "timeout 120 " + std::string(GKT_CLI_PATH) + " " + args + " >" + out.string() + " 2>" + err.string();
  const int raw = std::system(cmd.c_str());
  CliRun r{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, read_text(out), read_text(err)};
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

std::string scene(const std::string& name) {
  return (std::filesystem::path(GKT_SOURCE_DIR) / "tables" / "scenes" / name).string();
}

TEST(TableJson, CarriesVersionSceneAndColumnMeanings) {
  const CliRun r = gkt_run("table " + scene("hcs_stability.toml") + " --set 'alpha=[0.9, 0.6]' --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["gkt_version"], GKT_VERSION);
  EXPECT_EQ(doc["units"], "reduced");
  const auto& s = doc["scene"];
  EXPECT_EQ(s["model"], "smooth-inelastic");
  EXPECT_EQ(s["alpha"], nlohmann::json::array({0.9, 0.6}));
  // Keys the scene leaves out are listed with the default the model applied.
  for (const auto& key : s["defaults_applied"]) EXPECT_TRUE(s.contains(key.get<std::string>())) << key;
  EXPECT_EQ(s["scheme"], "standard");
  EXPECT_EQ(s["pair_correlation"], "carnahan-starling");
  ASSERT_EQ(doc["column_descriptions"].size(), doc["columns"].size());
  for (const auto& column : doc["columns"]) ASSERT_TRUE(doc["column_descriptions"].contains(column)) << column;
  const auto& shear = doc["column_descriptions"]["critical_wavenumber_shear"];
  EXPECT_EQ(shear["reduction"], "wavenumber");
  EXPECT_EQ(shear["si_unit"], "m^-1");
  EXPECT_EQ(shear["unit"], "reduced");
  EXPECT_NE(doc["column_descriptions"]["alpha"]["meaning"].get<std::string>().find("restitution"), std::string::npos);
}

TEST(TableJson, EvolveJsonCarriesTheVersion) {
  const CliRun r = gkt_run("evolve " + scene("cooling_constant_alpha.toml") + " --set points=3 --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["gkt_version"], GKT_VERSION);
  EXPECT_EQ(doc["rows"].size(), 3U);
}

TEST(TableJson, CsvBytesAreUnchangedByTheDescription) {
  const CliRun csv = gkt_run("table " + scene("hard_spheres_converged.toml") + " --set order=3");
  ASSERT_EQ(csv.status, 0) << csv.err;
  EXPECT_TRUE(csv.out.starts_with("dimension,shear_viscosity,")) << csv.out;
  EXPECT_EQ(csv.out.find("gkt_version"), std::string::npos);
}

// --units physical on the rough binary (theory.md §19.26): ζ* is reduced by ν0 = nT/η0 of m̄ = Σx_i m_i, σ̄ = Σx_iσ_i
// at T = Σx_i T_t,i, as the smooth mixture's, so --mass, --diameter, --temperature are m̄, σ̄, T and the species'
// own masses and diameters only enter through their ratios: the physical ζ is ζ* ν0 (hand-written ν0), the ratio
// columns stay as they are, and scaling every mass by 10 and every diameter by 3 in the scene changes nothing.
TEST(TableJson, PhysicalUnitsOfTheRoughBinary) {
  const double pi = std::numbers::pi, kB = 1.380649e-23;
  const double m = 1e-26, s = 1e-10, n = 1e25, T = kB * 300;
  const std::string reference =
      " --units physical --mass 1e-26 --diameter 1e-10 --number-density 1e25 --temperature 300 --format json";
  const std::string keys = " --set 'alpha=[0.8]' --set 'beta=[0.5]'";
  const CliRun reduced = gkt_run("table " + scene("rough_mixture_hcs.toml") + keys + " --format json");
  const CliRun physical = gkt_run("table " + scene("rough_mixture_hcs.toml") + keys + reference);
  ASSERT_EQ(reduced.status, 0) << reduced.err;
  ASSERT_EQ(physical.status, 0) << physical.err;
  const auto a = nlohmann::json::parse(reduced.out)["rows"][0];
  const auto doc = nlohmann::json::parse(physical.out);
  const auto b = doc["rows"][0];
  EXPECT_EQ(doc["column_descriptions"]["cooling_rate"]["unit"], "s^-1");
  const double nu0 = n * T / (5 / (16 * s * s) * std::sqrt(m * T / pi));
  EXPECT_NEAR(b["cooling_rate"].get<double>(), a["cooling_rate"].get<double>() * nu0,
              1e-14 * a["cooling_rate"].get<double>() * nu0);
  for (const char* name : {"temperature_ratio_1", "temperature_ratio_2", "rotational_temperature_ratio_1",
                           "rotational_temperature_ratio_2"})
    EXPECT_EQ(b[name].get<double>(), a[name].get<double>()) << name;

  std::ifstream in(std::string(GKT_SOURCE_DIR) + "/tables/scenes/rough_mixture_hcs.toml");
  std::stringstream text;
  text << in.rdbuf();
  std::string scaled = text.str();
  for (const auto& [from, to] :
       std::vector<std::pair<std::string, std::string>>{{"mass = 1\n", "mass = 10\n"},
                                                        {"mass = 4\n", "mass = 40\n"},
                                                        {"diameter = 1\n", "diameter = 3\n"},
                                                        {"diameter = 2\n", "diameter = 6\n"}}) {
    const auto at = scaled.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    scaled.replace(at, from.size(), to);
  }
  const auto path =
      std::filesystem::temp_directory_path() / ("gkt_rough_binary_scaled_" + std::to_string(getpid()) + ".toml");
  std::ofstream(path) << scaled;
  const CliRun rescaled = gkt_run("table " + path.string() + keys + reference);
  std::filesystem::remove(path);
  ASSERT_EQ(rescaled.status, 0) << rescaled.err;
  const auto c = nlohmann::json::parse(rescaled.out)["rows"][0];
  EXPECT_NEAR(c["cooling_rate"].get<double>(), b["cooling_rate"].get<double>(),
              1e-12 * b["cooling_rate"].get<double>());
  EXPECT_NEAR(c["temperature_ratio_1"].get<double>(), b["temperature_ratio_1"].get<double>(), 1e-12);
}

// --units physical: η of the elastic gas at order 1 is η0 (η* = 1) and the conductivity is
// κ* κ0 with κ* = 1; 3D argon and 2D disks against the hand-written first approximation.
TEST(TableJson, PhysicalUnitsConvertTheReducedColumns) {
  const double pi = std::numbers::pi, kB = 1.380649e-23;
  const double m = 6.6335e-26, s = 3.42e-10, n = 2.45e25, kelvin = 273.15, T = kB * kelvin;
  const std::string reference =
      " --units physical --mass 6.6335e-26 --diameter 3.42e-10 --number-density 2.45e25 "
      "--temperature 273.15";
  const CliRun r = gkt_run("table " + scene("hard_spheres_converged.toml") +
                           " --set dimension=3 --set order=1 --format json" + reference);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["units"], "physical");
  EXPECT_EQ(doc["reference"]["temperature"], kelvin);
  EXPECT_EQ(doc["column_descriptions"]["shear_viscosity"]["unit"], "kg m^-1 s^-1");
  const auto& row = doc["rows"][0];
  const double eta0 = 5 / (16 * s * s) * std::sqrt(m * T / pi);
  EXPECT_NEAR(row["shear_viscosity"].get<double>(), eta0, 1e-14 * eta0);
  EXPECT_NEAR(row["thermal_conductivity"].get<double>(), 15.0 / 4 * eta0 * kB / m, 1e-13 * eta0 * kB / m);
  const double d0 = 3 / (8 * n * s * s) * std::sqrt(T / (pi * m));
  EXPECT_NEAR(row["self_diffusion"].get<double>(), d0, 1e-14 * d0);

  // Order 2: η* = 1.015 (hard spheres): the physical column is the reduced one times η0, errors too.
  const CliRun reduced = gkt_run("table " + scene("hard_spheres_converged.toml") +
                                 " --set dimension=3 --set order=2 "
                                 "--format json");
  const CliRun physical = gkt_run("table " + scene("hard_spheres_converged.toml") +
                                  " --set dimension=3 --set order=2 --format json" + reference);
  ASSERT_EQ(physical.status, 0) << physical.err;
  const auto a = nlohmann::json::parse(reduced.out)["rows"][0], b = nlohmann::json::parse(physical.out)["rows"][0];
  EXPECT_NEAR(b["shear_viscosity"].get<double>(), a["shear_viscosity"].get<double>() * eta0, 1e-14 * eta0);
  EXPECT_NEAR(b["shear_viscosity_error"].get<double>(), a["shear_viscosity_error"].get<double>() * eta0,
              1e-2 * a["shear_viscosity_error"].get<double>() * eta0);
  EXPECT_EQ(b["order"], 2);

  // 2D disks: every column times its reduction in SI, dimensionless ones (a2, a3, order) unchanged.
  const CliRun hcs =
      gkt_run("table " + scene("hcs_stability.toml") + " --set alpha=0.8 --set dimension=2 --format json" +
              " --units physical --mass 1e-3 --diameter 5e-3 --number-density 1e4 --temperature 1e20");
  ASSERT_EQ(hcs.status, 0) << hcs.err;
  const auto h = nlohmann::json::parse(hcs.out);
  const CliRun hcs_reduced = gkt_run("table " + scene("hcs_stability.toml") +
                                     " --set alpha=0.8 --set dimension=2 "
                                     "--format json");
  const auto hr = nlohmann::json::parse(hcs_reduced.out);
  const double m2 = 1e-3, n2 = 1e4, T2 = kB * 1e20;
  const double eta2 = 1 / (2 * 5e-3) * std::sqrt(m2 * T2 / pi), kappa2 = 4 * eta2 / m2, nu0 = n2 * T2 / eta2;
  const double v0 = std::sqrt(2 * T2 / m2);
  const std::map<std::string, double> by_hand{{"none", 1},
                                              {"viscosity", eta2},
                                              {"conductivity", kappa2 * kB},
                                              {"density_heat", T2 * kappa2 / n2},
                                              {"collision_frequency", nu0},
                                              {"pressure", n2 * T2},
                                              {"wavenumber", nu0 / v0},
                                              {"length", v0 / nu0}};
  std::size_t converted = 0;
  for (const auto& [column, value] : hr["rows"][0].items()) {
    if (value.is_null() || column.ends_with("_error")) continue;  // errors: three significant digits
    const std::string reduction = h["column_descriptions"][column]["reduction"];
    ASSERT_TRUE(by_hand.contains(reduction)) << column << " " << reduction;
    const double expected = value.get<double>() * by_hand.at(reduction);
    EXPECT_NEAR(h["rows"][0][column].get<double>(), expected, 1e-13 * std::abs(expected)) << column;
    converted += reduction != "none";
  }
  EXPECT_GE(converted, 7U);  // ζ, η, κ, μ, k⊥c, k∥c, L_c (p is listed only for a dense gas)
}

TEST(TableJson, PhysicalUnitsRefuseWhatTheyCannotConvert) {
  const std::string table = "table " + scene("hard_spheres_converged.toml");
  const std::string all = " --mass 1 --diameter 1 --number-density 1 --temperature 1";
  const CliRun swept = gkt_run(table + " --units physical" + all);
  EXPECT_EQ(swept.status, 2);
  EXPECT_NE(swept.err.find("--units physical: dimension must be one value"), std::string::npos) << swept.err;
  const CliRun missing = gkt_run(table + " --set dimension=3 --units physical --mass 1");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("--diameter: required with --units physical"), std::string::npos) << missing.err;
  const CliRun stray = gkt_run(table + " --temperature 300");
  EXPECT_EQ(stray.status, 2);
  EXPECT_NE(stray.err.find("--temperature: only with --units physical"), std::string::npos) << stray.err;
  const CliRun negative = gkt_run(table +
                                  " --set dimension=3 --units physical --mass 1 --diameter -2 "
                                  "--number-density 1 --temperature 1");
  EXPECT_EQ(negative.status, 2);
  EXPECT_NE(negative.err.find("--diameter: must be a finite number > 0, got -2"), std::string::npos) << negative.err;
  const CliRun exact = gkt_run(table + " --set dimension=3 --set order=1 --exact --units physical" + all);
  EXPECT_EQ(exact.status, 2);
  EXPECT_NE(exact.err.find("not with --exact"), std::string::npos) << exact.err;
  const CliRun underflow = gkt_run(table +
                                   " --set dimension=3 --units physical --mass 1e-300 --diameter 1e300 "
                                   "--number-density 1 --temperature 1");
  EXPECT_EQ(underflow.status, 2);
  EXPECT_NE(underflow.err.find("over- or underflow of a double"), std::string::npos) << underflow.err;
  for (const CliRun* r : {&swept, &missing, &stray, &negative, &exact, &underflow})
    EXPECT_TRUE(r->out.empty()) << r->out;
}

TEST(ModelsDescribe, JsonListsEveryModelWithKeysCommandsAndColumns) {
  const CliRun r = gkt_run("models --describe --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["gkt_version"], GKT_VERSION);
  const auto names = gkt::transport_model_names();
  ASSERT_EQ(doc["models"].size(), names.size());
  for (std::size_t k = 0; k < names.size(); ++k) {
    const auto& m = doc["models"][k];
    const auto model = gkt::make_transport_model(names[k]);
    EXPECT_EQ(m["name"], names[k]);
    EXPECT_EQ(m["max_order"], model->max_order());
    EXPECT_EQ(m["columns"].size(), model->coefficient_names().size()) << names[k];
    for (const auto& column : model->coefficient_names()) {
      ASSERT_TRUE(m["columns"].contains(column)) << names[k] << " " << column;
      EXPECT_EQ(m["columns"][column]["reduced_by"], gkt::describe_column(names[k], column).reduced_by);
    }
    const auto params = model->parameters();
    ASSERT_EQ(m["keys"].size(), params.size() + 2) << names[k];  // + order, tolerance
    for (std::size_t p = 0; p < params.size(); ++p) {
      EXPECT_EQ(m["keys"][p]["name"], params[p].name);
      EXPECT_EQ(m["keys"][p]["allowed"], params[p].allowed());
    }
    const bool table = std::find(m["commands"].begin(), m["commands"].end(), "table") != m["commands"].end();
    EXPECT_TRUE(table);
    const bool evolve = std::find(m["commands"].begin(), m["commands"].end(), "evolve") != m["commands"].end();
    EXPECT_EQ(evolve, model->supports(gkt::Capability::evolve)) << names[k];
    EXPECT_EQ(m.contains("evolution_keys"), evolve);
  }
}

TEST(ModelsDescribe, OneModelAsText) {
  const CliRun r = gkt_run("models --describe smooth-inelastic");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.out.starts_with("smooth-inelastic: ")) << r.out;
  EXPECT_NE(r.out.find("  commands: table, formula, evolve, stability\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("    alpha: a number in (0, 1], default 1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("    tolerance: a number in (0, 1], no default"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("    shear_viscosity: shear viscosity η [η0; d = 2: kg s^-1; d = 3: kg m^-1 s^-1]"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("hard-spheres:"), std::string::npos);
  const CliRun unknown = gkt_run("models --describe soft-spheres");
  EXPECT_EQ(unknown.status, 2);
  EXPECT_NE(unknown.err.find("model: unknown model \"soft-spheres\""), std::string::npos) << unknown.err;
  const CliRun plain = gkt_run("models");  // the listing without --describe is as before
  EXPECT_NE(plain.out.find("  coefficients: shear_viscosity thermal_conductivity self_diffusion\n"), std::string::npos);
}

}  // namespace
