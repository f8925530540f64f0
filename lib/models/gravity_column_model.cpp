// The "gravity-column" model: the steady dilute granular column in gravity heated from the floor
// and closed by an elastic lid (gravity_column.hpp; docs/theory.md §23; seed 001 §3.3.2), with the
// engine's own κ*, μ*, ζ* (model smooth-inelastic at the scene's order or tolerance). One row per
// height: sweep `height` to print the profile. Reduced units m = σ = g = 1, T in mgσ
// (docs/conventions.md "gravity-column").
#include <cmath>
#include <optional>
#include <stdexcept>

#include "gkt/evolution/gravity_column.hpp"
#include "models/models.hpp"

namespace gkt::detail {

namespace {

constexpr int kIntervals = 16000;  // the coarse grid; the value is from 2 kIntervals, the error their difference

ParameterSpec positive(const char* name, double fallback, const char* description) {
  return {name,
          ParameterSpec::Kind::real,
          Rational(0),
          ParameterSpec::unbounded(),
          false,
          true,
          Rational::from_double(fallback),
          description,
          {}};
}

class GravityColumnModel final : public TransportModel {
 public:
  GravityColumnModel() : engine_(make_transport_model("smooth-inelastic")) {}
  [[nodiscard]] std::string name() const override { return "gravity-column"; }
  [[nodiscard]] std::string description() const override {
    return "steady dilute granular column in gravity, heated from the floor (temperature or heat flux), elastic "
           "lid: n, T, q and the local Knudsen number at a height, Navier-Stokes with the engine's kappa*, mu*, zeta*";
  }
  [[nodiscard]] std::vector<std::string> coefficient_names() const override {
    return {"number_density", "temperature", "heat_flux", "knudsen_number"};
  }
  [[nodiscard]] std::vector<ParameterSpec> parameters() const override {
    return {detail::dimension_spec(),
            detail::restitution_spec("alpha", "coefficient of normal restitution"),
            positive("particles_per_area", 1, "N = integral of n dz, in 1/sigma^(d-1)"),
            {"floor",
             ParameterSpec::Kind::choice,
             Rational(0),
             Rational(0),
             true,
             true,
             Rational(0),
             "what the vibrating floor fixes at z = 0",
             {"temperature", "heat_flux"}},
            positive("floor_value", 1, "T(0)/(m g sigma) or q(0)/(m g^(3/2) sigma^(5/2-d)) (floor)"),
            positive("lid_height", 10, "height H of the elastic lid, in sigma"),
            {"height",
             ParameterSpec::Kind::real,
             Rational(0),
             ParameterSpec::unbounded(),
             true,
             true,
             Rational(0),
             "height z of the row, in sigma, 0 <= z <= lid_height",
             {}}};
  }
  [[nodiscard]] int max_order() const override { return engine_->max_order(); }

  std::vector<CoefficientValue> evaluate(const ParameterPoint& point, const std::vector<std::string>& coefficients,
                                         const OrderRequest& order) override {
    const auto specs = parameters();
    const int d = point.number("dimension", Rational(3)) == Rational(2) ? 2 : 3;
    const Rational alpha = point.number("alpha", Rational(1));
    ParameterPoint engine_point;
    engine_point.numbers["dimension"] = Rational(d);
    engine_point.numbers["alpha"] = alpha;
    const auto ns =
        engine_->evaluate(engine_point, {"thermal_conductivity", "density_heat_coefficient", "cooling_rate"}, order);
    for (std::size_t k = 0; k < ns.size(); ++k)
      if (!ns[k].defined || !std::isfinite(ns[k].value.to_double()))
        throw std::invalid_argument(
            "alpha: the engine gives no kappa*, mu*, zeta* at this alpha and order (smooth-inelastic), so no column");
    GravityColumnProblem problem;
    problem.dimension = d;
    problem.transport = {ns[0].value.to_double(), ns[1].value.to_double(), ns[2].value.to_double()};
    problem.particles_per_area = point.number("particles_per_area", Rational(1)).to_double();
    problem.floor =
        point.choice("floor", "temperature") == "heat_flux" ? FloorCondition::heat_flux : FloorCondition::temperature;
    problem.floor_value = point.number("floor_value", Rational(1)).to_double();
    problem.lid_height = point.number("lid_height", Rational(10)).to_double();
    const double z = point.number("height", Rational(0)).to_double();
    if (z > problem.lid_height)
      throw std::invalid_argument("height: must be in [0, lid_height = " + std::to_string(problem.lid_height) +
                                  "], got " + std::to_string(z));
    if (!cached_ || !same(*cached_, problem)) {
      problem.intervals = kIntervals;
      coarse_ = solve_gravity_column(problem);
      problem.intervals = 2 * kIntervals;
      fine_ = solve_gravity_column(problem);
      cached_ = problem;
    }
    const GravityColumnPoint c = column_at(coarse_, z), f = column_at(fine_, z);
    int used_order = 0;
    bool converged = true;
    for (const auto& v : ns) {
      used_order = std::max(used_order, v.order);
      converged = converged && v.converged;
    }
    std::vector<CoefficientValue> out;
    for (const auto& name : coefficients) {
      double value = 0, coarse = 0;
      if (name == "number_density") {
        value = f.number_density, coarse = c.number_density;
      } else if (name == "temperature") {
        value = f.temperature, coarse = c.temperature;
      } else if (name == "heat_flux") {
        value = f.heat_flux, coarse = c.heat_flux;
      } else if (name == "knudsen_number") {
        value = f.knudsen_number, coarse = c.knudsen_number;
      } else {
        throw std::invalid_argument("coefficients: unknown coefficient '" + name +
                                    "' for model gravity-column; valid: " + join(coefficient_names()));
      }
      CoefficientValue v;
      v.value = Rational::from_double(value);
      v.error = Rational::from_double(std::abs(value - coarse));  // grid error: 2M against M intervals
      v.order = used_order;
      v.converged = converged;
      v.exact = false;
      out.push_back(v);
    }
    return out;
  }

 private:
  static bool same(const GravityColumnProblem& a, const GravityColumnProblem& b) {
    return a.dimension == b.dimension && a.transport.thermal_conductivity == b.transport.thermal_conductivity &&
           a.transport.density_heat_coefficient == b.transport.density_heat_coefficient &&
           a.transport.cooling_rate == b.transport.cooling_rate && a.particles_per_area == b.particles_per_area &&
           a.floor == b.floor && a.floor_value == b.floor_value && a.lid_height == b.lid_height;
  }
  std::unique_ptr<TransportModel> engine_;
  std::optional<GravityColumnProblem> cached_;
  GravityColumnProfile coarse_, fine_;
};

}  // namespace

std::unique_ptr<TransportModel> make_gravity_column_model() { return std::make_unique<GravityColumnModel>(); }

}  // namespace gkt::detail
