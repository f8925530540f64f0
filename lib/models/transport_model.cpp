// The façade's defaults: what a model that does not support a capability answers.
#include <stdexcept>

#include "gkt/models/transport_model.hpp"

namespace gkt {

const std::vector<std::string>& stability_coefficient_names() {
  static const std::vector<std::string> names{"critical_wavenumber_shear", "critical_wavenumber_heat",
                                              "critical_length"};
  return names;
}

ClosedForm TransportModel::closed_form(const ParameterPoint&, const std::string&, int) {
  throw std::invalid_argument("model: \"" + name() + "\" has no closed forms");
}

Trajectory TransportModel::evolve(const TrajectoryRequest&) {
  throw std::invalid_argument("model: \"" + name() + "\" has no cooling trajectory");
}

std::vector<std::string> TransportModel::table_caveats(const std::map<std::string, std::string>&,
                                                       const std::vector<std::string>&, int, bool) const {
  return {};
}

}  // namespace gkt
