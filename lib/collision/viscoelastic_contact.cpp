#include "gkt/collision/viscoelastic_contact.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <Eigen/Dense>

namespace gkt {

namespace {

// Near x = 0 the right side has x^{1/2}: integrate in the phase plane with z = √x, where
// dv/dz = 2z dv/dx = −2z⁴/v − 2βz² is smooth while v ≠ 0; around the turning point (v = 0) use
// x(v) instead, dx/dv = v/F, F = −x^{1/2}(x + βv) < 0 there.
int phase_plane_z(double z, const double y[], double f[], void* params) {
  const double beta = *static_cast<const double*>(params);
  f[0] = -2 * z * z * z * z / y[0] - 2 * beta * z * z;
  return GSL_SUCCESS;
}

int phase_plane_v(double v, const double y[], double f[], void* params) {
  const double beta = *static_cast<const double*>(params);
  const double x = y[0];
  f[0] = v / (-std::sqrt(x) * (x + beta * v));
  return GSL_SUCCESS;
}

/// Integrates one scalar ODE from t0 to t1 (rk8pd, tolerances 1e-15), returning y(t1).
double integrate(int (*rhs)(double, const double*, double*, void*), double t0, double t1, double y0, double beta) {
  gsl_odeiv2_system system{rhs, nullptr, 1, &beta};
  struct Driver {
    gsl_odeiv2_driver* d;
    ~Driver() { gsl_odeiv2_driver_free(d); }
  } driver{gsl_odeiv2_driver_alloc_y_new(&system, gsl_odeiv2_step_rk8pd, t1 > t0 ? 1e-3 : -1e-3, 1e-15, 1e-15)};
  double y[1]{y0};
  double t = t0;
  if (gsl_odeiv2_driver_apply(driver.d, &t, t1, y) != GSL_SUCCESS)
    throw std::runtime_error("viscoelastic contact: the integration failed");
  return y[0];
}

}  // namespace

double viscoelastic_contact_restitution(double beta) {
  if (!(beta >= 0 && beta <= 1))
    throw std::invalid_argument("beta: must be a number in [0, 1], got " + std::to_string(beta));
  // Compression in z up to z = 0.7 (v > 0.5 there for β ≤ 1), around the turning point in v
  // down to v = −0.1, restitution in z back to the surface.
  constexpr double z_switch = 0.7, v_switch = -0.1;
  const double v_in = integrate(phase_plane_z, 0.0, z_switch, 1.0, beta);
  const double x_out = integrate(phase_plane_v, v_in, v_switch, z_switch * z_switch, beta);
  return -integrate(phase_plane_z, std::sqrt(x_out), 0.0, v_switch, beta);
}

double viscoelastic_restitution_c1() {
  return std::tgamma(0.6) * std::sqrt(std::numbers::pi) / (std::pow(2.0, 0.2) * std::pow(5.0, 0.4) * std::tgamma(2.1));
}

std::vector<double> viscoelastic_restitution_series(int orders) {
  if (orders < 1 || orders > 4)
    throw std::invalid_argument("orders: the restitution series is fitted to beta^4 at most, got " +
                                std::to_string(orders));
  const double c1 = viscoelastic_restitution_c1();
  std::vector<double> c{-c1};
  if (orders == 1) return c;
  // The remainder r(β) = (ε − 1 + C1 β)/β² = c_2 + c_3 β + …, least squares on Chebyshev nodes.
  constexpr int nodes = 24, degree = 10;
  constexpr double lo = 0.05, hi = 0.3;
  Eigen::MatrixXd x(nodes, degree + 1);
  Eigen::VectorXd r(nodes);
  for (int i = 0; i < nodes; ++i) {
    const double beta = lo + (hi - lo) * (1 + std::cos(std::numbers::pi * (i + 0.5) / nodes)) / 2;  // Chebyshev node
    r(i) = (viscoelastic_contact_restitution(beta) - 1 + c1 * beta) / (beta * beta);
    double power = 1;
    for (int k = 0; k <= degree; ++k, power *= beta / hi) x(i, k) = power;
  }
  const Eigen::VectorXd fit = x.colPivHouseholderQr().solve(r);
  for (int j = 2; j <= orders; ++j) c.push_back(fit(j - 2) / std::pow(hi, j - 2));
  return c;
}

std::vector<double> hertz_restitution_coefficients(double c1, int orders) {
  if (orders < 1 || orders > 4)
    throw std::invalid_argument("orders: the restitution series is known to beta^4 at most, got " +
                                std::to_string(orders));
  static const std::vector<double> fitted = viscoelastic_restitution_series(4);
  const double scale = c1 / viscoelastic_restitution_c1();
  std::vector<double> h{-c1, 0.6 * c1 * c1};
  for (int j = 3; j <= 4; ++j) h.push_back(fitted[static_cast<std::size_t>(j) - 1] * std::pow(scale, j));
  h.resize(static_cast<std::size_t>(orders));
  return h;
}

}  // namespace gkt
