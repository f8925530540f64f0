// The C API of the binary mixture's per-cell table (include/gkt/gkt.h): BinaryTransportTable built
// from C arrays, evaluated in physical units as it is, and in reduced units through the reference
// gas of (m̄, σ̄) (docs/conventions.md, mixtures).
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "gkt/gkt.h"
#include "gkt/transport/common/reference_gas.hpp"
#include "gkt/transport/mixture/mixture.hpp"
#include "gkt/transport/mixture/mixture_transport_table.hpp"
#include "guard.hpp"
#include "table_common.hpp"

/// A binary's table and what the C layer needs to check states against it.
struct gkt_binary_table {
  gkt_binary_table(const gkt::Mixture& mixture, int order, int nodes, double max_packing, int packing_nodes,
                   double tolerance, std::array<double, 2> fraction_range, const gkt::MixtureReference& reference)
      : table(mixture, order, nodes, max_packing, packing_nodes, tolerance, fraction_range, reference),
        species(mixture, max_packing) {}
  gkt::BinaryTransportTable table;
  gkt::c_api::TableSpecies<2> species;
};

namespace gkt::c_api {
namespace {

/// Throws a Refusal unless fraction_1 is in [0, 1].
void require_fraction(double fraction_1, const std::string& field) {
  if (!(fraction_1 >= 0 && fraction_1 <= 1))
    throw Refusal{GKT_INVALID_ARGUMENT, refusal(field.c_str(), "", "a number in [0, 1]", fraction_1)};
}

/// Throws a Refusal (GKT_OUT_OF_RANGE) unless x_1 ∈ [0, 1] is within the table's fraction_range.
void require_covered_fraction(const gkt_binary_table& t, double fraction_1, const std::string& field) {
  const std::array<double, 2> range = t.table.fraction_range();
  if (!(fraction_1 >= range[0] && fraction_1 <= range[1]))
    throw Refusal{GKT_OUT_OF_RANGE, field + ": must be in [" + number(range[0]) + ", " + number(range[1]) +
                                        "] (the table's fraction_range), got " + number(fraction_1)};
}

/// True if (x_1, n, T) is a valid state the table covers (the checks of require_state, no message).
bool covers(const gkt_binary_table& t, double x1, double n, double temperature) {
  const std::array<double, 2> range = t.table.fraction_range();
  if (!(x1 >= range[0] && x1 <= range[1] && n > 0 && std::isfinite(n) && temperature > 0 && std::isfinite(temperature)))
    return false;
  return t.species.covers_packing({x1, 1 - x1}, n);
}

/// Throws a Refusal unless (x_1, n, T) is a state the table covers; suffix names the cell ("[3]").
void require_state(const gkt_binary_table& t, double x1, double n, double temperature, const std::string& suffix = "") {
  require_fraction(x1, "fraction_1" + suffix);
  require_covered_fraction(t, x1, "fraction_1" + suffix);
  require_positive(n, ("number_density" + suffix).c_str());
  require_positive(temperature, ("temperature" + suffix).c_str());
  require_packing_within(t.species.packing({x1, 1 - x1}, n), t.species.max_packing_fraction, suffix);
}

}  // namespace
}  // namespace gkt::c_api

using gkt::c_api::guarded;
using gkt::c_api::number;
using gkt::c_api::Refusal;
using gkt::c_api::require_pointer;

extern "C" {

gkt_status gkt_binary_table_create_about(int dimension, const double mass[2], const double diameter[2],
                                         const double alpha[4], int order, int nodes, double max_packing_fraction,
                                         int packing_nodes, double tolerance, const double fraction_range[2],
                                         const char* reference, int hcs_order, gkt_binary_table** out) {
  return guarded([&] {
    require_pointer(out, "out");
    const gkt::Mixture mixture = gkt::c_api::mixture_from_c(dimension, 2, mass, diameter, alpha);
    const gkt::MixtureReference about = gkt::c_api::reference_from_c(reference, hcs_order);
    auto t = std::make_unique<gkt_binary_table>(mixture, order, nodes, max_packing_fraction, packing_nodes, tolerance,
                                                fraction_range != nullptr
                                                    ? std::array<double, 2>{fraction_range[0], fraction_range[1]}
                                                    : std::array<double, 2>{0.0, 1.0},
                                                about);
    *out = t.release();
    return GKT_OK;
  });
}

gkt_status gkt_binary_table_create_to_tolerance(int dimension, const double mass[2], const double diameter[2],
                                                const double alpha[4], int order, int nodes,
                                                double max_packing_fraction, int packing_nodes, double tolerance,
                                                const double fraction_range[2], gkt_binary_table** out) {
  return gkt_binary_table_create_about(dimension, mass, diameter, alpha, order, nodes, max_packing_fraction,
                                       packing_nodes, tolerance, fraction_range, "maxwellian", 2, out);
}

gkt_status gkt_binary_table_create(int dimension, const double mass[2], const double diameter[2], const double alpha[4],
                                   int order, int nodes, double max_packing_fraction, int packing_nodes,
                                   gkt_binary_table** out) {
  return gkt_binary_table_create_to_tolerance(dimension, mass, diameter, alpha, order, nodes, max_packing_fraction,
                                              packing_nodes, 1e-3, nullptr, out);
}

void gkt_binary_table_destroy(gkt_binary_table* table) { std::unique_ptr<gkt_binary_table> owned(table); }

gkt_status gkt_binary_table_interpolation_error(const gkt_binary_table* table, double* out) {
  return guarded([&] {
    require_pointer(table, "table");
    require_pointer(out, "out");
    *out = table->table.interpolation_error();
    return GKT_OK;
  });
}

gkt_status gkt_binary_table_build_cost(const gkt_binary_table* table, int* intervals, int* solves, double* seconds) {
  return guarded([&] {
    require_pointer(table, "table");
    require_pointer(intervals, "intervals");
    require_pointer(solves, "solves");
    require_pointer(seconds, "seconds");
    *intervals = table->table.intervals();
    *solves = table->table.build_solves();
    *seconds = table->table.build_seconds();
    return GKT_OK;
  });
}

gkt_status gkt_binary_table_evaluate(const gkt_binary_table* table, double fraction_1, double number_density,
                                     double temperature, gkt_binary_transport* out) {
  return guarded([&] {
    require_pointer(table, "table");
    require_pointer(out, "out");
    if (!gkt::c_api::covers(*table, fraction_1, number_density, temperature))  // messages only on failure
      gkt::c_api::require_state(*table, fraction_1, number_density, temperature);
    *out = gkt::c_api::to_c<gkt_binary_transport>(table->table.evaluate(fraction_1, number_density, temperature));
    return GKT_OK;
  });
}

gkt_status gkt_binary_table_evaluate_cells(const gkt_binary_table* table, size_t cells, const double* fraction_1,
                                           const double* number_density, const double* temperature,
                                           gkt_binary_transport* out) {
  return guarded([&] {
    require_pointer(table, "table");
    require_pointer(out, "out");
    require_pointer(fraction_1, "fraction_1");
    require_pointer(number_density, "number_density");
    require_pointer(temperature, "temperature");
    const gkt_binary_table& t = *table;
    for (std::size_t i = 0; i < cells; ++i) {
      if (!gkt::c_api::covers(t, fraction_1[i], number_density[i], temperature[i]))  // messages only on failure
        gkt::c_api::require_state(t, fraction_1[i], number_density[i], temperature[i], gkt::c_api::cell_index(i));
    }
    for (std::size_t i = 0; i < cells; ++i)
      out[i] = gkt::c_api::to_c<gkt_binary_transport>(
          table->table.evaluate(fraction_1[i], number_density[i], temperature[i]));
    return GKT_OK;
  });
}

gkt_status gkt_binary_table_evaluate_reduced(const gkt_binary_table* table, double fraction_1, double packing_fraction,
                                             gkt_binary_transport* out) {
  return guarded([&] {
    require_pointer(table, "table");
    require_pointer(out, "out");
    gkt::c_api::require_fraction(fraction_1, "fraction_1");
    const gkt_binary_table& t = *table;
    gkt::c_api::require_covered_fraction(t, fraction_1, "fraction_1");
    gkt::c_api::require_reduced_packing(packing_fraction, t.species.max_packing_fraction);
    // A state of this φ at T = 1 (n = 1 when dilute, where n drops out of every reduced value),
    // evaluated physically and divided by the reference gas of (m̄, σ̄) at n, T.
    const double x[2] = {fraction_1, 1 - fraction_1};
    const double n = packing_fraction > 0 ? packing_fraction / t.species.packing({x[0], x[1]}, 1.0) : 1.0;
    const double temperature = 1;
    const gkt::BinaryTransport v = t.table.evaluate(fraction_1, n, temperature);
    const auto& sp = t.species;
    const double mbar = x[0] * sp.mass[0] + x[1] * sp.mass[1], sbar = x[0] * sp.diameter[0] + x[1] * sp.diameter[1];
    const gkt::ReferenceGas ref = gkt::reference_gas(sp.dimension, mbar, sbar, n, temperature);
    gkt_binary_transport r = gkt::c_api::to_c<gkt_binary_transport>(v);
    r.cooling_rate /= ref.collision_frequency;
    r.shear_viscosity /= ref.viscosity;
    r.thermal_conductivity /= ref.conductivity;
    for (double& d : r.mutual_diffusion) d /= n * ref.self_diffusion;
    for (std::size_t i = 0; i < 2; ++i) {
      r.thermal_diffusion[i] /= ref.self_diffusion;
      r.pressure_diffusion[i] /= ref.self_diffusion;
      r.dufour[i] /= ref.conductivity / temperature;
    }
    r.pressure /= n * temperature;
    r.bulk_viscosity /= ref.viscosity;
    *out = r;
    return GKT_OK;
  });
}

}  // extern "C"
