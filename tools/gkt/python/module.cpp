// The Python module `gkt` (pybind11): the gkt program's scenes, tables and time series, and the
// per-cell calls of gkt/cell.hpp over NumPy arrays. It is the gkt program's second face: a scene
// goes through the same code as `gkt table` / `gkt evolve` (tools/gkt/scene.cpp,
// table_command.cpp, evolve_command.cpp), so columns, canonical names and error messages are the
// CLI's. Bad input raises ValueError with the CLI's one-line message (pybind11 maps
// std::invalid_argument to ValueError). Long computations and the per-cell loops release the GIL.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include "../describe.hpp"
#include "../dsmc_command.hpp"
#include "../evolve_command.hpp"
#include "../scene.hpp"
#include "../table_command.hpp"
#include "../table_writer.hpp"
#include "gkt/cell.hpp"
#include "gkt/models/transport_model.hpp"
#include "gkt/simulation/uniform_shear_dsmc.hpp"
#include "gkt/transport/common/pair_correlation.hpp"

namespace py = pybind11;

namespace {

using gkt::cli::Table;

/// The default coefficients of `gkt stability` (as in main.cpp): the HCS stability values.
const std::vector<std::string> kStabilityCoefficients{"critical_wavenumber_shear", "critical_wavenumber_heat",
                                                      "critical_length"};

// ---- scenes: a path, TOML text or a dict ---------------------------------------

toml::array to_toml_array(const py::handle& items, const std::string& key);

void insert_value(toml::table& table, const std::string& name, const std::string& key, const py::handle& value);
void push_value(toml::array& array, const std::string& key, const py::handle& value);

/// Returns the TOML table of a dict; `where` names it in errors ("" for the scene itself, else the
/// dotted key of the nested table).
toml::table to_toml_table(const py::handle& mapping, const std::string& where) {
  toml::table table;
  for (const auto& item : py::reinterpret_borrow<py::dict>(mapping)) {
    if (!py::isinstance<py::str>(item.first))
      throw std::invalid_argument((where.empty() ? std::string("scene") : where) + ": keys must be strings, got " +
                                  py::str(py::type::of(item.first).attr("__name__")).cast<std::string>());
    const auto name = item.first.cast<std::string>();
    insert_value(table, name, where.empty() ? name : where + "." + name, item.second);
  }
  return table;
}

/// Passes the TOML value of one Python value of a scene dict to `put`; throws "<key>: …" for
/// types a scene cannot hold.
template <class Put>
void convert(const std::string& key, const py::handle& value, Put&& put) {
  if (py::isinstance<py::bool_>(value)) {
    put(value.cast<bool>());
  } else if (py::isinstance<py::str>(value)) {
    put(value.cast<std::string>());
  } else if (py::isinstance<py::dict>(value)) {
    put(to_toml_table(value, key));
  } else if (py::isinstance<py::float_>(value)) {
    put(value.cast<double>());
  } else if (py::isinstance<py::int_>(value)) {
    int overflow = 0;
    const long long v = PyLong_AsLongLongAndOverflow(value.ptr(), &overflow);
    if (overflow != 0) throw std::invalid_argument(key + ": integer out of range of a TOML integer");
    put(static_cast<int64_t>(v));
  } else if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    put(to_toml_array(value, key));
  } else if (py::hasattr(value, "tolist")) {  // NumPy arrays and scalars
    convert(key, value.attr("tolist")(), put);
  } else {
    throw std::invalid_argument(key + ": unsupported value of type " +
                                py::str(py::type::of(value).attr("__name__")).cast<std::string>() +
                                " (a scene dict holds numbers, strings, booleans, lists and dicts)");
  }
}

/// Inserts the value under `name`; `key` is its dotted path, for errors.
void insert_value(toml::table& table, const std::string& name, const std::string& key, const py::handle& value) {
  convert(key, value, [&](auto&& v) { table.insert_or_assign(name, std::forward<decltype(v)>(v)); });
}

void push_value(toml::array& array, const std::string& key, const py::handle& value) {
  convert(key, value, [&](auto&& v) { array.push_back(std::forward<decltype(v)>(v)); });
}

toml::array to_toml_array(const py::handle& items, const std::string& key) {
  toml::array array;
  for (const auto& item : py::reinterpret_borrow<py::iterable>(items)) push_value(array, key, item);
  return array;
}

/// Returns the scene table of `scene` with `overrides` applied: a dict (converted value by value),
/// an os.PathLike (a file), or a str — TOML text if it holds a newline or '=', else a file path.
toml::table scene_table(const py::object& scene, const std::vector<std::string>& overrides) {
  toml::table table;
  if (py::isinstance<py::dict>(scene)) {
    table = to_toml_table(scene, "");
  } else if (py::isinstance(scene, py::module_::import("os").attr("PathLike"))) {
    return gkt::cli::read_scene_table(py::module_::import("os").attr("fspath")(scene).cast<std::string>(), overrides);
  } else if (py::isinstance<py::str>(scene)) {
    const auto text = scene.cast<std::string>();
    if (text.find('\n') == std::string::npos && text.find('=') == std::string::npos)
      return gkt::cli::read_scene_table(text, overrides);
    table = gkt::cli::parse_scene_text(text, "<string>");
  } else {
    throw std::invalid_argument("scene: must be a path, TOML text or a dict, got " +
                                py::str(py::type::of(scene).attr("__name__")).cast<std::string>());
  }
  gkt::cli::apply_overrides(table, overrides);
  return table;
}

// ---- tables: formatted cells back to NumPy columns ------------------------------

/// Returns the table's columns as a dict {name: 1-D array}: "order" as int64, numeric columns as
/// float64 (the cells are shortest round-trip decimals, so the doubles are the CLI's bit for bit),
/// exact cells (--exact) as fractions.Fraction objects.
py::dict to_columns(const Table& table) {
  py::dict columns;
  const std::size_t rows = table.rows.size();
  const py::object fraction = py::module_::import("fractions").attr("Fraction");
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    const std::string& name = table.columns[c];
    if (name == "order") {
      py::array_t<long long> column(static_cast<py::ssize_t>(rows));
      auto out = column.mutable_unchecked<1>();
      for (std::size_t r = 0; r < rows; ++r) out(static_cast<py::ssize_t>(r)) = std::stoll(table.rows[r][c]);
      columns[py::str(name)] = column;
    } else if (table.numeric[c]) {
      py::array_t<double> column(static_cast<py::ssize_t>(rows));
      auto out = column.mutable_unchecked<1>();
      for (std::size_t r = 0; r < rows; ++r)
        out(static_cast<py::ssize_t>(r)) = std::strtod(table.rows[r][c].c_str(), nullptr);
      columns[py::str(name)] = column;
    } else {
      py::list cells;
      for (std::size_t r = 0; r < rows; ++r) cells.append(fraction(table.rows[r][c]));
      columns[py::str(name)] = py::module_::import("numpy").attr("array")(cells, py::arg("dtype") = "O");
    }
  }
  return columns;
}

void warn(const std::vector<std::string>& warnings) {
  for (const auto& w : warnings) PyErr_WarnEx(PyExc_UserWarning, ("gkt: warning: " + w).c_str(), 1);
  if (PyErr_Occurred()) throw py::error_already_set();  // warnings turned into errors
}

py::dict table(const py::object& scene, const std::vector<std::string>& overrides, bool exact, bool stability) {
  toml::table parsed = scene_table(scene, overrides);
  std::vector<std::string> warnings;
  Table result;
  {
    py::gil_scoped_release release;
    auto loaded = gkt::cli::load_scene(std::move(parsed));
    if (stability && !loaded.coefficients_given) {
      const auto names = gkt::make_transport_model(loaded.model)->coefficient_names();
      if (std::find(names.begin(), names.end(), kStabilityCoefficients.front()) == names.end())
        throw std::invalid_argument("model: \"" + loaded.model + "\" has no stability analysis; use " +
                                    gkt::cli::models_supporting(gkt::Capability::stability));
      loaded.coefficients = kStabilityCoefficients;
    }
    result = gkt::cli::compute_table(loaded, {exact}, warnings);
  }
  warn(warnings);
  return to_columns(result);
}

py::dict evolve(const py::object& scene, const std::vector<std::string>& overrides) {
  const toml::table parsed = scene_table(scene, overrides);
  std::string counters;
  Table result;
  {
    py::gil_scoped_release release;
    result = gkt::cli::evolve(parsed, counters);
  }
  return to_columns(result);
}

py::dict dsmc(const py::object& scene, const std::vector<std::string>& overrides, int jobs) {
  if (jobs < 1 || jobs > 64)
    throw std::invalid_argument("jobs: must be an integer in [1, 64], got " + std::to_string(jobs));
  toml::table parsed = scene_table(scene, overrides);
  gkt::cli::DsmcRunOptions options;
  options.jobs = jobs;
  bool interrupted = false;
  Table result;
  {
    py::gil_scoped_release release;
    result = gkt::cli::dsmc(std::move(parsed), options, interrupted);
  }
  return to_columns(result);
}

/// One run of the uniform-shear DSMC (gkt/simulation/uniform_shear_dsmc.hpp, theory.md §22.5):
/// per batch the reduced shear rate, the stresses P_ij/(2nT) and T/T_initial.
py::dict uniform_shear_dsmc(double alpha, double shear_rate, int dimension, int particles, double relaxation,
                            int batches, double collisions_per_batch, std::uint64_t seed) {
  gkt::DsmcSchedule schedule;
  schedule.particles = particles;
  schedule.relaxation = relaxation;
  schedule.batches = batches;
  schedule.per_batch = collisions_per_batch;
  schedule.seed = seed;
  gkt::UniformShearDsmcRun run;
  {
    py::gil_scoped_release release;
    run = gkt::run_uniform_shear_dsmc(dimension, {alpha, shear_rate}, schedule);
  }
  py::dict out;
  const auto put = [&out](const char* name, const std::vector<double>& values) {
    out[name] = py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
  };
  put("reduced_shear_rate", run.reduced_shear_rate);
  put("stress_xx", run.stress_xx);
  put("stress_yy", run.stress_yy);
  put("stress_zz", run.stress_zz);
  put("stress_xy", run.stress_xy);
  put("temperature", run.temperature);
  return out;
}

py::dict models() {
  py::dict out;
  for (const auto& name : gkt::transport_model_names()) {
    const auto model = gkt::make_transport_model(name);
    py::dict parameters;
    for (const auto& p : model->parameters()) parameters[py::str(p.name)] = p.allowed();
    py::dict entry;
    entry["description"] = model->description();
    entry["coefficients"] = model->coefficient_names();
    entry["parameters"] = parameters;
    entry["max_order"] = model->max_order();
    out[py::str(name)] = entry;
  }
  return out;
}

// ---- per-cell calls over NumPy arrays -------------------------------------------

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// Returns the arrays broadcast against each other (NumPy rules) as contiguous float64 copies.
std::vector<Array> broadcast(const std::vector<py::object>& arrays) {
  const py::object np = py::module_::import("numpy");
  py::tuple views = np.attr("broadcast_arrays")(*py::cast(arrays));
  std::vector<Array> out;
  for (const auto& v : views) out.push_back(Array::ensure(np.attr("ascontiguousarray")(v, "float64")));
  return out;
}

/// Returns {name: array of `shape`} from the fields of per-cell structs.
template <class Values, std::size_t N>
py::dict scatter(const std::vector<Values>& cells,
                 const std::array<std::pair<const char*, double Values::*>, N>& fields,
                 const std::vector<py::ssize_t>& shape) {
  py::dict out;
  for (const auto& [name, member] : fields) {
    py::array_t<double> column(shape);
    double* data = column.mutable_data();
    for (std::size_t i = 0; i < cells.size(); ++i) data[i] = cells[i].*member;
    out[name] = column;
  }
  return out;
}

std::vector<py::ssize_t> shape_of(const Array& a) { return {a.shape(), a.shape() + a.ndim()}; }

/// Returns the columns of a per-cell mixture table with `species` species (BinaryTransport or
/// TernaryTransport cells), each an array of `shape`, under the CLI's canonical names, and a `put` that
/// adds further columns the same way.
template <class Cell>
class MixtureColumns {
 public:
  MixtureColumns(const std::vector<Cell>& cells, std::vector<py::ssize_t> shape, std::size_t species)
      : cells_(cells), shape_(std::move(shape)) {
    put("cooling_rate", [](const Cell& v) { return v.cooling_rate; });
    for (std::size_t i = 0; i < species; ++i)
      put("temperature_ratio_" + std::to_string(i + 1), [i](const Cell& v) { return v.temperature_ratio[i]; });
    put("shear_viscosity", [](const Cell& v) { return v.shear_viscosity; });
    put("thermal_conductivity", [](const Cell& v) { return v.thermal_conductivity; });
    for (std::size_t i = 0; i < species; ++i)
      for (std::size_t j = 0; j < species; ++j)
        put("mutual_diffusion_" + std::to_string(i + 1) + "_" + std::to_string(j + 1),
            [k = species * i + j](const Cell& v) { return v.mutual_diffusion[k]; });
    for (std::size_t i = 0; i < species; ++i) {
      const std::string at = "_" + std::to_string(i + 1);
      put("thermal_diffusion" + at, [i](const Cell& v) { return v.thermal_diffusion[i]; });
      put("pressure_diffusion" + at, [i](const Cell& v) { return v.pressure_diffusion[i]; });
      put("dufour" + at, [i](const Cell& v) { return v.dufour[i]; });
    }
    put("pressure", [](const Cell& v) { return v.pressure; });
    put("bulk_viscosity", [](const Cell& v) { return v.bulk_viscosity; });
    put("cooling_rate_first_order", [](const Cell& v) { return v.cooling_rate_first_order; });
  }

  /// Adds the column `name` with get(cell) at every cell.
  template <class Get>
  void put(const std::string& name, Get get) {
    py::array_t<double> column(shape_);
    double* data = column.mutable_data();
    for (std::size_t i = 0; i < cells_.size(); ++i) data[i] = get(cells_[i]);
    out_[py::str(name)] = column;
  }

  /// Returns the columns.
  [[nodiscard]] py::dict dict() const { return out_; }

 private:
  const std::vector<Cell>& cells_;
  std::vector<py::ssize_t> shape_;
  py::dict out_;
};

py::dict first_sonine(const py::object& alpha, int dimension) {
  const auto in = broadcast({alpha});
  const std::span<const double> a(in[0].data(), static_cast<std::size_t>(in[0].size()));
  std::vector<gkt::FirstSonineValues> cells(a.size());
  {
    py::gil_scoped_release release;
    gkt::first_sonine_values(dimension, a, cells);
  }
  using V = gkt::FirstSonineValues;
  return scatter(
      cells,
      std::array<std::pair<const char*, double V::*>, 5>{{{"a2", &V::a2},
                                                          {"cooling_rate", &V::cooling_rate},
                                                          {"shear_viscosity", &V::shear_viscosity},
                                                          {"thermal_conductivity", &V::thermal_conductivity},
                                                          {"density_heat_coefficient", &V::density_heat_coefficient}}},
      shape_of(in[0]));
}

/// χ and φ dχ/dφ of the named closure at each φ (exact rationals from the double φ, rounded once;
/// a few µs a cell, ~20 times the closed forms it feeds). Throws "packing_fraction: must be a
/// number in [0, φ_max] …" as the models do.
void contact_values(int dimension, const std::string& closure, std::span<const double> phi, std::span<double> chi,
                    std::span<double> phi_dchi) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
  const gkt::PairCorrelation& pc = gkt::pair_correlation(closure);
  const gkt::Rational max = gkt::max_packing_fraction(dimension);
  const double max_phi = max.to_double();
  for (std::size_t i = 0; i < phi.size(); ++i) {
    if (!(phi[i] >= 0 && phi[i] <= max_phi))
      throw std::invalid_argument("packing_fraction: must be a number in [0, " + max.to_decimal_string() +
                                  "] for dimension = " + std::to_string(dimension) + ", got " +
                                  gkt::cli::format_number(phi[i]));
    const gkt::Rational p = gkt::Rational::from_double(phi[i]);
    chi[i] = pc.contact_value(dimension, p).to_double();
    phi_dchi[i] = pc.packing_derivative(dimension, p).to_double();
  }
}

py::dict enskog_first_sonine(const py::object& alpha, const py::object& packing_fraction, int dimension,
                             const py::object& chi, const py::object& phi_dchi, const std::string& pair_correlation) {
  if (chi.is_none() != phi_dchi.is_none())
    throw std::invalid_argument("chi: give both chi and phi_dchi, or neither (then pair_correlation gives them)");
  std::vector<py::object> inputs{alpha, packing_fraction};
  if (!chi.is_none()) {
    inputs.push_back(chi);
    inputs.push_back(phi_dchi);
  }
  const auto in = broadcast(inputs);
  const auto n = static_cast<std::size_t>(in[0].size());
  const std::span<const double> a(in[0].data(), n), phi(in[1].data(), n);
  std::vector<double> chi_values(n), phi_dchi_values(n);
  std::vector<gkt::EnskogState> states(n);
  std::vector<gkt::EnskogFirstSonineValues> cells(n);
  {
    py::gil_scoped_release release;
    if (in.size() == 4) {
      std::copy_n(in[2].data(), n, chi_values.begin());
      std::copy_n(in[3].data(), n, phi_dchi_values.begin());
    } else {
      contact_values(dimension, pair_correlation, phi, chi_values, phi_dchi_values);
    }
    for (std::size_t i = 0; i < n; ++i) states[i] = {phi[i], chi_values[i], phi_dchi_values[i]};
    gkt::enskog_first_sonine_values(dimension, a, states, cells);
  }
  using V = gkt::EnskogFirstSonineValues;
  return scatter(
      cells,
      std::array<std::pair<const char*, double V::*>, 8>{{{"a2", &V::a2},
                                                          {"cooling_rate", &V::cooling_rate},
                                                          {"pressure", &V::pressure},
                                                          {"shear_viscosity", &V::shear_viscosity},
                                                          {"bulk_viscosity", &V::bulk_viscosity},
                                                          {"thermal_conductivity", &V::thermal_conductivity},
                                                          {"density_heat_coefficient", &V::density_heat_coefficient},
                                                          {"cooling_rate_first_order", &V::cooling_rate_first_order}}},
      shape_of(in[0]));
}

/// Returns the row-major s × s restitution matrix α_ij of `alpha`, a number (every pair) or an
/// s × s array; Mixture::validate checks the values and the symmetry.
std::vector<double> restitution_matrix(const py::object& alpha, py::ssize_t s) {
  const py::array_t<double, py::array::c_style | py::array::forcecast> a(alpha);
  const auto size = static_cast<std::size_t>(s * s);
  if (a.ndim() == 0) return std::vector<double>(size, *a.data());
  if (a.ndim() == 2 && a.shape(0) == s && a.shape(1) == s) return {a.data(), a.data() + size};
  const std::string n = std::to_string(s);
  throw std::invalid_argument("alpha: must be a number or a " + n + " x " + n + " restitution matrix");
}

/// Returns the f^(0) a table is built about (theory.md §17.14): "maxwellian" (hcs_order ignored, as
/// MixtureReference ignores it), or "linear" / "nonlinear", the HCS of that scheme with a_2 … a_K in f^(0), K =
/// hcs_order (the table refuses K outside [2, 6]).
gkt::MixtureReference table_reference(const std::string& reference, int hcs_order) {
  if (reference == "maxwellian") return {};
  if (reference == "linear") return {gkt::MixtureHcsScheme::linear, hcs_order};
  if (reference == "nonlinear") return {gkt::MixtureHcsScheme::nonlinear, hcs_order};
  throw std::invalid_argument("reference: must be \"maxwellian\", \"linear\" or \"nonlinear\", got \"" + reference +
                              "\"");
}

/// A binary's Navier–Stokes table (gkt/transport/mixture/mixture_transport_table.hpp) built once,
/// evaluated per cell over NumPy arrays of (x_1, n, T).
class BinaryTable {
 public:
  BinaryTable(const std::array<double, 2>& mass, const std::array<double, 2>& diameter, const py::object& alpha,
              int dimension, int order, int nodes, double max_packing_fraction, int packing_nodes, double tolerance,
              const std::array<double, 2>& fraction_range, const std::string& reference, int hcs_order)
      : table_(build(mass, diameter, alpha, dimension, order, nodes, max_packing_fraction, packing_nodes, tolerance,
                     fraction_range, table_reference(reference, hcs_order))) {}

  [[nodiscard]] double interpolation_error() const { return table_->interpolation_error(); }
  [[nodiscard]] double validation_error() const { return table_->validation_error(); }
  /// Returns {intervals, solves, seconds}: what the build cost.
  [[nodiscard]] py::dict build_cost() const {
    py::dict out;
    out["intervals"] = table_->intervals();
    out["solves"] = table_->build_solves();
    out["seconds"] = table_->build_seconds();
    return out;
  }

  /// Returns the Navier–Stokes set at every (x_1, n, T) (broadcast) in the caller's units.
  py::dict evaluate(const py::object& fraction_1, const py::object& number_density,
                    const py::object& temperature) const {
    const auto in = broadcast({fraction_1, number_density, temperature});
    const auto n = static_cast<std::size_t>(in[0].size());
    std::vector<gkt::BinaryTransport> cells(n);
    {
      py::gil_scoped_release release;
      gkt::evaluate(*table_, {in[0].data(), n}, {in[1].data(), n}, {in[2].data(), n}, cells);
    }
    return MixtureColumns<gkt::BinaryTransport>(cells, shape_of(in[0]), 2).dict();
  }

 private:
  std::shared_ptr<const gkt::BinaryTransportTable> table_;

  static std::shared_ptr<const gkt::BinaryTransportTable> build(
      const std::array<double, 2>& mass, const std::array<double, 2>& diameter, const py::object& alpha, int dimension,
      int order, int nodes, double max_packing_fraction, int packing_nodes, double tolerance,
      const std::array<double, 2>& fraction_range, const gkt::MixtureReference& reference) {
    gkt::Mixture mixture =
        gkt::make_mixture(dimension, {{mass[0], diameter[0], 0.5, ""}, {mass[1], diameter[1], 0.5, ""}}, 1.0);
    mixture.alpha = restitution_matrix(alpha, 2);
    mixture.validate();
    py::gil_scoped_release release;
    return std::make_shared<const gkt::BinaryTransportTable>(mixture, order, nodes, max_packing_fraction, packing_nodes,
                                                             tolerance, fraction_range, reference);
  }
};

/// A ternary's Navier–Stokes table, dilute or dense (gkt/transport/mixture/ternary_transport_table.hpp),
/// built once, evaluated per cell over NumPy arrays of (x_1, x_2, n, T).
class TernaryTable {
 public:
  TernaryTable(const std::array<double, 3>& mass, const std::array<double, 3>& diameter, const py::object& alpha,
               int dimension, int order, int nodes, double tolerance, int max_nodes, double max_packing_fraction,
               int packing_nodes, const std::string& reference, int hcs_order)
      : table_(build(mass, diameter, alpha, dimension, order, nodes, tolerance, max_nodes, max_packing_fraction,
                     packing_nodes, table_reference(reference, hcs_order))) {}

  [[nodiscard]] double interpolation_error() const { return table_->interpolation_error(); }
  [[nodiscard]] double validation_error() const { return table_->validation_error(); }
  /// Returns {pieces, nodes_per_axis, packing_nodes, solves, seconds}: what the build cost.
  [[nodiscard]] py::dict build_cost() const {
    py::dict out;
    out["pieces"] = table_->pieces();
    out["nodes_per_axis"] = table_->nodes_per_axis();
    out["packing_nodes"] = table_->packing_nodes();
    out["solves"] = table_->build_solves();
    out["seconds"] = table_->build_seconds();
    return out;
  }

  /// Returns the Navier–Stokes set at every (x_1, x_2, n, T) (broadcast) in the caller's units.
  py::dict evaluate(const py::object& fraction_1, const py::object& fraction_2, const py::object& number_density,
                    const py::object& temperature) const {
    const auto in = broadcast({fraction_1, fraction_2, number_density, temperature});
    const auto n = static_cast<std::size_t>(in[0].size());
    std::vector<gkt::TernaryTransport> cells(n);
    {
      py::gil_scoped_release release;
      gkt::evaluate(*table_, {in[0].data(), n}, {in[1].data(), n}, {in[2].data(), n}, {in[3].data(), n}, cells);
    }
    return MixtureColumns<gkt::TernaryTransport>(cells, shape_of(in[0]), 3).dict();
  }

 private:
  std::shared_ptr<const gkt::TernaryTransportTable> table_;

  static std::shared_ptr<const gkt::TernaryTransportTable> build(const std::array<double, 3>& mass,
                                                                 const std::array<double, 3>& diameter,
                                                                 const py::object& alpha, int dimension, int order,
                                                                 int nodes, double tolerance, int max_nodes,
                                                                 double max_packing_fraction, int packing_nodes,
                                                                 const gkt::MixtureReference& reference) {
    gkt::Mixture mixture = gkt::make_mixture(dimension,
                                             {{mass[0], diameter[0], 1.0 / 3, ""},
                                              {mass[1], diameter[1], 1.0 / 3, ""},
                                              {mass[2], diameter[2], 1 - 2.0 / 3, ""}},
                                             1.0);
    mixture.alpha = restitution_matrix(alpha, 3);
    mixture.validate();
    py::gil_scoped_release release;
    return std::make_shared<const gkt::TernaryTransportTable>(mixture, order, nodes, tolerance, max_nodes,
                                                              max_packing_fraction, packing_nodes, reference);
  }
};

}  // namespace

PYBIND11_MODULE(gkt, m) {
  m.doc() =
      "gkt: Chapman-Enskog transport coefficients of granular and molecular gases from exact Sonine "
      "expansions.\n\nScenes are the gkt program's (docs/conventions.md): a path, TOML text or a dict. "
      "Columns have the CLI's canonical names; bad input raises ValueError with the CLI's one-line message.";
  m.attr("__version__") = GKT_VERSION;

  m.def("models", &models,
        "Returns {model name: {description, coefficients, parameters: {name: allowed values}, max_order}}, "
        "as `gkt models` lists them.");
  m.def(
      "table",
      [](const py::object& scene, const std::vector<std::string>& overrides, bool exact) {
        return table(scene, overrides, exact, false);
      },
      py::arg("scene"), py::kw_only(), py::arg("overrides") = std::vector<std::string>{}, py::arg("exact") = false,
      "Returns the table of `gkt table` as {column: 1-D NumPy array} (swept parameters, coefficients, "
      "<coefficient>_error, order).\n\n"
      "scene: a path (str or os.PathLike), TOML text (a str holding a newline or '='), or a dict (nested "
      "dicts for ranges, a list of dicts for [[species]]; NumPy arrays become sweep lists).\n"
      "overrides: ['KEY=VALUE', ...] applied like --set. exact: cells as fractions.Fraction (as --exact).\n"
      "A tolerance not reached gives a UserWarning with the CLI's warning line. The GIL is released while "
      "computing.");
  m.def(
      "stability",
      [](const py::object& scene, const std::vector<std::string>& overrides) {
        return table(scene, overrides, false, true);
      },
      py::arg("scene"), py::kw_only(), py::arg("overrides") = std::vector<std::string>{},
      "Returns the table of `gkt stability` (critical wave numbers and length of the HCS) as "
      "{column: array}; scene and overrides as in table().");
  m.def("evolve", &evolve, py::arg("scene"), py::kw_only(), py::arg("overrides") = std::vector<std::string>{},
        "Returns the time series of `gkt evolve` (time, collisions, temperature, a2, …, cooling_rate, and "
        "any requested coefficients) as {column: array}; scene and overrides as in table().");
  m.def("dsmc", &dsmc, py::arg("scene"), py::kw_only(), py::arg("overrides") = std::vector<std::string>{},
        py::arg("jobs") = 1,
        "Returns the table of `gkt dsmc` (the direct simulation Monte Carlo of docs/theory.md section 21) as "
        "{column: array}: one row of coefficients (a2, a3, cooling_rate, temperature_ratio_i, ...) each with its "
        "<name>_error (standard error over the independent runs), or with [output] distribution = true the speed "
        "histogram, or with haff = true T(t)/T0 against Haff's law. scene and overrides as in table(); jobs: "
        "runs simulated in parallel (1 to 64; the result does not depend on it). The GIL is released while "
        "simulating.");
  m.def("uniform_shear_dsmc", &uniform_shear_dsmc, py::arg("alpha"), py::arg("shear_rate"), py::kw_only(),
        py::arg("dimension") = 2, py::arg("particles") = 2000, py::arg("relaxation") = 50.0, py::arg("batches") = 10,
        py::arg("collisions_per_batch") = 10.0, py::arg("seed") = 1,
        "Returns one run of the uniform-shear-flow DSMC (docs/theory.md section 22.5; "
        "gkt::run_uniform_shear_dsmc) as {column: array over the batches}: reduced_shear_rate "
        "(a l/sqrt(2T/m)), stress_xx, stress_yy, stress_zz (0 in 2D), stress_xy (P_ij/(2nT)) and temperature "
        "(T/T_initial), each sampled at the end of a batch. shear_rate is a/nu0(T_initial) (start at Grad's "
        "value, `gkt.table` with model \"uniform-shear\"); relaxation and collisions_per_batch are collisions "
        "per particle. Average independent runs (different seeds) for error bars. Bad input raises ValueError "
        "naming the field. The GIL is released while simulating.");
  m.def("first_sonine", &first_sonine, py::arg("alpha"), py::kw_only(), py::arg("dimension") = 3,
        "Returns the dilute first-Sonine set {a2, cooling_rate, shear_viscosity, thermal_conductivity, "
        "density_heat_coefficient} (reduced as in docs/conventions.md: zeta* = zeta/nu0, eta* = eta/eta0, "
        "kappa* = kappa/kappa0, mu* = n mu/(T kappa0)) at every alpha of an array (theory.md (10.8)), in the "
        "array's shape. Per cell: gkt::first_sonine_values (gkt/cell.hpp), the GIL released.");
  m.def("enskog_first_sonine", &enskog_first_sonine, py::arg("alpha"), py::arg("packing_fraction"), py::kw_only(),
        py::arg("dimension") = 3, py::arg("chi") = py::none(), py::arg("phi_dchi") = py::none(),
        py::arg("pair_correlation") = std::string("carnahan-starling"),
        "Returns the dense (Enskog) first-Sonine set {a2, cooling_rate, pressure, shear_viscosity, "
        "bulk_viscosity, thermal_conductivity, density_heat_coefficient, cooling_rate_first_order} (reduced as "
        "in docs/conventions.md; theory.md section 15.7) at every (alpha, packing_fraction), broadcast as NumPy "
        "does. chi and phi_dchi (the contact value and phi dchi/dphi) default to the named pair correlation, "
        "evaluated exactly per cell (a few microseconds; pass both arrays to skip it). "
        "Per cell: gkt::enskog_first_sonine_values (gkt/cell.hpp), the GIL released.");

  py::class_<BinaryTable>(m, "BinaryTransportTable",
                          "The Navier-Stokes set of a granular binary, solved once on Chebyshev nodes of x_1 (and "
                          "phi) and interpolated per cell (docs/theory.md section 17.8, dense 18.10).")
      .def(py::init<const std::array<double, 2>&, const std::array<double, 2>&, const py::object&, int, int, int,
                    double, int, double, const std::array<double, 2>&, const std::string&, int>(),
           py::arg("mass"), py::arg("diameter"), py::arg("alpha"), py::kw_only(), py::arg("dimension") = 3,
           py::arg("order") = 1, py::arg("nodes") = 24, py::arg("max_packing_fraction") = 0.0,
           py::arg("packing_nodes") = 12, py::arg("tolerance") = 1e-3,
           py::arg("fraction_range") = std::array<double, 2>{0.0, 1.0}, py::arg("reference") = "maxwellian",
           py::arg("hcs_order") = 2,
           "Solves the binary (masses and diameters of species 1, 2; alpha a number or a symmetric 2 x 2 "
           "matrix) at Sonine order `order` on `nodes` points of x_1 in [0, 1] and, if max_packing_fraction > 0, "
           "`packing_nodes` points of phi in [0, max_packing_fraction]; refines the nodes and splits x_1 into "
           "intervals until the interpolation error is at most `tolerance` at every point checked, or raises "
           "ValueError naming the error reached and the x_1 interval. fraction_range = (x_low, x_high) limits the "
           "table to those compositions (e.g. below a pole of the truncated solution); evaluate then raises "
           "ValueError outside it. reference: the f0 every node is solved about, \"maxwellian\" (GDH's) or "
           "\"linear\" / \"nonlinear\", the HCS of that scheme with its cumulants a_2 ... a_K in f0, K = hcs_order in "
           "[2, 6] (docs/theory.md section 17.14; each node then costs ~20 times more). The GIL is released while "
           "solving.")
      .def_property_readonly("interpolation_error", &BinaryTable::interpolation_error,
                             "Returns the largest interpolation error of the reduced coefficients measured at build "
                             "time, between the nodes and at independent validation points (relative to "
                             "max(1, |value|)).")
      .def_property_readonly("validation_error", &BinaryTable::validation_error,
                             "Returns the interpolation error at the independent validation points alone.")
      .def_property_readonly("build_cost", &BinaryTable::build_cost,
                             "Returns {intervals, solves, seconds}: the x_1 intervals, the mixture solves and the "
                             "wall-clock seconds of the build.")
      .def("evaluate", &BinaryTable::evaluate, py::arg("fraction_1"), py::arg("number_density"), py::arg("temperature"),
           "Returns {cooling_rate, temperature_ratio_i, shear_viscosity, thermal_conductivity, "
           "mutual_diffusion_i_j, thermal_diffusion_i, pressure_diffusion_i, dufour_i, pressure, bulk_viscosity, "
           "cooling_rate_first_order} at every (x_1, n, T), broadcast as NumPy does, in the caller's units "
           "(mass, length, T in energy); nan beyond the table's phi_max. Per cell: gkt::evaluate (gkt/cell.hpp), "
           "the GIL released.");

  py::class_<TernaryTable>(m, "TernaryTransportTable",
                           "The Navier-Stokes set of a granular ternary, solved once on Chebyshev-Lobatto nodes of "
                           "the Duffy square of the composition triangle (x_1 = u, x_2 = (1 - u) v) (and phi) and "
                           "interpolated per cell (docs/theory.md section 17.8, \"Ternary tables\"; dense 18.10).")
      .def(py::init<const std::array<double, 3>&, const std::array<double, 3>&, const py::object&, int, int, int,
                    double, int, double, int, const std::string&, int>(),
           py::arg("mass"), py::arg("diameter"), py::arg("alpha"), py::kw_only(), py::arg("dimension") = 3,
           py::arg("order") = 1, py::arg("nodes") = 9, py::arg("tolerance") = 1e-3, py::arg("max_nodes") = 33,
           py::arg("max_packing_fraction") = 0.0, py::arg("packing_nodes") = 5, py::arg("reference") = "maxwellian",
           py::arg("hcs_order") = 2,
           "Solves the ternary (masses and diameters of species 1, 2, 3; alpha a number or a symmetric "
           "3 x 3 matrix) at Sonine order `order` on nodes x nodes points of the Duffy square and, if "
           "max_packing_fraction > 0, `packing_nodes` points of phi in [0, max_packing_fraction]; refines every "
           "axis (K -> 2K - 1, up to max_nodes) and splits the square into rectangles until the interpolation "
           "error is at most `tolerance` at every point checked, or raises ValueError naming the error reached, "
           "the point (x_1, x_2) and the region of x_1 and x_2/(1 - x_1) (and phi) (e.g. around a pole of the "
           "truncated solution). reference and hcs_order as for BinaryTransportTable. The GIL is released while "
           "solving.")
      .def_property_readonly("interpolation_error", &TernaryTable::interpolation_error,
                             "Returns the largest interpolation error of the reduced coefficients measured at build "
                             "time, at the midpoints and at independent validation points (relative to "
                             "max(1, |value|)).")
      .def_property_readonly("validation_error", &TernaryTable::validation_error,
                             "Returns the interpolation error at the independent validation points alone.")
      .def_property_readonly("build_cost", &TernaryTable::build_cost,
                             "Returns {pieces, nodes_per_axis, packing_nodes, solves, seconds}: the rectangles of the "
                             "Duffy square, the largest nodes per axis and in phi of a piece (1 in phi when dilute), "
                             "the mixture solves and the wall-clock seconds of the build.")
      .def("evaluate", &TernaryTable::evaluate, py::arg("fraction_1"), py::arg("fraction_2"), py::arg("number_density"),
           py::arg("temperature"),
           "Returns {cooling_rate, temperature_ratio_i, shear_viscosity, thermal_conductivity, "
           "mutual_diffusion_i_j, thermal_diffusion_i, pressure_diffusion_i, dufour_i, pressure, bulk_viscosity, "
           "cooling_rate_first_order} (i, j = 1, 2, 3) at every (x_1, x_2, n, T), broadcast as NumPy does, in the "
           "caller's units (mass, length, T in energy); x_1, x_2 >= 0 with x_1 + x_2 <= 1 (x_3 = 1 - x_1 - x_2); "
           "nan beyond the table's phi_max. Per cell: gkt::evaluate "
           "(gkt/cell.hpp), the GIL released.");
}
