// First-Sonine closed forms of the dilute smooth inelastic gas: the engine's expressions against
// the published formulas as exact rational functions of α, and the generated fast evaluator.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "gkt/transport/closed_forms/first_sonine_formulas.hpp"

using gkt::Rational;
using gkt::RationalFunction;
using gkt::RationalPolynomial;

namespace {
RationalFunction k(const Rational& c) { return RationalFunction{RationalPolynomial(c), RationalPolynomial(1L)}; }
RationalFunction poly(const RationalPolynomial& p) { return RationalFunction{p, RationalPolynomial(1L)}; }
}  // namespace

// Published standard first-Sonine results, composed symbolically:
//   a2 (van Noije & Ernst 1998), ζ* = ((d+2)/(4d))(1−α²)(1 + 3a2/16),
//   ν_η*, ν_κ* (Garzó 2019, ch. 3; Garzó, Santos & Montanero 2007), and
//   η* = 1/(ν_η − ζ/2), κ* = ((d−1)/d)(1+2a2)/(ν_κ − 2ζ), μ* = 2ζ(κ* + ((d−1)/d)a2/ζ)/(2ν_κ − 3ζ).
TEST(FirstSonineFormulas, EqualPublishedFormsAsRationalFunctions) {
  const auto al = poly(RationalPolynomial::variable());
  const auto one = k(Rational(1));
  for (int d : {2, 3}) {
    const Rational dd(d);
    const RationalFunction a2 =
        k(Rational(16)) * (one - al) * (one - k(Rational(2)) * al * al) /
        (k(Rational(9 + 24 * d)) - al * k(Rational(41 - 8 * d)) + k(Rational(30)) * al * al * (one - al));
    const RationalFunction zeta =
        k(Rational(d + 2) / (Rational(4) * dd)) * (one - al * al) * (one + k(Rational(3, 16)) * a2);
    const RationalFunction nu_eta = k(Rational(3) / (Rational(4) * dd)) *
                                    (one - al + k(Rational(2) * dd / Rational(3))) * (one + al) *
                                    (one - a2 * k(Rational(1, 32)));
    const RationalFunction nu_kappa =
        (one + al) * k(Rational(1) / dd) *
        (k(Rational(d - 1, 2)) + k(Rational(3 * (d + 8), 16)) * (one - al) +
         (k(Rational(4 + 5 * d)) - k(Rational(3 * (4 - d))) * al) * a2 * k(Rational(1, 512)));
    const RationalFunction eta = one / (nu_eta - zeta * k(Rational(1, 2)));
    const RationalFunction kappa =
        k(Rational(d - 1) / dd) * (one + k(Rational(2)) * a2) / (nu_kappa - k(Rational(2)) * zeta);
    const RationalFunction mu = (k(Rational(2)) * zeta * kappa + k(Rational(2) * Rational(d - 1) / dd) * a2) /
                                (k(Rational(2)) * nu_kappa - k(Rational(3)) * zeta);
    EXPECT_TRUE(gkt::first_sonine_closed_form(d, "a2").equals(a2)) << d;
    EXPECT_TRUE(gkt::first_sonine_closed_form(d, "cooling_rate").equals(zeta)) << d;
    EXPECT_TRUE(gkt::first_sonine_closed_form(d, "shear_viscosity").equals(eta)) << d;
    EXPECT_TRUE(gkt::first_sonine_closed_form(d, "thermal_conductivity").equals(kappa)) << d;
    EXPECT_TRUE(gkt::first_sonine_closed_form(d, "density_heat_coefficient").equals(mu)) << d;
  }
}

// Published modified first-Sonine results (Garzó, Santos & Montanero, Physica A 376, 94 (2007)):
// the same η*, κ*, μ* structure with ν_η* = (3/(4d))(1 − α + 2d/3)(1 + α)(1 + 7a2/16) and
//   ν_κ* = ((1+α)/d)[(d−1)/2 + (3/16)(d+8)(1−α) + (296 + 217d − 3(160 + 11d)α) a2/256].
TEST(FirstSonineFormulas, ModifiedSchemeEqualsPublishedFormsAsRationalFunctions) {
  const auto al = poly(RationalPolynomial::variable());
  const auto one = k(Rational(1));
  const auto modified = gkt::SonineScheme::modified;
  for (int d : {2, 3}) {
    const Rational dd(d);
    const RationalFunction a2 = gkt::first_sonine_closed_form(d, "a2");
    const RationalFunction zeta = gkt::first_sonine_closed_form(d, "cooling_rate");
    const RationalFunction nu_eta = k(Rational(3) / (Rational(4) * dd)) *
                                    (one - al + k(Rational(2) * dd / Rational(3))) * (one + al) *
                                    (one + a2 * k(Rational(7, 16)));
    const RationalFunction nu_kappa =
        (one + al) * k(Rational(1) / dd) *
        (k(Rational(d - 1, 2)) + k(Rational(3 * (d + 8), 16)) * (one - al) +
         (k(Rational(296 + 217 * d)) - k(Rational(3 * (160 + 11 * d))) * al) * a2 * k(Rational(1, 256)));
    const RationalFunction eta = one / (nu_eta - zeta * k(Rational(1, 2)));
    const RationalFunction kappa =
        k(Rational(d - 1) / dd) * (one + k(Rational(2)) * a2) / (nu_kappa - k(Rational(2)) * zeta);
    const RationalFunction mu = (k(Rational(2)) * zeta * kappa + k(Rational(2) * Rational(d - 1) / dd) * a2) /
                                (k(Rational(2)) * nu_kappa - k(Rational(3)) * zeta);
    EXPECT_TRUE(gkt::first_sonine_closed_form(d, "shear_viscosity", modified).equals(eta)) << d;
    EXPECT_TRUE(gkt::first_sonine_closed_form(d, "thermal_conductivity", modified).equals(kappa)) << d;
    EXPECT_TRUE(gkt::first_sonine_closed_form(d, "density_heat_coefficient", modified).equals(mu)) << d;
    EXPECT_FALSE(gkt::first_sonine_closed_form(d, "thermal_conductivity").equals(kappa)) << d;
  }
}

// The elastic limit is exact and the closed forms have no pole on (0, 1] (α → 1 continuous).
TEST(FirstSonineFormulas, ElasticLimitAndNoPoles) {
  for (int d : {2, 3}) {
    EXPECT_EQ(gkt::first_sonine_closed_form(d, "shear_viscosity").evaluate(Rational(1)), Rational(1));
    EXPECT_EQ(gkt::first_sonine_closed_form(d, "thermal_conductivity").evaluate(Rational(1)), Rational(1));
    EXPECT_TRUE(gkt::first_sonine_closed_form(d, "density_heat_coefficient").evaluate(Rational(1)).is_zero());
    for (const auto& name : gkt::kFirstSonineCoefficients) {
      const auto f = gkt::first_sonine_closed_form(d, name);
      for (int i = 1; i <= 1000; ++i)
        EXPECT_FALSE(f.denominator.evaluate(Rational(i, 1000)).is_zero()) << name << " pole at " << i << "/1000";
    }
  }
  EXPECT_THROW((void)gkt::first_sonine_closed_form(3, "a3"), std::invalid_argument);
}

// The generated C++ (lib/transport/closed_forms/generated) evaluates the exact forms to 1e-13 relative.
TEST(FirstSonineFormulas, GeneratedCodeMatchesExactValues) {
  for (int d : {2, 3}) {
    std::vector<RationalFunction> forms;
    for (const auto& name : gkt::kFirstSonineCoefficients) forms.push_back(gkt::first_sonine_closed_form(d, name));
    for (int i = 1; i <= 100; ++i) {
      const Rational alpha(i, 100);
      const auto v = gkt::first_sonine_values(d, alpha.to_double());
      const double got[] = {v.a2, v.cooling_rate, v.shear_viscosity, v.thermal_conductivity,
                            v.density_heat_coefficient};
      for (std::size_t c = 0; c < gkt::kFirstSonineCoefficients.size(); ++c) {
        const double exact =
            gkt::first_sonine_closed_form(d, gkt::kFirstSonineCoefficients[c]).evaluate(alpha).to_double();
        EXPECT_NEAR(got[c], exact, 1e-13 * std::max(1.0, std::abs(exact)))
            << gkt::kFirstSonineCoefficients[c] << " d=" << d << " alpha=" << alpha;
      }
    }
  }
  EXPECT_THROW((void)gkt::first_sonine_values(3, 0.0), std::invalid_argument);
}
