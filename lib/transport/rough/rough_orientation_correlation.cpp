#include "gkt/transport/rough/rough_orientation_correlation.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "gkt/algebra/rational_polynomial.hpp"
#include "gkt/collision/rough_collision_moments.hpp"
#include "gkt/transport/rough/rough_homogeneous_cooling_state.hpp"

namespace gkt {

namespace {

using S = RoughSlot;

/// One collision average ⟨Π F_v^{k_v}⟩/⟨1⟩ with θ symbolic, evaluated at τ = θ/κ and divided by
/// τ^{spin_power} (the moment in the scaled spin ŵ = w/√τ; spin_power = degree in w²).
double average(const RoughCollisionParameters<RationalPolynomial>& p, const std::vector<RoughForm>& forms,
               const std::vector<int>& k, int spin_power, double tau) {
  const RoughCollisionMoments<RationalPolynomial> table(p, forms, k);
  std::array<int, 4> index{};
  for (std::size_t v = 0; v < k.size(); ++v) index[v] = k[v];
  const RationalPolynomial m = table.moment(index);
  double value = 0, power = 1;
  for (long j = 0; j <= m.degree(); j += 2, power *= tau) value += m.coefficient(j).to_double() * power;
  return value * std::pow(tau, -spin_power);
}

RoughForm dot(S a, S b) { return rough_dot_form(a, b); }

/// ⟨P(a) P(b)⟩ for P(v, w) = (v·w)² − v²w²/3 at the slot pairs (va, wa), (vb, wb), in ŵ units.
double pp(const RoughCollisionParameters<RationalPolynomial>& p, S va, S wa, S vb, S wb, double tau) {
  const RoughForm fa = dot(va, wa), fb = dot(vb, wb);
  const RoughForm xa = dot(va, va), ya = dot(wa, wa), xb = dot(vb, vb), yb = dot(wb, wb);
  if (va == vb && wa == wb)  // ⟨P²⟩ = ⟨F⁴⟩ − (2/3)⟨F² X Y⟩ + ⟨X² Y²⟩/9
    return average(p, {fa}, {4}, 2, tau) - 2.0 / 3 * average(p, {fa, xa, ya}, {2, 1, 1}, 2, tau) +
           average(p, {xa, ya}, {2, 2}, 2, tau) / 9;
  return average(p, {fa, fb}, {2, 2}, 2, tau) - average(p, {fa, xb, yb}, {2, 1, 1}, 2, tau) / 3 -
         average(p, {xa, ya, fb}, {1, 1, 2}, 2, tau) / 3 + average(p, {xa, ya, xb, yb}, {1, 1, 1, 1}, 2, tau) / 9;
}

/// ⟨P(v, w)⟩ in ŵ units.
double p1(const RoughCollisionParameters<RationalPolynomial>& p, S v, S w, double tau) {
  return average(p, {dot(v, w)}, {2}, 1, tau) - average(p, {dot(v, v), dot(w, w)}, {1, 1}, 1, tau) / 3;
}

}  // namespace

RoughOrientationCorrelation rough_orientation_correlation(const Rational& alpha, const Rational& beta,
                                                          const Rational& kappa) {
  const auto params = rough_parameters_symbolic_temperature(3, alpha, beta, kappa);  // range checks
  const RoughCoolingState hcs = rough_homogeneous_cooling_state(3, alpha, beta, kappa, RoughHcsScheme::maxwellian);
  RoughOrientationCorrelation out;
  out.temperature_ratio = hcs.temperature_ratio;
  if (hcs.spin_decoupled) return out;
  const double tau = hcs.temperature_ratio / kappa.to_double();
  // Balance of ⟨P⟩ (degree 2 in c and in ŵ, theory.md (19.10)): 2 z ⟨P⟩ + R[P] = 0 with
  // ⟨P⟩ = b ⟨P²⟩_M = (5/4) b, R[P] = R_0 + b R_b, z = ζ*·4/(d+2) (19.11).
  const double r0 = p1(params, S::v1_post, S::w1_post, tau) - p1(params, S::v1, S::w1, tau);
  const double rb = pp(params, S::v1, S::w1, S::v1_post, S::w1_post, tau) -
                    pp(params, S::v1, S::w1, S::v1, S::w1, tau) +
                    pp(params, S::v2, S::w2, S::v1_post, S::w1_post, tau) - pp(params, S::v2, S::w2, S::v1, S::w1, tau);
  const double z = hcs.cooling_rate * 4 / 5;
  out.b = -r0 / (rb + 2.5 * z);
  out.correlation = 1.0 / 3 + out.b / 5;
  return out;
}

}  // namespace gkt
