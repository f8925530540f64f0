#include "describe.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <stdexcept>

#include <flint/fmpz.h>
#include <nlohmann/json.hpp>

#include "table_command.hpp"
#include "table_writer.hpp"

namespace gkt::cli {

namespace {

using Json = nlohmann::ordered_json;

const char* reduction_name(Reduction r) {
  switch (r) {
    case Reduction::none:
      return "none";
    case Reduction::viscosity:
      return "viscosity";
    case Reduction::conductivity:
      return "conductivity";
    case Reduction::self_diffusion:
      return "self_diffusion";
    case Reduction::density_heat:
      return "density_heat";
    case Reduction::collision_frequency:
      return "collision_frequency";
    case Reduction::pressure:
      return "pressure";
    case Reduction::wavenumber:
      return "wavenumber";
    case Reduction::length:
      return "length";
    case Reduction::mutual_diffusion:
      return "mutual_diffusion";
    case Reduction::dufour:
      return "dufour";
    case Reduction::mobility:
      return "mobility";
    case Reduction::other_reference:
      return "other_reference";
  }
  return "none";
}

/// A scene number as JSON: an integer as an integer, anything else as the nearest double.
Json number_json(const Rational& v) {
  if (fmpz_is_one(fmpq_denref(v.raw())) && fmpz_fits_si(fmpq_numref(v.raw()))) return fmpz_get_si(fmpq_numref(v.raw()));
  return v.to_double();
}

/// Returns true for a per-species or per-pair key (mass_1, alpha_1_2): its default is not used
/// when the scene does not give it (the species tables or the scalar alpha do).
bool indexed_key(const std::string& key) {
  return !key.empty() && std::isdigit(static_cast<unsigned char>(key.back())) != 0 &&
         key.find('_') != std::string::npos;
}

/// The SI unit of a reduction where the dimension may be swept.
std::string si_unit_text(Reduction r, const std::optional<int>& dimension) {
  if (dimension) return si_unit(r, *dimension);
  const std::string two = si_unit(r, 2), three = si_unit(r, 3);
  return two == three ? two : "d = 2: " + two + "; d = 3: " + three;
}

Json column_json(const ColumnDescription& d, const std::optional<int>& dimension, bool physical) {
  Json c;
  c["meaning"] = d.meaning;
  c["reduced_by"] = d.reduced_by;
  c["reduction"] = reduction_name(d.reduction);
  c["si_unit"] = si_unit_text(d.reduction, dimension);
  const bool dimensionless = d.reduction == Reduction::none;
  c["unit"] = dimensionless                                           ? "1"
              : physical && d.reduction != Reduction::other_reference ? si_unit_text(d.reduction, dimension)
                                                                      : "reduced";
  return c;
}

Json spec_json(const ParameterSpec& spec) {
  Json s;
  s["name"] = spec.name;
  s["kind"] = spec.kind == ParameterSpec::Kind::integer ? "integer"
              : spec.kind == ParameterSpec::Kind::real  ? "real"
                                                        : "choice";
  s["allowed"] = spec.allowed();
  if (spec.kind == ParameterSpec::Kind::choice) {
    s["choices"] = spec.choices;
    s["default"] = spec.choices.empty() ? Json() : Json(spec.choices.front());
  } else {
    if (spec.min > -ParameterSpec::unbounded()) s["min"] = number_json(spec.min);
    if (spec.max < ParameterSpec::unbounded()) s["max"] = number_json(spec.max);
    s["min_inclusive"] = spec.min_inclusive;
    s["max_inclusive"] = spec.max_inclusive;
    try {  // a default outside the allowed values (tolerance's 0) means none: the key is optional
      spec.check(spec.default_value);
      s["default"] = number_json(spec.default_value);
    } catch (const std::invalid_argument&) {
      s["default"] = nullptr;
    }
  }
  s["meaning"] = spec.description;
  return s;
}

ParameterPoint fixed_point(const Scene& scene) {
  ParameterPoint fixed;
  for (const auto& axis : scene.axes)
    if (axis.values.size() == 1 && axis.key != "order" && axis.key != "tolerance")
      fixed.numbers[axis.key] = axis.values.front();
  fixed.choices = scene.choices;
  return fixed;
}

}  // namespace

std::optional<int> scene_dimension(const Scene& scene) {
  for (const auto& axis : scene.axes)
    if (axis.key == "dimension") {
      if (axis.values.size() != 1) return std::nullopt;
      return static_cast<int>(axis.values.front().to_double());
    }
  for (const auto& spec : make_transport_model(scene.model)->parameters())
    if (spec.name == "dimension") return static_cast<int>(spec.default_value.to_double());
  return 3;  // a model without the key is three-dimensional (viscoelastic spheres)
}

std::string describe_table(const Scene& scene, const std::optional<PhysicalReference>& physical) {
  const auto model = make_transport_model(scene.model);
  const auto dimension = scene_dimension(scene);
  Json doc;
  doc["units"] = physical ? "physical" : "reduced";
  if (physical) {
    Json r;
    r["mass"] = physical->mass;
    r["diameter"] = physical->diameter;
    r["number_density"] = physical->number_density;
    r["temperature"] = physical->temperature;
    r["units"] = "kg, m, m^-" + std::to_string(dimension.value_or(3)) + ", K; k_B = 1.380649e-23 J/K";
    doc["reference"] = std::move(r);
  }
  Json s;
  s["model"] = scene.model;
  std::vector<std::string> defaults;
  const auto specs = model->scene_parameters(fixed_point(scene));
  for (const auto& spec : specs) {
    const auto axis =
        std::find_if(scene.axes.begin(), scene.axes.end(), [&](const Axis& a) { return a.key == spec.name; });
    if (axis != scene.axes.end()) {
      if (axis->swept) {
        Json values = Json::array();
        for (const auto& v : axis->values) values.push_back(number_json(v));
        s[spec.name] = std::move(values);
      } else {
        s[spec.name] = number_json(axis->values.front());
      }
    } else if (const auto choice = scene.choices.find(spec.name); choice != scene.choices.end()) {
      s[spec.name] = choice->second;
    } else if (!indexed_key(spec.name)) {
      s[spec.name] =
          spec.kind == ParameterSpec::Kind::choice ? Json(spec.choices.front()) : number_json(spec.default_value);
      defaults.push_back(spec.name);
    }
  }
  for (const auto& axis : scene.axes)  // the order request and anything the schema does not list
    if (!s.contains(axis.key)) {
      if (axis.swept) {
        Json values = Json::array();
        for (const auto& v : axis.values) values.push_back(number_json(v));
        s[axis.key] = std::move(values);
      } else {
        s[axis.key] = number_json(axis.values.front());
      }
    }
  s["coefficients"] = scene.coefficients;
  if (!scene.coefficients_given) defaults.emplace_back("coefficients");
  s["defaults_applied"] = defaults;
  doc["scene"] = std::move(s);

  Json columns;
  for (const auto& name : table_header(scene, {}).columns) {
    const auto spec = std::find_if(specs.begin(), specs.end(), [&](const ParameterSpec& p) { return p.name == name; });
    if (spec != specs.end() && name != "order") {
      Json c;
      c["meaning"] = "scene key (swept): " + spec->description;
      c["reduced_by"] = "—";
      c["reduction"] = "none";
      c["unit"] = "as in the scene";
      columns[name] = std::move(c);
    } else if (name == "tolerance") {
      columns[name] = Json{{"meaning", "scene key (swept): target estimated truncation error"},
                           {"reduced_by", "—"},
                           {"reduction", "none"},
                           {"unit", "as in the scene"}};
    } else {
      columns[name] = column_json(describe_column(scene.model, name), dimension, physical.has_value());
    }
  }
  doc["column_descriptions"] = std::move(columns);
  return doc.dump();
}

std::string describe_models(const std::string& name, bool json) {
  std::vector<std::string> names = transport_model_names();
  if (!name.empty()) {
    make_transport_model(name);  // an unknown name: the registry's one-line error
    names = {name};
  }
  Json models = Json::array();
  for (const auto& model_name : names) {
    const auto model = make_transport_model(model_name);
    Json m;
    m["name"] = model_name;
    m["description"] = model->description();
    Json commands = Json::array();
    for (const auto& [capability, command] :
         {std::pair{Capability::table, "table"}, std::pair{Capability::formula, "formula"},
          std::pair{Capability::evolve, "evolve"}, std::pair{Capability::stability, "stability"}})
      if (model->supports(capability)) commands.push_back(command);
    m["commands"] = std::move(commands);
    Json keys = Json::array();
    for (const auto& spec : model->parameters()) keys.push_back(spec_json(spec));
    for (const auto& spec : order_parameters(model->max_order())) keys.push_back(spec_json(spec));
    m["keys"] = std::move(keys);
    if (model->supports(Capability::evolve)) {
      Json evolution = Json::array();
      for (const auto& spec : model->evolution_parameters()) evolution.push_back(spec_json(spec));
      m["evolution_keys"] = std::move(evolution);
    }
    m["max_order"] = model->max_order();
    std::optional<int> dimension;
    const auto params = model->parameters();
    if (std::none_of(params.begin(), params.end(), [](const ParameterSpec& p) { return p.name == "dimension"; }))
      dimension = 3;
    Json columns;
    for (const auto& column : model->coefficient_names()) {
      Json c = column_json(describe_column(model_name, column), dimension, true);
      c.erase("unit");
      columns[column] = std::move(c);
    }
    m["columns"] = std::move(columns);
    m["column_rules"] =
        "each coefficient column c is followed (after all coefficients) by c_error, its estimated truncation error "
        "in the same reduction (theory.md (6.1)); the row ends with order";
    models.push_back(std::move(m));
  }
  if (json) {
    Json doc;
    doc["gkt_version"] = GKT_VERSION;
    doc["models"] = std::move(models);
    return doc.dump(2) + "\n";
  }
  std::ostringstream out;
  for (const auto& m : models) {
    out << m["name"].get<std::string>() << ": " << m["description"].get<std::string>() << "\n";
    out << "  commands: " << join(m["commands"].get<std::vector<std::string>>()) << "\n";
    out << "  keys:\n";
    for (const auto& k : m["keys"])
      out << "    " << k["name"].get<std::string>() << ": " << k["allowed"].get<std::string>()
          << (k["default"].is_null() ? ", no default" : ", default " + k["default"].dump())
          << (k["meaning"].get<std::string>().empty() ? "" : " — ") << k["meaning"].get<std::string>() << "\n";
    if (m.contains("evolution_keys")) {
      out << "  evolution keys (gkt evolve):\n";
      for (const auto& k : m["evolution_keys"])
        out << "    " << k["name"].get<std::string>() << ": " << k["allowed"].get<std::string>()
            << (k["default"].is_null() ? ", no default" : ", default " + k["default"].dump())
            << (k["meaning"].get<std::string>().empty() ? "" : " — ") << k["meaning"].get<std::string>() << "\n";
    }
    out << "  columns (reduced by; SI unit with --units physical):\n";
    for (const auto& [column, c] : m["columns"].items())
      out << "    " << column << ": " << c["meaning"].get<std::string>() << " [" << c["reduced_by"].get<std::string>()
          << "; " << c["si_unit"].get<std::string>() << "]\n";
    out << "  " << m["column_rules"].get<std::string>() << "\n";
  }
  return out.str();
}

std::string models_supporting(Capability capability) {
  std::vector<std::string> names;
  for (const auto& name : transport_model_names())
    if (make_transport_model(name)->supports(capability)) names.push_back("\"" + name + "\"");
  std::string joined;
  for (std::size_t i = 0; i < names.size(); ++i)
    joined += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return joined;
}

}  // namespace gkt::cli
