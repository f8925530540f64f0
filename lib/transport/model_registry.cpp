#include <algorithm>
#include <array>
#include <map>

#include <flint/fmpz.h>
#include <functional>
#include <stdexcept>

#include "gkt/hard_spheres.hpp"
#include "gkt/transport_model.hpp"

namespace gkt {

std::string ParameterSpec::allowed() const {
  const std::string kind_name = kind == Kind::integer ? "an integer" : "a number";
  if (kind == Kind::integer && min_inclusive && max_inclusive && max - min <= Rational(1))
    return min.to_string() + " or " + max.to_string();
  return kind_name + " in " + (min_inclusive ? "[" : "(") + min.to_string() + ", " + max.to_string() +
         (max_inclusive ? "]" : ")");
}

void ParameterSpec::check(const Rational& v) const {
  auto fail = [&]() { return std::invalid_argument(name + ": must be " + allowed() + ", got " + v.to_string()); };
  if (kind == Kind::integer) {
    Rational floor_part;
    fmpz_fdiv_q(fmpq_numref(floor_part.raw()), fmpq_numref(v.raw()), fmpq_denref(v.raw()));
    if (!(floor_part == v)) throw fail();
  }
  if (min_inclusive ? v < min : v <= min) throw fail();
  if (max_inclusive ? v > max : v >= max) throw fail();
}

namespace {

/// Picks the order: fixed, or the smallest meeting the tolerance (else the maximum, flagged).
template <class Estimate>
CoefficientValue choose_order(const OrderRequest& request, int max_order, Estimate&& estimate) {
  if (!request.tolerance) {
    const TruncationEstimate e = estimate(request.order);
    return {e.value, e.error, request.order, e.converging, true};
  }
  TruncationEstimate e{};
  for (int n = 1; n <= max_order; ++n) {
    e = estimate(n);
    if (e.converging && e.error < *request.tolerance) return {e.value, e.error, n, true, true};
  }
  return {e.value, e.error, max_order, false, true};
}

/// Elastic dilute hard spheres (d = 3) or disks (d = 2).
class HardSphereModel final : public TransportModel {
 public:
  [[nodiscard]] std::string name() const override { return "hard-spheres"; }
  [[nodiscard]] std::string description() const override {
    return "elastic dilute hard spheres (d = 3) or disks (d = 2): exact Sonine approximants";
  }
  [[nodiscard]] std::vector<std::string> coefficient_names() const override {
    return {"shear_viscosity", "thermal_conductivity", "self_diffusion"};
  }
  [[nodiscard]] std::vector<ParameterSpec> parameters() const override {
    return {{"dimension", ParameterSpec::Kind::integer, Rational(2), Rational(3), true, true, Rational(3),
             "spatial dimension"}};
  }
  [[nodiscard]] int max_order() const override { return kHardSphereMaxOrder; }

  std::vector<CoefficientValue> evaluate(const std::map<std::string, Rational>& parameters,
                                         const std::vector<std::string>& coefficients,
                                         const OrderRequest& order) override {
    Rational dim = parameters.contains("dimension") ? parameters.at("dimension") : Rational(3);
    this->parameters().front().check(dim);
    const int d = dim == Rational(2) ? 2 : 3;
    auto& system = systems_[static_cast<std::size_t>(d - 2)];
    if (!system) system = std::make_unique<HardSphereSonineSystem>(d);
    const auto names = coefficient_names();
    std::vector<CoefficientValue> out;
    for (const auto& c : coefficients) {
      const auto it = std::find(names.begin(), names.end(), c);
      if (it == names.end())
        throw std::invalid_argument("coefficients: unknown coefficient '" + c + "' for model " + name());
      const auto which = static_cast<HardSphereCoefficient>(it - names.begin());
      out.push_back(choose_order(order, max_order(), [&](int n) { return system->estimate(which, n); }));
    }
    return out;
  }

 private:
  std::array<std::unique_ptr<HardSphereSonineSystem>, 2> systems_;
};

using Factory = std::function<std::unique_ptr<TransportModel>()>;

const std::map<std::string, Factory>& registry() {
  static const std::map<std::string, Factory> models{
      {"hard-spheres", [] { return std::make_unique<HardSphereModel>(); }},
  };
  return models;
}

}  // namespace

std::unique_ptr<TransportModel> make_transport_model(const std::string& name) {
  const auto& r = registry();
  const auto it = r.find(name);
  if (it == r.end()) {
    std::string valid;
    for (const auto& [key, factory] : r) valid += (valid.empty() ? "" : ", ") + ("\"" + key + "\"");
    throw std::invalid_argument("model: unknown model \"" + name + "\"; valid models: " + valid);
  }
  return it->second();
}

std::vector<std::string> transport_model_names() {
  std::vector<std::string> names;
  for (const auto& [key, factory] : registry()) names.push_back(key);
  return names;
}

}  // namespace gkt
