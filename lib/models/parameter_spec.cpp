#include <stdexcept>

#include <flint/fmpz.h>

#include "gkt/models/transport_model.hpp"
#include "models/models.hpp"

namespace gkt {

std::string ParameterSpec::allowed() const {
  if (kind == Kind::choice) {
    return "one of " + detail::join(choices, "\"");
  }
  const std::string kind_name = kind == Kind::integer ? "an integer" : "a number";
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
  if (min_inclusive ? v < min : v <= min) throw fail();
  if (max_inclusive ? v > max : v >= max) throw fail();
}

void ParameterSpec::check(const std::string& c) const {
  if (kind != Kind::choice) throw std::invalid_argument(name + ": must be " + allowed() + ", got \"" + c + "\"");
  for (const auto& allowed_choice : choices)
    if (allowed_choice == c) return;
  throw std::invalid_argument(name + ": must be " + allowed() + ", got \"" + c + "\"");
}

Rational ParameterPoint::number(const std::string& key, const Rational& fallback) const {
  const auto it = numbers.find(key);
  return it == numbers.end() ? fallback : it->second;
}

std::string ParameterPoint::choice(const std::string& key, const std::string& fallback) const {
  const auto it = choices.find(key);
  return it == choices.end() ? fallback : it->second;
}

}  // namespace gkt
