#include "gkt/transport/rough/rough_mixture_cooling_state.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "gkt/collision/rough_mixture_collision_moments.hpp"

namespace gkt {

namespace {

/// Λ = (d+2)√2/8: ζ* = −(2/d) Λ Σ_j c_ij ⟨X1' − X1⟩ (theory.md (16.4)).
double lambda(int d) { return (d + 2) * std::sqrt(2.0) / 8.0; }

int rotational_freedom(int d) { return d == 3 ? 3 : 1; }

std::size_t pair_index(std::size_t i, std::size_t j) { return i + j; }  // 0: 1–1, 1: 1–2, 2: 2–2

/// The four temperatures' slots of an i–j table in the mixture's order (T_t,1, T_t,2, T_r,1, T_r,2).
std::array<std::size_t, 4> global_slots(std::size_t i, std::size_t j) { return {i, j, 2 + i, 2 + j}; }

/// Exact coefficients of every ordered pair (i, j).
using PairTables = std::array<std::array<RoughPairEnergyChanges, 2>, 2>;

PairTables pair_tables(const RoughBinaryMixture& m) {
  PairTables t;
  for (std::size_t i = 0; i < 2; ++i)
    for (std::size_t j = 0; j < 2; ++j)
      t[i][j] = rough_pair_energy_changes(m.dimension, m.alpha[pair_index(i, j)], m.beta[pair_index(i, j)],
                                          m.species[i], m.species[j]);
  return t;
}

/// Returns the matrix A of dT/dt = A T (time in 1/ν0(T), T the mixture temperature) at the
/// translational ratios γ_i = T_t,i/T (theory.md (19.55)).
Eigen::Matrix4d cooling_matrix(const RoughBinaryMixture& m, const PairTables& tables,
                               const std::array<double, 2>& gamma) {
  const int d = m.dimension;
  const double mean_mass =
      m.species[0].fraction * m.species[0].mass.to_double() + m.species[1].fraction * m.species[1].mass.to_double();
  const double mean_diameter =
      m.species[0].fraction * m.species[0].diameter + m.species[1].fraction * m.species[1].diameter;
  Eigen::Matrix4d a = Eigen::Matrix4d::Zero();
  for (std::size_t i = 0; i < 2; ++i)
    for (std::size_t j = 0; j < 2; ++j) {
      const double sigma_ij = 0.5 * (m.species[i].diameter + m.species[j].diameter) / mean_diameter;
      const double rate = m.species[j].fraction * std::pow(sigma_ij, d - 1) *
                          std::sqrt(gamma[i] * mean_mass / m.species[i].mass.to_double() +
                                    gamma[j] * mean_mass / m.species[j].mass.to_double()) *
                          lambda(d);
      const auto slots = global_slots(i, j);
      // Rows of the table for the particle of species i: 0 (translational), 2 (rotational).
      for (const std::size_t row : {std::size_t{0}, std::size_t{2}}) {
        const double freedom = row == 0 ? d : rotational_freedom(d);
        for (std::size_t c = 0; c < 4; ++c)
          a(static_cast<Eigen::Index>(slots[row]), static_cast<Eigen::Index>(slots[c])) +=
              (2.0 / freedom) * rate * tables[i][j].coefficient[row][c].to_double();
      }
    }
  return a;
}

struct PerronMode {
  double eigenvalue;
  Eigen::Vector4d vector;  // positive, T_t,1 = 1; +∞ in the slot of a decoupled spin
};

/// Returns the eigenvalue of largest real part (Perron: A has non-negative off-diagonal entries)
/// and its eigenvector, on the slots `kept` only (a decoupled spin's row and column of A vanish: its
/// T_r stays constant, the eigenvalue 0 is not the cooling mode; theory.md (19.130)).
PerronMode perron_mode(const Eigen::Matrix4d& a, const std::array<bool, 4>& kept) {
  std::vector<Eigen::Index> slots;
  for (Eigen::Index k = 0; k < 4; ++k)
    if (kept[static_cast<std::size_t>(k)]) slots.push_back(k);
  const auto n = static_cast<Eigen::Index>(slots.size());
  Eigen::MatrixXd reduced(n, n);
  for (Eigen::Index r = 0; r < n; ++r)
    for (Eigen::Index c = 0; c < n; ++c)
      reduced(r, c) = a(slots[static_cast<std::size_t>(r)], slots[static_cast<std::size_t>(c)]);
  Eigen::EigenSolver<Eigen::MatrixXd> solver(reduced);
  Eigen::Index best = 0;
  for (Eigen::Index k = 1; k < n; ++k)
    if (solver.eigenvalues()[k].real() > solver.eigenvalues()[best].real()) best = k;
  const Eigen::VectorXd v = solver.eigenvectors().col(best).real();
  Eigen::Vector4d out = Eigen::Vector4d::Constant(std::numeric_limits<double>::infinity());
  for (Eigen::Index r = 0; r < n; ++r) out(slots[static_cast<std::size_t>(r)]) = v(r) / v(0);
  return {solver.eigenvalues()[best].real(), out};
}

}  // namespace

void RoughBinaryMixture::validate() const {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
  for (std::size_t i = 0; i < 2; ++i) {
    const std::string name = "species[" + std::to_string(i) + "].";
    const auto& s = species[i];
    if (s.mass.sign() <= 0) throw std::invalid_argument(name + "mass: must be > 0, got " + s.mass.to_decimal_string());
    if (s.kappa.sign() <= 0 || s.kappa > Rational(1))
      throw std::invalid_argument(name + "moment_of_inertia: must be a number in (0, 1], got " +
                                  s.kappa.to_decimal_string());
    if (!(s.diameter > 0) || !std::isfinite(s.diameter))
      throw std::invalid_argument(name + "diameter: must be a finite number > 0, got " + std::to_string(s.diameter));
    if (!(s.fraction >= 0 && s.fraction <= 1))
      throw std::invalid_argument(name + "fraction: must be a number in [0, 1], got " + std::to_string(s.fraction));
  }
  if (std::abs(species[0].fraction + species[1].fraction - 1) > 1e-12)
    throw std::invalid_argument("fraction: the two mole fractions must sum to 1");
  for (std::size_t p = 0; p < 3; ++p) {
    if (alpha[p].sign() <= 0 || alpha[p] > Rational(1))
      throw std::invalid_argument("alpha[" + std::to_string(p) + "]: must be a number in (0, 1], got " +
                                  alpha[p].to_decimal_string());
    if (beta[p] < Rational(-1) || beta[p] > Rational(1))
      throw std::invalid_argument("beta[" + std::to_string(p) + "]: must be a number in [-1, 1], got " +
                                  beta[p].to_decimal_string());
  }
}

RoughPairEnergyChanges rough_pair_energy_changes(int dimension, const Rational& alpha, const Rational& beta,
                                                 const RoughMixtureComponent& species_i,
                                                 const RoughMixtureComponent& species_j) {
  const Rational half(1, 2);
  const std::vector<RoughForm> forms{scaled(rough_dot_form(RoughSlot::v1_post, RoughSlot::v1_post) +
                                                scaled(rough_dot_form(RoughSlot::v1, RoughSlot::v1), Rational(-1)),
                                            species_i.mass * half),
                                     scaled(rough_dot_form(RoughSlot::v2_post, RoughSlot::v2_post) +
                                                scaled(rough_dot_form(RoughSlot::v2, RoughSlot::v2), Rational(-1)),
                                            species_j.mass * half),
                                     scaled(rough_dot_form(RoughSlot::w1_post, RoughSlot::w1_post) +
                                                scaled(rough_dot_form(RoughSlot::w1, RoughSlot::w1), Rational(-1)),
                                            species_i.kappa * species_i.mass * half),
                                     scaled(rough_dot_form(RoughSlot::w2_post, RoughSlot::w2_post) +
                                                scaled(rough_dot_form(RoughSlot::w2, RoughSlot::w2), Rational(-1)),
                                            species_j.kappa * species_j.mass * half)};
  // ⟨ΔE_r⟩ is linear and homogeneous in the four temperatures (theory.md (19.54)): its coefficients are
  // the differences of the values at T = (1, 1, 1, 1) + e_c and at T = (1, 1, 1, 1).
  const auto changes = [&](const std::array<Rational, 4>& t) {
    const RoughSpecies i{species_i.mass, species_i.kappa, t[0], t[2]};
    const RoughSpecies j{species_j.mass, species_j.kappa, t[1], t[3]};
    const auto table =
        rough_mixture_collision_moments(rough_mixture_parameters(dimension, alpha, beta, i, j), forms, {1, 1, 1, 1});
    return std::array<Rational, 4>{
        table.moment(std::array<int, 4>{1, 0, 0, 0}), table.moment(std::array<int, 4>{0, 1, 0, 0}),
        table.moment(std::array<int, 4>{0, 0, 1, 0}), table.moment(std::array<int, 4>{0, 0, 0, 1})};
  };
  const std::array<Rational, 4> ones{Rational(1), Rational(1), Rational(1), Rational(1)};
  const auto base = changes(ones);
  RoughPairEnergyChanges out;
  for (std::size_t c = 0; c < 4; ++c) {
    auto t = ones;
    t[c] += Rational(1);
    const auto shifted = changes(t);
    for (std::size_t r = 0; r < 4; ++r) out.coefficient[r][c] = shifted[r] - base[r];
  }
  return out;
}

std::array<double, 4> rough_mixture_cooling_rates(const RoughBinaryMixture& mixture,
                                                  const std::array<double, 4>& temperatures) {
  mixture.validate();
  for (std::size_t k = 0; k < 4; ++k)
    if (!(temperatures[k] > 0) || !std::isfinite(temperatures[k]))
      throw std::invalid_argument("temperatures[" + std::to_string(k) + "]: must be a finite number > 0");
  const double t = mixture.species[0].fraction * temperatures[0] + mixture.species[1].fraction * temperatures[1];
  const Eigen::Matrix4d a = cooling_matrix(mixture, pair_tables(mixture), {temperatures[0] / t, temperatures[1] / t});
  const Eigen::Vector4d temps(temperatures[0], temperatures[1], temperatures[2], temperatures[3]);
  const Eigen::Vector4d change = a * temps;
  return {-change(0) / temps(0), -change(1) / temps(1), -change(2) / temps(2), -change(3) / temps(3)};
}

RoughMixtureCoolingState rough_mixture_cooling_state(const RoughBinaryMixture& mixture) {
  mixture.validate();
  const auto& x = mixture.species;
  // The spin of species k is coupled iff some pair it collides with has β > −1; a decoupled spin keeps
  // its T_r (θ_k = +∞ in the HCS) and drops out of the translational dynamics (theory.md (19.130)).
  std::array<bool, 4> kept{true, true, true, true};
  for (std::size_t k = 0; k < 2; ++k)
    kept[2 + k] = x[k].fraction * (1 + mixture.beta[pair_index(k, k)].to_double()) +
                      x[1 - k].fraction * (1 + mixture.beta[pair_index(k, 1 - k)].to_double()) >
                  0;
  // A decoupled spin that still exchanges energy with a tracer partner (x_j = 0, β_ij > −1) heats it without
  // cooling itself: T_t,j/T grows without bound, no HCS.
  for (std::size_t k = 0; k < 2; ++k)
    if (!kept[2 + k] && x[k].fraction > 0 && mixture.beta[pair_index(k, 1 - k)] > Rational(-1))
      throw std::invalid_argument("beta: the spin of species " + std::to_string(k + 1) +
                                  " does not cool (beta = -1 with itself) but heats the tracer species " +
                                  std::to_string(2 - k) + " (beta_1_2 > -1, fraction 0): no cooling state");
  const PairTables tables = pair_tables(mixture);
  const auto mode_at = [&](double log_ratio) {
    const double rho = std::exp(log_ratio), t = x[0].fraction + x[1].fraction * rho;
    return perron_mode(cooling_matrix(mixture, tables, {1 / t, rho / t}), kept);
  };
  // h(ln ρ) = ln(T_t,2/T_t,1 of the Perron vector) − ln ρ: the vector's ratio stays bounded as ρ → 0, ∞.
  const auto h = [&](double log_ratio) { return std::log(mode_at(log_ratio).vector(1)) - log_ratio; };
  double low = -1, high = 1;
  while (h(low) < 0 && low > -60) low *= 2;
  while (h(high) > 0 && high < 60) high *= 2;
  if (!(h(low) >= 0 && h(high) <= 0))
    throw std::runtime_error("rough_mixture_cooling_state: no bracket for T_t,2/T_t,1");
  for (int it = 0; it < 200 && high - low > 1e-15 * (1 + std::abs(low)); ++it) {
    const double mid = 0.5 * (low + high);
    (h(mid) > 0 ? low : high) = mid;
  }
  const double log_ratio = 0.5 * (low + high);
  const PerronMode mode = mode_at(log_ratio);
  RoughMixtureCoolingState out;
  const double t = x[0].fraction * mode.vector(0) + x[1].fraction * mode.vector(1);
  out.temperature_ratio = {mode.vector(0) / t, mode.vector(1) / t};
  out.rotational_ratio = {mode.vector(2) / mode.vector(0), mode.vector(3) / mode.vector(1)};
  // α = 1 and β = ±1 on every pair lose no energy ((19.51)): ζ* = 0 exactly, where the eigenvalue may leave 1e-16.
  const bool conservative =
      std::all_of(mixture.alpha.begin(), mixture.alpha.end(), [](const Rational& a) { return a == Rational(1); }) &&
      std::all_of(mixture.beta.begin(), mixture.beta.end(),
                  [](const Rational& b) { return b == Rational(1) || b == Rational(-1); });
  out.cooling_rate = conservative ? 0.0 : -mode.eigenvalue;
  return out;
}

}  // namespace gkt
