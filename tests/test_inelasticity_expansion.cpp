// Expansion in ε = 1 − α² (Goldhirsch, Noskowicz & Bar-Lev, J. Phys.: Condens. Matter 17 (2005)
// S2591, §3, 3D dilute): exact first-Sonine coefficients and the converged ones in GNB's units.
//
// GNB's units (their §3: T = ⟨v²⟩ with m = 1, ℓ = 1/(πnσ²), Q = ½∫v v² f) give
//   μ̃ = (5/16)√(π/3) η*,  κ̃ = (25/64)√(π/3) κ*,  λ̃ = (25/64)√(π/3) μ*,  δ̃ = (16/(5√(3π))) ζ*
// (docs/theory.md §11). Printed: μ̃ ≈ 0.3249 + 0.0576ε, κ̃ ≈ 0.4101 + 0.1072ε, λ̃ ≈ 0.2110ε,
// δ̃ ≈ √(16/(27π))ε − 0.0112ε².
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "gkt/transport/closed_forms/inelasticity_expansion.hpp"

using gkt::Rational;

namespace {
double round4(double x) { return std::round(x * 1e4) / 1e4; }
const double kMu = 5.0 / 16 * std::sqrt(std::numbers::pi / 3);
const double kKappa = 25.0 / 64 * std::sqrt(std::numbers::pi / 3);
const double kDelta = 16 / (5 * std::sqrt(3 * std::numbers::pi));
}  // namespace

// First Sonine, exact: ζ* = ((d+2)/(4d)) ε + O(ε²), η* = κ* = 1 + O(ε), μ* = O(ε).
TEST(InelasticityExpansion, FirstSonineExact) {
  for (int d : {2, 3}) {
    const auto zeta = gkt::first_sonine_inelasticity_expansion(d, "cooling_rate");
    EXPECT_TRUE(zeta[0].is_zero());
    EXPECT_EQ(zeta[1], Rational(d + 2, static_cast<unsigned long>(4 * d)));
    EXPECT_EQ(gkt::first_sonine_inelasticity_expansion(d, "shear_viscosity")[0], Rational(1));
    EXPECT_EQ(gkt::first_sonine_inelasticity_expansion(d, "thermal_conductivity")[0], Rational(1));
    EXPECT_TRUE(gkt::first_sonine_inelasticity_expansion(d, "density_heat_coefficient")[0].is_zero());
  }
  // GNB's leading cooling term √(16/(27π)) ε is the exact first-Sonine slope 5/12 in their units.
  EXPECT_NEAR(kDelta * gkt::first_sonine_inelasticity_expansion(3, "cooling_rate")[1].to_double(),
              std::sqrt(16 / (27 * std::numbers::pi)), 1e-15);
}

TEST(InelasticityExpansion, ConvergedAgainstGoldhirschNoskowiczBarLev) {
  const auto e = gkt::inelasticity_expansion(3, 10);
  for (const auto* s : {&e.shear_viscosity, &e.thermal_conductivity, &e.density_heat_coefficient, &e.cooling_rate})
    for (int j = 0; j < 3; ++j) EXPECT_LT(s->errors[j], j < 2 ? 2e-5 : 1e-4) << j;
  // Viscosity: ε⁰ to the printed digit; the ε¹ term is 0.2 % above the printed 0.0576
  // (ours 0.05772, unexplained; docs/theory.md §11).
  EXPECT_EQ(round4(kMu * e.shear_viscosity.coefficients[0]), 0.3249);
  EXPECT_NEAR(kMu * e.shear_viscosity.coefficients[1], 0.05772, 2e-5);
  // Heat conductivity and λ̃: all three printed numbers are reproduced when the conversion
  // factor is 2/5 instead of (25/64)√(π/3) = 0.399737 (a uniform +0.066 %); with the exact
  // factor ours are 0.409818, 0.107147, 0.210818.
  EXPECT_EQ(round4(0.4 * e.thermal_conductivity.coefficients[0]), 0.4101);
  EXPECT_EQ(round4(0.4 * e.thermal_conductivity.coefficients[1]), 0.1072);
  EXPECT_EQ(round4(0.4 * e.density_heat_coefficient.coefficients[1]), 0.2110);
  EXPECT_NEAR(kKappa * e.thermal_conductivity.coefficients[0], 0.409818, 2e-6);
  EXPECT_NEAR(kKappa * e.thermal_conductivity.coefficients[1], 0.107147, 1e-5);
  EXPECT_NEAR(kKappa * e.density_heat_coefficient.coefficients[1], 0.210818, 1e-5);
  EXPECT_NEAR(e.density_heat_coefficient.coefficients[0], 0.0, 1e-9);
  // Cooling: the ε term exactly; the ε² term is −0.01097 against the printed −0.0112 (2 %).
  EXPECT_NEAR(kDelta * e.cooling_rate.coefficients[1], std::sqrt(16 / (27 * std::numbers::pi)), 1e-7);
  EXPECT_NEAR(kDelta * e.cooling_rate.coefficients[2], -0.010969, 2e-5);
}
