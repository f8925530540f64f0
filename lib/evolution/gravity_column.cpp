// The steady dilute granular column in gravity (docs/theory.md §23; seed 001 §3.3.2, eq. (17)).
#include "gkt/evolution/gravity_column.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

namespace gkt {

namespace {

/// The constants of theory.md (23.3)–(23.5) in reduced units (m = σ = g = 1, T in mgσ).
struct ColumnConstants {
  double viscosity_factor;     ///< E: η0 = E √T, E = (d+2)/(8 c_d)
  double conductivity_factor;  ///< K: κ0 = K √T, K = d(d+2)/(2(d−1)) E
  double a;                    ///< 2(κ* − μ*)
  double mu;                   ///< μ*
  double b;                    ///< d ζ*/(2 E K), the sink of (23.5)
  double cross_section;        ///< π (d = 3), 2 (d = 2): the collision cross-section / σ^{d−1}
};

ColumnConstants constants(const GravityColumnProblem& p) {
  const int d = p.dimension;
  const double c_d = std::pow(std::numbers::pi, (d - 1) / 2.0) / std::tgamma(d / 2.0);
  const double e = (d + 2) / (8 * c_d);
  const double k = d * (d + 2) / (2.0 * (d - 1)) * e;
  const auto& t = p.transport;
  return {e,
          k,
          2 * (t.thermal_conductivity - t.density_heat_coefficient),
          t.density_heat_coefficient,
          d * t.cooling_rate / (2 * e * k),
          d == 3 ? std::numbers::pi : 2.0};
}

/// s = √T normalised to s = 1 at the floor, on the nodes u_i = U(y_i), y uniform with step k,
/// i = 0 (lid, u = ln P) … M (floor, u = ln(P + N)): a s_uu + μ* s_u − b e^{2u} s = 0 with the
/// elastic lid a s_u + μ* s = 0 (theory.md (23.5)). The map equidistributes the monitor
/// w(u) = μ*/a + 1/100 + √(b/a) e^u (theory.md §23.3): the slow power law of the dilute top and the
/// floor's boundary layer of width √(a/b)/x in u get comparable shares of the nodes.
struct Shape {
  double step = 0;                ///< k, the step in y
  std::vector<double> u, map, s;  ///< u_i, U'(y_i) = du/dy = 1/w(u_i), s_i
  bool failed = false;            ///< no positive finite √T on this grid (no regular column)
};

struct Monitor {
  double base, lambda;
  [[nodiscard]] double weight(double u) const { return base + lambda * std::exp(u); }
  [[nodiscard]] double primitive(double u) const { return base * u + lambda * std::exp(u); }
};

void gsl_check(int status, const char* what) {
  if (status != GSL_SUCCESS)
    throw std::runtime_error(std::string("gravity column: ") + what + ": " + gsl_strerror(status));
}

Shape solve_shape(const ColumnConstants& c, double lid_pressure, double particles, int intervals) {
  const int m = intervals;
  const double a = c.a, mu = c.mu;
  const Monitor w{mu / a + 0.01, std::sqrt(c.b / a)};
  const double u0 = std::log(lid_pressure), u1 = std::log(lid_pressure + particles);
  const double y0 = w.primitive(u0), y1 = w.primitive(u1);
  Shape shape;
  shape.step = (y1 - y0) / m;
  const double k = shape.step;
  shape.u.resize(m + 1);
  shape.map.resize(m + 1);
  shape.u[m] = u1;
  for (int i = m - 1; i >= 0; --i) {  // Newton from the right: y(u) is increasing and convex
    const double target = y0 + i * k;
    double u = shape.u[i + 1];
    for (int it = 0; it < 100; ++it) {
      const double du = (w.primitive(u) - target) / w.weight(u);
      u -= du;
      if (std::abs(du) <= 1e-15 * (1 + std::abs(u))) break;
    }
    shape.u[i] = i == 0 ? u0 : u;
  }
  for (int i = 0; i <= m; ++i) shape.map[i] = 1 / w.weight(shape.u[i]);
  // The tridiagonal rows (sub, diag, sup) = 0 except the floor's; Thomas elimination without
  // pivoting (the rows are diagonally dominant for b ≥ 0 and small k). A zero or non-finite pivot
  // marks the shape failed: this runs inside GSL's root finder, which must not see an exception.
  std::vector<double> diag(m), sup(m, 0), sub(m, 0), rhs(m, 0);
  for (int i = 0; i < m; ++i) {
    // a s_yy + (μ* U' − a U''/U') s_y − b e^{2u} U'² s = 0, U'' = −w'(u) U'³
    const double map = shape.map[i], second = -w.lambda * std::exp(shape.u[i]) * map * map * map;
    const double drift = mu * map - a * second / map, sink = c.b * std::exp(2 * shape.u[i]) * map * map;
    const double minus = a / (k * k) - drift / (2 * k), plus = a / (k * k) + drift / (2 * k);
    if (i == 0) {  // ghost point s_{−1} = s_1 + 2k U' (μ*/a) s_0 from the lid condition
      diag[0] = -2 * a / (k * k) - sink + minus * 2 * k * map * mu / a;
      sup[0] = 2 * a / (k * k);
      continue;
    }
    diag[i] = -2 * a / (k * k) - sink;
    sub[i] = minus;
    if (i + 1 < m) {
      sup[i] = plus;
    } else {
      rhs[i] = -plus;  // s_M = 1 at the floor
    }
  }
  for (int i = 1; i < m; ++i) {
    const double factor = sub[i] / diag[i - 1];
    diag[i] -= factor * sup[i - 1];
    rhs[i] -= factor * rhs[i - 1];
  }
  shape.s.assign(m + 1, 1.0);  // s_M = 1
  for (int i = m - 1; i >= 0; --i) shape.s[i] = (rhs[i] - (i + 1 < m ? sup[i] * shape.s[i + 1] : 0)) / diag[i];
  for (int i = 0; i < m; ++i)
    if (!std::isfinite(shape.s[i]) || !(shape.s[i] > 0)) shape.failed = true;
  return shape;
}

/// ds/du at node i: the lid condition at i = 0, central inside, second-order one-sided at the floor.
double slope(const ColumnConstants& c, const Shape& f, std::size_t i) {
  const auto& s = f.s;
  if (i == 0) return -c.mu * s[0] / c.a;
  if (i + 1 == s.size()) return (3 * s[i] - 4 * s[i - 1] + s[i - 2]) / (2 * f.step) / f.map[i];
  return (s[i + 1] - s[i - 1]) / (2 * f.step) / f.map[i];
}

/// The factor C with s = C f fixed by the floor condition (q is linear in s: q = K(a s' + μ* s)).
double floor_scale(const ColumnConstants& c, const GravityColumnProblem& p, const Shape& f) {
  if (p.floor == FloorCondition::temperature) return std::sqrt(p.floor_value);
  const double q = c.conductivity_factor * (c.a * slope(c, f, f.s.size() - 1) + c.mu * f.s.back());
  return q > 0 ? p.floor_value / q : std::numeric_limits<double>::quiet_NaN();
}

/// H = C² ∫ f² du (theory.md (23.6), trapezoid).
double height(const ColumnConstants& c, const GravityColumnProblem& p, const Shape& f) {
  double sum = 0;
  for (std::size_t i = 0; i + 1 < f.s.size(); ++i)
    sum += (f.s[i] * f.s[i] * f.map[i] + f.s[i + 1] * f.s[i + 1] * f.map[i + 1]) / 2;
  const double scale = floor_scale(c, p, f);
  return scale * scale * sum * f.step;
}

struct RootData {
  const ColumnConstants* c;
  const GravityColumnProblem* p;
  bool failed = false;  ///< some lid pressure gave no regular column (set inside GSL: no exceptions there)
};

double height_mismatch(double log_pressure, void* data) {
  auto* r = static_cast<RootData*>(data);
  const Shape f = solve_shape(*r->c, std::exp(log_pressure), r->p->particles_per_area, r->p->intervals);
  const double h = f.failed ? std::numeric_limits<double>::quiet_NaN() : height(*r->c, *r->p, f);
  if (!std::isfinite(h) || !(h > 0)) {
    r->failed = true;
    return 0;  // finite, so that GSL's error handler (abort) is never reached
  }
  return std::log(h / r->p->lid_height);
}

void check_regular(const RootData& data) {
  if (data.failed)
    throw std::invalid_argument(
        "alpha: no column with a positive temperature at these kappa*, mu*, zeta* and floor condition (the "
        "Navier-Stokes column needs alpha near 1, theory.md §23.3)");
}

void check_positive(double v, const char* name) {
  if (!std::isfinite(v) || v <= 0)
    throw std::invalid_argument(std::string(name) + ": must be a finite number > 0, got " + std::to_string(v));
}

}  // namespace

GravityColumnProfile solve_gravity_column(const GravityColumnProblem& p) {
  if (p.dimension != 2 && p.dimension != 3)
    throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(p.dimension));
  check_positive(p.particles_per_area, "particles_per_area");
  check_positive(p.floor_value, "floor_value");
  check_positive(p.lid_height, "lid_height");
  if (p.intervals < 16)
    throw std::invalid_argument("intervals: must be an integer >= 16, got " + std::to_string(p.intervals));
  const auto& t = p.transport;
  if (!(t.thermal_conductivity > t.density_heat_coefficient) || !std::isfinite(t.thermal_conductivity))
    throw std::invalid_argument(
        "thermal_conductivity: the column needs kappa* > mu* (theory.md (23.5)), got kappa* = " +
        std::to_string(t.thermal_conductivity) + ", mu* = " + std::to_string(t.density_heat_coefficient));
  if (!(t.cooling_rate >= 0) || !std::isfinite(t.cooling_rate) || !std::isfinite(t.density_heat_coefficient))
    throw std::invalid_argument("cooling_rate: must be a finite number >= 0, got " + std::to_string(t.cooling_rate));
  if (p.floor == FloorCondition::heat_flux && t.cooling_rate == 0)
    throw std::invalid_argument("floor_value: a heat-flux floor needs alpha < 1 (an elastic column conducts no heat)");
  const ColumnConstants c = constants(p);

  // Bracket ln P: the height falls as the lid pushes harder (theory.md §23.2).
  RootData data{&c, &p};
  const double centre = std::log(p.particles_per_area);
  double lo = centre - 4, hi = centre + 4;
  while (height_mismatch(lo, &data) < 0 && !data.failed) {
    lo = std::max(lo - 2 * (centre - lo), centre - 690);
    if (height_mismatch(lo, &data) < 0 && lo <= centre - 690)
      throw std::invalid_argument(
          "lid_height: no lid pressure above e^-690 N gives this height; the gas would be "
          "emptier than a double can hold up there: lower lid_height");
  }
  check_regular(data);
  while (height_mismatch(hi, &data) > 0 && !data.failed) {
    hi += 2 * (hi - centre);
    if (hi > centre + 600)
      throw std::invalid_argument("lid_height: no lid pressure below e^600 N gives this height: raise lid_height");
  }
  check_regular(data);
  gsl_function fn{&height_mismatch, &data};
  std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
  gsl_check(gsl_root_fsolver_set(solver.get(), &fn, lo, hi), "Brent bracket");
  for (int iteration = 0; iteration < 200; ++iteration) {
    gsl_check(gsl_root_fsolver_iterate(solver.get()), "Brent iteration");
    lo = gsl_root_fsolver_x_lower(solver.get());
    hi = gsl_root_fsolver_x_upper(solver.get());
    if (gsl_root_test_interval(lo, hi, 1e-14, 1e-13) == GSL_SUCCESS) break;
  }
  check_regular(data);
  const double log_pressure = gsl_root_fsolver_root(solver.get());

  const Shape f = solve_shape(c, std::exp(log_pressure), p.particles_per_area, p.intervals);
  const double scale = floor_scale(c, p, f);
  const std::size_t m = f.s.size() - 1;
  GravityColumnProfile out;
  out.lid_pressure = std::exp(log_pressure);
  for (auto* v : {&out.z, &out.number_density, &out.temperature, &out.heat_flux, &out.knudsen_number}) v->resize(m + 1);
  double z = 0;
  for (std::size_t j = 0; j <= m; ++j) {  // j from the floor; grid node i = m − j
    const std::size_t i = m - j;
    const double s = scale * f.s[i], su = scale * slope(c, f, i);
    if (j > 0) z += f.step * (s * s * f.map[i] + std::pow(scale * f.s[i + 1], 2) * f.map[i + 1]) / 2;
    const double n = std::exp(f.u[i]) / (s * s);
    out.z[j] = z;
    out.number_density[j] = n;
    out.temperature[j] = s * s;
    // (23.4); at the lid the condition a s' + μ* s = 0 makes it zero exactly, not to roundoff
    out.heat_flux[j] = i == 0 ? 0.0 : c.conductivity_factor * (c.a * su + c.mu * s);
    const double free_path = 1 / (std::numbers::sqrt2 * c.cross_section * n);
    const double grad_log_t = 2 * su / (s * s * s), grad_log_n = (1 - 2 * su / s) / (s * s);
    out.knudsen_number[j] = free_path * std::max(std::abs(grad_log_t), std::abs(grad_log_n));
    if (out.knudsen_height < 0 && out.knudsen_number[j] > 0.1) out.knudsen_height = z;
  }
  // z(lid) equals H to Brent's tolerance; pin it (a relative change far below the grid error) so
  // that a row at z = H reads the lid's node.
  const double stretch = p.lid_height / out.z.back();
  for (auto& height : out.z) height *= stretch;
  out.floor_heat_flux = out.heat_flux[0];
  const double d = p.dimension, sink = d / 2 * t.cooling_rate / c.viscosity_factor;
  for (std::size_t j = 0; j < m; ++j) {
    const double dz = out.z[j + 1] - out.z[j];
    out.particles += dz * (out.number_density[j] + out.number_density[j + 1]) / 2;
    auto local = [&](std::size_t k) {
      return sink * std::pow(out.number_density[k], 2) * std::pow(out.temperature[k], 1.5);  // (d/2) ζ n T
    };
    out.dissipation += dz * (local(j) + local(j + 1)) / 2;
  }
  return out;
}

GravityColumnPoint column_at(const GravityColumnProfile& profile, double z) {
  const auto& zs = profile.z;
  if (zs.empty() || !(z >= 0) || !(z <= zs.back() * (1 + 1e-8)))  // z.back() = H to the root tolerance
    throw std::invalid_argument("height: must be in [0, lid_height], got " + std::to_string(z));
  if (z >= zs.back()) {  // at the lid (H to the root tolerance): its node, q = 0 exactly
    const std::size_t l = zs.size() - 1;
    return {profile.number_density[l], profile.temperature[l], profile.heat_flux[l], profile.knudsen_number[l]};
  }
  std::size_t k = std::upper_bound(zs.begin(), zs.end(), z) - zs.begin();
  k = std::clamp<std::size_t>(k, 1, zs.size() - 1);
  const double w = (z - zs[k - 1]) / (zs[k] - zs[k - 1]);
  auto at = [&](const std::vector<double>& v) { return v[k - 1] + w * (v[k] - v[k - 1]); };
  // n and T (> 0) linear in their logarithm: exact for the barometric exponential.
  auto log_at = [&](const std::vector<double>& v) { return v[k - 1] * std::pow(v[k] / v[k - 1], w); };
  return {log_at(profile.number_density), log_at(profile.temperature), at(profile.heat_flux),
          at(profile.knudsen_number)};
}

}  // namespace gkt
