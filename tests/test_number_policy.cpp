// The number policy (docs/architecture.md §4): a number a caller gives is converted to an exact
// value once, where it enters — a decimal of a scene exactly, a double by ExactValue's rule — and
// the engine uses that value; the two entry points agree.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "gkt/algebra/exact_value.hpp"
#include "gkt/transport/mixture/mixture.hpp"
#include "gkt/transport/mixture/mixture_cooling_state.hpp"
#include "gkt/transport/mixture/mixture_navier_stokes.hpp"

using gkt::ExactValue;
using gkt::Rational;

namespace {

/// Every coefficient of a binary's order-2 Navier–Stokes solution, flattened.
std::vector<double> transport(gkt::ExactValue m1, gkt::ExactValue m2, double phi) {
  const gkt::Mixture mixture =
      gkt::make_mixture(3, {{std::move(m1), 1.0, 0.4, "1"}, {std::move(m2), 1.5, 0.6, "2"}}, 0.8, phi);
  const auto v = gkt::MixtureNavierStokes(mixture, 2).coefficients(2);
  std::vector<double> out{v.shear_viscosity, v.thermal_conductivity, v.cooling_rate_first_order, v.bulk_viscosity};
  for (const auto* part : {&v.mutual_diffusion, &v.thermal_diffusion, &v.dufour, &v.pressure_diffusion})
    out.insert(out.end(), part->begin(), part->end());
  const auto hcs = gkt::mixture_cooling_state(mixture, gkt::MixtureHcsScheme::linear);
  out.push_back(hcs.cooling_rate);
  out.insert(out.end(), hcs.temperature_ratio.begin(), hcs.temperature_ratio.end());
  return out;
}

}  // namespace

TEST(ExactValue, ADecimalTextIsKeptExactly) {
  const ExactValue tenth(Rational::parse("0.1"));
  EXPECT_EQ(tenth.exact(), Rational(1, 10));
  EXPECT_EQ(tenth.value(), 0.1);
  const ExactValue third(Rational::parse("1/3"));
  EXPECT_EQ(third.exact(), Rational(1, 3));
  EXPECT_EQ(third.value(), 1.0 / 3);
}

TEST(ExactValue, ADoubleIsConvertedOnceToTheValueItWasTypedAs) {
  // Not the double's binary value (0.1 is 3602879701896397/2^55): the short rational it rounds.
  EXPECT_EQ(ExactValue(0.1).exact(), Rational(1, 10));
  EXPECT_NE(ExactValue(0.1).exact(), Rational::from_double(0.1));
  EXPECT_EQ(ExactValue(1.0 / 3).exact(), Rational(1, 3));
  EXPECT_EQ(ExactValue(0.3).exact(), Rational(3, 10));
  EXPECT_EQ(ExactValue(-2.5).exact(), Rational(-5, 2));
  EXPECT_EQ(ExactValue(4.0).exact(), Rational(4));
  EXPECT_EQ(ExactValue(0.0).exact(), Rational(0));
  // No convergent with denominator ≤ 2^26 within 1e-12: the exact binary value, and value() is x.
  const double x = 1 + std::ldexp(1.0, -35);
  EXPECT_EQ(ExactValue(x).exact(), Rational::from_double(x));
  EXPECT_EQ(ExactValue(x).value(), x);
  // value() is the double of exact(): the solvers' double and the engine's rational are one number.
  for (const double y : {0.1, 0.7, 1.0 / 3, 2.0 / 7, 1e9, 123.456})
    EXPECT_EQ(ExactValue(y).value(), ExactValue(y).exact().to_double()) << y;
  // A non-finite double keeps its value for the caller's check (Mixture::validate refuses it).
  EXPECT_TRUE(std::isnan(ExactValue(std::nan("")).value()));
}

// A mass given as a scene's decimal (exact) and the same mass given as a double reach the engine
// as the same rational: every coefficient of the mixture is bitwise the same.
TEST(NumberPolicy, TextAndDoubleMassesGiveTheSameMixture) {
  for (const double phi : {0.0, 0.2}) {
    EXPECT_EQ(transport(ExactValue(Rational::parse("0.1")), ExactValue(Rational::parse("0.3")), phi),
              transport(0.1, 0.3, phi))
        << phi;
    EXPECT_EQ(transport(ExactValue(Rational(1, 3)), ExactValue(Rational(1)), phi), transport(1.0 / 3, 1.0, phi)) << phi;
  }
}
