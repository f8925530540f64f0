// The C API of the one-component gas (include/gkt/gkt.h): the dilute and dense first-Sonine sets,
// reduced and in physical units, per cell and for the caller's arrays of cells, and the double
// contact value χ(φ). Each call is the C++ call of gkt/cell.hpp behind the exception barrier (one
// per batch); physical units through the reference gas (docs/conventions.md "Reference values").
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

#include "gkt/cell.hpp"
#include "gkt/gkt.h"
#include "gkt/transport/common/pair_correlation.hpp"
#include "gkt/transport/common/reference_gas.hpp"
#include "guard.hpp"

namespace gkt::c_api {
namespace {

/// Throws a Refusal unless every field of the gas is finite and > 0.
void require_gas(const gkt_gas* gas) {
  require_pointer(gas, "gas");
  require_positive(gas->mass, "mass");
  require_positive(gas->diameter, "diameter");
  require_positive(gas->number_density, "number_density");
  require_positive(gas->temperature, "temperature");
}

/// Returns the reference values η0, κ0, ν0 of the gas (conventions.md).
ReferenceGas reference_of(int dimension, const gkt_gas& gas) {
  return reference_gas(dimension, gas.mass, gas.diameter, gas.number_density, gas.temperature);
}

gkt_first_sonine to_c(const FirstSonineValues& v) {
  return {v.a2, v.cooling_rate, v.shear_viscosity, v.thermal_conductivity, v.density_heat_coefficient};
}

gkt_enskog_first_sonine to_c(const EnskogFirstSonineValues& v) {
  return {v.a2,
          v.cooling_rate,
          v.pressure,
          v.shear_viscosity,
          v.bulk_viscosity,
          v.thermal_conductivity,
          v.density_heat_coefficient,
          v.cooling_rate_first_order};
}

/// True if every cell's inputs lie in the ranges the single-cell calls accept (α ∈ (0, 1], and φ in
/// [0, 0.5] (3D) or [0, 0.7] (2D) when phi is given; NaN fails): a few compares per cell, no message.
bool cell_in_range(int dimension, double alpha, const double* phi) {
  if (!(alpha > 0 && alpha <= 1)) return false;
  return phi == nullptr || (*phi >= 0 && *phi <= (dimension == 3 ? 0.5 : 0.7));
}

/// Throws the Refusal of cell i: the single-cell call's own message with the field named by its
/// index ("alpha[3]: must be a number in (0, 1], got 1.5"). Runs the single-cell call (enskog_state
/// when phi is given) only to obtain that message; out of line and cold.
[[noreturn, gnu::cold, gnu::noinline]] void refuse_cell(int dimension, std::size_t i, double alpha, const double* phi) {
  std::string message;
  try {
    if (phi != nullptr) static_cast<void>(gkt::enskog_state(dimension, *phi));
    static_cast<void>(gkt::first_sonine_values(dimension, alpha));
    message = "alpha: out of range, got " + number(alpha);  // cell_in_range and the library disagree (a bug)
  } catch (const std::invalid_argument& e) {
    message = e.what();
  }
  const std::size_t colon = message.find(':');
  message.insert(colon == std::string::npos ? 0 : colon, "[" + std::to_string(i) + "]");
  throw Refusal{GKT_INVALID_ARGUMENT, message};
}

/// Throws a Refusal unless dimension is 2 or 3.
void require_dimension(int dimension) {
  if (dimension != 2 && dimension != 3)
    throw Refusal{GKT_INVALID_ARGUMENT, "dimension: must be 2 or 3, got " + std::to_string(dimension)};
}

}  // namespace
}  // namespace gkt::c_api

using gkt::c_api::guarded;
using gkt::c_api::require_pointer;

extern "C" {

gkt_status gkt_first_sonine_values(int dimension, double alpha, gkt_first_sonine* out) {
  return guarded([&] {
    require_pointer(out, "out");
    *out = gkt::c_api::to_c(gkt::first_sonine_values(dimension, alpha));
    return GKT_OK;
  });
}

gkt_status gkt_first_sonine_values_cells(int dimension, size_t cells, const double* alpha, gkt_first_sonine* out) {
  return guarded([&] {
    require_pointer(alpha, "alpha");
    require_pointer(out, "out");
    gkt::c_api::require_dimension(dimension);
    for (std::size_t i = 0; i < cells; ++i)  // every cell checked before any is written
      if (!gkt::c_api::cell_in_range(dimension, alpha[i], nullptr)) [[unlikely]]
        gkt::c_api::refuse_cell(dimension, i, alpha[i], nullptr);
    for (std::size_t i = 0; i < cells; ++i) out[i] = gkt::c_api::to_c(gkt::first_sonine_values(dimension, alpha[i]));
    return GKT_OK;
  });
}

gkt_status gkt_first_sonine_physical(int dimension, double alpha, const gkt_gas* gas, gkt_first_sonine* out) {
  return guarded([&] {
    require_pointer(out, "out");
    gkt::c_api::require_gas(gas);
    const gkt::FirstSonineValues r = gkt::first_sonine_values(dimension, alpha);
    const gkt::ReferenceGas ref = gkt::c_api::reference_of(dimension, *gas);
    const double n = gas->number_density, t = gas->temperature;
    *out = {r.a2, r.cooling_rate * ref.collision_frequency, r.shear_viscosity * ref.viscosity,
            r.thermal_conductivity * ref.conductivity, r.density_heat_coefficient * t * ref.conductivity / n};
    return GKT_OK;
  });
}

gkt_status gkt_enskog_state_at(int dimension, double packing_fraction, gkt_enskog_state* out) {
  return guarded([&] {
    require_pointer(out, "out");
    const gkt::EnskogState s = gkt::enskog_state(dimension, packing_fraction);
    *out = {s.packing_fraction, s.chi, s.phi_dchi};
    return GKT_OK;
  });
}

gkt_status gkt_enskog_first_sonine_values(int dimension, double alpha, double packing_fraction,
                                          gkt_enskog_first_sonine* out) {
  return guarded([&] {
    require_pointer(out, "out");
    const gkt::EnskogState state = gkt::enskog_state(dimension, packing_fraction);
    *out = gkt::c_api::to_c(gkt::enskog_first_sonine_values(dimension, alpha, state));
    return GKT_OK;
  });
}

gkt_status gkt_enskog_first_sonine_values_cells(int dimension, size_t cells, const double* alpha,
                                                const double* packing_fraction, gkt_enskog_first_sonine* out) {
  return guarded([&] {
    require_pointer(alpha, "alpha");
    require_pointer(packing_fraction, "packing_fraction");
    require_pointer(out, "out");
    gkt::c_api::require_dimension(dimension);
    for (std::size_t i = 0; i < cells; ++i)  // every cell checked before any is written
      if (!gkt::c_api::cell_in_range(dimension, alpha[i], &packing_fraction[i])) [[unlikely]]
        gkt::c_api::refuse_cell(dimension, i, alpha[i], &packing_fraction[i]);
    for (std::size_t i = 0; i < cells; ++i) {
      const gkt::EnskogState state = gkt::enskog_state(dimension, packing_fraction[i]);
      out[i] = gkt::c_api::to_c(gkt::enskog_first_sonine_values(dimension, alpha[i], state));
    }
    return GKT_OK;
  });
}

gkt_status gkt_enskog_first_sonine_values_at(int dimension, double alpha, const gkt_enskog_state* state,
                                             gkt_enskog_first_sonine* out) {
  return guarded([&] {
    require_pointer(out, "out");
    require_pointer(state, "state");
    if (!(state->packing_fraction >= 0 && state->packing_fraction < 1))
      throw gkt::c_api::Refusal{GKT_INVALID_ARGUMENT, "packing_fraction: must be a number in [0, 1), got " +
                                                          gkt::c_api::number(state->packing_fraction)};
    gkt::c_api::require_positive(state->chi, "chi");
    if (!std::isfinite(state->phi_dchi))
      throw gkt::c_api::Refusal{GKT_INVALID_ARGUMENT,
                                "phi_dchi: must be a finite number, got " + gkt::c_api::number(state->phi_dchi)};
    const gkt::EnskogState s{state->packing_fraction, state->chi, state->phi_dchi};
    *out = gkt::c_api::to_c(gkt::enskog_first_sonine_values(dimension, alpha, s));
    return GKT_OK;
  });
}

gkt_status gkt_enskog_first_sonine_physical(int dimension, double alpha, const gkt_gas* gas,
                                            gkt_enskog_first_sonine* out) {
  return guarded([&] {
    require_pointer(out, "out");
    gkt::c_api::require_gas(gas);
    if (dimension != 2 && dimension != 3)
      throw gkt::c_api::Refusal{GKT_INVALID_ARGUMENT, "dimension: must be 2 or 3, got " + std::to_string(dimension)};
    // φ = n v_d σ^d (conventions.md); too dense a gas is refused naming number_density.
    const double phi = gas->number_density * gkt::unit_sphere_volume(dimension) * std::pow(gas->diameter, dimension);
    gkt::EnskogState state;
    try {
      state = gkt::enskog_state(dimension, phi);
    } catch (const std::invalid_argument& e) {
      throw gkt::c_api::Refusal{GKT_INVALID_ARGUMENT, std::string("number_density: n v_d sigma^d = ") +
                                                          gkt::c_api::number(phi) + " is too dense (" + e.what() + ")"};
    }
    const gkt::EnskogFirstSonineValues r = gkt::enskog_first_sonine_values(dimension, alpha, state);
    const gkt::ReferenceGas ref = gkt::c_api::reference_of(dimension, *gas);
    const double n = gas->number_density, t = gas->temperature;
    *out = {r.a2,
            r.cooling_rate * ref.collision_frequency,
            r.pressure * n * t,
            r.shear_viscosity * ref.viscosity,
            r.bulk_viscosity * ref.viscosity,
            r.thermal_conductivity * ref.conductivity,
            r.density_heat_coefficient * t * ref.conductivity / n,
            r.cooling_rate_first_order};
    return GKT_OK;
  });
}

}  // extern "C"
