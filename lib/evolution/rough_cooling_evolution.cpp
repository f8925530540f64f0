#include "gkt/evolution/rough_cooling_evolution.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <Eigen/Dense>

#include "evolution/cvode_support.hpp"

namespace gkt {

namespace {

using detail::check;
using detail::ContextDeleter;
using detail::CvodeDeleter;
using detail::keep_message;
using detail::MatrixDeleter;
using detail::SolverDeleter;
using detail::VectorDeleter;

/// State y = (ln T_t, ln T_r, C, a20, a02, a11, b00) (the cumulants only in the linear scheme, b00 only with
/// `oriented`).
struct Problem {
  const RoughCoolingRates* rates = nullptr;             // the engine's balances, or
  const RoughMaxwellianRates* maxwellian = nullptr;     // Maxwellian rates as a function of θ
  const RoughOrientedCoolingRates* oriented = nullptr;  // with `rates` (its collision frequency): the b00 balances
  const RoughSonineCoolingRates* sonine = nullptr;      // or the order-N linear scheme alone (y = ln T_t, ln T_r, C, u)
  Eigen::PartialPivLU<Eigen::MatrixXd> projection;      // ⟨ψ_t Φ_w⟩_M of the order-N scheme, factorised
  std::vector<double> sonine_initial;                   // u(0) of the order-N scheme
  const RoughLinearProductions* productions = nullptr;  // or the linear scheme's averages as a function of τ
  int dimension = 3;
  bool linear = false;
  std::array<double, 3> base{};  // Maxwellian ⟨x²⟩, ⟨y²⟩, ⟨xy⟩
  RoughCumulants initial{};      // a20, a02, a11 at τ = 0 (linear scheme)

  [[nodiscard]] int size() const {
    if (sonine != nullptr) return 3 + static_cast<int>(sonine->unknowns());
    return oriented != nullptr ? 7 : linear ? 6 : 3;
  }

  [[nodiscard]] std::array<double, 3> cumulants(const double* y) const {
    return linear ? std::array<double, 3>{y[3], y[4], y[5]} : std::array<double, 3>{};
  }
};

/// The rates of theory.md (19.24)–(19.25): d ln T_t/dτ = −√T_t z_t(a), d ln T_r/dτ = −√T_t z_r(a),
/// dC/dτ = √T_t (1 + c a20) and ⟨ψ_p⟩_M da_p/dτ = √T_t [G_p(τ, a) + l_p (z_r − z_t) ⟨ψ_p⟩_a],
/// l = (0, 2, 1) the spin degree of ψ = (x², y², xy) over two.
int right_hand_side(sunrealtype, N_Vector y, N_Vector ydot, void* data) {
  const auto& p = *static_cast<const Problem*>(data);
  const double* yv = N_VGetArrayPointer(y);
  double* dv = N_VGetArrayPointer(ydot);
  const double log_theta = yv[1] - yv[0];
  if (!std::isfinite(log_theta)) return 1;  // recoverable: CVODE retries with a smaller step
  const double sq = std::exp(0.5 * yv[0]);
  if (p.maxwellian != nullptr) {
    const auto z = (*p.maxwellian)(std::exp(log_theta));
    if (!std::isfinite(z[0]) || !std::isfinite(z[1])) return 1;
    dv[0] = -sq * z[0];
    dv[1] = -sq * z[1];
    dv[2] = sq;
    return 0;
  }
  if (p.sonine != nullptr) {
    // theory.md (19.25b): Π du/ds = G(τ, u) + l (z_r − z_t)⟨ψ⟩(u), ⟨ψ⟩(u) = ⟨ψ⟩_M + Π u, ds = √T_t dτ.
    const std::size_t k = p.sonine->unknowns();
    const std::span<const double> u(yv + 3, k);
    const RoughSonineRates r = p.sonine->at(std::exp(log_theta) / p.sonine->kappa(), u);
    dv[0] = -sq * r.translational_rate;
    dv[1] = -sq * r.rotational_rate;
    dv[2] = sq * p.sonine->collision_frequency_factor(u);
    const double spin_excess = r.rotational_rate - r.translational_rate;
    const auto& pm = p.sonine->projections();
    Eigen::VectorXd rhs(static_cast<Eigen::Index>(k));
    for (std::size_t t = 0; t < k; ++t) {
      double moment = p.sonine->maxwellian_moments()[t];
      for (std::size_t w = 0; w < k; ++w) moment += pm[t][w] * u[w];
      rhs(static_cast<Eigen::Index>(t)) = r.residual[t] + p.sonine->spin_degrees()[t] * spin_excess * moment;
    }
    const Eigen::VectorXd du = p.projection.solve(rhs);
    for (std::size_t t = 0; t < k; ++t) dv[3 + t] = sq * du(static_cast<Eigen::Index>(t));
    return 0;
  }
  const auto a = p.cumulants(yv);
  if (p.oriented != nullptr) {
    // The same with ψ = P (spin degree 1, ⟨P⟩ = b00⟨P²⟩_M): ⟨P²⟩_M db00/dτ = √T_t [G_P + (z_r − z_t) ⟨P⟩].
    const std::array<double, 4> a4{a[0], a[1], a[2], yv[6]};
    const RoughOrientedBalances b = p.oriented->at(std::exp(log_theta) / p.oriented->kappa(), a4);
    const auto base = p.oriented->base_moments();
    dv[0] = -sq * b.translational_rate;
    dv[1] = -sq * b.rotational_rate;
    dv[2] = sq * p.rates->collision_frequency_factor(a[0]);  // P averages to 0 over ŵ: no change
    constexpr std::array<double, 3> spin_degree{0, 2, 1};
    const double spin_excess = b.rotational_rate - b.translational_rate;
    for (std::size_t q = 0; q < 3; ++q)
      dv[3 + q] = sq * (b.residual[q] + spin_degree[q] * spin_excess * base[q] * (1 + a[q])) / base[q];
    dv[6] = sq * (b.residual[3] + spin_excess * base[3] * a4[3]) / base[3];
    return 0;
  }
  const RoughBalances b =
      p.productions != nullptr
          ? rough_linear_balances(p.dimension, p.productions->table(std::exp(log_theta) / p.productions->kappa), a)
          : p.rates->at(std::exp(log_theta) / p.rates->kappa(), a);
  if (p.productions != nullptr && !(std::isfinite(b.translational_rate) && std::isfinite(b.rotational_rate))) return 1;
  dv[0] = -sq * b.translational_rate;
  dv[1] = -sq * b.rotational_rate;
  dv[2] = sq * (p.productions != nullptr ? 1 + p.productions->collision_a20 * a[0]
                                         : p.rates->collision_frequency_factor(a[0]));
  if (!p.linear) return 0;
  constexpr std::array<double, 3> spin_degree{0, 2, 1};
  const double spin_excess = b.rotational_rate - b.translational_rate;
  for (std::size_t q = 0; q < 3; ++q)
    dv[3 + q] = sq * (b.residual[q + 1] + spin_degree[q] * spin_excess * p.base[q] * (1 + a[q])) / p.base[q];
  return 0;
}

/// The one-line error when the Sonine scheme of `problem` used its `budget` of CVODE steps on its way to `target`,
/// stopped at `reached` with the unknowns `yv` (theory.md §19.24, "Where it stalls").
EvolutionFailure step_budget_failure(const Problem& problem, long budget, double target, double reached,
                                     const double* yv, int flag) {
  const RoughSonineCoolingRates& r = *problem.sonine;
  const auto& ia = r.cumulant_indices();
  std::size_t largest = 0;
  for (std::size_t w = 1; w < ia.size(); ++w)
    if (std::abs(yv[3 + w]) > std::abs(yv[3 + largest])) largest = w;
  auto g = [](double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.3g", v);
    return std::string(buffer);
  };
  const bool nonlinear = r.scheme() == RoughSonineScheme::nonlinear;
  return EvolutionFailure(
      "max_steps: the " + std::string(nonlinear ? "nonlinear" : "linear") + " Sonine scheme at order " +
          std::to_string(r.order()) + " used its " + std::to_string(budget) + " CVODE steps before tau = " + g(target) +
          " (stopped at tau = " + g(reached) + ", theta = " + g(std::exp(yv[1] - yv[0])) + ", a" +
          std::to_string(ia[largest][0]) + std::to_string(ia[largest][1]) + " = " + g(yv[3 + largest]) +
          "): the truncated series does not bound the cumulants from this start (theory.md §19.24); use a lower "
          "order, hcs = \"linear\", or a warmer rotational_temperature",
      flag, reached);
}

RoughEvolutionResult integrate(Problem& problem, int dimension, double translational0, double rotational0,
                               const std::vector<double>& times, double rtol, double atol, long max_steps) {
  if (!(translational0 > 0) || !std::isfinite(translational0))
    throw std::invalid_argument("translational_temperature: must be a finite number > 0");
  if (!(rotational0 > 0) || !std::isfinite(rotational0))
    throw std::invalid_argument("rotational_temperature: must be a finite number > 0");
  if (!(rtol > 0) || !(atol > 0)) throw std::invalid_argument("rtol, atol: must be > 0");
  for (std::size_t i = 0; i < times.size(); ++i)
    if (!(times[i] > 0) || (i > 0 && !(times[i] > times[i - 1])))
      throw std::invalid_argument("times: must be positive and increasing");
  detail::check_max_steps(max_steps);
  const int n = problem.size();

  SUNContext raw_context = nullptr;
  check(SUNContext_Create(nullptr, &raw_context), "SUNContext_Create");
  const std::unique_ptr<std::remove_pointer_t<SUNContext>, ContextDeleter> context(raw_context);
  const std::unique_ptr<std::remove_pointer_t<N_Vector>, VectorDeleter> y(N_VNew_Serial(n, raw_context));
  double* yv = N_VGetArrayPointer(y.get());
  yv[0] = std::log(translational0);
  yv[1] = std::log(rotational0);
  yv[2] = 0.0;
  if (problem.sonine != nullptr) {
    for (int k = 3; k < n; ++k) yv[k] = problem.sonine_initial[static_cast<std::size_t>(k - 3)];
  } else {
    for (int k = 3; k < std::min(n, 6); ++k) yv[k] = problem.initial[static_cast<std::size_t>(k - 3)];
    if (n == 7) yv[6] = 0.0;  // b00(0) = 0: Maxwellian directions
  }

  const std::unique_ptr<void, CvodeDeleter> cvode(CVodeCreate(CV_BDF, raw_context));
  if (!cvode) throw std::runtime_error("CVODE: CVodeCreate failed");
  std::string cvode_message;
  check(CVodeSetErrHandlerFn(cvode.get(), keep_message, &cvode_message), "CVodeSetErrHandlerFn");
  check(CVodeInit(cvode.get(), right_hand_side, 0.0, y.get()), "CVodeInit");
  check(CVodeSStolerances(cvode.get(), rtol, atol), "CVodeSStolerances");
  check(CVodeSetUserData(cvode.get(), &problem), "CVodeSetUserData");
  const std::unique_ptr<std::remove_pointer_t<SUNMatrix>, MatrixDeleter> matrix(SUNDenseMatrix(n, n, raw_context));
  const std::unique_ptr<std::remove_pointer_t<SUNLinearSolver>, SolverDeleter> solver(
      SUNLinSol_Dense(y.get(), matrix.get(), raw_context));
  check(CVodeSetLinearSolver(cvode.get(), solver.get(), matrix.get()), "CVodeSetLinearSolver");

  const double d = dimension;
  RoughEvolutionResult result;
  for (double target : times) {
    double reached = 0;
    // A budget over the whole trajectory (theory.md §19.24): what is left of it bounds this call.
    try {
      reached = detail::advance_within_budget(cvode.get(), target, y.get(), cvode_message,
                                              "integrate to an earlier time", max_steps);
    } catch (const EvolutionFailure& e) {
      if (e.flag() != CV_TOO_MUCH_WORK || problem.sonine == nullptr) throw;
      throw step_budget_failure(problem, max_steps, target, e.time(), yv, e.flag());
    }
    RoughEvolutionSample s;
    s.time = reached;
    s.translational_temperature = std::exp(yv[0]);
    s.rotational_temperature = std::exp(yv[1]);
    s.collisions = yv[2];
    if (problem.sonine != nullptr) {
      const RoughSonineCoolingRates& r = *problem.sonine;
      const std::size_t na = r.cumulant_indices().size();
      s.cumulants.assign(yv + 3, yv + 3 + na);
      s.orientation_coefficients.assign(yv + 3 + na, yv + n);
      for (std::size_t w = 0; w < na; ++w) {
        const auto pq = r.cumulant_indices()[w];
        if (pq == std::array<int, 2>{2, 0}) s.a20 = s.cumulants[w];
        if (pq == std::array<int, 2>{0, 2}) s.a02 = s.cumulants[w];
        if (pq == std::array<int, 2>{1, 1}) s.a11 = s.cumulants[w];
      }
      for (std::size_t o = 0; o < s.orientation_coefficients.size(); ++o)
        s.orientation_correlation += r.correlation_weights()[o] * s.orientation_coefficients[o];
      if (!s.orientation_coefficients.empty()) s.b00 = s.orientation_coefficients.front();  // (0, 0) comes first
      if (dimension != 3) s.orientation_correlation = std::nan("");                         // c·ŵ ≡ 0 for disks
      const std::span<const double> u(yv + 3, r.unknowns());
      s.cooling_rate = (d + 2) / 4 * r.at(std::exp(yv[1] - yv[0]) / r.kappa(), u).translational_rate;
      result.samples.push_back(std::move(s));
      continue;
    }
    const auto a = problem.cumulants(yv);
    s.a20 = a[0];
    s.a02 = a[1];
    s.a11 = a[2];
    const double theta = std::exp(yv[1] - yv[0]);
    if (problem.oriented != nullptr) {
      s.b00 = yv[6];
      s.orientation_correlation = 1.0 / 3 + problem.oriented->correlation_weight() * s.b00;
      s.cooling_rate =
          (d + 2) / 4 *
          problem.oriented->at(theta / problem.oriented->kappa(), {a[0], a[1], a[2], s.b00}).translational_rate;
    } else {
      s.cooling_rate =
          (d + 2) / 4 *
          (problem.maxwellian != nullptr ? (*problem.maxwellian)(theta)[0]
           : problem.productions != nullptr
               ? rough_linear_balances(dimension, problem.productions->table(theta / problem.productions->kappa), a)
                     .translational_rate
               : problem.rates->at(theta / problem.rates->kappa(), a).translational_rate);
    }
    result.samples.push_back(s);
  }
  result.counters = detail::read_counters(cvode.get());
  return result;
}

}  // namespace

void check_rough_initial_cumulants(int dimension, const RoughCumulants& a) {
  if (dimension != 2 && dimension != 3) throw std::invalid_argument("dimension: must be 2 or 3");
  const char* names[] = {"a20", "a02", "a11"};
  for (std::size_t q = 0; q < 3; ++q)
    if (!std::isfinite(a[q])) throw std::invalid_argument(std::string(names[q]) + ": must be a finite number");
  const double d = dimension, d_r = dimension == 3 ? 3.0 : 1.0;
  // theory.md (19.24a): ⟨x²⟩ = (d(d+2)/4)(1 + a20) ≥ ⟨x⟩² = d²/4, likewise for y = ŵ², and
  // Cov(x, y)² = (d d_r a11/4)² ≤ Var x Var y.
  const double var_x = d * ((d + 2) * (1 + a[0]) - d) / 4, var_y = d_r * ((d_r + 2) * (1 + a[1]) - d_r) / 4;
  auto bound = [](double v) { return std::to_string(v); };
  if (var_x < 0)
    throw std::invalid_argument("a20: must be >= -2/(d+2) = " + bound(-2 / (d + 2)) +
                                " for dimension = " + std::to_string(dimension) + " (Var c² >= 0), got " + bound(a[0]));
  if (var_y < 0)
    throw std::invalid_argument("a02: must be >= -2/(d_r+2) = " + bound(-2 / (d_r + 2)) +
                                " for dimension = " + std::to_string(dimension) + " (Var w² >= 0), got " + bound(a[1]));
  const double limit = std::sqrt(var_x * var_y) / (d * d_r / 4);
  if (std::abs(a[2]) > limit)
    throw std::invalid_argument("a11: must be in [-" + bound(limit) + ", " + bound(limit) +
                                "] at these a20, a02 (Cauchy-Schwarz: Cov(c², w²)² <= Var c² Var w²), got " +
                                bound(a[2]));
}

RoughEvolutionResult evolve_rough_cooling(const RoughCoolingRates& rates, bool linear, double translational0,
                                          double rotational0, const std::vector<double>& times, double rtol,
                                          double atol, const RoughCumulants& initial_cumulants, long max_steps) {
  check_rough_initial_cumulants(rates.dimension(), initial_cumulants);
  if (!linear && initial_cumulants != RoughCumulants{})
    throw std::invalid_argument(
        "a20, a02, a11: the Maxwellian scheme carries no cumulants: use hcs = \"linear\" or leave them 0");
  Problem problem;
  problem.rates = &rates;
  problem.linear = linear;
  problem.initial = initial_cumulants;
  problem.base = rates.maxwellian_fourth_moments();
  return integrate(problem, rates.dimension(), translational0, rotational0, times, rtol, atol, max_steps);
}

RoughEvolutionResult evolve_rough_oriented_cooling(const RoughCoolingRates& rates,
                                                   const RoughOrientedCoolingRates& oriented, double translational0,
                                                   double rotational0, const std::vector<double>& times, double rtol,
                                                   double atol, const RoughCumulants& initial_cumulants,
                                                   long max_steps) {
  if (rates.dimension() != 3)
    throw std::invalid_argument("dimension: the orientation term needs spheres (dimension = 3)");
  if (rates.kappa() != oriented.kappa())
    throw std::invalid_argument("moment_of_inertia: the two rate tables are for different kappa");
  check_rough_initial_cumulants(3, initial_cumulants);
  Problem problem;
  problem.rates = &rates;
  problem.oriented = &oriented;
  problem.linear = true;
  problem.initial = initial_cumulants;
  problem.base = rates.maxwellian_fourth_moments();
  return integrate(problem, 3, translational0, rotational0, times, rtol, atol, max_steps);
}

RoughEvolutionResult evolve_rough_sonine_cooling(const RoughSonineCoolingRates& rates, double translational0,
                                                 double rotational0, const std::vector<double>& times, double rtol,
                                                 double atol, const RoughCumulants& initial_cumulants, long max_steps) {
  check_rough_initial_cumulants(rates.dimension(), initial_cumulants);
  detail::check_max_steps(max_steps);
  if (rates.spin_decoupled() && (initial_cumulants[1] != 0 || initial_cumulants[2] != 0))
    throw std::invalid_argument("a02, a11: at beta = -1 the spin decouples and carries no cumulant: leave them 0");
  Problem problem;
  problem.sonine = &rates;
  problem.linear = true;
  const std::size_t k = rates.unknowns();
  Eigen::MatrixXd pm(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k));
  for (std::size_t t = 0; t < k; ++t)
    for (std::size_t w = 0; w < k; ++w)
      pm(static_cast<Eigen::Index>(t), static_cast<Eigen::Index>(w)) = rates.projections()[t][w];
  problem.projection.compute(pm);
  problem.sonine_initial.assign(k, 0.0);  // the higher cumulants and every b_pq start at 0
  for (std::size_t w = 0; w < rates.cumulant_indices().size(); ++w) {
    const auto pq = rates.cumulant_indices()[w];
    if (pq == std::array<int, 2>{2, 0}) problem.sonine_initial[w] = initial_cumulants[0];
    if (pq == std::array<int, 2>{0, 2}) problem.sonine_initial[w] = initial_cumulants[1];
    if (pq == std::array<int, 2>{1, 1}) problem.sonine_initial[w] = initial_cumulants[2];
  }
  return integrate(problem, rates.dimension(), translational0, rotational0, times, rtol, atol, max_steps);
}

RoughEvolutionResult evolve_rough_linear_cooling(int dimension, const RoughLinearProductions& productions,
                                                 double translational0, double rotational0,
                                                 const std::vector<double>& times, double rtol, double atol,
                                                 const RoughCumulants& initial_cumulants, long max_steps) {
  check_rough_initial_cumulants(dimension, initial_cumulants);
  Problem problem;
  problem.productions = &productions;
  problem.dimension = dimension;
  problem.linear = true;
  problem.initial = initial_cumulants;
  const double dt = dimension, dr = dimension == 3 ? 3 : 1;
  problem.base = {dt / 2 * (dt / 2 + 1), dr / 2 * (dr / 2 + 1), dt / 2 * dr / 2};
  return integrate(problem, dimension, translational0, rotational0, times, rtol, atol, max_steps);
}

RoughEvolutionResult evolve_rough_maxwellian_cooling(int dimension, const RoughMaxwellianRates& rates,
                                                     double translational0, double rotational0,
                                                     const std::vector<double>& times, double rtol, double atol,
                                                     long max_steps) {
  if (dimension != 2 && dimension != 3) throw std::invalid_argument("dimension: must be 2 or 3");
  Problem problem;
  problem.maxwellian = &rates;
  return integrate(problem, dimension, translational0, rotational0, times, rtol, atol, max_steps);
}

}  // namespace gkt
