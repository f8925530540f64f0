// Private: exact Taylor expansion of the Gaussian collision integral J(Q(x)) in up to four
// auxiliary variables x = (x0, x1, x2, x3), Q(x) = Q0 + Σ_v x_v Q_v (docs/theory.md §3). The
// polynomials and the recurrence take the number of variables as a template parameter (the
// rough engine uses eight).
//
// J/J(0) = a^{1/2} n1^{−(d−1)/2} n2^{−1} with a, n1, n2 polynomials (degree 1, 2, 2) in x
// normalised to constant term 1. Its coefficients follow from the Euler-operator identity
//   Π · E f = f · Qc,   Π = a n1 n2,   Qc = ½(Ea) n1 n2 − ((d−1)/2) a (En1) n2 − a n1 (En2),
// (E = Σ x_v ∂_v), i.e. |m| f_m = Σ_{e≠0} (Qc_e − |m−e| Π_e) f_{m−e}: each coefficient costs
// one pass over the ≤ 56 monomials of Π — no symbolic differentiation, no power series
// division, exact in the ring (Q or Q[α]), run on integers under a common denominator
// (euler_recurrence.hpp).
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <type_traits>
#include <utility>
#include <vector>

#include "collision/euler_recurrence.hpp"
#include "collision/ring.hpp"
#include "gkt/collision/collision_rule.hpp"

namespace gkt::detail {

using ExactForm = std::array<std::array<Rational, 4>, 4>;

/// Exponent vector of a monomial in N auxiliary variables.
template <std::size_t N>
using ExponentVector = std::array<int, N>;

/// Number of auxiliary expansion variables of the smooth engine (the rough engine,
/// rough_collision_moments.cpp, runs the same recurrence in more).
inline constexpr int kVariables = 4;
using Exponents = ExponentVector<kVariables>;

/// Returns the reference form Q0 = diag(θ_i, θ_j, 0, 0): the two Maxwellians (theory.md (2.8)).
inline ExactForm reference_form(const CollisionPair& pair) {
  ExactForm q0{};
  q0[0][0] = pair.theta_i;
  q0[1][1] = pair.theta_j;
  return q0;
}

/// A polynomial in N auxiliary variables with few terms (exponent vectors e, coefficients c).
template <class Ring, std::size_t N = kVariables>
struct SmallPolynomial {
  using Exponents = ExponentVector<N>;
  struct Term {
    Exponents e;
    Ring c;
  };
  std::vector<Term> terms;

  void add(const Exponents& e, const Ring& c) {
    if (c.is_zero()) return;
    for (auto& t : terms)
      if (t.e == e) {
        t.c += c;
        return;
      }
    terms.push_back({e, c});
  }
  [[nodiscard]] Rational constant() const {
    for (const auto& t : terms)
      if (t.e == Exponents{}) return constant_term(t.c);
    return Rational(0);
  }
  friend SmallPolynomial operator+(const SmallPolynomial& a, const SmallPolynomial& b) {
    SmallPolynomial r = a;
    for (const auto& t : b.terms) r.add(t.e, t.c);
    return r;
  }
  friend SmallPolynomial operator-(const SmallPolynomial& a, const SmallPolynomial& b) {
    SmallPolynomial r = a;
    for (const auto& t : b.terms) r.add(t.e, -t.c);
    return r;
  }
  friend SmallPolynomial operator*(const SmallPolynomial& a, const SmallPolynomial& b) {
    SmallPolynomial r;
    for (const auto& x : a.terms)
      for (const auto& y : b.terms) {
        Exponents e{};
        for (std::size_t v = 0; v < N; ++v) e[v] = x.e[v] + y.e[v];
        r.add(e, x.c * y.c);
      }
    return r;
  }
  friend SmallPolynomial operator*(const Ring& c, const SmallPolynomial& a) {
    SmallPolynomial r;
    for (const auto& t : a.terms) r.add(t.e, c * t.c);
    return r;
  }
  /// Returns E p = Σ |e| c_e x^e (Euler operator).
  [[nodiscard]] SmallPolynomial euler() const {
    SmallPolynomial r;
    for (const auto& t : terms) {
      long degree = 0;
      for (std::size_t v = 0; v < N; ++v) degree += t.e[v];
      r.add(t.e, Ring(degree) * t.c);
    }
    return r;
  }
  void divide_by(const Rational& c) {
    for (auto& t : terms) divide(t.c, c);
  }
};

/// Dense box of Taylor coefficients f(k0, …, k3), 0 ≤ k_v ≤ box_v, of J_s(Q(x))/J_s(Q0), where
/// J_s carries the extra factor (σ̂·g)^s (s = 0: the hard-sphere rate).
template <class Ring>
struct GeneratingSeries {
  Exponents box{};
  std::vector<Ring> coefficients;
  /// Constant terms: J_s(Q0) = K_d Γ(1 + s/2) a0^{(1+s)/2} n1_0^{−(d−1)/2} n2_0^{−1−s/2}.
  Rational a0, n1_0, n2_0;

  [[nodiscard]] std::size_t index(int k0, int k1, int k2, int k3 = 0) const {
    return ((static_cast<std::size_t>(k0) * (box[1] + 1) + k1) * (box[2] + 1) + k2) * (box[3] + 1) + k3;
  }
  [[nodiscard]] const Ring& operator()(int k0, int k1, int k2, int k3 = 0) const {
    return coefficients[index(k0, k1, k2, k3)];
  }
};

/// Returns the Taylor coefficients f_m, 0 ≤ m_v ≤ box_v (index order of GeneratingSeries, k0
/// slowest), of the f with f_0 = 1 and Π·Ef = f·Qc (theory.md (3.2)–(3.3)) in N variables:
/// |m| f_m = Σ_{e≠0} (Qc_e − |m−e| Π_e) f_{m−e}. `pi` has constant term 1; the constant term of
/// `qc` (an Euler derivative: none) is ignored. Exact in the ring. `keep`: a down-closed subset of
/// the box to compute (solve_euler_recurrence); empty: all of it.
template <class Ring, std::size_t N>
std::vector<Ring> euler_recurrence(
    const SmallPolynomial<Ring, N>& pi, const SmallPolynomial<Ring, N>& qc, const ExponentVector<N>& box,
    const std::type_identity_t<std::function<bool(const ExponentVector<N>&)>>& keep = {}) {
  using Exponents = ExponentVector<N>;
  struct RecurrenceTerm {
    Exponents e;
    Ring q, p;
  };
  std::vector<RecurrenceTerm> rec;
  for (const auto& term : pi.terms)
    if (term.e != Exponents{}) rec.push_back({term.e, Ring(0L), term.c});
  for (const auto& term : qc.terms) {
    bool merged = false;
    for (auto& r : rec)
      if (r.e == term.e) {
        r.q = term.c;
        merged = true;
      }
    if (!merged && term.e != Exponents{}) rec.push_back({term.e, term.c, Ring(0L)});
  }
  return solve_euler_recurrence<Ring>(rec, box, keep);
}

/// Returns the Taylor coefficients of J(Q0 + Σ x_v Q_v)/J(Q0) in the box (exact in Ring).
template <class Ring>
GeneratingSeries<Ring> expand_gaussian_collision_integral(const CollisionPair& pair, const Ring& alpha,
                                                          const ExactForm& q0,
                                                          const std::array<ExactForm, kVariables>& dq,
                                                          const Exponents& box, const Rational& power = Rational(0)) {
  const auto t = pair.velocity_map();
  // M = Tᵀ Q T for Q0 and each direction; entries become polynomials in x of degree ≤ 1.
  auto congruence = [&](const ExactForm& q) {
    std::array<std::array<Rational, 3>, 3> m{};
    for (int r = 0; r < 3; ++r)
      for (int s = 0; s < 3; ++s)
        for (int a = 0; a < 4; ++a)
          for (int b = 0; b < 4; ++b)
            if (!q[a][b].is_zero() && !t[a][r].is_zero() && !t[b][s].is_zero()) m[r][s] += t[a][r] * q[a][b] * t[b][s];
    return m;
  };
  std::array<std::array<SmallPolynomial<Ring>, 3>, 3> m;
  {
    const auto m0 = congruence(q0);
    for (int r = 0; r < 3; ++r)
      for (int s = 0; s < 3; ++s) m[r][s].add(Exponents{}, Ring(m0[r][s]));
    for (int v = 0; v < kVariables; ++v) {
      const auto mv = congruence(dq[v]);
      Exponents e{};
      e[v] = 1;
      for (int r = 0; r < 3; ++r)
        for (int s = 0; s < 3; ++s) m[r][s].add(e, Ring(mv[r][s]));
    }
  }
  const auto& A = m[0][0];
  const auto& D = m[0][1];
  const auto& E = m[0][2];
  const auto& B = m[1][1];
  const auto& H = m[1][2];
  const auto& C = m[2][2];
  const Ring two(2L);
  auto n1 = A * (B + C + two * H) - (D + E) * (D + E);
  const auto d_minus_alpha_e = D - alpha * E;
  auto n2 = A * (B + (alpha * alpha) * C - (two * alpha) * H) - d_minus_alpha_e * d_minus_alpha_e;
  auto a = A;

  GeneratingSeries<Ring> out;
  out.box = box;
  out.a0 = a.constant();
  out.n1_0 = n1.constant();
  out.n2_0 = n2.constant();
  if (out.a0.sign() <= 0 || out.n1_0.sign() <= 0 || out.n2_0.sign() <= 0)
    throw std::domain_error("expand_gaussian_collision_integral: reference form is not integrable");
  a.divide_by(out.a0);
  n1.divide_by(out.n1_0);
  n2.divide_by(out.n2_0);

  // f = a^{(1+s)/2} n1^{−(d−1)/2} n2^{−1−s/2}  (theory.md (2.9); s = 0 gives (3.1)).
  const Ring ra((Rational(1) + power) / Rational(2));
  const Ring r1(Rational(pair.dimension - 1, 2));
  const Ring r2(Rational(1) + power / Rational(2));
  const auto pi = a * n1 * n2;
  const auto qc = ra * (a.euler() * n1 * n2) - r1 * (a * n1.euler() * n2) - r2 * (a * n1 * n2.euler());

  out.coefficients = euler_recurrence(pi, qc, box);
  return out;
}

}  // namespace gkt::detail
