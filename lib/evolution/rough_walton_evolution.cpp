#include "gkt/evolution/rough_walton_evolution.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "evolution/cvode_support.hpp"

namespace gkt {

RoughWaltonInterpolant::RoughWaltonInterpolant(int dimension, double alpha, double beta0, double kappa, double friction,
                                               double tau_lo, double tau_hi, int nodes)
    : dimension_(dimension),
      alpha_(alpha),
      beta0_(beta0),
      kappa_(kappa),
      friction_(friction),
      lo_(std::log(tau_lo)),
      hi_(std::log(tau_hi)) {
  if (!(tau_lo > 0) || !(tau_hi > tau_lo) || !std::isfinite(tau_hi))
    throw std::invalid_argument("temperature_ratio: the interpolation range must satisfy 0 < lo < hi");
  if (nodes < 4) throw std::invalid_argument("nodes: must be >= 4");
  const auto n = static_cast<std::size_t>(nodes);
  std::vector<RoughProductionTable> values(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double x = std::cos(std::numbers::pi * (static_cast<double>(k) + 0.5) / static_cast<double>(n));
    const RoughWaltonProductions p = rough_walton_productions(dimension, alpha, beta0, kappa, friction,
                                                              std::exp(0.5 * (lo_ + hi_) + 0.5 * (hi_ - lo_) * x));
    values[k] = p.table;
    collision_a20_ = p.collision_a20;
  }
  // c_j = (2/n) Σ_k f(x_k) cos(jπ(k + 1/2)/n) (c_0 halved at evaluation).
  coefficients_.assign(n, RoughProductionTable{});
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t k = 0; k < n; ++k) {
      const double w =
          2.0 / static_cast<double>(n) *
          std::cos(std::numbers::pi * static_cast<double>(j) * (static_cast<double>(k) + 0.5) / static_cast<double>(n));
      for (std::size_t x = 0; x < 4; ++x)
        for (std::size_t t = 0; t < 5; ++t) coefficients_[j][x][t] += w * values[k][x][t];
    }
}

RoughProductionTable RoughWaltonInterpolant::operator()(double tau) const {
  RoughProductionTable out{};
  const double lt = std::log(tau);
  if (!(lt >= lo_ && lt <= hi_)) {
    for (auto& row : out) row.fill(std::numeric_limits<double>::quiet_NaN());
    return out;
  }
  // Clenshaw's recurrence in x = (2 ln τ − lo − hi)/(hi − lo).
  const double x = (2 * lt - lo_ - hi_) / (hi_ - lo_);
  for (std::size_t r = 0; r < 4; ++r)
    for (std::size_t t = 0; t < 5; ++t) {
      double b1 = 0, b2 = 0;
      for (std::size_t j = coefficients_.size(); j-- > 1;) {
        const double b0 = 2 * x * b1 - b2 + coefficients_[j][r][t];
        b2 = b1;
        b1 = b0;
      }
      out[r][t] = x * b1 - b2 + 0.5 * coefficients_[0][r][t];
    }
  return out;
}

double RoughWaltonInterpolant::check(int samples) const {
  const auto n = static_cast<double>(coefficients_.size());
  double worst = 0;
  for (int k = 0; k < samples && k + 1 < static_cast<int>(coefficients_.size()); ++k) {
    // Between the Chebyshev nodes k and k + 1 (in x).
    const double x = std::cos(std::numbers::pi * (k + 1) / n);
    const double tau = std::exp(0.5 * (lo_ + hi_) + 0.5 * (hi_ - lo_) * x);
    const RoughProductionTable direct =
        rough_walton_productions(dimension_, alpha_, beta0_, kappa_, friction_, tau).table;
    const RoughProductionTable interpolated = (*this)(tau);
    for (std::size_t r = 0; r < 4; ++r)
      for (std::size_t t = 0; t < 5; ++t)
        worst = std::max(worst, std::abs(direct[r][t] - interpolated[r][t]) / (1 + std::abs(direct[r][t])));
  }
  return worst;
}

RoughEvolutionResult evolve_rough_walton_cooling(int dimension, double alpha, double beta0, double kappa,
                                                 double friction, double translational0, double rotational0,
                                                 const std::vector<double>& times, double rtol, double atol,
                                                 const RoughCumulants& initial_cumulants, long max_steps) {
  check_rough_initial_cumulants(dimension, initial_cumulants);
  detail::check_max_steps(max_steps);
  if (!(translational0 > 0) || !std::isfinite(translational0))
    throw std::invalid_argument("translational_temperature: must be a finite number > 0");
  if (!(rotational0 > 0) || !std::isfinite(rotational0))
    throw std::invalid_argument("rotational_temperature: must be a finite number > 0");
  const RoughWaltonCumulantState hcs = rough_walton_linear_cooling_state(dimension, alpha, beta0, kappa, friction);
  if (hcs.spin_decoupled)
    throw std::invalid_argument(
        "friction: the Walton spin decouples (no finite temperature ratio; theory.md section 19.10) at friction = " +
        std::to_string(friction) + ", beta0 = " + std::to_string(beta0) + "; use hcs = \"maxwellian\"");
  if (!hcs.linear_scheme_solved)
    throw std::invalid_argument(
        "hcs: the linear scheme of the Walton gas has no root with realizable cumulants at this state (docs/theory.md "
        "section 19.19); use hcs = \"maxwellian\"");
  const double tau0 = rotational0 / translational0 / kappa, tau_hcs = hcs.temperature_ratio / kappa;
  const double lo = std::min(std::log(tau0), std::log(tau_hcs)) - 0.5;
  const double hi = std::max(std::log(tau0), std::log(tau_hcs)) + 0.5;
  const int nodes = std::max(24, static_cast<int>(std::ceil(16 * (hi - lo))));
  const RoughWaltonInterpolant table(dimension, alpha, beta0, kappa, friction, std::exp(lo), std::exp(hi), nodes);
  RoughLinearProductions productions;
  productions.table = [&table](double tau) { return table(tau); };
  productions.collision_a20 = table.collision_a20();
  productions.kappa = kappa;
  return evolve_rough_linear_cooling(dimension, productions, translational0, rotational0, times, rtol, atol,
                                     initial_cumulants, max_steps);
}

}  // namespace gkt
