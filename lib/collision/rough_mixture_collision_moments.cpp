#include "gkt/collision/rough_mixture_collision_moments.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace gkt {

template <class Ring>
RoughCollisionMoments<Ring> rough_mixture_collision_moments(const RoughMixtureParameters<Ring>& parameters,
                                                            const std::vector<RoughForm>& forms,
                                                            const std::vector<int>& degrees,
                                                            std::function<bool(const RoughExponents&)> keep) {
  return RoughCollisionMoments<Ring>(parameters.collision_map(), forms, degrees, std::move(keep));
}

namespace {

/// Returns the Gaussian width of a slot's species (a_k for v, b_k for w; numeric temperatures only).
const Rational& slot_width(const RoughMixtureParameters<Rational>& parameters, RoughSlot slot) {
  if (parameters.spin_scale_i != Rational(1) || parameters.spin_scale_j != Rational(1))
    throw std::invalid_argument("spin_scale: the reduced forms need spin scales 1 (numeric temperatures)");
  const bool species_i = static_cast<int>(slot) % 2 == 0;
  return is_spin_slot(slot) ? (species_i ? parameters.spin_width_i : parameters.spin_width_j)
                            : (species_i ? parameters.velocity_width_i : parameters.velocity_width_j);
}

}  // namespace

RoughForm rough_mixture_reduced_square(const RoughMixtureParameters<Rational>& parameters, RoughSlot slot) {
  return scaled(rough_dot_form(slot, slot), slot_width(parameters, slot));
}

RoughForm rough_mixture_reduced_dot(const RoughMixtureParameters<Rational>& parameters, RoughSlot a, RoughSlot b) {
  const Rational product = slot_width(parameters, a) * slot_width(parameters, b);
  if (!product.is_square())
    throw std::invalid_argument("rough_mixture_reduced_dot: the product of the two slots' widths (" +
                                product.to_decimal_string() + ") is not the square of a rational");
  return scaled(rough_dot_form(a, b), product.exact_sqrt());
}

template RoughCollisionMoments<Rational> rough_mixture_collision_moments<Rational>(
    const RoughMixtureParameters<Rational>&, const std::vector<RoughForm>&, const std::vector<int>&,
    std::function<bool(const RoughExponents&)>);
template RoughCollisionMoments<RationalPolynomial> rough_mixture_collision_moments<RationalPolynomial>(
    const RoughMixtureParameters<RationalPolynomial>&, const std::vector<RoughForm>&, const std::vector<int>&,
    std::function<bool(const RoughExponents&)>);

}  // namespace gkt
