// A model's declared parameters (its schema): each key with its kind, range or choices and default,
// and the one validation every façade entry point applies before a model computes anything.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gkt/algebra/rational.hpp"

namespace gkt {

/// A model parameter: its key, kind and allowed closed/open range or choices (used to validate
/// input). A real parameter whose upper bound is at least ParameterSpec::unbounded() has none, and one
/// whose lower bound is at most −unbounded() has no lower bound.
struct ParameterSpec {
  /// What values the parameter takes: an integer, a real number or one of named choices.
  enum class Kind { integer, real, choice };
  /// The key, as typed on the command line (e.g. "alpha").
  std::string name;
  /// Integer, real or choice.
  Kind kind = Kind::real;
  /// Lower and upper bound of an integer or real parameter (exact).
  /// @{
  Rational min, max;
  /// @}
  /// True if `min` itself is allowed (closed lower end).
  bool min_inclusive = true;
  /// True if `max` itself is allowed (closed upper end).
  bool max_inclusive = true;
  /// Value used when the key is not given.
  Rational default_value;
  /// One-line meaning of the parameter.
  std::string description;
  std::vector<std::string> choices;  ///< allowed strings of a `choice` parameter (first = default)
  /// Returns the one-line description of the allowed values, e.g. "an integer in [2, 3]" or "a number > 0".
  [[nodiscard]] std::string allowed() const;
  /// Throws std::invalid_argument "<name>: must be …, got …" if v is not allowed.
  void check(const Rational& v) const;
  /// Throws std::invalid_argument "<name>: must be one of …, got …" if c is not a choice.
  void check(const std::string& c) const;
  /// Returns 10^300: an upper bound this large is no bound (allowed() says "a number > min").
  [[nodiscard]] static const Rational& unbounded();
};

/// The parameters of one evaluation: numbers (exact) and named choices.
struct ParameterPoint {
  /// The numeric parameters by key (exact).
  std::map<std::string, Rational> numbers;
  /// The choice parameters by key.
  std::map<std::string, std::string> choices;
  /// Returns the number `key`, or `fallback` if absent.
  [[nodiscard]] Rational number(const std::string& key, const Rational& fallback) const;
  /// Returns the choice `key`, or `fallback` if absent.
  [[nodiscard]] std::string choice(const std::string& key, const std::string& fallback) const;
};

/// Sonine order to use: a fixed order, or the smallest order whose estimated truncation
/// error is below a tolerance.
struct OrderRequest {
  /// The Sonine order used when no tolerance is given.
  int order = 1;
  /// When set, the smallest order whose estimated truncation error is below this tolerance is used instead of `order`.
  std::optional<Rational> tolerance;
  /// Set with `order` when that order was chosen by a tolerance scan (the second pass of a `gkt table`
  /// row): values whose accuracy the Sonine order does not govern — a mixture's HCS cumulant order
  /// (theory.md §16.3) — still meet this tolerance. Other models ignore it.
  std::optional<Rational> row_tolerance = std::nullopt;
};

/// Returns the spec named `name` in `schema`; throws std::logic_error if the schema has none (a
/// model reading a key it did not declare).
const ParameterSpec& find_parameter(const std::vector<ParameterSpec>& schema, std::string_view name);

/// Checks `point` against `schema` once: every name must be declared (else std::invalid_argument
/// "<name>: unknown parameter for <owner>; valid parameters: …"), every number and choice allowed
/// by its spec (the spec's own message, as the scene loader gives it). Absent keys are not checked.
void validate_parameters(const std::vector<ParameterSpec>& schema, const ParameterPoint& point,
                         const std::string& owner);

/// Returns the specs of the order request of a model with highest order `max_order`: `order`, an
/// integer in [1, max_order], and `tolerance`, a number in (0, 1].
std::vector<ParameterSpec> order_parameters(int max_order);

/// Checks an OrderRequest against order_parameters(max_order) (std::invalid_argument naming
/// `order` or `tolerance`).
void validate_order(const OrderRequest& order, int max_order);

}  // namespace gkt
