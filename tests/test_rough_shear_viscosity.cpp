// Shear viscosity of rough spheres and disks at first Sonine (docs/theory.md §19.7) against
//  (1) Pidduck's perfectly rough elastic spheres, η = [6(1+κ)²/(6+13κ)] η0 in the first
//      approximation ([chapman1970] §11.6), exactly;
//  (2) β = −1: the smooth gas's first Sonine η* = 1/(ν_η* − ζ*/2), ν_η* = (3/(4d))(1 − α + 2d/3)(1 + α),
//      ζ* = ((d+2)/(4d))(1 − α²) ([garzo2019]; theory.md §10.3).
#include <gtest/gtest.h>

#include "gkt/transport/rough/rough_shear_viscosity.hpp"

using gkt::Rational;

TEST(RoughShearViscosity, PidduckPerfectlyRoughElasticSpheres) {
  for (const Rational& kappa : {Rational(2, 5), Rational(1, 10), Rational(1), Rational(2, 3)}) {
    const Rational one(1);
    EXPECT_EQ(gkt::rough_shear_viscosity_at(3, one, one, kappa, one),
              Rational(6) * (one + kappa) * (one + kappa) / (Rational(6) + Rational(13) * kappa))
        << kappa;
  }
}

// Disks: the same engine gives 2(1+κ)²/(2+3κ) (theory.md §19.7; no published value to compare).
TEST(RoughShearViscosity, PerfectlyRoughElasticDisks) {
  for (const Rational& kappa : {Rational(1, 2), Rational(1, 10), Rational(1)}) {
    const Rational one(1);
    EXPECT_EQ(gkt::rough_shear_viscosity_at(2, one, one, kappa, one),
              Rational(2) * (one + kappa) * (one + kappa) / (Rational(2) + Rational(3) * kappa));
  }
}

TEST(RoughShearViscosity, SmoothLimit) {
  for (int d : {2, 3})
    for (long a10 : {9L, 5L, 2L}) {
      const double a = a10 / 10.0;
      const double nu = 3.0 / (4 * d) * (1 - a + 2.0 * d / 3) * (1 + a), zeta = (d + 2.0) / (4 * d) * (1 - a * a);
      EXPECT_NEAR(gkt::rough_shear_viscosity(d, Rational(a10, 10), Rational(-1), Rational(2, 5)), 1 / (nu - zeta / 2),
                  1e-13);
    }
}

TEST(RoughShearViscosity, RejectsBadInput) {
  EXPECT_THROW(gkt::rough_shear_viscosity_at(3, Rational(1), Rational(2), Rational(2, 5), Rational(1)),
               std::invalid_argument);
  EXPECT_THROW(gkt::rough_shear_viscosity(3, Rational(1), Rational(0), Rational(0)), std::invalid_argument);
}
