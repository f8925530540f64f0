// The "viscoelastic" model: BP's expansion constants of the homogeneous cooling of viscoelastic
// spheres (3D) and the δ'-series of the Navier–Stokes coefficients, derived by the engine
// (viscoelastic.hpp, viscoelastic_transport.hpp; docs/theory.md §13).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <optional>

#include "gkt/evolution/homogeneous_cooling_evolution.hpp"
#include "gkt/operators/viscoelastic_hierarchy.hpp"
#include "gkt/transport/viscoelastic/viscoelastic_transport.hpp"
#include "models/models.hpp"

namespace gkt::detail {

namespace {

constexpr int kMaxSonineOrder = 6;  // the error estimate asks for N + 1 and N + 2 ≤ 8
constexpr int kMaxSeriesOrder = 8;  // viscoelastic_transport_series: N + 3 (theory.md (6.3)) exists below the cap

/// A value of the state at one δ': a2, ζ*, η*, κ*, μ* — whose δ'-series coefficients are also
/// offered as <name>_<j>, j = 1 … J — or an HCS stability value (theory.md (14.1), (14.6)).
struct StateValue {
  const char* name;
  double (*at)(const ViscoelasticState&, const HcsStability&);
  /// The δ'^j coefficients of a series family; null for the stability values.
  const std::vector<double>& (*series)(const ViscoelasticTransportSeries&);
};

using State = ViscoelasticState;
using Series = ViscoelasticTransportSeries;
/// Every state value, series families first (the order of coefficient_names()); built once.
const std::array<StateValue, 8> kStateValues{{
    {"a2", [](const State& v, const HcsStability&) { return v.a2; },
     [](const Series& s) -> const std::vector<double>& { return s.cumulants[2]; }},
    {"cooling_rate", [](const State& v, const HcsStability&) { return v.cooling_rate; },
     [](const Series& s) -> const std::vector<double>& { return s.cooling_rate; }},
    {"shear_viscosity", [](const State& v, const HcsStability&) { return v.shear_viscosity; },
     [](const Series& s) -> const std::vector<double>& { return s.shear_viscosity; }},
    {"thermal_conductivity", [](const State& v, const HcsStability&) { return v.thermal_conductivity; },
     [](const Series& s) -> const std::vector<double>& { return s.thermal_conductivity; }},
    {"density_heat_coefficient", [](const State& v, const HcsStability&) { return v.density_heat_coefficient; },
     [](const Series& s) -> const std::vector<double>& { return s.density_heat_coefficient; }},
    {"critical_wavenumber_shear", [](const State&, const HcsStability& h) { return h.shear_wavenumber; }, nullptr},
    {"critical_wavenumber_heat", [](const State&, const HcsStability& h) { return h.heat_wavenumber; }, nullptr},
    {"critical_length", [](const State&, const HcsStability& h) { return h.critical_length; }, nullptr},
}};

/// Returns the state value named `name`, or null.
const StateValue* state_value(const std::string& name) {
  const auto it =
      std::find_if(kStateValues.begin(), kStateValues.end(), [&](const StateValue& v) { return name == v.name; });
  return it == kStateValues.end() ? nullptr : &*it;
}

/// Returns the value at δ' = x from the series through δ'^orders; the stability values from ζ*,
/// η*, κ*, μ* and λ_T of that state.
double at_state(const Series& s, const StateValue& value, double x, int orders) {
  const ViscoelasticState v = viscoelastic_state(s, x, orders);
  if (value.series != nullptr) return value.at(v, {});
  return value.at(v, monodisperse_stability(3, v.cooling_rate,
                                            {v.shear_viscosity, v.thermal_conductivity, v.density_heat_coefficient}, {},
                                            1.0, v.cooling_temperature_exponent));
}

class ViscoelasticModel final : public TransportModel {
 public:
  [[nodiscard]] std::string name() const override { return "viscoelastic"; }
  [[nodiscard]] std::string description() const override {
    return "viscoelastic spheres (3D), restitution 1 - C1 delta' u^(1/5) + (3/5) C1^2 delta'^2 u^(2/5): "
           "expansion constants of the cooling gas and delta'-series of eta*, kappa*, mu* (order 1 = first "
           "Sonine, as Brilliantov & Poeschel 2002)";
  }
  [[nodiscard]] std::vector<std::string> coefficient_names() const override {
    auto names = default_coefficients({});
    for (const auto& v : kStateValues) names.emplace_back(v.name);
    return names;
  }
  /// The constants and series coefficients; the values at one δ' (`delta_prime`) only on request.
  [[nodiscard]] std::vector<std::string> default_coefficients(const ParameterPoint&) const override {
    std::vector<std::string> names{"omega0", "omega1", "q0"};
    const int orders = static_cast<int>(ViscoelasticRestitution{}.series().size());
    for (const auto& v : kStateValues)
      if (v.series != nullptr)
        for (int j = 1; j <= orders; ++j) names.push_back(std::string(v.name) + "_" + std::to_string(j));
    return names;
  }
  [[nodiscard]] std::vector<ParameterSpec> parameters() const override {
    return {{"c1",
             ParameterSpec::Kind::real,
             Rational(0),
             Rational(10),
             false,
             true,
             Rational::parse("1.15344"),
             "first coefficient C1 of the viscoelastic restitution series",
             {}},
            {"delta_prime",
             ParameterSpec::Kind::real,
             Rational(0),
             Rational(3, 10),
             true,
             true,
             Rational(0),
             "delta' = delta (2T/T0)^(1/10) of the state at which a2, cooling_rate, shear_viscosity, ..., "
             "critical_* are summed from the series",
             {}}};
  }
  [[nodiscard]] int max_order() const override { return kMaxSonineOrder; }

  [[nodiscard]] bool supports(Capability capability) const override { return capability != Capability::formula; }

  std::vector<CoefficientValue> evaluate(const ParameterPoint& point, const std::vector<std::string>& coefficients,
                                         const OrderRequest& order) override {
    const SchemaPoint p(parameters(), point);  // validated by the registry's guard
    const Rational c1 = p.number("c1");
    const ViscoelasticRestitution restitution = ViscoelasticRestitution::hertz(c1.to_double());
    if (c1 != cached_c1_) {
      series_.clear();
      cached_c1_ = c1;
    }
    auto series_at = [&](int n) -> const ViscoelasticTransportSeries& {
      auto it = series_.find(n);
      if (it == series_.end()) it = series_.emplace(n, viscoelastic_transport_series(n, restitution)).first;
      return it->second;
    };
    std::optional<ViscoelasticConstants> constants;
    std::vector<CoefficientValue> out;
    for (const auto& name : coefficients) {
      if (name == "omega0" || name == "omega1" || name == "q0") {  // exact at a = 0: no Sonine truncation
        if (!constants) constants = viscoelastic_constants(restitution);
        const double v = name == "omega0" ? constants->omega0 : name == "omega1" ? constants->omega1 : constants->q0;
        out.push_back({Rational::from_double(v), Rational(0), 1, true, false, true});
        continue;
      }
      if (const StateValue* value = state_value(name)) {
        if (!p.given("delta_prime"))
          throw std::invalid_argument("delta_prime: required for '" + name + "' (" + p.spec("delta_prime").allowed() +
                                      ")");
        const double x = p.number("delta_prime").to_double();
        out.push_back(choose_order(order, kMaxSonineOrder, [&](int n) {
          const int all = static_cast<int>(restitution.series().size());
          auto at = [&](int m, int terms) { return at_state(series_at(m), *value, x, terms); };
          const double v_n = at(n, all), shorter = at(n, all - 1);
          // (6.3): order N + 3 where the changes change sign (NaN past the series' orders: not confirmed).
          OrderValue v = estimate_from_doubles_confirmed(v_n, at(n + 1, all), at(n + 2, all), [&] {
            return n + 3 <= kMaxSeriesOrder ? at(n + 3, all) : std::numeric_limits<double>::quiet_NaN();
          });
          if (v.infinite) {  // δ' = 0, the elastic gas: L_c* = +∞ whatever the series' length
            v.defined = shorter == v_n;
            v.infinite = v.defined;
          } else if (v.defined && std::isfinite(shorter)) {  // the last δ'-term as the series' remainder
            v.estimate.error = v.estimate.error + (Rational::from_double(v_n) - Rational::from_double(shorter)).abs();
          } else {
            v.defined = false;
          }
          return v;
        }));
        continue;
      }
      const auto split = name.rfind('_');
      const std::string base = split == std::string::npos ? name : name.substr(0, split);
      const int j = split == std::string::npos ? -1 : std::atoi(name.c_str() + split + 1);
      const int orders = static_cast<int>(restitution.series().size());
      const StateValue* family = state_value(base);
      if (family == nullptr || family->series == nullptr || j < 1 || j > orders ||
          name.substr(split + 1) != std::to_string(j))
        throw std::invalid_argument("coefficients: unknown coefficient '" + name +
                                    "' for model viscoelastic; valid: " + join(coefficient_names()));
      out.push_back(choose_order(order, kMaxSonineOrder, [&](int n) {
        auto at = [&](int m) {
          return Rational::from_double(family->series(series_at(m))[static_cast<std::size_t>(j)]);
        };
        return OrderValue{estimate_truncation_checked(
                              at(n), at(n + 1), at(n + 2),
                              [&] { return n + 3 <= kMaxSeriesOrder ? std::optional(at(n + 3)) : std::nullopt; }),
                          true, false};
      }));
    }
    return out;
  }

  [[nodiscard]] std::vector<ParameterSpec> evolution_parameters() const override {
    std::vector<ParameterSpec> specs{dimension_spec("spatial dimension (viscoelastic spheres: 3)"),
                                     {"delta",
                                      ParameterSpec::Kind::real,
                                      Rational(0),
                                      Rational(3, 10),
                                      true,
                                      true,
                                      Rational(0),
                                      "delta of the initial state T0 (the delta expansion is for small delta)",
                                      {}}};
    for (auto& spec : evolution_common_parameters()) specs.push_back(std::move(spec));
    return specs;
  }
  [[nodiscard]] std::vector<std::string> trajectory_coefficients() const override {
    return trajectory_coefficient_names();
  }
  /// The hierarchy at δ'(τ) = δ (2T/T0)^{1/10} integrated from a2(0) (theory.md §13.2); η*, κ*, μ*
  /// and λ_T from the δ'-series at Sonine order N at δ'(τ).
  Trajectory evolve(const TrajectoryRequest& request) override {
    const SchemaPoint p(evolution_parameters(), request.parameters);
    if (p.number("dimension") != Rational(3))
      throw std::invalid_argument("dimension: \"viscoelastic\" is three-dimensional (3)");
    if (!p.given("delta"))
      throw std::invalid_argument("delta: required for \"viscoelastic\", " + p.spec("delta").allowed());
    evolution_a2_spec(3).check(p.number("a2"));
    const int order = static_cast<int>(p.number("order").to_double());
    if (!request.coefficients.empty() && order > kMaxTransportOrder)
      throw std::invalid_argument("order: viscoelastic transport along the trajectory needs an integer in [1, " +
                                  std::to_string(kMaxTransportOrder) + "], got " + std::to_string(order));
    const int k_max = order + 1;  // cumulants a_2 … a_{order+1}
    const double delta = p.number("delta").to_double();
    const EvolutionResult result = evolve_viscoelastic_cooling(
        ViscoelasticHierarchy(k_max), delta, {p.number("a2").to_double()}, request.times, p.number("rtol").to_double(),
        p.number("atol").to_double(), static_cast<long>(p.number("max_steps").to_double()));
    std::optional<ViscoelasticTransportSeries> series;
    if (!request.coefficients.empty()) series = viscoelastic_transport_series(order);
    return tabulate_trajectory(name(), 3, k_max, result, request.coefficients, [&](const EvolutionSample& s) {
      const ViscoelasticState state = viscoelastic_state(*series, delta * std::pow(2.0 * s.temperature, 0.1));
      return SampleTransport{{state.shear_viscosity, state.thermal_conductivity, state.density_heat_coefficient},
                             state.cooling_temperature_exponent};
    });
  }

 private:
  static constexpr int kMaxTransportOrder = 8;  // viscoelastic_transport_series
  Rational cached_c1_{-1};
  std::map<int, ViscoelasticTransportSeries> series_;  // by Sonine order, for cached_c1_
};

}  // namespace

std::unique_ptr<TransportModel> make_viscoelastic_model() { return std::make_unique<ViscoelasticModel>(); }

}  // namespace gkt::detail
