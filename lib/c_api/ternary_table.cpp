// The C API of the dilute ternary's per-cell table (include/gkt/gkt.h): TernaryTransportTable built
// from C arrays (masses, diameters, the 3 × 3 restitution matrix), evaluated in physical or reduced
// units (docs/conventions.md, mixtures; docs/theory.md §17.8).
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "gkt/gkt.h"
#include "gkt/transport/mixture/mixture.hpp"
#include "gkt/transport/mixture/ternary_transport_table.hpp"
#include "guard.hpp"

/// A ternary's table.
struct gkt_ternary_table {
  gkt_ternary_table(const gkt::Mixture& mixture, int order, int nodes, double tolerance)
      : table(mixture, order, nodes, tolerance) {}
  gkt::TernaryTransportTable table;
};

namespace gkt::c_api {
namespace {

/// True if (x_1, x_2, n, T) is a state the table covers (the checks of require_state, no message).
bool covers(double x1, double x2, double n, double temperature) {
  return x1 >= 0 && x1 <= 1 && x2 >= 0 && x2 <= 1 - x1 && n > 0 && std::isfinite(n) && temperature > 0 &&
         std::isfinite(temperature);
}

/// Returns field + suffix + ": must be " + range + ", got " + x (built by appending: GCC 12's
/// -Wrestrict misreads chained operator+ on a const std::string&).
std::string refusal(const char* field, const std::string& suffix, const char* range, double x) {
  std::string out(field);
  out += suffix;
  out += ": must be ";
  out += range;
  out += ", got ";
  out += number(x);
  return out;
}

/// Throws a Refusal unless x_1 ∈ [0, 1] and x_2 ∈ [0, 1 − x_1]; suffix names the cell ("[3]").
void require_fractions(double x1, double x2, const std::string& suffix) {
  if (!(x1 >= 0 && x1 <= 1))
    throw Refusal{GKT_INVALID_ARGUMENT, refusal("fraction_1", suffix, "a number in [0, 1]", x1)};
  if (!(x2 >= 0 && x2 <= 1 - x1))
    throw Refusal{GKT_INVALID_ARGUMENT, refusal("fraction_2", suffix, "a number in [0, 1 - fraction_1]", x2)};
}

/// Throws a Refusal unless (x_1, x_2, n, T) is a state the table covers.
void require_state(double x1, double x2, double n, double temperature, const std::string& suffix) {
  require_fractions(x1, x2, suffix);
  if (!(n > 0 && std::isfinite(n)))
    throw Refusal{GKT_INVALID_ARGUMENT, refusal("number_density", suffix, "a finite number > 0", n)};
  if (!(temperature > 0 && std::isfinite(temperature)))
    throw Refusal{GKT_INVALID_ARGUMENT, refusal("temperature", suffix, "a finite number > 0", temperature)};
}

/// Returns "[i]", the suffix that names cell i in a message.
std::string index(std::size_t i) {
  std::string out(1, '[');
  out += std::to_string(i);
  out += ']';
  return out;
}

gkt_ternary_transport to_c(const TernaryTransport& v) {
  gkt_ternary_transport out{};
  out.cooling_rate = v.cooling_rate;
  out.shear_viscosity = v.shear_viscosity;
  out.thermal_conductivity = v.thermal_conductivity;
  for (std::size_t i = 0; i < 3; ++i) {
    out.temperature_ratio[i] = v.temperature_ratio[i];
    out.thermal_diffusion[i] = v.thermal_diffusion[i];
    out.pressure_diffusion[i] = v.pressure_diffusion[i];
    out.dufour[i] = v.dufour[i];
  }
  for (std::size_t k = 0; k < 9; ++k) out.mutual_diffusion[k] = v.mutual_diffusion[k];
  out.pressure = v.pressure;
  return out;
}

}  // namespace
}  // namespace gkt::c_api

using gkt::c_api::guarded;
using gkt::c_api::number;
using gkt::c_api::Refusal;
using gkt::c_api::require_pointer;

extern "C" {

gkt_status gkt_ternary_table_create(int dimension, const double mass[3], const double diameter[3],
                                    const double alpha[9], int order, int nodes, double tolerance,
                                    gkt_ternary_table** out) {
  return guarded([&] {
    require_pointer(out, "out");
    require_pointer(mass, "mass");
    require_pointer(diameter, "diameter");
    require_pointer(alpha, "alpha");
    if (dimension != 2 && dimension != 3)
      throw Refusal{GKT_INVALID_ARGUMENT, "dimension: must be 2 or 3, got " + std::to_string(dimension)};
    std::vector<gkt::Species> species(3);
    for (std::size_t i = 0; i < 3; ++i) {
      const std::string k = std::to_string(i + 1);
      gkt::c_api::require_positive(mass[i], ("mass_" + k).c_str());
      gkt::c_api::require_positive(diameter[i], ("diameter_" + k).c_str());
      species[i] = {mass[i], diameter[i], i < 2 ? 1.0 / 3 : 1 - 2.0 / 3, ""};
    }
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j)
        gkt::c_api::require_restitution(alpha[3 * i + j],
                                        ("alpha_" + std::to_string(i + 1) + "_" + std::to_string(j + 1)).c_str());
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = i + 1; j < 3; ++j)
        if (alpha[3 * i + j] != alpha[3 * j + i]) {
          std::string message = "alpha: the restitution matrix must be symmetric, got alpha_";
          message += std::to_string(i + 1);
          message += '_';
          message += std::to_string(j + 1);
          message += " = ";
          message += number(alpha[3 * i + j]);
          message += " and alpha_";
          message += std::to_string(j + 1);
          message += '_';
          message += std::to_string(i + 1);
          message += " = ";
          message += number(alpha[3 * j + i]);
          throw Refusal{GKT_INVALID_ARGUMENT, message};
        }
    gkt::Mixture mixture = gkt::make_mixture(dimension, species, 1.0);
    mixture.alpha.assign(alpha, alpha + 9);
    mixture.validate();
    auto t = std::make_unique<gkt_ternary_table>(mixture, order, nodes, tolerance);
    *out = t.release();
    return GKT_OK;
  });
}

void gkt_ternary_table_destroy(gkt_ternary_table* table) { std::unique_ptr<gkt_ternary_table> owned(table); }

gkt_status gkt_ternary_table_interpolation_error(const gkt_ternary_table* table, double* out) {
  return guarded([&] {
    require_pointer(table, "table");
    require_pointer(out, "out");
    *out = table->table.interpolation_error();
    return GKT_OK;
  });
}

gkt_status gkt_ternary_table_build_cost(const gkt_ternary_table* table, int* pieces, int* solves, double* seconds) {
  return guarded([&] {
    require_pointer(table, "table");
    require_pointer(pieces, "pieces");
    require_pointer(solves, "solves");
    require_pointer(seconds, "seconds");
    *pieces = table->table.pieces();
    *solves = table->table.build_solves();
    *seconds = table->table.build_seconds();
    return GKT_OK;
  });
}

gkt_status gkt_ternary_table_evaluate(const gkt_ternary_table* table, double fraction_1, double fraction_2,
                                      double number_density, double temperature, gkt_ternary_transport* out) {
  return guarded([&] {
    require_pointer(table, "table");
    require_pointer(out, "out");
    if (!gkt::c_api::covers(fraction_1, fraction_2, number_density, temperature))  // messages only on failure
      gkt::c_api::require_state(fraction_1, fraction_2, number_density, temperature, "");
    *out = gkt::c_api::to_c(table->table.evaluate(fraction_1, fraction_2, number_density, temperature));
    return GKT_OK;
  });
}

gkt_status gkt_ternary_table_evaluate_cells(const gkt_ternary_table* table, size_t cells, const double* fraction_1,
                                            const double* fraction_2, const double* number_density,
                                            const double* temperature, gkt_ternary_transport* out) {
  return guarded([&] {
    require_pointer(table, "table");
    require_pointer(out, "out");
    require_pointer(fraction_1, "fraction_1");
    require_pointer(fraction_2, "fraction_2");
    require_pointer(number_density, "number_density");
    require_pointer(temperature, "temperature");
    for (std::size_t i = 0; i < cells; ++i)
      if (!gkt::c_api::covers(fraction_1[i], fraction_2[i], number_density[i], temperature[i]))
        gkt::c_api::require_state(fraction_1[i], fraction_2[i], number_density[i], temperature[i],
                                  gkt::c_api::index(i));
    for (std::size_t i = 0; i < cells; ++i)
      out[i] = gkt::c_api::to_c(table->table.evaluate(fraction_1[i], fraction_2[i], number_density[i], temperature[i]));
    return GKT_OK;
  });
}

gkt_status gkt_ternary_table_evaluate_reduced(const gkt_ternary_table* table, double fraction_1, double fraction_2,
                                              gkt_ternary_transport* out) {
  return guarded([&] {
    require_pointer(table, "table");
    require_pointer(out, "out");
    gkt::c_api::require_fractions(fraction_1, fraction_2, "");
    *out = gkt::c_api::to_c(table->table.evaluate_reduced(fraction_1, fraction_2));
    return GKT_OK;
  });
}

}  // extern "C"
