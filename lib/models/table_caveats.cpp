// Caveats of a whole table beyond its error columns (docs/conventions.md, "Warnings").
#include "gkt/models/table_caveats.hpp"

#include <algorithm>

#include "gkt/models/transport_model.hpp"
#include "rough_parameters.hpp"

namespace gkt {

std::vector<std::string> table_caveats(const std::string& model, const std::map<std::string, std::string>& choices,
                                       const std::vector<std::string>& coefficients, int highest_order,
                                       bool tolerance) {
  std::vector<std::string> out;
  const auto choice = [&choices](const std::string& key, const std::string& fallback) {
    const auto it = choices.find(key);
    return it == choices.end() ? fallback : it->second;
  };
  // Model rough: the Sonine solver's default trial space is the translation x spin products; the aligned-spin and
  // chiral families of theory.md §19.21, §19.22 move eta*, kappa*, mu* by percents (3D alpha = 0.9, beta = 0.5:
  // eta* +1.9 %, kappa* +3.4 %, mu* +7.8 %), far beyond the product space's Sonine error. Order 1 alone is the
  // first approximation, whose error is not estimated (nan): nothing to qualify there.
  if (model == "rough" && choice("trial_space", "products") == "products" && (highest_order >= 2 || tolerance)) {
    const auto& critical = stability_coefficient_names();
    std::string columns;
    for (const auto& c : coefficients)
      if (detail::is_rough_sonine_column(c) || std::find(critical.begin(), critical.end(), c) != critical.end())
        columns += (columns.empty() ? "" : ", ") + c;
    if (!columns.empty()) {
      const bool maxwellian = choice("reference_state", "maxwellian") == "maxwellian";
      out.push_back("trial_space: the _error of " + columns +
                    " covers the Sonine truncation in the product trial space only; " +
                    (maxwellian ? std::string("trial_space = \"full\" adds the aligned and chiral families "
                                              "(theory.md 19.21-19.22)")
                                : std::string("it leaves out the aligned and chiral families (theory.md "
                                              "19.21-19.22; trial_space = \"full\", about Maxwellians only)")) +
                    ", which move these coefficients by percents");
    }
  }
  return out;
}

}  // namespace gkt
