// The "rough" model: rough inelastic hard spheres (d = 3) or disks (d = 2) with constant normal
// and tangential restitution α, β and reduced moment of inertia κ = 4I/(mσ²). Provides the
// homogeneous cooling state in the Maxwellian or the linear first-Sonine approximation
// (rough_homogeneous_cooling_state.hpp; docs/theory.md §19): θ = T_r/T_t, ζ*, a20, a02, a11; and the
// shear viscosity at first Sonine (rough_shear_viscosity.hpp, §19.7) and the orientational
// correlation C (rough_orientation_correlation.hpp, §19.8); κ*, μ* (rough_thermal_conductivity.hpp) and
// the bulk viscosity and first-order cooling rate (rough_bulk_viscosity.hpp, §19.9), d = 2, 3. At order N > 1
// (or with a tolerance) the five Navier–Stokes columns come from rough_sonine_transport.hpp (§19.15) with the
// error of theory.md (6.1) from orders N + 1, N + 2; the HCS columns stay first-Sonine (order 1 only).
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>

#include "gkt/transport/rough/rough_bulk_viscosity.hpp"
#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"
#include "gkt/transport/rough/rough_orientation_correlation.hpp"
#include "gkt/transport/rough/rough_shear_viscosity.hpp"
#include "gkt/transport/rough/rough_sonine_transport.hpp"
#include "gkt/transport/rough/rough_thermal_conductivity.hpp"
#include "models/models.hpp"
#include "models/rough_parameters.hpp"

namespace gkt::detail {

namespace {

// Order N needs the tables to N + 2 for its error estimate: K = 10 at the cap costs ~5 s per (α, β, κ) in 3D
// (docs/performance.md).
constexpr int kMaxRoughOrder = 8;

/// The Navier–Stokes columns of the higher-order solver (theory.md §19.15).
constexpr std::array<const char*, 5> kSonineColumns{"shear_viscosity", "bulk_viscosity", "thermal_conductivity",
                                                    "density_heat_coefficient", "cooling_rate_first_order"};

bool is_sonine_column(const std::string& name) {
  return std::find(kSonineColumns.begin(), kSonineColumns.end(), name) != kSonineColumns.end();
}

/// Returns the column `name` of one order's values.
double pick(const RoughTransportValues& v, const std::string& name) {
  if (name == "shear_viscosity") return v.shear_viscosity;
  if (name == "bulk_viscosity") return v.bulk_viscosity;
  if (name == "thermal_conductivity") return v.thermal_conductivity;
  if (name == "density_heat_coefficient") return v.density_heat_coefficient;
  return v.cooling_rate_first_order;
}

/// The tables of one (d, α, β, κ) and the values of every order solved so far.
struct RoughSonineEntry {
  std::unique_ptr<RoughSonineTransport> transport;
  std::map<int, RoughTransportValues> values;
};

class RoughModel final : public TransportModel {
 public:
  [[nodiscard]] std::string name() const override { return "rough"; }
  [[nodiscard]] std::string description() const override {
    return "rough inelastic hard spheres (d = 3) or disks (d = 2), constant normal and tangential restitution "
           "alpha, beta and reduced moment of inertia: homogeneous cooling state (temperature ratio, cooling "
           "rate, cumulants a20, a02, a11), Maxwellian or first Sonine; shear and bulk viscosity, thermal "
           "conductivity, density heat coefficient, first-order cooling rate at first Sonine or Sonine order up to 8 "
           "(translation x spin Sonine products, Maxwellian reference); translation-rotation "
           "correlation (3D)";
  }
  [[nodiscard]] std::vector<std::string> coefficient_names() const override {
    return {"rotational_temperature_ratio",
            "cooling_rate",
            "a20",
            "a02",
            "a11",
            "shear_viscosity",
            "bulk_viscosity",
            "thermal_conductivity",
            "density_heat_coefficient",
            "cooling_rate_first_order",
            "orientation_correlation"};
  }
  [[nodiscard]] std::vector<ParameterSpec> parameters() const override {
    auto specs = rough_grain_parameters("beta", "tangential restitution coefficient (-1 smooth, +1 perfectly rough)");
    specs.push_back(choice_spec("hcs",
                                "approximation of the homogeneous cooling state: first Sonine (cumulants linear), "
                                "Maxwellian, or first Sonine falling back to Maxwellian (cumulants nan) where the "
                                "linear scheme has no root",
                                {"linear", "maxwellian", "linear-or-maxwellian"}));
    return specs;
  }
  [[nodiscard]] int max_order() const override { return kMaxRoughOrder; }
  [[nodiscard]] bool supports(Capability capability) const override {
    return capability == Capability::table || capability == Capability::evolve;
  }
  [[nodiscard]] std::vector<ParameterSpec> evolution_parameters() const override {
    return rough_evolution_parameters(parameters(), {"dimension", "alpha", "beta", "moment_of_inertia", "hcs"});
  }
  /// T_t(τ), T_r(τ) and the cumulants from Maxwellians at T_t(0), T_r(0) (theory.md §19.13).
  Trajectory evolve(const TrajectoryRequest& request) override {
    return rough_trajectory(evolution_parameters(), request);
  }

  std::vector<CoefficientValue> evaluate(const ParameterPoint& point, const std::vector<std::string>& coefficients,
                                         const OrderRequest& order) override {
    const auto specs = parameters();
    const auto [d, alpha, beta, kappa] = read_rough_grain(specs, point, "beta");
    const std::string scheme = SchemaPoint(specs, point).choice("hcs");
    // Order 1 asked for as such is the first approximation of §19.7–19.9 (error not estimated); order 1 chosen by
    // a tolerance scan (row_tolerance set) carries its estimate like any other order.
    const bool first = order.order == 1 && !order.tolerance && !order.row_tolerance;
    for (const auto& name : coefficients)
      if (!first && !is_sonine_column(name))
        throw std::invalid_argument("coefficients: " + name +
                                    " of model rough is computed at order 1 only; use order = 1 without tolerance, "
                                    "or ask for shear_viscosity, bulk_viscosity, thermal_conductivity, "
                                    "density_heat_coefficient, cooling_rate_first_order");
    RoughCoolingState s;
    if (scheme == "linear") {
      s = linear_rough_state(d, alpha, beta, kappa);  // refuses the no-root region (theory.md §19.6)
    } else if (scheme == "maxwellian") {
      s = rough_homogeneous_cooling_state(d, alpha, beta, kappa, RoughHcsScheme::maxwellian);
    } else {  // linear-or-maxwellian: the Maxwellian θ, ζ* and nan cumulants where the linear scheme has no root
      s = rough_homogeneous_cooling_state(d, alpha, beta, kappa, RoughHcsScheme::linear);
      if (!s.linear_scheme_solved) {
        s = rough_homogeneous_cooling_state(d, alpha, beta, kappa, RoughHcsScheme::maxwellian);
        s.a20 = s.a02 = s.a11 = std::nan("");
      }
    }
    std::vector<CoefficientValue> out;
    for (const auto& name : coefficients) {
      if (!first) {  // order N > 1 or a tolerance: theory.md §19.15, error (6.1) from orders N + 1, N + 2
        // Tables to N + 2 for a fixed order; a tolerance scan starts at 3 and then takes the cap + 2 at once.
        const int tables = order.tolerance ? kMaxRoughOrder + 2 : order.order + 2;
        out.push_back(choose_order(order, max_order(), [&, d = d, alpha = alpha, beta = beta, kappa = kappa](int n) {
          const auto at = [&](int m) { return pick(sonine_values(d, alpha, beta, kappa, m, tables), name); };
          const double v0 = at(n), v1 = at(n + 1), v2 = at(n + 2);
          return estimate_from_doubles(v0, v1, v2);
        }));
        continue;
      }
      double x = 0;
      if (name == "rotational_temperature_ratio") {
        x = s.temperature_ratio;
      } else if (name == "cooling_rate") {
        x = s.cooling_rate;
      } else if (name == "a20") {
        x = s.a20;
      } else if (name == "a02") {
        x = s.a02;
      } else if (name == "a11") {
        x = s.a11;
      } else if (name == "orientation_correlation") {
        if (d != 3)
          throw std::invalid_argument(
              "coefficients: orientation_correlation needs dimension = 3 (disks spin normal to the plane)");
        x = rough_orientation_correlation(alpha, beta, kappa).correlation;  // theory.md §19.8
      } else if (name == "thermal_conductivity") {
        x = rough_thermal_conductivity(d, alpha, beta, kappa).total;  // theory.md §19.7; NaN at β = −1
      } else if (name == "density_heat_coefficient") {
        x = rough_thermal_conductivity(d, alpha, beta, kappa).density_heat_total;  // theory.md (19.16)
      } else if (name == "bulk_viscosity") {
        x = rough_bulk_viscosity(d, alpha, beta, kappa).bulk_viscosity;  // theory.md (19.18); NaN at β = −1
      } else if (name == "cooling_rate_first_order") {
        x = rough_bulk_viscosity(d, alpha, beta, kappa).cooling_rate_first_order;  // theory.md (19.19)
      } else if (name == "shear_viscosity") {
        // First Sonine with Maxwellian weights at the Maxwellian θ, whatever `hcs` (theory.md §19.7).
        x = rough_shear_viscosity(d, alpha, beta, kappa);
      } else {
        throw std::invalid_argument("coefficients: unknown coefficient '" + name +
                                    "' for model rough; valid: " + join(coefficient_names()));
      }
      // θ = inf at β = −1 (no spin cooling state), NaN where the linear scheme has no root.
      out.push_back(first_approximation(x));
    }
    return out;
  }

 private:
  /// Returns the values of order n; the tables are built to order 3 first, then to `tables` (≥ n) if needed.
  RoughTransportValues sonine_values(int d, const Rational& alpha, const Rational& beta, const Rational& kappa, int n,
                                     int tables) {
    if (sonine_.size() > 64) sonine_.clear();  // bound memory in long sweeps (never mid-evaluation)
    const std::string key =
        std::to_string(d) + "|" + alpha.to_string() + "|" + beta.to_string() + "|" + kappa.to_string();
    RoughSonineEntry& entry = sonine_[key];
    if (const auto it = entry.values.find(n); it != entry.values.end()) return it->second;
    if (!entry.transport || entry.transport->highest_order() < n) {
      const int k = n <= 3 ? 3 : std::max(n, tables);
      entry.transport = std::make_unique<RoughSonineTransport>(d, alpha, beta, kappa, k);
    }
    return entry.values[n] = entry.transport->at_maxwellian_state(n);
  }

  std::map<std::string, RoughSonineEntry> sonine_;
};

}  // namespace

RoughCoolingState linear_rough_state(int dimension, const Rational& alpha, const Rational& beta,
                                     const Rational& kappa) {
  RoughCoolingState s = rough_homogeneous_cooling_state(dimension, alpha, beta, kappa, RoughHcsScheme::linear);
  if (s.linear_scheme_solved) return s;
  throw std::invalid_argument("hcs: the linear scheme has no root at dimension = " + std::to_string(dimension) +
                              ", alpha = " + alpha.to_decimal_string() + ", beta = " + beta.to_decimal_string() +
                              ", moment_of_inertia = " + kappa.to_decimal_string() + " (" +
                              rough_linear_no_root_region(dimension) +
                              "); use hcs = \"maxwellian\" or \"linear-or-maxwellian\"");
}

std::unique_ptr<TransportModel> make_rough_model() { return std::make_unique<RoughModel>(); }

}  // namespace gkt::detail
