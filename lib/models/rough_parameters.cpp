#include "models/rough_parameters.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace gkt::detail {

std::vector<ParameterSpec> rough_grain_parameters(const std::string& tangential,
                                                  const std::string& tangential_description) {
  return {dimension_spec("spatial dimension (3: spheres, three rotational degrees of freedom; 2: disks, one)"),
          restitution_spec("alpha", "normal restitution coefficient"),
          {tangential,
           ParameterSpec::Kind::real,
           Rational(-1),
           Rational(1),
           true,
           true,
           Rational(1),
           tangential_description,
           {}},
          {"moment_of_inertia",
           ParameterSpec::Kind::real,
           Rational(0),
           Rational(1),
           false,
           true,
           Rational(2, 5),
           "reduced moment of inertia kappa = 4I/(m sigma^2) (2/5 uniform spheres, 1/2 uniform disks)",
           {}}};
}

RoughGrain read_rough_grain(const std::vector<ParameterSpec>& schema, const ParameterPoint& point,
                            const std::string& tangential) {
  const SchemaPoint p(schema, point);
  return {p.number("dimension") == Rational(2) ? 2 : 3, p.number("alpha"), p.number(tangential),
          p.number("moment_of_inertia")};
}

void require_first_approximation(const OrderRequest& order, const std::string& model) {
  if (order.tolerance)
    throw std::invalid_argument("tolerance: the " + model + " model has the first approximation only: use order = 1");
  if (order.order != 1) throw std::invalid_argument("order: must be exactly 1, got " + std::to_string(order.order));
}

CoefficientValue first_approximation(double x) {
  CoefficientValue v;
  v.order = 1;
  v.exact = false;
  v.error_estimated = false;  // no higher order to estimate from
  v.defined = std::isfinite(x);
  v.converged = v.defined;
  v.value = v.defined ? Rational::from_double(x) : Rational(0);
  return v;
}

CoefficientValue rough_stability_value(const HcsStability& s, const std::string& name) {
  const double x = name == "critical_wavenumber_shear"  ? s.shear_wavenumber
                   : name == "critical_wavenumber_heat" ? s.heat_wavenumber
                                                        : s.critical_length;
  CoefficientValue v = first_approximation(x);
  if (std::isinf(x) && x > 0) {  // stable at every wave number: L_c* = +∞, value and error 0
    v.defined = v.converged = true;
    v.infinite = true;
  }
  return v;
}

bool is_rough_sonine_column(const std::string& name) {
  static constexpr std::array<const char*, 5> columns{"shear_viscosity", "bulk_viscosity", "thermal_conductivity",
                                                      "density_heat_coefficient", "cooling_rate_first_order"};
  return std::find(columns.begin(), columns.end(), name) != columns.end();
}

double rough_sonine_column(const RoughTransportValues& v, const std::string& name) {
  if (name == "shear_viscosity") return v.shear_viscosity;
  if (name == "bulk_viscosity") return v.bulk_viscosity;
  if (name == "thermal_conductivity") return v.thermal_conductivity;
  if (name == "density_heat_coefficient") return v.density_heat_coefficient;
  return v.cooling_rate_first_order;
}

}  // namespace gkt::detail
