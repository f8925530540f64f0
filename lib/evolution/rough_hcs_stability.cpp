#include "gkt/evolution/rough_hcs_stability.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Eigenvalues>

namespace gkt {

namespace {

void check(const RoughStabilityInput& in) {
  if (in.dimension != 2 && in.dimension != 3) throw std::invalid_argument("dimension: must be 2 or 3");
  if (!(in.temperature_ratio > 0))
    throw std::invalid_argument("temperature_ratio: must be > 0 (+inf: the spin decoupled)");
  if (!(in.shear_viscosity > 0) || !std::isfinite(in.shear_viscosity))
    throw std::invalid_argument("shear_viscosity: must be a finite number > 0");
  if (!(in.thermal_conductivity > 0) || !std::isfinite(in.thermal_conductivity))
    throw std::invalid_argument("thermal_conductivity: must be a finite number > 0");
}

/// The four-field analysis also needs the relaxation rate Γ* of θ (theory.md (19.17)).
void check_with_spin(const RoughStabilityInput& in) {
  check(in);
  if (!std::isinf(in.temperature_ratio) && (!(in.relaxation_rate > 0) || !std::isfinite(in.relaxation_rate)))
    throw std::invalid_argument("relaxation_rate: must be a finite number > 0 (theory.md (19.17))");
  if (!std::isinf(in.temperature_ratio) && std::isnan(in.cooling_split_slope) &&
      (!std::isfinite(in.cooling_rate_first_order) || !std::isfinite(in.cooling_rate)))
    throw std::invalid_argument("cooling_rate_first_order: must be finite");
  if (!std::isinf(in.temperature_ratio) && (std::isinf(in.cooling_split_slope) || !std::isfinite(in.cooling_rate)))
    throw std::invalid_argument("cooling_split_slope: must be finite (or NaN: from cooling_rate_first_order)");
}

/// Returns the eigenvalues of a square complex matrix, ordered by decreasing real part.
template <int N>
std::array<std::complex<double>, N> ordered_eigenvalues(const std::array<std::array<std::complex<double>, N>, N>& m) {
  Eigen::Matrix<std::complex<double>, N, N> e;
  for (int r = 0; r < N; ++r)
    for (int c = 0; c < N; ++c) e(r, c) = m[r][c];
  const auto values = Eigen::ComplexEigenSolver<Eigen::Matrix<std::complex<double>, N, N>>(e, false).eigenvalues();
  std::array<std::complex<double>, N> out;
  for (int i = 0; i < N; ++i) out[i] = values(i);
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.real() > b.real(); });
  return out;
}

/// True when the spin is decoupled (θ = +∞, β = −1): T_t is the hydrodynamic temperature.
bool spin_decoupled(const RoughStabilityInput& in) { return std::isinf(in.temperature_ratio); }

}  // namespace

double rough_translational_share(int dimension, double temperature_ratio) {
  if (std::isinf(temperature_ratio)) return 1.0;
  const double d = dimension, d_r = dimension == 3 ? 3.0 : 1.0;
  return d / (d + d_r * temperature_ratio);
}

std::array<std::array<std::complex<double>, 3>, 3> rough_longitudinal_matrix(const RoughStabilityInput& in, double k) {
  check(in);
  const double d = in.dimension, a = in.cooling_rate;
  const double s = rough_translational_share(in.dimension, in.temperature_ratio);
  const bool decoupled = spin_decoupled(in);
  const double bulk = decoupled ? 0.0 : in.bulk_viscosity;
  const double zeta_u = decoupled ? 0.0 : in.cooling_rate_first_order;
  // theory.md (19.31): K, U carry the share s (∇T_t = τ_t∇T, heat capacity (d + d_r)/2), the work
  // term 2τ_t/(d + d_r) = 2s/d, the longitudinal viscosity the bulk viscosity.
  const double heat = s * (d + 2) / (2 * (d - 1));
  const double kappa = heat * in.thermal_conductivity, mu = heat * in.density_heat_coefficient;
  const double eta = (d - 1) / d * in.shear_viscosity + bulk / 2;
  const std::complex<double> i(0, 1);
  return {{{0.0, 0.0, -i * k},
           {-(a + mu * k * k), -(a / 2 + kappa * k * k), -(2 * s / d + zeta_u) * i * k},
           {-i * k / 2.0, -i * k / 2.0, a / 2 - eta * k * k}}};
}

std::array<std::array<std::complex<double>, 4>, 4> rough_longitudinal_matrix_with_spin(const RoughStabilityInput& in,
                                                                                       double k) {
  check_with_spin(in);
  const std::complex<double> i(0, 1), zero(0, 0);
  std::array<std::array<std::complex<double>, 4>, 4> out{};
  if (spin_decoupled(in)) {
    // θ = +∞ (β = −1): (ρ, δT_t/T_t, w∥) obey the smooth gas's (14.2) ((19.31) with s = 1, η_b = ζ_U = 0) and
    // δT_r/T_r is neither cooled nor worked on (the rotational heat flux is not in the closure, theory.md §19.15.1).
    const auto smooth = rough_longitudinal_matrix(in, k);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) out[r][c] = smooth[r][c];
    return out;
  }
  const double d = in.dimension, a = in.cooling_rate, gamma = in.relaxation_rate;
  const double s = rough_translational_share(in.dimension, in.temperature_ratio);
  // theory.md (19.37): ∂(ζ/ν0)/∂δ at fixed n, T, from ζ_U = Δ ∂(ζ/ν0)/∂δ and Δ = (2/d)/(ζ*/2 + Γ*) of (19.18).
  // About the Sonine HCS the slope of the cumulant rates is given (theory.md (19.142)).
  const double cooling_split = std::isnan(in.cooling_split_slope)
                                   ? in.cooling_rate_first_order * d * (a / 2 + gamma) / 2
                                   : in.cooling_split_slope;
  const double heat = s * (d + 2) / (2 * (d - 1));
  const double kappa = heat * in.thermal_conductivity, mu = heat * in.density_heat_coefficient;
  const double eta = (d - 1) / d * in.shear_viscosity;  // no bulk viscosity: it is the split δ's response
  // theory.md (19.36): the pressure nT_t with δT_t/T_t = ϑ − (1 − s)δ; the split relaxes at Γ* and is driven by the
  // work on the translation alone.
  out[0] = {zero, zero, -i * k, zero};
  out[1] = {-(a + mu * k * k), -(a / 2 + kappa * k * k), -(2 * s / d) * i * k, std::complex<double>(-cooling_split)};
  out[2] = {-i * k / 2.0, -i * k / 2.0, a / 2 - eta * k * k, i * k * (1 - s) / 2.0};
  out[3] = {zero, zero, (2 / d) * i * k, std::complex<double>(-gamma)};
  return out;
}

std::array<std::complex<double>, 4> rough_longitudinal_modes_with_spin(const RoughStabilityInput& in, double k) {
  return ordered_eigenvalues<4>(rough_longitudinal_matrix_with_spin(in, k));
}

std::array<std::complex<double>, 3> rough_longitudinal_modes(const RoughStabilityInput& in, double k) {
  return ordered_eigenvalues<3>(rough_longitudinal_matrix(in, k));
}

HcsStability rough_hcs_stability_with_spin(const RoughStabilityInput& in) {
  check_with_spin(in);
  HcsStability out;
  out.shear_wavenumber = shear_critical_wavenumber(in.cooling_rate, in.shear_viscosity);
  // Without cooling (ζ* ≤ 0: α = β = 1) no mode grows: the scan would only see round-off. With κ* ≤ μ* (disks at
  // α ≤ 0.3, first Sonine; theory.md §19.15) det M₄ = −Γ* det M₃ never vanishes and a real mode grows at every k*:
  // no crossing, reported as 0 like the three-field value.
  if (!(in.cooling_rate > 0) || !(in.thermal_conductivity > in.density_heat_coefficient)) {
    out.critical_length = critical_length(out.shear_wavenumber);
    return out;
  }
  // The largest Re λ of the longitudinal modes; a crossing is located by a geometric scan from the
  // three-field estimate's scale down and up, then bisection (theory.md §19.15.1).
  const auto growth = [&in](double k) { return rough_longitudinal_modes_with_spin(in, k)[0].real(); };
  const double scale = std::max({rough_hcs_stability(in).heat_wavenumber, out.shear_wavenumber, 1e-3});
  // Above k_top every mode is damped: the viscous, conductive and relaxation terms dominate ζ*/2.
  double k_top = 64 * scale;
  int guard = 0;
  while (growth(k_top) > 0 && guard++ < 40) k_top *= 2;
  if (growth(k_top) > 0) throw std::invalid_argument("thermal_conductivity: no damping at large k*");
  // Scan downwards for the first k with a growing mode (the largest unstable k).
  const int steps = 4096;
  const double k_low = 1e-6 * scale;
  double upper = k_top, lower = 0;
  bool found = false;
  for (int j = 1; j <= steps; ++j) {
    const double k = k_top * std::pow(k_low / k_top, static_cast<double>(j) / steps);
    if (growth(k) > 0) {
      lower = k;
      found = true;
      break;
    }
    upper = k;
  }
  if (found) {
    for (int j = 0; j < 200 && upper - lower > 1e-13 * upper; ++j) {
      const double mid = (lower + upper) / 2;
      (growth(mid) > 0 ? lower : upper) = mid;
    }
    out.heat_wavenumber = (lower + upper) / 2;
  }
  out.critical_length = critical_length(std::max(out.shear_wavenumber, out.heat_wavenumber));
  return out;
}

HcsStability rough_hcs_stability(const RoughStabilityInput& in) {
  check(in);
  const double d = in.dimension, zeta = std::max(in.cooling_rate, 0.0);
  const double s = rough_translational_share(in.dimension, in.temperature_ratio);
  HcsStability out;
  out.shear_wavenumber = shear_critical_wavenumber(in.cooling_rate, in.shear_viscosity);
  // det M = (k²/2)[ζ*/2 − s((d+2)/(2(d−1)))(κ* − μ*)k²] vanishes at (19.32).
  const double denominator = s * (d + 2) * (in.thermal_conductivity - in.density_heat_coefficient);
  const double numerator = (d - 1) * zeta;
  out.heat_wavenumber = numerator > 0 && denominator > 0 ? std::sqrt(numerator / denominator) : 0.0;
  out.critical_length = critical_length(std::max(out.shear_wavenumber, out.heat_wavenumber));
  return out;
}

}  // namespace gkt
