// The "aggregation" model: sticking grains (issue 21). For one pair of sizes i, j (monomer units)
// at temperatures T_i, T_j it gives the collision success factor ψ, the collision rate, the
// aggregation kernel β_ij and the energy a collision loses (docs/theory.md §20; reduced units of
// gkt/transport/aggregation/aggregation_kernel.hpp).
#include <cmath>
#include <stdexcept>

#include "gkt/transport/aggregation/aggregation_kernel.hpp"
#include "gkt/transport/aggregation/success_factor.hpp"
#include "gkt/transport/common/pair_correlation.hpp"
#include "models/models.hpp"

namespace gkt::detail {

namespace {

constexpr long kMaxSize = 1000000;

ParameterSpec real(const std::string& name, Rational lo, bool lo_in, Rational hi, Rational fallback,
                   const std::string& description) {
  return {name, ParameterSpec::Kind::real, lo, hi, lo_in, true, fallback, description, {}};
}

ParameterSpec size(const std::string& name) {
  return {name,        ParameterSpec::Kind::integer,
          Rational(1), Rational(kMaxSize),
          true,        true,
          Rational(1), "cluster size in monomers (mass i, diameter i^(1/d))",
          {}};
}

class AggregationModel final : public TransportModel {
 public:
  [[nodiscard]] std::string name() const override { return "aggregation"; }
  [[nodiscard]] std::string description() const override {
    return "sticking grains: collision success factor psi (relative-speed or normal-impact criterion, Maxwellian or "
           "HCS a2), collision rate, aggregation kernel and energy loss of sizes i, j at temperatures T_i, T_j";
  }
  [[nodiscard]] std::vector<std::string> coefficient_names() const override {
    return {"success_factor",  "collision_rate", "aggregation_kernel",
            "sticking_energy", "rebound_energy", "energy_loss"};
  }
  [[nodiscard]] std::vector<ParameterSpec> parameters() const override {
    return {dimension_spec(),
            restitution_spec("alpha", "normal restitution of rebounding collisions"),
            real("critical_energy", Rational(0), true, Rational(1000000), Rational(1),
                 "critical energy theta*/theta0 of two monomers; theta*_ij = theta*_11 mu_ij/mu_11"),
            size("size_i"),
            size("size_j"),
            real("temperature_i", Rational(0), false, Rational(1000000), Rational(1), "T_i/theta0 of size i"),
            real("temperature_j", Rational(0), false, Rational(1000000), Rational(1), "T_j/theta0 of size j"),
            real("a2", Rational(-1), true, Rational(1), Rational(0),
                 "HCS kurtosis cumulant of both partners (equal sizes and temperatures only); "
                 "[-8/(d(d+2)), 4/(d+2)]"),
            real("packing_fraction", Rational(0), true, Rational(7, 10), Rational(0),
                 "packing fraction: chi(phi) of the default pair correlation multiplies every rate"),
            choice_spec("criterion", "when a collision sticks", {"relative-speed", "normal-impact", "always"}),
            choice_spec("kernel", "aggregation kernel", {"kinetic", "constant", "sum"})};
  }
  [[nodiscard]] int max_order() const override { return 1; }
  [[nodiscard]] bool supports(Capability capability) const override {
    return capability == Capability::table || capability == Capability::evolve;
  }
  [[nodiscard]] std::vector<ParameterSpec> evolution_parameters() const override {
    return aggregation_evolution_parameters();
  }
  Trajectory evolve(const TrajectoryRequest& request) override { return aggregation_trajectory(request); }

  std::vector<CoefficientValue> evaluate(const ParameterPoint& point, const std::vector<std::string>& coefficients,
                                         const OrderRequest& order) override {
    const auto specs = parameters();
    std::vector<double> v;
    for (std::size_t k = 0; k + 2 < specs.size(); ++k) {
      const Rational x = point.number(specs[k].name, specs[k].default_value);
      specs[k].check(x);
      v.push_back(x.to_double());
    }
    const std::string criterion_name = point.choice("criterion", "relative-speed");
    specs[specs.size() - 2].check(criterion_name);
    const std::string kernel_name = point.choice("kernel", "kinetic");
    specs.back().check(kernel_name);
    if (order.tolerance || order.order != 1)
      throw std::invalid_argument("order: the aggregation model is closed-form: use order = 1");
    const int d = static_cast<int>(v[0]);
    const int i = static_cast<int>(v[3]), j = static_cast<int>(v[4]);
    const double ti = v[5], tj = v[6], a2 = v[7];
    const Rational phi = point.number("packing_fraction", Rational(0));
    if (phi >= max_packing_fraction(d))
      throw std::invalid_argument("packing_fraction: must be a number in [0, " +
                                  max_packing_fraction(d).to_decimal_string() +
                                  ") for dimension = " + std::to_string(d) + ", got " + phi.to_decimal_string());
    if (a2 != 0 && (i != j || ti != tj))
      throw std::invalid_argument(
          "a2: the HCS cumulant applies to a pair of equal sizes and temperatures (size_i = size_j, "
          "temperature_i = temperature_j)");
    AggregationGas gas;
    gas.dimension = d;
    gas.alpha = v[1];
    gas.critical_energy = v[2];
    gas.criterion = criterion_name == "normal-impact" ? StickingCriterion::normal_impact
                    : criterion_name == "always"      ? StickingCriterion::always
                                                      : StickingCriterion::relative_speed;
    gas.kernel = kernel_name == "constant" ? AggregationKernel::constant
                 : kernel_name == "sum"    ? AggregationKernel::sum
                                           : AggregationKernel::kinetic;
    gas.pair_correlation = pair_correlations().front().contact_value(d, phi).to_double();
    // The pair temperature T_ij = μ(T_i/m_i + T_j/m_j) sets both the relative speed and x = θ*_ij/T_ij.
    const double pair_t = pair_temperature(i, ti, j, tj);
    const double x = gas.criterion == StickingCriterion::always ? 0.0 : critical_pair_energy(gas, i, j) / pair_t;
    const PairCollisionAverages avg = pair_collision_averages(d, gas.criterion, x, a2);
    const double rate = collision_rate_coefficient(d, i, j, pair_t, gas.pair_correlation) * avg.rate_factor;
    const double inelastic = 1 - gas.alpha * gas.alpha;
    std::vector<CoefficientValue> out;
    for (const auto& c : coefficients) {
      double value = 0;
      if (c == "success_factor") {
        value = avg.success_factor;
      } else if (c == "collision_rate") {
        value = rate;
      } else if (c == "aggregation_kernel") {
        value = gas.kernel == AggregationKernel::kinetic ? rate * avg.success_factor
                                                         : pair_rates(gas, i, j, pair_t).aggregation;
      } else if (c == "sticking_energy") {
        value = avg.sticking_energy * pair_t;
      } else if (c == "rebound_energy") {
        value = inelastic * avg.normal_energy * pair_t;
      } else if (c == "energy_loss") {
        value = gas.kernel == AggregationKernel::kinetic
                    ? rate * pair_t * (avg.sticking_energy + inelastic * avg.normal_energy)
                    : pair_rates(gas, i, j, pair_t).energy_loss;
      } else {
        throw std::invalid_argument("coefficients: unknown coefficient '" + c +
                                    "' for model aggregation; valid: " + join(coefficient_names()));
      }
      CoefficientValue cv;
      cv.order = 1;
      cv.exact = false;
      cv.error_estimated = false;  // closed forms: no truncation
      cv.value = Rational::from_double(value);
      out.push_back(cv);
    }
    return out;
  }
};

}  // namespace

std::unique_ptr<TransportModel> make_aggregation_model() { return std::make_unique<AggregationModel>(); }

}  // namespace gkt::detail
