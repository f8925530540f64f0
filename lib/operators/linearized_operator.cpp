#include "gkt/operators/linearized_operator.hpp"

#include <cmath>
#include <numbers>

#include "collision/ring.hpp"
#include "gkt/algebra/sonine.hpp"
#include "gkt/collision/collision_moments.hpp"
#include "gkt/collision/gaussian_collision_integral.hpp"

#include <optional>
#include <stdexcept>
#include <utility>

namespace gkt {

double linearized_operator_prefactor(int dimension) {
  // ν = π^{−d} J0 with θ = 1: J0 = K_d √2 (collision_moments.hpp).
  const CollisionPair unit{dimension, Rational(1), Rational(1), Rational(1), Rational(1)};
  return reference_collision_integral(unit) * std::pow(std::numbers::pi, -dimension);
}

template <class Ring>
DenseMatrix<Ring> linearized_operator_matrix(int dimension, const Ring& alpha, OperatorPart part, int rank, int n_max) {
  const CollisionPair pair{dimension, Rational(1), Rational(1), Rational(1), Rational(1)};
  // L = −[M(1→1') − M(1→1)] − [M(2→1') − M(2→1)]   (unknown → test slot)
  auto gain1 = sonine_collision_moments<Ring>(pair, alpha, Slot::v1, Slot::v1_post, rank, n_max);
  const auto loss1 = sonine_collision_moments<Ring>(pair, alpha, Slot::v1, Slot::v1, rank, n_max);
  DenseMatrix<Ring> l(n_max + 1, n_max + 1);
  for (int p = 0; p <= n_max; ++p)
    for (int q = 0; q <= n_max; ++q) l(p, q) = loss1(p, q) - gain1(p, q);
  if (part == OperatorPart::full) {
    const auto gain2 = sonine_collision_moments<Ring>(pair, alpha, Slot::v2, Slot::v1_post, rank, n_max);
    const auto loss2 = sonine_collision_moments<Ring>(pair, alpha, Slot::v2, Slot::v1, rank, n_max);
    for (int p = 0; p <= n_max; ++p)
      for (int q = 0; q <= n_max; ++q) l(p, q) += loss2(p, q) - gain2(p, q);
  }
  return l;
}

namespace {

/// M_k(p, q) = Σ_{i ≤ k} Σ_{j ≤ q} Σ_{l ≤ p} w_k[i] s_q[j] s_p[l] y(i, j, l), contracted one index at a
/// time: weight power i, unknown power j, test power l.
template <class Ring, class Integrand>
std::vector<DenseMatrix<Ring>> contract_weighted(const std::vector<std::vector<Rational>>& w,
                                                 const std::vector<std::vector<Rational>>& s, int k_max, int n_max,
                                                 Integrand&& y) {
  const int ni = k_max + 1, nn = n_max + 1;
  auto at = [nn](int i, int j, int p) { return (static_cast<std::size_t>(i) * nn + j) * nn + p; };
  // The integrand once per (i, j, l) (it is a table lookup plus, for rank 2, a trace term).
  std::vector<Ring> yt(static_cast<std::size_t>(ni) * nn * nn, Ring(0L));
  for (int i = 0; i < ni; ++i)
    for (int j = 0; j < nn; ++j)
      for (int l = 0; l < nn; ++l) yt[at(i, j, l)] = y(i, j, l);
  std::vector<Ring> g(yt.size(), Ring(0L)), h(g.size(), Ring(0L));
  Ring scratch(0L);
  for (int i = 0; i < ni; ++i)
    for (int j = 0; j < nn; ++j)
      for (int p = 0; p < nn; ++p) {
        Ring acc(0L);
        for (int l = 0; l <= p; ++l) detail::add_scaled(acc, yt[at(i, j, l)], s[p][l], scratch);
        g[at(i, j, p)] = std::move(acc);
      }
  for (int i = 0; i < ni; ++i)
    for (int q = 0; q < nn; ++q)
      for (int p = 0; p < nn; ++p) {
        Ring acc(0L);
        for (int j = 0; j <= q; ++j) detail::add_scaled(acc, g[at(i, j, p)], s[q][j], scratch);
        h[at(i, q, p)] = std::move(acc);
      }
  std::vector<DenseMatrix<Ring>> out;
  for (int k = 0; k < ni; ++k) {
    DenseMatrix<Ring> m(nn, nn);
    for (int p = 0; p < nn; ++p)
      for (int q = 0; q < nn; ++q) {
        Ring acc(0L);
        for (int i = 0; i <= k; ++i) detail::add_scaled(acc, h[at(i, q, p)], w[k][i], scratch);
        m(p, q) = std::move(acc);
      }
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace

template <class Ring>
WeightedPairOperator<Ring> weighted_pair_operator_matrices(const CollisionPair& pair, const Ring& alpha, int rank,
                                                           int n_max, int k_max, const Rational& power) {
  if (rank < 0 || rank > 2) throw std::invalid_argument("rank: must be 0, 1 or 2");
  if (n_max < 0) throw std::invalid_argument("n_max: must be >= 0");
  if (k_max < 0) throw std::invalid_argument("k_max: must be >= 0");
  const int dimension = pair.dimension;
  const auto w = sonine_table(sonine_twice_m(dimension, 0), k_max);
  const auto s = sonine_table(sonine_twice_m(dimension, rank), n_max);
  const int e = rank == 2 ? 1 : 0;  // the trace term of Y_2·Y_2 needs one more power
  const Rational inv_d(1, static_cast<unsigned long>(dimension));
  const Rational self_factor = rank == 2 ? Rational(dimension - 1, static_cast<unsigned long>(dimension)) : Rational(1);
  const std::optional<std::pair<Slot, Slot>> none;

  // Weighted gain/loss with the unknown at a ∈ {v1, v2} and the test at b ∈ {v1', v1}.
  // (a) weight at v2, unknown v1, test v1'      (b) weight v2, unknown v1, test v1
  // (c) weight at v1, unknown v2, test v1'      (d) weight v1, unknown v2, test v1 (shares the X1 slot)
  const CollisionMomentTable<Ring> ta(pair, alpha, {Slot::v2, Slot::v1, Slot::v1_post}, {k_max, n_max + e, n_max + e},
                                      std::make_pair(Slot::v1, Slot::v1_post), rank, power);
  const CollisionMomentTable<Ring> tb(pair, alpha, {Slot::v2, Slot::v1}, {k_max, 2 * n_max + rank}, none, 0, power);
  const CollisionMomentTable<Ring> tc(pair, alpha, {Slot::v1, Slot::v2, Slot::v1_post}, {k_max, n_max + e, n_max + e},
                                      std::make_pair(Slot::v2, Slot::v1_post), rank, power);
  const CollisionMomentTable<Ring> td(pair, alpha, {Slot::v1, Slot::v2}, {k_max + n_max + e, n_max + e},
                                      std::make_pair(Slot::v2, Slot::v1), rank, power);
  auto contracted = [&](const CollisionMomentTable<Ring>& t, std::vector<int> k) {  // Y_r(c_a)·Y_r(c_b) terms
    if (rank < 2) return t.moment(k, rank);
    Ring v = t.moment(k, 2);
    // ⟨… (c_a·c_b)²⟩ − ⟨… X_a X_b⟩/d: the last two entries of k are the unknown's and test's powers,
    // except for (d), where the caller passes them separately.
    k[k.size() - 1] += 1;
    k[k.size() - 2] += 1;
    Ring trace = t.moment(k, 0);
    detail::scale(trace, inv_d);
    v -= trace;
    return v;
  };
  const auto ma = contract_weighted<Ring>(w, s, k_max, n_max, [&](int i, int j, int l) {
    return contracted(ta, {i, j, l});
  });
  const auto mb = contract_weighted<Ring>(w, s, k_max, n_max, [&](int i, int j, int l) {
    Ring v = tb.moment({i, j + l + rank});
    detail::scale(v, self_factor);
    return v;
  });
  const auto mc = contract_weighted<Ring>(w, s, k_max, n_max, [&](int i, int j, int l) {
    return contracted(tc, {i, j, l});
  });
  const auto md = contract_weighted<Ring>(w, s, k_max, n_max, [&](int i, int j, int l) {
    if (rank < 2) return td.moment({i + l, j}, rank);
    Ring v = td.moment({i + l, j}, 2);
    Ring trace = td.moment({i + l + 1, j + 1}, 0);
    detail::scale(trace, inv_d);
    v -= trace;
    return v;
  });
  WeightedPairOperator<Ring> out;
  for (int k = 0; k <= k_max; ++k) {
    DenseMatrix<Ring> self(n_max + 1, n_max + 1), cross(n_max + 1, n_max + 1);
    for (int p = 0; p <= n_max; ++p)
      for (int q = 0; q <= n_max; ++q) {
        self(p, q) = ma[k](p, q) - mb[k](p, q);
        cross(p, q) = mc[k](p, q) - md[k](p, q);
      }
    out.self.push_back(std::move(self));
    out.cross.push_back(std::move(cross));
  }
  return out;
}

template <class Ring>
std::vector<DenseMatrix<Ring>> hcs_linearized_operator_matrices(int dimension, const Ring& alpha, int rank, int n_max,
                                                                int k_max, const Rational& power) {
  if (rank < 0 || rank > 2) throw std::invalid_argument("rank: must be 0, 1 or 2");
  const CollisionPair pair{dimension, Rational(1), Rational(1), Rational(1), Rational(1)};
  // One species: L^(k) = (loss − gain) with the partner weighted, plus the same with the unknown at v2.
  const auto m = weighted_pair_operator_matrices<Ring>(pair, alpha, rank, n_max, k_max, power);
  std::vector<DenseMatrix<Ring>> out;
  for (int k = 0; k <= k_max; ++k) {
    DenseMatrix<Ring> l(n_max + 1, n_max + 1);
    for (int p = 0; p <= n_max; ++p)
      for (int q = 0; q <= n_max; ++q) {
        l(p, q) = Ring(0L);
        l(p, q) -= m.self[k](p, q);
        l(p, q) -= m.cross[k](p, q);
      }
    out.push_back(std::move(l));
  }
  return out;
}

template WeightedPairOperator<Rational> weighted_pair_operator_matrices<Rational>(const CollisionPair&, const Rational&,
                                                                                  int, int, int, const Rational&);
template WeightedPairOperator<RationalPolynomial> weighted_pair_operator_matrices<RationalPolynomial>(
    const CollisionPair&, const RationalPolynomial&, int, int, int, const Rational&);
template std::vector<DenseMatrix<Rational>> hcs_linearized_operator_matrices<Rational>(int, const Rational&, int, int,
                                                                                       int, const Rational&);
template std::vector<DenseMatrix<RationalPolynomial>> hcs_linearized_operator_matrices<RationalPolynomial>(
    int, const RationalPolynomial&, int, int, int, const Rational&);

template DenseMatrix<Rational> linearized_operator_matrix<Rational>(int, const Rational&, OperatorPart, int, int);
template DenseMatrix<RationalPolynomial> linearized_operator_matrix<RationalPolynomial>(int, const RationalPolynomial&,
                                                                                        OperatorPart, int, int);

}  // namespace gkt
