// Thermal conductivity of rough spheres at first Sonine (docs/theory.md §19.7) against Pidduck's
// perfectly rough elastic spheres ([chapman1970] §11.6) and, at β = −1, the smooth first Sonine
// κ* = ((d−1)/d)/(ν_κ* − 2ζ*), ν_κ* = ((1+α)/d)[(d−1)/2 + (3/16)(d+8)(1−α)], ζ* = ((d+2)/(4d))(1−α²)
// ([garzo2019]; theory.md §10.3) for the translational flux, and μ* likewise.
#include <gtest/gtest.h>

#include <cmath>

#include "gkt/transport/rough/rough_thermal_conductivity.hpp"

using gkt::Rational;

TEST(RoughThermalConductivity, PidduckGas) {
  for (long k10 : {4L, 1L, 10L, 5L}) {
    const double k = k10 / 10.0;
    const double pidduck =
        12 * (1 + k) * (1 + k) * (37 + 151 * k + 50 * k * k) / (25 * (12 + 75 * k + 101 * k * k + 102 * k * k * k));
    const auto c = gkt::rough_thermal_conductivity_at(Rational(1), Rational(1), Rational(k10, 10), 1.0);
    EXPECT_NEAR(c.total, pidduck, 1e-12) << "kappa=" << k;
    // The HCS of the elastic perfectly rough gas is equilibrium: same value through the HCS solver.
    const auto hcs = gkt::rough_thermal_conductivity(Rational(1), Rational(1), Rational(k10, 10));
    EXPECT_NEAR(hcs.total, pidduck, 1e-12);
    EXPECT_NEAR(hcs.density_heat_total, 0, 1e-14);  // no cooling, no μ
  }
}

TEST(RoughThermalConductivity, SmoothLimitTranslationalFlux) {
  for (long a10 : {9L, 5L, 2L}) {
    const double a = a10 / 10.0;
    const double nu = (1 + a) / 3 * (1 + 33.0 / 16 * (1 - a)), zeta = 5.0 / 12 * (1 - a * a);
    const auto c = gkt::rough_thermal_conductivity(Rational(a10, 10), Rational(-1), Rational(2, 5));
    const double kappa_star = 2.0 / 3 / (nu - 2 * zeta);
    EXPECT_NEAR(c.translational, kappa_star, 1e-12);
    EXPECT_TRUE(std::isnan(c.total));
    // μ* = 2ζ*κ*/(2ν_μ* − 3ζ*), ν_μ* = ν_κ* at first Sonine ([garzo2019]; theory.md §10.3).
    EXPECT_NEAR(c.density_heat_translational, 2 * zeta * kappa_star / (2 * nu - 3 * zeta), 1e-12);
    EXPECT_TRUE(std::isnan(c.density_heat_total));
  }
}
