// The "viscoelastic" model: BP's expansion constants of the homogeneous cooling of viscoelastic
// spheres (3D), derived by the engine (viscoelastic.hpp; docs/theory.md §13).
#include <cmath>

#include "gkt/viscoelastic.hpp"
#include "transport/models.hpp"

namespace gkt::detail {

namespace {

class ViscoelasticModel final : public TransportModel {
 public:
  [[nodiscard]] std::string name() const override { return "viscoelastic"; }
  [[nodiscard]] std::string description() const override {
    return "viscoelastic spheres (3D), restitution 1 - C1 delta' u^(1/5) + (3/5) C1^2 delta'^2 u^(2/5): "
           "expansion constants of the cooling gas (first Sonine, as Brilliantov & Poeschel 2002)";
  }
  [[nodiscard]] std::vector<std::string> coefficient_names() const override {
    return {"omega0", "omega1", "q0", "a2_1", "a2_2", "shear_viscosity_1", "density_heat_coefficient_1"};
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
             {}}};
  }
  [[nodiscard]] int max_order() const override { return 1; }

  std::vector<CoefficientValue> evaluate(const ParameterPoint& point, const std::vector<std::string>& coefficients,
                                         const OrderRequest& order) override {
    const Rational c1 = point.number("c1", Rational::parse("1.15344"));
    parameters().front().check(c1);
    if (order.tolerance || order.order != 1)
      throw std::invalid_argument("order: \"viscoelastic\" gives the first Sonine constants (order = 1)");
    ViscoelasticRestitution restitution;
    restitution.c1 = c1.to_double();
    const ViscoelasticConstants c = viscoelastic_constants(restitution);
    std::vector<CoefficientValue> out;
    for (const auto& name : coefficients) {
      const double value = name == "omega0"                       ? c.omega0
                           : name == "omega1"                     ? c.omega1
                           : name == "q0"                         ? c.q0
                           : name == "a2_1"                       ? c.a2_1
                           : name == "a2_2"                       ? c.a2_2
                           : name == "shear_viscosity_1"          ? c.shear_viscosity_1
                           : name == "density_heat_coefficient_1" ? c.density_heat_coefficient_1
                                                                  : std::nan("");
      if (std::isnan(value))
        throw std::invalid_argument("coefficients: unknown coefficient '" + name + "' for model viscoelastic");
      // ω0, ω1, q0 are exact at a = 0 (no Sonine truncation); a2_1, a2_2 are first Sonine (K = 2)
      // like BP's; their truncation error is not estimated yet (reported as 0, flagged).
      const bool truncated = name != "omega0" && name != "omega1" && name != "q0";
      out.push_back({Rational::from_double(value), Rational(0), 1, !truncated, false, true});
    }
    return out;
  }
};

}  // namespace

std::unique_ptr<TransportModel> make_viscoelastic_model() { return std::make_unique<ViscoelasticModel>(); }

}  // namespace gkt::detail
