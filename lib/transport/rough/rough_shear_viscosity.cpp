#include "gkt/transport/rough/rough_shear_viscosity.hpp"

#include <cmath>
#include <vector>

#include "gkt/algebra/rational_polynomial.hpp"
#include "gkt/collision/rough_collision_moments.hpp"
#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"

namespace gkt {

namespace {

/// L_η and ⟨Δc1²⟩ as exact polynomials in τ = θ/κ (theory.md (19.13)); only translational forms,
/// so no negative powers of τ.
struct ShearPolynomials {
  std::vector<Rational> l_eta, energy;  // coefficients of τ^j
};

std::vector<Rational> in_tau(const RationalPolynomial& p) {
  std::vector<Rational> c;
  for (long j = 0; j <= p.degree(); j += 2) c.push_back(p.coefficient(j));
  return c;
}

void add(std::vector<Rational>& a, const std::vector<Rational>& b, const Rational& s) {
  if (a.size() < b.size()) a.resize(b.size(), Rational(0));
  for (std::size_t j = 0; j < b.size(); ++j) a[j] += s * b[j];
}

ShearPolynomials shear_polynomials(int d, const Rational& alpha, const Rational& beta, const Rational& kappa) {
  const auto p = rough_parameters_symbolic_temperature(d, alpha, beta, kappa);
  using S = RoughSlot;
  const RoughForm x1 = rough_dot_form(S::v1, S::v1), x2 = rough_dot_form(S::v2, S::v2),
                  x1p = rough_dot_form(S::v1_post, S::v1_post);
  // Y2(a):Y2(b) = (a·b)² − a² b²/d.
  const RoughCollisionMoments<RationalPolynomial> same(p, {rough_dot_form(S::v1, S::v1_post), x1, x1p}, {2, 2, 1});
  const RoughCollisionMoments<RationalPolynomial> other(p, {rough_dot_form(S::v1, S::v2), x1, x2}, {2, 1, 1});
  const RoughCollisionMoments<RationalPolynomial> other_post(p, {rough_dot_form(S::v2, S::v1_post), x2, x1p},
                                                             {2, 1, 1});
  const Rational inv_d(1, static_cast<unsigned long>(d));
  ShearPolynomials s;
  // ⟨Y2(c1):Y2(c1)⟩ − ⟨Y2(c1):Y2(c1')⟩ + ⟨Y2(c2):Y2(c1)⟩ − ⟨Y2(c2):Y2(c1')⟩.
  add(s.l_eta, in_tau(same.moment({0, 2, 0, 0})), Rational(1) - inv_d);
  add(s.l_eta, in_tau(same.moment({2, 0, 0, 0})), Rational(-1));
  add(s.l_eta, in_tau(same.moment({0, 1, 1, 0})), inv_d);
  add(s.l_eta, in_tau(other.moment({2, 0, 0, 0})), Rational(1));
  add(s.l_eta, in_tau(other.moment({0, 1, 1, 0})), -inv_d);
  add(s.l_eta, in_tau(other_post.moment({2, 0, 0, 0})), Rational(-1));
  add(s.l_eta, in_tau(other_post.moment({0, 1, 1, 0})), inv_d);
  add(s.energy, in_tau(same.moment({0, 0, 1, 0})), Rational(1));
  add(s.energy, in_tau(same.moment({0, 1, 0, 0})), Rational(-1));
  return s;
}

template <class T>
T horner(const std::vector<Rational>& c, const T& x) {
  T v(0);
  for (std::size_t j = c.size(); j-- > 0;) {
    if constexpr (std::is_same_v<T, double>) {
      v = v * x + c[j].to_double();
    } else {
      v = v * x + c[j];
    }
  }
  return v;
}

}  // namespace

Rational rough_shear_viscosity_at(int dimension, const Rational& alpha, const Rational& beta, const Rational& kappa,
                                  const Rational& temperature_ratio) {
  (void)rough_parameters(dimension, alpha, beta, kappa, temperature_ratio);  // range checks
  const ShearPolynomials s = shear_polynomials(dimension, alpha, beta, kappa);
  const Rational tau = temperature_ratio / kappa, d(dimension);
  // ζ* = −((d+2)/(2d)) ⟨Δc1²⟩ (9.4), ν_η* = L_η/(d − 1) (5.4).
  const Rational zeta = -(d + Rational(2)) / (Rational(2) * d) * horner(s.energy, tau);
  return Rational(1) / (horner(s.l_eta, tau) / (d - Rational(1)) - zeta / Rational(2));
}

double rough_shear_viscosity(int dimension, const Rational& alpha, const Rational& beta, const Rational& kappa) {
  const RoughCoolingState hcs =
      rough_homogeneous_cooling_state(dimension, alpha, beta, kappa, RoughHcsScheme::maxwellian);
  const ShearPolynomials s = shear_polynomials(dimension, alpha, beta, kappa);
  // At β = −1 neither polynomial depends on τ (the spin decouples): any τ will do.
  const double tau = hcs.spin_decoupled ? 1.0 : hcs.temperature_ratio / kappa.to_double(), d = dimension;
  const double zeta = -(d + 2) / (2 * d) * horner(s.energy, tau);
  return 1 / (horner(s.l_eta, tau) / (d - 1) - zeta / 2);
}

}  // namespace gkt
