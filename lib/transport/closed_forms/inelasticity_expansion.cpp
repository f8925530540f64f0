#include "gkt/transport/closed_forms/inelasticity_expansion.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

#include <Eigen/Dense>

#include "gkt/transport/closed_forms/first_sonine_formulas.hpp"
#include "gkt/transport/monodisperse/homogeneous_cooling_state.hpp"
#include "gkt/transport/monodisperse/navier_stokes.hpp"

namespace gkt {

std::array<Rational, 3> first_sonine_inelasticity_expansion(int dimension, const std::string& coefficient) {
  const RationalFunction f = first_sonine_closed_form(dimension, coefficient);
  // f(α) = f(1) + f'(1)(α−1) + ½f''(1)(α−1)² + …, α − 1 = −ε/2 − ε²/8 + O(ε³).
  auto derivative = [](const RationalFunction& g) {
    RationalFunction d;
    RationalPolynomial np, dp;
    fmpq_poly_derivative(np.raw(), g.numerator.raw());
    fmpq_poly_derivative(dp.raw(), g.denominator.raw());
    d.numerator = np * g.denominator - g.numerator * dp;
    d.denominator = g.denominator * g.denominator;
    return d.reduced();
  };
  const RationalFunction f1 = derivative(f), f2 = derivative(f1);
  const Rational v0 = f.evaluate(Rational(1)), v1 = f1.evaluate(Rational(1)), v2 = f2.evaluate(Rational(1));
  return {v0, Rational(-1, 2) * v1, Rational(-1, 8) * v1 + Rational(1, 8) * v2};
}

InelasticityExpansion inelasticity_expansion(int dimension, int order) {
  if (order < 3) throw std::invalid_argument("order: the fit compares with order − 2; must be >= 3");
  NavierStokesSolver ns(dimension);
  HomogeneousCoolingState hcs(dimension);
  constexpr int kPoints = 11;
  // values[n][quantity][k] at α = 1 − k/400 for n ∈ {order − 2, order}.
  auto sample = [&](int n) {
    std::array<std::array<double, kPoints>, 4> v{};
    for (int k = 0; k < kPoints; ++k) {
      const Rational alpha = Rational(1) - Rational(k, 400);
      const HcsState s = hcs.solve(alpha, n + 1, HcsScheme::nonlinear);
      const NavierStokesValues t = ns.solve(alpha, n, s.a);
      v[0][k] = t.shear_viscosity;
      v[1][k] = t.thermal_conductivity;
      v[2][k] = t.density_heat_coefficient;
      v[3][k] = s.cooling_rate;
    }
    return v;
  };
  std::array<double, kPoints> eps{};
  for (int k = 0; k < kPoints; ++k) {
    const Rational alpha = Rational(1) - Rational(k, 400);
    eps[k] = (Rational(1) - alpha * alpha).to_double();
  }
  auto fit = [&](const std::array<double, kPoints>& y, int degree) {
    Eigen::MatrixXd a(kPoints, degree + 1);
    Eigen::VectorXd b(kPoints);
    for (int i = 0; i < kPoints; ++i) {
      for (int j = 0; j <= degree; ++j) a(i, j) = std::pow(eps[i], j);
      b(i) = y[i];
    }
    return Eigen::VectorXd(a.colPivHouseholderQr().solve(b));
  };
  const auto high = sample(order), low = sample(order - 2);
  std::array<EpsilonSeries, 4> series;
  for (int q = 0; q < 4; ++q) {
    const Eigen::VectorXd best = fit(high[q], 5), lower_order = fit(low[q], 5), lower_degree = fit(high[q], 4);
    for (int j = 0; j < 3; ++j) {
      series[q].coefficients[j] = best(j);
      series[q].errors[j] = std::abs(best(j) - lower_order(j)) + std::abs(best(j) - lower_degree(j));
    }
  }
  return {series[0], series[1], series[2], series[3]};
}

}  // namespace gkt
