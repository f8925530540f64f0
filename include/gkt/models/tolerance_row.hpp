// One row of a tolerance scan for the front ends (`gkt table`, the Python module): which order each
// coefficient is reported at, and which of them miss the tolerance (docs/conventions.md, "Tables").
#pragma once

#include <string>
#include <vector>

#include "gkt/algebra/rational.hpp"
#include "gkt/models/parameter_spec.hpp"
#include "gkt/models/transport_model.hpp"

namespace gkt {

/// The coefficients of one parameter point scanned to a tolerance.
struct ToleranceRow {
  /// Per requested coefficient, as reported: `order` is the order of that value, `converged` true only if
  /// its reported error is an estimate below the tolerance.
  std::vector<CoefficientValue> values;
  /// The row's order: the smallest at which every coefficient's own scan stopped (the largest stop).
  int order = 0;
};

/// Returns the row of `coefficients` at `point` scanned to `tolerance` with `model`: each coefficient at the
/// row's order (the largest of their own stops, re-evaluated there with OrderRequest::row_tolerance) if its
/// estimated error there converges below the tolerance, else at its own stop if that met the tolerance
/// (e.g. a mode that breaks down between the two orders, or a value at a turning point: theory.md §10.6),
/// else at the row's order flagged not converged. A coefficient whose order range ends below the row's order
/// (the model refuses it there with std::invalid_argument) is reported at its own stop.
ToleranceRow evaluate_tolerance_row(TransportModel& model, const ParameterPoint& point,
                                    const std::vector<std::string>& coefficients, const Rational& tolerance);

}  // namespace gkt
