#include "models/rough_mixture_columns.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <stdexcept>

#include "gkt/transport/rough/rough_mixture_cooling_state.hpp"
#include "models/rough_parameters.hpp"

namespace gkt::detail {

namespace {

std::string index_name(const std::string& base, int i) { return base + "_" + std::to_string(i); }
std::string index_name(const std::string& base, int i, int j) { return index_name(index_name(base, i), j); }

ParameterSpec real(const std::string& name, const Rational& min, bool min_inclusive, const Rational& max,
                   bool max_inclusive, const Rational& fallback, const std::string& description) {
  return {name, ParameterSpec::Kind::real, min, max, min_inclusive, max_inclusive, fallback, description, {}};
}

/// The keys of the one-gas model that the binary does not take (its HCS is Maxwellian, no Navier–Stokes columns).
constexpr std::array<const char*, 3> kOneGasOnly{"reference_state", "rotational_temperature_closure", "hcs_order"};

}  // namespace

std::vector<ParameterSpec> rough_mixture_parameters() {
  std::vector<ParameterSpec> p{{"species",
                                ParameterSpec::Kind::integer,
                                Rational(1),
                                Rational(2),
                                true,
                                true,
                                Rational(1),
                                "number of species (1: one gas; 2: a binary mixture, set by two [[species]] tables)",
                                {}}};
  for (int i = 1; i <= 2; ++i) {
    p.push_back(real(index_name("mass", i), Rational(0), false, Rational(1000000000L), true, Rational(1),
                     "mass of species i (any unit)"));
    p.push_back(real(index_name("diameter", i), Rational(0), false, Rational(1000000000L), true, Rational(1),
                     "diameter of species i (any unit)"));
    p.push_back(real(index_name("fraction", i), Rational(0), true, Rational(1), true, Rational(1, 2),
                     "mole fraction x_i (the fractions sum to 1; 0 = tracer)"));
    p.push_back(real(index_name("moment_of_inertia", i), Rational(0), false, Rational(1), true, Rational(2, 5),
                     "reduced moment of inertia kappa_i = 4I_i/(m_i sigma_i^2) of species i (default: "
                     "moment_of_inertia)"));
  }
  for (int i = 1; i <= 2; ++i)
    for (int j = i; j <= 2; ++j) {
      p.push_back(
          restitution_spec(index_name("alpha", i, j), "normal restitution of the pair (i, j) (default: alpha)"));
      p.push_back(real(index_name("beta", i, j), Rational(-1), true, Rational(1), true, Rational(1),
                       "tangential restitution of the pair (i, j) (default: beta)"));
    }
  return p;
}

std::vector<std::string> rough_mixture_columns() {
  return {"temperature_ratio_1", "temperature_ratio_2", "rotational_temperature_ratio_1",
          "rotational_temperature_ratio_2", "cooling_rate"};
}

bool is_rough_mixture_point(const ParameterPoint& point) { return point.number("species", Rational(1)) == Rational(2); }

void refuse_species_keys_for_one_gas(const ParameterPoint& point) {
  for (const auto& spec : rough_mixture_parameters())
    if (spec.name != "species" && point.numbers.contains(spec.name))
      throw std::invalid_argument(spec.name + ": per-species keys need species = 2 (two [[species]] tables)");
}

RoughBinaryMixture rough_binary_mixture(const SchemaPoint& p) {
  RoughBinaryMixture m;
  m.dimension = p.number("dimension") == Rational(2) ? 2 : 3;
  for (int i = 1; i <= 2; ++i) {
    for (const char* field : {"mass", "diameter", "fraction"})
      if (!p.given(index_name(field, i)))
        throw std::invalid_argument("species[" + std::to_string(i) + "]." + field + ": required");
    const std::string kappa = index_name("moment_of_inertia", i);
    auto& s = m.species[static_cast<std::size_t>(i - 1)];
    s.mass = p.number(index_name("mass", i));
    s.kappa = p.given(kappa) ? p.number(kappa) : p.number("moment_of_inertia");
    s.diameter = p.number(index_name("diameter", i)).to_double();
    s.fraction = p.number(index_name("fraction", i)).to_double();
  }
  const Rational sum = p.number("fraction_1") + p.number("fraction_2");
  if (sum != Rational(1))
    throw std::invalid_argument("fraction: the mole fractions x_1 + x_2 must sum to 1, got " + sum.to_decimal_string());
  for (int i = 1; i <= 2; ++i)
    for (int j = i; j <= 2; ++j) {
      const auto pair = static_cast<std::size_t>(i + j - 2);  // 0: 1–1, 1: 1–2, 2: 2–2
      const std::string a = index_name("alpha", i, j), b = index_name("beta", i, j);
      m.alpha[pair] = p.given(a) ? p.number(a) : p.number("alpha");
      m.beta[pair] = p.given(b) ? p.number(b) : p.number("beta");
    }
  return m;
}

std::vector<CoefficientValue> rough_mixture_values(const std::vector<ParameterSpec>& schema,
                                                   const ParameterPoint& point,
                                                   const std::vector<std::string>& coefficients,
                                                   const OrderRequest& order) {
  const SchemaPoint p(schema, point);
  require_first_approximation(order, "rough binary-mixture");
  for (const char* key : kOneGasOnly)
    if (p.given(key))
      throw std::invalid_argument(std::string(key) +
                                  ": not taken by the rough binary mixture (species = 2: Maxwellian HCS only)");
  if (p.given("hcs") && p.choice("hcs") != "maxwellian")
    throw std::invalid_argument(
        "hcs: the rough binary mixture (species = 2) has the Maxwellian HCS only: use hcs = "
        "\"maxwellian\", got \"" +
        p.choice("hcs") + "\"");
  const auto columns = rough_mixture_columns();
  for (const auto& name : coefficients)
    if (std::find(columns.begin(), columns.end(), name) == columns.end())
      throw std::invalid_argument("coefficients: " + name +
                                  " is not computed for the rough binary mixture (species = 2); valid: "
                                  "temperature_ratio_i, rotational_temperature_ratio_i, cooling_rate");
  const RoughBinaryMixture m = rough_binary_mixture(p);
  const RoughMixtureCoolingState state = rough_mixture_cooling_state(m);
  std::vector<CoefficientValue> out;
  for (const auto& name : coefficients) {
    const double x = name == "temperature_ratio_1"              ? state.temperature_ratio[0]
                     : name == "temperature_ratio_2"            ? state.temperature_ratio[1]
                     : name == "rotational_temperature_ratio_1" ? state.rotational_ratio[0]
                     : name == "rotational_temperature_ratio_2" ? state.rotational_ratio[1]
                                                                : state.cooling_rate;
    out.push_back(first_approximation(x));
  }
  return out;
}

}  // namespace gkt::detail
