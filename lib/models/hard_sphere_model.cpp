// The "hard-spheres" model: elastic dilute hard spheres or disks (hard_spheres.hpp).
#include <algorithm>
#include <array>

#include "gkt/transport/monodisperse/hard_spheres.hpp"
#include "models/models.hpp"

namespace gkt::detail {

namespace {

class HardSphereModel final : public TransportModel {
 public:
  [[nodiscard]] std::string name() const override { return "hard-spheres"; }
  [[nodiscard]] std::string description() const override {
    return "elastic dilute hard spheres (d = 3) or disks (d = 2): exact Sonine approximants";
  }
  [[nodiscard]] std::vector<std::string> coefficient_names() const override {
    return {"shear_viscosity", "thermal_conductivity", "self_diffusion"};
  }
  [[nodiscard]] std::vector<ParameterSpec> parameters() const override { return {dimension_spec()}; }
  [[nodiscard]] int max_order() const override { return kHardSphereMaxOrder; }

  [[nodiscard]] bool supports(Capability capability) const override {
    return capability == Capability::table || capability == Capability::formula;
  }

  std::vector<CoefficientValue> evaluate(const ParameterPoint& point, const std::vector<std::string>& coefficients,
                                         const OrderRequest& order) override {
    const int d = SchemaPoint(parameters(), point).number("dimension") == Rational(2) ? 2 : 3;
    auto& system = systems_[static_cast<std::size_t>(d - 2)];
    if (!system) system = std::make_unique<HardSphereSonineSystem>(d);
    const auto names = coefficient_names();
    std::vector<CoefficientValue> out;
    for (const auto& c : coefficients) {
      const auto it = std::find(names.begin(), names.end(), c);
      if (it == names.end())
        throw std::invalid_argument("coefficients: unknown coefficient '" + c + "' for model " + name());
      const auto which = static_cast<HardSphereCoefficient>(it - names.begin());
      out.push_back(choose_order(order, max_order(), [&](int n) { return OrderValue{system->estimate(which, n)}; }));
    }
    return out;
  }

  /// The Sonine approximant at `order` is an exact rational number: a constant closed form.
  ClosedForm closed_form(const ParameterPoint& point, const std::string& coefficient, int order) override {
    const Rational v = evaluate(point, {coefficient}, {order, {}}).front().value;
    const int d = SchemaPoint(parameters(), point).number("dimension") == Rational(2) ? 2 : 3;
    return {RationalFunction{RationalPolynomial(v), RationalPolynomial(1L)}, d, SonineScheme::standard};
  }

 private:
  std::array<std::unique_ptr<HardSphereSonineSystem>, 2> systems_;
};

}  // namespace

std::unique_ptr<TransportModel> make_hard_sphere_model() { return std::make_unique<HardSphereModel>(); }

}  // namespace gkt::detail
