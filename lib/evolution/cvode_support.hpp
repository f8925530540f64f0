// Private: RAII owners of the SUNDIALS objects (C API) and the flag check that the CVODE
// integrations of this floor share.
#pragma once

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "gkt/evolution/homogeneous_cooling_evolution.hpp"

namespace gkt::detail {

struct ContextDeleter {
  void operator()(SUNContext c) const { SUNContext_Free(&c); }
};
struct VectorDeleter {
  void operator()(N_Vector v) const { N_VDestroy(v); }
};
struct MatrixDeleter {
  void operator()(SUNMatrix m) const { SUNMatDestroy(m); }
};
struct SolverDeleter {
  void operator()(SUNLinearSolver s) const { SUNLinSolFree(s); }
};
struct CvodeDeleter {
  void operator()(void* mem) const { CVodeFree(&mem); }
};

/// Throws std::runtime_error "CVODE: <what> failed (flag …)" for a negative SUNDIALS flag.
inline void check(int flag, const char* what) {
  if (flag < 0) throw std::runtime_error(std::string("CVODE: ") + what + " failed (flag " + std::to_string(flag) + ")");
}

/// CVODE's error handler: keeps the last error message (one line) instead of printing it.
inline void keep_message(int error_code, const char*, const char*, char* message, void* data) {
  if (error_code >= 0) return;  // warnings: the counters and the result tell the story
  std::string& kept = *static_cast<std::string*>(data);
  kept = message;
  kept.erase(0, kept.find_first_not_of(" \n"));
  for (char& c : kept)
    if (c == '\n' || c == '\r') c = ' ';
  while (!kept.empty() && (kept.back() == ' ' || kept.back() == '.')) kept.pop_back();
}

/// Returns the τ CVODE reached on its way to `target` (CV_NORMAL); throws EvolutionFailure
/// "rtol: …" (too much accuracy asked) or "times: …" with CVODE's kept `message`, adding
/// `times_hint` to the latter (docs/conventions.md, gkt evolve).
inline double advance_to(void* cvode, double target, N_Vector y, const std::string& message,
                         const std::string& times_hint) {
  sunrealtype reached = 0;
  const int flag = CVode(cvode, target, y, &reached, CV_NORMAL);
  if (flag < 0) {
    const std::string what =
        "CVODE: " + (message.empty() ? "CVode failed (flag " + std::to_string(flag) + ")" : message);
    if (flag == CV_TOO_MUCH_ACC) throw EvolutionFailure("rtol: " + what + "; use rtol >= 1e-14", flag, reached);
    throw EvolutionFailure("times: " + what + "; " + times_hint, flag, reached);
  }
  return reached;
}

/// Throws std::invalid_argument "max_steps: …" unless the trajectory's CVODE step budget `max_steps` is ≥ 1.
inline void check_max_steps(long max_steps) {
  if (max_steps < 1) throw std::invalid_argument("max_steps: must be >= 1, got " + std::to_string(max_steps));
}

/// Returns the τ CVODE reached on its way to `target` as advance_to, with at most what is left of a budget of
/// `max_steps` CVODE steps over the whole trajectory (the steps taken so far count against it); when the budget runs
/// out first, throws EvolutionFailure "max_steps: …" (flag CV_TOO_MUCH_WORK) naming the budget, `target` and the τ
/// reached (docs/conventions.md, gkt evolve).
inline double advance_within_budget(void* cvode, double target, N_Vector y, const std::string& message,
                                    const std::string& times_hint, long max_steps) {
  long used = 0;
  CVodeGetNumSteps(cvode, &used);
  check(CVodeSetMaxNumSteps(cvode, std::max(1L, max_steps - used)), "CVodeSetMaxNumSteps");
  try {
    return advance_to(cvode, target, y, message, times_hint);
  } catch (const EvolutionFailure& e) {
    if (e.flag() != CV_TOO_MUCH_WORK) throw;
    auto g = [](double v) {
      char buffer[32];
      std::snprintf(buffer, sizeof buffer, "%.6g", v);
      return std::string(buffer);
    };
    throw EvolutionFailure("max_steps: used its " + std::to_string(max_steps) +
                               " CVODE steps before time = " + g(target) + " (stopped at time = " + g(e.time()) +
                               "); raise max_steps or integrate to an earlier time",
                           e.flag(), e.time());
  }
}

/// Returns CVODE's work counters for `cvode` (steps, right-hand sides, Jacobians, error-test
/// failures, nonlinear iterations).
inline EvolutionCounters read_counters(void* cvode) {
  EvolutionCounters counters;
  long v = 0;
  CVodeGetNumSteps(cvode, &v);
  counters.steps = v;
  CVodeGetNumRhsEvals(cvode, &v);
  counters.rhs_evaluations = v;
  CVodeGetNumJacEvals(cvode, &v);
  counters.jacobian_evaluations = v;
  CVodeGetNumErrTestFails(cvode, &v);
  counters.error_test_failures = v;
  CVodeGetNumNonlinSolvIters(cvode, &v);
  counters.nonlinear_iterations = v;
  return counters;
}

}  // namespace gkt::detail
