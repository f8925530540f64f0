#include "gkt/transport/rough/rough_sonine_transport.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"
#include "transport/rough/rough_aligned_families.hpp"
#include "transport/rough/rough_chiral_families.hpp"
#include "transport/rough/rough_sonine_systems.hpp"
#include "transport/rough/rough_weighted_elements.hpp"

namespace gkt {

struct RoughSonineTransport::Tables {
  int dimension = 3;
  bool spin_decoupled = false;
  double hcs_temperature_ratio = 1;
  Rational kappa;
  detail::RoughCollisionElements elements;
  std::unique_ptr<detail::RoughWeightedCollisionElements> weighted;  ///< null without cumulant tables
  std::unique_ptr<detail::RoughFamilyElements> aligned;  ///< null for the product space (aligned or full otherwise)
  bool members_tied = false;  ///< the full space's member level follows the order (rough_full_space_members)
};

RoughSonineTransport::RoughSonineTransport(int dimension, const Rational& alpha, const Rational& beta,
                                           const Rational& kappa, int highest_order) {
  const auto p = rough_parameters_symbolic_temperature(dimension, alpha, beta, kappa);  // range checks
  if (highest_order < 1) throw std::invalid_argument("order: must be an integer >= 1");
  const RoughCoolingState hcs =
      rough_homogeneous_cooling_state(dimension, alpha, beta, kappa, RoughHcsScheme::maxwellian);
  tables_ = std::unique_ptr<Tables>(new Tables{dimension, hcs.spin_decoupled, hcs.temperature_ratio, kappa,
                                               detail::RoughCollisionElements(p, highest_order), nullptr, nullptr});
}

RoughSonineTransport::RoughSonineTransport(int dimension, const Rational& alpha, const Rational& beta,
                                           const Rational& kappa, int highest_order, RoughTrialSpace space,
                                           int aligned_order)
    : RoughSonineTransport(dimension, alpha, beta, kappa, highest_order) {
  if (space == RoughTrialSpace::product) return;
  if (aligned_order < (space == RoughTrialSpace::full ? 0 : 1))
    throw std::invalid_argument(
        "aligned_order: must be an integer >= 1 (0 ties the full space's members to the order)");
  if (space == RoughTrialSpace::full) {
    tables_->members_tied = aligned_order == kRoughMembersTiedToOrder;
    tables_->aligned = std::make_unique<detail::RoughChiralFamilyElements>(
        dimension, alpha, beta, kappa, highest_order,
        tables_->members_tied ? rough_full_space_members(highest_order) : aligned_order);
    return;
  }
  if (dimension != 3)
    throw std::invalid_argument("trial_space: the aligned-spin families need dimension = 3 (c.w vanishes for disks)");
  tables_->aligned = std::make_unique<detail::RoughAlignedFamilyElements>(
      rough_parameters_symbolic_temperature(dimension, alpha, beta, kappa), highest_order, aligned_order);
}

RoughSonineTransport::RoughSonineTransport(int dimension, const Rational& alpha, const Rational& beta,
                                           const Rational& kappa, int highest_order, int cumulant_degree,
                                           bool orientation)
    : RoughSonineTransport(dimension, alpha, beta, kappa, highest_order) {
  if (cumulant_degree < 2) throw std::invalid_argument("cumulant_degree: must be an integer >= 2");
  if (orientation && dimension != 3)
    throw std::invalid_argument("orientation: the b_pq terms need dimension = 3 (c.w vanishes for disks)");
  tables_->weighted = std::make_unique<detail::RoughWeightedCollisionElements>(
      rough_parameters_symbolic_temperature(dimension, alpha, beta, kappa), highest_order, cumulant_degree,
      orientation);
}

int rough_full_space_members(int order) {
  if (order < 1) throw std::invalid_argument("order: must be an integer >= 1");
  return (order + 1) / 2;
}

RoughSonineTransport::~RoughSonineTransport() = default;
RoughSonineTransport::RoughSonineTransport(RoughSonineTransport&&) noexcept = default;
RoughSonineTransport& RoughSonineTransport::operator=(RoughSonineTransport&&) noexcept = default;

int RoughSonineTransport::highest_order() const { return tables_->elements.highest_order(); }

int RoughSonineTransport::cumulant_degree() const { return tables_->weighted ? tables_->weighted->weight_degree() : 0; }

RoughTransportValues RoughSonineTransport::at_cooling_state(int order, const RoughSonineCoolingState& hcs) const {
  const Tables& t = *tables_;
  if (order < 1 || order > highest_order())
    throw std::invalid_argument("order: must be an integer in [1, " + std::to_string(highest_order()) + "]");
  if (t.aligned)
    throw std::invalid_argument("trial_space: the aligned-spin families are built about Maxwellians only (use at)");
  if (!hcs.solved) throw std::invalid_argument("hcs: the Sonine HCS has no solution at this state");
  if (hcs.spin_decoupled != t.spin_decoupled)
    throw std::invalid_argument("hcs: the Sonine HCS is of another state (spin decoupled or not)");
  if (!t.weighted) throw std::invalid_argument("hcs: the tables were built without cumulant_degree");
  const bool oriented = std::any_of(hcs.orientation_coefficients.begin(), hcs.orientation_coefficients.end(),
                                    [](double b) { return b != 0; });
  if (oriented && !t.weighted->oriented())
    throw std::invalid_argument("hcs: orientation terms b_pq without the orientation tables (build with orientation)");
  detail::RoughCumulantReference reference{t.weighted.get(), hcs.indices, hcs.cumulants, {}, {}, hcs.cooling_rate};
  if (oriented) {
    reference.orientation_indices = hcs.orientation_indices;
    reference.orientation_coefficients = hcs.orientation_coefficients;
    for (const auto& [p, q] : hcs.orientation_indices)
      if (p + q + 2 > cumulant_degree())
        throw std::invalid_argument("hcs: orientation coefficient b" + std::to_string(p) + std::to_string(q) +
                                    " above the weighted tables' degree " + std::to_string(cumulant_degree()));
  }
  for (const auto& [p, q] : hcs.indices)
    if (p + q > cumulant_degree())
      throw std::invalid_argument("hcs: cumulant a" + std::to_string(p) + std::to_string(q) +
                                  " above the weighted tables' degree " + std::to_string(cumulant_degree()));
  const double theta = hcs.temperature_ratio;
  const bool decoupled = std::isinf(theta);
  if (decoupled != t.spin_decoupled || !(theta > 0))
    throw std::invalid_argument("hcs: temperature_ratio must be > 0 and finite (+inf only at beta = -1)");
  const detail::RoughModeState state{t.dimension, decoupled ? 1.0 : theta / t.kappa.to_double(), decoupled, &reference};
  return detail::solve_rough_navier_stokes(t.elements, state, order, theta);
}

RoughTransportValues RoughSonineTransport::at(int order, double temperature_ratio) const {
  const Tables& t = *tables_;
  if (order < 1 || order > highest_order())
    throw std::invalid_argument("order: must be an integer in [1, " + std::to_string(highest_order()) + "]");
  const bool decoupled = std::isinf(temperature_ratio);
  if (decoupled != t.spin_decoupled || !(temperature_ratio > 0))
    throw std::invalid_argument("temperature_ratio: must be > 0 and finite (+inf only at beta = -1)");
  // At β = −1 no translational element depends on τ (the spin decouples): any τ will do.
  const detail::RoughModeState state{t.dimension,     decoupled ? 1.0 : temperature_ratio / t.kappa.to_double(),
                                     decoupled,       nullptr,
                                     t.aligned.get(), t.members_tied ? rough_full_space_members(order) : 0};
  return detail::solve_rough_navier_stokes(t.elements, state, order, temperature_ratio);
}

RoughTransportValues RoughSonineTransport::at_maxwellian_state(int order) const {
  return at(order, tables_->hcs_temperature_ratio);
}

}  // namespace gkt
