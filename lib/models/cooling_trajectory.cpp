// The table of a cooling trajectory, shared by the models that evolve: the integrator's samples
// and the transport coefficients at each sample, by name (theory.md §12.3).
#include "gkt/models/cooling_trajectory.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <functional>

#include "gkt/evolution/homogeneous_cooling_evolution.hpp"
#include "models/models.hpp"

namespace gkt {

std::vector<ParameterSpec> output_time_parameters() {
  return {{"t_end",
           ParameterSpec::Kind::real,
           Rational(0),
           ParameterSpec::unbounded(),
           false,
           true,
           Rational(1),
           "last output time tau = omega_M(0) t",
           {}},
          {"points",
           ParameterSpec::Kind::integer,
           Rational(1),
           Rational(1000000L),
           true,
           true,
           Rational(50),
           "number of output times, log-spaced up to t_end",
           {}}};
}

bool sets_own_output_times(const std::vector<ParameterSpec>& evolution_parameters) {
  return std::any_of(evolution_parameters.begin(), evolution_parameters.end(),
                     [](const ParameterSpec& s) { return s.name == "t_end"; });
}

std::vector<double> log_spaced_times(double t_end, int points) {
  std::vector<double> times;
  const double start = std::min(0.01, t_end / 100);
  for (int i = 0; i < points; ++i)
    times.push_back(points == 1 ? t_end : start * std::pow(t_end / start, static_cast<double>(i) / (points - 1)));
  return times;
}

namespace detail {

namespace {

/// The coefficients a trajectory offers, and how each is read from η*, κ*, μ* and the stability.
struct TrajectoryColumn {
  const char* name;
  double (*value)(const NavierStokesValues&, const HcsStability&);
};

constexpr std::array<TrajectoryColumn, 6> kTrajectoryColumns{{
    {"shear_viscosity", [](const NavierStokesValues& v, const HcsStability&) { return v.shear_viscosity; }},
    {"thermal_conductivity", [](const NavierStokesValues& v, const HcsStability&) { return v.thermal_conductivity; }},
    {"density_heat_coefficient",
     [](const NavierStokesValues& v, const HcsStability&) { return v.density_heat_coefficient; }},
    {"critical_wavenumber_shear", [](const NavierStokesValues&, const HcsStability& s) { return s.shear_wavenumber; }},
    {"critical_wavenumber_heat", [](const NavierStokesValues&, const HcsStability& s) { return s.heat_wavenumber; }},
    {"critical_length", [](const NavierStokesValues&, const HcsStability& s) { return s.critical_length; }},
}};

}  // namespace

/// Returns the shortest decimal that reads back as x, exactly (the bound a double comparison used).
Rational shortest_decimal(double x) {
  char buffer[64];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, x);
  return Rational::parse(std::string(buffer, r.ptr));
}

ParameterSpec evolution_a2_spec(int dimension) {
  const int d = dimension;
  return {"a2",
          ParameterSpec::Kind::real,
          shortest_decimal(-8.0 / (d * (d + 2))),
          shortest_decimal(4.0 / (d + 2)),
          true,
          true,
          Rational(0),
          "initial fourth cumulant a2(0): f_M(1 + a2 S_2) positive at c = 0 and at the minimum of S_2",
          {}};
}

ParameterSpec evolution_max_steps_parameter() {
  return {"max_steps",
          ParameterSpec::Kind::integer,
          Rational(1),
          Rational(1000000000),
          true,
          true,
          Rational(kEvolutionMaxSteps),
          "CVODE step budget over the whole trajectory; past it exit 2 naming the time reached",
          {}};
}

std::vector<ParameterSpec> evolution_common_parameters() {
  auto real = [](const char* name, const Rational& min, bool min_inclusive, const Rational& max,
                 const Rational& fallback, const char* description) {
    return ParameterSpec{name, ParameterSpec::Kind::real, min, max, min_inclusive, true, fallback, description, {}};
  };
  // a2 in the union of both dimensions' ranges here; evolve() applies evolution_a2_spec(d).
  ParameterSpec a2 = evolution_a2_spec(2);
  return {{"order",
           ParameterSpec::Kind::integer,
           Rational(1),
           Rational(12),
           true,
           true,
           Rational(3),
           "Sonine order N: the hierarchy keeps a_2 ... a_{N+1}",
           {}},
          real("rtol", Rational(0), false, Rational(1, 10), Rational::parse("1e-8"), "CVODE relative tolerance"),
          real("atol", Rational(0), false, Rational(1), Rational::parse("1e-12"), "CVODE absolute tolerance"),
          a2,
          evolution_max_steps_parameter()};
}

std::vector<std::string> trajectory_coefficient_names() {
  std::vector<std::string> names;
  for (const auto& c : kTrajectoryColumns) names.emplace_back(c.name);
  return names;
}

Trajectory tabulate_trajectory(const std::string& model, int dimension, int k_max, const EvolutionResult& result,
                               const std::vector<std::string>& coefficients,
                               const std::function<SampleTransport(const EvolutionSample&)>& transport) {
  std::vector<const TrajectoryColumn*> wanted;
  for (const auto& c : coefficients) {
    const auto it = std::find_if(kTrajectoryColumns.begin(), kTrajectoryColumns.end(),
                                 [&](const TrajectoryColumn& column) { return c == column.name; });
    if (it == kTrajectoryColumns.end())
      throw std::invalid_argument("coefficients: '" + c + "' is not offered along a " + model +
                                  " trajectory; valid: " + join(trajectory_coefficient_names()));
    wanted.push_back(&*it);
  }
  Trajectory t;
  t.columns = {"time", "collisions", "temperature"};
  for (int k = 2; k <= k_max; ++k) {
    std::string name(1, 'a');
    name += std::to_string(k);
    t.columns.push_back(name);
  }
  t.columns.emplace_back("cooling_rate");
  for (const auto& c : coefficients) t.columns.push_back(c);
  for (const auto& s : result.samples) {
    std::vector<double> row{s.time, s.collisions, s.temperature};
    for (int k = 2; k <= k_max; ++k) row.push_back(s.a[static_cast<std::size_t>(k)]);
    row.push_back(s.cooling_rate);
    if (!wanted.empty()) {
      const SampleTransport at = transport(s);
      // Critical sizes at the instantaneous state (theory.md §12.3), ζ*(τ) from the hierarchy.
      const HcsStability stability = monodisperse_stability(dimension, s.cooling_rate, at.values, at.dense, at.alpha,
                                                            at.cooling_temperature_exponent);
      for (const auto* column : wanted) row.push_back(column->value(at.values, stability));
    }
    t.rows.push_back(std::move(row));
  }
  t.counters = result.counters;
  return t;
}

}  // namespace detail

}  // namespace gkt
