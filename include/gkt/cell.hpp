// The per-cell calls of gkt for hydrodynamic solvers, in one header: double in and out, fixed-size
// structs, no allocation (docs/architecture.md "Number policy"). Each call exists for one cell and,
// here, for a batch of cells held in the caller's arrays (std::span): the batch forms loop over the
// single-cell ones, so a batch equals the single calls value for value.
//
//   first_sonine_values         dilute gas, a2, ζ*, η*, κ*, μ* at α (first_sonine_formulas.hpp)
//   enskog_first_sonine_values  dense gas at α and (φ, χ, φ dχ/dφ) (enskog_closed_form.hpp)
//   evaluate(BinaryTransportTable, …)  a binary's Navier–Stokes set at (x_1, n, T) in physical units
//                                      (mixture_transport_table.hpp)
//   evaluate(TernaryTransportTable, …) a dilute ternary's set at (x_1, x_2, n, T) in physical units
//                                      (ternary_transport_table.hpp)
//
// Everything is reduced as in docs/conventions.md. The contact value χ(φ) is the caller's: the
// registry of pair_correlation.hpp evaluates it exactly (rationals), once per table, not per cell.
#pragma once

#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>

#include "gkt/transport/closed_forms/enskog_closed_form.hpp"
#include "gkt/transport/closed_forms/first_sonine_formulas.hpp"
#include "gkt/transport/common/enskog_state.hpp"
#include "gkt/transport/mixture/mixture_transport_table.hpp"
#include "gkt/transport/mixture/ternary_transport_table.hpp"

namespace gkt {

namespace detail {
/// Throws std::invalid_argument "<name>: must have the N cells of <reference>, got M" unless sizes agree.
inline void require_cells(const char* name, std::size_t size, const char* reference, std::size_t cells) {
  if (size != cells)
    throw std::invalid_argument(std::string(name) + ": must have the " + std::to_string(cells) + " cells of " +
                                reference + ", got " + std::to_string(size));
}
}  // namespace detail

/// Writes out[i] = first_sonine_values(dimension, alpha[i]) (a2, ζ*, η*, κ*, μ*; theory.md (10.8))
/// for every cell i; no allocation. Throws std::invalid_argument if out and alpha differ in length,
/// and whatever the single-cell call throws.
inline void first_sonine_values(int dimension, std::span<const double> alpha, std::span<FirstSonineValues> out) {
  detail::require_cells("out", out.size(), "alpha", alpha.size());
  for (std::size_t i = 0; i < alpha.size(); ++i) out[i] = first_sonine_values(dimension, alpha[i]);
}

/// Writes out[i] = enskog_first_sonine_values(dimension, alpha[i], state[i]) (the dense first-Sonine
/// set, theory.md §15.7) for every cell i; no allocation. Throws std::invalid_argument if state or
/// out differ in length from alpha, and whatever the single-cell call throws.
inline void enskog_first_sonine_values(int dimension, std::span<const double> alpha, std::span<const EnskogState> state,
                                       std::span<EnskogFirstSonineValues> out) {
  detail::require_cells("state", state.size(), "alpha", alpha.size());
  detail::require_cells("out", out.size(), "alpha", alpha.size());
  for (std::size_t i = 0; i < alpha.size(); ++i) out[i] = enskog_first_sonine_values(dimension, alpha[i], state[i]);
}

/// Writes out[i] = table.evaluate(fraction_1[i], number_density[i], temperature[i]) (the binary's
/// Navier–Stokes set in the caller's units; nan beyond the table's φ_max) for every cell i; no
/// allocation. Throws std::invalid_argument if the spans differ in length.
inline void evaluate(const BinaryTransportTable& table, std::span<const double> fraction_1,
                     std::span<const double> number_density, std::span<const double> temperature,
                     std::span<BinaryTransport> out) {
  detail::require_cells("number_density", number_density.size(), "fraction_1", fraction_1.size());
  detail::require_cells("temperature", temperature.size(), "fraction_1", fraction_1.size());
  detail::require_cells("out", out.size(), "fraction_1", fraction_1.size());
  for (std::size_t i = 0; i < fraction_1.size(); ++i)
    out[i] = table.evaluate(fraction_1[i], number_density[i], temperature[i]);
}

/// Writes out[i] = table.evaluate(fraction_1[i], fraction_2[i], number_density[i], temperature[i])
/// (the dilute ternary's Navier–Stokes set in the caller's units) for every cell i; no allocation.
/// Throws std::invalid_argument if the spans differ in length, and whatever the single-cell call
/// throws (cells before the bad one are written).
inline void evaluate(const TernaryTransportTable& table, std::span<const double> fraction_1,
                     std::span<const double> fraction_2, std::span<const double> number_density,
                     std::span<const double> temperature, std::span<TernaryTransport> out) {
  detail::require_cells("fraction_2", fraction_2.size(), "fraction_1", fraction_1.size());
  detail::require_cells("number_density", number_density.size(), "fraction_1", fraction_1.size());
  detail::require_cells("temperature", temperature.size(), "fraction_1", fraction_1.size());
  detail::require_cells("out", out.size(), "fraction_1", fraction_1.size());
  for (std::size_t i = 0; i < fraction_1.size(); ++i)
    out[i] = table.evaluate(fraction_1[i], fraction_2[i], number_density[i], temperature[i]);
}

}  // namespace gkt
