#include "gkt/transport/rough/rough_split_slopes.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

namespace gkt {

namespace {

/// Returns the Richardson-extrapolated central difference of f at x (steps h and h/2): error O(h⁴).
template <class F>
double derivative(const F& f, double x, double h) {
  const double coarse = (f(x + h) - f(x - h)) / (2 * h);
  const double fine = (f(x + h / 2) - f(x - h / 2)) / h;
  return (4 * fine - coarse) / 3;
}

}  // namespace

RoughSplitSlopes rough_split_slopes(const RoughSonineCoolingRates& rates, double temperature_ratio,
                                    std::span<const double> unknowns) {
  if (!(temperature_ratio > 0) || !std::isfinite(temperature_ratio))
    throw std::invalid_argument("temperature_ratio: must be a finite number > 0");
  if (rates.spin_decoupled())
    throw std::invalid_argument("beta: must be > -1 (at beta = -1 the spin decouples and has no split)");
  const std::size_t k = rates.unknowns();
  if (unknowns.size() != k)
    throw std::invalid_argument("unknowns: must hold " + std::to_string(k) + " values (a_pq then b_pq)");
  const double d = rates.dimension(), d_r = rates.dimension() == 3 ? 3.0 : 1.0;
  const double c = (d + 2) / 4;  // ζ* = ((d + 2)/4) z: ν0(T_t) over nσ^{d−1}v_t ν (theory.md (5.3))
  const double kappa = rates.kappa(), theta = temperature_ratio, log_theta = std::log(theta);
  std::vector<double> u(unknowns.begin(), unknowns.end());
  const RoughSonineRates at_state = rates.at(theta / kappa, u);
  const double excess = at_state.rotational_rate - at_state.translational_rate;
  if (!(std::abs(excess) <= 1e-9 * std::max(1.0, std::abs(at_state.translational_rate))))
    throw std::invalid_argument("temperature_ratio: the rates must balance there (zeta_r = zeta_t: the HCS)");
  RoughSplitSlopes out;
  out.temperature_ratio = theta;
  out.cooling_rate = c * at_state.translational_rate;

  // theory.md (19.140): the rates at θ' = e^ℓ with the unknowns v. Δ = ζ_r* − ζ_t*; Q = ζ/ν0(T_t of the state) at
  // fixed n, T: ν0 scales as √T_t and T_t' = (d + d_r)T/(d + d_rθ'), s' = d/(d + d_rθ').
  const auto excess_at = [&](double ell, const std::vector<double>& v) {
    const RoughSonineRates r = rates.at(std::exp(ell) / kappa, v);
    return c * (r.rotational_rate - r.translational_rate);
  };
  const auto cooling_at = [&](double ell, const std::vector<double>& v) {
    const double t = std::exp(ell), s = d / (d + d_r * t);
    const RoughSonineRates r = rates.at(t / kappa, v);
    return c * std::sqrt((d + d_r * theta) / (d + d_r * t)) * (s * r.translational_rate + (1 - s) * r.rotational_rate);
  };
  const double h = 1e-3;
  // (19.141)–(19.142): the cumulants held.
  out.relaxation_rate = derivative([&](double ell) { return excess_at(ell, u); }, log_theta, h);
  out.cooling_split_slope = derivative([&](double ell) { return cooling_at(ell, u); }, log_theta, h);

  const double nan = std::numeric_limits<double>::quiet_NaN();
  out.relaxation_rate_slaved = out.cooling_split_slope_slaved = out.homogeneous_relaxation_rate = nan;
  out.homogeneous_relaxation_frequency = nan;
  double residual = 0;
  for (double g : at_state.residual) residual = std::max(residual, std::abs(g));
  if (k == 0 || !(residual <= 1e-9)) {
    if (k == 0) {  // nothing to slave: the Maxwellian closure
      out.relaxation_rate_slaved = out.homogeneous_relaxation_rate = out.relaxation_rate;
      out.homogeneous_relaxation_frequency = 0;
      out.cooling_split_slope_slaved = out.cooling_split_slope;
    }
    return out;
  }
  // The homogeneous linear scheme (theory.md (19.25b)) in ν0 time: dℓ/dτ = −Δ, Π dv/dτ = c[G + l (z_r − z_t)⟨ψ⟩(v)].
  const auto n = static_cast<Eigen::Index>(k);
  Eigen::MatrixXd projection(n, n);
  for (std::size_t t = 0; t < k; ++t)
    for (std::size_t w = 0; w < k; ++w)
      projection(static_cast<Eigen::Index>(t), static_cast<Eigen::Index>(w)) = rates.projections()[t][w];
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(projection);
  const auto flow = [&](double ell, const std::vector<double>& v) {
    const RoughSonineRates r = rates.at(std::exp(ell) / kappa, v);
    Eigen::VectorXd rhs(n + 1);
    rhs(0) = -c * (r.rotational_rate - r.translational_rate);
    Eigen::VectorXd balance(n);
    for (std::size_t t = 0; t < k; ++t) {
      double moment = rates.maxwellian_moments()[t];
      for (std::size_t w = 0; w < k; ++w) moment += rates.projections()[t][w] * v[w];
      balance(static_cast<Eigen::Index>(t)) =
          c * (r.residual[t] + rates.spin_degrees()[t] * (r.rotational_rate - r.translational_rate) * moment);
    }
    rhs.tail(n) = lu.solve(balance);
    return rhs;
  };
  // Jacobian J = ∂(dℓ/dτ, dv/dτ)/∂(ℓ, v); the unknowns enter linearly (products dropped), a central step of 1e-4 is
  // exact to round-off.
  Eigen::MatrixXd jacobian(n + 1, n + 1);
  for (Eigen::Index col = 0; col <= n; ++col) {
    const double step = col == 0 ? h : 1e-4;
    const auto shifted = [&](double sign) {
      std::vector<double> v = u;
      double ell = log_theta;
      if (col == 0)
        ell += sign * step;
      else
        v[static_cast<std::size_t>(col - 1)] += sign * step;
      return flow(ell, v);
    };
    if (col == 0) {
      const Eigen::VectorXd coarse = (shifted(1) - shifted(-1)) / (2 * step);
      const auto half = [&](double sign) { return flow(log_theta + sign * step / 2, u); };
      const Eigen::VectorXd fine = (half(1) - half(-1)) / step;
      jacobian.col(0) = (4 * fine - coarse) / 3;
    } else {
      jacobian.col(col) = (shifted(1) - shifted(-1)) / (2 * step);
    }
  }
  // (19.143): the unknowns on the static solution of their balances at θ', v = v_H + A δ, A = −J_vv⁻¹ J_vℓ.
  const Eigen::VectorXd slave = -jacobian.bottomRightCorner(n, n).fullPivLu().solve(jacobian.bottomLeftCorner(n, 1));
  double slaved_relaxation = -jacobian(0, 0);
  double slaved_cooling = out.cooling_split_slope;
  for (Eigen::Index w = 0; w < n; ++w) {
    slaved_relaxation -= jacobian(0, w + 1) * slave(w);
    const auto cooling_of = [&](double x) {
      std::vector<double> v = u;
      v[static_cast<std::size_t>(w)] = x;
      return cooling_at(log_theta, v);
    };
    const double x = u[static_cast<std::size_t>(w)];
    slaved_cooling += (cooling_of(x + 1e-4) - cooling_of(x - 1e-4)) / 2e-4 * slave(w);
  }
  out.relaxation_rate_slaved = slaved_relaxation;
  out.cooling_split_slope_slaved = slaved_cooling;
  // (19.144): the slowest decay of the homogeneous scheme, −max Re λ(J): the late-time rate of θ's approach to the HCS.
  const Eigen::VectorXcd values = Eigen::EigenSolver<Eigen::MatrixXd>(jacobian, false).eigenvalues();
  std::complex<double> slowest = values(0);
  for (Eigen::Index i = 1; i < values.size(); ++i)
    if (values(i).real() > slowest.real()) slowest = values(i);
  out.homogeneous_relaxation_rate = -slowest.real();
  out.homogeneous_relaxation_frequency = std::abs(slowest.imag());
  return out;
}

}  // namespace gkt
