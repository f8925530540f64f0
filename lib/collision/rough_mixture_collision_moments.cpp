#include "gkt/collision/rough_mixture_collision_moments.hpp"

#include <stdexcept>
#include <utility>

namespace gkt {

template <class Ring>
RoughCollisionMoments<Ring> rough_mixture_collision_moments(const RoughMixtureParameters<Ring>& parameters,
                                                            const std::vector<RoughForm>& forms,
                                                            const std::vector<int>& degrees,
                                                            std::function<bool(const RoughExponents&)> keep) {
  return RoughCollisionMoments<Ring>(parameters.collision_map(), forms, degrees, std::move(keep));
}

RoughForm rough_mixture_reduced_square(const RoughMixtureParameters<Rational>& parameters, RoughSlot slot) {
  if (parameters.spin_scale_i != Rational(1) || parameters.spin_scale_j != Rational(1))
    throw std::invalid_argument("rough_mixture_reduced_square: spin scales must be 1 (numeric temperatures)");
  const bool species_i = static_cast<int>(slot) % 2 == 0;
  const Rational& width = is_spin_slot(slot) ? (species_i ? parameters.spin_width_i : parameters.spin_width_j)
                                             : (species_i ? parameters.velocity_width_i : parameters.velocity_width_j);
  return scaled(rough_dot_form(slot, slot), width);
}

template RoughCollisionMoments<Rational> rough_mixture_collision_moments<Rational>(
    const RoughMixtureParameters<Rational>&, const std::vector<RoughForm>&, const std::vector<int>&,
    std::function<bool(const RoughExponents&)>);
template RoughCollisionMoments<RationalPolynomial> rough_mixture_collision_moments<RationalPolynomial>(
    const RoughMixtureParameters<RationalPolynomial>&, const std::vector<RoughForm>&, const std::vector<int>&,
    std::function<bool(const RoughExponents&)>);

}  // namespace gkt
