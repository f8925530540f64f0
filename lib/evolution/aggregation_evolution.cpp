#include "gkt/evolution/aggregation_evolution.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunlinsol/sunlinsol_spgmr.h>
#include <sunmatrix/sunmatrix_dense.h>

#include "evolution/cvode_support.hpp"

namespace gkt {

namespace {

using detail::check;
using detail::ContextDeleter;
using detail::CvodeDeleter;
using detail::MatrixDeleter;
using detail::SolverDeleter;
using detail::VectorDeleter;

constexpr int kDenseLimit = 64;  // dense direct solver up to K = 64, Krylov (SPGMR) above

/// Where a merger of pivots a ≤ b lands: a share `fraction` at pivot `lower`, the rest at lower + 1
/// (fixed pivot, theory.md (20.15)); lower = −1: beyond the last pivot, the pair rebounds.
struct Target {
  int lower = -1;
  double fraction = 1;
};

/// y = (n_1 … n_K, E) with E = (d/2) θ Σ n_k the granular energy density (theory.md (20.12)).
struct Problem {
  AggregationGas gas;
  std::vector<double> pivots;
  std::vector<Target> targets;                // K × K, entries a ≤ b used
  mutable double events = 0, collisions = 0;  // totals of the last right-hand side

  void place_mergers() {
    const auto K = pivots.size();
    targets.assign(K * K, Target{});
    for (std::size_t a = 0; a < K; ++a)
      for (std::size_t b = a; b < K; ++b) {
        const double v = pivots[a] + pivots[b];
        const auto above = std::upper_bound(pivots.begin(), pivots.end(), v);
        const auto lower = static_cast<std::size_t>(above - pivots.begin()) - 1;  // x_lower ≤ v
        Target& t = targets[a * K + b];
        if (pivots[lower] == v) {
          t = {static_cast<int>(lower), 1.0};
        } else if (above != pivots.end()) {
          t = {static_cast<int>(lower), (pivots[lower + 1] - v) / (pivots[lower + 1] - pivots[lower])};
        }
      }
  }
};

/// The right-hand side: Smoluchowski's birth and death terms (theory.md (20.12), (20.15)) over
/// unordered pairs a ≤ b, each event conserving number and mass, and the energy sink (20.13).
void balance(const Problem& p, const double* y, double* dy) {
  const auto K = p.pivots.size();
  double number = 0;
  for (std::size_t k = 0; k < K; ++k) {
    number += y[k];
    dy[k] = 0;
  }
  const double d = p.gas.dimension;
  const double theta = 2 * y[K] / (d * number);
  double loss = 0, events = 0, collisions = 0;
  for (std::size_t a = 0; a < K; ++a) {
    const double na = y[a];
    for (std::size_t b = a; b < K; ++b) {
      const double pair = (a == b ? 0.5 : 1.0) * na * y[b];
      const Target& t = p.targets[a * K + b];
      const bool may_stick = t.lower >= 0;
      const PairRates r = pair_rates(p.gas, p.pivots[a], p.pivots[b], theta, may_stick);
      loss += pair * r.energy_loss;
      collisions += pair * r.collisions;
      if (!may_stick || r.aggregation == 0) continue;
      const double rate = pair * r.aggregation;
      events += rate;
      const auto lower = static_cast<std::size_t>(t.lower);
      dy[lower] += rate * t.fraction;
      if (t.fraction < 1) dy[lower + 1] += rate * (1 - t.fraction);
      dy[a] -= rate;
      dy[b] -= rate;
    }
  }
  dy[K] = -loss;
  p.events = events;
  p.collisions = collisions;
}

int rates(sunrealtype, N_Vector y, N_Vector ydot, void* data) {
  const auto& p = *static_cast<const Problem*>(data);
  const double* yv = N_VGetArrayPointer(y);
  if (!(yv[p.pivots.size()] > 0)) return 1;  // recoverable: CVODE retries with a smaller step
  balance(p, yv, N_VGetArrayPointer(ydot));
  return 0;
}

void keep_message(int error_code, const char*, const char*, char* message, void* data) {
  if (error_code >= 0) return;
  std::string& kept = *static_cast<std::string*>(data);
  kept = message;
  for (char& c : kept)
    if (c == '\n' || c == '\r') c = ' ';
}

}  // namespace

std::vector<double> geometric_pivots(double ratio, double largest) {
  if (!(ratio > 1 && ratio <= 2)) throw std::invalid_argument("grid_ratio: must be a number in (1, 2]");
  if (!(largest >= 2) || !std::isfinite(largest)) throw std::invalid_argument("sizes: must be a number >= 2");
  std::vector<double> x{1.0};
  while (x.back() < largest) x.push_back(std::max(x.back() + 1, ratio * x.back()));
  return x;
}

AggregationResult evolve_aggregation(const AggregationGas& gas, int sizes, const std::vector<double>& times,
                                     double rtol, double atol, bool keep_distribution, long max_steps) {
  if (sizes < 2) throw std::invalid_argument("sizes: must be an integer >= 2, got " + std::to_string(sizes));
  std::vector<double> pivots(static_cast<std::size_t>(sizes));
  for (int k = 0; k < sizes; ++k) pivots[static_cast<std::size_t>(k)] = k + 1;
  return evolve_aggregation(gas, pivots, times, rtol, atol, keep_distribution, max_steps);
}

AggregationResult evolve_aggregation(const AggregationGas& gas, const std::vector<double>& pivots,
                                     const std::vector<double>& times, double rtol, double atol, bool keep_distribution,
                                     long max_steps) {
  validate(gas);
  detail::check_max_steps(max_steps);
  if (pivots.size() < 2 || pivots.front() != 1)
    throw std::invalid_argument("sizes: the grid needs at least two pivots, the first at 1");
  for (std::size_t k = 1; k < pivots.size(); ++k)
    if (!(pivots[k] >= pivots[k - 1] + 1))
      throw std::invalid_argument("sizes: pivots must increase by at least one monomer");
  const int sizes = static_cast<int>(pivots.size());
  if (!(rtol > 0) || !(atol > 0)) throw std::invalid_argument("rtol, atol: must be > 0");
  if (times.empty()) throw std::invalid_argument("times: must be a non-empty list of increasing times > 0");
  for (std::size_t i = 0; i < times.size(); ++i)
    if (!(times[i] > 0) || (i > 0 && !(times[i] > times[i - 1])))
      throw std::invalid_argument("times: must be positive and increasing");
  Problem problem;
  problem.gas = gas;
  problem.pivots = pivots;
  problem.place_mergers();
  const int n = sizes + 1;

  SUNContext raw_context = nullptr;
  check(SUNContext_Create(nullptr, &raw_context), "SUNContext_Create");
  const std::unique_ptr<std::remove_pointer_t<SUNContext>, ContextDeleter> context(raw_context);
  const std::unique_ptr<std::remove_pointer_t<N_Vector>, VectorDeleter> y(N_VNew_Serial(n, raw_context));
  double* yv = N_VGetArrayPointer(y.get());
  for (int k = 0; k < sizes; ++k) yv[k] = 0;
  yv[0] = 1;                        // monomers, n_1(0) = 1
  yv[sizes] = 0.5 * gas.dimension;  // E(0) = (d/2) θ0 n_1(0)

  const std::unique_ptr<void, CvodeDeleter> cvode(CVodeCreate(CV_BDF, raw_context));
  if (!cvode) throw std::runtime_error("CVODE: CVodeCreate failed");
  std::string cvode_message;
  check(CVodeSetErrHandlerFn(cvode.get(), keep_message, &cvode_message), "CVodeSetErrHandlerFn");
  check(CVodeInit(cvode.get(), rates, 0.0, y.get()), "CVodeInit");
  check(CVodeSStolerances(cvode.get(), rtol, atol), "CVodeSStolerances");
  check(CVodeSetUserData(cvode.get(), &problem), "CVodeSetUserData");
  std::unique_ptr<std::remove_pointer_t<SUNMatrix>, MatrixDeleter> matrix;
  std::unique_ptr<std::remove_pointer_t<SUNLinearSolver>, SolverDeleter> solver;
  AggregationResult result;
  if (sizes <= kDenseLimit) {
    matrix.reset(SUNDenseMatrix(n, n, raw_context));
    solver.reset(SUNLinSol_Dense(y.get(), matrix.get(), raw_context));
    result.linear_solver = "dense";
  } else {
    solver.reset(SUNLinSol_SPGMR(y.get(), SUN_PREC_NONE, 0, raw_context));
    result.linear_solver = "spgmr";
  }
  check(CVodeSetLinearSolver(cvode.get(), solver.get(), matrix.get()), "CVodeSetLinearSolver");

  for (double target : times) {
    const double reached = detail::advance_within_budget(
        cvode.get(), target, y.get(), cvode_message, "integrate to an earlier time or use a smaller atol", max_steps);
    AggregationSample s;
    s.time = reached;
    double number = 0, mass = 0;
    for (int k = 0; k < sizes; ++k) {
      number += yv[k];
      mass += pivots[static_cast<std::size_t>(k)] * yv[k];
    }
    s.number_density = number;
    s.mass = mass;
    s.mean_size = mass / number;
    s.temperature = 2 * yv[sizes] / (gas.dimension * number);
    std::vector<double> scratch(static_cast<std::size_t>(n));
    balance(problem, yv, scratch.data());
    s.success_factor = problem.collisions > 0 ? problem.events / problem.collisions : 0.0;
    if (keep_distribution) s.distribution.assign(yv, yv + sizes);
    result.samples.push_back(std::move(s));
  }
  result.counters = detail::read_counters(cvode.get());
  return result;
}

}  // namespace gkt
