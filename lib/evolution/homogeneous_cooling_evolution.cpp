#include "gkt/evolution/homogeneous_cooling_evolution.hpp"
#include "gkt/operators/viscoelastic_hierarchy.hpp"

#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

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

/// State y = (θ = T/T0, C, a_2 … a_K); rates (theory.md (12.1)). The hierarchy is fixed (constant
/// α) or re-evaluated at δ'(θ) (viscoelastic).
struct Problem {
  const CumulantHierarchy* h = nullptr;
  const ViscoelasticHierarchy* viscoelastic = nullptr;
  double delta = 0;
  mutable std::optional<CumulantHierarchy> current;
  int k_max = 0;
  double zeta_factor = 0;  // 4/(d+2) · (d+2)/(2d) = 2/d: dθ/dτ = (2/d) R_1 θ^{3/2}
  double chi = 1;          // Enskog: every collision rate is χ times the dilute one (theory.md (15.1))
  mutable std::vector<double> a, f, jac, grad_e, grad_c;

  /// The hierarchy at the state's temperature.
  const CumulantHierarchy& at(double theta) const {
    if (viscoelastic == nullptr) return *h;
    const double delta_prime = delta * std::pow(2.0 * theta, 0.1);
    if (current)
      viscoelastic->refresh(delta_prime, *current);  // in place after the first call
    else
      current.emplace(viscoelastic->at(delta_prime));
    return *current;
  }
  void unpack(const double* y) const {
    a.assign(static_cast<std::size_t>(k_max) + 1, 0.0);
    a[0] = 1.0;
    for (int k = 2; k <= k_max; ++k) a[k] = y[k];
  }
};

int rates(sunrealtype, N_Vector y, N_Vector ydot, void* data) {
  const auto& p = *static_cast<const Problem*>(data);
  const double* yv = N_VGetArrayPointer(y);
  double* dv = N_VGetArrayPointer(ydot);
  const double theta = yv[0];
  if (!(theta > 0)) return 1;  // recoverable: CVODE retries with a smaller step
  p.unpack(yv);
  const double sq = p.chi * std::sqrt(theta);
  const CumulantHierarchy& h = p.at(theta);
  dv[0] = p.zeta_factor * h.energy_moment(p.a) * theta * sq;
  dv[1] = sq * h.collision_rate(p.a);
  h.residual(p.a, p.f, nullptr);
  for (int k = 2; k <= p.k_max; ++k) dv[k] = sq * p.f[static_cast<std::size_t>(k - 2)] / h.norm(k);
  return 0;
}

int jacobian(sunrealtype, N_Vector y, N_Vector, SUNMatrix jm, void* data, N_Vector, N_Vector, N_Vector) {
  const auto& p = *static_cast<const Problem*>(data);
  const double* yv = N_VGetArrayPointer(y);
  const double theta = yv[0];
  if (!(theta > 0)) return 1;
  p.unpack(yv);
  const int n = p.k_max + 1, unknowns = p.k_max - 1;
  const double root = std::sqrt(theta), sq = p.chi * root;
  p.jac.assign(static_cast<std::size_t>(unknowns) * unknowns, 0.0);
  p.h->residual(p.a, p.f, &p.jac);
  p.h->gradients(p.a, p.grad_e, p.grad_c);
  const double r1 = p.h->energy_moment(p.a), rate = p.h->collision_rate(p.a);
  SUNMatZero(jm);
  SM_ELEMENT_D(jm, 0, 0) = 1.5 * p.zeta_factor * r1 * sq;
  SM_ELEMENT_D(jm, 1, 0) = p.chi * 0.5 * rate / root;
  for (int k = 2; k < n; ++k) {
    SM_ELEMENT_D(jm, 0, k) = p.zeta_factor * p.grad_e[k] * theta * sq;
    SM_ELEMENT_D(jm, 1, k) = sq * p.grad_c[k];
    SM_ELEMENT_D(jm, k, 0) = p.chi * 0.5 * p.f[static_cast<std::size_t>(k - 2)] / (root * p.h->norm(k));
    for (int q = 2; q < n; ++q)
      SM_ELEMENT_D(jm, k, q) = sq * p.jac[static_cast<std::size_t>(k - 2) * unknowns + (q - 2)] / p.h->norm(k);
  }
  return 0;
}

EvolutionResult integrate(Problem& problem, int dimension, double temperature0, const std::vector<double>& initial_a,
                          const std::vector<double>& times, double rtol, double atol, bool analytic_jacobian,
                          long max_steps) {
  if (!(temperature0 > 0)) throw std::invalid_argument("temperature: must be > 0");
  detail::check_max_steps(max_steps);
  if (!(rtol > 0) || !(atol > 0)) throw std::invalid_argument("rtol, atol: must be > 0");
  for (std::size_t i = 0; i < times.size(); ++i)
    if (!(times[i] > 0) || (i > 0 && !(times[i] > times[i - 1])))
      throw std::invalid_argument("times: must be positive and increasing");
  const int k_max = problem.k_max, n = k_max + 1;

  SUNContext raw_context = nullptr;
  check(SUNContext_Create(nullptr, &raw_context), "SUNContext_Create");
  const std::unique_ptr<std::remove_pointer_t<SUNContext>, ContextDeleter> context(raw_context);
  const std::unique_ptr<std::remove_pointer_t<N_Vector>, VectorDeleter> y(N_VNew_Serial(n, raw_context));
  double* yv = N_VGetArrayPointer(y.get());
  yv[0] = temperature0;
  yv[1] = 0.0;
  for (int k = 2; k <= k_max; ++k)
    yv[k] = static_cast<std::size_t>(k - 2) < initial_a.size() ? initial_a[static_cast<std::size_t>(k - 2)] : 0.0;

  const std::unique_ptr<void, CvodeDeleter> cvode(CVodeCreate(CV_BDF, raw_context));
  if (!cvode) throw std::runtime_error("CVODE: CVodeCreate failed");
  std::string cvode_message;
  check(CVodeSetErrHandlerFn(cvode.get(), keep_message, &cvode_message), "CVodeSetErrHandlerFn");
  check(CVodeInit(cvode.get(), rates, 0.0, y.get()), "CVodeInit");
  check(CVodeSStolerances(cvode.get(), rtol, atol), "CVodeSStolerances");
  check(CVodeSetUserData(cvode.get(), &problem), "CVodeSetUserData");
  const std::unique_ptr<std::remove_pointer_t<SUNMatrix>, MatrixDeleter> matrix(SUNDenseMatrix(n, n, raw_context));
  const std::unique_ptr<std::remove_pointer_t<SUNLinearSolver>, SolverDeleter> solver(
      SUNLinSol_Dense(y.get(), matrix.get(), raw_context));
  check(CVodeSetLinearSolver(cvode.get(), solver.get(), matrix.get()), "CVodeSetLinearSolver");
  if (analytic_jacobian) check(CVodeSetJacFn(cvode.get(), jacobian), "CVodeSetJacFn");

  EvolutionResult result;
  for (double target : times) {
    const double reached = detail::advance_within_budget(
        cvode.get(), target, y.get(), cvode_message, "integrate to an earlier time or use a smaller atol", max_steps);
    EvolutionSample s;
    s.time = reached;
    s.temperature = yv[0];
    s.collisions = yv[1];
    problem.unpack(yv);
    s.a = problem.a;
    s.cooling_rate =
        -problem.chi * (dimension + 2) * problem.at(yv[0] / temperature0).energy_moment(s.a) / (2.0 * dimension);
    result.samples.push_back(std::move(s));
  }
  result.counters = detail::read_counters(cvode.get());
  return result;
}

}  // namespace

bool EvolutionFailure::tolerances() const { return flag_ == CV_TOO_MUCH_ACC; }

EvolutionResult evolve_homogeneous_cooling(const CumulantHierarchy& hierarchy, double temperature0,
                                           const std::vector<double>& initial_a, const std::vector<double>& times,
                                           double rtol, double atol, double chi, long max_steps) {
  if (!(chi >= 1) || !std::isfinite(chi))
    throw std::invalid_argument("packing_fraction: the contact value chi must be finite and >= 1, got " +
                                std::to_string(chi));
  Problem problem;
  problem.chi = chi;
  problem.h = &hierarchy;
  problem.k_max = hierarchy.k_max();
  problem.zeta_factor = 2.0 / hierarchy.dimension();
  return integrate(problem, hierarchy.dimension(), temperature0, initial_a, times, rtol, atol, true, max_steps);
}

EvolutionResult evolve_viscoelastic_cooling(const ViscoelasticHierarchy& hierarchy, double delta,
                                            const std::vector<double>& initial_a, const std::vector<double>& times,
                                            double rtol, double atol, long max_steps) {
  if (!(delta >= 0)) throw std::invalid_argument("delta: must be >= 0");
  Problem problem;
  problem.viscoelastic = &hierarchy;
  problem.delta = delta;
  problem.k_max = hierarchy.k_max();
  problem.zeta_factor = 2.0 / 3;
  return integrate(problem, 3, 1.0, initial_a, times, rtol, atol, false, max_steps);
}

}  // namespace gkt
