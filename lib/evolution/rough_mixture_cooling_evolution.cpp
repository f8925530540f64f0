#include "gkt/evolution/rough_mixture_cooling_evolution.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
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
using detail::keep_message;
using detail::MatrixDeleter;
using detail::SolverDeleter;
using detail::VectorDeleter;

/// The Maxwellian energy balance of the binary, tabulated once: the exact pair coefficients of (19.54) and the
/// factors of (19.55) that do not depend on the temperatures. Slots k = (T_t,1, T_t,2, T_r,1, T_r,2).
struct Balance {
  int dimension = 3;
  std::array<double, 2> fraction{}, inverse_mass{};  // x_i, m̄/m_i
  /// [i][j]: the rows (translational, rotational of the particle of species i) of dT/dt per unit of
  /// √(γ_i m̄/m_i + γ_j m̄/m_j), over the four global slots: (2/f) Λ x_j (σ_ij/σ̄)^{d−1} coefficient.
  std::array<std::array<std::array<std::array<double, 4>, 2>, 2>, 2> row{};

  explicit Balance(const RoughBinaryMixture& m) : dimension(m.dimension) {
    const int d = m.dimension;
    const double lambda = (d + 2) * std::sqrt(2.0) / 8.0;  // Λ of theory.md (16.4)
    double mean_mass = 0, mean_diameter = 0;
    for (const auto& s : m.species) {
      mean_mass += s.fraction * s.mass.to_double();
      mean_diameter += s.fraction * s.diameter;
    }
    for (std::size_t i = 0; i < 2; ++i) {
      fraction[i] = m.species[i].fraction;
      inverse_mass[i] = mean_mass / m.species[i].mass.to_double();
    }
    for (std::size_t i = 0; i < 2; ++i)
      for (std::size_t j = 0; j < 2; ++j) {
        const RoughPairEnergyChanges c =
            rough_pair_energy_changes(d, m.alpha[i + j], m.beta[i + j], m.species[i], m.species[j]);
        const double sigma = 0.5 * (m.species[i].diameter + m.species[j].diameter) / mean_diameter;
        const double weight = m.species[j].fraction * std::pow(sigma, d - 1) * lambda;
        // The table's slots (i, j, r_i, r_j) in the global order (theory.md §19.17).
        const std::array<std::size_t, 4> global{i, j, 2 + i, 2 + j};
        for (std::size_t r = 0; r < 2; ++r) {
          const double freedom = r == 0 ? d : (d == 3 ? 3 : 1);
          for (std::size_t col = 0; col < 4; ++col)
            row[i][j][r][global[col]] += (2.0 / freedom) * weight * c.coefficient[2 * r][col].to_double();
        }
      }
  }

  /// Returns dT_k/dt in units of ν0(T) (T = Σx_i T_t,i) at the temperatures `t` (theory.md (19.55)).
  [[nodiscard]] std::array<double, 4> change(const std::array<double, 4>& t) const {
    const double mix = fraction[0] * t[0] + fraction[1] * t[1];
    std::array<double, 4> out{};
    for (std::size_t i = 0; i < 2; ++i)
      for (std::size_t j = 0; j < 2; ++j) {
        const double speed = std::sqrt((t[i] * inverse_mass[i] + t[j] * inverse_mass[j]) / mix);
        for (std::size_t r = 0; r < 2; ++r) {
          double sum = 0;
          for (std::size_t c = 0; c < 4; ++c) sum += row[i][j][r][c] * t[c];
          out[2 * r + i] += speed * sum;
        }
      }
    return out;
  }

  /// Returns ζ* = −(dT/dt)/(ν0(T) T) of the mixture temperature T = Σx_i T_t,i.
  [[nodiscard]] double cooling_rate(const std::array<double, 4>& t) const {
    const auto c = change(t);
    return -(fraction[0] * c[0] + fraction[1] * c[1]) / (fraction[0] * t[0] + fraction[1] * t[1]);
  }
};

/// State y = (ln T_t,1, ln T_t,2, ln T_r,1, ln T_r,2) in units of T_ref: d ln T_k/dτ = √(T/T_ref) (dT_k/dt)/(ν0(T) T_k)
/// (ν0 ∝ √T; theory.md (19.180)).
int right_hand_side(sunrealtype, N_Vector y, N_Vector ydot, void* data) {
  const auto& b = *static_cast<const Balance*>(data);
  const double* yv = N_VGetArrayPointer(y);
  double* dv = N_VGetArrayPointer(ydot);
  std::array<double, 4> t{};
  for (std::size_t k = 0; k < 4; ++k) {
    t[k] = std::exp(yv[k]);
    if (!(t[k] > 0) || !std::isfinite(t[k])) return 1;  // recoverable: a smaller step
  }
  const double mix = b.fraction[0] * t[0] + b.fraction[1] * t[1];
  const auto c = b.change(t);
  for (std::size_t k = 0; k < 4; ++k) dv[k] = std::sqrt(mix) * c[k] / t[k];
  return 0;
}

std::string shortest(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", v);
  return buffer;
}

}  // namespace

RoughMixtureEvolutionResult evolve_rough_mixture_cooling(const RoughBinaryMixture& mixture,
                                                         const std::array<double, 4>& initial,
                                                         const std::vector<double>& times, double rtol, double atol,
                                                         long max_steps) {
  mixture.validate();
  const std::array<const char*, 4> names{"translational_temperature_1", "translational_temperature_2",
                                         "rotational_temperature_1", "rotational_temperature_2"};
  for (std::size_t k = 0; k < 4; ++k)
    if (!(initial[k] > 0) || !std::isfinite(initial[k]))
      throw std::invalid_argument(std::string(names[k]) + ": must be a finite number > 0, got " + shortest(initial[k]));
  if (!(rtol > 0) || !(atol > 0)) throw std::invalid_argument("rtol, atol: must be > 0");
  detail::check_max_steps(max_steps);
  for (std::size_t i = 0; i < times.size(); ++i)
    if (!(times[i] > 0) || (i > 0 && !(times[i] > times[i - 1])))
      throw std::invalid_argument("times: must be positive and increasing");
  // A species whose spin is decoupled but heats a tracer partner has no HCS (theory.md §19.26): refused as the
  // steady solver refuses it (its T_t,j/T grows without bound).
  (void)rough_mixture_cooling_state(mixture);

  const Balance balance(mixture);
  constexpr sunindextype n = 4;
  SUNContext raw_context = nullptr;
  check(SUNContext_Create(nullptr, &raw_context), "SUNContext_Create");
  const std::unique_ptr<std::remove_pointer_t<SUNContext>, ContextDeleter> context(raw_context);
  const std::unique_ptr<std::remove_pointer_t<N_Vector>, VectorDeleter> y(N_VNew_Serial(n, raw_context));
  double* yv = N_VGetArrayPointer(y.get());
  for (std::size_t k = 0; k < 4; ++k) yv[k] = std::log(initial[k]);

  const std::unique_ptr<void, CvodeDeleter> cvode(CVodeCreate(CV_BDF, raw_context));
  if (!cvode) throw std::runtime_error("CVODE: CVodeCreate failed");
  std::string cvode_message;
  check(CVodeSetErrHandlerFn(cvode.get(), keep_message, &cvode_message), "CVodeSetErrHandlerFn");
  check(CVodeInit(cvode.get(), right_hand_side, 0.0, y.get()), "CVodeInit");
  check(CVodeSStolerances(cvode.get(), rtol, atol), "CVodeSStolerances");
  check(CVodeSetUserData(cvode.get(), const_cast<Balance*>(&balance)), "CVodeSetUserData");
  const std::unique_ptr<std::remove_pointer_t<SUNMatrix>, MatrixDeleter> matrix(SUNDenseMatrix(n, n, raw_context));
  const std::unique_ptr<std::remove_pointer_t<SUNLinearSolver>, SolverDeleter> solver(
      SUNLinSol_Dense(y.get(), matrix.get(), raw_context));
  check(CVodeSetLinearSolver(cvode.get(), solver.get(), matrix.get()), "CVodeSetLinearSolver");

  RoughMixtureEvolutionResult result;
  for (const double target : times) {
    // A budget over the whole trajectory (as every evolve path, docs/conventions.md).
    const double reached = detail::advance_within_budget(cvode.get(), target, y.get(), cvode_message,
                                                         "integrate to an earlier time", max_steps);
    RoughMixtureEvolutionSample s;
    s.time = reached;
    std::array<double, 4> t{};
    for (std::size_t k = 0; k < 4; ++k) t[k] = std::exp(yv[k]);
    s.translational_temperature = {t[0], t[1]};
    s.rotational_temperature = {t[2], t[3]};
    s.temperature = balance.fraction[0] * t[0] + balance.fraction[1] * t[1];
    if (!(s.temperature > 0) || !std::isfinite(s.temperature))
      throw EvolutionFailure("times: the temperature left the range of a double", -1, reached);
    s.cooling_rate = balance.cooling_rate(t);
    result.samples.push_back(s);
  }
  result.counters = detail::read_counters(cvode.get());
  return result;
}

}  // namespace gkt
