#include "gkt/transport/aggregation/aggregation_kernel.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace gkt {

void validate(const AggregationGas& gas) {
  if (gas.dimension != 2 && gas.dimension != 3) throw std::invalid_argument("dimension: must be 2 or 3");
  if (!(gas.alpha > 0 && gas.alpha <= 1)) throw std::invalid_argument("alpha: must be in (0, 1]");
  if (!(gas.critical_energy >= 0) || !std::isfinite(gas.critical_energy))
    throw std::invalid_argument("critical_energy: must be a finite number >= 0");
  if (!(gas.pair_correlation >= 1) || !std::isfinite(gas.pair_correlation))
    throw std::invalid_argument("pair_correlation: must be a finite number >= 1");
  if (!(gas.kernel_constant > 0) || !std::isfinite(gas.kernel_constant))
    throw std::invalid_argument("kernel_constant: must be a finite number > 0");
}

double collision_rate_coefficient(int dimension, double i, double j, double theta, double pair_correlation) {
  const double reduced_mass = i * j / (i + j);
  // ∫dσ̂ Θ(ĝ·σ̂)(ĝ·σ̂) = π^{(d−1)/2}/Γ((d+1)/2) times the mean speed √(2θ/μ) Γ((d+1)/2)/Γ(d/2):
  // σ² 2√π √(2θ/μ) (3D, contact distance σ = (i^{1/3} + j^{1/3})/2), σ √π √(2θ/μ) (2D).
  const double speed = std::sqrt(2 * theta / reduced_mass);
  const double root_pi = std::sqrt(std::numbers::pi);
  if (dimension == 3) {
    const double sigma = 0.5 * (std::cbrt(i) + std::cbrt(j));
    return pair_correlation * sigma * sigma * 2 * root_pi * speed;
  }
  const double sigma = 0.5 * (std::sqrt(i) + std::sqrt(j));
  return pair_correlation * sigma * root_pi * speed;
}

double critical_pair_energy(const AggregationGas& gas, double i, double j) {
  const double reduced_mass = i * j / (i + j);
  return gas.critical_energy * reduced_mass / 0.5;
}

PairRates pair_rates(const AggregationGas& gas, double i, double j, double theta, bool may_stick) {
  PairRates r;
  r.collisions = collision_rate_coefficient(gas.dimension, i, j, theta, gas.pair_correlation);
  const double inelastic = 1 - gas.alpha * gas.alpha;
  if (!may_stick) {  // every collision rebounds: ⟨μ g_n²/2⟩ = θ per collision
    r.energy_loss = r.collisions * theta * inelastic;
    return r;
  }
  if (gas.kernel == AggregationKernel::kinetic) {
    const double x = gas.criterion == StickingCriterion::always ? 0.0 : critical_pair_energy(gas, i, j) / theta;
    const PairCollisionAverages avg = pair_collision_averages(gas.dimension, gas.criterion, x);
    r.aggregation = r.collisions * avg.success_factor;
    r.energy_loss = r.collisions * theta * (avg.sticking_energy + inelastic * avg.normal_energy);
    return r;
  }
  // Velocity-blind kernels: a sticking pair carries the mean relative energy (d/2)θ; the kinetic
  // collisions rebound inelastically (theory.md (20.11)).
  r.aggregation = gas.kernel == AggregationKernel::constant ? gas.kernel_constant : gas.kernel_constant * (i + j);
  r.energy_loss = r.aggregation * 0.5 * gas.dimension * theta + r.collisions * theta * inelastic;
  return r;
}

}  // namespace gkt
