// The parameter specs several models declare alike (models.hpp).
#include <utility>

#include "models/models.hpp"

namespace gkt::detail {

ParameterSpec dimension_spec(std::string description) {
  return {"dimension", ParameterSpec::Kind::integer, Rational(2), Rational(3), true, true,
          Rational(3), std::move(description),       {}};
}

ParameterSpec restitution_spec(std::string name, std::string description) {
  return {std::move(name), ParameterSpec::Kind::real, Rational(0), Rational(1), false, true,
          Rational(1),     std::move(description),    {}};
}

ParameterSpec choice_spec(std::string name, std::string description, std::vector<std::string> choices) {
  return {std::move(name), ParameterSpec::Kind::choice, Rational(0),       Rational(0), true, true,
          Rational(0),     std::move(description),      std::move(choices)};
}

}  // namespace gkt::detail
