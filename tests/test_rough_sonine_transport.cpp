// Navier–Stokes coefficients of the rough gas at Sonine order N (docs/theory.md §19.16).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "gkt/models/transport_model.hpp"
#include "gkt/transport/common/sonine_solution.hpp"
#include "gkt/transport/monodisperse/navier_stokes.hpp"
#include "gkt/transport/rough/rough_bulk_viscosity.hpp"
#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"
#include "gkt/transport/rough/rough_shear_viscosity.hpp"
#include "gkt/transport/rough/rough_sonine_transport.hpp"
#include "gkt/transport/rough/rough_thermal_conductivity.hpp"

namespace gkt {
namespace {

double rel(double a, double b) { return std::abs(a - b) / std::max(1.0, std::abs(b)); }

// Order 1 is the first-Sonine solvers of §19.7 and §19.9 (shear, heat, scalar) to round-off.
TEST(RoughSonineTransport, OrderOneIsTheFirstSonineSolvers) {
  struct Case {
    int d;
    Rational alpha, beta, kappa;
  };
  for (const Case& c :
       {Case{3, Rational(9, 10), Rational(1, 2), Rational(2, 5)}, Case{3, Rational(7, 10), Rational(0), Rational(2, 5)},
        Case{3, Rational(1, 2), Rational(1), Rational(1, 4)}, Case{2, Rational(9, 10), Rational(1, 2), Rational(1, 2)},
        Case{2, Rational(3, 5), Rational(-1, 2), Rational(1, 2)}}) {
    const RoughSonineTransport t(c.d, c.alpha, c.beta, c.kappa, 1);
    const RoughTransportValues v = t.at_maxwellian_state(1);
    const double eta = rough_shear_viscosity(c.d, c.alpha, c.beta, c.kappa);
    const RoughThermalConductivity k = rough_thermal_conductivity(c.d, c.alpha, c.beta, c.kappa);
    const RoughScalarResponse b = rough_bulk_viscosity(c.d, c.alpha, c.beta, c.kappa);
    EXPECT_LT(rel(v.shear_viscosity, eta), 1e-12) << c.d << " " << v.shear_viscosity << " " << eta;
    EXPECT_LT(rel(v.thermal_conductivity, k.total), 1e-12) << v.thermal_conductivity << " " << k.total;
    EXPECT_LT(rel(v.density_heat_coefficient, k.density_heat_total), 1e-12)
        << v.density_heat_coefficient << " " << k.density_heat_total;
    EXPECT_LT(rel(v.bulk_viscosity, b.bulk_viscosity), 1e-12) << v.bulk_viscosity << " " << b.bulk_viscosity;
    EXPECT_LT(rel(v.cooling_rate_first_order, b.cooling_rate_first_order), 1e-12)
        << v.cooling_rate_first_order << " " << b.cooling_rate_first_order;
  }
}

// β = −1: the spin decouples and the translational families are the smooth gas's standard Sonine systems with
// Maxwellian weights (NavierStokesSolver with a = (1, 0, 0)) at every order; the totals have no HCS value.
TEST(RoughSonineTransport, SmoothLimitIsTheSmoothSolverAtEveryOrder) {
  for (int d : {3, 2}) {
    NavierStokesSolver smooth(d);
    for (const Rational& alpha : {Rational(9, 10), Rational(7, 10), Rational(1, 2)}) {
      const RoughSonineTransport t(d, alpha, Rational(-1), Rational(2, 5), 6);
      for (int n = 1; n <= 6; ++n) {
        const RoughTransportValues v = t.at_maxwellian_state(n);
        const NavierStokesValues s = smooth.solve(alpha, n, {1, 0, 0});
        EXPECT_LT(rel(v.shear_viscosity, s.shear_viscosity), 1e-12) << d << " " << n;
        EXPECT_LT(rel(v.thermal_conductivity_translational, s.thermal_conductivity), 1e-12) << d << " " << n;
        EXPECT_LT(rel(v.density_heat_translational, s.density_heat_coefficient), 1e-12) << d << " " << n;
        EXPECT_TRUE(std::isnan(v.thermal_conductivity) && std::isnan(v.density_heat_coefficient));
        EXPECT_TRUE(std::isnan(v.bulk_viscosity) && std::isnan(v.cooling_rate_first_order));
      }
    }
  }
}

// Pidduck's perfectly rough elastic spheres (α = β = 1, θ = 1): the first approximations of [chapman1970] §11.6
// (η*, κ* ratio and η_b of theory.md §19.7, (19.20)); μ* = ζ_U = 0 at every order (no cooling); the higher orders
// raise η*, κ*, η_b monotonically and converge geometrically.
TEST(RoughSonineTransport, PidduckGasAtEveryOrder) {
  const Rational kappa(2, 5);
  const double k = 0.4;
  for (int d : {3, 2}) {
    const RoughSonineTransport t(d, Rational(1), Rational(1), kappa, 8);
    const RoughTransportValues first = t.at(1, 1.0);
    if (d == 3) {
      EXPECT_NEAR(first.shear_viscosity, 6 * (1 + k) * (1 + k) / (6 + 13 * k), 1e-13);
      EXPECT_NEAR(
          first.thermal_conductivity,
          12 * (1 + k) * (1 + k) * (37 + 151 * k + 50 * k * k) / (25 * (12 + 75 * k + 101 * k * k + 102 * k * k * k)),
          1e-12);
      EXPECT_NEAR(first.bulk_viscosity, (1 + k) * (1 + k) / (10 * k), 1e-13);
    } else {
      EXPECT_NEAR(first.shear_viscosity, 2 * (1 + k) * (1 + k) / (2 + 3 * k), 1e-13);
      EXPECT_NEAR(first.bulk_viscosity, (1 + k) * (1 + k) / (9 * k), 1e-13);
    }
    RoughTransportValues previous = first;
    double step = 1;
    for (int n = 2; n <= 8; ++n) {
      const RoughTransportValues v = t.at(n, 1.0);
      EXPECT_NEAR(v.density_heat_coefficient, 0, 1e-13);
      EXPECT_NEAR(v.cooling_rate_first_order, 0, 1e-13);
      const double de = v.shear_viscosity - previous.shear_viscosity,
                   dk = v.thermal_conductivity - previous.thermal_conductivity,
                   db = v.bulk_viscosity - previous.bulk_viscosity;
      EXPECT_GT(de, 0) << d << " " << n;
      EXPECT_GT(dk, 0) << d << " " << n;
      EXPECT_GT(db, 0) << d << " " << n;
      if (n >= 4) {  // geometric: each correction under half the last
        EXPECT_LT(de, 0.5 * step) << d << " " << n;
      }
      step = de;
      previous = v;
    }
    EXPECT_LT(step, 1e-6);
  }
}

// Convergence in order: 3D (α, β) = (0.9, 0.5) all five coefficients settle; (0.7, 0) η* settles while κ* and μ*
// keep oscillating (the standard scheme's breakdown, theory.md §19.16); disks (0.9, 0.5), κ = 1/2.
TEST(RoughSonineTransport, ConvergenceInOrder) {
  {
    const RoughSonineTransport t(3, Rational(9, 10), Rational(1, 2), Rational(2, 5), 8);
    const RoughTransportValues v6 = t.at_maxwellian_state(6), v7 = t.at_maxwellian_state(7),
                               v8 = t.at_maxwellian_state(8), v2 = t.at_maxwellian_state(2),
                               v1 = t.at_maxwellian_state(1);
    EXPECT_LT(std::abs(v8.shear_viscosity - v7.shear_viscosity), 1e-6);
    EXPECT_LT(std::abs(v7.shear_viscosity - v6.shear_viscosity), 1e-6);
    EXPECT_GT(std::abs(v2.shear_viscosity - v1.shear_viscosity), 5e-3);  // order 1 is 0.8 % off
    EXPECT_LT(std::abs(v8.thermal_conductivity - v6.thermal_conductivity), 1e-3);
    EXPECT_GT(std::abs(v1.thermal_conductivity - v8.thermal_conductivity), 4e-2);  // order 1 is 2.7 % off
    EXPECT_LT(std::abs(v8.bulk_viscosity - v6.bulk_viscosity), 5e-4);
    EXPECT_LT(std::abs(v8.cooling_rate_first_order - v6.cooling_rate_first_order), 2e-4);
  }
  {
    const RoughSonineTransport t(3, Rational(7, 10), Rational(0), Rational(2, 5), 8);
    const RoughTransportValues v6 = t.at_maxwellian_state(6), v7 = t.at_maxwellian_state(7),
                               v8 = t.at_maxwellian_state(8);
    EXPECT_LT(std::abs(v8.shear_viscosity - v7.shear_viscosity), 3e-4);
    EXPECT_LT(std::abs(v7.shear_viscosity - v6.shear_viscosity), 3e-4);
    EXPECT_GT(std::abs(v7.thermal_conductivity - v6.thermal_conductivity), 0.05);
  }
  {
    const RoughSonineTransport t(2, Rational(9, 10), Rational(1, 2), Rational(1, 2), 6);
    const RoughTransportValues v4 = t.at_maxwellian_state(4), v5 = t.at_maxwellian_state(5),
                               v6 = t.at_maxwellian_state(6);
    EXPECT_LT(std::abs(v6.shear_viscosity - v5.shear_viscosity), 1e-4);
    EXPECT_LT(std::abs(v6.shear_viscosity - v5.shear_viscosity), std::abs(v5.shear_viscosity - v4.shear_viscosity));
    EXPECT_LT(std::abs(v6.bulk_viscosity - v5.bulk_viscosity), 1e-3);
  }
}

TEST(RoughSonineTransport, RefusesBadInput) {
  EXPECT_THROW(RoughSonineTransport(3, Rational(9, 10), Rational(1, 2), Rational(2, 5), 0), std::invalid_argument);
  EXPECT_THROW(RoughSonineTransport(4, Rational(9, 10), Rational(1, 2), Rational(2, 5), 2), std::invalid_argument);
  EXPECT_THROW(RoughSonineTransport(3, Rational(9, 10), Rational(2), Rational(2, 5), 2), std::invalid_argument);
  const RoughSonineTransport t(3, Rational(9, 10), Rational(1, 2), Rational(2, 5), 2);
  EXPECT_THROW((void)t.at(3, 1.0), std::invalid_argument);
  EXPECT_THROW((void)t.at(1, -1.0), std::invalid_argument);
}

// The model: order N > 1 gives the library's value with the error (6.3) from orders N + 1, N + 2 and, where their
// changes change sign (η* at order 2: +3.3e-5, −1.7e-4), N + 3; the HCS columns are refused beyond order 1.
TEST(RoughSonineTransport, ModelOrderAndError) {
  auto model = make_transport_model("rough");
  ParameterPoint point;
  point.numbers = {{"dimension", Rational(3)},
                   {"alpha", Rational(9, 10)},
                   {"beta", Rational(1, 2)},
                   {"moment_of_inertia", Rational(2, 5)}};
  point.choices = {{"hcs", "maxwellian"}};
  OrderRequest request;
  request.order = 2;
  const auto out = model->evaluate(point, {"shear_viscosity", "thermal_conductivity"}, request);
  const RoughSonineTransport t(3, Rational(9, 10), Rational(1, 2), Rational(2, 5), 5);
  const double e2 = t.at_maxwellian_state(2).shear_viscosity, e3 = t.at_maxwellian_state(3).shear_viscosity,
               e4 = t.at_maxwellian_state(4).shear_viscosity, e5 = t.at_maxwellian_state(5).shear_viscosity;
  EXPECT_NEAR(out[0].value.to_double(), e2, 1e-15);
  EXPECT_TRUE(changes_sign(Rational::from_double(e2), Rational::from_double(e3), Rational::from_double(e4)));
  const TruncationEstimate e = estimate_truncation_confirmed(Rational::from_double(e2), Rational::from_double(e3),
                                                             Rational::from_double(e4), Rational::from_double(e5));
  EXPECT_NEAR(out[0].error.to_double(), e.error.to_double(), 1e-15);
  EXPECT_GT(out[0].error.to_double(), 0);
  EXPECT_EQ(out[0].order, 2);
  EXPECT_NEAR(out[1].value.to_double(), t.at_maxwellian_state(2).thermal_conductivity, 1e-15);
  EXPECT_THROW((void)model->evaluate(point, {"rotational_temperature_ratio"}, request), std::invalid_argument);
}

// A tolerance scan's error covers the orders it did not read (theory.md §19.23, (19.100)): 3D (α, β) = (0.9, 0.5),
// `tolerance = 1e-4`, against order 11 (past the model's tables, 10). Under (6.3) alone ζ_U stopped at order 3
// claiming 1.6e-5 while 8.2e-5 from order 11 (5.2 times the claim); the window keeps the stop and widens the
// error to 8.7e-5. κ*, which wanders by ~1e-3 from order 7 on, does not meet 1e-4 and says why.
TEST(RoughSonineTransport, ToleranceErrorCoversTheLaterOrders) {
  auto model = make_transport_model("rough");
  ParameterPoint point;
  point.numbers = {{"dimension", Rational(3)},
                   {"alpha", Rational(9, 10)},
                   {"beta", Rational(1, 2)},
                   {"moment_of_inertia", Rational(2, 5)}};
  OrderRequest request;
  request.tolerance = Rational(1, 10000);
  const std::vector<std::string> names{"cooling_rate_first_order", "shear_viscosity", "bulk_viscosity",
                                       "thermal_conductivity"};
  const auto out = model->evaluate(point, names, request);
  const RoughTransportValues ref =
      RoughSonineTransport(3, Rational(9, 10), Rational(1, 2), Rational(2, 5), 11).at_maxwellian_state(11);
  const double refs[] = {ref.cooling_rate_first_order, ref.shear_viscosity, ref.bulk_viscosity,
                         ref.thermal_conductivity};
  EXPECT_TRUE(out[0].converged);  // ζ_U meets 1e-4: the window keeps an honest stop
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (!out[k].converged) continue;
    EXPECT_LT(out[k].error.to_double(), 1e-4) << names[k];
    EXPECT_GE(out[k].error.to_double(), std::abs(out[k].value.to_double() - refs[k]))
        << names[k] << " at order " << out[k].order;
  }
  EXPECT_FALSE(out[3].converged);
  EXPECT_NE(out[3].divergence, Divergence::none);  // the CLI's warning says why (describe_divergence)
}

}  // namespace
}  // namespace gkt
