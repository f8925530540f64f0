#include "gkt/evolution/mixture_cooling_evolution.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
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
using detail::MatrixDeleter;
using detail::SolverDeleter;
using detail::VectorDeleter;

/// State y = (ln(T_i/T(0)) for every species, then a_2,i … a_K,i species by species); rates of
/// theory.md (16.12): d ln T_i/dτ = −√(T/T(0)) ζ_i*, da_k,i/dτ = √(T/T(0)) ȧ_k,i (ν0 ∝ √T).
struct Problem {
  const Mixture* mixture = nullptr;
  const MixtureCoolingDynamics* dynamics = nullptr;
  int k_max = 2;
  std::size_t species = 0, per_species = 0;  // cumulants carried per species (K − 1, or 0)
  mutable std::vector<double> gamma;
  mutable std::vector<std::vector<double>> cumulants;
  mutable double temperature = 1;  // T/T(0)

  /// Reads γ_i, T/T(0) and the a_k,i from y; false if a temperature is not a positive finite number.
  bool unpack(const double* y) const {
    temperature = 0;
    gamma.assign(species, 0.0);
    for (std::size_t i = 0; i < species; ++i) {
      gamma[i] = std::exp(y[i]);
      temperature += mixture->species[i].fraction * gamma[i];
    }
    if (!(temperature > 0) || !std::isfinite(temperature)) return false;
    for (double& g : gamma) g /= temperature;
    cumulants.assign(species, std::vector<double>(static_cast<std::size_t>(k_max) + 1, 0.0));
    for (std::size_t i = 0; i < species; ++i) {
      cumulants[i][0] = 1;
      for (std::size_t k = 0; k < per_species; ++k) cumulants[i][k + 2] = y[species + i * per_species + k];
    }
    return true;
  }
};

int rates(sunrealtype, N_Vector y, N_Vector ydot, void* data) {
  const auto& p = *static_cast<const Problem*>(data);
  const double* yv = N_VGetArrayPointer(y);
  double* dv = N_VGetArrayPointer(ydot);
  if (!p.unpack(yv)) return 1;  // recoverable: CVODE retries with a smaller step
  MixtureCoolingRates r;
  try {
    r = p.dynamics->rates(p.gamma, p.cumulants);
  } catch (const std::invalid_argument&) {
    return 1;  // a trial state out of range (e.g. γ_i not finite): a smaller step
  }
  const double clock = std::sqrt(p.temperature);
  for (std::size_t i = 0; i < p.species; ++i) {
    dv[i] = -clock * r.cooling_rate[i];
    for (std::size_t k = 0; k < p.per_species; ++k)
      dv[p.species + i * p.per_species + k] = clock * r.cumulant_rate[i][k + 2];
  }
  return 0;
}

/// CVODE's error handler: keeps the last error message (one line) instead of printing it.
void keep_message(int error_code, const char*, const char*, char* message, void* data) {
  if (error_code >= 0) return;
  std::string& kept = *static_cast<std::string*>(data);
  kept = message;
  kept.erase(0, kept.find_first_not_of(" \n"));
  for (char& c : kept)
    if (c == '\n' || c == '\r') c = ' ';
  while (!kept.empty() && (kept.back() == ' ' || kept.back() == '.')) kept.pop_back();
}

}  // namespace

MixtureEvolutionResult evolve_mixture_cooling(const Mixture& mixture, MixtureHcsScheme scheme, int hcs_order,
                                              std::span<const double> initial_temperature_ratio,
                                              const std::vector<std::vector<double>>& initial_cumulants,
                                              const std::vector<double>& times, double rtol, double atol,
                                              long max_steps) {
  mixture.validate();
  detail::check_max_steps(max_steps);
  const std::size_t s = mixture.size();
  const bool maxwellian = scheme == MixtureHcsScheme::maxwellian;
  if (hcs_order < 2 || hcs_order > 6)
    throw std::invalid_argument("hcs_order: must be an integer in [2, 6], got " + std::to_string(hcs_order));
  if (initial_temperature_ratio.size() != s)
    throw std::invalid_argument("temperature_ratio: one initial ratio per species (" + std::to_string(s) + ")");
  double norm = 0;
  for (std::size_t i = 0; i < s; ++i) {
    const double g = initial_temperature_ratio[i];
    if (!(g > 0) || !std::isfinite(g))
      throw std::invalid_argument("temperature_ratio_" + std::to_string(i + 1) + ": must be a number > 0, got " +
                                  std::to_string(g));
    norm += mixture.species[i].fraction * g;
  }
  if (!(std::abs(norm - 1) <= 1e-12))
    throw std::invalid_argument("temperature_ratio_i: the initial ratios T_i/T must satisfy sum_i x_i T_i/T = 1, got " +
                                std::to_string(norm));
  const auto per_species = maxwellian ? std::size_t{0} : static_cast<std::size_t>(hcs_order - 1);
  if (!initial_cumulants.empty()) {
    if (maxwellian) throw std::invalid_argument("a2_species_i: the Maxwellian scheme carries no cumulants");
    if (initial_cumulants.size() != s)
      throw std::invalid_argument("a2_species_i: one list of initial cumulants per species");
    for (const auto& c : initial_cumulants)
      if (c.size() > per_species)
        throw std::invalid_argument("a2_species_i: at most a_2 … a_" + std::to_string(hcs_order) + " per species");
  }
  if (!(rtol > 0) || !(atol > 0)) throw std::invalid_argument("rtol, atol: must be > 0");
  for (std::size_t i = 0; i < times.size(); ++i)
    if (!(times[i] > 0) || (i > 0 && !(times[i] > times[i - 1])))
      throw std::invalid_argument("times: must be positive and increasing");

  // The pair moments are tabulated once over the width ratios between the start and the HCS (the
  // Maxwellian one, within 8 % of the others' ratios; theory.md §16.3), widened by 0.1 in ln(γ_i/γ_j).
  const MixtureCoolingState rest = mixture_cooling_state(mixture, MixtureHcsScheme::maxwellian);
  std::vector<double> low(s * s), high(s * s);
  for (std::size_t i = 0; i < s; ++i)
    for (std::size_t j = 0; j < s; ++j) {
      const double start = std::log(initial_temperature_ratio[i] / initial_temperature_ratio[j]);
      const double end = std::log(rest.temperature_ratio[i] / rest.temperature_ratio[j]);
      low[i * s + j] = std::min(start, end) - 0.1;
      high[i * s + j] = std::max(start, end) + 0.1;
    }
  const MixtureCoolingDynamics dynamics(mixture, scheme, hcs_order, low, high);
  Problem problem;
  problem.mixture = &mixture;
  problem.dynamics = &dynamics;
  problem.k_max = hcs_order;
  problem.species = s;
  problem.per_species = per_species;
  const auto n = static_cast<sunindextype>(s + s * per_species);

  SUNContext raw_context = nullptr;
  check(SUNContext_Create(nullptr, &raw_context), "SUNContext_Create");
  const std::unique_ptr<std::remove_pointer_t<SUNContext>, ContextDeleter> context(raw_context);
  const std::unique_ptr<std::remove_pointer_t<N_Vector>, VectorDeleter> y(N_VNew_Serial(n, raw_context));
  double* yv = N_VGetArrayPointer(y.get());
  for (std::size_t i = 0; i < s; ++i) {
    yv[i] = std::log(initial_temperature_ratio[i]);  // T_i(0)/T(0)
    for (std::size_t k = 0; k < per_species; ++k)
      yv[s + i * per_species + k] =
          initial_cumulants.empty() || k >= initial_cumulants[i].size() ? 0.0 : initial_cumulants[i][k];
  }

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

  MixtureEvolutionResult result;
  for (double target : times) {
    const double reached = detail::advance_within_budget(
        cvode.get(), target, y.get(), cvode_message, "integrate to an earlier time or use a smaller atol", max_steps);
    if (!problem.unpack(yv)) throw EvolutionFailure("times: the temperature left the range of a double", -1, reached);
    MixtureEvolutionSample sample;
    sample.time = reached;
    sample.temperature = problem.temperature;
    sample.temperature_ratio = problem.gamma;
    sample.cumulants = problem.cumulants;
    sample.cooling_rate = dynamics.rates(problem.gamma, problem.cumulants).mixture_cooling_rate;
    result.samples.push_back(std::move(sample));
  }
  result.counters = detail::read_counters(cvode.get());
  return result;
}

}  // namespace gkt
