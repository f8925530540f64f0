#include "gkt/transport/mixture/mixture_transport_table.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "gkt/transport/common/pair_correlation.hpp"
#include "gkt/transport/common/reference_gas.hpp"
#include "gkt/transport/mixture/mixture_navier_stokes.hpp"
#include "transport/mixture/table_messages.hpp"

namespace gkt {

using detail::refuse_state;
using detail::short_number;

namespace {

/// Throws "fraction_1: must be a number in [low, high] (the table's range), got x".
[[noreturn, gnu::cold, gnu::noinline]] void refuse_fraction(double x, double low, double high) {
  throw std::invalid_argument("fraction_1: must be a number in [" + short_number(low, 6) + ", " +
                              short_number(high, 6) + "] (the table's fraction_range), got " + short_number(x));
}

}  // namespace

BinaryTransportTable::Reduced BinaryTransportTable::solve(const Mixture& mixture, int order,
                                                          const MixtureReference& reference) {
  const MixtureNavierStokes ns(mixture, order, reference);
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

namespace {

/// A piece of x_1 waiting to be solved and checked: its interval, node counts, and how its error
/// went under bisection (the parent's error; successive bisections that did not halve it).
struct Pending {
  double low, high;
  int nodes, packing_nodes;
  bool split;
  double parent_error;
  int stalls;
};

/// Where and how large the worst error of a piece was.
struct Worst {
  double error = 0, fraction = 0, packing = 0;
};

constexpr int kMaxStalls = 6;             // bisections in a row that did not halve the error
constexpr double kMinWidth = 1.0 / 4096;  // the narrowest piece the build splits to

}  // namespace

BinaryTransportTable::BinaryTransportTable(const Mixture& mixture, int order, int nodes, double max_packing_fraction,
                                           int packing_nodes, double tolerance, std::array<double, 2> fraction_range,
                                           MixtureReference reference)
    : dimension_(mixture.dimension),
      max_packing_(max_packing_fraction),
      fraction_range_(fraction_range),
      reference_(std::move(reference)) {
  const auto started = std::chrono::steady_clock::now();
  if (mixture.size() != 2) throw std::invalid_argument("species: the transport table is for binaries (2 species)");
  if (nodes < 3 || nodes > kMaxNodes)
    throw std::invalid_argument("nodes: must be an integer in [3, 64], got " + std::to_string(nodes));
  if (packing_nodes < 3 || packing_nodes > kMaxNodes)
    throw std::invalid_argument("packing_nodes: must be an integer in [3, 64], got " + std::to_string(packing_nodes));
  if (order < 1 || order > 12) throw std::invalid_argument("order: must be an integer in [1, 12]");
  if (reference_.scheme != MixtureHcsScheme::maxwellian && (reference_.hcs_order < 2 || reference_.hcs_order > 6))
    throw std::invalid_argument("hcs_order: must be an integer in [2, 6] for a table about the cumulant HCS, got " +
                                std::to_string(reference_.hcs_order));
  const Rational limit = gkt::max_packing_fraction(mixture.dimension);
  if (!(max_packing_fraction >= 0 && max_packing_fraction < limit.to_double()))
    throw std::invalid_argument("max_packing_fraction: must be a number in [0, " + limit.to_decimal_string() +
                                ") for dimension = " + std::to_string(mixture.dimension));
  if (!(tolerance > 0 && tolerance <= 1))
    throw std::invalid_argument("tolerance: must be a number in (0, 1], got " + short_number(tolerance));
  if (!(fraction_range[0] >= 0 && fraction_range[0] < fraction_range[1] && fraction_range[1] <= 1))
    throw std::invalid_argument("fraction_range: must be [x_low, x_high] with 0 <= x_low < x_high <= 1, got [" +
                                short_number(fraction_range[0], 6) + ", " + short_number(fraction_range[1], 6) + "]");
  Mixture species = mixture;  // what the table keeps: dimension, masses, diameters, α
  species.species[0].fraction = species.species[1].fraction = 0.5;
  species.packing_fraction = 0;
  species.validate();
  for (std::size_t i = 0; i < 2; ++i) {
    mass_[i] = mixture.species[i].mass.value();
    diameter_[i] = mixture.species[i].diameter;
    species_volume_[i] = unit_sphere_volume(dimension_) * std::pow(diameter_[i], dimension_);
  }
  // Solves by (x_1, φ): refining K → 2K − 1 Chebyshev–Lobatto nodes keeps the old nodes and turns
  // the angular midpoints into the new ones, bit for bit (the angles πk/(K − 1) and π(k + ½)/(K − 1)
  // become π(2k)/(2K − 2) and π(2k + 1)/(2K − 2): doubling is exact), so no state is solved twice;
  // the halves of a bisected piece share its ends and midpoint.
  std::map<std::pair<double, double>, Reduced> solved;
  auto at = [&](double x1, double phi) -> const Reduced& {
    const auto key = std::make_pair(x1, phi);
    if (const auto it = solved.find(key); it != solved.end()) return it->second;
    Mixture m = species;
    m.species[0].fraction = x1;
    m.species[1].fraction = 1 - x1;
    m.packing_fraction = phi;
    return solved.emplace(key, solve(m, order, reference_)).first->second;
  };
  // The largest error of a piece's interpolant against direct solves at the grid of angular
  // positions offset + k·step in x_1 and φ (offset ½, step 1: the midpoints; offset ⅓, step 2: the
  // validation points, never nodes nor midpoints of any refinement of the piece).
  auto measure = [&](const Piece& piece, double offset, int step) {
    Worst worst;
    const int nx = static_cast<int>(piece.fraction_axis.nodes.size()),
              np = static_cast<int>(piece.packing_axis.nodes.size());
    for (int a = 0; a<std::max(1, np - 1); a += np> 1 ? step : 1)
      for (int b = 0; b + 1 < nx; b += step) {
        const double x1 = piece.fraction_axis.at_angle(b + offset),
                     phi = np > 1 ? piece.packing_axis.at_angle(a + offset) : piece.packing_axis.nodes[0];
        const Reduced& exact = at(x1, phi);
        const Reduced interpolated = piece.reduced_at(x1, phi);
        for (int c = 0; c < kReduced; ++c) {
          double e = std::abs(interpolated[c] - exact[c]) / std::max(1.0, std::abs(exact[c]));
          if (!std::isfinite(e)) e = INFINITY;
          if (e > worst.error) worst = {e, x1, phi};
        }
      }
    return worst;
  };
  std::vector<Pending> pending{
      {fraction_range[0], fraction_range[1], nodes, max_packing_ > 0 ? packing_nodes : 1, false, INFINITY, 0}};
  while (!pending.empty()) {
    const Pending p = pending.back();
    pending.pop_back();
    Piece piece{Axis(p.nodes, p.low, p.high), Axis(p.packing_nodes, 0, max_packing_), {}};
    for (double phi : piece.packing_axis.nodes)
      for (double x1 : piece.fraction_axis.nodes) piece.values.push_back(at(x1, phi));
    Worst worst = measure(piece, 0.5, 1);
    if (worst.error <= tolerance) {
      const Worst check = measure(piece, 1.0 / 3, 2);
      if (check.error <= tolerance) {
        interpolation_error_ = std::max({interpolation_error_, worst.error, check.error});
        validation_error_ = std::max(validation_error_, check.error);
        pieces_.push_back(std::move(piece));
        continue;
      }
      worst = check;
    }
    // Refine: both axes K → 2K − 1 until 64 nodes (before any bisection), then bisect x_1.
    const int refined = 2 * p.nodes - 1, refined_packing = max_packing_ > 0 ? 2 * p.packing_nodes - 1 : 1;
    if (!p.split && refined <= kMaxNodes && refined_packing <= kMaxNodes) {
      pending.push_back({p.low, p.high, refined, refined_packing, false, worst.error, 0});
      continue;
    }
    const int stalls = worst.error > 0.5 * p.parent_error ? p.stalls + 1 : 0;
    const double middle = 0.5 * (p.low + p.high);
    if (p.high - p.low > kMinWidth && stalls < kMaxStalls) {
      pending.push_back({middle, p.high, nodes, p.packing_nodes, true, worst.error, stalls});
      pending.push_back({p.low, middle, nodes, p.packing_nodes, true, worst.error, stalls});
      continue;
    }
    std::string grid = std::to_string(p.nodes) + " nodes in x_1";
    std::string where = "x_1 = " + short_number(worst.fraction);
    if (max_packing_ > 0) {
      grid += " x " + std::to_string(p.packing_nodes) + " in phi";
      where += ", phi = " + short_number(worst.packing);
    }
    throw std::invalid_argument(
        "tolerance: the interpolation error " + short_number(worst.error) + " at " + where + " exceeds the tolerance " +
        short_number(tolerance) + " on x_1 in [" + short_number(p.low, 6) + ", " + short_number(p.high, 6) + "] with " +
        grid + ", and bisecting no longer helps (the order-" + std::to_string(order) +
        " coefficients vary too fast there, e.g. a pole of the truncated solution; a fraction_range that "
        "leaves it out may build)");
  }
  std::sort(pieces_.begin(), pieces_.end(), [](const Piece& l, const Piece& r) {
    return l.fraction_axis.nodes.front() < r.fraction_axis.nodes.front();
  });
  for (std::size_t k = 0; k + 1 < pieces_.size(); ++k) breaks_.push_back(pieces_[k].fraction_axis.nodes.back());
  // Interpolated values stay within the Lebesgue constant (< 3.7 per axis for ≤ 64
  // Chebyshev–Lobatto nodes, [berrut2004]) times the largest node value: 16× bounds both axes.
  for (const Piece& piece : pieces_)
    for (const Reduced& v : piece.values)
      for (double c : v) reduced_bound_ = std::max(reduced_bound_, 16 * std::abs(c));
  build_solves_ = static_cast<int>(solved.size());
  build_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

int BinaryTransportTable::fraction_nodes() const {
  int count = 1;  // x_1 = 0, then each piece's nodes above its lower end
  for (const Piece& piece : pieces_) count += static_cast<int>(piece.fraction_axis.nodes.size()) - 1;
  return count;
}

int BinaryTransportTable::packing_nodes() const {
  int count = 1;
  for (const Piece& piece : pieces_) count = std::max(count, static_cast<int>(piece.packing_axis.nodes.size()));
  return count;
}

BinaryTransportTable::Reduced BinaryTransportTable::Piece::reduced_at(double x, double phi) const {
  std::array<double, kMaxNodes> wx{}, wp{};
  fraction_axis.factors(x, wx);
  packing_axis.factors(phi, wp);
  const std::size_t nx = fraction_axis.nodes.size(), np = packing_axis.nodes.size();
  Reduced out{};
  for (std::size_t a = 0; a < np; ++a) {
    if (wp[a] == 0) continue;
    Reduced row{};
    for (std::size_t b = 0; b < nx; ++b) {
      const Reduced& v = values[a * nx + b];
      for (int c = 0; c < kReduced; ++c) row[c] += wx[b] * v[c];
    }
    for (int c = 0; c < kReduced; ++c) out[c] += wp[a] * row[c];
  }
  return out;
}

BinaryTransport BinaryTransportTable::evaluate(double x1, double n, double temperature) const {
  if (!(x1 >= fraction_range_[0] && x1 <= fraction_range_[1])) {
    if (fraction_range_[0] == 0 && fraction_range_[1] == 1)
      refuse_state("fraction_1", "a number in [0, 1]", x1, temperature);
    refuse_fraction(x1, fraction_range_[0], fraction_range_[1]);
  }
  if (!(n > 0 && n < INFINITY)) refuse_state("number_density", "a finite number > 0", n, temperature);
  if (!(temperature > 0 && temperature < INFINITY))
    refuse_state("temperature", "a finite number > 0", temperature, temperature);
  const int d = dimension_;
  const double x[2] = {x1, 1 - x1};
  // φ = n v_d Σ x_i σ_i^d (v_d σ_i^d kept from the build).
  const double phi = max_packing_ > 0 ? n * (x[0] * species_volume_[0] + x[1] * species_volume_[1]) : 0.0;
  BinaryTransport out;
  if (phi > max_packing_) {
    const double nan = std::nan("");
    out = {nan, {nan, nan}, nan, nan, {nan, nan, nan, nan}, {nan, nan}, {nan, nan}, {nan, nan}, nan, nan, nan};
    return out;
  }
  // The piece holding x_1 (the lower one at a shared end: both interpolate the same node value).
  const auto piece = static_cast<std::size_t>(std::lower_bound(breaks_.begin(), breaks_.end(), x1) - breaks_.begin());
  const Reduced r = pieces_[piece].reduced_at(x[0], phi);
  const double mbar = x[0] * mass_[0] + x[1] * mass_[1], sbar = x[0] * diameter_[0] + x[1] * diameter_[1];
  // Reference gas (m̄, σ̄) at n, T (docs/conventions.md).
  const ReferenceGas ref = reference_gas(d, mbar, sbar, n, temperature);
  const double eta0 = ref.viscosity, kappa0 = ref.conductivity, d0 = ref.self_diffusion;
  const double scales[] = {ref.collision_frequency, eta0, kappa0, n * d0, d0, kappa0 / temperature, n * temperature};
  out.cooling_rate = r[0] * scales[0];
  out.temperature_ratio = {r[1], r[2]};
  out.shear_viscosity = r[3] * eta0;
  out.thermal_conductivity = r[4] * kappa0;
  for (std::size_t k = 0; k < 4; ++k) out.mutual_diffusion[k] = r[5 + k] * scales[3];
  for (std::size_t i = 0; i < 2; ++i) {
    out.thermal_diffusion[i] = r[9 + i] * d0;
    out.pressure_diffusion[i] = r[11 + i] * d0;
    out.dufour[i] = r[13 + i] * scales[5];
  }
  out.pressure = r[15] * scales[6];
  out.bulk_viscosity = r[16] * eta0;
  out.cooling_rate_first_order = r[17];
  // The scales must be normal doubles (an extreme n or T would otherwise make a coefficient 0 by
  // underflow without a word), small enough that no |reduced value| ≤ reduced_bound_ overflows.
  const double smallest = std::min({scales[0], scales[1], scales[2], scales[3], scales[4], scales[5], scales[6]});
  const double largest = std::max({scales[0], scales[1], scales[2], scales[3], scales[4], scales[5], scales[6]});
  if (!(smallest >= std::numeric_limits<double>::min() && largest * reduced_bound_ < INFINITY))
    refuse_state("number_density, temperature", "", n, temperature);
  return out;
}

}  // namespace gkt
