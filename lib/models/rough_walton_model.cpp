// The "rough-walton" model: rough inelastic hard spheres (d = 3) or disks (d = 2) with Coulomb
// friction in Walton's form, β(γ) = min{β0, −1 + ((1+κ)/κ)(1+α) μ_f cot γ}
// (rough_walton.hpp; docs/theory.md §19.10): the Maxwellian HCS (θ, ζ*), the first-Sonine η*, κ*, μ*
// and the scalar Navier–Stokes response (bulk viscosity, first-order cooling rate). μ_f → ∞ is the "rough"
// model.
#include <cmath>
#include <stdexcept>

#include "gkt/transport/rough/rough_walton.hpp"
#include "models/models.hpp"
#include "models/rough_parameters.hpp"

namespace gkt::detail {

namespace {

class RoughWaltonModel final : public TransportModel {
 public:
  [[nodiscard]] std::string name() const override { return "rough-walton"; }
  [[nodiscard]] std::string description() const override {
    return "rough inelastic hard spheres (d = 3) or disks (d = 2) with Coulomb friction (Walton): "
           "beta = min{beta0, -1 + ((1+kappa)/kappa)(1+alpha) friction cot(impact angle)}; Maxwellian "
           "homogeneous cooling state (temperature ratio, cooling rate); first-Sonine shear and bulk viscosity, "
           "thermal conductivity, density heat coefficient and first-order cooling rate";
  }
  [[nodiscard]] std::vector<std::string> coefficient_names() const override {
    return {"rotational_temperature_ratio",
            "cooling_rate",
            "shear_viscosity",
            "bulk_viscosity",
            "thermal_conductivity",
            "density_heat_coefficient",
            "cooling_rate_first_order"};
  }
  [[nodiscard]] std::vector<ParameterSpec> parameters() const override {
    auto specs = rough_grain_parameters(
        "beta0", "tangential restitution of sticking collisions (-1 smooth, +1 perfectly rough)");
    specs.push_back({"friction",
                     ParameterSpec::Kind::real,
                     Rational(0),
                     Rational(1000000),
                     true,
                     true,
                     Rational(1, 2),
                     "Coulomb friction coefficient mu_f (0: smooth; the model rough is mu_f -> infinity)",
                     {}});
    return specs;
  }
  [[nodiscard]] int max_order() const override { return 1; }
  [[nodiscard]] bool supports(Capability capability) const override {
    return capability == Capability::table || capability == Capability::evolve;
  }
  [[nodiscard]] std::vector<ParameterSpec> evolution_parameters() const override {
    return rough_evolution_parameters(parameters(), {"dimension", "alpha", "beta0", "moment_of_inertia", "friction"});
  }
  /// T_t(τ), T_r(τ) from Maxwellians, the Walton rates by quadrature at every step (theory.md §19.13).
  Trajectory evolve(const TrajectoryRequest& request) override {
    return rough_walton_trajectory(evolution_parameters(), request);
  }

  std::vector<CoefficientValue> evaluate(const ParameterPoint& point, const std::vector<std::string>& coefficients,
                                         const OrderRequest& order) override {
    const auto specs = parameters();
    const auto [d, alpha, beta0, kappa] = read_rough_grain(specs, point, "beta0");
    require_first_approximation(order, "rough-walton");
    const RoughWaltonState s =
        rough_walton_cooling_state(d, alpha, beta0, kappa, SchemaPoint(specs, point).number("friction"));
    std::vector<CoefficientValue> out;
    for (const auto& name : coefficients) {
      double x = 0;
      if (name == "rotational_temperature_ratio") {
        x = s.temperature_ratio;  // +inf when the spin decouples
      } else if (name == "cooling_rate") {
        x = s.cooling_rate;
      } else if (name == "shear_viscosity") {
        x = s.shear_viscosity;  // theory.md (19.23)
      } else if (name == "thermal_conductivity") {
        x = s.thermal_conductivity;  // theory.md (19.15) with (19.23)
      } else if (name == "density_heat_coefficient") {
        x = s.density_heat_coefficient;  // theory.md (19.16)
      } else if (name == "bulk_viscosity") {
        x = s.bulk_viscosity;  // theory.md (19.18)
      } else if (name == "cooling_rate_first_order") {
        x = s.cooling_rate_first_order;  // theory.md (19.19)
      } else {
        throw std::invalid_argument("coefficients: unknown coefficient '" + name +
                                    "' for model rough-walton; valid: " + join(coefficient_names()));
      }
      out.push_back(first_approximation(x));
    }
    return out;
  }
};

}  // namespace

std::unique_ptr<TransportModel> make_rough_walton_model() { return std::make_unique<RoughWaltonModel>(); }

}  // namespace gkt::detail
