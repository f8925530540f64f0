// Invariants of the exact-algebra layer: rational parsing and conversion, Sonine polynomials.
#include <gtest/gtest.h>

#include <cmath>

#include "gkt/algebra/rational.hpp"
#include "gkt/algebra/rational_polynomial.hpp"
#include "gkt/algebra/sonine.hpp"

using gkt::Rational;

TEST(Rational, ParsesDecimalsExactly) {
  EXPECT_EQ(Rational::parse("0.6"), Rational(3, 5));
  EXPECT_EQ(Rational::parse("-1.25e-3"), Rational(-1, 800));
  EXPECT_EQ(Rational::parse("205/202"), Rational(205, 202));
  EXPECT_THROW(Rational::parse("0.6x"), std::invalid_argument);
  EXPECT_THROW(Rational::parse("1/0"), std::invalid_argument);
}

// What the user typed comes back the way it was typed: parse ∘ to_decimal_string is the identity,
// and a non-terminating fraction falls back to p/q.
TEST(Rational, EchoesTerminatingDecimals) {
  EXPECT_EQ(Rational(5001, 10000).to_decimal_string(), "0.5001");
  EXPECT_EQ(Rational(-1, 800).to_decimal_string(), "-0.00125");
  EXPECT_EQ(Rational(3, 2).to_decimal_string(), "1.5");
  EXPECT_EQ(Rational(-7).to_decimal_string(), "-7");
  EXPECT_EQ(Rational(0).to_decimal_string(), "0");
  EXPECT_EQ(Rational(1, 3).to_decimal_string(), "1/3");
  EXPECT_EQ(Rational(-205, 202).to_decimal_string(), "-205/202");
  for (const char* text : {"0.6", "-1.25e-3", "1e-30", "123456789.000123", "0.3"})
    EXPECT_EQ(Rational::parse(Rational::parse(text).to_decimal_string()), Rational::parse(text)) << text;
}

TEST(Rational, ConvertsToNearestDouble) {
  EXPECT_EQ(Rational(1, 3).to_double(), 1.0 / 3.0);
  EXPECT_EQ(Rational(205, 202).to_double(), 205.0 / 202.0);
  const Rational big = Rational::factorial(60) / (Rational::factorial(59) * Rational(7));
  EXPECT_EQ(big.to_double(), 60.0 / 7.0);
  EXPECT_EQ(Rational::from_double(0.1).to_double(), 0.1);
}

TEST(Rational, ExactSquareRoots) {
  EXPECT_EQ(Rational(49, 4).exact_sqrt(), Rational(7, 2));
  EXPECT_FALSE(Rational(2).is_square());
  EXPECT_THROW((void)Rational(2).exact_sqrt(), std::domain_error);
}

TEST(RationalPolynomial, ArithmeticAndEvaluation) {
  const auto a = gkt::RationalPolynomial::variable();
  const auto p = (a + gkt::RationalPolynomial(1)) * (a - gkt::RationalPolynomial(1));  // α² − 1
  EXPECT_EQ(p.degree(), 2);
  EXPECT_EQ(p.evaluate(Rational(3, 5)), Rational(-16, 25));
  EXPECT_EQ(p.to_string(), "alpha^2 - 1");
}

// Sonine polynomials against the explicit low orders [chapman1970] eq. 7.51,2:
// S_m^(0) = 1, S_m^(1) = m + 1 − x, S_m^(2) = (m+1)(m+2)/2 − (m+2) x + x²/2.
TEST(Sonine, LowOrdersHalfInteger) {
  const long twice_m = 3;  // m = 3/2
  const auto s1 = gkt::sonine_coefficients(twice_m, 1);
  EXPECT_EQ(s1[0], Rational(5, 2));
  EXPECT_EQ(s1[1], Rational(-1));
  const auto s2 = gkt::sonine_coefficients(twice_m, 2);
  EXPECT_EQ(s2[0], Rational(35, 8));
  EXPECT_EQ(s2[1], Rational(-7, 2));
  EXPECT_EQ(s2[2], Rational(1, 2));
}

// Orthogonality, exactly: Σ_{k,l} c_k c'_l Γ(m+1+k+l)/Γ(m+1) = δ_pq Γ(m+p+1)/(p! Γ(m+1)).
TEST(Sonine, OrthogonalityExact) {
  for (long twice_m : {-1L, 0L, 1L, 2L, 3L, 5L}) {
    for (int p = 0; p <= 8; ++p)
      for (int q = 0; q <= 8; ++q) {
        const auto a = gkt::sonine_coefficients(twice_m, p);
        const auto b = gkt::sonine_coefficients(twice_m, q);
        Rational sum;
        for (int k = 0; k <= p; ++k)
          for (int l = 0; l <= q; ++l)
            sum += a[k] * b[l] * Rational::rising_half(twice_m + 2, static_cast<unsigned long>(k + l));
        EXPECT_EQ(sum, p == q ? gkt::sonine_norm(twice_m, p) : Rational(0))
            << "2m=" << twice_m << " p=" << p << " q=" << q;
      }
  }
}

// Generating function Σ s^n S_m^(n)(x) = (1−s)^{−m−1} exp(−xs/(1−s)), summed to high order.
TEST(Sonine, GeneratingFunction) {
  for (long twice_m : {1L, 3L, 5L}) {
    const double x = 1.7, s = 0.3;
    double sum = 0, power = 1;
    for (int n = 0; n <= 60; ++n, power *= s) sum += power * gkt::sonine_value(twice_m, n, x);
    EXPECT_NEAR(sum, gkt::sonine_generating_function(twice_m, x, s), 1e-12);
  }
}

TEST(Sonine, RecurrenceMatchesExactCoefficients) {
  const auto c = gkt::sonine_coefficients(5, 12);
  double direct = 0;
  for (int k = 12; k >= 0; --k) direct = direct * 2.3 + c[k].to_double();
  EXPECT_NEAR(gkt::sonine_value(5, 12, 2.3), direct, 1e-10 * std::abs(direct) + 1e-12);
}
