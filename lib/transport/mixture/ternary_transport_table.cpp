#include "gkt/transport/mixture/ternary_transport_table.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "gkt/transport/common/pair_correlation.hpp"
#include "gkt/transport/common/reference_gas.hpp"
#include "gkt/transport/mixture/mixture_navier_stokes.hpp"
#include "transport/mixture/table_messages.hpp"

namespace gkt {

using detail::refuse_state;
using detail::short_number;

namespace {

/// A rectangle of the Duffy square waiting to be solved and checked: its tree cell, extent, nodes
/// per axis, and how its error went under splitting (the parent's error; splits in a row that did
/// not halve it).
struct Pending {
  int cell;
  double u_low, u_high, v_low, v_high;
  int nodes, packing_nodes;
  bool split;
  double parent_error;
  int stalls;
};

/// Where and how large the worst error of a piece was (in the fractions x_1, x_2 and φ).
struct Worst {
  double error = 0, fraction_1 = 0, fraction_2 = 0, packing = 0;
};

constexpr int kMaxStalls = 4;            // splits in a row that did not halve the error
constexpr double kMinWidth = 1.0 / 256;  // the narrowest rectangle the build splits to

}  // namespace

TernaryTransportTable::Reduced TernaryTransportTable::solve(const Mixture& mixture, int order,
                                                            const MixtureReference& reference) {
  const MixtureNavierStokes ns(mixture, order, reference);
  const MixtureTransportValues v = ns.coefficients(order);
  const MixtureCoolingState& hcs = ns.cooling_state();
  Reduced r{};
  r[0] = hcs.cooling_rate;
  for (std::size_t i = 0; i < 3; ++i) r[1 + i] = hcs.temperature_ratio[i];
  r[4] = v.shear_viscosity;
  r[5] = v.thermal_conductivity;
  for (std::size_t k = 0; k < 9; ++k) r[6 + k] = v.mutual_diffusion[k];
  for (std::size_t i = 0; i < 3; ++i) {
    r[15 + i] = v.thermal_diffusion[i];
    r[18 + i] = v.pressure_diffusion[i];
    r[21 + i] = v.dufour[i];
  }
  r[24] = v.pressure;  // 1, 0, 0 when dilute
  r[25] = v.bulk_viscosity;
  r[26] = v.cooling_rate_first_order;
  return r;
}

TernaryTransportTable::Reduced TernaryTransportTable::Piece::reduced_at(double u, double v, double phi) const {
  std::array<double, kMaxNodes> wu{}, wv{}, wp{};
  u_axis.factors(u, wu);
  v_axis.factors(v, wv);
  packing_axis.factors(phi, wp);
  const std::size_t nu = u_axis.nodes.size(), nv = v_axis.nodes.size(), np = packing_axis.nodes.size();
  Reduced out{};
  for (std::size_t p = 0; p < np; ++p) {
    if (wp[p] == 0) continue;
    Reduced plane{};
    for (std::size_t a = 0; a < nv; ++a) {
      if (wv[a] == 0) continue;
      Reduced row{};
      for (std::size_t b = 0; b < nu; ++b) {
        if (wu[b] == 0) continue;
        const Reduced& value = values[(p * nv + a) * nu + b];
        for (int c = 0; c < kReduced; ++c) row[c] += wu[b] * value[c];
      }
      for (int c = 0; c < kReduced; ++c) plane[c] += wv[a] * row[c];
    }
    for (int c = 0; c < kReduced; ++c) out[c] += wp[p] * plane[c];
  }
  return out;
}

TernaryTransportTable::TernaryTransportTable(const Mixture& mixture, int order, int nodes, double tolerance,
                                             int max_nodes, double max_packing_fraction, int packing_nodes,
                                             MixtureReference reference)
    : dimension_(mixture.dimension), max_packing_(max_packing_fraction), reference_(std::move(reference)) {
  const auto started = std::chrono::steady_clock::now();
  if (mixture.size() != 3)
    throw std::invalid_argument("species: the ternary transport table is for 3 species, got " +
                                std::to_string(mixture.size()));
  if (nodes < 3 || nodes > kMaxNodes)
    throw std::invalid_argument("nodes: must be an integer in [3, 33], got " + std::to_string(nodes));
  if (max_nodes < nodes || max_nodes > kMaxNodes)
    throw std::invalid_argument("max_nodes: must be an integer in [nodes, 33] = [" + std::to_string(nodes) +
                                ", 33], got " + std::to_string(max_nodes));
  if (order < 1 || order > 12) throw std::invalid_argument("order: must be an integer in [1, 12]");
  if (!(tolerance > 0 && tolerance <= 1))
    throw std::invalid_argument("tolerance: must be a number in (0, 1], got " + short_number(tolerance));
  if (reference_.scheme != MixtureHcsScheme::maxwellian && (reference_.hcs_order < 2 || reference_.hcs_order > 6))
    throw std::invalid_argument("hcs_order: must be an integer in [2, 6] for a table about the cumulant HCS, got " +
                                std::to_string(reference_.hcs_order));
  if (packing_nodes < 3 || packing_nodes > kMaxNodes)
    throw std::invalid_argument("packing_nodes: must be an integer in [3, 33], got " + std::to_string(packing_nodes));
  if (mixture.dimension == 2 || mixture.dimension == 3) {
    const Rational limit = gkt::max_packing_fraction(mixture.dimension);
    if (!(max_packing_fraction >= 0 && max_packing_fraction < limit.to_double()))
      throw std::invalid_argument("max_packing_fraction: must be a number in [0, " + limit.to_decimal_string() +
                                  ") for dimension = " + std::to_string(mixture.dimension) + ", got " +
                                  short_number(max_packing_fraction));
  }
  const bool dense = max_packing_fraction > 0;
  if (!dense && mixture.packing_fraction != 0)
    throw std::invalid_argument("packing_fraction: a dilute ternary table (max_packing_fraction = 0) needs 0, got " +
                                short_number(mixture.packing_fraction));
  Mixture species = mixture;  // what the table keeps: dimension, masses, diameters, α
  for (Species& s : species.species) s.fraction = 1.0 / 3;
  species.species[2].fraction = 1 - 2.0 / 3;
  species.packing_fraction = 0;
  species.validate();
  for (std::size_t i = 0; i < 3; ++i) {
    mass_[i] = mixture.species[i].mass.value();
    diameter_[i] = mixture.species[i].diameter;
    species_volume_[i] = unit_sphere_volume(dimension_) * std::pow(diameter_[i], dimension_);
  }
  // Solves by (u, v) of the Duffy square, x_1 = u, x_2 = (1 − u) v, x_3 = (1 − u)(1 − v)
  // ([duffy1982]): refining K → 2K − 1 keeps the nodes and makes the midpoints nodes, bit for bit,
  // and the quarters of a split share its edges, so no state is solved twice (the edge u = 1, one
  // state x_1 = 1, is solved once per v node: those values are equal).
  std::map<std::tuple<double, double, double>, Reduced> solved;
  auto at = [&](double u, double v, double phi) -> const Reduced& {
    const auto key = std::make_tuple(u, v, phi);
    if (const auto it = solved.find(key); it != solved.end()) return it->second;
    Mixture m = species;
    m.species[0].fraction = u;
    m.species[1].fraction = (1 - u) * v;
    m.species[2].fraction = (1 - u) * (1 - v);
    m.packing_fraction = phi;
    return solved.emplace(key, solve(m, order, reference_)).first->second;
  };
  // The largest error of a piece's interpolant against direct solves on the grid of angular
  // positions offset + k·step in u and v (and φ) (offset ½, step 1: every pair of midpoints; offset ⅓,
  // step 2: validation points, never nodes nor midpoints of any refinement of the piece).
  auto measure = [&](const Piece& piece, double offset, int step) {
    Worst worst;
    const int nu = static_cast<int>(piece.u_axis.nodes.size()), nv = static_cast<int>(piece.v_axis.nodes.size());
    const int np = static_cast<int>(piece.packing_axis.nodes.size());
    for (int q = 0; q + 1 < std::max(np, 2); q += step)
      for (int a = 0; a + 1 < nv; a += step)
        for (int b = 0; b + 1 < nu; b += step) {
          const double u = piece.u_axis.at_angle(b + offset), v = piece.v_axis.at_angle(a + offset);
          const double phi = np > 1 ? piece.packing_axis.at_angle(q + offset) : piece.packing_axis.nodes[0];
          const Reduced& exact = at(u, v, phi);
          const Reduced interpolated = piece.reduced_at(u, v, phi);
          for (int c = 0; c < kReduced; ++c) {
            double e = std::abs(interpolated[c] - exact[c]) / std::max(1.0, std::abs(exact[c]));
            if (!std::isfinite(e)) e = INFINITY;
            if (e > worst.error) worst = {e, u, (1 - u) * v, phi};
          }
        }
    return worst;
  };
  tree_.push_back({});
  std::vector<Pending> pending{{0, 0.0, 1.0, 0.0, 1.0, nodes, dense ? packing_nodes : 1, false, INFINITY, 0}};
  while (!pending.empty()) {
    const Pending p = pending.back();
    pending.pop_back();
    Piece piece{
        Axis(p.nodes, p.u_low, p.u_high), Axis(p.nodes, p.v_low, p.v_high), Axis(p.packing_nodes, 0, max_packing_), {}};
    for (double phi : piece.packing_axis.nodes)
      for (double v : piece.v_axis.nodes)
        for (double u : piece.u_axis.nodes) piece.values.push_back(at(u, v, phi));
    Worst worst = measure(piece, 0.5, 1);
    if (worst.error <= tolerance) {
      const Worst check = measure(piece, 1.0 / 3, 2);
      if (check.error <= tolerance) {
        interpolation_error_ = std::max({interpolation_error_, worst.error, check.error});
        validation_error_ = std::max(validation_error_, check.error);
        tree_[static_cast<std::size_t>(p.cell)].piece = static_cast<int>(pieces_.size());
        pieces_.push_back(std::move(piece));
        continue;
      }
      worst = check;
    }
    // Refine every axis K → 2K − 1 up to max_nodes (before any split), then split into quarters that
    // keep the φ nodes reached.
    const int refined = 2 * p.nodes - 1, refined_packing = dense ? 2 * p.packing_nodes - 1 : 1;
    if (!p.split && refined <= max_nodes && refined_packing <= kMaxNodes) {
      pending.push_back(
          {p.cell, p.u_low, p.u_high, p.v_low, p.v_high, refined, refined_packing, false, worst.error, 0});
      continue;
    }
    const int stalls = worst.error > 0.5 * p.parent_error ? p.stalls + 1 : 0;
    if (p.u_high - p.u_low > kMinWidth && stalls < kMaxStalls) {
      const double u_middle = 0.5 * (p.u_low + p.u_high), v_middle = 0.5 * (p.v_low + p.v_high);
      const int child = static_cast<int>(tree_.size());
      tree_[static_cast<std::size_t>(p.cell)] = {-1, child, u_middle, v_middle};
      for (int k = 0; k < 4; ++k) {
        tree_.push_back({});
        const bool upper_u = (k & 1) != 0, upper_v = (k & 2) != 0;
        pending.push_back({child + k, upper_u ? u_middle : p.u_low, upper_u ? p.u_high : u_middle,
                           upper_v ? v_middle : p.v_low, upper_v ? p.v_high : v_middle, nodes, p.packing_nodes, true,
                           worst.error, stalls});
      }
      continue;
    }
    const std::string phi = dense ? ", phi = " + short_number(worst.packing) : std::string();
    const std::string grid = dense ? " x " + std::to_string(p.packing_nodes) + " in phi" : std::string();
    throw std::invalid_argument(
        "tolerance: the interpolation error " + short_number(worst.error) + " at (x_1, x_2) = (" +
        short_number(worst.fraction_1) + ", " + short_number(worst.fraction_2) + ")" + phi + " exceeds the tolerance " +
        short_number(tolerance) + " on x_1 in [" + short_number(p.u_low, 6) + ", " + short_number(p.u_high, 6) +
        "], x_2/(1 - x_1) in [" + short_number(p.v_low, 6) + ", " + short_number(p.v_high, 6) + "] with " +
        std::to_string(p.nodes) + " x " + std::to_string(p.nodes) + " nodes" + grid +
        ", and splitting no longer helps (the order-" + std::to_string(order) +
        " coefficients vary too fast there, e.g. a pole of the truncated solution)");
  }
  // Interpolated values stay within the Lebesgue constant (< 3.3 per axis for ≤ 33
  // Chebyshev–Lobatto nodes, [berrut2004]) times the largest node value: 16× bounds both axes.
  for (const Piece& piece : pieces_)
    for (const Reduced& v : piece.values)
      for (double c : v) reduced_bound_ = std::max(reduced_bound_, 16 * std::abs(c));
  build_solves_ = static_cast<int>(solved.size());
  build_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

int TernaryTransportTable::nodes_per_axis() const {
  int count = 0;
  for (const Piece& piece : pieces_) count = std::max(count, static_cast<int>(piece.u_axis.nodes.size()));
  return count;
}

int TernaryTransportTable::packing_nodes() const {
  int count = 0;
  for (const Piece& piece : pieces_) count = std::max(count, static_cast<int>(piece.packing_axis.nodes.size()));
  return count;
}

TernaryTransportTable::Reduced TernaryTransportTable::reduced(double x1, double x2, double phi) const {
  if (!(x1 >= 0 && x1 <= 1)) refuse_state("fraction_1", "a number in [0, 1]", x1, 1);
  if (!(x2 >= 0 && x2 <= 1 - x1)) refuse_state("fraction_2", "a number in [0, 1 - fraction_1]", x2, 1);
  // The Duffy coordinates (v = 0 on the vertex x_1 = 1, where every v gives the same state).
  const double u = x1, v = x1 < 1 ? std::min(1.0, x2 / (1 - x1)) : 0.0;
  std::size_t c = 0;
  while (tree_[c].child >= 0)
    c = static_cast<std::size_t>(tree_[c].child + (v > tree_[c].v_split ? 2 : 0) + (u > tree_[c].u_split ? 1 : 0));
  return pieces_[static_cast<std::size_t>(tree_[c].piece)].reduced_at(u, v, phi);
}

TernaryTransport TernaryTransportTable::evaluate_reduced(double x1, double x2, double phi) const {
  if (!(phi >= 0 && phi <= max_packing_))
    refuse_state("packing_fraction", "a number in [0, the table's max_packing_fraction]", phi, 1);
  const Reduced r = reduced(x1, x2, phi);
  TernaryTransport out;
  out.cooling_rate = r[0];
  for (std::size_t i = 0; i < 3; ++i) out.temperature_ratio[i] = r[1 + i];
  out.shear_viscosity = r[4];
  out.thermal_conductivity = r[5];
  for (std::size_t k = 0; k < 9; ++k) out.mutual_diffusion[k] = r[6 + k];
  for (std::size_t i = 0; i < 3; ++i) {
    out.thermal_diffusion[i] = r[15 + i];
    out.pressure_diffusion[i] = r[18 + i];
    out.dufour[i] = r[21 + i];
  }
  out.pressure = r[24];
  out.bulk_viscosity = r[25];
  out.cooling_rate_first_order = r[26];
  return out;
}

TernaryTransport TernaryTransportTable::evaluate(double x1, double x2, double n, double temperature) const {
  if (!(n > 0 && n < INFINITY)) refuse_state("number_density", "a finite number > 0", n, temperature);
  if (!(temperature > 0 && temperature < INFINITY))
    refuse_state("temperature", "a finite number > 0", temperature, temperature);
  if (!(x1 >= 0 && x1 <= 1)) refuse_state("fraction_1", "a number in [0, 1]", x1, 1);
  if (!(x2 >= 0 && x2 <= 1 - x1)) refuse_state("fraction_2", "a number in [0, 1 - fraction_1]", x2, 1);
  const double x[3] = {x1, x2, 1 - x1 - x2};
  // φ = n v_d Σ x_i σ_i^d (v_d σ_i^d kept from the build); above φ_max every value is nan.
  const double phi =
      max_packing_ > 0 ? n * (x[0] * species_volume_[0] + x[1] * species_volume_[1] + x[2] * species_volume_[2]) : 0.0;
  if (phi > max_packing_) {
    const double nan = std::nan("");
    TernaryTransport out;
    out.cooling_rate = out.shear_viscosity = out.thermal_conductivity = out.pressure = nan;
    out.bulk_viscosity = out.cooling_rate_first_order = nan;
    out.temperature_ratio.fill(nan);
    out.mutual_diffusion.fill(nan);
    out.thermal_diffusion.fill(nan);
    out.pressure_diffusion.fill(nan);
    out.dufour.fill(nan);
    return out;
  }
  const Reduced r = reduced(x1, x2, phi);
  const double mbar = x[0] * mass_[0] + x[1] * mass_[1] + x[2] * mass_[2];
  const double sbar = x[0] * diameter_[0] + x[1] * diameter_[1] + x[2] * diameter_[2];
  // Reference gas (m̄, σ̄) at n, T (docs/conventions.md).
  const ReferenceGas ref = reference_gas(dimension_, mbar, sbar, n, temperature);
  const double eta0 = ref.viscosity, kappa0 = ref.conductivity, d0 = ref.self_diffusion;
  const double scales[] = {ref.collision_frequency, eta0, kappa0, n * d0, d0, kappa0 / temperature, n * temperature};
  TernaryTransport out;
  out.cooling_rate = r[0] * scales[0];
  for (std::size_t i = 0; i < 3; ++i) out.temperature_ratio[i] = r[1 + i];
  out.shear_viscosity = r[4] * eta0;
  out.thermal_conductivity = r[5] * kappa0;
  for (std::size_t k = 0; k < 9; ++k) out.mutual_diffusion[k] = r[6 + k] * scales[3];
  for (std::size_t i = 0; i < 3; ++i) {
    out.thermal_diffusion[i] = r[15 + i] * d0;
    out.pressure_diffusion[i] = r[18 + i] * d0;
    out.dufour[i] = r[21 + i] * scales[5];
  }
  out.pressure = r[24] * scales[6];
  out.bulk_viscosity = r[25] * eta0;
  out.cooling_rate_first_order = r[26];
  // The scales must be normal doubles, small enough that no |reduced value| ≤ reduced_bound_ overflows.
  const double smallest = *std::min_element(std::begin(scales), std::end(scales));
  const double largest = *std::max_element(std::begin(scales), std::end(scales));
  if (!(smallest >= std::numeric_limits<double>::min() && largest * std::max(1.0, reduced_bound_) < INFINITY))
    refuse_state("number_density, temperature", "", n, temperature);
  return out;
}

}  // namespace gkt
