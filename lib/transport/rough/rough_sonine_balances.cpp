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

using Table = RoughCollisionMoments<RationalPolynomial>;
using Parameters = RoughCollisionParameters<RationalPolynomial>;

/// Returns the form c_a·c_a, ŵ_a·ŵ_a or c_a·ŵ_a of one particle (slots v, w), as W_a·W_b.
RoughForm dot(RoughSlot a, RoughSlot b) { return rough_dot_form(a, b); }

/// Returns the exponent sum of forms [first, first + 3) (x, y, f of one particle): its degree, f² counting 2.
int particle_degree(const RoughExponents& e, std::size_t first) { return e[first] + e[first + 1] + e[first + 2]; }

/// The oriented gain with the weight on one partner (v, w = v1, w1 or v2, w2; linear scheme, theory.md §19.14):
/// ⟨x^i y^j f^k x1'^l y1'^n f1'^o⟩/⟨1⟩ (x = v·v, y = w·w, f = v·w), each particle's degree ≤ m, f to power 2.
Table oriented_partner_gain(const Parameters& p, int m, RoughSlot v, RoughSlot w) {
  using S = RoughSlot;
  return {p,
          {dot(v, v), dot(w, w), dot(v, w), dot(S::v1_post, S::v1_post), dot(S::w1_post, S::w1_post),
           dot(S::v1_post, S::w1_post)},
          {m, m, 2, m, m, 2},
          [m](const RoughExponents& e) { return particle_degree(e, 0) <= m && particle_degree(e, 3) <= m; }};
}

/// The oriented gain with both weights (nonlinear scheme, theory.md §19.14): ⟨x1^i y1^j f1^k x2^.. y2^.. f2^..
/// x1'^.. y1'^.. f1'^..⟩/⟨1⟩, nine forms (the engine's most), each particle's degree ≤ m, every f to power 2.
Table oriented_product_gain(const Parameters& p, int m) {
  using S = RoughSlot;
  return {p,
          {dot(S::v1, S::v1), dot(S::w1, S::w1), dot(S::v1, S::w1), dot(S::v2, S::v2), dot(S::w2, S::w2),
           dot(S::v2, S::w2), dot(S::v1_post, S::v1_post), dot(S::w1_post, S::w1_post), dot(S::v1_post, S::w1_post)},
          {m, m, 2, m, m, 2, m, m, 2},
          [m](const RoughExponents& e) {
            return particle_degree(e, 0) <= m && particle_degree(e, 3) <= m && particle_degree(e, 6) <= m;
          }};
}

/// The oriented loss ⟨x1^i y1^j f1^k x2^.. y2^.. f2^..⟩/⟨1⟩: partner 1 carries weight and test (degree ≤ 2m, f to
/// power 4), partner 2 the weight (≤ m); without `products` one of the two weights is 1 (partner 2 at degree 0, or
/// partner 1 at most m).
Table oriented_loss(const Parameters& p, int m, bool products) {
  using S = RoughSlot;
  return {p,
          {dot(S::v1, S::v1), dot(S::w1, S::w1), dot(S::v1, S::w1), dot(S::v2, S::v2), dot(S::w2, S::w2),
           dot(S::v2, S::w2)},
          {2 * m, 2 * m, 4, m, m, 2},
          [m, products](const RoughExponents& e) {
            const int w1 = particle_degree(e, 0), w2 = particle_degree(e, 3);
            return w1 <= 2 * m && w2 <= m && (products || w2 == 0 || w1 <= m);
          }};
}

}  // namespace

RoughSonineBalances::RoughSonineBalances(int dimension, const Rational& alpha, const Rational& beta,
                                         const Rational& kappa, int highest_degree, bool products, bool orientation)
    : dimension_(dimension), highest_(highest_degree), products_(products), decoupled_(beta == Rational(-1)) {
  const auto params = rough_parameters_symbolic_temperature(dimension, alpha, beta, kappa);  // validates
  if (highest_degree < 2) throw std::invalid_argument("RoughSonineBalances: highest Sonine degree must be >= 2");
  // Disks: ŵ is normal to the plane of c, c·ŵ ≡ 0 and P ≡ −xy/3 adds nothing; at β = −1 no spin balance.
  const bool oriented = orientation && dimension == 3 && !decoupled_;
  build_structure(oriented);
  const int m = highest_degree;
  const int spin_top = decoupled_ ? 0 : m;
  const std::size_t nm = monomials_.size(), nt = tests_.size();
  d_.assign(nm * nm * nt, TauLaurent{});
  // D(a, b; t) = Σ_terms c [gain − loss], as a function of the table lookups.
  auto fill = [&](const auto& gain_of, const auto& loss_of) {
    for (std::size_t a = 0; a < nm; ++a)
      for (std::size_t b = 0; b < nm; ++b) {
        if (!products && a != 0 && b != 0) continue;
        for (std::size_t t = 0; t < nt; ++t) {
          const Test& test = tests_[t];
          if (decoupled_ && test.terms.front().first[1] > 0) continue;  // no spin balance at β = −1
          auto& out = d_[(a * nm + b) * nt + t];
          for (const auto& [e, c] : test.terms) {
            const int spin = monomials_[a][1] + monomials_[a][2] + monomials_[b][1] + monomials_[b][2] + e[1] + e[2];
            add_scaled(out, gain_of(monomials_[a], monomials_[b], e), spin, c);
            add_scaled(out, loss_of(monomials_[a], monomials_[b], e), spin, -c);
          }
          for (const auto& x : out.exact) out.c.push_back(x.to_double());
        }
      }
  };

  const RoughForm x1 = rough_dot_form(RoughSlot::v1, RoughSlot::v1), y1 = rough_dot_form(RoughSlot::w1, RoughSlot::w1);
  const RoughForm x2 = rough_dot_form(RoughSlot::v2, RoughSlot::v2), y2 = rough_dot_form(RoughSlot::w2, RoughSlot::w2);
  const RoughForm x1p = rough_dot_form(RoughSlot::v1_post, RoughSlot::v1_post),
                  y1p = rough_dot_form(RoughSlot::w1_post, RoughSlot::w1_post);
  using E3 = std::array<int, 3>;
  if (!oriented) {
    // The engine tables: gain ⟨x1^i y1^j x2^k y2^l x1'^m y1'^n⟩ and loss ⟨x1^i y1^j x2^k y2^l⟩. Only the
    // moments the balances use (down-closed sets: total degrees per particle capped, and without the
    // products one of the partners unweighted) — a fifth of the boxes at M = 4.
    const bool both = products;
    const RoughCollisionMoments<RationalPolynomial> gain(
        params, {x1, y1, x2, y2, x1p, y1p}, {m, spin_top, m, spin_top, m, spin_top},
        [m, both](const RoughExponents& e) {
          const int w1 = e[0] + e[1], w2 = e[2] + e[3];
          return w1 <= m && w2 <= m && e[4] + e[5] <= m && (both || w1 == 0 || w2 == 0);
        });
    const RoughCollisionMoments<RationalPolynomial> loss(
        params, {x1, y1, x2, y2}, {2 * m, 2 * spin_top, m, spin_top}, [m, both](const RoughExponents& e) {
          const int w1 = e[0] + e[1], w2 = e[2] + e[3];
          return w1 <= 2 * m && w2 <= m && (both || w2 == 0 || w1 <= m);
        });
    fill(
        [&](const E3& u, const E3& v, const E3& t) {
          return gain.moment({u[0], u[1], v[0], v[1], t[0], t[1]});
        },
        [&](const E3& u, const E3& v, const E3& t) {
          return loss.moment({u[0] + t[0], u[1] + t[1], v[0], v[1]});
        });
    return;
  }
  // Oriented: f = c·w enters as f² per P, so its exponent is 2e; a monomial's degree counts f² as 2. Linear
  // scheme: the gain with the weight on partner 1 or on partner 2 (six forms each); nonlinear: one gain table
  // with both weights (nine forms). One loss table.
  if (products) {
    const auto gain = oriented_product_gain(params, m);
    const auto loss = oriented_loss(params, m, true);
    fill(
        [&](const E3& u, const E3& v, const E3& t) {
          return gain.moment({u[0], u[1], 2 * u[2], v[0], v[1], 2 * v[2], t[0], t[1], 2 * t[2]});
        },
        [&](const E3& u, const E3& v, const E3& t) {
          return loss.moment({u[0] + t[0], u[1] + t[1], 2 * (u[2] + t[2]), v[0], v[1], 2 * v[2]});
        });
    return;
  }
  const auto gain1 = oriented_partner_gain(params, m, RoughSlot::v1, RoughSlot::w1);
  const auto gain2 = oriented_partner_gain(params, m, RoughSlot::v2, RoughSlot::w2);
  const auto loss = oriented_loss(params, m, false);
  fill(
      [&](const E3& u, const E3& v, const E3& t) {
        if (v[0] + v[1] + v[2] == 0) return gain1.moment({u[0], u[1], 2 * u[2], t[0], t[1], 2 * t[2]});
        return gain2.moment({v[0], v[1], 2 * v[2], t[0], t[1], 2 * t[2]});
      },
      [&](const E3& u, const E3& v, const E3& t) {
        return loss.moment({u[0] + t[0], u[1] + t[1], 2 * (u[2] + t[2]), v[0], v[1], 2 * v[2]});
      });
}

RoughSonineBalances::RoughSonineBalances(int dimension, int highest_degree, bool spin_decoupled, bool orientation)
    : dimension_(dimension), highest_(highest_degree), products_(false), decoupled_(spin_decoupled) {
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument("dimension: must be 2 or 3, got " + std::to_string(dimension));
  if (highest_degree < 2) throw std::invalid_argument("RoughSonineBalances: highest Sonine degree must be >= 2");
  build_structure(orientation && dimension == 3 && !spin_decoupled);
}

void RoughSonineBalances::build_structure(bool oriented) {
  const int dimension = dimension_, m = highest_;
  const int spin_top = decoupled_ ? 0 : m;
  for (int n = 2; n <= m; ++n)
    for (int q = 0; q <= std::min(n, spin_top); ++q) cumulants_.push_back({n - q, q});
  if (oriented)
    for (int n = 0; n <= m - 2; ++n)
      for (int q = 0; q <= n; ++q) orientations_.push_back({n - q, q});
  tests_.push_back({1, {{{1, 0, 0}, Rational(1)}}});
  tests_.push_back({1, {{{0, 1, 0}, Rational(1)}}});
  for (const auto& c : cumulants_) tests_.push_back({c[0] + c[1], {{{c[0], c[1], 0}, Rational(1)}}});
  // P x^k y^l = x^k y^l (c·ŵ)² − x^{k+1} y^{l+1}/3.
  for (const auto& c : orientations_)
    tests_.push_back({c[0] + c[1] + 2, {{{c[0], c[1], 1}, Rational(1)}, {{c[0] + 1, c[1] + 1, 0}, Rational(-1, 3)}}});
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= std::min(m - i, spin_top); ++j) monomials_.push_back({i, j, 0});
  if (oriented)
    for (int i = 0; i <= m - 2; ++i)
      for (int j = 0; i + j <= m - 2; ++j) monomials_.push_back({i, j, 1});
  auto monomial_index = [&](const std::array<int, 3>& e) {
    for (std::size_t k = 0; k < monomials_.size(); ++k)
      if (monomials_[k] == e) return k;
    throw std::logic_error("RoughSonineBalances: monomial outside the table");
  };

  // Sonine products as monomials, and the Maxwellian averages ⟨ψ_t⟩_M, ⟨ψ_t Φ⟩_M: with f = c·ŵ,
  // ⟨x^i y^j f^{2e}⟩_M = ⟨x^{i+e}⟩⟨y^{j+e}⟩⟨cos^{2e}Θ⟩, ⟨cos²Θ⟩ = 1/3, ⟨cos⁴Θ⟩ = 1/5 (d = 3).
  const long dt = dimension, dr = dimension == 3 ? 3 : 1;  // 2(m_t + 1), 2(m_r + 1)
  auto moment_m = [&](const std::array<int, 3>& e) {
    const Rational angular = e[2] == 0 ? Rational(1) : e[2] == 1 ? Rational(1, 3) : Rational(1, 5);
    return Rational::rising_half(dt, static_cast<unsigned long>(e[0] + e[2])) *
           Rational::rising_half(dr, static_cast<unsigned long>(e[1] + e[2])) * angular;
  };
  const std::size_t nw = cumulants_.size() + orientations_.size();
  weight_terms_.resize(nw + 1);
  weight_terms_[0].push_back({0, 1.0});
  std::vector<std::vector<std::pair<std::array<int, 3>, Rational>>> exact_weights(nw);
  for (std::size_t w = 0; w < cumulants_.size(); ++w) {
    const auto sx = sonine_coefficients(dt, cumulants_[w][0]), sy = sonine_coefficients(dr, cumulants_[w][1]);
    for (int i = 0; i <= cumulants_[w][0]; ++i)
      for (int j = 0; j <= cumulants_[w][1]; ++j)
        exact_weights[w].push_back({{i, j, 0}, sx[static_cast<std::size_t>(i)] * sy[static_cast<std::size_t>(j)]});
  }
  // P S_p^(5/2)(x) S_q^(5/2)(y): the rank-2 Sonine polynomials of (cc)°:(ŵŵ)°, orthogonal within the family.
  for (std::size_t o = 0; o < orientations_.size(); ++o) {
    auto& terms = exact_weights[cumulants_.size() + o];
    const auto sx = sonine_coefficients(dt + 4, orientations_[o][0]),
               sy = sonine_coefficients(dr + 4, orientations_[o][1]);
    for (int i = 0; i <= orientations_[o][0]; ++i)
      for (int j = 0; j <= orientations_[o][1]; ++j) {
        const Rational c = sx[static_cast<std::size_t>(i)] * sy[static_cast<std::size_t>(j)];
        terms.push_back({{i, j, 1}, c});
        terms.push_back({{i + 1, j + 1, 0}, c * Rational(-1, 3)});
      }
    // C − 1/3 = ⟨(cos²Θ − 1/3) Φ⟩: only the f² terms contribute, ⟨(cos²Θ − 1/3) cos²Θ⟩ = 4/45.
    Rational c_weight;
    for (const auto& [e, c] : terms)
      if (e[2] == 1)
        c_weight += c * Rational(4, 45) * Rational::rising_half(dt, static_cast<unsigned long>(e[0] + 1)) *
                    Rational::rising_half(dr, static_cast<unsigned long>(e[1] + 1));
    correlation_weights_.push_back(c_weight.to_double());
  }
  for (std::size_t w = 0; w < nw; ++w)
    for (const auto& [e, c] : exact_weights[w]) weight_terms_[w + 1].push_back({monomial_index(e), c.to_double()});
  for (const auto& t : tests_) {
    Rational mean;
    for (const auto& [e, c] : t.terms) mean += c * moment_m(e);
    maxwellian_.push_back(mean.to_double());
    std::vector<double> row;
    for (const auto& terms : exact_weights) {
      Rational s;
      for (const auto& [et, ct] : t.terms)
        for (const auto& [e, c] : terms) s += ct * c * moment_m({et[0] + e[0], et[1] + e[1], et[2] + e[2]});
      row.push_back(s.to_double());
    }
    projection_.push_back(std::move(row));
  }
}

RoughSonineBalances::Productions RoughSonineBalances::productions(double tau, bool linear) const {
  const std::size_t nm = monomials_.size(), nt = tests_.size();
  std::vector<double> d(nm * nm * nt, 0.0);
  for (std::size_t a = 0; a < nm; ++a)
    for (std::size_t b = 0; b < nm; ++b) {
      if (linear && a != 0 && b != 0) continue;
      for (std::size_t t = 0; t < nt; ++t) {
        const auto& l = d_[(a * nm + b) * nt + t];
        if (!l.c.empty()) d[(a * nm + b) * nt + t] = l(tau);
      }
    }
  return contract(d, linear);
}

RoughSonineBalances::Productions RoughSonineBalances::productions_from(const MonomialAverage& gain,
                                                                       const MonomialAverage& loss) const {
  const std::size_t nm = monomials_.size(), nt = tests_.size();
  std::vector<double> d(nm * nm * nt, 0.0);
  for (std::size_t a = 0; a < nm; ++a)
    for (std::size_t b = 0; b < nm; ++b) {
      if (a != 0 && b != 0) continue;
      for (std::size_t t = 0; t < nt; ++t) {
        const Test& test = tests_[t];
        if (decoupled_ && test.terms.front().first[1] > 0) continue;  // no spin balance at β = −1
        double sum = 0;
        for (const auto& [e, c] : test.terms)
          sum += c.to_double() * (gain(monomials_[a], monomials_[b], e) - loss(monomials_[a], monomials_[b], e));
        d[(a * nm + b) * nt + t] = sum;
      }
    }
  return contract(d, true);
}

RoughSonineBalances::Productions RoughSonineBalances::contract(const std::vector<double>& d, bool linear) const {
  const std::size_t nm = monomials_.size(), nt = tests_.size(), nw = weight_terms_.size();
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
  const std::size_t k = unknowns(), nt = tests_.size();
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
    const double degree = tests_[t].degree;
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
  return translational_rate(productions(tau, linear), a, linear);
}

double RoughSonineBalances::translational_rate(const Productions& r, std::span<const double> a, bool linear) const {
  double rx = r(0, 0, 0);
  for (std::size_t p = 0; p < unknowns(); ++p) {
    rx += a[p] * (r(p + 1, 0, 0) + r(0, p + 1, 0));
    if (!linear)
      for (std::size_t q = 0; q < unknowns(); ++q) rx += a[p] * a[q] * r(p + 1, q + 1, 0);
  }
  return -2.0 / dimension_ * rx;
}

}  // namespace gkt::detail
