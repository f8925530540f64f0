#include "gkt/evolution/hcs_stability.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "evolution/mixture_longitudinal_matrix.hpp"

namespace gkt {

std::array<std::array<std::complex<double>, 3>, 3> longitudinal_matrix(int dimension, double cooling_rate,
                                                                       double shear_viscosity,
                                                                       double thermal_conductivity,
                                                                       double density_heat_coefficient, double k,
                                                                       const StabilityDensity& dense) {
  const double d = dimension, a = cooling_rate, p = dense.pressure;
  const double kappa = (d + 2) / (2 * (d - 1)) * thermal_conductivity;  // theory.md (14.2)
  const double mu = (d + 2) / (2 * (d - 1)) * density_heat_coefficient;
  const double eta = (d - 1) / d * shear_viscosity + dense.bulk_viscosity / 2;
  const std::complex<double> i(0, 1);
  return {
      {{0.0, 0.0, -i * k},
       {-(a * (1 + dense.log_chi_derivative) + mu * k * k), -(a * dense.cooling_temperature_exponent + kappa * k * k),
        -(2 / d * p + dense.cooling_rate_first_order) * i * k},
       {-i * k / 2.0 * (p + dense.pressure_derivative), -i * k / 2.0 * p, a / 2 - eta * k * k}}};
}

double shear_critical_wavenumber(double cooling_rate, double shear_viscosity) {
  return std::sqrt(std::max(cooling_rate, 0.0) / shear_viscosity);
}

double critical_length(double largest_wavenumber) {
  return largest_wavenumber > 0 ? 2 * std::numbers::pi / largest_wavenumber : INFINITY;
}

HcsStability hcs_stability(int dimension, double cooling_rate, double shear_viscosity, double thermal_conductivity,
                           double density_heat_coefficient, const StabilityDensity& dense) {
  if (dimension != 2 && dimension != 3) throw std::invalid_argument("dimension: must be 2 or 3");
  if (!(shear_viscosity > 0) || !(thermal_conductivity > 0))
    throw std::invalid_argument("hcs_stability: transport coefficients must be positive");
  const double d = dimension, zeta = std::max(cooling_rate, 0.0), p = dense.pressure;
  HcsStability s;
  s.shear_wavenumber = shear_critical_wavenumber(cooling_rate, shear_viscosity);
  // det M = (k²/2)[(ζ*(1+λ) + U k²) p* − (λ_T ζ* + K k²)(p* + φ∂p*)] vanishes at (14.5), (14.6).
  const double kappa = (d + 2) / (2 * (d - 1)) * thermal_conductivity;
  const double mu = (d + 2) / (2 * (d - 1)) * density_heat_coefficient;
  const double longitudinal = p + dense.pressure_derivative;
  const double numerator =
      zeta * ((1 + dense.log_chi_derivative) * p - dense.cooling_temperature_exponent * longitudinal);
  const double denominator = kappa * longitudinal - mu * p;
  s.heat_wavenumber = numerator > 0 && denominator > 0 ? std::sqrt(numerator / denominator) : 0.0;
  s.critical_length = critical_length(std::max(s.shear_wavenumber, s.heat_wavenumber));
  return s;
}

MixtureStabilityInput mixture_stability_input(const Mixture& mixture, const MixtureNavierStokes& solver,
                                              const MixtureTransportValues& v) {
  MixtureStabilityInput in;
  in.dimension = mixture.dimension;
  for (const auto& sp : mixture.species) in.fraction.push_back(sp.fraction);
  in.cooling_rate = solver.cooling_state().cooling_rate;
  in.cooling_derivative = solver.cooling_sensitivity().cooling_rate;
  in.shear_viscosity = v.shear_viscosity;
  in.thermal_conductivity = v.thermal_conductivity;
  in.dufour = v.dufour;
  in.drift = v.drift;
  in.thermal_drift = v.thermal_drift;
  in.pressure = v.pressure;
  in.pressure_derivative = v.pressure_derivative;
  in.bulk_viscosity = v.bulk_viscosity;
  in.cooling_rate_first_order = v.cooling_rate_first_order;
  return in;
}

Eigen::MatrixXcd mixture_longitudinal_matrix(const MixtureStabilityInput& in, double k) {
  const auto s = static_cast<Eigen::Index>(in.fraction.size());
  const double d = in.dimension, z = in.cooling_rate, k2 = k * k;
  const double to_heat = (d + 2) / (2 * (d - 1));  // K = to_heat λ*, U_j = to_heat D''_j* (14.2)
  const double nu_d0 = d / (d + 2);                // ν0 D0/v̄²
  const std::complex<double> i(0, 1);
  Eigen::MatrixXcd m = Eigen::MatrixXcd::Zero(s + 2, s + 2);
  const Eigen::Index t = s, w = s + 1;
  for (Eigen::Index a = 0; a < s; ++a) {
    const auto A = static_cast<std::size_t>(a);
    for (Eigen::Index b = 0; b < s; ++b) {
      const auto B = static_cast<std::size_t>(b);
      m(a, b) = k2 * nu_d0 * in.drift[A * in.fraction.size() + B];  // −∇·(n_a w_a)/n_a
      m(t, b) -= k2 * nu_d0 * in.fraction[A] * in.drift[A * in.fraction.size() + B];
    }
    m(a, t) = k2 * nu_d0 * in.thermal_drift[A];
    m(a, w) = -i * k;
    m(t, t) -= k2 * nu_d0 * in.fraction[A] * in.thermal_drift[A];
    m(t, a) -= in.fraction[A] * in.cooling_derivative[A] + to_heat * in.dufour[A] * k2;
    // δp/(nT) = Σ_a x_a P_a ρ_a + p* θ (theory.md (18.13)); P_a = 1 in the dilute gas.
    const double pa = in.pressure_derivative.empty() ? 1.0 : in.pressure_derivative[A];
    m(w, a) = -i * k / 2.0 * in.fraction[A] * pa;
  }
  m(t, t) -= z / 2 + to_heat * in.thermal_conductivity * k2;
  m(t, w) = -(2 / d * in.pressure + in.cooling_rate_first_order) * i * k;
  m(w, t) = -i * k / 2.0 * in.pressure;
  m(w, w) = z / 2 - ((d - 1) / d * in.shear_viscosity + in.bulk_viscosity / 2) * k2;
  return m;
}

HcsStability mixture_hcs_stability(const MixtureStabilityInput& in) {
  if (!(in.shear_viscosity > 0) || !(in.thermal_conductivity > 0))
    throw std::invalid_argument("hcs_stability: transport coefficients must be positive");
  HcsStability out;
  out.shear_wavenumber = shear_critical_wavenumber(in.cooling_rate, in.shear_viscosity);
  // det M is a real polynomial of degree s + 2 in z = k²: interpolate it at z = 0 … s+2, drop the
  // powers of z that vanish identically (conservation), take the largest positive real root.
  const auto degree = static_cast<Eigen::Index>(in.fraction.size()) + 2;
  Eigen::MatrixXd vandermonde(degree + 1, degree + 1);
  Eigen::VectorXd values(degree + 1);
  for (Eigen::Index r = 0; r <= degree; ++r) {
    const double z = static_cast<double>(r);
    for (Eigen::Index c = 0; c <= degree; ++c) vandermonde(r, c) = std::pow(z, static_cast<double>(c));
    values(r) = mixture_longitudinal_matrix(in, std::sqrt(z)).determinant().real();
  }
  const Eigen::VectorXd coefficients = vandermonde.fullPivLu().solve(values);
  const double scale = coefficients.cwiseAbs().maxCoeff();
  Eigen::Index low = 0, high = degree;
  while (low <= degree && std::abs(coefficients(low)) <= 1e-10 * scale) ++low;
  while (high > low && std::abs(coefficients(high)) <= 1e-10 * scale) --high;
  double largest = 0;
  if (high > low) {
    const Eigen::Index n = high - low;  // companion matrix of Σ c_{low+j} z^j
    Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(n, n);
    for (Eigen::Index j = 1; j < n; ++j) companion(j, j - 1) = 1;
    for (Eigen::Index j = 0; j < n; ++j) companion(j, n - 1) = -coefficients(low + j) / coefficients(high);
    const Eigen::VectorXcd roots = companion.eigenvalues();
    for (const auto& r : roots)
      if (r.real() > 0 && std::abs(r.imag()) <= 1e-9 * std::abs(r)) largest = std::max(largest, r.real());
  }
  // The interpolated polynomial locates the root but amplifies rounding (~10³); polish it by the
  // secant method on det M itself, a simple root at k∥c*².
  if (largest > 0) {
    auto det = [&](double z) { return mixture_longitudinal_matrix(in, std::sqrt(z)).determinant().real(); };
    double z0 = largest, z1 = largest * (1 + 1e-6), f0 = det(z0), f1 = det(z1);
    for (int k = 0; k < 30 && f1 != f0 && std::abs(z1 - z0) > 1e-16 * z1; ++k) {
      const double z2 = z1 - f1 * (z1 - z0) / (f1 - f0);
      z0 = z1, f0 = f1, z1 = z2, f1 = det(z2);
    }
    if (std::abs(z1 / largest - 1) < 1e-6) largest = z1;  // keep the interpolated root if the secant wanders
  }
  out.heat_wavenumber = std::sqrt(largest);
  out.critical_length = critical_length(std::max(out.shear_wavenumber, out.heat_wavenumber));
  return out;
}

}  // namespace gkt
