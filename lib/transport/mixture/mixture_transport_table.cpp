#include "gkt/transport/mixture/mixture_transport_table.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "gkt/transport/common/pair_correlation.hpp"
#include "gkt/transport/common/reference_gas.hpp"
#include "gkt/transport/mixture/mixture_navier_stokes.hpp"

namespace gkt {

BinaryTransportTable::Reduced BinaryTransportTable::solve(const Mixture& mixture, int order) {
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
          v.dufour[1],
          v.pressure,
          v.bulk_viscosity,
          v.cooling_rate_first_order};
}

BinaryTransportTable::Axis::Axis(int count, double top) {
  // Chebyshev–Lobatto points of [0, top] and their barycentric weights (−1)^k, halved at the ends
  // ([berrut2004] eq. 5.2); a single node when the axis is degenerate (top = 0).
  const int last = top > 0 ? count - 1 : 0;
  for (int k = 0; k <= last; ++k) {
    nodes.push_back(last == 0 ? 0.0 : 0.5 * top * (1 - std::cos(std::numbers::pi * k / last)));
    weights.push_back((k % 2 == 0 ? 1.0 : -1.0) * (k == 0 || k == last ? 0.5 : 1.0));
  }
}

void BinaryTransportTable::Axis::factors(double t, std::array<double, kMaxNodes>& w) const {
  const std::size_t n = nodes.size();
  double sum = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double difference = t - nodes[k];
    if (difference == 0) {
      std::fill_n(w.begin(), n, 0.0);
      w[k] = 1;
      return;
    }
    w[k] = weights[k] / difference;
    sum += w[k];
  }
  for (std::size_t k = 0; k < n; ++k) w[k] /= sum;
}

BinaryTransportTable::BinaryTransportTable(const Mixture& mixture, int order, int nodes, double max_packing_fraction,
                                           int packing_nodes)
    : dimension_(mixture.dimension),
      max_packing_(max_packing_fraction),
      fraction_axis_(std::clamp(nodes, 3, kMaxNodes), 1.0),
      packing_axis_(std::clamp(packing_nodes, 3, kMaxNodes), max_packing_fraction) {
  if (mixture.size() != 2) throw std::invalid_argument("species: the transport table is for binaries (2 species)");
  if (nodes < 3 || nodes > kMaxNodes)
    throw std::invalid_argument("nodes: must be an integer in [3, 64], got " + std::to_string(nodes));
  if (packing_nodes < 3 || packing_nodes > kMaxNodes)
    throw std::invalid_argument("packing_nodes: must be an integer in [3, 64], got " + std::to_string(packing_nodes));
  if (order < 1 || order > 12) throw std::invalid_argument("order: must be an integer in [1, 12]");
  const Rational limit = gkt::max_packing_fraction(mixture.dimension);
  if (!(max_packing_fraction >= 0 && max_packing_fraction < limit.to_double()))
    throw std::invalid_argument("max_packing_fraction: must be a number in [0, " + limit.to_decimal_string() +
                                ") for dimension = " + std::to_string(mixture.dimension));
  for (std::size_t i = 0; i < 2; ++i) {
    mass_[i] = mixture.species[i].mass;
    diameter_[i] = mixture.species[i].diameter;
    species_volume_[i] = unit_sphere_volume(dimension_) * std::pow(diameter_[i], dimension_);
  }
  auto at = [&](double x1, double phi) {
    Mixture m = mixture;
    m.species[0].fraction = x1;
    m.species[1].fraction = 1 - x1;
    m.packing_fraction = phi;
    return solve(m, order);
  };
  for (double phi : packing_axis_.nodes)
    for (double x1 : fraction_axis_.nodes) values_.push_back(at(x1, phi));
  // Midpoints in the angle (where the interpolant is least pinned): in x_1 at every φ midpoint (or
  // at φ = 0 for a dilute table).
  auto midpoints = [](const Axis& axis) {
    std::vector<double> out;
    const auto last = static_cast<double>(axis.nodes.size() - 1);
    const double top = axis.nodes.back();
    for (std::size_t k = 0; k + 1 < axis.nodes.size(); ++k)
      out.push_back(0.5 * top * (1 - std::cos(std::numbers::pi * (static_cast<double>(k) + 0.5) / last)));
    if (out.empty()) out.push_back(0.0);
    return out;
  };
  for (double phi : midpoints(packing_axis_))
    for (double x1 : midpoints(fraction_axis_)) {
      const Reduced solved = at(x1, phi), interpolated = reduced_at(x1, phi);
      for (int c = 0; c < kReduced; ++c)
        interpolation_error_ =
            std::max(interpolation_error_, std::abs(interpolated[c] - solved[c]) / std::max(1.0, std::abs(solved[c])));
    }
}

BinaryTransportTable::Reduced BinaryTransportTable::reduced_at(double x, double phi) const {
  std::array<double, kMaxNodes> wx{}, wp{};
  fraction_axis_.factors(x, wx);
  packing_axis_.factors(phi, wp);
  const std::size_t nx = fraction_axis_.nodes.size(), np = packing_axis_.nodes.size();
  Reduced out{};
  for (std::size_t a = 0; a < np; ++a) {
    if (wp[a] == 0) continue;
    Reduced row{};
    for (std::size_t b = 0; b < nx; ++b) {
      const Reduced& v = values_[a * nx + b];
      for (int c = 0; c < kReduced; ++c) row[c] += wx[b] * v[c];
    }
    for (int c = 0; c < kReduced; ++c) out[c] += wp[a] * row[c];
  }
  return out;
}

BinaryTransport BinaryTransportTable::evaluate(double x1, double n, double temperature) const {
  const int d = dimension_;
  const double x[2] = {std::clamp(x1, 0.0, 1.0), 1 - std::clamp(x1, 0.0, 1.0)};
  // φ = n v_d Σ x_i σ_i^d (v_d σ_i^d kept from the build).
  const double phi = max_packing_ > 0 ? n * (x[0] * species_volume_[0] + x[1] * species_volume_[1]) : 0.0;
  BinaryTransport out;
  if (phi > max_packing_) {
    const double nan = std::nan("");
    out = {nan, {nan, nan}, nan, nan, {nan, nan, nan, nan}, {nan, nan}, {nan, nan}, {nan, nan}, nan, nan, nan};
    return out;
  }
  const Reduced r = reduced_at(x[0], phi);
  const double mbar = x[0] * mass_[0] + x[1] * mass_[1], sbar = x[0] * diameter_[0] + x[1] * diameter_[1];
  // Reference gas (m̄, σ̄) at n, T (docs/conventions.md).
  const ReferenceGas ref = reference_gas(d, mbar, sbar, n, temperature);
  const double eta0 = ref.viscosity, kappa0 = ref.conductivity, d0 = ref.self_diffusion;
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
  out.pressure = r[15] * n * temperature;
  out.bulk_viscosity = r[16] * eta0;
  out.cooling_rate_first_order = r[17];
  return out;
}

}  // namespace gkt
