// What the C wrappers of the binary and ternary tables share (table_common.hpp).
#include "table_common.hpp"

#include <vector>

namespace gkt::c_api {

Mixture mixture_from_c(int dimension, std::size_t species, const double* mass, const double* diameter,
                       const double* alpha) {
  require_pointer(mass, "mass");
  require_pointer(diameter, "diameter");
  require_pointer(alpha, "alpha");
  if (dimension != 2 && dimension != 3)
    throw Refusal{GKT_INVALID_ARGUMENT, "dimension: must be 2 or 3, got " + std::to_string(dimension)};
  std::vector<Species> list(species);
  for (std::size_t i = 0; i < species; ++i) {
    const std::string k = std::to_string(i + 1);
    require_positive(mass[i], ("mass_" + k).c_str());
    require_positive(diameter[i], ("diameter_" + k).c_str());
    list[i] = {mass[i], diameter[i], 1.0 / static_cast<double>(species), ""};
  }
  list.back().fraction = 1 - static_cast<double>(species - 1) / static_cast<double>(species);
  for (std::size_t i = 0; i < species; ++i)
    for (std::size_t j = 0; j < species; ++j)
      require_restitution(alpha[species * i + j],
                          ("alpha_" + std::to_string(i + 1) + "_" + std::to_string(j + 1)).c_str());
  for (std::size_t i = 0; i < species; ++i)
    for (std::size_t j = i + 1; j < species; ++j)
      if (alpha[species * i + j] != alpha[species * j + i]) {
        const std::string ij = std::to_string(i + 1) + "_" + std::to_string(j + 1);
        const std::string ji = std::to_string(j + 1) + "_" + std::to_string(i + 1);
        std::string message = "alpha: the restitution matrix must be symmetric, got alpha_";
        message += ij;
        message += " = ";
        message += number(alpha[species * i + j]);
        message += " and alpha_";
        message += ji;
        message += " = ";
        message += number(alpha[species * j + i]);
        throw Refusal{GKT_INVALID_ARGUMENT, message};
      }
  Mixture mixture = make_mixture(dimension, list, 1.0);
  mixture.alpha.assign(alpha, alpha + species * species);
  mixture.validate();
  return mixture;
}

MixtureReference reference_from_c(const char* reference, int hcs_order) {
  require_pointer(reference, "reference");
  const std::string name(reference);
  if (name == "maxwellian") return {};
  if (name == "linear") return {MixtureHcsScheme::linear, hcs_order};
  if (name == "nonlinear") return {MixtureHcsScheme::nonlinear, hcs_order};
  throw Refusal{GKT_INVALID_ARGUMENT,
                "reference: must be \"maxwellian\", \"linear\" or \"nonlinear\", got \"" + name + "\""};
}

std::string cell_index(std::size_t i) {
  std::string out(1, '[');
  out += std::to_string(i);
  out += ']';
  return out;
}

std::string refusal(const char* field, const std::string& suffix, const char* range, double x) {
  std::string out(field);
  out += suffix;
  out += ": must be ";
  out += range;
  out += ", got ";
  out += number(x);
  return out;
}

void require_packing_within(double phi, double max_packing_fraction, const std::string& suffix) {
  if (max_packing_fraction > 0 && phi > max_packing_fraction) {
    std::string message = "number_density";
    message += suffix;
    message += ": the packing fraction n v_d sum_i x_i sigma_i^d = ";
    message += number(phi);
    message += " exceeds the table's max_packing_fraction ";
    message += number(max_packing_fraction);
    throw Refusal{GKT_OUT_OF_RANGE, message};
  }
}

void require_reduced_packing(double phi, double max_packing_fraction) {
  if (phi >= 0 && phi <= max_packing_fraction) return;
  if (phi > max_packing_fraction && std::isfinite(phi))
    throw Refusal{GKT_OUT_OF_RANGE, "packing_fraction: must be in [0, " + number(max_packing_fraction) +
                                        "] (the table's max_packing_fraction), got " + number(phi)};
  throw Refusal{GKT_INVALID_ARGUMENT, "packing_fraction: must be a number >= 0, got " + number(phi)};
}

}  // namespace gkt::c_api
