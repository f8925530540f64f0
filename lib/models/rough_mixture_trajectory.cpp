// What `gkt evolve` asks the "rough" model for when the scene has two [[species]] tables: the Maxwellian free cooling
// of the rough binary mixture, T_t,i(τ), T_r,i(τ) from any initial temperatures (rough_mixture_cooling_evolution.hpp;
// docs/theory.md §19.31, conventions.md).
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "gkt/evolution/rough_mixture_cooling_evolution.hpp"
#include "models/models.hpp"
#include "models/rough_mixture_columns.hpp"

namespace gkt::detail {

namespace {

std::string species_key(const char* base, int i) { return std::string(base) + "_" + std::to_string(i); }

}  // namespace

std::vector<ParameterSpec> rough_mixture_evolution_parameters() {
  std::vector<ParameterSpec> specs;
  for (int i = 1; i <= 2; ++i)
    for (const char* base : {"translational_temperature", "rotational_temperature"})
      specs.push_back({species_key(base, i),
                       ParameterSpec::Kind::real,
                       Rational(0),
                       ParameterSpec::unbounded(),
                       false,
                       true,
                       Rational(1),
                       std::string("initial ") + (base[0] == 't' ? "T_t,i(0)/T_ref" : "T_r,i(0)/T_ref") +
                           " of species i of a rough binary (species = 2; default: " + base + ")",
                       {}});
  return specs;
}

Trajectory rough_mixture_trajectory(const std::vector<ParameterSpec>& schema, const TrajectoryRequest& request) {
  const SchemaPoint p(schema, request.parameters);
  if (!request.coefficients.empty())
    throw std::invalid_argument("coefficients: none are offered along a rough binary-mixture trajectory");
  for (const char* key : {"reference_state", "rotational_temperature_closure", "hcs_order", "trial_space"})
    if (p.given(key))
      throw std::invalid_argument(std::string(key) +
                                  ": not taken by the rough binary mixture (species = 2: Maxwellian trajectory only)");
  if (p.given("hcs") && p.choice("hcs") != "maxwellian")
    throw std::invalid_argument(
        "hcs: the rough binary mixture (species = 2) evolves in the Maxwellian approximation only: use hcs = "
        "\"maxwellian\", got \"" +
        p.choice("hcs") + "\"");
  if (p.given("order") && p.number("order") != Rational(1))
    throw std::invalid_argument("order: the rough binary mixture (species = 2) evolves at order 1 only, got " +
                                p.number("order").to_decimal_string());
  for (const char* key : {"a20", "a02", "a11"})
    if (p.given(key))
      throw std::invalid_argument(std::string(key) +
                                  ": the rough binary mixture (species = 2) evolves Maxwellians, no initial cumulants");
  const RoughBinaryMixture mixture = rough_binary_mixture(p);
  std::array<double, 4> initial{};
  for (int i = 1; i <= 2; ++i) {
    const std::string t = species_key("translational_temperature", i), r = species_key("rotational_temperature", i);
    initial[static_cast<std::size_t>(i - 1)] =
        (p.given(t) ? p.number(t) : p.number("translational_temperature")).to_double();
    initial[static_cast<std::size_t>(i + 1)] =
        (p.given(r) ? p.number(r) : p.number("rotational_temperature")).to_double();
  }
  const RoughMixtureEvolutionResult result =
      evolve_rough_mixture_cooling(mixture, initial, request.times, p.number("rtol").to_double(),
                                   p.number("atol").to_double(), static_cast<long>(p.number("max_steps").to_double()));
  Trajectory out;
  out.columns = {"time",
                 "temperature",
                 "translational_temperature_1",
                 "translational_temperature_2",
                 "rotational_temperature_1",
                 "rotational_temperature_2",
                 "temperature_ratio_1",
                 "temperature_ratio_2",
                 "rotational_temperature_ratio_1",
                 "rotational_temperature_ratio_2",
                 "cooling_rate"};
  for (const auto& s : result.samples) {
    const auto& tt = s.translational_temperature;
    const auto& tr = s.rotational_temperature;
    out.rows.push_back({s.time, s.temperature, tt[0], tt[1], tr[0], tr[1], tt[0] / s.temperature, tt[1] / s.temperature,
                        tr[0] / tt[0], tr[1] / tt[1], s.cooling_rate});
  }
  out.counters = result.counters;
  return out;
}

}  // namespace gkt::detail
