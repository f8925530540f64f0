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

/// Returns the forms and degrees of a table with the weighted slot c: X_c, Y_c (total degree ≤ W) and, for the
/// orientation weight, (v_c·w_c) of degree ≤ 2 counted twice in that total.
void add_weight_forms(std::vector<RoughForm>& forms, std::vector<int>& degrees, S vc, S wc, int w, bool oriented) {
  forms.push_back(rough_dot_form(vc, vc));
  forms.push_back(rough_dot_form(wc, wc));
  degrees.push_back(w);
  degrees.push_back(w);
  if (!oriented) return;
  forms.push_back(rough_dot_form(vc, wc));
  degrees.push_back(2);
}

/// Returns ⟨(c_a·c_b)^r X_a^i Y_a^j X_b^k Y_b^l X_c^m Y_c^n (c_c·w_c)^o⟩/⟨1⟩ (r, o ≤ 2; i + j, k + l ≤ K;
/// m + n + o ≤ W): the gain of a trial slot a, the post-collisional test slot b and the weighted partner slot c.
Moments weighted_gain_table(const RoughCollisionParameters<RationalPolynomial>& p, S va, S wa, S vb, S wb, S vc, S wc,
                            int k, int w, bool oriented) {
  std::vector<RoughForm> forms{rough_dot_form(va, vb), rough_dot_form(va, va), rough_dot_form(wa, wa),
                               rough_dot_form(vb, vb), rough_dot_form(wb, wb)};
  std::vector<int> degrees{2, k, k, k, k};
  add_weight_forms(forms, degrees, vc, wc, w, oriented);
  return {p, forms, degrees,
          [k, w](const RoughExponents& e) { return e[1] + e[2] <= k && e[3] + e[4] <= k && e[5] + e[6] + e[7] <= w; }};
}

}  // namespace

RoughWeightedCollisionElements::RoughWeightedCollisionElements(
    const RoughCollisionParameters<RationalPolynomial>& parameters, int highest_order, int weight_degree, bool oriented)
    : k_(highest_order), w_(weight_degree), oriented_(oriented) {
  if (weight_degree < 2) throw std::invalid_argument("weight_degree: must be an integer >= 2");
  if (oriented && parameters.dimension != 3)
    throw std::invalid_argument("oriented: the orientation weight needs dimension = 3 (c.w vanishes for disks)");
  const int k = k_, w = w_, d = parameters.dimension, dr = rough_rotational_dimension(d);
  // Weight on partner 1 (the test particle's own slot): the loss ⟨(c2·c1)^r X2^i Y2^j X1^{k+m} Y1^{l+n} (c1·w1)^o⟩
  // and the gain with the test on 1'. Weight on partner 2: the loss ⟨X1^{r+i+k} Y1^{j+l} X2^m Y2^n (c2·w2)^o⟩ (trial
  // and test on 1) and the gain with the trial on 1, the test on 1'.
  std::vector<RoughForm> own_forms{rough_dot_form(S::v2, S::v1), rough_dot_form(S::v2, S::v2),
                                   rough_dot_form(S::w2, S::w2), rough_dot_form(S::v1, S::v1),
                                   rough_dot_form(S::w1, S::w1)};
  std::vector<int> own_degrees{2, k, k, k + w, k + w};
  if (oriented) own_forms.push_back(rough_dot_form(S::v1, S::w1)), own_degrees.push_back(2);
  const Moments own_loss(parameters, own_forms, own_degrees,
                         [k, w](const RoughExponents& e) { return e[1] + e[2] <= k && e[3] + e[4] + e[5] <= k + w; });
  const Moments own_gain =
      weighted_gain_table(parameters, S::v2, S::w2, S::v1_post, S::w1_post, S::v1, S::w1, k, w, oriented);
  std::vector<RoughForm> partner_forms{rough_dot_form(S::v1, S::v1), rough_dot_form(S::w1, S::w1)};
  std::vector<int> partner_degrees{2 * k + 2, 2 * k};
  add_weight_forms(partner_forms, partner_degrees, S::v2, S::w2, w, oriented);
  const Moments partner_loss(parameters, partner_forms, partner_degrees,
                             [w](const RoughExponents& e) { return e[2] + e[3] + e[4] <= w; });
  const Moments partner_gain =
      weighted_gain_table(parameters, S::v1, S::w1, S::v1_post, S::w1_post, S::v2, S::w2, k, w, oriented);
  const Rational inv_d(1, static_cast<unsigned long>(d));
  const auto sx = sonine_table(sonine_twice_m(d, 0), w);
  const auto sy = sonine_table(dr - 2, w);
  const auto s5 = sonine_table(5, w);  // S^(5/2) of the orientation family (theory.md (19.26a))
  contracted_.resize(static_cast<std::size_t>((w + 1) * (w + 1)));
  if (oriented) oriented_contracted_.resize(contracted_.size());
  for (int rank = 0; rank <= 2; ++rank) {
    // (c_a·c_b)^r, minus X_a X_b/d for r = 2 (theory.md (4.2)), for a gain table; o = exponent of (c_c·w_c).
    const auto pair = [&](const Moments& m, int i, int j, int a, int b, int mw, int nw, int o) {
      if (rank < 2) return m.moment({rank, i, j, a, b, mw, nw, o});
      RationalPolynomial v = m.moment({2, i, j, a, b, mw, nw, o});
      RationalPolynomial x = m.moment({0, i + 1, j, a + 1, b, mw, nw, o});
      x *= inv_d;
      v -= x;
      return v;
    };
    const auto own = [&](int i, int j, int a, int b, int mw, int nw, int o) {
      if (rank < 2) return own_loss.moment({rank, i, j, a + mw, b + nw, o});
      RationalPolynomial v = own_loss.moment({2, i, j, a + mw, b + nw, o});
      RationalPolynomial x = own_loss.moment({0, i + 1, j, a + 1 + mw, b + nw, o});
      x *= inv_d;
      v -= x;
      return v;
    };
    // −⟨[x_c^m y_c^n (c_c·w_c)^o ψ(other)] Δψ'(1)⟩ summed over both weighted slots, in λ-scaled form.
    const auto weighted = [&](int i, int j, int a, int b, int mw, int nw, int o) {
      RationalPolynomial v = partner_loss.moment({rank + i + a, j + b, mw, nw, o});
      v *= rough_contraction_weight(d, rank);
      v -= pair(partner_gain, i, j, a, b, mw, nw, o);
      v += own(i, j, a, b, mw, nw, o);
      v -= pair(own_gain, i, j, a, b, mw, nw, o);
      return v;
    };
    const int top = rank == 2 ? k - 1 : k;
    // The raw tables of every weight monomial x_c^m y_c^n (ŷ = Y/τ: times λ^{2(2K + W − j − l − n)}) and, oriented,
    // of P x_c^m y_c^n = [(c_c·w_c)² X^m Y^n − X^{m+1} Y^{n+1}/3]/τ^{1+n} (m + n ≤ W − 2).
    std::vector<RoughTable4> raw, raw_oriented;
    for (int mw = 0; mw <= w; ++mw)
      for (int nw = 0; nw <= w; ++nw) {
        raw.emplace_back(mw + nw <= w ? k : 0);
        raw_oriented.emplace_back(oriented && mw + nw + 2 <= w ? k : 0);
        if (mw + nw > w) continue;
        const Rational third(1, 3);
        for (int i = 0; i <= top; ++i)
          for (int j = 0; i + j <= top; ++j)
            for (int a = 0; a <= top; ++a)
              for (int b = 0; a + b <= top; ++b) {
                raw.back()(i, j, a, b) = shifted_by(weighted(i, j, a, b, mw, nw, 0), 2L * (2 * k + w - j - b - nw));
                if (!oriented || mw + nw + 2 > w) continue;
                RationalPolynomial v = weighted(i, j, a, b, mw, nw, 2);
                RationalPolynomial xy = weighted(i, j, a, b, mw + 1, nw + 1, 0);
                xy *= third;
                v -= xy;
                raw_oriented.back()(i, j, a, b) = shifted_by(v, 2L * (2 * k + w - j - b - nw - 1));
              }
      }
    // Combines the monomials into one weight polynomial, contracts with the Sonine coefficients, rounds.
    const auto store = [&](const std::vector<RoughTable4>& tables, const std::vector<std::vector<Rational>>& tx,
                           const std::vector<std::vector<Rational>>& ty, int pw, int qw,
                           std::vector<std::vector<long double>>& out) {
      RoughTable4 t(k);
      for (int mw = 0; mw <= pw; ++mw)
        for (int nw = 0; nw <= qw; ++nw) {
          const Rational c = tx[static_cast<std::size_t>(pw)][static_cast<std::size_t>(mw)] *
                             ty[static_cast<std::size_t>(qw)][static_cast<std::size_t>(nw)];
          const RoughTable4& r = tables[static_cast<std::size_t>(mw * (w + 1) + nw)];
          for (int i = 0; i <= top; ++i)
            for (int j = 0; i + j <= top; ++j)
              for (int a = 0; a <= top; ++a)
                for (int b = 0; a + b <= top; ++b) add_scaled(t(i, j, a, b), r(i, j, a, b), c);
        }
      for (const RationalPolynomial& e : contract_sonine(t, top, sonine_twice_m(d, rank), dr - 2).release()) {
        // e = λ^{4K + 2W} × element, even in λ: Σ_j e_{2j} τ^{j − 2K − W}.
        std::vector<long double> c;
        for (long j = 0; j <= e.degree(); j += 2) c.push_back(static_cast<long double>(e.coefficient(j).to_double()));
        out.push_back(std::move(c));
      }
    };
    for (int pw = 0; pw <= w; ++pw)
      for (int qw = 0; pw + qw <= w; ++qw) {
        const auto index = static_cast<std::size_t>(pw * (w + 1) + qw);
        if (pw + qw >= 2) store(raw, sx, sy, pw, qw, contracted_[index][static_cast<std::size_t>(rank)]);
        if (oriented && pw + qw + 2 <= w)
          store(raw_oriented, s5, s5, pw, qw, oriented_contracted_[index][static_cast<std::size_t>(rank)]);
      }
  }
}

double RoughWeightedCollisionElements::evaluate(const std::vector<std::vector<long double>>& c, int rank, int p_test,
                                                int q_test, int p_trial, int q_trial, double tau) const {
  const int top = rank == 2 ? k_ - 1 : k_, n = top + 1;
  if (p_test + q_test > top || p_trial + q_trial > top || p_test < 0 || q_test < 0 || p_trial < 0 || q_trial < 0)
    throw std::out_of_range("RoughWeightedCollisionElements: Sonine index above the table");
  const auto& e = c[static_cast<std::size_t>(((p_trial * n + q_trial) * n + p_test) * n + q_test)];
  long double value = 0;
  const long double t = tau;
  for (std::size_t j = e.size(); j-- > 0;) value = value * t + e[j];
  return static_cast<double>(value * std::pow(t, -2.0L * k_ - w_));
}

double RoughWeightedCollisionElements::element(int rank, int p_test, int q_test, int p_trial, int q_trial, int p_weight,
                                               int q_weight, double tau) const {
  if (p_weight < 0 || q_weight < 0 || p_weight + q_weight > w_ || p_weight + q_weight < 2)
    throw std::out_of_range("RoughWeightedCollisionElements: cumulant index above the table");
  return evaluate(contracted_[static_cast<std::size_t>(p_weight * (w_ + 1) + q_weight)][static_cast<std::size_t>(rank)],
                  rank, p_test, q_test, p_trial, q_trial, tau);
}

double RoughWeightedCollisionElements::orientation_element(int rank, int p_test, int q_test, int p_trial, int q_trial,
                                                           int p_weight, int q_weight, double tau) const {
  if (!oriented_ || p_weight < 0 || q_weight < 0 || p_weight + q_weight + 2 > w_)
    throw std::out_of_range("RoughWeightedCollisionElements: orientation index above the table");
  return evaluate(
      oriented_contracted_[static_cast<std::size_t>(p_weight * (w_ + 1) + q_weight)][static_cast<std::size_t>(rank)],
      rank, p_test, q_test, p_trial, q_trial, tau);
}

}  // namespace gkt::detail
