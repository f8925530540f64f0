#include "transport/rough/rough_weighted_elements.hpp"

#include <cmath>
#include <stdexcept>

#include "gkt/algebra/sonine.hpp"
#include "gkt/collision/rough_collision_moments.hpp"
#include "transport/rough/rough_sonine_systems.hpp"

namespace gkt::detail {

namespace {

using S = RoughSlot;
using Moments = RoughCollisionMoments<RationalPolynomial>;

/// Returns ⟨(c_a·c_b)^r X_a^i Y_a^j X_b^k Y_b^l X_c^m Y_c^n⟩/⟨1⟩ (r ≤ 2; i + j, k + l ≤ K; m + n ≤ W): the gain of a
/// trial slot a, the post-collisional test slot b and the weighted partner slot c.
Moments weighted_gain_table(const RoughCollisionParameters<RationalPolynomial>& p, S va, S wa, S vb, S wb, S vc, S wc,
                            int k, int w) {
  return {p,
          {rough_dot_form(va, vb), rough_dot_form(va, va), rough_dot_form(wa, wa), rough_dot_form(vb, vb),
           rough_dot_form(wb, wb), rough_dot_form(vc, vc), rough_dot_form(wc, wc)},
          {2, k, k, k, k, w, w},
          [k, w](const RoughExponents& e) { return e[1] + e[2] <= k && e[3] + e[4] <= k && e[5] + e[6] <= w; }};
}

}  // namespace

RoughWeightedCollisionElements::RoughWeightedCollisionElements(
    const RoughCollisionParameters<RationalPolynomial>& parameters, int highest_order, int weight_degree)
    : k_(highest_order), w_(weight_degree) {
  if (weight_degree < 2) throw std::invalid_argument("weight_degree: must be an integer >= 2");
  const int k = k_, w = w_, d = parameters.dimension, dr = rough_rotational_dimension(d);
  // Weight on partner 1 (the test particle's own slot): the loss ⟨(c2·c1)^r X2^i Y2^j X1^{k+m} Y1^{l+n}⟩ and the
  // gain with the test on 1'. Weight on partner 2: the loss ⟨X1^{r+i+k} Y1^{j+l} X2^m Y2^n⟩ (trial and test on 1)
  // and the gain with the trial on 1, the test on 1'.
  const Moments own_loss(parameters,
                         {rough_dot_form(S::v2, S::v1), rough_dot_form(S::v2, S::v2), rough_dot_form(S::w2, S::w2),
                          rough_dot_form(S::v1, S::v1), rough_dot_form(S::w1, S::w1)},
                         {2, k, k, k + w, k + w},
                         [k, w](const RoughExponents& e) { return e[1] + e[2] <= k && e[3] + e[4] <= k + w; });
  const Moments own_gain = weighted_gain_table(parameters, S::v2, S::w2, S::v1_post, S::w1_post, S::v1, S::w1, k, w);
  const Moments partner_loss(parameters,
                             {rough_dot_form(S::v1, S::v1), rough_dot_form(S::w1, S::w1), rough_dot_form(S::v2, S::v2),
                              rough_dot_form(S::w2, S::w2)},
                             {2 * k + 2, 2 * k, w, w}, [w](const RoughExponents& e) { return e[2] + e[3] <= w; });
  const Moments partner_gain =
      weighted_gain_table(parameters, S::v1, S::w1, S::v1_post, S::w1_post, S::v2, S::w2, k, w);
  const Rational inv_d(1, static_cast<unsigned long>(d));
  const auto sx = sonine_table(sonine_twice_m(d, 0), w);
  const auto sy = sonine_table(dr - 2, w);
  contracted_.resize(static_cast<std::size_t>((w + 1) * (w + 1)));
  for (int rank = 0; rank <= 2; ++rank) {
    // (c_a·c_b)^r, minus X_a X_b/d for r = 2 (theory.md (4.2)), for a table whose first five forms are the pair's.
    const auto pair = [&](const Moments& m, int i, int j, int a, int b, int mw, int nw) {
      if (rank < 2) return m.moment({rank, i, j, a, b, mw, nw});
      RationalPolynomial v = m.moment({2, i, j, a, b, mw, nw});
      RationalPolynomial x = m.moment({0, i + 1, j, a + 1, b, mw, nw});
      x *= inv_d;
      v -= x;
      return v;
    };
    const auto own = [&](int i, int j, int a, int b, int mw, int nw) {
      if (rank < 2) return own_loss.moment({rank, i, j, a + mw, b + nw});
      RationalPolynomial v = own_loss.moment({2, i, j, a + mw, b + nw});
      RationalPolynomial x = own_loss.moment({0, i + 1, j, a + 1 + mw, b + nw});
      x *= inv_d;
      v -= x;
      return v;
    };
    const int top = rank == 2 ? k - 1 : k;
    // The raw tables of every weight monomial x_c^m y_c^n (ŷ = Y/τ: times λ^{2(2K + W − j − l − n)}).
    std::vector<RoughTable4> raw;
    for (int mw = 0; mw <= w; ++mw)
      for (int nw = 0; nw <= w; ++nw) {
        raw.emplace_back(mw + nw <= w ? k : 0);
        if (mw + nw > w) continue;
        RoughTable4& t = raw.back();
        for (int i = 0; i <= top; ++i)
          for (int j = 0; i + j <= top; ++j)
            for (int a = 0; a <= top; ++a)
              for (int b = 0; a + b <= top; ++b) {
                RationalPolynomial v = partner_loss.moment({rank + i + a, j + b, mw, nw});
                v *= rough_contraction_weight(d, rank);
                v -= pair(partner_gain, i, j, a, b, mw, nw);
                v += own(i, j, a, b, mw, nw);
                v -= pair(own_gain, i, j, a, b, mw, nw);
                t(i, j, a, b) = shifted_by(v, 2L * (2 * k + w - j - b - nw));
              }
      }
    for (int pw = 0; pw <= w; ++pw)
      for (int qw = 0; pw + qw <= w; ++qw) {
        if (pw + qw < 2) continue;
        RoughTable4 t(k);
        for (int mw = 0; mw <= pw; ++mw)
          for (int nw = 0; nw <= qw; ++nw) {
            const Rational c = sx[static_cast<std::size_t>(pw)][static_cast<std::size_t>(mw)] *
                               sy[static_cast<std::size_t>(qw)][static_cast<std::size_t>(nw)];
            const RoughTable4& r = raw[static_cast<std::size_t>(mw * (w + 1) + nw)];
            for (int i = 0; i <= top; ++i)
              for (int j = 0; i + j <= top; ++j)
                for (int a = 0; a <= top; ++a)
                  for (int b = 0; a + b <= top; ++b) add_scaled(t(i, j, a, b), r(i, j, a, b), c);
          }
        auto& out = contracted_[static_cast<std::size_t>(pw * (w + 1) + qw)][static_cast<std::size_t>(rank)];
        for (const RationalPolynomial& e : contract_sonine(t, top, sonine_twice_m(d, rank), dr - 2).release()) {
          // e = λ^{4K + 2W} × element, even in λ: Σ_j e_{2j} τ^{j − 2K − W}.
          std::vector<long double> c;
          for (long j = 0; j <= e.degree(); j += 2) c.push_back(static_cast<long double>(e.coefficient(j).to_double()));
          out.push_back(std::move(c));
        }
      }
  }
}

double RoughWeightedCollisionElements::element(int rank, int p_test, int q_test, int p_trial, int q_trial, int p_weight,
                                               int q_weight, double tau) const {
  const int top = rank == 2 ? k_ - 1 : k_, n = top + 1;
  if (p_test + q_test > top || p_trial + q_trial > top || p_test < 0 || q_test < 0 || p_trial < 0 || q_trial < 0 ||
      p_weight < 0 || q_weight < 0 || p_weight + q_weight > w_ || p_weight + q_weight < 2)
    throw std::out_of_range("RoughWeightedCollisionElements: Sonine index above the table");
  const auto& c = contracted_[static_cast<std::size_t>(p_weight * (w_ + 1) + q_weight)][static_cast<std::size_t>(rank)]
                             [static_cast<std::size_t>(((p_trial * n + q_trial) * n + p_test) * n + q_test)];
  long double value = 0;
  const long double t = tau;
  for (std::size_t j = c.size(); j-- > 0;) value = value * t + c[j];
  return static_cast<double>(value * std::pow(t, -2.0L * k_ - w_));
}

}  // namespace gkt::detail
