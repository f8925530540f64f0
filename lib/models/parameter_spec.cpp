// The schema of a model: allowed values of one parameter, and the one validation of a point.
#include <algorithm>
#include <stdexcept>

#include <flint/fmpz.h>

#include "gkt/models/parameter_spec.hpp"
#include "support/strings.hpp"

namespace gkt {

std::string ParameterSpec::allowed() const {
  if (kind == Kind::choice) {
    return "one of " + detail::join(choices, "\"");
  }
  const std::string kind_name = kind == Kind::integer ? "an integer" : "a number";
  if (max >= unbounded() && min <= -unbounded()) return kind_name;  // no bound either way
  if (max >= unbounded()) return kind_name + (min_inclusive ? " >= " : " > ") + min.to_decimal_string();
  if (kind == Kind::integer && min_inclusive && max_inclusive && min == max)
    return "exactly " + min.to_decimal_string();
  if (kind == Kind::integer && min_inclusive && max_inclusive && max - min == Rational(1))
    return min.to_decimal_string() + " or " + max.to_decimal_string();
  std::string out = kind_name;
  out += min_inclusive ? " in [" : " in (";
  out += min.to_decimal_string() + ", " + max.to_decimal_string();
  out += max_inclusive ? "]" : ")";
  return out;
}

void ParameterSpec::check(const Rational& v) const {
  auto fail = [&]() {
    return std::invalid_argument(name + ": must be " + allowed() + ", got " + v.to_decimal_string());
  };
  if (kind == Kind::choice) throw fail();
  if (kind == Kind::integer && !fmpz_is_one(fmpq_denref(v.raw()))) throw fail();
  if (min > -unbounded() && (min_inclusive ? v < min : v <= min)) throw fail();
  if (max_inclusive ? v > max : v >= max) throw fail();
}

void ParameterSpec::check(const std::string& c) const {
  if (kind != Kind::choice) throw std::invalid_argument(name + ": must be " + allowed() + ", got \"" + c + "\"");
  for (const auto& allowed_choice : choices)
    if (allowed_choice == c) return;
  throw std::invalid_argument(name + ": must be " + allowed() + ", got \"" + c + "\"");
}

const Rational& ParameterSpec::unbounded() {
  static const Rational bound = Rational::parse("1e300");
  return bound;
}

Rational ParameterPoint::number(const std::string& key, const Rational& fallback) const {
  const auto it = numbers.find(key);
  return it == numbers.end() ? fallback : it->second;
}

std::string ParameterPoint::choice(const std::string& key, const std::string& fallback) const {
  const auto it = choices.find(key);
  return it == choices.end() ? fallback : it->second;
}

const ParameterSpec& find_parameter(const std::vector<ParameterSpec>& schema, std::string_view name) {
  const auto it = std::find_if(schema.begin(), schema.end(), [&](const ParameterSpec& s) { return s.name == name; });
  if (it == schema.end()) throw std::logic_error("schema: no parameter named " + std::string(name));
  return *it;
}

void validate_parameters(const std::vector<ParameterSpec>& schema, const ParameterPoint& point,
                         const std::string& owner) {
  auto spec_of = [&](const std::string& name) -> const ParameterSpec& {
    const auto it = std::find_if(schema.begin(), schema.end(), [&](const ParameterSpec& s) { return s.name == name; });
    if (it != schema.end()) return *it;
    std::vector<std::string> valid;
    for (const auto& s : schema) valid.push_back(s.name);
    std::sort(valid.begin(), valid.end());
    throw std::invalid_argument(name + ": unknown parameter for " + owner +
                                "; valid parameters: " + detail::join(valid));
  };
  for (const auto& [name, value] : point.numbers) spec_of(name).check(value);
  for (const auto& [name, value] : point.choices) spec_of(name).check(value);
}

std::vector<ParameterSpec> order_parameters(int max_order) {
  return {{"order",
           ParameterSpec::Kind::integer,
           Rational(1),
           Rational(max_order),
           true,
           true,
           Rational(1),
           "Sonine order (number of polynomials)",
           {}},
          {"tolerance",
           ParameterSpec::Kind::real,
           Rational(0),
           Rational(1),
           false,
           true,
           Rational(0),
           "target estimated truncation error",
           {}}};
}

void validate_order(const OrderRequest& order, int max_order) {
  const auto specs = order_parameters(max_order);
  if (order.tolerance)
    find_parameter(specs, "tolerance").check(*order.tolerance);
  else
    find_parameter(specs, "order").check(Rational(order.order));
}

}  // namespace gkt
