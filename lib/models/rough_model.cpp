// The "rough" model: rough inelastic hard spheres (d = 3) or disks (d = 2) with constant normal
// and tangential restitution α, β and reduced moment of inertia κ = 4I/(mσ²). Provides the
// homogeneous cooling state in the Maxwellian or the linear first-Sonine approximation
// (rough_homogeneous_cooling_state.hpp; docs/theory.md §19): θ = T_r/T_t, ζ*, a20, a02, a11; and the
// shear viscosity at first Sonine (rough_shear_viscosity.hpp, §19.7) and the orientational
// correlation C (rough_orientation_correlation.hpp, §19.8); κ*, μ* (rough_thermal_conductivity.hpp) and
// the bulk viscosity and first-order cooling rate (rough_bulk_viscosity.hpp, §19.9), d = 2, 3; the
// linear stability of the HCS from them (rough_hcs_stability.hpp, §19.14).
#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "gkt/evolution/rough_hcs_stability.hpp"
#include "gkt/transport/rough/rough_bulk_viscosity.hpp"
#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"
#include "gkt/transport/rough/rough_orientation_correlation.hpp"
#include "gkt/transport/rough/rough_shear_viscosity.hpp"
#include "gkt/transport/rough/rough_thermal_conductivity.hpp"
#include "models/models.hpp"
#include "models/rough_parameters.hpp"

namespace gkt::detail {

namespace {

/// The coefficients of `gkt table` before the stability values were added (its default columns).
const std::vector<std::string> kRoughTableColumns{"rotational_temperature_ratio",
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

/// Returns the HCS stability of the constant-β gas from its first-Sonine coefficients at the Maxwellian
/// θ, ζ* (the state they are computed about, whatever `hcs`; theory.md §19.14). At β = −1 the spin
/// decouples: the smooth gas's translational equations with the translational κ*, μ*.
HcsStability rough_stability(int d, const Rational& alpha, const Rational& beta, const Rational& kappa) {
  const RoughCoolingState m = rough_homogeneous_cooling_state(d, alpha, beta, kappa, RoughHcsScheme::maxwellian);
  const RoughThermalConductivity q = rough_thermal_conductivity(d, alpha, beta, kappa);
  const RoughScalarResponse b = rough_bulk_viscosity(d, alpha, beta, kappa);
  const bool decoupled = std::isinf(m.temperature_ratio);
  RoughStabilityInput in;
  in.dimension = d;
  in.temperature_ratio = m.temperature_ratio;
  // α = 1, β = ±1 loses no energy ((19.3)): ζ* = 0 exactly, where the solver's double may leave 1e-17.
  const bool conservative = alpha == Rational(1) && (beta == Rational(1) || beta == Rational(-1));
  in.cooling_rate = conservative ? 0.0 : m.cooling_rate;
  in.shear_viscosity = rough_shear_viscosity(d, alpha, beta, kappa);
  in.bulk_viscosity = b.bulk_viscosity;  // NaN at β = −1: not used there
  in.thermal_conductivity = decoupled ? q.translational : q.total;
  in.density_heat_coefficient = decoupled ? q.density_heat_translational : q.density_heat_total;
  in.cooling_rate_first_order = b.cooling_rate_first_order;
  return rough_hcs_stability(in);
}

class RoughModel final : public TransportModel {
 public:
  [[nodiscard]] std::string name() const override { return "rough"; }
  [[nodiscard]] std::string description() const override {
    return "rough inelastic hard spheres (d = 3) or disks (d = 2), constant normal and tangential restitution "
           "alpha, beta and reduced moment of inertia: homogeneous cooling state (temperature ratio, cooling "
           "rate, cumulants a20, a02, a11), Maxwellian or first Sonine; first-Sonine shear and bulk viscosity, "
           "thermal conductivity, density heat coefficient, first-order cooling rate; translation-rotation "
           "correlation (3D); linear stability of the homogeneous cooling state";
  }
  [[nodiscard]] std::vector<std::string> coefficient_names() const override {
    auto names = kRoughTableColumns;
    for (const auto& c : stability_coefficient_names()) names.push_back(c);
    return names;
  }
  /// Without `coefficients` a scene gets the columns it had before the stability values existed.
  [[nodiscard]] std::vector<std::string> default_coefficients(const ParameterPoint&) const override {
    return kRoughTableColumns;
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
  [[nodiscard]] int max_order() const override { return 1; }
  [[nodiscard]] bool supports(Capability capability) const override {
    return capability == Capability::table || capability == Capability::evolve || capability == Capability::stability;
  }
  [[nodiscard]] std::vector<ParameterSpec> evolution_parameters() const override {
    auto specs = rough_evolution_parameters(parameters(), {"dimension", "alpha", "beta", "moment_of_inertia", "hcs"});
    for (auto& spec : rough_initial_cumulant_parameters()) specs.push_back(std::move(spec));
    return specs;
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
    require_first_approximation(order, "rough");
    const auto& critical = stability_coefficient_names();
    const auto is_critical = [&critical](const std::string& c) {
      return std::find(critical.begin(), critical.end(), c) != critical.end();
    };
    // The stability values use the Maxwellian state whatever `hcs` (theory.md §19.14): a request for
    // them alone does not need, nor refuse, the scheme's state.
    RoughCoolingState s;
    if (!std::all_of(coefficients.begin(), coefficients.end(), is_critical)) {
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
    }
    std::optional<HcsStability> stability;
    std::vector<CoefficientValue> out;
    for (const auto& name : coefficients) {
      if (is_critical(name)) {
        if (!stability) stability = rough_stability(d, alpha, beta, kappa);  // theory.md §19.14
        out.push_back(rough_stability_value(*stability, name));
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
