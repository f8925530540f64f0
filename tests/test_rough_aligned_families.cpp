// The aligned-spin trial families of the rough gas's Navier–Stokes modes (docs/theory.md §19.21): their exact
// collision elements against an independent Monte Carlo over collisions, the product block of the same code against
// RoughCollisionElements, the symmetry of the Galerkin matrix at Pidduck's gas, and the limits.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

#include "gkt/collision/rough_collision_rule.hpp"
#include "gkt/transport/rough/rough_orientation_correlation.hpp"
#include "gkt/transport/rough/rough_sonine_transport.hpp"
#include "rough_monte_carlo.hpp"
#include "transport/rough/rough_aligned_families.hpp"
#include "transport/rough/rough_sonine_systems.hpp"

namespace gkt {
namespace {

using test::dot3;
using test::Vec3;
using Tensor = std::array<std::array<double, 3>, 3>;

double rel(double a, double b) { return std::abs(a - b) / std::max(1.0, std::abs(b)); }

Tensor symmetric(const Vec3& a, const Vec3& b) {
  Tensor t{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) t[i][j] = 0.5 * (a[i] * b[j] + a[j] * b[i]);
  return t;
}
Tensor traceless(Tensor t) {
  const double trace = t[0][0] + t[1][1] + t[2][2];
  for (int i = 0; i < 3; ++i) t[i][i] -= trace / 3;
  return t;
}
double contract(const Tensor& a, const Tensor& b) {
  double s = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) s += a[i][j] * b[i][j];
  return s;
}

// The functions of the header written out directly in vectors (theory.md (19.48)): index 0 the lowest product of
// the rank ((cc)°; c S_1(x); S_1(x), S_1 from the library's Sonine coefficients), 1 and 2 the aligned families.
double sonine_at(int rank, double x) {
  const auto s = detail::rough_sonine_function(3, rank, rank == 2 ? 0 : 1, 0).s;
  double v = 0;
  for (std::size_t i = s.size(); i-- > 0;) v = v * x + s[i].to_double();
  return v;
}
Tensor tensor_function(int k, const Vec3& c, const Vec3& w) {
  const double y = dot3(w, w), p = dot3(c, w);
  const Tensor cc = traceless(symmetric(c, c));
  if (k == 0) return cc;
  if (k == 1) return traceless(symmetric(w, w));
  Tensor t = traceless(symmetric(c, w));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) t[i][j] = p * t[i][j] - y / 3 * cc[i][j];
  return t;
}
Vec3 vector_function(int k, const Vec3& c, const Vec3& w) {
  const double x = dot3(c, c), y = dot3(w, w), p = dot3(c, w);
  Vec3 v{};
  for (int i = 0; i < 3; ++i) v[i] = k == 0 ? c[i] * sonine_at(1, x) : w[i] * p - c[i] * y / 3;
  return v;
}
double scalar_function(int k, const Vec3& c, const Vec3& w) {
  const double x = dot3(c, c), y = dot3(w, w), p = dot3(c, w);
  return k == 0 ? sonine_at(0, x) : p * p - x * y / 3;
}

// ⟨φ, 𝓛ψ⟩ = ⟨(ψ(1) + ψ(2)):(φ(1) − φ(1'))⟩ for every pair of the lowest product and the aligned families of each
// rank: the integrand of one collision, rank r, test t, trial k.
double integrand(const test::RoughCollision& c, double lambda, int rank, int t, int k) {
  const auto scaled = [&](int s) {
    Vec3 w = c.w[static_cast<std::size_t>(s)];
    for (double& x : w) x /= lambda;
    return w;
  };
  const Vec3 w1 = scaled(2), w2 = scaled(3), w1p = scaled(6);
  if (rank == 2) {
    const Tensor a = tensor_function(k, c.w[0], w1), b = tensor_function(k, c.w[1], w2);
    const Tensor f1 = tensor_function(t, c.w[0], w1), f1p = tensor_function(t, c.w[4], w1p);
    return contract(a, f1) - contract(a, f1p) + contract(b, f1) - contract(b, f1p);
  }
  if (rank == 1) {
    const Vec3 a = vector_function(k, c.w[0], w1), b = vector_function(k, c.w[1], w2);
    const Vec3 f1 = vector_function(t, c.w[0], w1), f1p = vector_function(t, c.w[4], w1p);
    return dot3(a, f1) - dot3(a, f1p) + dot3(b, f1) - dot3(b, f1p);
  }
  return (scalar_function(k, c.w[0], w1) + scalar_function(k, c.w[1], w2)) *
         (scalar_function(t, c.w[0], w1) - scalar_function(t, c.w[4], w1p));
}

// The exact aligned elements against a Monte Carlo over collisions (tests/rough_monte_carlo.hpp: the collision applied
// from the impulse in vector form, no reduction to the engine's forms), 1.2 × 10⁵ collisions at (α, β, κ, θ) =
// (0.7, 0.3, 2/5, 13/10), every element within 5σ (ratio estimator), each error under 5 % of max(1, |element|).
TEST(RoughAlignedFamilies, ElementsAgainstMonteCarlo) {
  const double kappa = 0.4, theta = 1.3, lambda = std::sqrt(theta / kappa);
  const detail::RoughAlignedFamilyElements exact(
      rough_parameters_symbolic_temperature(3, Rational(7, 10), Rational(3, 10), Rational(2, 5)), 1);
  test::RoughCollisionSampler sampler(3, 0.7, 0.3, kappa, theta, 41);
  constexpr int kPairs = 9 + 4 + 4;
  std::array<double, kPairs> wv{}, w2v{}, w2v2{};
  double weight = 0, weight2 = 0;
  for (long i = 0; i < 120000; ++i) {
    const test::RoughCollision c = sampler.draw();
    if (c.weight <= 0) continue;
    std::size_t k = 0;
    for (int rank = 0; rank < 3; ++rank)
      for (int t = 0; t < 1 + exact.count(rank); ++t)
        for (int r = 0; r < 1 + exact.count(rank); ++r, ++k) {
          const double v = integrand(c, lambda, rank, t, r);
          wv[k] += c.weight * v;
          w2v[k] += c.weight * c.weight * v;
          w2v2[k] += c.weight * c.weight * v * v;
        }
    weight += c.weight;
    weight2 += c.weight * c.weight;
  }
  std::size_t k = 0;
  for (int rank = 0; rank < 3; ++rank) {
    const int p0 = rank == 2 ? 0 : 1;
    for (int t = 0; t < 1 + exact.count(rank); ++t)
      for (int r = 0; r < 1 + exact.count(rank); ++r, ++k) {
        const double mean = wv[k] / weight;
        const double sigma = std::sqrt(w2v2[k] - 2 * mean * w2v[k] + mean * mean * weight2) / weight;
        const double e =
            exact.element(rank, t == 0 ? p0 : -1, t == 0 ? 0 : t, r == 0 ? p0 : -1, r == 0 ? 0 : r, theta / kappa);
        EXPECT_LT(std::abs(e - mean), 5 * sigma) << rank << " " << t << " " << r << ": " << e << " vs " << mean;
        EXPECT_LT(sigma, 0.05 * std::max(1.0, std::abs(e))) << rank << " " << t << " " << r;
      }
  }
}

// Exact checks by other routes: (i) the first approximation of the orientation correlation (theory.md (19.14), its
// own engine tables) has b = −R_0[P]/(R_b[P] + (5/2)z) with R_0[P] = −⟨P, 𝓛1⟩/2 and R_b[P] = −⟨P, 𝓛P⟩, the scalar
// family's elements here (1e-10); (ii) the momentum row ⟨c, 𝓛ψ⟩ vanishes for every trial ψ, the aligned vector F and
// the products alike (c1 + c2 is conserved); (iii) at Pidduck's gas the energy row ⟨x + y, 𝓛ψ⟩ vanishes too
// (x + y = 3 − S_1(x) − L_1(y) at θ = κτ = 1, and ⟨1, 𝓛ψ⟩ = 0), for the scalar family P. (ii) and (iii) hold for any
// trial, so they check the assembly (slots, signs, the gain and loss terms), not the families' coefficients; (i) and
// the Monte Carlo check those (a coefficient 1/3 → 1/4 in P or F fails both).
TEST(RoughAlignedFamilies, OrientationCorrelationAndConservation) {
  for (const auto& [alpha, beta] : {std::pair{Rational(9, 10), Rational(1, 2)}, std::pair{Rational(1, 2), Rational(0)},
                                    std::pair{Rational(7, 10), Rational(-1, 2)}}) {
    const Rational kappa(2, 5);
    const auto p = rough_parameters_symbolic_temperature(3, alpha, beta, kappa);
    const detail::RoughAlignedFamilyElements aligned(p, 2);
    const detail::RoughCollisionElements plain(p, 1);
    const RoughOrientationCorrelation c = rough_orientation_correlation(alpha, beta, kappa);
    const double tau = c.temperature_ratio / kappa.to_double();
    const double z = -plain.element(0, 1, 0, 0, 0, tau) / 3;
    const double r0 = -aligned.element(0, -1, 1, 0, 0, tau) / 2, rb = -aligned.element(0, -1, 1, -1, 1, tau);
    EXPECT_LT(std::abs(-r0 / (rb + 2.5 * z) - c.b), 1e-10 * std::max(1e-3, std::abs(c.b))) << alpha.to_double();
    double momentum = 0, size = 0;
    for (const auto& [pt, qt] :
         {std::pair{0, 1}, std::pair{1, 0}, std::pair{0, 2}, std::pair{1, 1}, std::pair{-1, 1}}) {
      momentum = std::max(momentum, std::abs(aligned.element(1, 0, 0, pt, qt, tau)));
      size = std::max(size, std::abs(aligned.element(1, 1, 0, pt, qt, tau)));
    }
    EXPECT_LT(momentum, 1e-12 * size);
    EXPECT_GT(size, 0.1);
  }
  const detail::RoughAlignedFamilyElements pidduck(
      rough_parameters_symbolic_temperature(3, Rational(1), Rational(1), Rational(2, 5)), 1);
  const double energy = pidduck.element(0, 1, 0, -1, 1, 2.5) + pidduck.element(0, 0, 1, -1, 1, 2.5);
  EXPECT_LT(std::abs(energy), 1e-12);
  EXPECT_GT(std::abs(pidduck.element(0, 1, 0, -1, 1, 2.5)), 1e-2);  // each part alone does not vanish
}

// The products' block of the same dot-product route equals RoughCollisionElements (the engine's slot-pair tables,
// another assembly): every element of order 2 of the three ranks, d = 3, at two θ, to 1e-10.
TEST(RoughAlignedFamilies, ProductBlockIsTheSonineEngine) {
  const auto p = rough_parameters_symbolic_temperature(3, Rational(9, 10), Rational(1, 2), Rational(2, 5));
  const detail::RoughAlignedFamilyElements aligned(p, 2);
  const detail::RoughCollisionElements plain(p, 2);
  for (double tau : {0.8671 / 0.4, 3.0})
    for (int rank = 0; rank <= 2; ++rank) {
      const int top = rank == 2 ? 1 : 2;
      for (int pt = 0; pt <= top; ++pt)
        for (int qt = 0; pt + qt <= top; ++qt)
          for (int pr = 0; pr <= top; ++pr)
            for (int qr = 0; pr + qr <= top; ++qr)
              EXPECT_LT(rel(aligned.element(rank, pt, qt, pr, qr, tau), plain.element(rank, pt, qt, pr, qr, tau)),
                        1e-10)
                  << rank << " " << pt << qt << " " << pr << qr;
    }
}

// Pidduck's gas (α = β = 1, θ = 1) is time-reversible: 𝓛 is symmetric in the Maxwellian product between functions of
// equal parity under (c, ŵ) → (−c, −ŵ), which all products and aligned families share; the augmented matrix is
// symmetric (1e-11), and the Galerkin η*, κ*, η_b* can only rise when the space grows (variational).
TEST(RoughAlignedFamilies, SymmetricAtPidduckAndVariational) {
  const auto p = rough_parameters_symbolic_temperature(3, Rational(1), Rational(1), Rational(2, 5));
  const int order = 2;
  const detail::RoughAlignedFamilyElements aligned(p, order);
  const double tau = 2.5;
  for (int rank = 0; rank <= 2; ++rank) {
    std::vector<std::array<int, 2>> f;
    const int top = rank == 2 ? order - 1 : order;
    for (int a = 0; a <= top; ++a)
      for (int b = 0; a + b <= top; ++b) f.push_back({a, b});
    for (int k = 1; k <= aligned.count(rank); ++k) f.push_back({-1, k});
    double largest = 0;
    for (const auto& x : f)
      for (const auto& y : f) {
        const double xy = aligned.element(rank, x[0], x[1], y[0], y[1], tau);
        const double yx = aligned.element(rank, y[0], y[1], x[0], x[1], tau);
        EXPECT_LT(std::abs(xy - yx), 1e-11 * std::max(1.0, std::abs(xy))) << rank;
        if (x[0] < 0 || y[0] < 0) largest = std::max(largest, std::abs(xy));
      }
    EXPECT_GT(largest, 0.1) << rank;  // the families do couple
  }
  const RoughSonineTransport product(3, Rational(1), Rational(1), Rational(2, 5), 3);
  const RoughSonineTransport with(3, Rational(1), Rational(1), Rational(2, 5), 3, RoughTrialSpace::aligned);
  const RoughSonineTransport more(3, Rational(1), Rational(1), Rational(2, 5), 3, RoughTrialSpace::aligned, 2);
  for (int n = 1; n <= 3; ++n) {
    const auto a = product.at(n, 1.0), b = with.at(n, 1.0), c = more.at(n, 1.0);
    EXPECT_GT(b.shear_viscosity, a.shear_viscosity + 1e-3) << n;
    EXPECT_GT(b.thermal_conductivity, a.thermal_conductivity + 1e-3) << n;
    EXPECT_GT(b.bulk_viscosity, a.bulk_viscosity) << n;
    EXPECT_GE(c.shear_viscosity, b.shear_viscosity - 1e-12) << n;  // a larger space again
    EXPECT_GE(c.thermal_conductivity, b.thermal_conductivity - 1e-12) << n;
    EXPECT_GE(c.bulk_viscosity, b.bulk_viscosity - 1e-12) << n;
    EXPECT_LT(std::abs(b.density_heat_coefficient), 1e-12) << n;  // μ* = 0 at Pidduck's gas, still
  }
}

// The Maxwellian products of the lowest aligned families, summed from the invariants' moments, equal the ones worked
// by hand in theory.md (19.48) (⟨T1:T1⟩ = 5/2, ⟨T1:T2⟩ = 5/4, ⟨T2:T2⟩ = 85/48, ⟨F·F⟩ = ⟨P²⟩ = 5/4), and G = degree × N
// (the families are homogeneous of degrees 2, 4; 3; 4); with a second member G and N are symmetric where they must be.
TEST(RoughAlignedFamilies, MaxwellProducts) {
  const detail::RoughAlignedFamilyElements a(
      rough_parameters_symbolic_temperature(3, Rational(9, 10), Rational(1, 2), Rational(2, 5)), 1);
  const double n[3][2][2] = {{{1.25, 0}, {0, 0}}, {{1.25, 0}, {0, 0}}, {{2.5, 1.25}, {1.25, 85.0 / 48}}};
  const int degree[3][2] = {{4, 0}, {3, 0}, {2, 4}};
  for (int rank = 0; rank <= 2; ++rank)
    for (int i = 1; i <= a.count(rank); ++i)
      for (int j = 1; j <= a.count(rank); ++j) {
        EXPECT_LT(std::abs(a.maxwell_product(rank, i, j) - n[rank][i - 1][j - 1]), 1e-14) << rank << i << j;
        EXPECT_LT(std::abs(a.maxwell_scaling_product(rank, i, j) - degree[rank][i - 1] * n[rank][i - 1][j - 1]), 1e-13)
            << rank << i << j;
      }
  const detail::RoughAlignedFamilyElements b(
      rough_parameters_symbolic_temperature(3, Rational(9, 10), Rational(1, 2), Rational(2, 5)), 1, 2);
  for (int rank = 0; rank <= 2; ++rank) {
    EXPECT_EQ(b.count(rank), 3 * (rank == 2 ? 2 : 1));
    for (int i = 1; i <= b.count(rank); ++i)
      for (int j = 1; j <= b.count(rank); ++j)
        EXPECT_LT(std::abs(b.maxwell_product(rank, i, j) - b.maxwell_product(rank, j, i)), 1e-13);
  }
}

// β = −1: the spin decouples and every aligned family with it; the translational values are the product space's.
// Disks have no c·ŵ: refused; and the families have no weighted (cumulant-reference) elements: refused.
TEST(RoughAlignedFamilies, SmoothLimitAndRefusals) {
  const RoughSonineTransport product(3, Rational(7, 10), Rational(-1), Rational(2, 5), 2);
  const RoughSonineTransport with(3, Rational(7, 10), Rational(-1), Rational(2, 5), 2, RoughTrialSpace::aligned);
  for (int n = 1; n <= 2; ++n) {
    EXPECT_EQ(with.at_maxwellian_state(n).shear_viscosity, product.at_maxwellian_state(n).shear_viscosity);
    EXPECT_EQ(with.at_maxwellian_state(n).thermal_conductivity_translational,
              product.at_maxwellian_state(n).thermal_conductivity_translational);
  }
  EXPECT_THROW(RoughSonineTransport(2, Rational(9, 10), Rational(1, 2), Rational(1, 2), 1, RoughTrialSpace::aligned),
               std::invalid_argument);
  const RoughSonineCoolingState hcs =
      rough_sonine_cooling_state(3, Rational(7, 10), Rational(-1), Rational(2, 5), 1, RoughSonineScheme::linear);
  EXPECT_THROW((void)with.at_cooling_state(1, hcs), std::invalid_argument);
}

}  // namespace
}  // namespace gkt
