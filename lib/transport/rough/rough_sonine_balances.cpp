#include "transport/rough/rough_sonine_balances.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "gkt/algebra/rational_polynomial.hpp"
#include "gkt/collision/rough_collision_moments.hpp"

namespace gkt::detail {

double TauLaurent::operator()(double tau) const {
  double v = 0;
  for (std::size_t j = c.size(); j-- > 0;) v = v * tau + c[j];
  return v * std::pow(tau, -shift);
}

namespace {

/// Coefficients of x^i, i = 0 … p, in S_p^(m)(x) with 2(m + 1) = twice_m1 (docs/theory.md (1.1)):
/// (−1)^i (m+1)_p / ((m+1)_i i! (p−i)!).
std::vector<Rational> sonine_coefficients(long twice_m1, int p) {
  std::vector<Rational> c;
  const Rational top = Rational::rising_half(twice_m1, static_cast<unsigned long>(p));
  for (int i = 0; i <= p; ++i) {
    Rational x = top / Rational::rising_half(twice_m1, static_cast<unsigned long>(i)) /
                 Rational::factorial(static_cast<unsigned long>(i)) /
                 Rational::factorial(static_cast<unsigned long>(p - i));
    c.push_back(i % 2 == 0 ? x : -x);
  }
  return c;
}

/// Appends Σ_j p_{2j} τ^{j − spin_power} · s to l (a moment of w = λŵ with λ² = τ, over τ^{spin power}).
void add_scaled(TauLaurent& l, const RationalPolynomial& p, int spin_power, const Rational& s) {
  if (p.is_zero()) return;
  if (l.exact.empty()) l.shift = spin_power;
  if (spin_power > l.shift) {
    l.exact.insert(l.exact.begin(), static_cast<std::size_t>(spin_power - l.shift), Rational(0));
    l.shift = spin_power;
  }
  const auto offset = static_cast<std::size_t>(l.shift - spin_power);
  for (long j = 0; j <= p.degree(); j += 2) {
    const auto at = offset + static_cast<std::size_t>(j / 2);
    if (l.exact.size() <= at) l.exact.resize(at + 1, Rational(0));
    l.exact[at] += s * p.coefficient(j);
  }
}

}  // namespace

RoughSonineBalances::RoughSonineBalances(int dimension, const Rational& alpha, const Rational& beta,
                                         const Rational& kappa, int highest_degree, bool products)
    : dimension_(dimension), highest_(highest_degree), products_(products), decoupled_(beta == Rational(-1)) {
  const auto params = rough_parameters_symbolic_temperature(dimension, alpha, beta, kappa);  // validates
  if (highest_degree < 2) throw std::invalid_argument("RoughSonineBalances: highest Sonine degree must be >= 2");
  const int m = highest_degree;
  const int spin_top = decoupled_ ? 0 : m;
  for (int n = 2; n <= m; ++n)
    for (int q = 0; q <= std::min(n, spin_top); ++q) cumulants_.push_back({n - q, q});
  tests_.push_back({1, 0});
  tests_.push_back({0, 1});
  for (const auto& c : cumulants_) tests_.push_back(c);
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= std::min(m - i, spin_top); ++j) monomials_.push_back({i, j});
  auto monomial_index = [&](int i, int j) {
    for (std::size_t k = 0; k < monomials_.size(); ++k)
      if (monomials_[k][0] == i && monomials_[k][1] == j) return k;
    throw std::logic_error("RoughSonineBalances: monomial outside the table");
  };

  // Sonine products S_p(x) S_q(y) as monomials, and the Maxwellian averages ⟨x^k y^l⟩_M, ⟨x^k y^l Φ⟩_M.
  const long dt = dimension, dr = dimension == 3 ? 3 : 1;  // 2(m_t + 1), 2(m_r + 1)
  auto moment_m = [&](int k, int l) {
    return Rational::rising_half(dt, static_cast<unsigned long>(k)) *
           Rational::rising_half(dr, static_cast<unsigned long>(l));
  };
  weight_terms_.resize(cumulants_.size() + 1);
  weight_terms_[0].push_back({0, 1.0});
  std::vector<std::vector<std::pair<std::array<int, 2>, Rational>>> exact_weights(cumulants_.size());
  for (std::size_t w = 0; w < cumulants_.size(); ++w) {
    const auto sx = sonine_coefficients(dt, cumulants_[w][0]), sy = sonine_coefficients(dr, cumulants_[w][1]);
    for (int i = 0; i <= cumulants_[w][0]; ++i)
      for (int j = 0; j <= cumulants_[w][1]; ++j) {
        const Rational c = sx[static_cast<std::size_t>(i)] * sy[static_cast<std::size_t>(j)];
        exact_weights[w].push_back({{i, j}, c});
        weight_terms_[w + 1].push_back({monomial_index(i, j), c.to_double()});
      }
  }
  for (const auto& t : tests_) {
    maxwellian_.push_back(moment_m(t[0], t[1]).to_double());
    std::vector<double> row;
    for (const auto& terms : exact_weights) {
      Rational s;
      for (const auto& [e, c] : terms) s += c * moment_m(t[0] + e[0], t[1] + e[1]);
      row.push_back(s.to_double());
    }
    projection_.push_back(std::move(row));
  }

  // The engine tables: gain ⟨x1^i y1^j x2^k y2^l x1'^m y1'^n⟩ and loss ⟨x1^i y1^j x2^k y2^l⟩.
  const RoughForm x1 = rough_dot_form(RoughSlot::v1, RoughSlot::v1), y1 = rough_dot_form(RoughSlot::w1, RoughSlot::w1);
  const RoughForm x2 = rough_dot_form(RoughSlot::v2, RoughSlot::v2), y2 = rough_dot_form(RoughSlot::w2, RoughSlot::w2);
  const RoughForm x1p = rough_dot_form(RoughSlot::v1_post, RoughSlot::v1_post),
                  y1p = rough_dot_form(RoughSlot::w1_post, RoughSlot::w1_post);
  // Only the moments the balances use (down-closed sets: total degrees per particle capped, and without
  // the products one of the partners unweighted) — a fifth of the boxes at M = 4.
  const bool both = products;
  const RoughCollisionMoments<RationalPolynomial> gain(
      params, {x1, y1, x2, y2, x1p, y1p}, {m, spin_top, m, spin_top, m, spin_top}, [m, both](const RoughExponents& e) {
        const int w1 = e[0] + e[1], w2 = e[2] + e[3];
        return w1 <= m && w2 <= m && e[4] + e[5] <= m && (both || w1 == 0 || w2 == 0);
      });
  const RoughCollisionMoments<RationalPolynomial> loss(params, {x1, y1, x2, y2}, {2 * m, 2 * spin_top, m, spin_top},
                                                       [m, both](const RoughExponents& e) {
                                                         const int w1 = e[0] + e[1], w2 = e[2] + e[3];
                                                         return w1 <= 2 * m && w2 <= m && (both || w2 == 0 || w1 <= m);
                                                       });
  const std::size_t nm = monomials_.size(), nt = tests_.size();
  d_.assign(nm * nm * nt, TauLaurent{});
  for (std::size_t a = 0; a < nm; ++a)
    for (std::size_t b = 0; b < nm; ++b) {
      if (!products && a != 0 && b != 0) continue;
      const auto [i, j] = monomials_[a];
      const auto [k, l] = monomials_[b];
      for (std::size_t t = 0; t < nt; ++t) {
        const auto [mx, my] = tests_[t];
        if (decoupled_ && my > 0) continue;  // the spin tests are not balanced at β = −1
        auto& out = d_[(a * nm + b) * nt + t];
        const int spin = j + l + my;
        add_scaled(out, gain.moment({i, j, k, l, mx, my}), spin, Rational(1));
        add_scaled(out, loss.moment({i + mx, j + my, k, l}), spin, Rational(-1));
        for (const auto& x : out.exact) out.c.push_back(x.to_double());
      }
    }
}

RoughSonineBalances::Productions RoughSonineBalances::productions(double tau, bool linear) const {
  const std::size_t nm = monomials_.size(), nt = tests_.size(), nw = weight_terms_.size();
  std::vector<double> d(nm * nm * nt, 0.0);
  for (std::size_t a = 0; a < nm; ++a)
    for (std::size_t b = 0; b < nm; ++b) {
      if (linear && a != 0 && b != 0) continue;
      for (std::size_t t = 0; t < nt; ++t) {
        const auto& l = d_[(a * nm + b) * nt + t];
        if (!l.c.empty()) d[(a * nm + b) * nt + t] = l(tau);
      }
    }
  Productions r;
  r.weights = nw;
  r.tests = nt;
  r.r.assign(nw * nw * nt, 0.0);
  for (std::size_t w1 = 0; w1 < nw; ++w1)
    for (std::size_t w2 = 0; w2 < nw; ++w2) {
      if (linear && w1 != 0 && w2 != 0) continue;
      for (const auto& [a, ca] : weight_terms_[w1])
        for (const auto& [b, cb] : weight_terms_[w2])
          for (std::size_t t = 0; t < nt; ++t) r.r[(w1 * nw + w2) * nt + t] += ca * cb * d[(a * nm + b) * nt + t];
    }
  return r;
}

std::vector<double> RoughSonineBalances::evaluate(const Productions& r, std::span<const double> a, bool linear) const {
  const std::size_t k = cumulants_.size(), nt = tests_.size();
  if (a.size() != k) throw std::invalid_argument("RoughSonineBalances: wrong number of cumulants");
  if (!linear && !products_) throw std::logic_error("RoughSonineBalances: built without the product averages");
  // R[t](a) in full, and its parts of degree 0 and 1 in a.
  std::vector<double> r0(nt), r1(nt, 0.0), rr(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    r0[t] = r(0, 0, t);
    for (std::size_t p = 0; p < k; ++p) r1[t] += a[p] * (r(p + 1, 0, t) + r(0, p + 1, t));
    rr[t] = r0[t] + r1[t];
    if (!linear)
      for (std::size_t p = 0; p < k; ++p)
        for (std::size_t q = 0; q < k; ++q) rr[t] += a[p] * a[q] * r(p + 1, q + 1, t);
  }
  const double d = dimension_, dr = dimension_ == 3 ? 3 : 1;
  const double z0 = -2 / d * r0[0], z = -2 / d * rr[0], dz = -2 / d * r1[0];
  std::vector<double> f;
  if (!decoupled_) f.push_back(rr[0] / d - rr[1] / dr);
  for (std::size_t t = 2; t < nt; ++t) {
    double delta = 0;  // ⟨ψ⟩ − ⟨ψ⟩_M
    for (std::size_t p = 0; p < k; ++p) delta += a[p] * projection_[t][p];
    const double degree = tests_[t][0] + tests_[t][1];
    const double scaling =
        linear ? z0 * maxwellian_[t] + z0 * delta + dz * maxwellian_[t] : z * (maxwellian_[t] + delta);
    f.push_back(degree * scaling + rr[t]);
  }
  return f;
}

std::vector<double> RoughSonineBalances::residual(double tau, std::span<const double> a, bool linear) const {
  return evaluate(productions(tau, linear), a, linear);
}

double RoughSonineBalances::translational_rate(double tau, std::span<const double> a, bool linear) const {
  const Productions r = productions(tau, linear);
  double rx = r(0, 0, 0);
  for (std::size_t p = 0; p < cumulants_.size(); ++p) {
    rx += a[p] * (r(p + 1, 0, 0) + r(0, p + 1, 0));
    if (!linear)
      for (std::size_t q = 0; q < cumulants_.size(); ++q) rx += a[p] * a[q] * r(p + 1, q + 1, 0);
  }
  return -2.0 / dimension_ * rx;
}

}  // namespace gkt::detail
