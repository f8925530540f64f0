// The C API of the ternary's per-cell table, dilute or dense (include/gkt/gkt.h): TernaryTransportTable
// built from C arrays (masses, diameters, the 3 × 3 restitution matrix; φ_max and φ nodes when dense),
// evaluated in physical or reduced units (docs/conventions.md, mixtures; docs/theory.md §17.8, §18.10).
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "gkt/gkt.h"
#include "gkt/transport/mixture/mixture.hpp"
#include "gkt/transport/mixture/ternary_transport_table.hpp"
#include "guard.hpp"
#include "table_common.hpp"

/// A ternary's table and what the C layer needs to check states against it.
struct gkt_ternary_table {
  gkt_ternary_table(const gkt::Mixture& mixture, int order, int nodes, int max_nodes, double tolerance,
                    double max_packing, int packing_nodes, const gkt::MixtureReference& reference)
      : table(mixture, order, nodes, tolerance, max_nodes, max_packing, packing_nodes, reference),
        species(mixture, max_packing) {}
  gkt::TernaryTransportTable table;
  gkt::c_api::TableSpecies<3> species;
};

namespace gkt::c_api {
namespace {

/// True if (x_1, x_2, n, T) is a state the table covers (the checks of require_state, no message).
bool covers(const gkt_ternary_table& t, double x1, double x2, double n, double temperature) {
  return x1 >= 0 && x1 <= 1 && x2 >= 0 && x2 <= 1 - x1 && n > 0 && std::isfinite(n) && temperature > 0 &&
         std::isfinite(temperature) && t.species.covers_packing({x1, x2, 1 - x1 - x2}, n);
}

/// Throws a Refusal unless x_1 ∈ [0, 1] and x_2 ∈ [0, 1 − x_1]; suffix names the cell ("[3]").
void require_fractions(double x1, double x2, const std::string& suffix) {
  if (!(x1 >= 0 && x1 <= 1))
    throw Refusal{GKT_INVALID_ARGUMENT, refusal("fraction_1", suffix, "a number in [0, 1]", x1)};
  if (!(x2 >= 0 && x2 <= 1 - x1))
    throw Refusal{GKT_INVALID_ARGUMENT, refusal("fraction_2", suffix, "a number in [0, 1 - fraction_1]", x2)};
}

/// Throws a Refusal unless (x_1, x_2, n, T) is a state the table covers (GKT_OUT_OF_RANGE for a φ above a
/// dense table's max_packing_fraction).
void require_state(const gkt_ternary_table& t, double x1, double x2, double n, double temperature,
                   const std::string& suffix) {
  require_fractions(x1, x2, suffix);
  if (!(n > 0 && std::isfinite(n)))
    throw Refusal{GKT_INVALID_ARGUMENT, refusal("number_density", suffix, "a finite number > 0", n)};
  if (!(temperature > 0 && std::isfinite(temperature)))
    throw Refusal{GKT_INVALID_ARGUMENT, refusal("temperature", suffix, "a finite number > 0", temperature)};
  require_packing_within(t.species.packing({x1, x2, 1 - x1 - x2}, n), t.species.max_packing_fraction, suffix);
}

}  // namespace
}  // namespace gkt::c_api

using gkt::c_api::guarded;
using gkt::c_api::number;
using gkt::c_api::Refusal;
using gkt::c_api::require_pointer;

extern "C" {

gkt_status gkt_ternary_table_create_about(int dimension, const double mass[3], const double diameter[3],
                                          const double alpha[9], int order, int nodes, int max_nodes, double tolerance,
                                          double max_packing_fraction, int packing_nodes, const char* reference,
                                          int hcs_order, gkt_ternary_table** out) {
  return guarded([&] {
    require_pointer(out, "out");
    const gkt::Mixture mixture = gkt::c_api::mixture_from_c(dimension, 3, mass, diameter, alpha);
    const gkt::MixtureReference about = gkt::c_api::reference_from_c(reference, hcs_order);
    auto t = std::make_unique<gkt_ternary_table>(mixture, order, nodes, max_nodes, tolerance, max_packing_fraction,
                                                 packing_nodes, about);
    *out = t.release();
    return GKT_OK;
  });
}

gkt_status gkt_ternary_table_create_dense(int dimension, const double mass[3], const double diameter[3],
                                          const double alpha[9], int order, int nodes, int max_nodes, double tolerance,
                                          double max_packing_fraction, int packing_nodes, gkt_ternary_table** out) {
  return gkt_ternary_table_create_about(dimension, mass, diameter, alpha, order, nodes, max_nodes, tolerance,
                                        max_packing_fraction, packing_nodes, "maxwellian", 2, out);
}

gkt_status gkt_ternary_table_create(int dimension, const double mass[3], const double diameter[3],
                                    const double alpha[9], int order, int nodes, double tolerance,
                                    gkt_ternary_table** out) {
  return gkt_ternary_table_create_dense(dimension, mass, diameter, alpha, order, nodes, 33, tolerance, 0.0, 5, out);
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
    if (!gkt::c_api::covers(*table, fraction_1, fraction_2, number_density, temperature))  // messages only on failure
      gkt::c_api::require_state(*table, fraction_1, fraction_2, number_density, temperature, "");
    *out = gkt::c_api::to_c<gkt_ternary_transport>(
        table->table.evaluate(fraction_1, fraction_2, number_density, temperature));
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
      if (!gkt::c_api::covers(*table, fraction_1[i], fraction_2[i], number_density[i], temperature[i]))
        gkt::c_api::require_state(*table, fraction_1[i], fraction_2[i], number_density[i], temperature[i],
                                  gkt::c_api::cell_index(i));
    for (std::size_t i = 0; i < cells; ++i)
      out[i] = gkt::c_api::to_c<gkt_ternary_transport>(
          table->table.evaluate(fraction_1[i], fraction_2[i], number_density[i], temperature[i]));
    return GKT_OK;
  });
}

gkt_status gkt_ternary_table_evaluate_reduced(const gkt_ternary_table* table, double fraction_1, double fraction_2,
                                              gkt_ternary_transport* out) {
  return gkt_ternary_table_evaluate_reduced_dense(table, fraction_1, fraction_2, 0.0, out);
}

gkt_status gkt_ternary_table_evaluate_reduced_dense(const gkt_ternary_table* table, double fraction_1,
                                                    double fraction_2, double packing_fraction,
                                                    gkt_ternary_transport* out) {
  return guarded([&] {
    require_pointer(table, "table");
    require_pointer(out, "out");
    gkt::c_api::require_fractions(fraction_1, fraction_2, "");
    gkt::c_api::require_reduced_packing(packing_fraction, table->species.max_packing_fraction);
    *out = gkt::c_api::to_c<gkt_ternary_transport>(
        table->table.evaluate_reduced(fraction_1, fraction_2, packing_fraction));
    return GKT_OK;
  });
}

}  // extern "C"
