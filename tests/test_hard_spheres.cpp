// Elastic hard spheres and disks: published values and invariants of the Sonine solver.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <flint/fmpq_mat.h>

#include "gkt/models/transport_model.hpp"
#include "gkt/operators/linearized_operator.hpp"
#include "gkt/transport/monodisperse/hard_spheres.hpp"

using gkt::HardSphereCoefficient;
using gkt::Rational;

// Exact Sonine approximants, 3D: Chapman & Cowling, The Mathematical Theory of Non-uniform
// Gases, 3rd ed. (1970) §10.51: [η]_2 = (1 + 3/202)[η]_1, [κ]_2 = (1 + 1/44)[κ]_1; third
// approximants as re-derived independently by exact Gaussian moments (PHYSICS.md §2).
TEST(HardSpheres3D, ExactSonineApproximants) {
  gkt::HardSphereSonineSystem s(3);
  EXPECT_EQ(s.reduced_coefficient(HardSphereCoefficient::shear_viscosity, 1), Rational(1));
  EXPECT_EQ(s.reduced_coefficient(HardSphereCoefficient::shear_viscosity, 2), Rational(205, 202));
  EXPECT_EQ(s.reduced_coefficient(HardSphereCoefficient::shear_viscosity, 3), Rational(1178769, 1160344));
  EXPECT_EQ(s.reduced_coefficient(HardSphereCoefficient::thermal_conductivity, 1), Rational(1));
  EXPECT_EQ(s.reduced_coefficient(HardSphereCoefficient::thermal_conductivity, 2), Rational(45, 44));
  EXPECT_EQ(s.reduced_coefficient(HardSphereCoefficient::thermal_conductivity, 3), Rational(60989, 59512));
}

// Self-diffusion, second approximation: f_D = 1/(1 − Δ), Δ = (6C* − 5)²/(55 − 12B* + 16A*)
// (Hirschfelder, Curtiss & Bird 1954, §8.2; Mason, J. Chem. Phys. 27, 75 (1957)) with
// A* = B* = C* = 1 for rigid spheres: Δ = 1/59, f_D = 59/58.
TEST(HardSpheres3D, SelfDiffusionSecondApproximation) {
  gkt::HardSphereSonineSystem s(3);
  EXPECT_EQ(s.reduced_coefficient(HardSphereCoefficient::self_diffusion, 1), Rational(1));
  EXPECT_EQ(s.reduced_coefficient(HardSphereCoefficient::self_diffusion, 2), Rational(59, 58));
}

// Converged factors: Pekeris & Alterman, Proc. Natl. Acad. Sci. 43, 998 (1957):
// f_η = 1.016034, f_κ = 1.025218 (7 printed digits). Order 20 has estimated error < 1e-10,
// so the value must round to the printed digits.
TEST(HardSpheres3D, ConvergedPekerisAlterman) {
  gkt::HardSphereSonineSystem s(3);
  const auto eta = s.estimate(HardSphereCoefficient::shear_viscosity, 20);
  const auto kappa = s.estimate(HardSphereCoefficient::thermal_conductivity, 20);
  EXPECT_LT(eta.error.to_double(), 1e-10);
  EXPECT_LT(kappa.error.to_double(), 1e-10);
  EXPECT_NEAR(eta.value.to_double(), 1.016034, 5e-7);
  EXPECT_NEAR(kappa.value.to_double(), 1.025218, 5e-7);
  EXPECT_EQ(std::round(eta.value.to_double() * 1e6) / 1e6, 1.016034);
  EXPECT_EQ(std::round(kappa.value.to_double() * 1e6) / 1e6, 1.025218);
}

// Hard disks: first correction 1/50 to the viscosity (Gass, J. Chem. Phys. 54, 1898 (1971),
// second Sonine approximation f_η = 1.02); converged values documented in docs/theory.md §7.
TEST(HardDisks2D, SecondApproximationAndConvergence) {
  gkt::HardSphereSonineSystem s(2);
  EXPECT_EQ(s.reduced_coefficient(HardSphereCoefficient::shear_viscosity, 2), Rational(51, 50));
  for (auto c : {HardSphereCoefficient::shear_viscosity, HardSphereCoefficient::thermal_conductivity,
                 HardSphereCoefficient::self_diffusion}) {
    const auto e = s.estimate(c, 20);
    EXPECT_TRUE(e.converging);
    EXPECT_LT(e.error.to_double(), 1e-9);
  }
}

// Invariant: the Sonine sequence increases monotonically (variational principle for the
// elastic operator) and converges geometrically; the estimated error bounds the actual error
// (taken from order 40) from above, within a factor 1.5.
TEST(HardSpheres, ConvergenceAndErrorEstimate) {
  for (int d : {2, 3}) {
    gkt::HardSphereSonineSystem s(d);
    for (auto c : {HardSphereCoefficient::shear_viscosity, HardSphereCoefficient::thermal_conductivity,
                   HardSphereCoefficient::self_diffusion}) {
      const Rational truth = s.reduced_coefficient(c, 40);
      for (int n = 1; n <= 25; ++n) {
        EXPECT_LT(s.reduced_coefficient(c, n), s.reduced_coefficient(c, n + 1)) << "d=" << d << " N=" << n;
        const auto e = s.estimate(c, n);
        const double actual = (truth - e.value).abs().to_double();
        EXPECT_GE(e.error.to_double(), actual) << "d=" << d << " N=" << n;
        EXPECT_LE(e.error.to_double(), 1.5 * actual) << "d=" << d << " N=" << n;
      }
    }
  }
}

// Normalisation chain, independent of the reduction constants: η from ν·L and the
// Chapman–Enskog formula η = T(d−1)(d+2)/(4σ^{d−1}v0) (L⁻¹)_00/ν equals the closed-form
// first-Sonine η0 of docs/conventions.md; likewise κ and D (m = T = σ = n = 1).
TEST(HardSpheres, FirstSonineMatchesReferenceFormulas) {
  for (int d : {2, 3}) {
    const double nu = gkt::linearized_operator_prefactor(d);
    const double v0 = std::sqrt(2.0);
    const auto shear = gkt::linearized_operator_matrix<Rational>(d, Rational(1), gkt::OperatorPart::full, 2, 0);
    const auto heat = gkt::linearized_operator_matrix<Rational>(d, Rational(1), gkt::OperatorPart::full, 1, 1);
    const auto tracer = gkt::linearized_operator_matrix<Rational>(d, Rational(1), gkt::OperatorPart::tracer, 1, 0);
    const double eta = (d - 1) * (d + 2) / 4.0 / v0 / (nu * shear(0, 0).to_double());
    const double kappa = v0 / d * std::pow(d * (d + 2) / 4.0, 2) / (nu * heat(1, 1).to_double());
    const double diff = v0 * d / 4.0 / (nu * tracer(0, 0).to_double());
    EXPECT_NEAR(eta / gkt::reference_shear_viscosity(d, 1, 1, 1), 1.0, 1e-14) << d;
    EXPECT_NEAR(kappa / gkt::reference_thermal_conductivity(d, 1, 1, 1), 1.0, 1e-14) << d;
    EXPECT_NEAR(diff / gkt::reference_self_diffusion(d, 1, 1, 1, 1), 1.0, 1e-14) << d;
  }
  // The PHYSICS.md 3D closed forms: η0 = (5/16σ²)√(mT/π), D0 = (3/(8nσ²))√(T/(πm)).
  EXPECT_NEAR(gkt::reference_shear_viscosity(3, 1, 1, 1), 5 / (16 * std::sqrt(std::numbers::pi)), 1e-15);
  EXPECT_NEAR(gkt::reference_shear_viscosity(2, 1, 1, 1), 1 / (2 * std::sqrt(std::numbers::pi)), 1e-15);
  EXPECT_NEAR(gkt::reference_self_diffusion(3, 1, 1, 1, 1), 3 / (8 * std::sqrt(std::numbers::pi)), 1e-15);
}

namespace {
bool leading_minors_positive(const gkt::DenseMatrix<Rational>& l, int first, int n) {
  for (int k = 1; k <= n; ++k) {
    fmpq_mat_t m;
    fmpq_mat_init(m, k, k);
    for (int r = 0; r < k; ++r)
      for (int c = 0; c < k; ++c) fmpq_set(fmpq_mat_entry(m, r, c), l(first + r, first + c).raw());
    Rational det;
    fmpq_mat_det(det.raw(), m);
    fmpq_mat_clear(m);
    if (det.sign() <= 0) return false;
  }
  return true;
}
}  // namespace

// Invariants of the elastic operator: symmetric; conservation laws give exact null rows and
// columns (rank 1: momentum, index 0; rank 0: number and energy, indices 0 and 1); positive
// definite on the complement (Sylvester's criterion, exact determinants).
TEST(LinearizedOperator, ElasticSymmetryConservationPositivity) {
  const int n = 8;
  for (int d : {2, 3}) {
    for (int rank = 0; rank <= 2; ++rank) {
      const auto l = gkt::linearized_operator_matrix<Rational>(d, Rational(1), gkt::OperatorPart::full, rank, n);
      for (int p = 0; p <= n; ++p)
        for (int q = 0; q <= n; ++q) EXPECT_EQ(l(p, q), l(q, p)) << d << " " << rank << " " << p << " " << q;
      const int conserved = rank == 0 ? 2 : rank == 1 ? 1 : 0;
      for (int c = 0; c < conserved; ++c)
        for (int q = 0; q <= n; ++q) EXPECT_TRUE(l(c, q).is_zero()) << d << " " << rank << " " << c << " " << q;
      EXPECT_TRUE(leading_minors_positive(l, conserved, n + 1 - conserved)) << d << " " << rank;
    }
    const auto tracer = gkt::linearized_operator_matrix<Rational>(d, Rational(1), gkt::OperatorPart::tracer, 1, n);
    EXPECT_TRUE(leading_minors_positive(tracer, 0, n + 1)) << d;
  }
}

// Inelastic collisions still conserve momentum (rank-1 row 0 vanishes for every α) but not
// energy: the rank-0 energy row is ∝ (1 − α²); symbolic α gives this as a polynomial identity.
TEST(LinearizedOperator, InelasticConservationExactInAlpha) {
  const auto alpha = gkt::RationalPolynomial::variable();
  for (int d : {2, 3}) {
    const auto vec = gkt::linearized_operator_matrix<gkt::RationalPolynomial>(d, alpha, gkt::OperatorPart::full, 1, 3);
    for (int q = 0; q <= 3; ++q) EXPECT_TRUE(vec(0, q).is_zero());
    const auto scalar =
        gkt::linearized_operator_matrix<gkt::RationalPolynomial>(d, alpha, gkt::OperatorPart::full, 0, 3);
    for (int q = 0; q <= 3; ++q) {
      EXPECT_TRUE(scalar(0, q).is_zero());  // number conserved
      EXPECT_TRUE(scalar(1, q).evaluate(Rational(1)).is_zero());
      EXPECT_TRUE(scalar(1, q).evaluate(Rational(-1)).is_zero());  // factor (1 − α²)
    }
    EXPECT_FALSE(scalar(1, 0).is_zero());
  }
}

// The model registry: unknown names list the valid ones; tolerance picks the smallest order.
TEST(ModelRegistry, NamesAndTolerance) {
  try {
    (void)gkt::make_transport_model("no-such-model");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("\"hard-spheres\""), std::string::npos);
  }
  auto m = gkt::make_transport_model("hard-spheres");
  gkt::OrderRequest request;
  request.tolerance = Rational(1, 1000000);
  const auto v = m->evaluate({{{"dimension", Rational(3)}}, {}}, {"shear_viscosity"}, request);
  ASSERT_EQ(v.size(), 1U);
  EXPECT_LT(v[0].error, Rational(1, 1000000));
  gkt::HardSphereSonineSystem s(3);
  EXPECT_GE(s.estimate(HardSphereCoefficient::shear_viscosity, v[0].order - 1).error, Rational(1, 1000000));
  EXPECT_THROW((void)m->evaluate({{{"dimension", Rational(4)}}, {}}, {"shear_viscosity"}, {}), std::invalid_argument);
}
