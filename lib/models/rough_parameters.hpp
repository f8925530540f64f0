// Private: what the two rough-sphere adapters ("rough", "rough-walton") share — the keys of a rough
// grain (dimension, α, a tangential restitution, κ), reading them from a point, the first-order-only
// request and the first-approximation value (docs/theory.md §19).
#pragma once

#include <string>
#include <vector>

#include "gkt/evolution/hcs_stability.hpp"
#include "gkt/transport/rough/rough_sonine_transport.hpp"
#include "models/models.hpp"

namespace gkt::detail {

/// Returns the schema dimension, alpha, `tangential`, moment_of_inertia (in this order): d ∈ {2, 3}
/// (default 3), α ∈ (0, 1] (default 1), `tangential` ∈ [−1, 1] (default 1, described as
/// `tangential_description`), κ = 4I/(mσ²) ∈ (0, 1] (default 2/5).
std::vector<ParameterSpec> rough_grain_parameters(const std::string& tangential,
                                                  const std::string& tangential_description);

/// The rough grain of a validated point (absent keys take the schema's defaults).
struct RoughGrain {
  int dimension = 3;
  Rational alpha, tangential, moment_of_inertia;
};
/// Returns the grain of `point` read by name through `schema`, the tangential restitution from key `tangential`.
RoughGrain read_rough_grain(const std::vector<ParameterSpec>& schema, const ParameterPoint& point,
                            const std::string& tangential);

/// Throws std::invalid_argument unless `order` asks for order = 1 (the rough models have the first
/// approximation only); `model` names the model in the message.
void require_first_approximation(const OrderRequest& order, const std::string& model);

/// Returns the stability value `name` (one of stability_coefficient_names()) of `s` as a first
/// approximation; critical_length = +∞ (a stable HCS) as CoefficientValue::infinite (docs/conventions.md
/// "The elastic end"), NaN (no HCS) as undefined.
CoefficientValue rough_stability_value(const HcsStability& s, const std::string& name);

/// Returns x as a first approximation: order 1, no error estimate, undefined (and not converged)
/// where x is not finite (θ = inf where the spin decouples, NaN where a scheme has no root).
CoefficientValue first_approximation(double x);

/// Returns true if `name` is one of the five Navier–Stokes columns the rough Sonine solvers give at any order
/// (shear_viscosity, bulk_viscosity, thermal_conductivity, density_heat_coefficient, cooling_rate_first_order;
/// theory.md §19.16, §19.20).
bool is_rough_sonine_column(const std::string& name);

/// Returns the Navier–Stokes column `name` (is_rough_sonine_column) of one order's values, reduced as
/// RoughTransportValues holds it.
double rough_sonine_column(const RoughTransportValues& v, const std::string& name);

}  // namespace gkt::detail
