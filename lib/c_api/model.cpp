// The C API of the model registry (include/gkt/gkt.h): any model by name, its parameters set by
// name and checked against the model's ParameterSpecs (a misspelled key is refused, never
// ignored), any coefficient at any order as `gkt table` computes it.
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gkt/gkt.h"
#include "gkt/models/transport_model.hpp"
#include "guard.hpp"

/// A registry model and its parameter point.
struct gkt_model {
  std::unique_ptr<gkt::TransportModel> model;
  std::vector<gkt::ParameterSpec> specs;
  gkt::ParameterPoint point;
};

namespace gkt::c_api {
namespace {

/// Returns the spec called key; throws a Refusal listing the model's keys otherwise.
const ParameterSpec& spec_of(const gkt_model& m, const char* key) {
  require_pointer(key, "key");
  for (const auto& s : m.specs)
    if (s.name == key) return s;
  std::string valid;
  for (const auto& s : m.specs) valid += (valid.empty() ? "" : ", ") + s.name;
  throw Refusal{GKT_INVALID_ARGUMENT,
                std::string(key) + ": unknown parameter of model \"" + m.model->name() + "\"; valid: " + valid};
}

/// Returns the parameters as the model's coefficient list sees them: the numbers set, and the
/// default of every number not set (as a scene does).
ParameterPoint fixed_point(const gkt_model& m) {
  ParameterPoint fixed = m.point;
  for (const auto& s : m.specs)
    if (s.kind != ParameterSpec::Kind::choice && !fixed.numbers.contains(s.name))
      fixed.numbers[s.name] = s.default_value;
  return fixed;
}

/// Evaluates names[0 … count−1] at the order request and writes them to out (all or nothing).
gkt_status evaluate(gkt_model* m, std::size_t count, const char* const* names, const OrderRequest& order,
                    gkt_coefficient* out) {
  require_pointer(m, "model");
  require_pointer(out, "out");
  require_pointer(names, "names");
  if (count == 0) throw Refusal{GKT_INVALID_ARGUMENT, "count: must be at least 1, got 0"};
  const auto valid = m->model->scene_coefficient_names(fixed_point(*m));
  std::vector<std::string> requested;
  for (std::size_t i = 0; i < count; ++i) {
    require_pointer(names[i], "names[i]");
    if (std::find(valid.begin(), valid.end(), names[i]) == valid.end()) {
      std::string list;
      for (const auto& v : valid) list += (list.empty() ? "" : ", ") + v;
      throw Refusal{GKT_INVALID_ARGUMENT, std::string("coefficients: unknown coefficient '") + names[i] +
                                              "' for model \"" + m->model->name() + "\"; valid: " + list};
    }
    requested.emplace_back(names[i]);
  }
  const std::vector<CoefficientValue> values = m->model->evaluate(m->point, requested, order);
  // What the error estimates do not cover, as `gkt table` warns once per table (docs/conventions.md, "Warnings").
  int highest_order = order.order;
  for (const CoefficientValue& v : values) highest_order = std::max(highest_order, v.order);
  const auto caveats = m->model->table_caveats(m->point.choices, requested, highest_order, order.tolerance.has_value());
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < count; ++i) {
    const CoefficientValue& v = values[i];
    // As `gkt table` prints them: nan with error inf where no value exists, error nan where unestimated.
    out[i] = {v.defined ? v.value.to_double() : nan,
              !v.defined          ? inf
              : v.error_estimated ? v.error.to_double()
                                  : nan,
              v.order, v.converged ? 1 : 0, v.defined ? 1 : 0};
  }
  set_last_warnings(caveats);
  return GKT_OK;
}

}  // namespace
}  // namespace gkt::c_api

using gkt::c_api::guarded;
using gkt::c_api::number;
using gkt::c_api::Refusal;
using gkt::c_api::require_pointer;

extern "C" {

gkt_status gkt_model_create(const char* name, gkt_model** out) {
  return guarded([&] {
    require_pointer(out, "out");
    require_pointer(name, "name");
    auto m = std::make_unique<gkt_model>();
    m->model = gkt::make_transport_model(name);
    m->specs = m->model->parameters();
    *out = m.release();
    return GKT_OK;
  });
}

void gkt_model_destroy(gkt_model* model) { std::unique_ptr<gkt_model> owned(model); }

gkt_status gkt_model_set_number(gkt_model* model, const char* key, double value) {
  return guarded([&] {
    require_pointer(model, "model");
    const gkt::ParameterSpec& spec = gkt::c_api::spec_of(*model, key);
    if (spec.kind == gkt::ParameterSpec::Kind::choice)
      throw Refusal{GKT_INVALID_ARGUMENT,
                    spec.name + ": must be " + spec.allowed() + " (set it with gkt_model_set_choice)"};
    if (!std::isfinite(value))
      throw Refusal{GKT_INVALID_ARGUMENT, spec.name + ": must be " + spec.allowed() + ", got " + number(value)};
    // The shortest decimal of the double, read exactly: what a scene file holding it would give.
    const gkt::Rational exact = gkt::Rational::parse(number(value));
    spec.check(exact);
    model->point.numbers[spec.name] = exact;
    return GKT_OK;
  });
}

gkt_status gkt_model_set_choice(gkt_model* model, const char* key, const char* value) {
  return guarded([&] {
    require_pointer(model, "model");
    require_pointer(value, "value");
    const gkt::ParameterSpec& spec = gkt::c_api::spec_of(*model, key);
    spec.check(std::string(value));
    model->point.choices[spec.name] = value;
    return GKT_OK;
  });
}

gkt_status gkt_model_evaluate(gkt_model* model, size_t count, const char* const* names, int order,
                              gkt_coefficient* out) {
  return guarded([&] {
    gkt::c_api::set_last_warnings({});  // a failing call leaves none
    require_pointer(model, "model");
    const int top = model->model->max_order();
    if (order < 1 || order > top)
      throw Refusal{GKT_INVALID_ARGUMENT,
                    "order: must be an integer in [1, " + std::to_string(top) + "], got " + std::to_string(order)};
    return gkt::c_api::evaluate(model, count, names, gkt::OrderRequest{order, std::nullopt}, out);
  });
}

gkt_status gkt_model_evaluate_to_tolerance(gkt_model* model, size_t count, const char* const* names, double tolerance,
                                           gkt_coefficient* out) {
  return guarded([&] {
    gkt::c_api::set_last_warnings({});
    if (!(tolerance > 0 && tolerance <= 1))
      throw Refusal{GKT_INVALID_ARGUMENT, "tolerance: must be a number in (0, 1], got " + number(tolerance)};
    const gkt::Rational exact = gkt::Rational::parse(number(tolerance));
    return gkt::c_api::evaluate(model, count, names, gkt::OrderRequest{1, exact}, out);
  });
}

}  // extern "C"
