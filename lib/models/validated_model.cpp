// The guard the registry puts in front of every model: each façade entry point checks its input
// against the model's declared schema (names, ranges, choices, order) once, here, so a misspelled
// key or an out-of-range value is refused exactly as the scene loader refuses it, whoever calls.
#include <algorithm>
#include <stdexcept>

#include "models/models.hpp"

namespace gkt::detail {

namespace {

/// Returns "model \"<name>\"", the owner named in unknown-parameter errors.
std::string owner(const TransportModel& m) { return "model \"" + m.name() + "\""; }

class ValidatedModel final : public TransportModel {
 public:
  explicit ValidatedModel(std::unique_ptr<TransportModel> model) : model_(std::move(model)) {}

  [[nodiscard]] std::string name() const override { return model_->name(); }
  [[nodiscard]] std::string description() const override { return model_->description(); }
  [[nodiscard]] std::vector<std::string> coefficient_names() const override { return model_->coefficient_names(); }
  [[nodiscard]] std::vector<std::string> scene_coefficient_names(const ParameterPoint& fixed) const override {
    return model_->scene_coefficient_names(fixed);
  }
  [[nodiscard]] std::vector<std::string> default_coefficients(const ParameterPoint& fixed) const override {
    return model_->default_coefficients(fixed);
  }
  [[nodiscard]] std::vector<ParameterSpec> parameters() const override { return model_->parameters(); }
  [[nodiscard]] std::vector<ParameterSpec> scene_parameters(const ParameterPoint& fixed) const override {
    return model_->scene_parameters(fixed);
  }
  [[nodiscard]] int max_order() const override { return model_->max_order(); }
  [[nodiscard]] bool supports(Capability capability) const override { return model_->supports(capability); }
  [[nodiscard]] std::vector<ParameterSpec> evolution_parameters() const override {
    return model_->evolution_parameters();
  }
  [[nodiscard]] std::vector<std::string> trajectory_coefficients() const override {
    return model_->trajectory_coefficients();
  }
  [[nodiscard]] std::vector<std::string> table_caveats(const std::map<std::string, std::string>& choices,
                                                       const std::vector<std::string>& coefficients, int highest_order,
                                                       bool tolerance) const override {
    return model_->table_caveats(choices, coefficients, highest_order, tolerance);
  }

  std::vector<CoefficientValue> evaluate(const ParameterPoint& point, const std::vector<std::string>& coefficients,
                                         const OrderRequest& order) override {
    // The point's own dimension fixes ranges that differ between d = 2 and 3 (packing fraction).
    validate_parameters(model_->scene_parameters(point), point, owner(*model_));
    validate_order(order, model_->max_order());
    return model_->evaluate(point, coefficients, order);
  }
  ClosedForm closed_form(const ParameterPoint& point, const std::string& coefficient, int order) override {
    if (!model_->supports(Capability::formula)) return TransportModel::closed_form(point, coefficient, order);
    validate_parameters(model_->scene_parameters(point), point, owner(*model_));
    validate_order({order, {}}, model_->max_order());
    return model_->closed_form(point, coefficient, order);
  }
  Trajectory evolve(const TrajectoryRequest& request) override {
    if (!model_->supports(Capability::evolve)) return TransportModel::evolve(request);
    const auto schema = model_->evolution_parameters();
    validate_parameters(schema, request.parameters, owner(*model_) + " (evolution)");
    if (sets_own_output_times(schema)) {
      if (!request.times.empty())
        throw std::invalid_argument("times: " + owner(*model_) + " sets its output times from t_end and points");
    } else {
      for (std::size_t i = 0; i < request.times.size(); ++i)
        if (!(request.times[i] > 0) || (i > 0 && !(request.times[i] > request.times[i - 1])))
          throw std::invalid_argument("times: must be a non-empty list of increasing times > 0");
      if (request.times.empty()) throw std::invalid_argument("times: must be a non-empty list of increasing times > 0");
    }
    const auto offered = model_->trajectory_coefficients();
    for (const auto& c : request.coefficients)
      if (std::find(offered.begin(), offered.end(), c) == offered.end())
        throw std::invalid_argument("coefficients: '" + c + "' is not offered along a " + model_->name() +
                                    " trajectory; valid: " + join(offered));
    return model_->evolve(request);
  }

 private:
  std::unique_ptr<TransportModel> model_;
};

}  // namespace

std::unique_ptr<TransportModel> validated(std::unique_ptr<TransportModel> model) {
  return std::make_unique<ValidatedModel>(std::move(model));
}

}  // namespace gkt::detail
