#include "gkt/mixture_transport_table.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "gkt/mixture_navier_stokes.hpp"
#include "transport/reference_gas.hpp"

namespace gkt {

using detail::reference_gas;
using detail::ReferenceGas;

std::array<double, BinaryTransportTable::kReduced> BinaryTransportTable::solve(const Mixture& mixture, int order) {
  const MixtureNavierStokes ns(mixture, order);
  const MixtureTransportValues v = ns.coefficients(order);
  const MixtureCoolingState& hcs = ns.cooling_state();
  return {hcs.cooling_rate,
          hcs.temperature_ratio[0],
          hcs.temperature_ratio[1],
          v.shear_viscosity,
          v.thermal_conductivity,
          v.mutual_diffusion[0],
          v.mutual_diffusion[1],
          v.mutual_diffusion[2],
          v.mutual_diffusion[3],
          v.thermal_diffusion[0],
          v.thermal_diffusion[1],
          v.pressure_diffusion[0],
          v.pressure_diffusion[1],
          v.dufour[0],
          v.dufour[1]};
}

BinaryTransportTable::BinaryTransportTable(const Mixture& mixture, int order, int nodes)
    : dimension_(mixture.dimension) {
  if (mixture.size() != 2) throw std::invalid_argument("species: the transport table is for binaries (2 species)");
  if (nodes < 3) throw std::invalid_argument("nodes: must be an integer >= 3, got " + std::to_string(nodes));
  if (order < 1 || order > 12) throw std::invalid_argument("order: must be an integer in [1, 12]");
  // The reduced dilute set depends on x_1 alone; a dense one would also depend on φ, which n changes.
  if (mixture.packing_fraction != 0)
    throw std::invalid_argument("packing_fraction: the transport table is for the dilute binary (0)");
  for (std::size_t i = 0; i < 2; ++i) {
    mass_[i] = mixture.species[i].mass;
    diameter_[i] = mixture.species[i].diameter;
  }
  auto at = [&](double x1) {
    Mixture m = mixture;
    m.species[0].fraction = x1;
    m.species[1].fraction = 1 - x1;
    return solve(m, order);
  };
  // Chebyshev–Lobatto points of [0, 1] and their barycentric weights (−1)^k, halved at the ends
  // ([berrut2004] eq. 5.2).
  const int last = nodes - 1;
  for (int k = 0; k <= last; ++k) {
    nodes_.push_back(0.5 * (1 - std::cos(std::numbers::pi * k / last)));
    weights_.push_back((k % 2 == 0 ? 1.0 : -1.0) * (k == 0 || k == last ? 0.5 : 1.0));
    values_.push_back(at(nodes_.back()));
  }
  for (int k = 0; k < last; ++k) {  // midpoints in the angle: where the interpolant is least pinned
    const double x = 0.5 * (1 - std::cos(std::numbers::pi * (k + 0.5) / last));
    const auto solved = at(x), interpolated = reduced_at(x);
    for (int c = 0; c < kReduced; ++c)
      interpolation_error_ =
          std::max(interpolation_error_, std::abs(interpolated[c] - solved[c]) / std::max(1.0, std::abs(solved[c])));
  }
}

std::array<double, BinaryTransportTable::kReduced> BinaryTransportTable::reduced_at(double x) const {
  std::array<double, kReduced> out{};
  double denominator = 0;
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    const double difference = x - nodes_[k];
    if (difference == 0) return values_[k];
    const double w = weights_[k] / difference;
    denominator += w;
    for (int c = 0; c < kReduced; ++c) out[c] += w * values_[k][c];
  }
  for (double& v : out) v /= denominator;
  return out;
}

BinaryTransport BinaryTransportTable::evaluate(double x1, double n, double temperature) const {
  const std::array<double, kReduced> r = reduced_at(std::clamp(x1, 0.0, 1.0));
  const int d = dimension_;
  const double x[2] = {x1, 1 - x1};
  const double mbar = x[0] * mass_[0] + x[1] * mass_[1], sbar = x[0] * diameter_[0] + x[1] * diameter_[1];
  // Reference gas (m̄, σ̄) at n, T (docs/conventions.md).
  const ReferenceGas ref = reference_gas(d, mbar, sbar, n, temperature);
  const double eta0 = ref.viscosity, kappa0 = ref.conductivity, d0 = ref.self_diffusion;
  BinaryTransport out;
  out.cooling_rate = r[0] * ref.collision_frequency;
  out.temperature_ratio = {r[1], r[2]};
  out.shear_viscosity = r[3] * eta0;
  out.thermal_conductivity = r[4] * kappa0;
  for (std::size_t k = 0; k < 4; ++k) out.mutual_diffusion[k] = r[5 + k] * n * d0;
  for (std::size_t i = 0; i < 2; ++i) {
    out.thermal_diffusion[i] = r[9 + i] * d0;
    out.pressure_diffusion[i] = r[11 + i] * d0;
    out.dufour[i] = r[13 + i] * kappa0 / temperature;
  }
  return out;
}

}  // namespace gkt
