// Private to the C API: what the wrappers of the binary and the ternary per-cell tables share
// (binary_table.cpp, ternary_table.cpp): the mixture built from C arrays, the state checks of a
// (dense) table and the conversion of a C++ transport set to its C struct.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <string>

#include "gkt/gkt.h"
#include "gkt/transport/common/reference_gas.hpp"
#include "gkt/transport/mixture/mixture.hpp"
#include "gkt/transport/mixture/mixture_cooling_state.hpp"
#include "guard.hpp"

namespace gkt::c_api {

/// Returns the validated mixture of `species` species (2 or 3) of mass[i], diameter[i] and the row-major
/// restitution matrix alpha[species·i + j], equal fractions, φ = 0 (what a table keeps of a mixture);
/// throws a Refusal naming the field ("mass_2", "alpha_1_3", "alpha" for an asymmetric matrix, "dimension").
Mixture mixture_from_c(int dimension, std::size_t species, const double* mass, const double* diameter,
                       const double* alpha);

/// Returns the f^(0) a table is built about (theory.md §17.14): reference "maxwellian" (hcs_order ignored, as
/// MixtureReference ignores it), "linear" or "nonlinear" (the HCS of that scheme with a_2 … a_K in f^(0), K =
/// hcs_order, which the table refuses outside [2, 6]); throws a Refusal naming reference otherwise.
MixtureReference reference_from_c(const char* reference, int hcs_order);

/// Returns "[i]", the suffix that names cell i in a message.
std::string cell_index(std::size_t i);

/// Returns field + suffix + ": must be " + range + ", got " + x (built by appending: GCC 12's
/// -Wrestrict misreads chained operator+ on a const std::string&).
std::string refusal(const char* field, const std::string& suffix, const char* range, double x);

/// Throws a Refusal (GKT_OUT_OF_RANGE, naming number_density + suffix) if the state's packing fraction
/// φ exceeds a dense table's max_packing_fraction (a dilute table, max ≤ 0, treats any n as dilute).
void require_packing_within(double phi, double max_packing_fraction, const std::string& suffix);

/// Throws a Refusal unless φ is in [0, max_packing_fraction] (GKT_OUT_OF_RANGE above it, GKT_INVALID_ARGUMENT
/// for a negative or non-number φ), naming packing_fraction: the reduced evaluation of a table.
void require_reduced_packing(double phi, double max_packing_fraction);

/// What the C layer keeps of a table's species to check states against it: φ = n Σ x_i v_d σ_i^d.
template <std::size_t S>
struct TableSpecies {
  int dimension = 3;
  std::array<double, S> mass{}, diameter{};
  std::array<double, S> species_volume{};  // v_d σ_i^d
  double max_packing_fraction = 0;

  TableSpecies(const Mixture& mixture, double max_packing)
      : dimension(mixture.dimension), max_packing_fraction(max_packing) {
    for (std::size_t i = 0; i < S; ++i) {
      mass[i] = mixture.species[i].mass.value();
      diameter[i] = mixture.species[i].diameter;
      species_volume[i] = unit_sphere_volume(dimension) * std::pow(diameter[i], dimension);
    }
  }
  /// Returns φ = n Σ x_i v_d σ_i^d at the fractions x (size S) and density n.
  [[nodiscard]] double packing(const std::array<double, S>& x, double n) const {
    double volume = 0;
    for (std::size_t i = 0; i < S; ++i) volume += x[i] * species_volume[i];
    return n * volume;
  }
  /// True if the state's φ is covered (always, for a dilute table).
  [[nodiscard]] bool covers_packing(const std::array<double, S>& x, double n) const {
    return max_packing_fraction <= 0 || packing(x, n) <= max_packing_fraction;
  }
};

/// Returns the C struct C (gkt_binary_transport, gkt_ternary_transport) of the C++ set v (BinaryTransport,
/// TernaryTransport): the same fields, arrays element by element.
template <class C, class Cpp>
C to_c(const Cpp& v) {
  C out{};
  out.cooling_rate = v.cooling_rate;
  out.shear_viscosity = v.shear_viscosity;
  out.thermal_conductivity = v.thermal_conductivity;
  for (std::size_t i = 0; i < v.temperature_ratio.size(); ++i) {
    out.temperature_ratio[i] = v.temperature_ratio[i];
    out.thermal_diffusion[i] = v.thermal_diffusion[i];
    out.pressure_diffusion[i] = v.pressure_diffusion[i];
    out.dufour[i] = v.dufour[i];
  }
  for (std::size_t k = 0; k < v.mutual_diffusion.size(); ++k) out.mutual_diffusion[k] = v.mutual_diffusion[k];
  out.pressure = v.pressure;
  out.bulk_viscosity = v.bulk_viscosity;
  out.cooling_rate_first_order = v.cooling_rate_first_order;
  return out;
}

}  // namespace gkt::c_api
