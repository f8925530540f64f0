// The "uniform-shear" model: the steady uniform shear flow of smooth inelastic disks (d = 2) or
// spheres (d = 3) at constant α in Grad's approximation (uniform_shear_flow.hpp; docs/theory.md
// §22), in GNB's units: reduced_shear_rate γ = a ℓ/√(2T/m) (ℓ = 1/(2nσ) in 2D, 1/(πnσ²) in 3D) and
// the stresses P_ij/(2nT) (docs/conventions.md). One approximation only: order must be 1.
#include <stdexcept>

#include "gkt/transport/closed_forms/uniform_shear_flow.hpp"
#include "models/models.hpp"

namespace gkt::detail {

namespace {

class UniformShearModel final : public TransportModel {
 public:
  [[nodiscard]] std::string name() const override { return "uniform-shear"; }
  [[nodiscard]] std::string description() const override {
    return "steady uniform shear flow of smooth inelastic hard spheres (d = 3) or disks (d = 2) at constant "
           "alpha, Grad's moment approximation: reduced shear rate a l/sqrt(2T/m) and stresses P_ij/(2nT)";
  }
  [[nodiscard]] std::vector<std::string> coefficient_names() const override {
    return {"reduced_shear_rate", "stress_xx", "stress_yy", "stress_zz", "stress_xy"};
  }
  /// stress_zz exists in 3D only.
  [[nodiscard]] std::vector<std::string> scene_coefficient_names(const ParameterPoint& fixed) const override {
    if (fixed.number("dimension", Rational(3)) == Rational(3)) return coefficient_names();
    return {"reduced_shear_rate", "stress_xx", "stress_yy", "stress_xy"};
  }
  [[nodiscard]] std::vector<ParameterSpec> parameters() const override {
    return {detail::dimension_spec(),
            detail::restitution_spec("alpha",
                                     "coefficient of normal restitution (alpha = 1: no shear in the steady state)")};
  }
  [[nodiscard]] int max_order() const override { return 1; }

  std::vector<CoefficientValue> evaluate(const ParameterPoint& point, const std::vector<std::string>& coefficients,
                                         const OrderRequest& order) override {
    const auto specs = parameters();
    const Rational dim = point.number("dimension", Rational(3));
    specs[0].check(dim);
    const Rational alpha = point.number("alpha", Rational(1));
    specs[1].check(alpha);
    if (order.tolerance)
      throw std::invalid_argument("tolerance: the uniform-shear model has Grad's approximation only: use order = 1");
    if (order.order != 1) throw std::invalid_argument("order: must be exactly 1, got " + std::to_string(order.order));
    const int d = dim == Rational(2) ? 2 : 3;
    const UniformShearFlow usf = uniform_shear_flow_grad(d, alpha.to_double());
    std::vector<CoefficientValue> out;
    for (const auto& name : coefficients) {
      double x = 0;
      if (name == "reduced_shear_rate") {
        x = usf.reduced_shear_rate;
      } else if (name == "stress_xx") {
        x = usf.stress_xx;
      } else if (name == "stress_yy") {
        x = usf.stress_yy;
      } else if (name == "stress_zz" && d == 3) {
        x = usf.stress_zz;
      } else if (name == "stress_zz") {
        throw std::invalid_argument("coefficients: stress_zz exists in dimension 3 only, got dimension = 2");
      } else if (name == "stress_xy") {
        x = usf.stress_xy;
      } else {
        throw std::invalid_argument("coefficients: unknown coefficient '" + name +
                                    "' for model uniform-shear; valid: " + join(coefficient_names()));
      }
      CoefficientValue v;
      v.value = Rational::from_double(x);
      v.order = 1;
      v.exact = false;
      v.error_estimated = false;  // Grad's approximation: no higher order to estimate its error from
      out.push_back(v);
    }
    return out;
  }
};

}  // namespace

std::unique_ptr<TransportModel> make_uniform_shear_model() { return std::make_unique<UniformShearModel>(); }

}  // namespace gkt::detail
