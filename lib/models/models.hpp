// Private: the model factories the registry knows, and the rules they share (reading a point
// through the schema, choosing an order).
#pragma once

#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "gkt/evolution/hcs_stability.hpp"
#include "gkt/models/transport_model.hpp"
#include "gkt/transport/common/enskog_state.hpp"
#include "gkt/transport/common/sonine_solution.hpp"
#include "gkt/transport/monodisperse/navier_stokes.hpp"
#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"
#include "support/strings.hpp"

namespace gkt::detail {

std::unique_ptr<TransportModel> make_hard_sphere_model();
std::unique_ptr<TransportModel> make_smooth_inelastic_model();
std::unique_ptr<TransportModel> make_viscoelastic_model();
std::unique_ptr<TransportModel> make_mixture_model();
std::unique_ptr<TransportModel> make_rough_model();
std::unique_ptr<TransportModel> make_aggregation_model();
/// Returns the keys of `gkt evolve` for the aggregation model (aggregation_trajectory.cpp), its
/// output times (t_end, points) and size grid among them.
std::vector<ParameterSpec> aggregation_evolution_parameters();
/// Returns the aggregation trajectory of a validated request (request.times empty: the model sets
/// its times from t_end and points): the moments, or with distribution = true the long format.
Trajectory aggregation_trajectory(const TrajectoryRequest& request);
std::unique_ptr<TransportModel> make_rough_walton_model();
/// Returns the keys of `gkt evolve` for the rough models (rough_trajectory.cpp): the specs `names`
/// of `model_parameters`, the initial temperatures, rtol, atol.
std::vector<ParameterSpec> rough_evolution_parameters(const std::vector<ParameterSpec>& model_parameters,
                                                      const std::vector<std::string>& names);
/// Returns the rough gas's cooling trajectory for a request validated against `schema`
/// (rough_evolution_parameters): the temperatures, θ, ζ* and, with hcs = "linear", a20, a02, a11.
Trajectory rough_trajectory(const std::vector<ParameterSpec>& schema, const TrajectoryRequest& request);

/// Returns the keys a20, a02, a11 of `gkt evolve` for the "rough" model: the initial cumulants of the
/// linear scheme (default 0), bounded here by the union of both dimensions' realizability limits; the
/// exact limits of theory.md (19.24a) are applied per dimension (check_rough_initial_cumulants).
std::vector<ParameterSpec> rough_initial_cumulant_parameters();
/// Returns the key `order` of `gkt evolve` for the "rough" model: the Sonine order N of the linear scheme's
/// trajectory, an integer in [1, 3] (default 1: the first-Sonine trajectory; theory.md §19.13, (19.25b)).
ParameterSpec rough_evolution_order_parameter();
/// Returns the key `max_steps` of `gkt evolve` for the "rough" model: the CVODE step budget of every scheme's
/// trajectory, an integer in [1, 10⁹] (default kRoughSonineMaxSteps; theory.md §19.24).
ParameterSpec rough_evolution_max_steps_parameter();
/// Returns the Walton gas's Maxwellian cooling trajectory (keys dimension, alpha, beta0,
/// moment_of_inertia, friction, the initial temperatures, rtol, atol): the temperatures, θ and ζ*.
Trajectory rough_walton_trajectory(const std::vector<ParameterSpec>& schema, const TrajectoryRequest& request);
/// Returns the linear-scheme HCS; throws std::invalid_argument "hcs: …" naming the region where the
/// linear scheme has no root (theory.md §19.6) instead of returning a state without one.
RoughCoolingState linear_rough_state(int dimension, const Rational& alpha, const Rational& beta, const Rational& kappa);
std::unique_ptr<TransportModel> make_uniform_shear_model();
std::unique_ptr<TransportModel> make_gravity_column_model();

/// Returns the spec of `dimension`: an integer in [2, 3], default 3, described as `description`.
ParameterSpec dimension_spec(std::string description = "spatial dimension");
/// Returns the spec of a restitution coefficient `name`: a number in (0, 1], default 1.
ParameterSpec restitution_spec(std::string name, std::string description);
/// Returns the spec of the choice `name` among `choices` (the first is the default).
ParameterSpec choice_spec(std::string name, std::string description, std::vector<std::string> choices);

/// Returns `model` behind a guard that validates every call against the model's schema first
/// (validated_model.cpp): the registry hands out only guarded models.
std::unique_ptr<TransportModel> validated(std::unique_ptr<TransportModel> model);

/// A validated parameter point read through its schema, by name: an absent key takes the declared
/// default (a choice its first entry).
class SchemaPoint {
 public:
  SchemaPoint(std::vector<ParameterSpec> schema, const ParameterPoint& point)
      : schema_(std::move(schema)), point_(point) {}
  /// Returns the number `name`, or its declared default.
  [[nodiscard]] Rational number(std::string_view name) const {
    const auto it = point_.numbers.find(std::string(name));
    return it != point_.numbers.end() ? it->second : find_parameter(schema_, name).default_value;
  }
  /// Returns the choice `name`, or its declared default (the first choice).
  [[nodiscard]] std::string choice(std::string_view name) const {
    const auto it = point_.choices.find(std::string(name));
    return it != point_.choices.end() ? it->second : find_parameter(schema_, name).choices.front();
  }
  /// Returns true if the point gives `name`.
  [[nodiscard]] bool given(std::string_view name) const {
    return point_.numbers.contains(std::string(name)) || point_.choices.contains(std::string(name));
  }
  /// Returns the declared spec of `name`.
  [[nodiscard]] const ParameterSpec& spec(std::string_view name) const { return find_parameter(schema_, name); }

 private:
  std::vector<ParameterSpec> schema_;
  const ParameterPoint& point_;
};

/// Returns the one-line error for a required parameter that is absent: "<name>: required, <allowed>".
inline std::invalid_argument missing(const ParameterSpec& spec) {
  return std::invalid_argument(spec.name + ": required, " + spec.allowed());
}

/// Returns the HCS stability values of a one-component state (theory.md (14.3)–(14.6)) from ζ*
/// (dense: χ ζ*_dilute), η*, κ*, μ* (and the dense bulk viscosity and ζ_U) of one order, for the
/// dense gas `dense` at restitution α and λ_T = ∂ln ζ/∂ln T (½ for constant α). The dilute defaults
/// give p* = 1 exactly.
HcsStability monodisperse_stability(int dimension, double cooling_rate, const NavierStokesValues& values,
                                    const EnskogState& dense = {}, double alpha = 1,
                                    double cooling_temperature_exponent = 0.5);

/// η*, κ*, μ* at one sample of a cooling trajectory and the λ_T its stability needs.
struct SampleTransport {
  NavierStokesValues values;
  double cooling_temperature_exponent = 0.5;
  EnskogState dense{};  ///< the dense gas's φ, χ (dilute default: p* = 1)
  double alpha = 1;     ///< restitution, for the dense gas's p* (unused when dilute)
};

/// Returns the names of the coefficients offered along a cooling trajectory (η*, κ*, μ*, critical values).
std::vector<std::string> trajectory_coefficient_names();

/// Returns the trajectory table of `model` in dimension d keeping a_2 … a_{k_max}: the samples of
/// `result`, and per sample the `coefficients` from `transport` (called only if any are asked for).
Trajectory tabulate_trajectory(const std::string& model, int dimension, int k_max, const EvolutionResult& result,
                               const std::vector<std::string>& coefficients,
                               const std::function<SampleTransport(const EvolutionSample&)>& transport);

/// Returns the spec of an evolution's Sonine order, CVODE tolerances, initial a2 (positivity
/// of f_M(1 + a2 S_2) in either dimension; evolution_a2_spec(d) is the exact range, theory.md §12) and
/// max_steps (evolution_max_steps_parameter).
std::vector<ParameterSpec> evolution_common_parameters();
/// Returns the key `max_steps` of `gkt evolve`: the CVODE step budget over the whole trajectory, an integer in
/// [1, 10⁹] (default kEvolutionMaxSteps).
ParameterSpec evolution_max_steps_parameter();
/// Returns the a2 spec of dimension d: [−8/(d(d+2)), 4/(d+2)] written as the shortest decimals of
/// those doubles (a positive distribution at c = 0 and at the minimum of S_2).
ParameterSpec evolution_a2_spec(int dimension);

/// A value at one order as a model computes it: estimate plus whether it exists at all.
struct OrderValue {
  TruncationEstimate estimate;
  bool defined = true;
  bool exact = true;
  bool infinite = false;  ///< +∞ at this order and the next two (estimate: value and error 0)
};

/// Returns the inexact value v_N with the error `estimate` gives from the nearest rationals of v_N, v_{N+1},
/// v_{N+2}. +∞ at all three orders is an exact +∞ (critical_length of a gas that never clusters:
/// conventions.md); any other non-finite value leaves it undefined (printed nan, error inf) and `estimate` is not
/// called.
template <class Estimate>
OrderValue order_value_from_doubles(double v_n, double v_n1, double v_n2, Estimate&& estimate) {
  OrderValue v{{Rational(0), Rational(0), false}, true, false};
  if (std::isinf(v_n) && v_n > 0 && v_n1 == v_n && v_n2 == v_n) {
    v.estimate = {Rational(0), Rational(0), true};
    v.infinite = true;
    return v;
  }
  v.defined = std::isfinite(v_n) && std::isfinite(v_n1) && std::isfinite(v_n2);
  if (v.defined)
    v.estimate = estimate(Rational::from_double(v_n), Rational::from_double(v_n1), Rational::from_double(v_n2));
  return v;
}

/// Returns the inexact value v_N with its error from v_{N+1}, v_{N+2} (estimate_truncation, (6.1)), as
/// order_value_from_doubles does.
inline OrderValue estimate_from_doubles(double v_n, double v_n1, double v_n2) {
  return order_value_from_doubles(v_n, v_n1, v_n2, [](const Rational& a, const Rational& b, const Rational& c) {
    return estimate_truncation(a, b, c);
  });
}

/// Returns estimate_from_doubles(v_n, v_n1, v_n2) with the turning-point check of theory.md (6.3): where the
/// two changes have opposite signs, `next()` gives v_{N+3} (NaN if there is none) and
/// estimate_truncation_checked decides between an alternation and a turn. Every model's Sonine scan on doubles
/// estimates its error here.
template <class Next>
OrderValue estimate_from_doubles_confirmed(double v_n, double v_n1, double v_n2, Next&& next) {
  return order_value_from_doubles(v_n, v_n1, v_n2, [&](const Rational& a, const Rational& b, const Rational& c) {
    return estimate_truncation_checked(a, b, c, [&] {
      const double v_n3 = next();
      return std::isfinite(v_n3) ? std::optional<Rational>(Rational::from_double(v_n3)) : std::nullopt;
    });
  });
}

/// Returns the inexact v_N with the window error of theory.md (19.100)–(19.101) (estimate_truncation_windowed) from
/// v = (v_N, …, v_H), the values of every order a scan computed; the window ends before the first non-finite value
/// past v_{N+2}. Defined as order_value_from_doubles(v_N, v_{N+1}, v_{N+2}) is.
inline OrderValue estimate_from_doubles_windowed(std::span<const double> v) {
  return order_value_from_doubles(v[0], v[1], v[2], [&](const Rational&, const Rational&, const Rational&) {
    std::vector<Rational> window;
    for (const double x : v) {
      if (!std::isfinite(x)) break;
      window.push_back(Rational::from_double(x));
    }
    return estimate_truncation_windowed(window);
  });
}

/// Applies an OrderRequest: the fixed order, or the smallest order whose estimate converges
/// below the tolerance; if none does, the order with the smallest estimated error (optimal
/// truncation of an asymptotic series), flagged not converged. The scan stops once the estimated
/// error has grown for three successive orders past its minimum.
template <class ValueAt>
CoefficientValue choose_order(const OrderRequest& request, int max_order, ValueAt&& value_at) {
  auto to_value = [](const OrderValue& v, int order, bool converged) {
    CoefficientValue c{v.estimate.value, v.estimate.error, order, converged, v.exact, v.defined};
    c.infinite = v.infinite;
    c.divergence = v.estimate.divergence;
    return c;
  };
  if (!request.tolerance) {
    const OrderValue v = value_at(request.order);
    return to_value(v, request.order, v.defined && v.estimate.converging);
  }
  int best = 0, growing = 0;
  OrderValue best_value{};
  for (int n = 1; n <= max_order; ++n) {
    const OrderValue v = value_at(n);
    if (!v.defined) continue;
    if (v.estimate.converging && v.estimate.error < *request.tolerance) return to_value(v, n, true);
    if (best == 0 || v.estimate.error < best_value.estimate.error) {
      best = n;
      best_value = v;
      growing = 0;
    } else if (++growing == 3) {
      break;  // the error grew three orders in a row past its minimum: an asymptotic series
    }
  }
  if (best == 0) return to_value(value_at(max_order), max_order, false);
  return to_value(best_value, best, false);
}

}  // namespace gkt::detail
