// The interface every transport model implements, and the one registry that names them
// (cf. Cantera's TransportFactory): front ends pick models by name only through here.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gkt/algebra/rational.hpp"

namespace gkt {

/// A model parameter: its key, kind and allowed closed/open range or choices (used to validate
/// input).
struct ParameterSpec {
  enum class Kind { integer, real, choice };
  std::string name;
  Kind kind = Kind::real;
  Rational min, max;
  bool min_inclusive = true;
  bool max_inclusive = true;
  Rational default_value;
  std::string description;
  std::vector<std::string> choices;  ///< allowed strings of a `choice` parameter (first = default)
  /// Returns a one-line description of the allowed values, e.g. "an integer in [2, 3]".
  [[nodiscard]] std::string allowed() const;
  /// Throws std::invalid_argument "<name>: must be …, got …" if v is not allowed.
  void check(const Rational& v) const;
  /// Throws std::invalid_argument "<name>: must be one of …, got …" if c is not a choice.
  void check(const std::string& c) const;
};

/// The parameters of one evaluation: numbers (exact) and named choices.
struct ParameterPoint {
  std::map<std::string, Rational> numbers;
  std::map<std::string, std::string> choices;
  /// Returns the number `key`, or `fallback` if absent.
  [[nodiscard]] Rational number(const std::string& key, const Rational& fallback) const;
  /// Returns the choice `key`, or `fallback` if absent.
  [[nodiscard]] std::string choice(const std::string& key, const std::string& fallback) const;
};

/// Sonine order to use: a fixed order, or the smallest order whose estimated truncation
/// error is below a tolerance.
struct OrderRequest {
  int order = 1;
  std::optional<Rational> tolerance;
};

/// One coefficient at one parameter point.
struct CoefficientValue {
  Rational value;               ///< reduced value (exact when `exact`)
  Rational error;               ///< estimated truncation error
  int order = 0;                ///< Sonine order used
  bool converged = true;        ///< false if the tolerance was not met or the series does not converge
  bool exact = true;            ///< value and error are exact rationals
  bool defined = true;          ///< false if no value with an error estimate exists at this order
  bool error_estimated = true;  ///< false: the approximation's error is not estimated (printed nan)
  /// true: the value is +∞ at every order used (the critical_length of a gas whose HCS is stable at
  /// every wave number, e.g. the elastic gas: docs/conventions.md); value and error are then 0.
  bool infinite = false;
};

/// A transport model: named coefficients as functions of named parameters.
class TransportModel {
 public:
  virtual ~TransportModel() = default;
  [[nodiscard]] virtual std::string name() const = 0;
  [[nodiscard]] virtual std::string description() const = 0;
  /// Returns the canonical coefficient names this model computes.
  [[nodiscard]] virtual std::vector<std::string> coefficient_names() const = 0;
  /// Returns the coefficient names offered at a scene's fixed parameters (e.g. one
  /// temperature_ratio_i per species of a mixture); by default all of coefficient_names().
  [[nodiscard]] virtual std::vector<std::string> scene_coefficient_names(const ParameterPoint& fixed) const {
    static_cast<void>(fixed);
    return coefficient_names();
  }
  /// Returns the coefficients a scene computes when it does not list any; by default all of
  /// scene_coefficient_names().
  [[nodiscard]] virtual std::vector<std::string> default_coefficients(const ParameterPoint& fixed) const {
    return scene_coefficient_names(fixed);
  }
  /// Returns the model's parameters (scene keys) with their ranges.
  [[nodiscard]] virtual std::vector<ParameterSpec> parameters() const = 0;
  /// Returns the highest Sonine order accepted.
  [[nodiscard]] virtual int max_order() const = 0;
  /// Returns the requested coefficients at one parameter point (reduced as in
  /// docs/conventions.md), computing only those; state is reused between calls.
  virtual std::vector<CoefficientValue> evaluate(const ParameterPoint& parameters,
                                                 const std::vector<std::string>& coefficients,
                                                 const OrderRequest& order) = 0;
};

/// Returns a new model by name; throws std::invalid_argument listing the valid names.
std::unique_ptr<TransportModel> make_transport_model(const std::string& name);

/// Returns the registered model names, sorted.
std::vector<std::string> transport_model_names();

}  // namespace gkt
