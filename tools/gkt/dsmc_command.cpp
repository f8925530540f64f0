#include "dsmc_command.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <numbers>
#include <set>
#include <stdexcept>
#include <thread>

#include "gkt/models/transport_model.hpp"
#include "gkt/operators/viscoelastic_hierarchy.hpp"
#include "gkt/simulation/gravity_column_dsmc.hpp"
#include "gkt/simulation/homogeneous_dsmc.hpp"
#include "gkt/simulation/random_stream.hpp"
#include "gkt/simulation/shear_viscosity_dsmc.hpp"
#include "gkt/simulation/uniform_shear_dsmc.hpp"
#include "gkt/transport/closed_forms/uniform_shear_flow.hpp"
#include "gkt/transport/common/pair_correlation.hpp"
#include "scene.hpp"

namespace gkt::cli {

namespace {

constexpr int kHistogramBins = 50;  // c = v/v0 in [0, 5)
constexpr double kHistogramWidth = 0.1;
constexpr long kMaxParticles = 10000000;  // 10^7 particles: ~0.25 GB of velocities
constexpr long kMaxRuns = 100000;
constexpr double kMaxCollisions = 1e6;    // collisions per particle (sampled or relaxation)
constexpr double kMaxColumnTime = 1e6;    // gravity-column: settle_time, sample_time (√(σ/g))
constexpr long kMaxColumnCells = 100000;  // gravity-column: lid_height / cell_height

std::invalid_argument error(const std::string& message) { return std::invalid_argument(message); }

enum class Family { smooth, viscoelastic, mixture, rough, walton, shear, column };
enum class Output { summary, distribution, haff };

/// A validated DSMC scene.
struct DsmcScene {
  std::string model;
  Family family = Family::smooth;
  int dimension = 3;
  DsmcSchedule schedule;
  long runs = 0;
  std::uint64_t seed = 0;
  Output output = Output::summary;
  SmoothRestitution restitution;
  // smooth-inelastic: the Enskog gas at packing fraction φ, χ(φ) of the chosen closure (theory.md §21.7)
  double packing_fraction = 0, pair_correlation = 1;
  std::vector<DsmcSpecies> species;
  std::vector<double> alpha;  // s × s
  RoughDsmcParameters rough;
  UniformShearDsmcParameters shear;
  GravityColumnDsmcParameters column;  // gravity-column: the seed is set per run
  // smooth-inelastic: the strained-HCS measurement of η* (theory.md §21.6); 0 kicks: none
  long viscosity_kicks = 0;
  double viscosity_window = 20;
  ShearViscosityDsmcParameters viscosity;
};

/// Returns the single number `key` of the scene (a list or table is refused); throws if absent.
Rational required_number(const toml::table& t, const std::string& key, const std::string& allowed) {
  const auto* node = t.get(key);
  if (node == nullptr) throw error(key + ": required (" + allowed + ")");
  if (node->is_array() || node->is_table())
    throw error(key + ": must be a single number (" + allowed + "); gkt dsmc does not sweep");
  return scene_number(*node, key);
}

/// Returns the integer `key` in [min, max] (required).
long required_integer(const toml::table& t, const std::string& key, long min, long max) {
  const std::string allowed = "an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
  const Rational v = required_number(t, key, allowed);
  if (v < Rational(min) || v > Rational(max) || Rational(std::lround(v.to_double())) != v)
    throw error(key + ": must be " + allowed + ", got " + v.to_decimal_string());
  return std::lround(v.to_double());
}

/// Returns the number `key` in (min, max] (required).
double required_real(const toml::table& t, const std::string& key, double min, double max, bool min_inclusive) {
  const std::string allowed =
      std::string("a number in ") + (min_inclusive ? "[" : "(") + format_number(min) + ", " + format_number(max) + "]";
  const double v = required_number(t, key, allowed).to_double();
  if (v < min || (v == min && !min_inclusive) || v > max)
    throw error(key + ": must be " + allowed + ", got " + format_number(v));
  return v;
}

/// Returns the model's parameter `key`, checked against the model's own schema (its range and message).
double model_number(const toml::table& t, const TransportModel& model, const std::string& key,
                    const std::string& schema_key = "") {
  const std::string name = schema_key.empty() ? key : schema_key;
  const auto specs = model.parameters();
  const auto it = std::find_if(specs.begin(), specs.end(), [&](const ParameterSpec& s) { return s.name == name; });
  if (it == specs.end()) throw std::logic_error("dsmc: model \"" + model.name() + "\" has no parameter " + name);
  const Rational v = required_number(t, key, it->allowed());
  it->check(v);
  return v.to_double();
}

/// Reads the optional packing_fraction (range of the model's schema at this dimension) and
/// pair_correlation (its registry) of the dense smooth gas into s (theory.md §21.7, §22.8);
/// `model` is smooth-inelastic's schema (uniform-shear's `gkt table` is dilute: the keys are not its own).
void read_dense_scene(const toml::table& t, const TransportModel& model, DsmcScene& s) {
  ParameterPoint fixed;
  fixed.numbers["dimension"] = Rational(s.dimension);
  const auto specs = model.scene_parameters(fixed);
  auto spec = [&](const std::string& name) {
    const auto it = std::find_if(specs.begin(), specs.end(), [&](const ParameterSpec& p) { return p.name == name; });
    if (it == specs.end()) throw std::logic_error("dsmc: model \"" + model.name() + "\" has no parameter " + name);
    return *it;
  };
  const ParameterSpec phi_spec = spec("packing_fraction"), closure_spec = spec("pair_correlation");
  Rational phi = phi_spec.default_value;
  if (t.contains("packing_fraction")) {
    phi = required_number(t, "packing_fraction", phi_spec.allowed());
    phi_spec.check(phi);
  }
  std::string closure = closure_spec.choices.front();
  if (const auto* node = t.get("pair_correlation")) {
    if (!node->is_string())
      throw error("pair_correlation: must be a string, one of " + join(closure_spec.choices, "\""));
    closure = node->as_string()->get();
    closure_spec.check(closure);
  }
  s.packing_fraction = phi.to_double();
  s.pair_correlation = pair_correlation(closure).contact_value(s.dimension, phi).to_double();
}

/// Reads the optional [output] table.
Output read_output(const toml::table& t) {
  const auto* node = t.get("output");
  if (node == nullptr) return Output::summary;
  const auto* table = node->as_table();
  if (table == nullptr) throw error("output: must be a table, e.g. [output] distribution = true or haff = true");
  bool distribution = false, haff = false;
  for (const auto& [key, value] : *table) {
    const std::string k(key.str());
    if (k != "distribution" && k != "haff")
      throw error("output." + quote_short(k) + ": unknown key; valid keys: distribution, haff");
    if (!value.is_boolean()) throw error("output." + k + ": must be true or false");
    (k == "distribution" ? distribution : haff) = value.as_boolean()->get();
  }
  if (distribution && haff) throw error("output: choose one of distribution and haff per run, not both");
  return distribution ? Output::distribution : (haff ? Output::haff : Output::summary);
}

/// Reads the gravity-column keys (docs/conventions.md "gkt dsmc contract"; theory.md §23.3) into
/// s.column; the model's own keys are checked against the gravity-column schema.
void read_column_scene(const toml::table& t, const TransportModel& model, DsmcScene& s) {
  GravityColumnDsmcParameters& c = s.column;
  c.dimension = s.dimension;
  c.alpha = model_number(t, model, "alpha");
  c.particles_per_area = model_number(t, model, "particles_per_area");
  if (t.contains("floor")) {
    const auto* floor = t.get("floor");
    if (!floor->is_string() || floor->as_string()->get() != "temperature")
      throw error(
          "floor: must be \"temperature\" for gkt dsmc with model \"gravity-column\" (the simulated floor is a "
          "thermal wall at floor_value; compare with a heat-flux floor through the printed heat_flux)");
  }
  c.floor_temperature = model_number(t, model, "floor_value");
  if (!std::isfinite(c.floor_temperature)) throw error("floor_value: must be finite");
  c.lid_height = model_number(t, model, "lid_height");
  if (!std::isfinite(c.lid_height)) throw error("lid_height: must be finite");
  if (t.contains("cell_height")) c.cell_height = required_real(t, "cell_height", 0, 1e6, false);
  const double cells = c.lid_height / c.cell_height;
  if (cells < 2 || cells > static_cast<double>(kMaxColumnCells))
    throw error("cell_height: must give between 2 and " + std::to_string(kMaxColumnCells) +
                " cells below the lid (lid_height / cell_height), got " + format_number(cells));
  if (t.contains("time_step")) c.time_step = required_real(t, "time_step", 0, 1, false);
  if (t.contains("settle_time")) c.settle_time = required_real(t, "settle_time", 0, kMaxColumnTime, true);
  c.sample_time = required_real(t, "sample_time", 0, kMaxColumnTime, false);
  if (c.sample_time < 5 * c.time_step)
    throw error("sample_time: must be at least 5 time_step (one sample every 5 steps), got " +
                format_number(c.sample_time));
  c.particles = static_cast<int>(required_integer(t, "particles", 100, kMaxParticles));
  s.runs = required_integer(t, "runs", 2, kMaxRuns);
  s.seed = static_cast<std::uint64_t>(required_integer(t, "seed", 0, 9007199254740991L));  // 2^53 − 1
  s.output = read_output(t);
  if (s.output != Output::summary)
    throw error(std::string(s.output == Output::haff ? "output.haff" : "output.distribution") +
                ": not available for model \"gravity-column\" (the output is the profile, one row per cell)");
}

DsmcScene read_dsmc_scene(toml::table t) {
  DsmcScene s;
  const auto* model_node = t.get("model");
  const std::vector<std::string> models{"smooth-inelastic", "viscoelastic",  "mixture",       "rough",
                                        "rough-walton",     "uniform-shear", "gravity-column"};
  if (model_node == nullptr || !model_node->is_string())
    throw error("model: required string; gkt dsmc simulates " + join(models, "\""));
  s.model = model_node->as_string()->get();
  const auto at = std::find(models.begin(), models.end(), s.model);
  if (at == models.end())
    throw error("model: \"" + quote_short(s.model) + "\" has no DSMC; gkt dsmc simulates " + join(models, "\""));
  s.family = static_cast<Family>(at - models.begin());
  if (s.family == Family::mixture) flatten_mixture(t);
  const auto model = make_transport_model(s.model);

  std::set<std::string> keys{"model", "dimension", "particles", "runs", "seed", "output"};
  if (s.family != Family::column) keys.insert({"collisions_per_particle", "relaxation", "batches"});
  switch (s.family) {
    case Family::smooth:
      keys.insert(
          {"alpha", "viscosity_kicks", "viscosity_window", "viscosity_kick", "packing_fraction", "pair_correlation"});
      break;
    case Family::viscoelastic:
      keys.insert({"delta_prime", "c1"});
      break;
    case Family::mixture:
      keys.insert({"species", "alpha"});
      break;
    case Family::rough:
      keys.insert({"alpha", "beta", "moment_of_inertia", "temperature_ratio"});
      break;
    case Family::walton:
      keys.insert({"alpha", "beta0", "moment_of_inertia", "friction", "temperature_ratio"});
      break;
    case Family::shear:
      keys.insert({"alpha", "shear_rate", "packing_fraction", "pair_correlation"});
      break;
    case Family::column:  // the model's keys (no `height`: every cell is a row) and the column's schedule in time
      keys.insert({"alpha", "particles_per_area", "floor", "floor_value", "lid_height", "cell_height", "time_step",
                   "settle_time", "sample_time"});
      break;
  }
  for (const auto& [key, value] : t) {
    const std::string k(key.str());
    const bool species_key = s.family == Family::mixture && (k.starts_with("mass_") || k.starts_with("diameter_") ||
                                                             k.starts_with("fraction_") || k.starts_with("alpha_"));
    if (!keys.contains(k) && !species_key)
      throw error(
          quote_short(k) + ": unknown key for gkt dsmc with model \"" + s.model +
          "\"; valid keys: " + join(std::vector<std::string>(keys.begin(), keys.end())) +
          (s.family == Family::mixture ? ", [[species]] tables or mass_i, diameter_i, fraction_i, alpha_i_j" : ""));
  }

  if (s.family == Family::viscoelastic) {
    if (t.contains("dimension") && required_number(t, "dimension", "3") != Rational(3))
      throw error("dimension: must be 3 for model \"viscoelastic\" (spheres)");
    s.dimension = 3;
  } else {
    s.dimension = static_cast<int>(model_number(t, *model, "dimension"));
  }
  if (s.family == Family::column) {
    read_column_scene(t, *model, s);
    return s;
  }
  s.schedule.particles = static_cast<int>(required_integer(t, "particles", 2, kMaxParticles));
  const double sampled = required_real(t, "collisions_per_particle", 0, kMaxCollisions, false);
  // The sheared gas relaxes T towards its steady value as well as the shape of f: a longer default.
  const double default_relaxation = s.family == Family::shear ? 20.0 : 10.0;
  s.schedule.relaxation =
      t.contains("relaxation") ? required_real(t, "relaxation", 0, kMaxCollisions, true) : default_relaxation;
  s.schedule.batches = t.contains("batches") ? static_cast<int>(required_integer(t, "batches", 1, 100000)) : 20;
  s.schedule.per_batch = sampled / s.schedule.batches;
  if (s.schedule.per_batch * s.schedule.particles < 2)
    throw error("collisions_per_particle: must give each of the " + std::to_string(s.schedule.batches) +
                " batches at least one collision (collisions_per_particle * particles / batches >= 2)");
  s.runs = required_integer(t, "runs", 2, kMaxRuns);
  s.seed = static_cast<std::uint64_t>(required_integer(t, "seed", 0, 9007199254740991L));  // 2^53 − 1
  s.output = read_output(t);

  switch (s.family) {
    case Family::smooth:
      s.restitution.alpha = model_number(t, *model, "alpha");
      read_dense_scene(t, *model, s);
      if (t.contains("viscosity_kicks") && s.packing_fraction > 0)
        throw error(
            "viscosity_kicks: the strained-HCS viscosity is simulated for the dilute gas only (packing_fraction = "
            "0): the Enskog collisional transfer of momentum is not simulated");
      if (t.contains("viscosity_kicks")) {
        s.viscosity_kicks = required_integer(t, "viscosity_kicks", 1, 1000000);
        if (s.output != Output::summary)
          throw error("viscosity_kicks: the shear viscosity is a summary column; not with [output] " +
                      std::string(s.output == Output::haff ? "haff" : "distribution"));
      }
      if (t.contains("viscosity_window")) s.viscosity_window = required_real(t, "viscosity_window", 0, 1000, false);
      if (t.contains("viscosity_kick")) s.viscosity.kick = required_real(t, "viscosity_kick", 0, 0.5, false);
      if (s.viscosity_kicks == 0 && (t.contains("viscosity_window") || t.contains("viscosity_kick")))
        throw error("viscosity_kicks: required with viscosity_window or viscosity_kick (kicks per run, >= 1)");
      s.viscosity.alpha = s.restitution.alpha;
      break;
    case Family::viscoelastic: {
      double c1 = 0;  // absent: the model's default (the table's c1 too)
      if (t.contains("c1")) {
        c1 = model_number(t, *model, "c1");
      } else {
        for (const auto& spec : model->parameters())
          if (spec.name == "c1") c1 = spec.default_value.to_double();
      }
      s.restitution.series = ViscoelasticRestitution::hertz(c1).series();
      s.restitution.delta_prime = model_number(t, *model, "delta_prime");
      break;
    }
    case Family::mixture: {
      const long k = t.contains("species") ? required_integer(t, "species", 1, 4) : 0;
      if (k < 1) throw error("species: required ([[species]] tables with mass, diameter, fraction)");
      double fractions = 0;
      long total = 0;
      for (long i = 1; i <= k; ++i) {
        const std::string n = std::to_string(i);
        DsmcSpecies sp;
        sp.mass = model_number(t, *model, "mass_" + n);
        sp.diameter = model_number(t, *model, "diameter_" + n);
        const double x = model_number(t, *model, "fraction_" + n);
        fractions += x;
        sp.count = static_cast<int>(std::lround(x * s.schedule.particles));
        if (sp.count < 1)
          throw error("fraction_" + n + ": gives no particle of species " + n + " among " +
                      std::to_string(s.schedule.particles) + " particles");
        total += sp.count;
        s.species.push_back(sp);
      }
      if (std::abs(fractions - 1) > 1e-12)
        throw error("fraction_i: the fractions must add up to 1, got " + format_number(fractions));
      if (total != s.schedule.particles)
        throw error("particles: fraction_i * particles must be whole numbers of particles (" + std::to_string(total) +
                    " after rounding, not " + std::to_string(s.schedule.particles) + ")");
      s.alpha.assign(static_cast<std::size_t>(k * k), 0);
      for (long i = 0; i < k; ++i)
        for (long j = i; j < k; ++j) {
          const std::string pair = "alpha_" + std::to_string(i + 1) + "_" + std::to_string(j + 1);
          const double a = t.contains(pair) ? model_number(t, *model, pair) : model_number(t, *model, "alpha");
          s.alpha[static_cast<std::size_t>(i * k + j)] = s.alpha[static_cast<std::size_t>(j * k + i)] = a;
        }
      break;
    }
    case Family::rough:
    case Family::walton: {
      s.rough.alpha = model_number(t, *model, "alpha");
      s.rough.beta = model_number(t, *model, s.family == Family::rough ? "beta" : "beta0");
      s.rough.kappa = model_number(t, *model, "moment_of_inertia");
      if (s.family == Family::walton) s.rough.friction = model_number(t, *model, "friction");
      if (t.contains("temperature_ratio"))
        s.rough.initial_temperature_ratio = required_real(t, "temperature_ratio", 0, 1e6, false);
      break;
    }
    case Family::column:
      break;
    case Family::shear: {
      s.shear.alpha = model_number(t, *model, "alpha");
      if (s.shear.alpha == 1)
        throw error(
            "alpha: must be a number in (0, 1) for gkt dsmc with model \"uniform-shear\" (no steady shear "
            "flow at alpha = 1), got 1");
      // a/ν0(T_initial); absent: Grad's steady a* (theory.md (22.6)), so T starts near its steady value.
      s.shear.shear_rate = t.contains("shear_rate") ? required_real(t, "shear_rate", 0, 100, false)
                                                    : uniform_shear_flow_grad(s.dimension, s.shear.alpha).shear_rate;
      read_dense_scene(t, *make_transport_model("smooth-inelastic"), s);
      s.shear.packing_fraction = s.packing_fraction;
      s.shear.pair_correlation = s.pair_correlation;
      if (s.output != Output::summary)
        throw error(std::string(s.output == Output::haff ? "output.haff" : "output.distribution") +
                    ": not available for model \"uniform-shear\" (the steady state has no Haff law; no speed "
                    "histogram)");
      break;
    }
  }
  if (s.output == Output::distribution) {
    if (s.family == Family::mixture) throw error("output.distribution: not available for model \"mixture\"");
    s.schedule.histogram_bins = kHistogramBins;
    s.schedule.histogram_width = kHistogramWidth;
  }
  return s;
}

/// One run's batch series, reduced to the values of the table (plus the trace for Haff's law).
struct RunResult {
  std::vector<double> values;  ///< in the order of the summary columns
  std::vector<double> histogram;
  DsmcTrace trace;
  GravityColumnDsmcProfile column;  ///< gravity-column: the run's profile
};

double batch_mean(const std::vector<double>& x) { return mean_and_error(x).mean; }

/// ⟨x^p⟩ over the Maxwellian, x = c²: Γ(d/2 + p)/Γ(d/2).
double maxwell_power(int d, int p) {
  double m = 1;
  for (int k = 0; k < p; ++k) m *= 0.5 * d + k;
  return m;
}

RunResult simulate(const DsmcScene& s, long run) {
  DsmcSchedule schedule = s.schedule;
  schedule.seed = dsmc_run_seed(s.seed, static_cast<std::uint64_t>(run));
  RunResult r;
  const int d = s.dimension;
  switch (s.family) {
    case Family::smooth:
    case Family::viscoelastic: {
      const auto out = run_smooth_hcs_dsmc(d, s.restitution, schedule, s.pair_correlation);
      // a2 = ⟨c⁴⟩/⟨c⁴⟩_M − 1; a3 from ⟨c⁶⟩ = ⟨x³⟩_M + a2⟨x³S2⟩ + a3⟨x³S3⟩ (S_k ⟂ x³ for k > 3),
      // S2, S3 the Sonine polynomials of index m = d/2 − 1 (docs/theory.md §9).
      const double m = 0.5 * d - 1, x3 = maxwell_power(d, 3), x4 = maxwell_power(d, 4), x5 = maxwell_power(d, 5),
                   x6 = maxwell_power(d, 6);
      const double x3s2 = 0.5 * x5 - (m + 2) * x4 + 0.5 * (m + 1) * (m + 2) * x3;
      const double x3s3 =
          -x6 / 6 + 0.5 * (m + 3) * x5 - 0.5 * (m + 2) * (m + 3) * x4 + (m + 1) * (m + 2) * (m + 3) / 6 * x3;
      const double a2 = batch_mean(out.c4) / maxwell_power(d, 2) - 1;
      const double a3 = (batch_mean(out.c6) - x3 - a2 * x3s2) / x3s3;
      r.values = {a2, a3, batch_mean(out.cooling_rate)};
      r.histogram = out.speed_histogram;
      r.trace = out.trace;
      if (s.viscosity_kicks > 0) {  // a run of its own, from the same seed: kicks perturb a2, a3, ζ*
        DsmcSchedule kicked = schedule;
        kicked.histogram_bins = 0;
        kicked.batches = static_cast<int>(s.viscosity_kicks);
        kicked.per_batch = s.viscosity_window;
        r.values.push_back(batch_mean(run_shear_viscosity_dsmc(d, s.viscosity, kicked).shear_viscosity));
      }
      break;
    }
    case Family::mixture: {
      const auto out = run_mixture_hcs_dsmc(d, s.species, s.alpha, schedule);
      r.values = {batch_mean(out.cooling_rate)};
      for (const auto& x : out.temperature_ratio) r.values.push_back(batch_mean(x));
      for (const auto& x : out.a2) r.values.push_back(batch_mean(x));
      r.trace = out.trace;
      break;
    }
    case Family::rough:
    case Family::walton: {
      const auto out = run_rough_hcs_dsmc(d, s.rough, schedule);
      r.values = {batch_mean(out.temperature_ratio), batch_mean(out.cooling_rate), batch_mean(out.a20),
                  batch_mean(out.a02), batch_mean(out.a11)};
      r.histogram = out.speed_histogram;
      r.trace = out.trace;
      break;
    }
    case Family::column: {
      GravityColumnDsmcParameters p = s.column;
      p.seed = dsmc_run_seed(s.seed, static_cast<std::uint64_t>(run));
      r.column = run_gravity_column_dsmc(p);
      break;
    }
    case Family::shear: {
      const auto out = run_uniform_shear_dsmc(d, s.shear, schedule);
      r.values = {batch_mean(out.reduced_shear_rate), batch_mean(out.stress_xx), batch_mean(out.stress_yy)};
      if (d == 3) r.values.push_back(batch_mean(out.stress_zz));
      r.values.push_back(batch_mean(out.stress_xy));
      break;
    }
  }
  return r;
}

std::vector<std::string> summary_names(const DsmcScene& s) {
  switch (s.family) {
    case Family::smooth:
    case Family::viscoelastic:
      if (s.viscosity_kicks > 0) return {"a2", "a3", "cooling_rate", "shear_viscosity"};
      return {"a2", "a3", "cooling_rate"};
    case Family::mixture: {
      std::vector<std::string> n{"cooling_rate"};
      for (std::size_t i = 1; i <= s.species.size(); ++i) n.push_back("temperature_ratio_" + std::to_string(i));
      for (std::size_t i = 1; i <= s.species.size(); ++i) n.push_back("a2_species_" + std::to_string(i));
      return n;
    }
    case Family::rough:
    case Family::walton:
      return {"temperature_ratio", "cooling_rate", "a20", "a02", "a11"};
    case Family::shear:  // the columns of `gkt table` for uniform-shear (stress_zz in 3D only)
      if (s.dimension == 3) return {"reduced_shear_rate", "stress_xx", "stress_yy", "stress_zz", "stress_xy"};
      return {"reduced_shear_rate", "stress_xx", "stress_yy", "stress_xy"};
    case Family::column:  // the profile's columns besides `height` (the names of `gkt table`, gravity-column)
      return {"number_density", "temperature", "heat_flux"};
  }
  return {};
}

/// Runs every run, `jobs` at a time; the results in run order, whatever the order they finish in.
std::vector<RunResult> simulate_all(const DsmcScene& s, const DsmcRunOptions& options, bool& interrupted) {
  const auto runs = static_cast<std::size_t>(s.runs);
  std::vector<RunResult> results(runs);
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stopping{false};
  std::mutex mutex;
  std::condition_variable finished;
  std::size_t done = 0;
  std::exception_ptr failure;
  auto worker = [&] {
    for (;;) {
      if (stopping.load()) return;
      const std::size_t k = next.fetch_add(1);
      if (k >= runs) return;
      try {
        RunResult r = simulate(s, static_cast<long>(k));
        const std::lock_guard<std::mutex> lock(mutex);
        results[k] = std::move(r);
        ++done;
      } catch (...) {
        const std::lock_guard<std::mutex> lock(mutex);
        if (!failure) failure = std::current_exception();
        stopping = true;
        ++done;
      }
      finished.notify_one();
    }
  };
  const std::size_t threads = std::min<std::size_t>(static_cast<std::size_t>(std::max(options.jobs, 1)), runs);
  std::vector<std::jthread> pool;
  for (std::size_t k = 0; k < threads; ++k) pool.emplace_back(worker);
  {
    std::unique_lock<std::mutex> lock(mutex);
    std::size_t reported = 0;
    while (done < runs && !stopping.load()) {
      finished.wait_for(lock, std::chrono::milliseconds(200));
      if (options.progress && done != reported) {
        reported = done;
        lock.unlock();
        options.progress(reported, runs);
        lock.lock();
      }
      if (options.stop && options.stop()) stopping = true;
    }
  }
  pool.clear();  // joins: a run that started finishes
  if (failure) std::rethrow_exception(failure);
  interrupted = done < runs;
  return results;
}

void add_estimate(std::vector<std::string>& row, const std::vector<double>& values) {
  const DsmcEstimate e = mean_and_error(values);
  row.push_back(format_number(e.mean));
  row.push_back(format_number(e.error));
}

}  // namespace

Table dsmc(toml::table scene, const DsmcRunOptions& options, bool& interrupted) {
  const DsmcScene s = read_dsmc_scene(std::move(scene));
  const auto results = simulate_all(s, options, interrupted);
  Table table;
  table.model = s.model;
  if (interrupted) return table;
  const std::size_t runs = results.size();
  auto column = [&](auto value_of) {
    std::vector<double> x(runs);
    for (std::size_t r = 0; r < runs; ++r) x[r] = value_of(results[r]);
    return x;
  };
  std::vector<std::string> row;
  if (s.family == Family::column) {  // one row per cell: the height of its centre, then n, T, q over the runs
    table.columns = {"height"};
    for (const auto& name : summary_names(s)) {
      table.columns.push_back(name);
      table.columns.push_back(name + "_error");
    }
    const auto& z = results.front().column.z;
    for (std::size_t c = 0; c < z.size(); ++c) {
      row = {format_number(z[c])};
      add_estimate(row, column([c](const RunResult& r) { return r.column.number_density[c]; }));
      add_estimate(row, column([c](const RunResult& r) { return r.column.temperature[c]; }));
      add_estimate(row, column([c](const RunResult& r) { return r.column.heat_flux[c]; }));
      table.rows.push_back(row);
    }
    table.numeric.assign(table.columns.size(), true);
    table.planned_rows = table.rows.size();
    return table;
  }
  switch (s.output) {
    case Output::summary: {
      const auto names = summary_names(s);
      for (std::size_t k = 0; k < names.size(); ++k) {
        table.columns.push_back(names[k]);
        table.columns.push_back(names[k] + "_error");
        add_estimate(row, column([k](const RunResult& r) { return r.values[k]; }));
      }
      table.rows.push_back(row);
      break;
    }
    case Output::distribution: {
      // P(c) per unit c against the Maxwellian 2c^{d−1}e^{−c²}/Γ(d/2), averaged over the bin (Simpson).
      table.columns = {"speed", "density", "density_error", "maxwellian", "ratio", "ratio_error"};
      const int d = s.dimension;
      auto maxwellian = [d](double c) { return 2 * std::pow(c, d - 1) * std::exp(-c * c) / std::tgamma(0.5 * d); };
      for (int b = 0; b < kHistogramBins; ++b) {
        const double lo = b * kHistogramWidth, hi = lo + kHistogramWidth, mid = 0.5 * (lo + hi);
        const double reference = (maxwellian(lo) + 4 * maxwellian(mid) + maxwellian(hi)) / 6;
        const auto density =
            column([b](const RunResult& r) { return r.histogram[static_cast<std::size_t>(b)] / kHistogramWidth; });
        const DsmcEstimate e = mean_and_error(density);
        table.rows.push_back({format_number(mid), format_number(e.mean), format_number(e.error),
                              format_number(reference), format_number(e.mean / reference),
                              format_number(e.error / reference)});
      }
      break;
    }
    case Output::haff: {
      // T(t)/T0 at the end of each batch against Haff's law (1 + ζ* t/2)^{−2}, t in units 1/ν0(T0)
      // and ζ* the mean cooling rate the runs measured (theory.md §21.3).
      table.columns = {"collisions_per_particle", "time", "time_error", "temperature", "temperature_error", "haff"};
      const auto names = summary_names(s);
      const auto k = static_cast<std::size_t>(std::find(names.begin(), names.end(), "cooling_rate") - names.begin());
      const double zeta = mean_and_error(column([k](const RunResult& r) { return r.values[k]; })).mean;
      for (int b = 0; b < s.schedule.batches; ++b) {
        const auto i = static_cast<std::size_t>(b);
        const DsmcEstimate t = mean_and_error(column([i](const RunResult& r) { return r.trace.time[i]; }));
        const DsmcEstimate temperature =
            mean_and_error(column([i](const RunResult& r) { return r.trace.temperature[i]; }));
        const double haff = 1 / ((1 + 0.5 * zeta * t.mean) * (1 + 0.5 * zeta * t.mean));
        table.rows.push_back({format_number((b + 1) * s.schedule.per_batch), format_number(t.mean),
                              format_number(t.error), format_number(temperature.mean), format_number(temperature.error),
                              format_number(haff)});
      }
      break;
    }
  }
  table.numeric.assign(table.columns.size(), true);
  table.planned_rows = table.rows.size();
  return table;
}

}  // namespace gkt::cli
