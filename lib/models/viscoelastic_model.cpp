// The "viscoelastic" model: BP's expansion constants of the homogeneous cooling of viscoelastic
// spheres (3D) and the δ'-series of the Navier–Stokes coefficients, derived by the engine
// (viscoelastic.hpp, viscoelastic_transport.hpp; docs/theory.md §13).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>

#include "gkt/evolution/hcs_stability.hpp"
#include "gkt/transport/viscoelastic/viscoelastic_transport.hpp"
#include "models/models.hpp"

namespace gkt::detail {

namespace {

constexpr int kMaxSonineOrder = 6;  // the error estimate asks for N + 1 and N + 2 ≤ 8

/// The series coefficients offered by name: <family>_<j>, j = 1 … J (δ'^j).
const std::vector<std::string>& series_families() {
  static const std::vector<std::string> f{"a2", "cooling_rate", "shear_viscosity", "thermal_conductivity",
                                          "density_heat_coefficient"};
  return f;
}

const std::array<std::string, 3> kCritical{"critical_wavenumber_shear", "critical_wavenumber_heat", "critical_length"};

/// Returns a2, ζ*, η*, κ*, μ* or a critical value (theory.md (14.1), (14.6)) at δ' from the series
/// through δ'^orders.
double at_state(const ViscoelasticTransportSeries& s, const std::string& name, double x, int orders) {
  const ViscoelasticState v = viscoelastic_state(s, x, orders);
  if (name == "a2") return v.a2;
  if (name == "cooling_rate") return v.cooling_rate;
  if (name == "shear_viscosity") return v.shear_viscosity;
  if (name == "thermal_conductivity") return v.thermal_conductivity;
  if (name == "density_heat_coefficient") return v.density_heat_coefficient;
  StabilityDensity dilute;
  dilute.cooling_temperature_exponent = v.cooling_temperature_exponent;
  const HcsStability h =
      hcs_stability(3, v.cooling_rate, v.shear_viscosity, v.thermal_conductivity, v.density_heat_coefficient, dilute);
  return name == "critical_wavenumber_shear"  ? h.shear_wavenumber
         : name == "critical_wavenumber_heat" ? h.heat_wavenumber
                                              : h.critical_length;
}

/// Returns the δ'^j coefficient of a series family.
double coefficient(const ViscoelasticTransportSeries& s, const std::string& name, int j) {
  const auto& c = name == "a2"                     ? s.cumulants[2]
                  : name == "cooling_rate"         ? s.cooling_rate
                  : name == "shear_viscosity"      ? s.shear_viscosity
                  : name == "thermal_conductivity" ? s.thermal_conductivity
                                                   : s.density_heat_coefficient;
  return c[static_cast<std::size_t>(j)];
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
    for (const auto& f : series_families()) names.push_back(f);
    for (const auto& c : kCritical) names.push_back(c);
    return names;
  }
  /// The constants and series coefficients; the values at one δ' (`delta_prime`) only on request.
  [[nodiscard]] std::vector<std::string> default_coefficients(const ParameterPoint&) const override {
    std::vector<std::string> names{"omega0", "omega1", "q0"};
    const int orders = static_cast<int>(ViscoelasticRestitution{}.series().size());
    for (const auto& f : series_families())
      for (int j = 1; j <= orders; ++j) names.push_back(f + "_" + std::to_string(j));
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

  std::vector<CoefficientValue> evaluate(const ParameterPoint& point, const std::vector<std::string>& coefficients,
                                         const OrderRequest& order) override {
    const Rational c1 = point.number("c1", Rational::parse("1.15344"));
    parameters().front().check(c1);
    if (!order.tolerance && (order.order < 1 || order.order > kMaxSonineOrder))
      throw std::invalid_argument("order: \"viscoelastic\" takes a Sonine order in [1, " +
                                  std::to_string(kMaxSonineOrder) + "], got " + std::to_string(order.order));
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
      if (std::find(kCritical.begin(), kCritical.end(), name) != kCritical.end() ||
          std::find(series_families().begin(), series_families().end(), name) != series_families().end()) {
        if (!point.numbers.contains("delta_prime"))
          throw std::invalid_argument("delta_prime: required for '" + name + "' (a number in [0, 0.3])");
        const Rational delta_prime = point.number("delta_prime", Rational(0));
        parameters()[1].check(delta_prime);
        const double x = delta_prime.to_double();
        out.push_back(choose_order(order, kMaxSonineOrder, [&](int n) {
          const int all = static_cast<int>(restitution.series().size());
          auto at = [&](int m, int terms) { return at_state(series_at(m), name, x, terms); };
          const double value = at(n, all), shorter = at(n, all - 1);
          OrderValue v = estimate_from_doubles(value, at(n + 1, all), at(n + 2, all));
          if (v.infinite) {  // δ' = 0, the elastic gas: L_c* = +∞ whatever the series' length
            v.defined = shorter == value;
            v.infinite = v.defined;
          } else if (v.defined && std::isfinite(shorter)) {  // the last δ'-term as the series' remainder
            v.estimate.error = v.estimate.error + (Rational::from_double(value) - Rational::from_double(shorter)).abs();
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
      if (std::find(series_families().begin(), series_families().end(), base) == series_families().end() || j < 1 ||
          j > orders || name.substr(split + 1) != std::to_string(j))
        throw std::invalid_argument("coefficients: unknown coefficient '" + name +
                                    "' for model viscoelastic; valid: " + join(coefficient_names()));
      out.push_back(choose_order(order, kMaxSonineOrder, [&](int n) {
        auto at = [&](int m) { return Rational::from_double(coefficient(series_at(m), base, j)); };
        return OrderValue{estimate_truncation(at(n), at(n + 1), at(n + 2)), true, false};
      }));
    }
    return out;
  }

 private:
  Rational cached_c1_{-1};
  std::map<int, ViscoelasticTransportSeries> series_;  // by Sonine order, for cached_c1_
};

}  // namespace

std::unique_ptr<TransportModel> make_viscoelastic_model() { return std::make_unique<ViscoelasticModel>(); }

}  // namespace gkt::detail
