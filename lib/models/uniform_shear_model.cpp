// The "uniform-shear" model: the steady uniform shear flow of smooth inelastic disks (d = 2) or
// spheres (d = 3) at constant α (docs/theory.md §22), in GNB's units: reduced_shear_rate
// γ = a ℓ/√(2T/m) (ℓ = 1/(2nσ) in 2D, 1/(πnσ²) in 3D) and the stresses P_ij/(2nT)
// (docs/conventions.md). order = 1 is Grad's approximation (uniform_shear_flow.hpp, no error
// estimate); order N ≥ 2 the moment solution with Hermite polynomials of degree ≤ 2N and the full
// bilinear collision moments (uniform_shear_moments.hpp, theory.md §22.7), its error the
// successive-order difference |v_N − v_{N−1}|; N ≤ 6 in 2D, ≤ 3 in 3D.
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include "gkt/transport/closed_forms/uniform_shear_flow.hpp"
#include "gkt/transport/closed_forms/uniform_shear_moments.hpp"
#include "models/models.hpp"

namespace gkt::detail {

namespace {

class UniformShearModel final : public TransportModel {
 public:
  [[nodiscard]] std::string name() const override { return "uniform-shear"; }
  [[nodiscard]] std::string description() const override {
    return "steady uniform shear flow of smooth inelastic hard spheres (d = 3) or disks (d = 2) at constant "
           "alpha, Grad's moment approximation (order 1) or the moment solution with Hermite polynomials of degree "
           "<= 2N and the full bilinear collision moments (order N >= 2): reduced shear rate a l/sqrt(2T/m) and "
           "stresses P_ij/(2nT)";
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
  [[nodiscard]] int max_order() const override { return uniform_shear_max_moment_order(2); }

  std::vector<CoefficientValue> evaluate(const ParameterPoint& point, const std::vector<std::string>& coefficients,
                                         const OrderRequest& order) override {
    const auto specs = parameters();
    const Rational dim = point.number("dimension", Rational(3));
    specs[0].check(dim);
    const Rational alpha = point.number("alpha", Rational(1));
    specs[1].check(alpha);
    const int d = dim == Rational(2) ? 2 : 3;
    const int cap = uniform_shear_max_moment_order(d);
    if (order.order < 1 || order.order > max_order())
      throw std::invalid_argument("order: must be an integer in [1, " + std::to_string(max_order()) + "], got " +
                                  std::to_string(order.order));
    if (!order.tolerance && order.order > cap)
      throw std::invalid_argument(
          "order: must be at most " + std::to_string(cap) + " in dimension " + std::to_string(d) +
          " (the moment solution's cost grows as K^3, theory.md §22.7), got " + std::to_string(order.order));
    for (const auto& name : coefficients)
      if (name != "reduced_shear_rate" && name != "stress_xx" && name != "stress_yy" && name != "stress_xy" &&
          name != "stress_zz")
        throw std::invalid_argument("coefficients: unknown coefficient '" + name +
                                    "' for model uniform-shear; valid: " + join(coefficient_names()));
      else if (name == "stress_zz" && d == 2)
        throw std::invalid_argument("coefficients: stress_zz exists in dimension 3 only, got dimension = 2");
    std::vector<CoefficientValue> out;
    if (order.order == 1 && !order.tolerance) {  // Grad's approximation, as before (no error estimate)
      const UniformShearFlow usf = uniform_shear_flow_grad(d, alpha.to_double());
      for (const auto& name : coefficients) {
        CoefficientValue v;
        v.value = Rational::from_double(
            pick(name, usf.reduced_shear_rate, usf.stress_xx, usf.stress_yy, usf.stress_zz, usf.stress_xy));
        v.order = 1;
        v.exact = false;
        v.error_estimated = false;  // Grad's approximation: no higher order to estimate its error from
        out.push_back(v);
      }
      return out;
    }
    for (const auto& name : coefficients)
      out.push_back(choose_order(order, cap, [&](int n) {
        OrderValue v;
        v.exact = false;
        v.defined = n >= 2;  // order 1 (Grad) has no previous order to estimate its error from
        if (!v.defined) return v;
        const double now = value_at(d, alpha, n, name), before = value_at(d, alpha, n - 1, name);
        v.estimate.value = Rational::from_double(now);
        v.estimate.error = Rational::from_double(std::abs(now - before));
        v.estimate.converging = true;
        return v;
      }));
    return out;
  }

 private:
  static double pick(const std::string& name, double gamma, double xx, double yy, double zz, double xy) {
    if (name == "reduced_shear_rate") return gamma;
    if (name == "stress_xx") return xx;
    if (name == "stress_yy") return yy;
    if (name == "stress_zz") return zz;
    return xy;
  }

  /// Returns one column at order n: Grad's (n = 1) or the moment solution's (n ≥ 2), the
  /// solutions cached per dimension and α (orders 1 … n are solved together, by continuation).
  double value_at(int d, const Rational& alpha, int n, const std::string& name) {
    if (n == 1) {
      const UniformShearFlow g = uniform_shear_flow_grad(d, alpha.to_double());
      return pick(name, g.reduced_shear_rate, g.stress_xx, g.stress_yy, g.stress_zz, g.stress_xy);
    }
    const std::string key = std::to_string(d) + "|" + alpha.to_string();
    if (cache_.size() > 256 && !cache_.contains(key)) cache_.clear();  // bound memory in long sweeps
    auto& solutions = cache_[key];
    if (static_cast<int>(solutions.size()) < n) {
      solutions.clear();
      if (alpha == Rational(1)) {  // equilibrium: no shear at every order
        for (int k = 1; k <= n; ++k) {
          UniformShearMoments eq;
          eq.order = k;
          eq.stress_xx = eq.stress_yy = 0.5;
          eq.stress_zz = d == 3 ? 0.5 : 0.0;
          solutions.push_back(eq);
        }
      } else {
        solutions = uniform_shear_flow_moments(d, alpha.to_double(), n);
      }
    }
    const auto& s = solutions[static_cast<std::size_t>(n - 1)];
    return pick(name, s.reduced_shear_rate, s.stress_xx, s.stress_yy, s.stress_zz, s.stress_xy);
  }

  std::map<std::string, std::vector<UniformShearMoments>> cache_;
};

}  // namespace

std::unique_ptr<TransportModel> make_uniform_shear_model() { return std::make_unique<UniformShearModel>(); }

}  // namespace gkt::detail
