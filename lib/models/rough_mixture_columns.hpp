// Private: the binary mixture of rough grains inside the "rough" model (`species = 2`, from two
// [[species]] tables): its keys, its columns and their values from the Maxwellian HCS of
// rough_mixture_cooling_state.hpp (docs/theory.md §19.17, §19.26) or, with hcs = "linear", the first-Sonine
// HCS of rough_mixture_sonine_cooling_state.hpp (§19.30).
#pragma once

#include <string>
#include <vector>

#include "gkt/transport/rough/rough_mixture_cooling_state.hpp"
#include "models/models.hpp"

namespace gkt::detail {

/// Returns the keys a rough binary mixture adds to the rough model's schema: `species` (1 = one gas,
/// default; 2 = the binary), mass_i, diameter_i, fraction_i, moment_of_inertia_i (i = 1, 2) and the
/// pair restitutions alpha_i_j, beta_i_j (i ≤ j; default: the scalar alpha, beta).
std::vector<ParameterSpec> rough_mixture_parameters();

/// Returns the rough binary mixture's columns: temperature_ratio_i (T_t,i/T), rotational_temperature_ratio_i
/// (T_r,i/T_t,i) for i = 1, 2 and cooling_rate (ζ/ν0(m̄, σ̄); theory.md (19.55)).
std::vector<std::string> rough_mixture_columns();

/// Returns the rough binary mixture's cumulant columns a20_i, a02_i, a11_i (i = 1, 2) of the first-Sonine HCS
/// (theory.md (19.170)), computed with hcs = "linear" or "linear-or-maxwellian" only.
std::vector<std::string> rough_mixture_cumulant_columns();

/// Returns true if the point describes a binary mixture (species = 2).
bool is_rough_mixture_point(const ParameterPoint& point);

/// Returns the binary of `p` (species = 2; the rough model's schema): m_i, σ_i, x_i, κ_i (default: moment_of_inertia)
/// and the pair α_ij, β_ij (default: alpha, beta). Throws std::invalid_argument naming the key for a missing
/// mass_i, diameter_i, fraction_i and for fractions not summing to 1 (exactly, as rationals).
RoughBinaryMixture rough_binary_mixture(const SchemaPoint& p);

/// Returns the keys `gkt evolve` adds for the binary: translational_temperature_i, rotational_temperature_i
/// (i = 1, 2; T(0)/T_ref, default the one-gas translational_temperature, rotational_temperature).
std::vector<ParameterSpec> rough_mixture_evolution_parameters();

/// Returns the Maxwellian free cooling of the binary of `request` (theory.md §19.31) validated against `schema` (the
/// rough model's evolution parameters): columns time, temperature, translational_temperature_i,
/// rotational_temperature_i, temperature_ratio_i, rotational_temperature_ratio_i, cooling_rate. Throws
/// std::invalid_argument naming the key for an hcs other than "maxwellian", initial cumulants, order > 1, a one-gas
/// key the binary does not take, and bad initial temperatures.
Trajectory rough_mixture_trajectory(const std::vector<ParameterSpec>& schema, const TrajectoryRequest& request);

/// Returns the values of `coefficients` (rough_mixture_columns, rough_mixture_cumulant_columns) of the binary of
/// `point`, validated against `schema` (the rough model's): the Maxwellian HCS (hcs not given or "maxwellian") or
/// the first-Sonine linear HCS (hcs = "linear"; "linear-or-maxwellian" falls back to the Maxwellian values with
/// `nan` cumulants where it has no realizable root); first approximation, order 1 only. Throws
/// std::invalid_argument naming the key for a one-gas key the binary does not take, another order, hcs =
/// "nonlinear", cumulant columns with the Maxwellian HCS, "linear" without a root, fractions not summing to 1
/// and any column the binary does not have.
std::vector<CoefficientValue> rough_mixture_values(const std::vector<ParameterSpec>& schema,
                                                   const ParameterPoint& point,
                                                   const std::vector<std::string>& coefficients,
                                                   const OrderRequest& order);

/// Throws std::invalid_argument naming the first per-species key (mass_i, …, beta_i_j) that `point` gives
/// while it describes one gas (species = 1).
void refuse_species_keys_for_one_gas(const ParameterPoint& point);

}  // namespace gkt::detail
