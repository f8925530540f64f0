// The one registry of transport models (cf. Cantera's TransportFactory). Every model it hands out
// validates its calls against its schema first (validated_model.cpp).
#include <functional>
#include <map>
#include <stdexcept>

#include "gkt/models/transport_model.hpp"
#include "models/models.hpp"

namespace gkt {

namespace {

using Factory = std::function<std::unique_ptr<TransportModel>()>;

const std::map<std::string, Factory>& registry() {
  static const std::map<std::string, Factory> models{
      {"aggregation", detail::make_aggregation_model},
      {"gravity-column", detail::make_gravity_column_model},
      {"hard-spheres", detail::make_hard_sphere_model},
      {"mixture", detail::make_mixture_model},
      {"rough", detail::make_rough_model},
      {"rough-walton", detail::make_rough_walton_model},
      {"smooth-inelastic", detail::make_smooth_inelastic_model},
      {"uniform-shear", detail::make_uniform_shear_model},
      {"viscoelastic", detail::make_viscoelastic_model},
  };
  return models;
}

}  // namespace

std::unique_ptr<TransportModel> make_transport_model(const std::string& name) {
  const auto& r = registry();
  const auto it = r.find(name);
  if (it == r.end()) {
    throw std::invalid_argument("model: unknown model \"" + name +
                                "\"; valid models: " + detail::join(transport_model_names(), "\""));
  }
  return detail::validated(it->second());
}

std::vector<std::string> transport_model_names() {
  std::vector<std::string> names;
  for (const auto& entry : registry()) names.push_back(entry.first);
  return names;
}

}  // namespace gkt
