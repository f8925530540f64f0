#include "gkt/transport/rough/rough_sonine_transport.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"
#include "transport/rough/rough_sonine_systems.hpp"

namespace gkt {

struct RoughSonineTransport::Tables {
  int dimension = 3;
  bool spin_decoupled = false;
  double hcs_temperature_ratio = 1;
  Rational kappa;
  detail::RoughCollisionElements elements;
};

RoughSonineTransport::RoughSonineTransport(int dimension, const Rational& alpha, const Rational& beta,
                                           const Rational& kappa, int highest_order) {
  const auto p = rough_parameters_symbolic_temperature(dimension, alpha, beta, kappa);  // range checks
  if (highest_order < 1) throw std::invalid_argument("order: must be an integer >= 1");
  const RoughCoolingState hcs =
      rough_homogeneous_cooling_state(dimension, alpha, beta, kappa, RoughHcsScheme::maxwellian);
  tables_ = std::unique_ptr<Tables>(new Tables{dimension, hcs.spin_decoupled, hcs.temperature_ratio, kappa,
                                               detail::RoughCollisionElements(p, highest_order)});
}

RoughSonineTransport::~RoughSonineTransport() = default;
RoughSonineTransport::RoughSonineTransport(RoughSonineTransport&&) noexcept = default;
RoughSonineTransport& RoughSonineTransport::operator=(RoughSonineTransport&&) noexcept = default;

int RoughSonineTransport::highest_order() const { return tables_->elements.highest_order(); }

RoughTransportValues RoughSonineTransport::at(int order, double temperature_ratio) const {
  const Tables& t = *tables_;
  if (order < 1 || order > highest_order())
    throw std::invalid_argument("order: must be an integer in [1, " + std::to_string(highest_order()) + "]");
  const bool decoupled = std::isinf(temperature_ratio);
  if (decoupled != t.spin_decoupled || !(temperature_ratio > 0))
    throw std::invalid_argument("temperature_ratio: must be > 0 and finite (+inf only at beta = -1)");
  // At β = −1 no translational element depends on τ (the spin decouples): any τ will do.
  const detail::RoughModeState state{t.dimension, decoupled ? 1.0 : temperature_ratio / t.kappa.to_double(), decoupled};
  return detail::solve_rough_navier_stokes(t.elements, state, order, temperature_ratio);
}

RoughTransportValues RoughSonineTransport::at_maxwellian_state(int order) const {
  return at(order, tables_->hcs_temperature_ratio);
}

}  // namespace gkt
