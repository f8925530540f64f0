// The façade: the interface every transport model implements, and the one registry that names
// them (cf. Cantera's TransportFactory). Front ends pick models by name only through here and ask
// the model for everything a subcommand needs: its schema (parameters(), evolution_parameters(),
// coefficient names, max_order(), supports()), the table values (evaluate), the closed forms
// (closed_form) and the cooling trajectory (evolve). A model from make_transport_model validates
// every call against its schema before it computes anything.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "gkt/algebra/rational.hpp"
#include "gkt/models/closed_form.hpp"
#include "gkt/models/cooling_trajectory.hpp"
#include "gkt/models/parameter_spec.hpp"
#include "gkt/transport/common/sonine_solution.hpp"

namespace gkt {

/// One coefficient at one parameter point.
struct CoefficientValue {
  Rational value;               ///< reduced value (exact when `exact`)
  Rational error;               ///< estimated truncation error
  int order = 0;                ///< Sonine order used
  bool converged = true;        ///< false if the tolerance was not met or the series does not converge
  bool exact = true;            ///< value and error are exact rationals
  bool defined = true;          ///< false if no value with an error estimate exists at this order
  bool error_estimated = true;  ///< false: the approximation's error is not estimated (printed nan)
  /// true: the value is +∞ at every order used (the critical_length of a gas whose HCS is stable at
  /// every wave number, e.g. the elastic gas: docs/conventions.md); value and error are then 0.
  bool infinite = false;
  /// Why the error estimate at `order` is flagged not converging (docs/theory.md (6.1), (6.3);
  /// describe_divergence words it); Divergence::none where it converges or the scan only missed the tolerance.
  Divergence divergence = Divergence::none;
};

/// What a model can answer, one per front-end subcommand: a table of coefficients (every model),
/// exact closed forms, a cooling trajectory, the stability of the homogeneous cooling state.
enum class Capability { table, formula, evolve, stability };

/// Returns the names of the HCS stability values (theory.md §14), the coefficients a stability
/// analysis lists by default: critical_wavenumber_shear, critical_wavenumber_heat, critical_length.
const std::vector<std::string>& stability_coefficient_names();

/// A transport model: named coefficients as functions of named parameters.
class TransportModel {
 public:
  virtual ~TransportModel() = default;
  /// Returns the model's name.
  [[nodiscard]] virtual std::string name() const = 0;
  /// Returns a one-line description of the model.
  [[nodiscard]] virtual std::string description() const = 0;
  /// Returns the canonical coefficient names this model computes.
  [[nodiscard]] virtual std::vector<std::string> coefficient_names() const = 0;
  /// Returns the coefficient names offered at a scene's fixed parameters (e.g. one
  /// temperature_ratio_i per species of a mixture); by default all of coefficient_names().
  [[nodiscard]] virtual std::vector<std::string> scene_coefficient_names(const ParameterPoint& fixed) const {
    static_cast<void>(fixed);
    return coefficient_names();
  }
  /// Returns the coefficients a scene computes when it does not list any; by default all of
  /// scene_coefficient_names().
  [[nodiscard]] virtual std::vector<std::string> default_coefficients(const ParameterPoint& fixed) const {
    return scene_coefficient_names(fixed);
  }
  /// Returns the model's parameters (scene keys) with their ranges.
  [[nodiscard]] virtual std::vector<ParameterSpec> parameters() const = 0;
  /// Returns the parameters with the ranges that hold at a scene's fixed parameters (e.g. the
  /// packing-fraction limit of a fixed dimension); by default parameters().
  [[nodiscard]] virtual std::vector<ParameterSpec> scene_parameters(const ParameterPoint& fixed) const {
    static_cast<void>(fixed);
    return parameters();
  }
  /// Returns the highest Sonine order accepted.
  [[nodiscard]] virtual int max_order() const = 0;
  /// Returns whether the model answers `capability`; by default a table only. A model that
  /// supports stability offers every name of stability_coefficient_names().
  [[nodiscard]] virtual bool supports(Capability capability) const { return capability == Capability::table; }
  /// Returns the requested coefficients at one parameter point (reduced as in
  /// docs/conventions.md), computing only those; state is reused between calls. Throws
  /// std::invalid_argument naming the key on an unknown parameter or an out-of-range value.
  virtual std::vector<CoefficientValue> evaluate(const ParameterPoint& parameters,
                                                 const std::vector<std::string>& coefficients,
                                                 const OrderRequest& order) = 0;
  /// Returns the exact closed form of `coefficient` at Sonine order `order` and the fixed
  /// parameters `point` (α, and φ of a dense gas, stay symbolic; φ > 0 in `point` asks for the
  /// dense form). Only if supports(Capability::formula); throws std::invalid_argument otherwise.
  virtual ClosedForm closed_form(const ParameterPoint& point, const std::string& coefficient, int order);
  /// Returns the parameters of a cooling trajectory (the keys of `gkt evolve` besides the output
  /// times); empty unless supports(Capability::evolve).
  [[nodiscard]] virtual std::vector<ParameterSpec> evolution_parameters() const { return {}; }
  /// Returns the coefficients offered along a cooling trajectory.
  [[nodiscard]] virtual std::vector<std::string> trajectory_coefficients() const { return {}; }
  /// Returns the integrated cooling trajectory (theory.md §12). Only if supports(Capability::evolve);
  /// throws std::invalid_argument otherwise and on bad input, std::runtime_error if the integrator fails.
  virtual Trajectory evolve(const TrajectoryRequest& request);
  /// Returns what the `_error` columns of a whole table do not cover, one warning line each (no prefix), for
  /// the scene's choice keys `choices` (absent: the default), its `coefficients`, the highest Sonine order of its
  /// rows and whether a `tolerance` scans (docs/conventions.md, "Warnings"); none by default.
  [[nodiscard]] virtual std::vector<std::string> table_caveats(const std::map<std::string, std::string>& choices,
                                                               const std::vector<std::string>& coefficients,
                                                               int highest_order, bool tolerance) const;
};

/// Returns a new model by name; throws std::invalid_argument listing the valid names.
std::unique_ptr<TransportModel> make_transport_model(const std::string& name);

/// Returns the registered model names, sorted.
std::vector<std::string> transport_model_names();

}  // namespace gkt
