#include "gkt/collision/rough_mixture_collision_rule.hpp"

#include <stdexcept>
#include <string>

#include "collision/ring.hpp"
#include "collision/rough_pair_map.hpp"

namespace gkt {

namespace {

void check_positive(const Rational& x, const std::string& field) {
  if (x.sign() <= 0) throw std::invalid_argument(field + ": must be > 0, got " + x.to_decimal_string());
}

void check_parameters(int dimension, const Rational& alpha, const Rational& beta, const RoughSpecies& i,
                      const RoughSpecies& j) {
  detail::check_rough_restitution(dimension, alpha, beta);
  for (const auto& [s, name] : {std::pair<const RoughSpecies&, const char*>{i, "species_i"}, {j, "species_j"}}) {
    const std::string prefix(name);
    check_positive(s.mass, prefix + ".mass");
    if (s.kappa.sign() <= 0 || s.kappa > Rational(1))
      throw std::invalid_argument(prefix + ".moment_of_inertia: must be a number in (0, 1], got " +
                                  s.kappa.to_decimal_string());
    check_positive(s.translational_temperature, prefix + ".translational_temperature");
    check_positive(s.rotational_temperature, prefix + ".rotational_temperature");
  }
}

template <class Ring>
RoughMixtureParameters<Ring> widths(int dimension, const Ring& alpha, const Ring& beta, const RoughSpecies& i,
                                    const RoughSpecies& j, const Ring& spin_scale) {
  RoughMixtureParameters<Ring> p;
  p.dimension = dimension;
  p.alpha = alpha;
  p.beta = beta;
  p.mass_i = i.mass;
  p.mass_j = j.mass;
  p.kappa_i = i.kappa;
  p.kappa_j = j.kappa;
  p.velocity_width_i = i.mass / (Rational(2) * i.translational_temperature);
  p.velocity_width_j = j.mass / (Rational(2) * j.translational_temperature);
  p.spin_scale_i = spin_scale;
  p.spin_scale_j = spin_scale;
  p.spin_width_i = i.kappa * i.mass / (Rational(2) * i.rotational_temperature);
  p.spin_width_j = j.kappa * j.mass / (Rational(2) * j.rotational_temperature);
  return p;
}

}  // namespace

template <class Ring>
Rational RoughMixtureParameters<Ring>::tangential_mass() const {
  const Rational one(1);
  return one / ((one + kappa_i) / (kappa_i * mass_i) + (one + kappa_j) / (kappa_j * mass_j));
}

template <class Ring>
RoughCollisionMap<Ring> RoughMixtureParameters<Ring>::collision_map() const {
  const Ring one(1L);
  const Rational total = mass_i + mass_j, m_t = tangential_mass();
  // Normal impulse J_n/m_i = −(1+α)(m_j/(m_i+m_j)) u σ̂, J_n/m_j = −(1+α)(m_i/(m_i+m_j)) u σ̂.
  Ring n_i = alpha + one, n_j = alpha + one;
  detail::scale(n_i, mass_j / total);
  detail::scale(n_j, mass_i / total);
  // Tangential: J_t = −(1+β) M g_c,t; Δv1t = J_t/m_i, Δv2t = −J_t/m_j, Δs_k = J_t/(κ_k m_k) (s = w × σ̂).
  Ring t_i = beta + one, t_j = beta + one;
  detail::scale(t_i, m_t / mass_i);
  detail::scale(t_j, m_t / mass_j);
  Ring r_i = t_i, r_j = t_j;
  detail::divide(r_i, kappa_i);
  detail::divide(r_j, kappa_j);
  return detail::assemble_rough_pair_map<Ring>(
      dimension, {.width = {velocity_width_i, velocity_width_j, spin_width_i, spin_width_j},
                  .spin_scale_i = spin_scale_i,
                  .spin_scale_j = spin_scale_j,
                  .normal_i = n_i,
                  .normal_j = n_j,
                  .tangential_i = t_i,
                  .tangential_j = t_j,
                  .spin_i = r_i,
                  .spin_j = r_j});
}

RoughMixtureParameters<Rational> rough_mixture_parameters(int dimension, const Rational& alpha, const Rational& beta,
                                                          const RoughSpecies& species_i,
                                                          const RoughSpecies& species_j) {
  check_parameters(dimension, alpha, beta, species_i, species_j);
  return widths<Rational>(dimension, alpha, beta, species_i, species_j, Rational(1));
}

RoughMixtureParameters<RationalPolynomial> rough_mixture_parameters_symbolic_spin(int dimension, const Rational& alpha,
                                                                                  const Rational& beta,
                                                                                  const RoughSpecies& species_i,
                                                                                  const RoughSpecies& species_j) {
  check_parameters(dimension, alpha, beta, species_i, species_j);
  return widths<RationalPolynomial>(dimension, RationalPolynomial(alpha), RationalPolynomial(beta), species_i,
                                    species_j, RationalPolynomial::variable());
}

template struct RoughMixtureParameters<Rational>;
template struct RoughMixtureParameters<RationalPolynomial>;

}  // namespace gkt
