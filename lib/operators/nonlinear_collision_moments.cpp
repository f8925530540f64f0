#include "gkt/operators/nonlinear_collision_moments.hpp"

#include <stdexcept>

#include "collision/ring.hpp"
#include "gkt/algebra/sonine.hpp"
#include "gkt/collision/collision_moments.hpp"

namespace gkt {

template <class Ring>
BilinearCollisionMoments<Ring> bilinear_collision_moments(int dimension, const Ring& alpha, int k_max) {
  if (k_max < 1) throw std::invalid_argument("k_max: must be >= 1");
  const CollisionPair pair{dimension, Rational(1), Rational(1), Rational(1), Rational(1)};
  const auto moments = scalar_collision_moments<Ring>(pair, alpha, k_max);  // E(a, b, c)
  const int n = k_max + 1;
  const auto s = sonine_table(sonine_twice_m(dimension, 0), k_max);  // s[p][j]: coefficient of x^j in S_p
  auto idx = [n](int a, int b, int c) { return (static_cast<std::size_t>(a) * n + b) * n + c; };

  // Contract one index at a time (O(K⁴) instead of O(K⁶)).
  // g(a, b, p) = Σ_c s_pc [E(a, b, c) − E(a + c, b, 0)]
  std::vector<Ring> g(static_cast<std::size_t>(n) * n * n, Ring(0L));
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      for (int p = 0; p < n; ++p) {
        Ring acc(0L);
        for (int c = 0; c <= p; ++c) {
          Ring diff = moments(a, b, c) - moments(a + c, b, 0);
          detail::scale(diff, s[p][c]);
          acc += diff;
        }
        g[idx(a, b, p)] = std::move(acc);
      }
  // h(k, b, p) = Σ_a s_ka g(a, b, p)
  std::vector<Ring> h(g.size(), Ring(0L));
  for (int k = 0; k < n; ++k)
    for (int b = 0; b < n; ++b)
      for (int p = 0; p < n; ++p) {
        Ring acc(0L);
        for (int a = 0; a <= k; ++a) {
          Ring v = g[idx(a, b, p)];
          detail::scale(v, s[k][a]);
          acc += v;
        }
        h[idx(k, b, p)] = std::move(acc);
      }
  BilinearCollisionMoments<Ring> out;
  out.dimension = dimension;
  out.k_max = k_max;
  out.sonine.assign(g.size(), Ring(0L));
  for (int p = 0; p < n; ++p)
    for (int k = 0; k < n; ++k)
      for (int l = 0; l < n; ++l) {
        Ring acc(0L);
        for (int b = 0; b <= l; ++b) {
          Ring v = h[idx(k, b, p)];
          detail::scale(v, s[l][b]);
          acc += v;
        }
        out.sonine[idx(p, k, l)] = std::move(acc);
      }
  // E(k, l) = Σ_a Σ_b s_ka s_lb [E(a, b, 1) − E(a + 1, b, 0)]
  out.energy.assign(static_cast<std::size_t>(n) * n, Ring(0L));
  for (int k = 0; k < n; ++k)
    for (int l = 0; l < n; ++l) {
      Ring acc(0L);
      for (int a = 0; a <= k; ++a)
        for (int b = 0; b <= l; ++b) {
          Ring v = moments(a, b, 1) - moments(a + 1, b, 0);
          detail::scale(v, s[k][a] * s[l][b]);
          acc += v;
        }
      out.energy[static_cast<std::size_t>(k) * n + l] = std::move(acc);
    }
  out.frequency.assign(static_cast<std::size_t>(n) * n, Ring(0L));
  for (int k = 0; k < n; ++k)
    for (int l = 0; l < n; ++l) {
      Ring acc(0L);
      for (int a = 0; a <= k; ++a)
        for (int b = 0; b <= l; ++b) {
          Ring v = moments(a, b, 0);
          detail::scale(v, s[k][a] * s[l][b]);
          acc += v;
        }
      out.frequency[static_cast<std::size_t>(k) * n + l] = std::move(acc);
    }
  return out;
}

template BilinearCollisionMoments<Rational> bilinear_collision_moments<Rational>(int, const Rational&, int);
template BilinearCollisionMoments<RationalPolynomial> bilinear_collision_moments<RationalPolynomial>(
    int, const RationalPolynomial&, int);

}  // namespace gkt
