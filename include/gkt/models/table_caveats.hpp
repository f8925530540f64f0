// What a table's error columns do not cover, said once per table by the front ends (`gkt table`, `gkt stability`,
// the Python module) as warnings (docs/conventions.md, "Warnings").
#pragma once

#include <map>
#include <string>
#include <vector>

namespace gkt {

/// Returns the caveats (one warning line each, no prefix) of a table of `coefficients` of model `model` with the
/// scene's choice keys `choices` (absent: the default), at Sonine orders up to `highest_order` or, if `tolerance`,
/// scanned to a tolerance: for model rough with trial_space = "products" and a Navier-Stokes or stability column
/// at order >= 2 or a tolerance, that the `_error` columns measure the Sonine truncation in the product trial space
/// only (theory.md §19.21, §19.22); empty otherwise.
std::vector<std::string> table_caveats(const std::string& model, const std::map<std::string, std::string>& choices,
                                       const std::vector<std::string>& coefficients, int highest_order, bool tolerance);

}  // namespace gkt
