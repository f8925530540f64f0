#include "gkt/operators/collisional_transfer.hpp"

#include <cmath>
#include <stdexcept>

#include "algebra/coefficient_polynomial.hpp"
#include "collision/ring.hpp"
#include "gkt/algebra/sonine.hpp"
#include "gkt/collision/quadratic_form_moments.hpp"
#include "gkt/operators/linearized_operator.hpp"
#include "operators/transfer_contractions.hpp"

namespace gkt {

using detail::contract2;
using detail::contract3;
using detail::derivative_factors;
using detail::max_degree;
using detail::Table;
using detail::temperature_factors;

namespace {

/// Returns c_d with n σ^d = c_d φ: c_d = 2^{d−1} d Γ(d/2)/π^{d/2}.
double packing_factor(int dimension) {
  const double d = dimension;
  return std::pow(2.0, d - 1) * d * std::tgamma(d / 2) / std::pow(M_PI, d / 2);
}

}  // namespace

double collisional_transfer_factor(int dimension) {
  // π^{−d} J_{−1,0} = ν √(π/2) (theory.md (15.3)).
  return packing_factor(dimension) * linearized_operator_prefactor(dimension) * std::sqrt(M_PI / 2);
}

double collisional_gradient_factor(int dimension) {
  const double d = dimension, c_d = packing_factor(dimension);
  return c_d * c_d * linearized_operator_prefactor(dimension) * std::sqrt(2.0) * std::pow(M_PI, (d - 1) / 2) /
         (d * (d + 2) * (d + 2) * std::tgamma(d / 2));
}

template <class Ring>
CollisionalTransferMoments<Ring> collisional_transfer_moments(int dimension, const Ring& alpha, int n_max, int k_max,
                                                              int n_test) {
  if (dimension != 2 && dimension != 3) throw std::invalid_argument("dimension: must be 2 or 3");
  if (n_test < 0 || n_test > n_max) n_test = n_max;
  if (n_max < 0 || k_max < 0) throw std::invalid_argument("collisional_transfer_moments: negative size");
  const int d = dimension;
  const CollisionPair pair{d, Rational(1), Rational(1), Rational(1), Rational(1)};
  const Table st = sonine_table(sonine_twice_m(d, 2), n_max);
  const Table sv = sonine_table(sonine_twice_m(d, 1), n_max);
  const Table sk = sonine_table(sonine_twice_m(d, 0), k_max);
  const Table dl = derivative_factors(d, k_max);
  const Table tl = temperature_factors(d, k_max);
  const int nk = max_degree(sk), nd = max_degree(dl), nt = max_degree(tl), nn = n_max + 1;
  // Source tables need only the test rows p ≤ n_test (their boxes grow with it).
  const Table st_test = sonine_table(sonine_twice_m(d, 2), n_test);
  const Table sv_test = sonine_table(sonine_twice_m(d, 1), n_test);
  const Table ss_test = sonine_table(sonine_twice_m(d, 0), n_test);
  const int nn_test = n_test + 1;

  const SlotVector c1 = slot_vector(Slot::v1), c2 = slot_vector(Slot::v2), c1p = slot_vector(Slot::v1_post);
  const SlotVector h = collision_vector();
  const SlotVector g = combine(slot_vector(Slot::v1), c2, Rational(1));  // 2G = c1 + c2
  const VelocityForm x1 = dot_form(c1, c1), x2 = dot_form(c2, c2), x1p = dot_form(c1p, c1p);
  const Rational minus_one(-1), inv_d(1, static_cast<unsigned long>(d)), quarter(1, 4), half(1, 2);
  using Q = QuadraticFormMoments<Ring>;

  CollisionalTransferMoments<Ring> out;
  out.dimension = d;
  out.n_max = n_max;
  out.n_test = n_test;
  out.k_max = k_max;

  {  // shear source: polarisation (c·H)(c·c2) = ¼[(c·(H + c2))² − (c·(H − c2))²]
    const int nn = nn_test;
    const Q gp(pair, alpha, {x1, x2, x1p, dot_form(c1p, combine(h, c2, Rational(1)))}, {nk, nd, nn, 2}, minus_one);
    const Q gm(pair, alpha, {x1, x2, x1p, dot_form(c1p, combine(h, c2, minus_one))}, {nk, nd, nn, 2}, minus_one);
    const Q lp(pair, alpha, {x1, x2, dot_form(c1, combine(h, c2, Rational(1)))}, {nk + nn, nd, 2}, minus_one);
    const Q lm(pair, alpha, {x1, x2, dot_form(c1, combine(h, c2, minus_one))}, {nk + nn, nd, 2}, minus_one);
    const Q hc(pair, alpha, {x1, x2, x1p, dot_form(h, c2)}, {nk + nn + 1, nd, nn + 1, 1}, minus_one);
    auto raw = [&](int a, int b, int j) {
      Ring gain = gp.moment({a, b, j, 2}) - gm.moment({a, b, j, 2});
      detail::scale(gain, quarter);
      Ring gain2 = hc.moment({a, b, j + 1, 1});
      detail::scale(gain2, inv_d);
      Ring loss = lp.moment({a + j, b, 2, 0}) - lm.moment({a + j, b, 2, 0});
      detail::scale(loss, quarter);
      Ring loss2 = hc.moment({a + j + 1, b, 0, 1});
      detail::scale(loss2, inv_d);
      return (gain - gain2) - (loss - loss2);
    };
    out.shear_source = contract3<Ring>(raw, st_test, sk, dl);
  }
  {  // shear flux [q][k]
    const Q f(pair, alpha, {x1, x2, dot_form(h, c2), dot_form(h, h)}, {nk, nn + 1, 2, 1}, minus_one);
    auto raw = [&](int a, int b) {
      Ring v = f.moment({a, b + 1, 0, 1});
      detail::scale(v, inv_d);
      return f.moment({a, b, 2, 0}) - v;
    };
    out.shear_flux = contract2<Ring>(raw, st, sk);
  }
  {  // shear gradient [k][l]
    const Q f(pair, alpha, {x1, x2, dot_form(h, c2)}, {nk, nd, 1}, Rational(0));
    auto raw = [&](int a, int b) { return f.moment({b, a, 1, 0}); };  // a ↔ X2 (l), b ↔ X1 (k)
    out.shear_gradient = contract2<Ring>(raw, sk, dl);
  }
  {  // heat sources [p][k][l]
    const int nb = std::max(nt, nk), nn = nn_test;
    const Q hg(pair, alpha, {x1, x2, x1p, dot_form(h, c1p)}, {nk, nb, nn, 1}, minus_one);
    const Q hl(pair, alpha, {x1, x2, dot_form(h, c1)}, {nk + nn, nb, 1}, minus_one);
    auto raw = [&](int a, int b, int j) { return hg.moment({a, b, j, 1}) - hl.moment({a + j, b, 1, 0}); };
    out.heat_source_temperature = contract3<Ring>(raw, sv_test, sk, tl);
    out.heat_source_density = contract3<Ring>(raw, sv_test, sk, sk);
  }
  {  // heat flux [q][k]: (H·G) = ½ H·(c1 + c2)
    const Q f(pair, alpha, {x1, x2, dot_form(h, g), dot_form(h, c2)}, {nk, nn, 1, 1}, minus_one);
    auto raw = [&](int a, int b) {
      Ring v = f.moment({a, b, 1, 1});
      detail::scale(v, half);
      return v;
    };
    out.heat_flux = contract2<Ring>(raw, sv, sk);
  }
  {  // heat gradients [k][l]
    const int nb = std::max(nt, nk);
    const Q f(pair, alpha, {x1, x2, dot_form(h, g)}, {nk, nb, 1}, Rational(0));
    auto raw = [&](int a, int b) {
      Ring v = f.moment({b, a, 1, 0});
      detail::scale(v, half);
      return v;
    };
    out.heat_gradient_temperature = contract2<Ring>(raw, sk, tl);
    out.heat_gradient_density = contract2<Ring>(raw, sk, sk);
  }
  const Table ss = sonine_table(sonine_twice_m(d, 0), n_max);  // scalar test functions
  {                                                            // scalar source [p][k][l]
    const Q f(pair, alpha, {x1, x2, x1p, dot_form(h, c2)}, {nk + nn_test, nd, nn_test, 1}, minus_one);
    auto raw = [&](int a, int b, int j) { return f.moment({a, b, j, 1}) - f.moment({a + j, b, 0, 1}); };
    out.scalar_source = contract3<Ring>(raw, ss_test, sk, dl);
  }
  {  // cooling rate pieces
    const Q f(pair, alpha, {x1, x2, dot_form(h, c2)}, {nk, nd, 1}, Rational(1));
    auto raw = [&](int a, int b) { return f.moment({b, a, 1, 0}); };
    out.cooling_gradient = contract2<Ring>(raw, sk, dl);
    const Q c(pair, alpha, {x1, x2}, {nk, nn}, Rational(2));
    auto raw_c = [&](int a, int b) { return c.moment({a, b, 0, 0}); };
    out.cooling_scalar = contract2<Ring>(raw_c, ss, sk);
  }
  return out;
}

template CollisionalTransferMoments<Rational> collisional_transfer_moments<Rational>(int, const Rational&, int, int,
                                                                                     int);
template CollisionalTransferMoments<RationalPolynomial> collisional_transfer_moments<RationalPolynomial>(
    int, const RationalPolynomial&, int, int, int);

}  // namespace gkt
