// Private: the model factories the registry knows, and the order-selection rule they share.
#pragma once

#include <memory>
#include <string>

#include "gkt/models/transport_model.hpp"
#include "gkt/transport/common/sonine_solution.hpp"
#include "support/strings.hpp"

namespace gkt::detail {

std::unique_ptr<TransportModel> make_hard_sphere_model();
std::unique_ptr<TransportModel> make_smooth_inelastic_model();
std::unique_ptr<TransportModel> make_viscoelastic_model();
std::unique_ptr<TransportModel> make_mixture_model();
std::unique_ptr<TransportModel> make_rough_model();
std::unique_ptr<TransportModel> make_aggregation_model();

/// A value at one order as a model computes it: estimate plus whether it exists at all.
struct OrderValue {
  TruncationEstimate estimate;
  bool defined = true;
  bool exact = true;
};

/// Applies an OrderRequest: the fixed order, or the smallest order whose estimate converges
/// below the tolerance; if none does, the order with the smallest estimated error (optimal
/// truncation of an asymptotic series), flagged not converged. The scan stops once the estimated
/// error has grown for three successive orders past its minimum.
template <class ValueAt>
CoefficientValue choose_order(const OrderRequest& request, int max_order, ValueAt&& value_at) {
  auto to_value = [](const OrderValue& v, int order, bool converged) {
    return CoefficientValue{v.estimate.value, v.estimate.error, order, converged, v.exact, v.defined};
  };
  if (!request.tolerance) {
    const OrderValue v = value_at(request.order);
    return to_value(v, request.order, v.defined && v.estimate.converging);
  }
  int best = 0, growing = 0;
  OrderValue best_value{};
  for (int n = 1; n <= max_order; ++n) {
    const OrderValue v = value_at(n);
    if (!v.defined) continue;
    if (v.estimate.converging && v.estimate.error < *request.tolerance) return to_value(v, n, true);
    if (best == 0 || v.estimate.error < best_value.estimate.error) {
      best = n;
      best_value = v;
      growing = 0;
    } else if (++growing == 3) {
      break;  // the error grew three orders in a row past its minimum: an asymptotic series
    }
  }
  if (best == 0) return to_value(value_at(max_order), max_order, false);
  return to_value(best_value, best, false);
}

}  // namespace gkt::detail
