#include "gkt/transport/mixture/mixture_tail_exponents.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "gkt/transport/common/reference_gas.hpp"

namespace gkt {

std::vector<double> mixture_tail_exponents(const Mixture& mixture, const MixtureCoolingState& state) {
  mixture.validate();
  const std::size_t s = mixture.size();
  if (state.temperature_ratio.size() != s)
    throw std::invalid_argument("state: temperature_ratio needs one value per species");
  const int d = mixture.dimension;
  // β = π^{(d−1)/2}/Γ((d+1)/2): the loss rate of a fast particle per n σ^{d−1} V (π in 3D, 2 in 2D).
  const double beta = std::pow(std::numbers::pi, (d - 1) / 2.0) / std::tgamma((d + 1) / 2.0);
  const double zeta = state.cooling_rate * unit_reference_gas(d).collision_frequency;  // ζ = ζ* ν0
  const double sigma_bar = mixture.mean_diameter(), mass_bar = mixture.mean_mass();
  std::vector<double> out;
  for (std::size_t i = 0; i < s; ++i) {
    double loss = 0;  // Σ_j x_j (σ_ij/σ̄)^{d−1}
    for (std::size_t j = 0; j < s; ++j)
      loss += mixture.species[j].fraction *
              std::pow(0.5 * (mixture.species[i].diameter + mixture.species[j].diameter) / sigma_bar, d - 1);
    const double theta = mixture.species[i].mass.value() / mass_bar / state.temperature_ratio[i];
    // theory.md (17.28): φ_i ~ exp(−A_i c_i), A_i = 2β Σ_j x_j σ_ij^{d−1}/(ζ √θ_i).
    out.push_back(zeta > 0 ? 2 * beta * loss / (zeta * std::sqrt(theta)) : std::numeric_limits<double>::infinity());
  }
  return out;
}

}  // namespace gkt
