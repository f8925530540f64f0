#include "models/rough_mixture_columns.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>

#include "gkt/transport/rough/rough_mixture_cooling_state.hpp"
#include "gkt/transport/rough/rough_mixture_sonine_cooling_state.hpp"
#include "models/rough_parameters.hpp"

namespace gkt::detail {

namespace {

std::string index_name(const std::string& base, int i) { return base + "_" + std::to_string(i); }
std::string index_name(const std::string& base, int i, int j) { return index_name(index_name(base, i), j); }

ParameterSpec real(const std::string& name, const Rational& min, bool min_inclusive, const Rational& max,
                   bool max_inclusive, const Rational& fallback, const std::string& description) {
  return {name, ParameterSpec::Kind::real, min, max, min_inclusive, max_inclusive, fallback, description, {}};
}

/// The keys of the one-gas model that the binary does not take (its HCS is first Sonine at most, no Navier–Stokes
/// columns).
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

std::vector<std::string> rough_mixture_cumulant_columns() {
  return {"a20_1", "a02_1", "a11_1", "a20_2", "a02_2", "a11_2"};
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
                                  ": not taken by the rough binary mixture (species = 2: Maxwellian or first-Sonine "
                                  "HCS only)");
  // Not given: the Maxwellian HCS (the binary's default before the Sonine HCS existed, theory.md §19.26).
  const std::string scheme = p.given("hcs") ? p.choice("hcs") : "maxwellian";
  if (scheme != "maxwellian" && scheme != "linear" && scheme != "linear-or-maxwellian")
    throw std::invalid_argument(
        "hcs: the rough binary mixture (species = 2) has the Maxwellian and the first-Sonine linear HCS: use hcs = "
        "\"maxwellian\", \"linear\" or \"linear-or-maxwellian\", got \"" +
        scheme + "\"");
  auto columns = rough_mixture_columns();
  const auto cumulants = rough_mixture_cumulant_columns();
  columns.insert(columns.end(), cumulants.begin(), cumulants.end());
  for (const auto& name : coefficients) {
    if (std::find(columns.begin(), columns.end(), name) == columns.end())
      throw std::invalid_argument("coefficients: " + name +
                                  " is not computed for the rough binary mixture (species = 2); valid: "
                                  "temperature_ratio_i, rotational_temperature_ratio_i, cooling_rate, a20_i, a02_i, "
                                  "a11_i");
    if (scheme == "maxwellian" && std::find(cumulants.begin(), cumulants.end(), name) != cumulants.end())
      throw std::invalid_argument("coefficients: " + name +
                                  " needs the first-Sonine HCS of the rough binary mixture: use hcs = \"linear\"");
  }
  const RoughBinaryMixture m = rough_binary_mixture(p);
  const RoughMixtureCoolingState maxwellian = rough_mixture_cooling_state(m);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Columns in the order of rough_mixture_columns() then rough_mixture_cumulant_columns().
  std::array<double, 11> value{maxwellian.temperature_ratio[0],
                               maxwellian.temperature_ratio[1],
                               maxwellian.rotational_ratio[0],
                               maxwellian.rotational_ratio[1],
                               maxwellian.cooling_rate,
                               nan,
                               nan,
                               nan,
                               nan,
                               nan,
                               nan};
  if (scheme != "maxwellian") {
    const RoughMixtureSonineCoolingState s = rough_mixture_sonine_cooling_state(m);
    if (s.solved)
      value = {s.temperature_ratio[0],
               s.temperature_ratio[1],
               s.rotational_ratio[0],
               s.rotational_ratio[1],
               s.cooling_rate,
               s.a20[0],
               s.a02[0],
               s.a11[0],
               s.a20[1],
               s.a02[1],
               s.a11[1]};
    else if (scheme == "linear")
      throw std::invalid_argument(
          "hcs: the first-Sonine linear HCS of this rough binary mixture has no root with realizable cumulants "
          "(Newton from the Maxwellian HCS, theory.md section 19.30); use hcs = \"linear-or-maxwellian\" or "
          "\"maxwellian\"");
  }
  std::vector<CoefficientValue> out;
  for (const auto& name : coefficients) {
    const auto at = static_cast<std::size_t>(std::find(columns.begin(), columns.end(), name) - columns.begin());
    // A decoupled spin (θ_i = +∞, theory.md (19.130)) prints nan, as before.
    out.push_back(first_approximation(std::isinf(value[at]) ? nan : value[at]));
  }
  return out;
}

}  // namespace gkt::detail
