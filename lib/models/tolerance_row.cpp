#include "gkt/models/tolerance_row.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>

namespace gkt {

namespace {
/// True if `v` is a value whose estimated error converges below `tolerance`.
bool meets(const CoefficientValue& v, const Rational& tolerance) {
  if (!v.defined || !v.converged) return false;
  if (v.infinite || !v.error_estimated) return true;  // exact +∞, or a value the model does not estimate
  return v.error < tolerance;
}
}  // namespace

ToleranceRow evaluate_tolerance_row(TransportModel& model, const ParameterPoint& point,
                                    const std::vector<std::string>& coefficients, const Rational& tolerance) {
  OrderRequest scan;
  scan.tolerance = tolerance;
  const std::vector<CoefficientValue> own = model.evaluate(point, coefficients, scan);
  ToleranceRow row;
  for (const auto& v : own) row.order = std::max(row.order, v.order);
  if (own.empty()) return row;
  OrderRequest at_row;
  at_row.order = row.order;
  at_row.row_tolerance = tolerance;
  std::vector<std::optional<CoefficientValue>> common(coefficients.size());
  try {
    const std::vector<CoefficientValue> all = model.evaluate(point, coefficients, at_row);
    std::copy(all.begin(), all.end(), common.begin());
  } catch (const std::invalid_argument&) {
    // The first pass accepted these parameters, so what the row's order can break is an order range: a
    // coefficient whose orders stop below the row's (e.g. the rough HCS columns, orders 1 … 3, beside
    // η* at 7). Each coefficient alone, then; one outside its range keeps its own stop.
    for (std::size_t k = 0; k < coefficients.size(); ++k) {
      try {
        common[k] = model.evaluate(point, {coefficients[k]}, at_row).front();
      } catch (const std::invalid_argument&) {
        common[k] = std::nullopt;
      }
    }
  }
  for (std::size_t k = 0; k < common.size(); ++k) {
    const bool stopped = own[k].converged;  // the coefficient's own scan met the tolerance
    CoefficientValue v = common[k] ? *common[k] : own[k];
    // At the row's order the estimate is (6.1)/(6.3) at a fixed order: it may miss the tolerance the
    // coefficient met at its own stop (a breakdown, a turn); the own stop is then the honest report.
    if (stopped && !meets(v, tolerance)) v = own[k];
    v.converged = stopped && meets(v, tolerance);
    row.values.push_back(v);
  }
  return row;
}

}  // namespace gkt
