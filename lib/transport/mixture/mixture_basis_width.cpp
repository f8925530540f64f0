#include "gkt/transport/mixture/mixture_basis_width.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "gkt/transport/mixture/mixture_tail_exponents.hpp"

namespace gkt {

std::vector<double> mixture_basis_width(const Mixture& mixture, const MixtureCoolingState& state, int target_order) {
  if (target_order < 1 || target_order > 100)
    throw std::invalid_argument("target_order: must be an integer in [1, 100], got " + std::to_string(target_order));
  const std::vector<double> tail = mixture_tail_exponents(mixture, state);  // A_i, theory.md (17.28); validates
  const std::size_t s = mixture.size();
  const int d = mixture.dimension;
  double smallest = std::numeric_limits<double>::infinity();  // A* of (17.30)
  for (std::size_t i = 0; i < s; ++i) {
    const double m_i = mixture.species[i].mass.value();
    const double speed_i = state.temperature_ratio[i] / m_i;  // its thermal speed², 2T_i/m_i in units of 2T
    double removing = 0, all = 0;  // Σ_j x_j σ_ij^{d−1} min(1, 2μ_ji) and Σ_j x_j σ_ij^{d−1}
    double drag = 0, bath = 0;     // the dragging (lighter) partners' weight and their weighted thermal speed²
    for (std::size_t j = 0; j < s; ++j) {
      const double sigma_ij = 0.5 * (mixture.species[i].diameter + mixture.species[j].diameter);
      const double rate = mixture.species[j].fraction * std::pow(sigma_ij, d - 1);
      const double m_j = mixture.species[j].mass.value(), mu_ji = m_j / (m_i + m_j);
      removing += rate * std::min(1.0, 2 * mu_ji);
      all += rate;
      drag += rate * (1 - std::min(1.0, 2 * mu_ji));
      bath += rate * (1 - std::min(1.0, 2 * mu_ji)) * state.temperature_ratio[j] / m_j;
    }
    const double share = removing / all;  // s_i of (17.30)
    // A species mostly dragged by lighter partners that are faster than it (the Fokker–Planck regime,
    // its thermal speed² below half theirs) keeps a Gaussian tail and does not count; dragged by partners
    // as fast as itself, the drag grows with its speed and its tail is exponential, exponent s_i A_i.
    const bool gaussian = share < 0.5 && speed_i < 0.5 * bath / drag;
    if (!gaussian) smallest = std::min(smallest, share * tail[i]);
  }
  // (17.30): the tail of species i turns the series near order s_i² A_i² w/4 (theory.md §10.6 in the
  // variable c' = c_i/√w); the Maxwellian core's coefficients in the basis of width w fall as (1 − 1/w)^q,
  // 2^−q at the cap w = 2.
  const double w = std::isfinite(smallest) ? std::clamp(4.0 * target_order / (smallest * smallest), 1.0, 2.0) : 1.0;
  return std::vector<double>(s, w);
}

}  // namespace gkt
